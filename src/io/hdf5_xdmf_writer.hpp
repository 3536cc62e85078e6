#pragma once
/// Results in one HDF5 file per run, written collectively with MPI-IO, and an
/// XDMF file beside it for ParaView. The layout is in doc/output-format.md:
///   /mesh/coordinates   (nodes x 3) double
///   /mesh/connectivity  (cells x n) int64, Exodus node order, 0-based; n the most nodes of a
///                       cell (8 for hexahedra), a smaller cell's row padded with -1
///   /mesh/topology      the cells as XDMF reads them, when /mesh/connectivity will not do
///                       (several types: "Mixed", 1-D; quadratic hexahedra: VTK node order)
///   /mesh/block_id      (cells) int32
///   /mesh/cell_rank     (cells) int32, the owning rank
///   /steps/NNNNNN/      attributes time, cycle, dt; node fields (nodes) or
///                       (nodes x c), cell fields (cells) or (cells x c)
///   /gap/               the gap surface, if the mesh has a gap: coordinates (points x 3),
///                       connectivity (quads x 4), node_a, node_b, area, s, t (points)
///   /gap/steps/NNNNNN/  every node field of step NNNNNN at the gap points (the pairs'
///                       values of write_gap_field() where given)
///   /gap_ID/...         the same for each further gap, ID its side set (Mesh::gap_name())
///   /pair_NAME/...      the same for each contact pair NAME (Mesh::contact_pairs): the faces of
///                       its secondary side set, a point per node (node_a the node, node_b and
///                       the pair index -1, area each face's share), its steps every node field
///                       at those nodes
///   /history/NAME       one dataset per history column (history_columns(mesh's gaps, pairs)), a
///   row per
///                       step; rows are held back and written at each end_step and finish
/// Rows are in global-id order whatever the number of ranks: each rank writes
/// the rows it owns. The root holds the run's metadata (kiln_version, created,
/// input_path, input, status); each dataset of a field of the catalog its unit,
/// components and meaning. While the run goes the files are BASE.running.h5 and
/// BASE.running.xmf; after each step the file is flushed and the XDMF file is
/// rewritten, so a run that fails later leaves readable results behind; finish()
/// renames them BASE.h5 and BASE.xmf.
/// Before the first step the XDMF file shows the mesh alone (one grid, no time).
/// Every member function is collective on the communicator, which must outlive the
/// writer; errors are thrown on all ranks alike (kiln::InputError when the files
/// cannot be created or written, kiln::InternalError for a misuse such as a field
/// with the wrong number of values), and the destructor closes everything.

#include "io/results_writer.hpp"
#include "mesh/mesh.hpp"

#include <mpi.h>

#include <memory>
#include <string>
#include <vector>

namespace kiln
{
class Hdf5XdmfWriter final : public ResultsWriter
{
public:
  /// Creates `base_path`.running.h5 and .running.xmf (collective on `comm`) and
  /// writes /mesh and the metadata. `owned_nodes` and `owned_cells` are this rank's
  /// rows, in increasing order; every node and cell is owned by exactly one rank.
  /// `cell_rank` is the owner of every cell (replicated).
  Hdf5XdmfWriter(MPI_Comm comm, const std::string &base_path, const Mesh &mesh,
                 const std::vector<int> &owned_nodes, const std::vector<int> &owned_cells,
                 const std::vector<int> &cell_rank, const ResultsMetadata &metadata = {});
  ~Hdf5XdmfWriter() override;
  Hdf5XdmfWriter(const Hdf5XdmfWriter &) = delete;
  Hdf5XdmfWriter &operator=(const Hdf5XdmfWriter &) = delete;

  /// Starts group /steps/NNNNNN (NNNNNN = number of steps written before).
  void begin_step(double time, int cycle, double dt) override;
  /// `values` holds n_components values per owned node, node after node. The name
  /// (letters, digits, '_', '-', '.') must be new in this step. In the XDMF file a
  /// field is a Scalar (1 component), Vector (3) or Matrix (others, e.g. Voigt tensors).
  void write_node_field(const std::string &name, int n_components,
                        const std::vector<double> &values) override;
  /// `values` holds n_components values per owned cell, cell after cell.
  void write_cell_field(const std::string &name, int n_components,
                        const std::vector<double> &values) override;
  /// Kept for the gap surfaces' datasets of the node field `name` of this step.
  void write_gap_field(const std::string &name, const std::vector<double> &per_pair) override;
  /// Closes the step group, writes the history rows held back, flushes the file and
  /// rewrites the XDMF file.
  void end_step() override;
  /// Holds the row back for /history until the next end_step() or finish().
  void write_history(const std::vector<double> &row) override;
  /// Writes the root attribute "status", closes the file and renames both files.
  void finish(const std::string &status) override;
  void set_final_base(const std::string &final_base) override;

  /// The files' current paths (BASE.running.* until finish(), then BASE.*).
  std::string h5_path() const;
  std::string xdmf_path() const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::string finished_h5_; ///< the final path, once finished
};
} // namespace kiln
