#include "io/checkpoint.hpp"

#include "base/errors.hpp"
#include "io/checkpoint_h5.hpp"
#include "io/checkpoint_quadrature_state.hpp"
#include "io/hdf5_errors.hpp"
#include "io/row_gather.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultMpiComm.hpp>
#include <hdf5.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <sstream>

namespace kiln
{
namespace internal
{
namespace
{
/// The values of each of `vectors` (all on one map, one-to-one) on rank 0, in global-id order
/// (empty elsewhere). One RowGather serves them all.
std::vector<std::vector<double>> gather(const std::vector<const Tpetra::Vector<> *> &vectors)
{
  const auto map = vectors.front()->getMap();
  const auto ids = map->getNodeElementList();
  const RowGather rows(*Teuchos::rcp_dynamic_cast<const Teuchos::MpiComm<int>>(map->getComm(), true)
                            ->getRawMpiComm(),
                       std::vector<int>(ids.begin(), ids.end()),
                       static_cast<int>(map->getGlobalNumElements()));
  std::vector<std::vector<double>> gathered;
  for (const Tpetra::Vector<> *x : vectors)
  {
    const auto values = x->getData();
    gathered.push_back(rows.to_rank_zero(std::vector<double>(values.begin(), values.end()), 1));
  }
  return gathered;
}

/// Every rank's `record` (all of one length) on rank 0, rank by rank; empty if the lengths
/// differ or are 0. Collective.
std::vector<double> gather_records(const std::vector<double> &record,
                                   const Teuchos::Comm<int> &comm, int &length)
{
  const int here = static_cast<int>(record.size());
  int shortest = 0, longest = 0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, here, Teuchos::outArg(shortest));
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, here, Teuchos::outArg(longest));
  length = shortest == longest ? longest : 0;
  if (length == 0)
    return {};
  std::vector<double> all(comm.getRank() == 0 ? static_cast<std::size_t>(length * comm.getSize())
                                              : 0);
  Teuchos::gather(record.data(), length, all.data(), length, 0, comm);
  return all;
}

/// Whether every value of `vectors` is a finite number.
bool all_finite(const std::vector<const std::vector<double> *> &vectors)
{
  for (const auto *v : vectors)
    for (const double value : *v)
      if (!std::isfinite(value))
        return false;
  return true;
}

/// The largest time or step a checkpoint may hold [s]: 10^15 s, 30 million years.
constexpr double largest_time = 1e15;

/// An error naming the first scalar of `state` (or `output_steps`) out of its range: times and
/// steps finite and in [0, largest_time], counts >= 0.
void check_ranges(const TimeStepper::State &state, const int output_steps)
{
  const std::pair<const char *, double> times[] = {{"time", state.time},
                                                   {"next_step", state.next_step},
                                                   {"last_step", state.last_step},
                                                   {"step_before", state.step_before}};
  for (const auto &[name, value] : times)
    if (!std::isfinite(value) || value < 0.0 || value > largest_time)
    {
      std::ostringstream m;
      m << "its attribute state/" << name << " = " << value
        << " is out of range (a finite number in [0, " << largest_time
        << "] s is expected): a damaged checkpoint";
      throw std::runtime_error(m.str());
    }
  const TimeStepper::Statistics &t = state.statistics;
  const std::pair<const char *, int> counts[] = {{"accepted", state.accepted},
                                                 {"attempts", state.attempts},
                                                 {"steps", t.steps},
                                                 {"error_rejections", t.error_rejections},
                                                 {"newton_failures", t.newton_failures},
                                                 {"newton_iterations", t.newton_iterations},
                                                 {"linear_iterations", t.linear_iterations},
                                                 {"output_steps", output_steps}};
  for (const auto &[name, value] : counts)
    if (value < 0)
      throw std::runtime_error("its attribute state/" + std::string(name) + " = " +
                               std::to_string(value) +
                               " is negative (a count >= 0 is expected): a damaged checkpoint");
}

/// Reads the checkpoint just written at `path` back (every checksum of its state checked) and
/// compares it with what was written: an error if anything differs. `components`: the state
/// at quadrature points, by name (none: the checkpoint has none).
void verify_checkpoint(
    const std::string &path, const double time,
    const std::vector<const std::vector<double> *> &states,
    const std::vector<std::pair<std::string, const std::vector<double> *>> &components)
{
  const H5 file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose,
                "reading the file back failed");
  verify_quadrature_state(file, components);
  const H5 s(H5Gopen2(file, "state", H5P_DEFAULT), H5Gclose, "reading group state back");
  const char *const names[] = {"x", "x_1", "x_2"};
  for (std::size_t v = 0; v < states.size(); ++v)
  {
    const std::vector<double> read = read_array<double>(s, names[v], states[v]->size());
    if (!read.empty() &&
        std::memcmp(read.data(), states[v]->data(), read.size() * sizeof(double)) != 0)
      throw std::runtime_error(std::string("dataset state/") + names[v] +
                               " read back differs from what was written");
  }
  const double read_time = read_attribute<double>(s, "time");
  if (std::memcmp(&read_time, &time, sizeof time) != 0)
    throw std::runtime_error("attribute state/time read back differs from what was written");
}

} // namespace
} // namespace internal

