#include "io/exodus_results_writer.hpp"

#include "base/errors.hpp"
#include "mesh/exodus_io.hpp"

#include <Teuchos_DefaultMpiComm.hpp>
#include <exodusII.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <set>
#include <sstream>
#include <utility>

namespace kiln
{
namespace internal
{
namespace // file-local: these names must not clash with other files' kiln::internal helpers
{
/// Longest variable, block or set name the results file can hold (Exodus fixes it when
/// the file is defined, before the variables are known).
constexpr int results_name_length = 64;

enum class Center
{
  node,
  cell
};

struct FieldSpec
{
  std::string name;
  Center center = Center::node;
  int n_components = 1;
};

const char *kind_of(const Center center)
{
  return center == Center::node ? "node" : "cell";
}

/// True on every rank if `local_ok` is true on every rank.
bool all_ok(const MPI_Comm comm, const bool local_ok)
{
  int ok = local_ok ? 1 : 0;
  int global_ok = 0;
  MPI_Allreduce(&ok, &global_ok, 1, MPI_INT, MPI_MIN, comm);
  return global_ok == 1;
}

/// Throws the same InternalError on every rank if `local_ok` is false on any rank.
void check_internal_collectively(const MPI_Comm comm, const bool local_ok, const char *condition,
                                 const std::string &message)
{
  if (!all_ok(comm, local_ok))
    throw_internal_error(__FILE__, __LINE__, condition, message);
}

/// Throws an InternalError (on the calling rank; used for checks every rank makes alike).
void check_usage(const bool ok, const char *condition, const std::string &message)
{
  if (!ok)
    throw_internal_error(__FILE__, __LINE__, condition, message);
}

/// Field names become Exodus variable names: keep them plain.
bool is_valid_field_name(const std::string &name)
{
  if (name.empty())
    return false;
  for (const char c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.'))
      return false;
  return true;
}

/// Who owns which rows, as rank 0 sees it: the owned ids of every rank, rank after rank.
struct GatheredRows
{
  std::vector<int> counts; ///< rows per rank
  std::vector<int> displs; ///< first position of each rank's rows in `ids`
  std::vector<int> ids;    ///< the owned ids of rank 0, then rank 1, ...
};

GatheredRows gather_rows(const MPI_Comm comm, const std::vector<int> &owned)
{
  int rank = 0, size = 0;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  GatheredRows g;
  const int n_owned = static_cast<int>(owned.size());
  if (rank == 0)
    g.counts.resize(size);
  MPI_Gather(&n_owned, 1, MPI_INT, g.counts.data(), 1, MPI_INT, 0, comm);
  if (rank == 0)
  {
    g.displs.resize(size);
    int total = 0;
    for (int r = 0; r < size; ++r)
    {
      g.displs[r] = total;
      total += g.counts[r];
    }
    g.ids.resize(total);
  }
  MPI_Gatherv(owned.data(), n_owned, MPI_INT, g.ids.data(), g.counts.data(), g.displs.data(),
              MPI_INT, 0, comm);
  return g;
}
} // namespace
} // namespace internal

std::vector<std::string> ExodusResultsWriter::variable_names(const std::string &name,
                                                             const int n_components)
{
  if (n_components == 1)
    return {name};
  if (n_components == 3)
    return {name + "_x", name + "_y", name + "_z"};
  if (n_components == 6)
    return {name + "_xx", name + "_yy", name + "_zz", name + "_xy", name + "_yz", name + "_xz"};
  std::vector<std::string> names;
  for (int k = 0; k < n_components; ++k)
    names.push_back(name + "_" + std::to_string(k));
  return names;
}

std::vector<int> ExodusResultsWriter::variable_components(const int n_components)
{
  // Kiln's Voigt order is xx yy zz xy xz yz; the variables are written xx yy zz xy yz xz.
  if (n_components == 6)
    return {0, 1, 2, 3, 5, 4};
  std::vector<int> components;
  for (int k = 0; k < n_components; ++k)
    components.push_back(k);
  return components;
}

struct ExodusResultsWriter::Impl
{
  using Center = internal::Center;
  using FieldSpec = internal::FieldSpec;

