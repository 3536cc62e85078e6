#include "io/exodus_results_writer.hpp"

#include "io/collective_checks.hpp"
#include "io/exodus_results_file.hpp"
#include "io/exodus_variables.hpp"
#include "io/history_csv.hpp"
#include "io/row_gather.hpp"

#include "base/errors.hpp"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <utility>

namespace kiln
{
using internal::Center;
using internal::ExodusVariables;
using internal::FieldSpec;

std::vector<std::string> ExodusResultsWriter::variable_names(const std::string &name,
                                                             const int n_components)
{
  return ExodusVariables::names(name, n_components);
}

std::vector<int> ExodusResultsWriter::variable_components(const int n_components)
{
  return ExodusVariables::components(n_components);
}

/// Every rank: the file's variables and the step in progress. Rank 0 also holds the file and
/// the step's gathered values (per step field, component after component, each in global-id
/// order, as RowGather gives them).
struct ExodusResultsWriter::Impl
{
  Impl(MPI_Comm comm, const std::string &base_path, const Mesh &mesh,
       const std::vector<int> &owned_nodes, const std::vector<int> &owned_cells);

  void check_field(const FieldSpec &field) const;
  void write_field(const FieldSpec &field, const std::vector<double> &values);
  /// Rank 0: the variables at the first step, then the step with its gathered `values`.
  void write_step(bool first_step, const std::vector<std::vector<double>> &values,
                  const std::vector<double> &globals) const;
  /// The global variables of the step being ended: the last history row if it is this
  /// step's (its "step" is the cycle), else step, time and dt with NaN for the rest, and the
  /// step waits in `pending` for its row.
  std::vector<double> step_globals();