void write_checkpoint(const std::string &path, const TimeStepper::State &state,
                      const CheckpointInfo &info, const RunFingerprint &fingerprint,
                      const Teuchos::Comm<int> &comm, const QuadratureState *quadrature_state)
{
  using namespace internal;
  // Gathered on rank 0 in global-id order (node-major: the file's rows are nodes).
  const std::vector<std::vector<double>> states =
      gather({state.x.get(), state.x_1.get(), state.x_2.get()});
  const std::vector<double> &x = states[0], &x_1 = states[1], &x_2 = states[2];
  const hsize_t F = static_cast<hsize_t>(state.x->getMap()->getGlobalNumElements()) /
                    static_cast<hsize_t>(fingerprint.n_nodes);
  int origin_length = 0;
  const std::vector<double> origins =
      gather_records(info.preconditioner_origin, comm, origin_length);
  // The state at quadrature points, likewise, per component.
  std::vector<int> points;
  std::vector<std::vector<double>> components;
  if (quadrature_state != nullptr)
  {
    points = points_per_cell(*quadrature_state, fingerprint.n_cells, comm);
    components = gather_quadrature_state(*quadrature_state, points, comm);
  }
  std::vector<const std::vector<double> *> all_values = {&x, &x_1, &x_2};
  for (const auto &component : components)
    all_values.push_back(&component);
  std::ostringstream time;
  time << state.time;
  check_run_collectively(
      comm, all_finite(all_values) && std::isfinite(state.time),
      path + ": the state at t = " + time.str() +
          " s holds values that are not finite numbers (NaN or Inf); it is not written as a "
          "checkpoint, and the checkpoints written before are kept");
  quiet_hdf5_errors();
  std::string error;
  if (comm.getRank() == 0)
  {
    const std::string tmp = path + ".tmp";
    try
    {
      // Built in memory (HDF5's core driver, no backing store) and written to disk by
      // write_file(): HDF5 itself never meets a full disk, whose failed close would leave the
      // file open in the library (and MPI_Finalize crashing in HDF5's clean-up).
      const H5 fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "file access properties");
      check(H5Pset_fapl_core(fapl, std::size_t{1} << 20, false), "the in-memory file");
      H5 file(H5Fcreate(tmp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl), H5Fclose,
              "cannot create the file");
      {
        write_attribute(file, "format", std::string("kiln checkpoint"));
        write_attribute(file, "format_version", checkpoint_format_version);
        write_attribute(file, "kiln_version", info.kiln_version);
        write_attribute(file, "created", info.created);
        write_attribute(file, "input_path", info.input_path);
        // As the results carry it: which run wrote the file, without reading the fingerprint.
        write_attribute(file, "run_fingerprint", fingerprint.digest());
        write_string(file, "input", info.input_xml);

        const H5 print(H5Gcreate2(file, "fingerprint", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                       H5Gclose, "group fingerprint");
        write_attribute(print, "n_nodes", fingerprint.n_nodes);
        write_attribute(print, "n_cells", fingerprint.n_cells);
        write_attribute(print, "n_pairs", fingerprint.n_pairs);
        write_attribute(print, "gap_side_set", fingerprint.gap_side_set);
        write_attribute(print, "mesh_hash", fingerprint.mesh_hash);
        write_attribute(print, "layout", fingerprint.layout);
        write_attribute(print, "n_physics", static_cast<int>(fingerprint.physics.size()));
        for (std::size_t i = 0; i < fingerprint.physics.size(); ++i)
        {
          write_attribute(print, "physics_name_" + std::to_string(i), fingerprint.physics[i].first);
          write_string(print, "physics_" + std::to_string(i), fingerprint.physics[i].second);
        }

        const H5 s(H5Gcreate2(file, "state", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
                   "group state");
        write_attribute(s, "time", state.time);
        write_attribute(s, "next_step", state.next_step);
        write_attribute(s, "last_step", state.last_step);
        write_attribute(s, "step_before", state.step_before);
        write_attribute(s, "accepted", state.accepted);
        write_attribute(s, "attempts", state.attempts);
        write_attribute(s, "newton_failed", state.newton_failed ? 1 : 0);
        const TimeStepper::Statistics &stats = state.statistics;
        write_attribute(s, "steps", stats.steps);
        write_attribute(s, "error_rejections", stats.error_rejections);
        write_attribute(s, "newton_failures", stats.newton_failures);
        write_attribute(s, "newton_iterations", stats.newton_iterations);
        write_attribute(s, "linear_iterations", stats.linear_iterations);
        write_attribute(s, "output_steps", info.output_steps);
        write_array(s, "x", x, F);
        write_array(s, "x_1", x_1, F);
        write_array(s, "x_2", x_2, F);

        const H5 contact(H5Gcreate2(file, "contact", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                         H5Gclose, "group contact");
        write_array(contact, "active", info.active, 1);
        write_array(contact, "gap_normal_traction", info.traction, 1);
        if (!info.pair_rows.empty())
        {
          // The pairs' rows (the same on every rank), with their length.
          write_attribute(contact, "n_pair_rows", static_cast<int>(info.pair_rows.size()));
          write_array(contact, "pair_rows", info.pair_rows, 1);
        }
        if (!info.pair_heat_u.empty())
        {
          // The surfaces' u of the pairs' heat cells (the same on every rank), with its length.
          write_attribute(contact, "n_pair_heat_u", static_cast<int>(info.pair_heat_u.size()));
          write_array(contact, "pair_heat_u", info.pair_heat_u, 1);
        }
        if (!origins.empty())
        {
          // One row per rank (NewtonSolver::preconditioner_origin()).
          const H5 solver(H5Gcreate2(file, "solver", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                          H5Gclose, "group solver");
          write_array(solver, "preconditioner_origin", origins,
                      static_cast<hsize_t>(origin_length));
        }
        if (quadrature_state != nullptr)
          write_quadrature_state(file, quadrature_state->names(), points, components);
      }
      check(H5Fflush(file, H5F_SCOPE_LOCAL), "flushing the file");
      const ssize_t size = H5Fget_file_image(file, nullptr, 0);
      if (size < 0)
        throw std::runtime_error("the file's image" + in_parentheses(hdf5_failure_reason()));
      std::vector<char> image(static_cast<std::size_t>(size));
      if (H5Fget_file_image(file, image.data(), image.size()) != size)
        throw std::runtime_error("the file's image" + in_parentheses(hdf5_failure_reason()));
      file.close("closing the file");
      write_file(tmp, image);
      std::vector<std::pair<std::string, const std::vector<double> *>> written_components;
      for (std::size_t k = 0; k < components.size(); ++k)
        written_components.emplace_back(quadrature_state->names()[k], &components[k]);
      verify_checkpoint(tmp, state.time, {&x, &x_1, &x_2}, written_components);
      std::filesystem::rename(tmp, path);
    }
    catch (const std::exception &e)
    {
      std::error_code ignored;
      std::filesystem::remove(tmp, ignored);
      error = e.what();
    }
  }
  check_write_collectively(comm, error.empty(), path,
                           "cannot write the checkpoint: " + error +
                               "; nothing was put in its place. Check that its folder exists and "
                               "is writable (Kiln/Checkpoint/\"File Base\"), that the disk is "
                               "not full and that no file-size limit (ulimit -f) stops it");
}

Checkpoint read_checkpoint(const std::string &path, const RunFingerprint &run,
                           const Teuchos::RCP<const Map> &map, const Teuchos::Comm<int> &comm,
                           QuadratureState *quadrature_state)
{
  using namespace internal;
  Checkpoint c;
  SavedQuadratureState saved_state;
  std::string error, difference;
  std::vector<double> x, x_1, x_2;
  try
  {
    // The failures below become one message; HDF5's own error stack stays quiet.
    const QuietHdf5Errors quiet;
    if (!std::filesystem::is_regular_file(path))
      throw std::runtime_error("no such file");
    const H5 file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose,
                  "not an HDF5 file, or a damaged (truncated) one");
    if (H5Aexists(file, "format") <= 0 || read_string(file, "format", true) != "kiln checkpoint")
      throw std::runtime_error("not a Kiln checkpoint (a results file? checkpoints are written "
                               "by Kiln/Checkpoint)");
    const int version = read_attribute<int>(file, "format_version");
    if (version != checkpoint_format_version)
      throw std::runtime_error("format version " + std::to_string(version) +
                               ", but this Kiln reads version " +
                               std::to_string(checkpoint_format_version));
    c.info.kiln_version = read_string(file, "kiln_version", true);
    c.info.created = read_string(file, "created", true);
    c.info.input_path = read_string(file, "input_path", true);
    c.info.input_xml = read_string(file, "input", false);

    const H5 print(H5Gopen2(file, "fingerprint", H5P_DEFAULT), H5Gclose, "group fingerprint");
    RunFingerprint &f = c.fingerprint;
    f.n_nodes = read_attribute<int>(print, "n_nodes");
    f.n_cells = read_attribute<int>(print, "n_cells");
    f.n_pairs = read_attribute<int>(print, "n_pairs");
    f.gap_side_set = read_attribute<int>(print, "gap_side_set");
    f.mesh_hash = read_string(print, "mesh_hash", true);
    f.layout = read_string(print, "layout", true);
    const int n_physics = read_attribute<int>(print, "n_physics");
    for (int i = 0; i < n_physics; ++i)
      f.physics.emplace_back(read_string(print, "physics_name_" + std::to_string(i), true),
                             read_string(print, "physics_" + std::to_string(i), false));
    difference = run.difference(f);
    if (!difference.empty())
      throw std::runtime_error("another run's");

    const H5 s(H5Gopen2(file, "state", H5P_DEFAULT), H5Gclose, "group state");
    TimeStepper::State &state = c.state;
    state.time = read_attribute<double>(s, "time");
    state.next_step = read_attribute<double>(s, "next_step");
    state.last_step = read_attribute<double>(s, "last_step");
    state.step_before = read_attribute<double>(s, "step_before");
    state.accepted = read_attribute<int>(s, "accepted");
    state.attempts = read_attribute<int>(s, "attempts");
    state.newton_failed = read_attribute<int>(s, "newton_failed") != 0;
    state.statistics.steps = read_attribute<int>(s, "steps");
    state.statistics.error_rejections = read_attribute<int>(s, "error_rejections");
    state.statistics.newton_failures = read_attribute<int>(s, "newton_failures");
    state.statistics.newton_iterations = read_attribute<int>(s, "newton_iterations");
    state.statistics.linear_iterations = read_attribute<int>(s, "linear_iterations");
    c.info.output_steps = read_attribute<int>(s, "output_steps");
    const std::size_t n = map->getGlobalNumElements();
    if (n % static_cast<std::size_t>(std::max(f.n_nodes, 1)) != 0)
      throw std::runtime_error("its " + std::to_string(f.n_nodes) +
                               " nodes do not fit this run's " + std::to_string(n) + " unknowns");
    check_ranges(state, c.info.output_steps);
    x = read_array<double>(s, "x", n);
    x_1 = read_array<double>(s, "x_1", n);
    x_2 = read_array<double>(s, "x_2", n);
    if (!all_finite({&x, &x_1, &x_2}))
      throw std::runtime_error("its state (state/x, x_1 or x_2) holds values that are not finite "
                               "numbers (NaN or Inf): a damaged checkpoint");

    const H5 contact(H5Gopen2(file, "contact", H5P_DEFAULT), H5Gclose, "group contact");
    c.info.active = read_array<int>(contact, "active", f.n_pairs);
    c.info.traction = read_array<double>(contact, "gap_normal_traction", f.n_pairs);
    if (H5Lexists(contact, "pair_rows", H5P_DEFAULT) > 0)
      c.info.pair_rows =
          read_array<double>(contact, "pair_rows",
                             static_cast<std::size_t>(read_attribute<int>(contact, "n_pair_rows")));
    if (H5Lexists(contact, "pair_heat_u", H5P_DEFAULT) > 0)
      c.info.pair_heat_u = read_array<double>(
          contact, "pair_heat_u",
          static_cast<std::size_t>(read_attribute<int>(contact, "n_pair_heat_u")));
    for (std::size_t i = 0; i < c.info.active.size(); ++i)
      if ((c.info.active[i] != 0 && c.info.active[i] != 1) || !std::isfinite(c.info.traction[i]))
        throw std::runtime_error("its contact state of gap pair " + std::to_string(i) +
                                 " is out of range (active not 0 or 1, or a traction that is not "
                                 "a finite number): a damaged checkpoint");
    if (H5Lexists(file, "solver", H5P_DEFAULT) > 0)
    {
      const H5 solver(H5Gopen2(file, "solver", H5P_DEFAULT), H5Gclose, "group solver");
      c.info.preconditioner_origin =
          read_row(solver, "preconditioner_origin", comm.getSize(), comm.getRank());
    }
    saved_state = read_saved_quadrature_state(file, f.n_cells);
  }
  catch (const std::exception &e)
  {
    error = e.what();
  }
  check_collectively(comm, difference.empty(), path,
                     "cannot continue this run from the checkpoint: " + difference +
                         " (the checkpoint was written by " + c.info.input_path + ")");
  check_collectively(comm, error.empty(), path,
                     "cannot read the checkpoint: " + error +
                         ". Give a checkpoint written by Kiln/Checkpoint (a file NAME-NNNNNN.h5 "
                         "or NAME.h5 of its \"File Base\")");
  restore_quadrature_state(path, c.info.kiln_version, saved_state, quadrature_state, comm);
  // The owned unknowns.
  TimeStepper::State &state = c.state;
  for (auto *target : {&state.x, &state.x_1, &state.x_2})
    *target = Teuchos::rcp(new Tpetra::Vector<>(map));
  const std::vector<double> *sources[] = {&x, &x_1, &x_2};
  Teuchos::RCP<Tpetra::Vector<>> targets[] = {state.x, state.x_1, state.x_2};
  for (int v = 0; v < 3; ++v)
  {
    auto values = targets[v]->getDataNonConst();
    for (std::size_t i = 0; i < map->getNodeNumElements(); ++i)
      values[i] = (*sources[v])[map->getGlobalElement(static_cast<LO>(i))];
  }
  return c;
}
} // namespace kiln