  MPI_Comm comm = MPI_COMM_NULL;
  int rank = 0;
  std::string path;
  int n_nodes = 0;
  int n_cells = 0;
  std::size_t n_owned_nodes = 0;
  std::size_t n_owned_cells = 0;

  // Every rank: the file's variables (fixed by the first step) and the current step.
  std::vector<FieldSpec> variables;
  bool variables_defined = false;
  bool in_step = false;
  int n_steps = 0;
  double time = 0.0;
  int cycle = 0;
  double dt = 0.0;
  std::vector<FieldSpec> step_fields;

  // Rank 0 only: who owns what, the layout, the open file and the step's gathered values
  // (per step field, component after component, each in global-id order).
  internal::GatheredRows node_rows;
  internal::GatheredRows cell_rows;
  ExodusLayout layout;
  int exo = -1;
  std::vector<std::vector<double>> step_values;

  Impl() = default;
  ~Impl()
  {
    if (exo >= 0)
      ex_close(exo);
  }
  Impl(const Impl &) = delete;
  Impl &operator=(const Impl &) = delete;

  void create_file(const Mesh &mesh, const std::vector<int> &cell_rank);
  void check_field(const std::string &name, Center center, int n_components) const;
  void write_field(const std::string &name, Center center, int n_components,
                   const std::vector<double> &values);
  void define_variables() const;
  void write_step() const;
  /// The declared field with this name, or nullptr.
  const FieldSpec *find_variable(const std::string &name) const;
  /// 1-based index of the first Exodus variable of `field` among its center's variables.
  int first_variable_index(const FieldSpec &field) const;
};

void ExodusResultsWriter::Impl::create_file(const Mesh &mesh, const std::vector<int> &cell_rank)
{
  std::string error;
  if (rank == 0)
  {
    try
    {
      const std::filesystem::path parent = std::filesystem::path(path).parent_path();
      std::error_code ignored;
      KILN_CHECK_INPUT(parent.empty() || std::filesystem::is_directory(parent, ignored), path,
                       "cannot create the results file: the folder \""
                           << parent.string()
                           << "\" does not exist; create it or choose another output path");
      int comp_ws = sizeof(double), io_ws = sizeof(double);
      // Classic netCDF (not netCDF-4/HDF5): a reader sees the steps up to the last flush,
      // and a writer that dies between flushes leaves them readable.
      exo = ex_create(path.c_str(), EX_CLOBBER | EX_LARGE_MODEL, &comp_ws, &io_ws);
      KILN_CHECK_INPUT(exo >= 0, path,
                       "cannot create the results file; check that its folder is writable, or "
                       "choose another output path");
      layout = exodus_layout(mesh, mesh.gap_side_set);
      internal::put_exodus_mesh(exo, path, mesh, layout, "Kiln results",
                                internal::results_name_length, &cell_rank);
      internal::check_exodus_write(ex_update(exo), path, "flushing the file");
    }
    catch (const InputError &e)
    {
      error = e.what();
    }
  }
  const Teuchos::MpiComm<int> teuchos_comm(comm);
  // The message already names the file.
  check_collectively(teuchos_comm, error.empty(), "", error);
}

const ExodusResultsWriter::Impl::FieldSpec *
ExodusResultsWriter::Impl::find_variable(const std::string &name) const
{
  for (const auto &f : variables)
    if (f.name == name)
      return &f;
  return nullptr;
}

int ExodusResultsWriter::Impl::first_variable_index(const FieldSpec &field) const
{
  int index = 1;
  for (const auto &f : variables)
  {
    if (f.name == field.name)
      return index;
    if (f.center == field.center)
      index += f.n_components;
  }
  return -1;
}

/// The checks every rank makes alike (the calls are collective, with the same arguments but
/// the values), so each throws the same InternalError without communication.
void ExodusResultsWriter::Impl::check_field(const std::string &name, const Center center,
                                            const int n_components) const
{
  const std::string field = std::string(internal::kind_of(center)) + " field \"" + name + "\"";
  internal::check_usage(in_step, "in_step",
                        std::string("write_") + internal::kind_of(center) + "_field(\"" + name +
                            "\") called outside begin_step()/end_step()");
  internal::check_usage(internal::is_valid_field_name(name), "is_valid_field_name(name)",
                        "field name \"" + name +
                            "\" is not valid: use letters, digits, '_', '-' and '.'");
  internal::check_usage(n_components >= 1, "n_components >= 1",
                        field + " has " + std::to_string(n_components) + " components; need >= 1");
  for (const auto &f : step_fields)
    internal::check_usage(f.name != name, "field written once per step",
                          "field \"" + name + "\" is written twice in step " +
                              std::to_string(n_steps));
  if (variables_defined)
  {
    const FieldSpec *declared = find_variable(name);
    internal::check_usage(
        declared != nullptr && declared->center == center && declared->n_components == n_components,
        "field declared in the first step",
        field + " with " + std::to_string(n_components) +
            " components does not match the fields of the first step; Exodus defines "
            "its variables once, so every step must write the fields of the first step");
    return;
  }
  // First step: the names must fit and must not clash with variables of earlier fields.
  std::set<std::string> taken;
  for (const auto &f : step_fields)
    if (f.center == center)
      for (const auto &v : ExodusResultsWriter::variable_names(f.name, f.n_components))
        taken.insert(v);
  for (const auto &v : ExodusResultsWriter::variable_names(name, n_components))
  {
    internal::check_usage(static_cast<int>(v.size()) <= internal::results_name_length,
                          "name length",
                          "Exodus variable \"" + v + "\" of " + field + " is longer than " +
                              std::to_string(internal::results_name_length) + " characters");
    internal::check_usage(taken.count(v) == 0, "unique variable names",
                          "Exodus variable \"" + v + "\" of " + field +
                              " is also a variable of an earlier field of this step");
  }
}

void ExodusResultsWriter::Impl::write_field(const std::string &name, const Center center,
                                            const int n_components,
                                            const std::vector<double> &values)
{
  check_field(name, center, n_components);
  const bool on_nodes = center == Center::node;
  const std::size_t n_owned = on_nodes ? n_owned_nodes : n_owned_cells;
  std::ostringstream message;
  message << internal::kind_of(center) << " field \"" << name << "\" has " << values.size()
          << " values on some rank, expected " << n_components << " per owned "
          << internal::kind_of(center);
  internal::check_internal_collectively(
      comm, values.size() == n_owned * static_cast<std::size_t>(n_components),
      "values.size() == n_owned * n_components", message.str());

  // Gather to rank 0, then put every value at its global row, component after component.
  const internal::GatheredRows &rows = on_nodes ? node_rows : cell_rows;
  std::vector<int> counts, displs;
  std::vector<double> received;
  if (rank == 0)
  {
    for (std::size_t r = 0; r < rows.counts.size(); ++r)
    {
      counts.push_back(rows.counts[r] * n_components);
      displs.push_back(rows.displs[r] * n_components);
    }
    received.resize(rows.ids.size() * n_components);
  }
  MPI_Gatherv(values.data(), static_cast<int>(values.size()), MPI_DOUBLE, received.data(),
              counts.data(), displs.data(), MPI_DOUBLE, 0, comm);
  if (rank == 0)
  {
    const std::size_t n_rows = on_nodes ? n_nodes : n_cells;
    std::vector<double> by_component(n_rows * n_components);
    for (std::size_t k = 0; k < rows.ids.size(); ++k)
      for (int c = 0; c < n_components; ++c)
        by_component[c * n_rows + rows.ids[k]] = received[k * n_components + c];
    step_values.push_back(std::move(by_component));
  }
  step_fields.push_back({name, center, n_components});
}

/// Rank 0, at the end of the first step: the global, nodal and element variables, in the
/// order of `variables`, each field's components together.
void ExodusResultsWriter::Impl::define_variables() const
{
  internal::ExodusNames globals({"dt", "cycle"});
  internal::check_exodus_write(ex_put_variable_param(exo, EX_GLOBAL, 2), path,
                               "defining the global variables");
  internal::check_exodus_write(ex_put_variable_names(exo, EX_GLOBAL, 2, globals.data()), path,
                               "naming the global variables");
  for (const Center center : {Center::node, Center::cell})
  {
    std::vector<std::string> names;
    for (const auto &f : variables)
      if (f.center == center)
        for (const auto &v : ExodusResultsWriter::variable_names(f.name, f.n_components))
          names.push_back(v);
    if (names.empty())
      continue;
    const ex_entity_type type = center == Center::node ? EX_NODAL : EX_ELEM_BLOCK;
    const int n = static_cast<int>(names.size());
    const std::string what =
        std::string("defining the ") + internal::kind_of(center) + " variables";
    internal::check_exodus_write(ex_put_variable_param(exo, type, n), path, what);
    internal::ExodusNames buffers(names);
    internal::check_exodus_write(ex_put_variable_names(exo, type, n, buffers.data()), path, what);
    if (type == EX_ELEM_BLOCK)
    {
      // Every element variable on every block.
      const int n_blocks = static_cast<int>(layout.block_ids.size());
      std::vector<int> truth(static_cast<std::size_t>(n_blocks) * n, 1);
      internal::check_exodus_write(
          ex_put_truth_table(exo, EX_ELEM_BLOCK, n_blocks, n, truth.data()), path,
          "writing the element variable truth table");
    }
  }
}

/// Rank 0: the step's time, global variables and fields; then the flush.
void ExodusResultsWriter::Impl::write_step() const
{
  const int step = n_steps + 1; // Exodus counts from 1
  const std::string what = "writing output step " + std::to_string(n_steps);
  internal::check_exodus_write(ex_put_time(exo, step, &time), path, what);
  const double globals[2] = {dt, static_cast<double>(cycle)};
  internal::check_exodus_write(ex_put_glob_vars(exo, step, 2, globals), path, what);
  for (std::size_t f = 0; f < step_fields.size(); ++f)
  {
    const FieldSpec &field = step_fields[f];
    const std::vector<double> &values = step_values[f];
    const int first = first_variable_index(field);
    const std::vector<int> components =
        ExodusResultsWriter::variable_components(field.n_components);
    const std::string field_what = what + ", field \"" + field.name + "\"";
    for (int k = 0; k < field.n_components; ++k)
    {
      if (field.center == Center::node)
      {
        const double *data = values.data() + static_cast<std::size_t>(components[k]) * n_nodes;
        internal::check_exodus_write(ex_put_var(exo, step, EX_NODAL, first + k, 1, n_nodes, data),
                                     path, field_what);
        continue;
      }
      const double *data = values.data() + static_cast<std::size_t>(components[k]) * n_cells;
      for (std::size_t b = 0; b < layout.block_ids.size(); ++b)
      {
        std::vector<double> block_values;
        for (const int c : layout.block_cells[b])
          block_values.push_back(data[c]);
        internal::check_exodus_write(
            ex_put_var(exo, step, EX_ELEM_BLOCK, first + k, layout.block_ids[b],
                       static_cast<int64_t>(block_values.size()), block_values.data()),
            path, field_what);
      }
    }
  }
  internal::check_exodus_write(ex_update(exo), path, "flushing the file after " + what);
}

ExodusResultsWriter::ExodusResultsWriter(const MPI_Comm comm, const std::string &base_path,
                                         const Mesh &mesh, const std::vector<int> &owned_nodes,
                                         const std::vector<int> &owned_cells,
                                         const std::vector<int> &cell_rank)
    : impl_(std::make_unique<Impl>())
{
  Impl &m = *impl_;
  m.comm = comm;
  MPI_Comm_rank(comm, &m.rank);
  m.path = base_path + ".exo";
  m.n_nodes = mesh.n_nodes();
  m.n_cells = mesh.n_cells();

  // The ownership must be a partition of the rows; a mistake here is the caller's.
  const auto is_sorted_in_range = [](const std::vector<int> &rows, const int n)
  {
    for (std::size_t i = 0; i < rows.size(); ++i)
      if (rows[i] < 0 || rows[i] >= n || (i > 0 && rows[i] <= rows[i - 1]))
        return false;
    return true;
  };
  long long counts[2] = {static_cast<long long>(owned_nodes.size()),
                         static_cast<long long>(owned_cells.size())};
  MPI_Allreduce(MPI_IN_PLACE, counts, 2, MPI_LONG_LONG, MPI_SUM, comm);
  internal::check_internal_collectively(
      comm,
      is_sorted_in_range(owned_nodes, m.n_nodes) && is_sorted_in_range(owned_cells, m.n_cells) &&
          counts[0] == m.n_nodes && counts[1] == m.n_cells &&
          cell_rank.size() == static_cast<std::size_t>(m.n_cells) &&
          mesh.block_id.size() == static_cast<std::size_t>(m.n_cells),
      "owned rows form a partition",
      "owned_nodes/owned_cells must be increasing, in range and own every row once; "
      "cell_rank and block_id need one entry per cell");
  m.n_owned_nodes = owned_nodes.size();
  m.n_owned_cells = owned_cells.size();
  m.node_rows = internal::gather_rows(comm, owned_nodes);
  m.cell_rows = internal::gather_rows(comm, owned_cells);
  m.create_file(mesh, cell_rank);
}

ExodusResultsWriter::~ExodusResultsWriter() = default;

void ExodusResultsWriter::begin_step(const double time, const int cycle, const double dt)
{
  Impl &m = *impl_;
  internal::check_usage(!m.in_step, "!in_step", "begin_step() called twice without end_step()");
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
  impl_->write_field(name, internal::Center::node, n_components, values);
}

void ExodusResultsWriter::write_cell_field(const std::string &name, const int n_components,
                                           const std::vector<double> &values)
{
  impl_->write_field(name, internal::Center::cell, n_components, values);
}

void ExodusResultsWriter::end_step()
{
  Impl &m = *impl_;
  internal::check_usage(m.in_step, "in_step", "end_step() called without begin_step()");
  if (m.variables_defined && m.step_fields.size() != m.variables.size())
  {
    std::string missing;
    for (const auto &f : m.variables)
      if (std::none_of(m.step_fields.begin(), m.step_fields.end(),
                       [&](const Impl::FieldSpec &s) { return s.name == f.name; }))
        missing += (missing.empty() ? "\"" : ", \"") + f.name + "\"";
    m.in_step = false;
    internal::check_usage(false, "every field of the first step written",
                          "step " + std::to_string(m.n_steps) + " does not write " + missing +
                              ", written in the first step; Exodus defines its variables "
                              "once, so every step must write the fields of the first step");
  }
  const bool first_step = !m.variables_defined;
  if (first_step)
  {
    m.variables = m.step_fields;
    m.variables_defined = true;
  }
  std::string error;
  if (m.rank == 0)
  {
    try
    {
      if (first_step)
        m.define_variables();
      m.write_step();
    }
    catch (const InputError &e)
    {
      error = e.what();
    }
  }
  m.in_step = false;
  m.step_values.clear();
  const Teuchos::MpiComm<int> teuchos_comm(m.comm);
  check_collectively(teuchos_comm, error.empty(), "", error);
  ++m.n_steps;
}

std::string ExodusResultsWriter::exo_path() const
{
  return impl_->path;
}
} // namespace kiln
