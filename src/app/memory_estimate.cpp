#include "app/memory_estimate.hpp"

#include "base/errors.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultMpiComm.hpp>
#include <mpi.h>
#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace kiln
{
namespace internal
{
// Calibrated on the development machine (2 cores, 24 GB; Debian 12, Trilinos 13.2, Open MPI
// 4.1) by benchmarks/memory_fit.py (2026-11-27, after changelog 0025): the peak resident
// memory (VmHWM, largest rank), on 1 and 2 ranks, of the contact box of
// inputs/contact-box-close.xml (Thermo-Elasticity with contact, F = 4 unknowns per node) at
// 16^3, 24^3, 32^3, 40^3 cells and of its heat conduction alone (F = 1) at 24^3, 32^3, 48^3,
// 64^3 cells, to the first backward Euler step, and of the elastic cube of
// inputs/elastic-cube.xml (F = 3, CG) at 20^3, 30^3, 40^3 cells. Fitted by least squares to
//   base + cells m_F + unknowns / ranks (k_F + 8 V),
// one (m_F, k_F) per F, V the Krylov vectors the longest solve touched (flexible GMRES: two
// per iteration, plus 2, the pages of the others are never touched; CG: 8): every run within
// 4.5% but the smallest (16^3 on one rank, 8%). m_F is what every rank holds whatever the
// number of ranks: mostly what a second rank adds that grows with the mesh (ghost rows,
// Tpetra's maps and imports: on 2 ranks a rank's heap peaks 12% above half of one rank's,
// heaptrack, doc/scaling/targets.md), the mesh held whole being a few MB; k_F its share of
// the unknowns (matrices, graphs, multigrid, vectors). Another F would take the line through F = 1
// and 4. The estimate counts the whole Krylov basis (V = "Num Blocks" + 1 for GMRES), as a long
// solve touches it. Measured at 1 and 2 ranks only: the largest rank's extra (ghost layer,
// imbalance) is in the per-cell term, which overestimates it on many ranks. A direct solver's
// fill-in is not counted.
constexpr double base_bytes = 94e6; ///< the program, Trilinos, MPI

/// The fitted bytes per cell (m_F) and per unknown (k_F) for F unknowns per node.
struct PerField
{
  int fields;
  double per_cell, per_unknown;
};
constexpr PerField fitted[] = {{1, 480.0, 551.0}, {3, 3100.0, 2052.0}, {4, 3140.0, 2787.0}};

PerField per_field(const int fields)
{
  for (const PerField &f : fitted)
    if (f.fields == fields)
      return f;
  // The line through F = 1 and F = 4 (no physics of Kiln has another F today).
  const PerField &one = fitted[0], &four = fitted[2];
  const double s = (fields - 1.0) / 3.0;
  return {fields, one.per_cell + s * (four.per_cell - one.per_cell),
          one.per_unknown + s * (four.per_unknown - one.per_unknown)};
}

/// One value of /proc/self/status ("VmHWM:  1234 kB") [bytes], or -1.
double proc_status_bytes(const std::string &key)
{
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind(key + ":", 0) == 0)
    {
      std::istringstream value(line.substr(key.size() + 1));
      double kb = -1.0;
      value >> kb;
      return kb < 0.0 ? -1.0 : kb * 1024.0;
    }
  return -1.0;
}

/// MemAvailable of /proc/meminfo [bytes], or -1.
double mem_available()
{
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  double kb = -1.0;
  std::string unit;
  while (meminfo >> key >> kb >> unit)
    if (key == "MemAvailable:")
      return kb * 1024.0;
  return -1.0;
}

/// The ranks of `comm` on this node.
int ranks_on_this_node(const Teuchos::Comm<int> &comm)
{
  const auto *mpi = dynamic_cast<const Teuchos::MpiComm<int> *>(&comm);
  if (mpi == nullptr)
    return 1;
  MPI_Comm node;
  MPI_Comm_split_type(*mpi->getRawMpiComm(), MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
  int size = 1;
  MPI_Comm_size(node, &size);
  MPI_Comm_free(&node);
  return size;
}

/// The vectors the linear solver of the "Solver" block keeps: a GMRES basis of "Num Blocks"
/// + 1 vectors (Belos' default 300), and "Num Blocks" more for flexible GMRES; a few for the
/// other Krylov methods.
int krylov_vectors(const Teuchos::ParameterList &solver)
{
  const Teuchos::ParameterList &linear = solver.sublist("Linear Solver");
  if (!linear.isType<std::string>("Linear Solver Type") ||
      linear.get<std::string>("Linear Solver Type") != "Belos")
    return 0;
  const Teuchos::ParameterList belos =
      linear.isSublist("Linear Solver Types") &&
              linear.sublist("Linear Solver Types").isSublist("Belos")
          ? linear.sublist("Linear Solver Types").sublist("Belos")
          : Teuchos::ParameterList();
  const std::string type = belos.isType<std::string>("Solver Type")
                               ? belos.get<std::string>("Solver Type")
                               : std::string("Block GMRES");
  if (type.find("GMRES") == std::string::npos && type != "GCRODR")
    return 8;
  const Teuchos::ParameterList options =
      belos.isSublist("Solver Types") && belos.sublist("Solver Types").isSublist(type)
          ? belos.sublist("Solver Types").sublist(type)
          : Teuchos::ParameterList();
  const int blocks = options.isType<int>("Num Blocks") ? options.get<int>("Num Blocks") : 300;
  // Flexible GMRES keeps the preconditioned vectors too.
  const bool flexible =
      options.isType<bool>("Flexible Gmres") && options.get<bool>("Flexible Gmres");
  return (flexible ? 2 : 1) * blocks + 1;
}
} // namespace internal

MemoryEstimate::MemoryEstimate(const long long cells, const long long nodes, const int fields,
                               const int krylov_vectors, const int ranks)
    : cells_(cells), nodes_(nodes), fields_(fields), krylov_vectors_(krylov_vectors),
      ranks_(std::max(1, ranks)), unknowns_(nodes * fields)
{
}

MemoryEstimate MemoryEstimate::of(const MeshFactory::Counts &counts, const DofLayout &layout,
                                  const Teuchos::ParameterList &solver, const int ranks)
{
  return MemoryEstimate(counts.cells, counts.nodes, layout.n_node_fields(),
                        internal::krylov_vectors(solver), ranks);
}

double MemoryEstimate::mesh_bytes() const
{
  return static_cast<double>(cells_) * internal::per_field(fields_).per_cell;
}

double MemoryEstimate::unknown_bytes() const
{
  const double per_unknown = internal::per_field(fields_).per_unknown + 8.0 * krylov_vectors_;
  return per_unknown * static_cast<double>(unknowns_) / ranks_;
}

double MemoryEstimate::bytes_per_rank() const
{
  return base_bytes() + mesh_bytes() + unknown_bytes();
}

double MemoryEstimate::base_bytes() const
{
  return internal::base_bytes;
}

std::string memory_text(const double bytes)
{
  std::ostringstream s;
  s << std::setprecision(3);
  if (bytes >= 1e12)
    s << bytes / 1e12 << " TB";
  else if (bytes >= 1e9)
    s << bytes / 1e9 << " GB";
  else if (bytes >= 1e6)
    s << bytes / 1e6 << " MB";
  else
    s << bytes / 1e3 << " kB";
  return s.str();
}

std::string MemoryEstimate::summary() const
{
  std::ostringstream s;
  // The three parts, each rounded as printed, add up to the total (rounded the same way).
  s << "about " << memory_text(bytes_per_rank()) << " per rank (" << memory_text(base_bytes())
    << " the program, its libraries and MPI; " << memory_text(mesh_bytes())
    << " on every rank for the " << cells_
    << " cells (what more ranks do not divide: ghost rows, maps, the mesh); "
    << memory_text(unknown_bytes()) << " for ";
  if (ranks_ > 1)
    s << "1/" << ranks_ << " of ";
  s << "the " << unknowns_ << " unknowns";
  if (krylov_vectors_ > 0)
    s << ", with a Krylov basis of " << krylov_vectors_ << " vectors";
  s << ")";
  return s.str();
}

double available_memory(const Teuchos::Comm<int> &comm, std::string &how)
{
  const double resident = std::max(0.0, internal::proc_status_bytes("VmRSS"));
  const double available = internal::mem_available();
  const int on_node = internal::ranks_on_this_node(comm);
  double room = available < 0.0 ? HUGE_VAL : available / on_node;
  std::ostringstream s;
  if (available >= 0.0)
    s << "MemAvailable " << memory_text(available) << " for the " << on_node << " rank"
      << (on_node > 1 ? "s" : "") << " on this node";
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
  {
    const double in_use = std::max(0.0, internal::proc_status_bytes("VmSize"));
    const double left = std::max(0.0, static_cast<double>(limit.rlim_cur) - in_use);
    room = std::min(room, left);
    s << (available >= 0.0 ? "; " : "") << "an address-space limit (ulimit -v) of "
      << memory_text(static_cast<double>(limit.rlim_cur)) << ", " << memory_text(in_use)
      << " of it in use";
  }
  how = s.str();
  return resident + room;
}

void check_memory(const Teuchos::ParameterList &params, const DofLayout &layout,
                  const std::string &input_path, const std::string &mesh_file,
                  const Teuchos::Comm<int> &comm, std::ostream &out)
{
  const MeshFactory factory(params.sublist("Mesh"), input_path + ": Kiln/Mesh", mesh_file);
  const MeshFactory::Counts counts = factory.counts();
  const MemoryEstimate estimate =
      MemoryEstimate::of(counts, layout, params.sublist("Solver"), comm.getSize());
  std::string how;
  const double available = available_memory(comm, how);
  const bool fits = estimate.bytes_per_rank() <= available;
  std::ostringstream message;
  if (!fits)
    message << counts.source << ": the run needs " << estimate.summary()
            << ", but this machine gives a rank about " << memory_text(available) << " (" << how
            << "): use fewer cells (a coarser mesh), or more ranks on more nodes (the unknowns "
               "are shared among the ranks, the mesh is not)";
  // A GMRES basis is counted whole, though only solves that long fill it (Belos touches its
  // vectors as it goes): a shorter one is a way out too.
  if (!fits && estimate.krylov_vectors() > 8)
    message << ", or a shorter Krylov basis (\"Num Blocks\" of the Belos solver in "
            << "Kiln/Solver/Linear Solver: the estimate counts all " << estimate.krylov_vectors()
            << " vectors of its basis, which only solves of that many iterations fill)";
  check_collectively(comm, fits, "", message.str());
  if (comm.getRank() == 0)
    out << "memory: " << estimate.summary() << " estimated; a rank has about "
        << memory_text(available) << "\n";
}

double peak_resident_memory(const Teuchos::Comm<int> &comm)
{
  const double mine = std::max(0.0, internal::proc_status_bytes("VmHWM"));
  double largest = 0.0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, mine, Teuchos::outArg(largest));
  return largest;
}
} // namespace kiln
