#include "io/exodus_results_replay.hpp"

#include "base/errors.hpp"
#include "io/exodus_variables.hpp"
#include "io/field_catalog.hpp"
#include "mesh/exodus_io.hpp"

#include <exodusII.h>
#include <netcdf.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace kiln
{
namespace
{
/// A field of the file: its name, its variables (1-based Exodus indices) and where each goes.
struct ExodusField
{
  std::string name;
  int n_components;
  int first_variable; ///< 1-based; the field's variables follow it
};

/// The Exodus file open for reading; closed on every way out.
class ExodusReader
{
public:
  explicit ExodusReader(const std::string &path)
  {
    int comp_ws = sizeof(double), io_ws = 0;
    float version = 0.0F;
    exo_ = ex_open(path.c_str(), EX_READ, &comp_ws, &io_ws, &version);
    if (exo_ < 0)
      throw std::runtime_error("not a readable Exodus file");
  }
  ~ExodusReader() { ex_close(exo_); }
  ExodusReader(const ExodusReader &) = delete;
  ExodusReader &operator=(const ExodusReader &) = delete;
  int id() const { return exo_; }

  /// The names of the variables of `type`.
  std::vector<std::string> names(const ex_entity_type type) const
  {
    int n = 0;
    if (ex_get_variable_param(exo_, type, &n) < 0)
      throw std::runtime_error("cannot read the number of variables");
    std::vector<std::vector<char>> buffers(static_cast<std::size_t>(n),
                                           std::vector<char>(MAX_STR_LENGTH + 1, '\0'));
    std::vector<char *> pointers;
    for (auto &b : buffers)
      pointers.push_back(b.data());
    if (n > 0 && ex_get_variable_names(exo_, type, n, pointers.data()) < 0)
      throw std::runtime_error("cannot read the names of the variables");
    std::vector<std::string> result;
    for (const auto &b : buffers)
      result.emplace_back(b.data());
    return result;
  }

private:
  int exo_ = -1;
};

/// The variables `names` grouped back into fields (ExodusVariables::names() in reverse).
std::vector<ExodusField> fields_of(const std::vector<std::string> &names)
{
  std::vector<ExodusField> fields;
  for (std::size_t i = 0; i < names.size();)
  {
    ExodusField field{names[i], 1, static_cast<int>(i) + 1};
    for (std::size_t p = names[i].rfind('_');
         p != std::string::npos && p > 0 && field.n_components == 1; p = names[i].rfind('_', p - 1))
    {
      const std::string base = names[i].substr(0, p);
      const FieldDescription *known = describe_field(base);
      for (const int n : {known != nullptr ? known->n_components() : 0, 3, 6})
      {
        if (n < 2 || i + static_cast<std::size_t>(n) > names.size())
          continue;
        const std::vector<std::string> expected = internal::ExodusVariables::names(base, n);
        if (std::equal(expected.begin(), expected.end(), names.begin() + static_cast<long>(i)))
        {
          field = {base, n, static_cast<int>(i) + 1};
          break;
        }
      }
    }
    fields.push_back(field);
    i += static_cast<std::size_t>(field.n_components);
  }
  return fields;
}
} // namespace

ResultsSummary exodus_results_summary(const std::string &path)
{
  ResultsSummary summary{"", -std::numeric_limits<double>::infinity()};
  try
  {
    const ExodusReader file(path);
    const int exo = file.id();
    std::size_t length = 0;
    nc_type type = NC_NAT;
    if (nc_inq_att(exo, NC_GLOBAL, "run_fingerprint", &type, &length) == NC_NOERR &&
        type == NC_CHAR)
    {
      std::string text(length, '\0');
      if (nc_get_att_text(exo, NC_GLOBAL, "run_fingerprint", text.data()) == NC_NOERR)
        summary.run_fingerprint = text.substr(0, text.find('\0'));
    }
    const int n_steps = static_cast<int>(ex_inquire_int(exo, EX_INQ_TIME));
    std::vector<double> times(static_cast<std::size_t>(std::max(n_steps, 0)));
    if (n_steps > 0 && ex_get_all_times(exo, times.data()) >= 0)
      for (const double t : times)
        summary.end_time = std::max(summary.end_time, t);
  }
  catch (const std::runtime_error &)
  {
    // Not a readable Exodus file: no fingerprint, no steps.
  }
  return summary;
}

int replay_exodus_results(const std::string &path, const double until, const Mesh &mesh,
                          const ReplayRows &rows, const std::vector<ResultsWriter *> &writers,
                          const Teuchos::Comm<int> &comm)
{
  using Field = internal::ReplayField;
  using Step = internal::ReplayStep;
  std::vector<Step> steps;
  std::string error;
  try
  {
    // Every rank reads the file (read-only), then writes its rows.
    const ExodusReader file(path);
    const int exo = file.id();
    const int n_file_nodes = static_cast<int>(ex_inquire_int(exo, EX_INQ_NODES));
    const int n_file_cells = static_cast<int>(ex_inquire_int(exo, EX_INQ_ELEM));
    if (n_file_nodes != rows.n_nodes || n_file_cells != rows.n_cells)
      throw std::runtime_error("it has " + std::to_string(n_file_cells) + " cells and " +
                               std::to_string(n_file_nodes) + " nodes, this mesh " +
                               std::to_string(rows.n_cells) + " and " +
                               std::to_string(rows.n_nodes));
    const ExodusLayout layout = exodus_layout(mesh, mesh.gap_side_sets);
    const int n_steps = static_cast<int>(ex_inquire_int(exo, EX_INQ_TIME));
    std::vector<double> times(static_cast<std::size_t>(std::max(n_steps, 0)));
    if (n_steps > 0 && ex_get_all_times(exo, times.data()) < 0)
      throw std::runtime_error("cannot read the times of the steps");
    const std::vector<std::string> global_names = file.names(EX_GLOBAL);
    const auto global_index = [&](const std::string &name)
    {
      for (std::size_t g = 0; g < global_names.size(); ++g)
        if (global_names[g] == name)
          return static_cast<int>(g);
      throw std::runtime_error("no global variable \"" + name + "\": not a Kiln results file");
    };
    const int step_global = n_steps > 0 ? global_index("step") : 0;
    const int dt_global = n_steps > 0 ? global_index("dt") : 0;
    const std::vector<ExodusField> node_fields = fields_of(file.names(EX_NODAL));
    const std::vector<ExodusField> cell_fields = fields_of(file.names(EX_ELEM_BLOCK));
    std::vector<double> globals(global_names.size());
    for (int s = 0; s < n_steps; ++s)
    {
      if (times[s] > until + 1e-12 * std::max(1.0, std::abs(until)))
        break;
      if (!globals.empty() && ex_get_var(exo, s + 1, EX_GLOBAL, 1, 0,
                                         static_cast<int64_t>(globals.size()), globals.data()) < 0)
        throw std::runtime_error("cannot read the global variables of step " +
                                 std::to_string(s + 1));
      Step step{times[s],
                globals[dt_global],
                static_cast<int>(std::lround(globals[step_global])),
                {},
                {}};
      const auto read = [&](const ExodusField &f, const bool on_nodes)
      {
        const int n_rows = on_nodes ? rows.n_nodes : rows.n_cells;
        std::vector<double> all(static_cast<std::size_t>(n_rows) * f.n_components);
        std::vector<double> variable;
        for (int k = 0; k < f.n_components; ++k)
        {
          const auto put = [&](const std::vector<int> *cells)
          {
            for (std::size_t r = 0; r < variable.size(); ++r)
              all[static_cast<std::size_t>(cells != nullptr ? (*cells)[r] : static_cast<int>(r)) *
                      f.n_components +
                  k] = variable[r];
          };
          if (on_nodes)
          {
            variable.resize(static_cast<std::size_t>(n_rows));
            if (ex_get_var(exo, s + 1, EX_NODAL, f.first_variable + k, 1, n_rows, variable.data()) <
                0)
              throw std::runtime_error("cannot read " + f.name + " of step " +
                                       std::to_string(s + 1));
            put(nullptr);
          }
          else
            for (std::size_t b = 0; b < layout.block_ids.size(); ++b)
            {
              variable.resize(layout.block_cells[b].size());
              if (ex_get_var(exo, s + 1, EX_ELEM_BLOCK, f.first_variable + k, layout.block_ids[b],
                             static_cast<int64_t>(variable.size()), variable.data()) < 0)
                throw std::runtime_error("cannot read " + f.name + " of step " +
                                         std::to_string(s + 1) + " in block " +
                                         std::to_string(layout.block_ids[b]));
              put(&layout.block_cells[b]);
            }
        }
        Field mine{f.name, on_nodes, f.n_components, {}};
        for (const int r : on_nodes ? rows.owned_nodes : rows.owned_cells)
          mine.values.insert(mine.values.end(), all.begin() + std::size_t(r) * f.n_components,
                             all.begin() + std::size_t(r + 1) * f.n_components);
        step.fields.push_back(std::move(mine));
      };
      for (const ExodusField &f : node_fields)
        read(f, true);
      for (const ExodusField &f : cell_fields)
        read(f, false);
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
