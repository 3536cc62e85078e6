#include "io/results_replay.hpp"

#include "base/errors.hpp"
#include "io/field_catalog.hpp"
#include "io/h5_handle.hpp"
#include "io/hdf5_errors.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <map>
#include <stdexcept>

namespace kiln
{
namespace internal
{
namespace
{
/// The names of the links in a group, in name order.
std::vector<std::string> links_of(const hid_t group)
{
  std::vector<std::string> names;
  H5Literate(
      group, H5_INDEX_NAME, H5_ITER_INC, nullptr,
      [](hid_t, const char *name, const H5L_info_t *, void *data) -> herr_t
      {
        static_cast<std::vector<std::string> *>(data)->emplace_back(name);
        return 0;
      },
      &names);
  return names;
}

/// The values of the dataset `name` in `group` as `T` (double or int64), all its rows.
template <typename T> std::vector<T> read_all(const hid_t group, const std::string &name)
{
  const H5Handle set(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose);
  const H5Handle space(set.valid() ? H5Dget_space(set.get()) : H5I_INVALID_HID, H5Sclose);
  if (!space.valid())
    throw std::runtime_error("cannot open " + name);
  std::vector<T> values(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space.get())));
  if (H5Dread(set.get(), std::is_same_v<T, double> ? H5T_NATIVE_DOUBLE : H5T_NATIVE_INT64, H5S_ALL,
              H5S_ALL, H5P_DEFAULT, values.data()) < 0)
    throw std::runtime_error("cannot read " + name);
  return values;
}

/// The gap fields of step `step` in the file's gap surfaces (/gap, /gap_ID), per pair of
/// `gap_pairs` ((node_a, node_b) of Mesh::gap_pairs; NaN where no surface has the pair).
std::vector<std::pair<std::string, std::vector<double>>>
read_gap_fields(const hid_t file, const std::string &step,
                const std::vector<std::pair<int, int>> &gap_pairs)
{
  std::vector<std::pair<std::string, std::vector<double>>> fields;
  if (gap_pairs.empty())
    return fields;
  std::map<std::pair<int, int>, std::size_t> pair_of;
  for (std::size_t p = 0; p < gap_pairs.size(); ++p)
    pair_of[gap_pairs[p]] = p;
  for (const std::string &surface : links_of(file))
  {
    if (surface != "gap" && surface.rfind("gap_", 0) != 0)
      continue;
    const H5Handle group(H5Gopen2(file, (surface + "/steps/" + step).c_str(), H5P_DEFAULT),
                         H5Gclose);
    if (!group.valid())
      continue;
    const H5Handle points(H5Gopen2(file, surface.c_str(), H5P_DEFAULT), H5Gclose);
    const std::vector<std::int64_t> a = read_all<std::int64_t>(points.get(), "node_a");
    const std::vector<std::int64_t> b = read_all<std::int64_t>(points.get(), "node_b");
    for (const char *name : {"gap_opening", "contact_pressure", "contact_active", "gap_heat_flux"})
    {
      if (H5Lexists(group.get(), name, H5P_DEFAULT) <= 0)
        continue;
      const std::vector<double> values = read_all<double>(group.get(), name);
      auto at = std::find_if(fields.begin(), fields.end(),
                             [&](const auto &f) { return f.first == name; });
      if (at == fields.end())
        at = fields.insert(fields.end(),
                           {name, std::vector<double>(gap_pairs.size(),
                                                      std::numeric_limits<double>::quiet_NaN())});
      for (std::size_t p = 0; p < values.size() && p < a.size() && p < b.size(); ++p)
        if (const auto it = pair_of.find({static_cast<int>(a[p]), static_cast<int>(b[p])});
            it != pair_of.end())
          at->second[it->second] = values[p];
    }
  }
  return fields;
}

template <typename T> T read_attribute(const hid_t object, const char *name)
{
  const H5Handle a(H5Aopen(object, name, H5P_DEFAULT), H5Aclose);
  T value{};
  if (!a.valid() ||
      H5Aread(a.get(), std::is_same_v<T, double> ? H5T_NATIVE_DOUBLE : H5T_NATIVE_INT, &value) < 0)
    throw std::runtime_error(std::string("cannot read the attribute ") + name);
  return value;
}
} // namespace
} // namespace internal

int internal::write_replayed(const std::string &path, const std::string &error,
                             const std::vector<ReplayStep> &steps,
                             const std::vector<ResultsWriter *> &writers,
                             const Teuchos::Comm<int> &comm)
{
  check_collectively(comm, error.empty(), path,
                     "cannot continue the results of the earlier run from this file: " + error);
  for (const ReplayStep &step : steps)
    for (ResultsWriter *writer : writers)
    {
      writer->begin_step(step.time, step.cycle, step.dt);
      for (const auto &[name, per_pair] : step.gap_fields)
        writer->write_gap_field(name, per_pair);
      for (const ReplayField &f : step.fields)
        if (f.on_nodes)
          writer->write_node_field(f.name, f.n_components, f.values);
        else
          writer->write_cell_field(f.name, f.n_components, f.values);
      writer->end_step();
    }
  return static_cast<int>(steps.size());
}

