#pragma once
/// The memory a run needs on each MPI rank, estimated from the mesh counts before anything is
/// allocated, against what this machine gives: every set-up (kiln --check and a run) prints
/// it, and refuses an input that would not fit before it allocates the mesh.
#include "discretization/dof_manager.hpp"
#include "mesh/mesh_factory.hpp"

#include <Teuchos_Comm.hpp>
#include <Teuchos_ParameterList.hpp>

#include <ostream>
#include <string>

namespace kiln
{
class MemoryEstimate
{
public:
  /// `cells` and `nodes` of the whole mesh, `fields` unknowns per node, `krylov_vectors` the
  /// vectors the linear solver keeps (a GMRES basis), `ranks` MPI ranks.
  MemoryEstimate(long long cells, long long nodes, int fields, int krylov_vectors, int ranks);
  /// From the input: the mesh's counts, the layout and the validated "Solver" block.
  static MemoryEstimate of(const MeshFactory::Counts &counts, const DofLayout &layout,
                           const Teuchos::ParameterList &solver, int ranks);

  /// What every rank holds whole: the mesh, its partition, the global numbering [bytes].
  double mesh_bytes() const;
  /// One rank's share of the unknowns: the matrices and their graphs, the multigrid
  /// hierarchy, the vectors and the Krylov basis [bytes].
  double unknown_bytes() const;
  /// What every rank holds before the input: the program, its libraries and MPI [bytes].
  double base_bytes() const;
  /// The peak resident memory of a rank [bytes]: base_bytes() + mesh_bytes() + unknown_bytes().
  double bytes_per_rank() const;
  long long unknowns() const { return unknowns_; }
  int krylov_vectors() const { return krylov_vectors_; }
  /// "about 1.23 GB per rank (94 MB the program, its libraries and MPI; 136 MB on every rank
  /// for the 32768 cells (...); 1.0 GB for 1/2 of the 148104 unknowns)": the total, then the
  /// three parts it is the sum of.
  std::string summary() const;

private:
  long long cells_;
  long long nodes_;
  int fields_;
  int krylov_vectors_;
  int ranks_;
  long long unknowns_;
};

/// Bytes as "870 MB", "1.23 GB".
std::string memory_text(double bytes);

/// What this machine gives one rank of `comm`, as the peak resident memory it may reach
/// [bytes]: what it holds now plus the least of its share of MemAvailable (/proc/meminfo, shared
/// by the ranks on this node) and the address space left under RLIMIT_AS (ulimit -v); a
/// description of both in `how`.
double available_memory(const Teuchos::Comm<int> &comm, std::string &how);

/// Prints the estimate of the run that the input `params` (the validated root list; the mesh
/// file of kiln --mesh in `mesh_file`) asks for on `out`, and throws the same InputError on
/// every rank if it does not fit on some rank, naming what sets the mesh size (Box "Cells" or
/// the mesh file), the estimate, the memory available and what to do. Collective.
void check_memory(const Teuchos::ParameterList &params, const DofLayout &layout,
                  const std::string &input_path, const std::string &mesh_file,
                  const Teuchos::Comm<int> &comm, std::ostream &out);

/// The largest peak resident memory of the ranks so far (VmHWM of /proc/self/status) [bytes];
/// 0 where the system does not tell. Collective.
double peak_resident_memory(const Teuchos::Comm<int> &comm);
} // namespace kiln