  MPI_Comm comm;
  int rank = 0;
  std::string base;
  std::string path;
  internal::RowGather node_rows;
  internal::RowGather cell_rows;
  ExodusVariables variables;
  bool in_step = false;
  int n_steps = 0;
  double time = 0.0;
  int cycle = 0;
  double dt = 0.0;
  std::vector<FieldSpec> step_fields;
  std::vector<std::vector<double>> step_values;
  std::vector<double> last_row; ///< the last history row given, or empty
  /// Written output steps without their history row yet: (cycle, output step index).
  std::vector<std::pair<int, int>> pending;
  std::size_t n_columns = 0; ///< of the history: history_columns(mesh's gaps)
  std::unique_ptr<internal::ExodusResultsFile> file;
};

ExodusResultsWriter::Impl::Impl(const MPI_Comm communicator, const std::string &base_path,
                                const Mesh &mesh, const std::vector<int> &owned_nodes,
                                const std::vector<int> &owned_cells)
    : comm(communicator), base(base_path), path(base_path + ".running.exo"),
      node_rows(communicator, owned_nodes, mesh.n_nodes()),
      cell_rows(communicator, owned_cells, mesh.n_cells()),
      n_columns(history_columns(mesh.gap_side_sets, mesh.contact_pair_names()).size())
{
  MPI_Comm_rank(comm, &rank);
}

/// The checks every rank makes alike (the calls are collective, with the same arguments but
/// the values), so each throws the same InternalError without communication.
void ExodusResultsWriter::Impl::check_field(const FieldSpec &field) const
{
  const std::string &name = field.name;
  internal::check_write_field(in_step, field);
  internal::check_usage(internal::is_valid_field_name(name), "is_valid_field_name(name)",
                        "field name \"" + name +
                            "\" is not valid: use letters, digits, '_', '-' and '.'");
  internal::check_usage(field.n_components >= 1, "n_components >= 1",
                        std::string(internal::kind_of(field.center)) + " field \"" + name +
                            "\" has " + std::to_string(field.n_components) +
                            " components; need >= 1");
  for (const auto &f : step_fields)
    internal::check_usage(f.name != name, "field written once per step",
                          "field \"" + name + "\" is written twice in step " +
                              std::to_string(n_steps));
  variables.check_field(field, step_fields);
}

void ExodusResultsWriter::Impl::write_field(const FieldSpec &field,
                                            const std::vector<double> &values)
{
  check_field(field);
  const internal::RowGather &rows = field.center == Center::node ? node_rows : cell_rows;
  internal::check_field_size(comm, field, rows.n_owned(), values.size());
  std::vector<double> gathered = rows.to_rank_zero(values, field.n_components);
  if (rank == 0)
    step_values.push_back(std::move(gathered));
  step_fields.push_back(field);
}

namespace
{
/// The index of the history column `name`.
std::size_t history_column(const std::string &name)
{
  const auto &columns = history_columns();
  const auto it = std::find_if(columns.begin(), columns.end(),
                               [&](const HistoryColumn &c) { return c.name == name; });
  KILN_ASSERT(it != columns.end(), name);
  return static_cast<std::size_t>(it - columns.begin());
}
} // namespace

std::vector<double> ExodusResultsWriter::Impl::step_globals()
{
  const std::size_t step_column = history_column("step");
  if (!last_row.empty() && last_row[step_column] == cycle)
    return last_row;
  std::vector<double> globals(n_columns, std::numeric_limits<double>::quiet_NaN());
  globals[step_column] = cycle;
  globals[history_column("time")] = time;
  globals[history_column("dt")] = dt;
  pending.emplace_back(cycle, n_steps);
  return globals;
}

void ExodusResultsWriter::Impl::write_step(const bool first_step,
                                           const std::vector<std::vector<double>> &values,
                                           const std::vector<double> &globals) const
{
  if (first_step)
    file->define_variables(variables);
  file->write_step({n_steps, time, globals, step_fields, values}, variables);
}

ExodusResultsWriter::ExodusResultsWriter(const MPI_Comm comm, const std::string &base_path,
                                         const Mesh &mesh, const std::vector<int> &owned_nodes,
                                         const std::vector<int> &owned_cells,
                                         const std::vector<int> &cell_rank,
                                         const ResultsMetadata &metadata)
{
  // The ownership must be a partition of the rows; a mistake here is the caller's.
  internal::check_row_partition(comm, mesh, owned_nodes, owned_cells, cell_rank);
  impl_ = std::make_unique<Impl>(comm, base_path, mesh, owned_nodes, owned_cells);
  Impl &m = *impl_;
  internal::run_on_rank_zero(comm,
                             [&]
                             {
                               m.file = std::make_unique<internal::ExodusResultsFile>(
                                   m.path, mesh, cell_rank, metadata.run_fingerprint);
                             });
}

ExodusResultsWriter::~ExodusResultsWriter() = default;

void ExodusResultsWriter::begin_step(const double time, const int cycle, const double dt)
{
  Impl &m = *impl_;
  internal::check_begin_step(m.in_step);
  m.in_step = true;
  m.time = time;
  m.cycle = cycle;
  m.dt = dt;
  m.step_fields.clear();
  m.step_values.clear();
}

void ExodusResultsWriter::write_node_field(const std::string &name, const int n_components,
                                           const std::vector<double> &values)
{
  impl_->write_field({name, Center::node, n_components}, values);
}

void ExodusResultsWriter::write_cell_field(const std::string &name, const int n_components,
                                           const std::vector<double> &values)
{
  impl_->write_field({name, Center::cell, n_components}, values);
}

/// Every step writes the fields of the first (Exodus defines the variables once).
void ExodusResultsWriter::end_step()
{
  Impl &m = *impl_;
  internal::check_end_step(m.in_step);
  m.in_step = false;
  if (m.variables.defined() && m.step_fields.size() != m.variables.fields().size())
    internal::check_usage(false, "every field of the first step written",
                          "step " + std::to_string(m.n_steps) + " does not write " +
                              m.variables.missing_from(m.step_fields) +
                              ", written in the first step; Exodus defines its variables "
                              "once, so every step must write the fields of the first step");
  const bool first_step = !m.variables.defined();
  if (first_step)
    m.variables.define(m.step_fields);
  std::vector<std::vector<double>> values;
  values.swap(m.step_values); // released when this call ends, written or not
  const std::vector<double> globals = m.step_globals();
  internal::run_on_rank_zero(m.comm, [&] { m.write_step(first_step, values, globals); });
  ++m.n_steps;
}

/// The row of a written step (a continued run's earlier steps, replayed before their rows
/// are read) completes its global variables; rows of steps not written are kept until the
/// next end_step().
void ExodusResultsWriter::write_history(const std::vector<double> &row)
{
  Impl &m = *impl_;
  internal::check_usage(row.size() == m.n_columns, "row.size() == n_columns",
                        "a history row needs one value per column of "
                        "history_columns(mesh.gap_side_sets, mesh.contact_pair_names())");
  m.last_row = row;
  const double step = row[history_column("step")];
  std::vector<int> complete; // output steps of this row
  for (const auto &[cycle, index] : m.pending)
    if (cycle == step)
      complete.push_back(index);
  // Rows come in increasing step order: a pending step before this row has lost its row.
  m.pending.erase(std::remove_if(m.pending.begin(), m.pending.end(),
                                 [&](const std::pair<int, int> &p) { return p.first <= step; }),
                  m.pending.end());
  if (!complete.empty())
    internal::run_on_rank_zero(m.comm,
                               [&]
                               {
                                 for (const int index : complete)
                                   m.file->write_globals(index, row);
                               });
}

void ExodusResultsWriter::set_final_base(const std::string &final_base)
{
  impl_->base = final_base;
}

void ExodusResultsWriter::finish(const std::string & /*status*/)
{
  Impl &m = *impl_;
  if (m.in_step) // the same on every rank: the calls are collective
    throw InternalError(m.path + ": finish() while a step is open; call end_step() first");
  const std::string final_path = m.base + ".exo";
  internal::run_on_rank_zero(m.comm,
                             [&]
                             {
                               m.file.reset();
                               KILN_CHECK_INPUT(
                                   std::rename(m.path.c_str(), final_path.c_str()) == 0, final_path,
                                   "cannot rename " << m.path
                                                    << " to its final name; check "
                                                       "the folder's permissions");
                             });
  m.path = final_path;
}

std::string ExodusResultsWriter::exo_path() const
{
  return impl_->path;
}
} // namespace kiln