ResultsSummary results_summary(const std::string &path)
{
  using internal::H5Handle;
  ResultsSummary summary{"", -std::numeric_limits<double>::infinity()};
  {
    const internal::QuietHdf5Errors quiet;
    const H5Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
    const H5Handle a(file.valid() && H5Aexists(file.get(), "run_fingerprint") > 0
                         ? H5Aopen(file.get(), "run_fingerprint", H5P_DEFAULT)
                         : H5I_INVALID_HID,
                     H5Aclose);
    const H5Handle type(a.valid() ? H5Aget_type(a.get()) : H5I_INVALID_HID, H5Tclose);
    if (type.valid() && H5Tget_class(type.get()) == H5T_STRING &&
        H5Tis_variable_str(type.get()) == 0)
    {
      std::string text(H5Tget_size(type.get()), '\0');
      if (H5Aread(a.get(), type.get(), text.data()) >= 0)
        summary.run_fingerprint = text.substr(0, text.find('\0'));
    }
    const H5Handle all(file.valid() ? H5Gopen2(file.get(), "steps", H5P_DEFAULT) : H5I_INVALID_HID,
                       H5Gclose);
    if (all.valid())
      for (const std::string &name : internal::links_of(all.get()))
        try
        {
          const H5Handle group(H5Gopen2(all.get(), name.c_str(), H5P_DEFAULT), H5Gclose);
          summary.end_time =
              std::max(summary.end_time, internal::read_attribute<double>(group.get(), "time"));
        }
        catch (const std::runtime_error &)
        {
          // A step without its time (cut off while it was begun) ends nothing.
        }
  }
  return summary;
}

int replay_results(const std::string &path, const double until, const ReplayRows &rows,
                   const std::vector<ResultsWriter *> &writers, const Teuchos::Comm<int> &comm)
{
  using internal::H5Handle;
  using Field = internal::ReplayField;
  using Step = internal::ReplayStep;
  // Every rank reads the steps (serial HDF5, read-only), then each writes its rows.
  std::vector<Step> steps;
  std::string error;
  try
  {
    const internal::QuietHdf5Errors quiet;
    const H5Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
    if (!file.valid())
      throw std::runtime_error("not a readable HDF5 file");
    const H5Handle all(H5Gopen2(file.get(), "steps", H5P_DEFAULT), H5Gclose);
    if (!all.valid())
      throw std::runtime_error("no /steps group: not a Kiln results file");
    for (const std::string &name : internal::links_of(all.get()))
    {
      const H5Handle group(H5Gopen2(all.get(), name.c_str(), H5P_DEFAULT), H5Gclose);
      Step step{internal::read_attribute<double>(group.get(), "time"),
                internal::read_attribute<double>(group.get(), "dt"),
                internal::read_attribute<int>(group.get(), "cycle"),
                {},
                {}};
      if (step.time > until + 1e-12 * std::max(1.0, std::abs(until)))
        break;
      for (const std::string &field : internal::links_of(group.get()))
      {
        const H5Handle set(H5Dopen2(group.get(), field.c_str(), H5P_DEFAULT), H5Dclose);
        const H5Handle space(H5Dget_space(set.get()), H5Sclose);
        hsize_t dims[2] = {0, 1};
        const int rank = H5Sget_simple_extent_ndims(space.get());
        H5Sget_simple_extent_dims(space.get(), dims, nullptr);
        const FieldDescription *known = describe_field(field);
        const bool on_nodes =
            known != nullptr ? known->on_nodes : dims[0] == static_cast<hsize_t>(rows.n_nodes);
        if (rank < 1 || rank > 2 ||
            dims[0] != static_cast<hsize_t>(on_nodes ? rows.n_nodes : rows.n_cells))
          throw std::runtime_error("step " + name + "/" + field + " has " +
                                   std::to_string(dims[0]) +
                                   " rows, which fit neither this mesh's nodes nor its cells");
        const int n_components = rank == 2 ? static_cast<int>(dims[1]) : 1;
        std::vector<double> all_rows(dims[0] * static_cast<hsize_t>(n_components));
        if (H5Dread(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, all_rows.data()) <
            0)
          throw std::runtime_error("cannot read step " + name + "/" + field);
        // Files before changelog 0032 hold minus the contact pressure as gap_normal_traction:
        // continued as contact_pressure, the field of the new steps.
        const bool traction = field == "gap_normal_traction";
        Field f{traction ? "contact_pressure" : field, on_nodes, n_components, {}};
        for (const int r : on_nodes ? rows.owned_nodes : rows.owned_cells)
          f.values.insert(f.values.end(), all_rows.begin() + std::size_t(r) * n_components,
                          all_rows.begin() + std::size_t(r + 1) * n_components);
        if (traction)
          for (double &v : f.values)
            v = -v + 0.0;
        step.fields.push_back(std::move(f));
      }
      step.gap_fields = internal::read_gap_fields(file.get(), name, rows.gap_pairs);
      steps.push_back(std::move(step));
    }
  }
  catch (const std::exception &e)
  {
    error = e.what();
  }
  return internal::write_replayed(path, error, steps, writers, comm);
}
} // namespace kiln
