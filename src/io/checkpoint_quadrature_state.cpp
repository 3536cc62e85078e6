#include "io/checkpoint_quadrature_state.hpp"

#include "base/errors.hpp"
#include "discretization/dof_manager.hpp"
#include "io/checkpoint_h5.hpp"
#include "io/row_gather.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultMpiComm.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace kiln
{
namespace internal
{
namespace
{
/// The first point of each cell in global cell order, and the number of all (the last entry).
std::vector<GO> point_offsets(const std::vector<int> &points)
{
  std::vector<GO> offsets(points.size() + 1, 0);
  for (std::size_t c = 0; c < points.size(); ++c)
    offsets[c + 1] = offsets[c] + points[c];
  return offsets;
}

MPI_Comm raw_mpi_comm(const Teuchos::Comm<int> &comm)
{
  return *dynamic_cast<const Teuchos::MpiComm<int> &>(comm).getRawMpiComm();
}

/// The names of `names` that `others` lacks, joined ("a, b"), or "".
std::string missing_from(const std::vector<std::string> &names,
                         const std::vector<std::string> &others)
{
  std::string missing;
  for (const std::string &name : names)
    if (std::find(others.begin(), others.end(), name) == others.end())
      missing += (missing.empty() ? "" : ", ") + name;
  return missing;
}

} // namespace

std::vector<int> points_per_cell(const QuadratureState &qs, const int n_cells,
                                 const Teuchos::Comm<int> &comm)
{
  std::vector<int> local(static_cast<std::size_t>(n_cells), 0), global(local.size(), 0);
  for (int c = 0; c < qs.n_cells(); ++c)
    local[static_cast<std::size_t>(qs.cells()[c])] = qs.n_points(c);
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, n_cells, local.data(), global.data());
  return global;
}

std::vector<std::vector<double>> gather_quadrature_state(const QuadratureState &qs,
                                                         const std::vector<int> &points,
                                                         const Teuchos::Comm<int> &comm)
{
  const std::vector<GO> offsets = point_offsets(points);
  std::vector<int> ids;
  ids.reserve(static_cast<std::size_t>(qs.n_points()));
  for (int c = 0; c < qs.n_cells(); ++c)
    for (int q = 0; q < qs.n_points(c); ++q)
      ids.push_back(static_cast<int>(offsets[static_cast<std::size_t>(qs.cells()[c])] + q));
  const RowGather rows(raw_mpi_comm(comm), ids, static_cast<int>(offsets.back()));
  std::vector<std::vector<double>> gathered;
  for (int k = 0; k < qs.n_state(); ++k)
    gathered.push_back(rows.to_rank_zero(qs.old_component(k), 1));
  return gathered;
}

void write_quadrature_state(const hid_t file, const std::vector<std::string> &names,
                            const std::vector<int> &points,
                            const std::vector<std::vector<double>> &components)
{
  const H5 q(H5Gcreate2(file, "quadrature_state", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
             "group quadrature_state");
  write_attribute(q, "n_components", static_cast<int>(names.size()));
  write_array(q, "points_per_cell", points, 1);
  const H5 values(H5Gcreate2(q, "components", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
                  "group quadrature_state/components");
  for (std::size_t k = 0; k < names.size(); ++k)
  {
    write_attribute(q, "component_" + std::to_string(k), names[k]);
    write_array(values, names[k], components[k], 1);
  }
}

void verify_quadrature_state(
    const hid_t file,
    const std::vector<std::pair<std::string, const std::vector<double> *>> &components)
{
  if (components.empty())
    return;
  const H5 values(H5Gopen2(file, "quadrature_state/components", H5P_DEFAULT), H5Gclose,
                  "reading group quadrature_state/components back");
  for (const auto &[name, written] : components)
  {
    const std::vector<double> read = read_array<double>(values, name, written->size());
    if (!read.empty() &&
        std::memcmp(read.data(), written->data(), read.size() * sizeof(double)) != 0)
      throw std::runtime_error("dataset quadrature_state/components/" + name +
                               " read back differs from what was written");
  }
}

SavedQuadratureState read_saved_quadrature_state(const hid_t file, const int n_cells)
{
  SavedQuadratureState saved;
  if (H5Lexists(file, "quadrature_state", H5P_DEFAULT) <= 0)
    return saved;
  saved.present = true;
  const H5 group(H5Gopen2(file, "quadrature_state", H5P_DEFAULT), H5Gclose,
                 "group quadrature_state");
  const int n = read_attribute<int>(group, "n_components");
  if (n < 1 || n > 10000)
    throw std::runtime_error("its attribute quadrature_state/n_components = " + std::to_string(n) +
                             " is out of range: a damaged checkpoint");
  saved.points = read_array<int>(group, "points_per_cell", static_cast<std::size_t>(n_cells));
  std::size_t total = 0;
  for (const int p : saved.points)
  {
    if (p < 0)
      throw std::runtime_error("its dataset quadrature_state/points_per_cell holds a negative "
                               "count: a damaged checkpoint");
    total += static_cast<std::size_t>(p);
  }
  const H5 components(H5Gopen2(group, "components", H5P_DEFAULT), H5Gclose,
                      "group quadrature_state/components");
  for (int k = 0; k < n; ++k)
  {
    saved.names.push_back(read_string(group, "component_" + std::to_string(k), true));
    saved.components.push_back(read_array<double>(components, saved.names.back(), total));
    const std::vector<double> &values = saved.components.back();
    if (!std::all_of(values.begin(), values.end(), [](const double v) { return std::isfinite(v); }))
      throw std::runtime_error("its state at quadrature points (quadrature_state/components/" +
                               saved.names.back() +
                               ") holds values that are not finite numbers (NaN or Inf): a "
                               "damaged checkpoint");
  }
  return saved;
}

void restore_quadrature_state(const std::string &path, const std::string &version,
                              const SavedQuadratureState &saved, QuadratureState *qs,
                              const Teuchos::Comm<int> &comm)
{
  const std::vector<std::string> none;
  const std::vector<std::string> &names = qs != nullptr ? qs->names() : none;
  const std::string start_anew = "; continue it with the Kiln that wrote it (" + version +
                                 "), or start this run anew (without --restart)";
  check_collectively(comm, saved.present || qs == nullptr, path,
                     "the checkpoint holds no state at the quadrature points, which this run's "
                     "constitutive models need (components " +
                         missing_from(names, {}) +
                         "): it was written by a run whose models kept none" + start_anew);
  check_collectively(comm, !saved.present || qs != nullptr, path,
                     "the checkpoint holds state at the quadrature points (components " +
                         missing_from(saved.names, {}) +
                         ") that this run's constitutive models do not declare: the run would "
                         "not continue as the one that wrote it" +
                         start_anew);
  if (qs == nullptr)
    return;
  const std::string lacking = missing_from(names, saved.names);
  check_collectively(comm, lacking.empty(), path,
                     "the checkpoint's state at the quadrature points lacks the components " +
                         lacking + " that this run's constitutive models need" + start_anew);
  const std::string extra = missing_from(saved.names, names);
  check_collectively(comm, extra.empty(), path,
                     "the checkpoint's state at the quadrature points has the components " + extra +
                         " that this run's constitutive models do not declare" + start_anew);
  const std::vector<GO> offsets = point_offsets(saved.points);
  std::string differs;
  for (int c = 0; c < qs->n_cells() && differs.empty(); ++c)
  {
    const int g = qs->cells()[c];
    if (saved.points[static_cast<std::size_t>(g)] != qs->n_points(c))
      differs = "cell " + std::to_string(g) + " (from 0) has " +
                std::to_string(saved.points[static_cast<std::size_t>(g)]) +
                " quadrature points with state in the checkpoint and " +
                std::to_string(qs->n_points(c)) + " in this run: its element or its model differs" +
                start_anew;
  }
  check_collectively(comm, differs.empty(), path, differs);
  for (int k = 0; k < qs->n_state(); ++k)
  {
    const auto at = std::find(saved.names.begin(), saved.names.end(), qs->names()[k]);
    const std::vector<double> &all =
        saved.components[static_cast<std::size_t>(at - saved.names.begin())];
    std::vector<double> values;
    values.reserve(static_cast<std::size_t>(qs->n_points()));
    for (int c = 0; c < qs->n_cells(); ++c)
      for (int q = 0; q < qs->n_points(c); ++q)
        values.push_back(all[static_cast<std::size_t>(offsets[qs->cells()[c]] + q)]);
    qs->set_component(k, values);
  }
}
} // namespace internal
} // namespace kiln
