#include "io/exodus_results_file.hpp"

#include "base/errors.hpp"
#include "io/history_csv.hpp"
#include "io/write_room.hpp"

#include <exodusII.h>
#include <netcdf.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>

namespace kiln
{
namespace internal
{
namespace
{
/// check_exodus_write() for the results: a failure the system names a full disk or a
/// file-size limit (netCDF passes its errno on) is a WriteError.
void check_results_write(const int status, const std::string &path, const std::string &what)
{
  if (status >= 0)
    return;
  const int system_error = errno;
  const char *message = nullptr, *function = nullptr;
  int code = 0;
  ex_get_err(&message, &function, &code);
  const int reason = is_write_failure(code) ? code : system_error;
  if (is_write_failure(reason))
    throw WriteError(path + ": cannot write the results while " + what + " (" +
                     std::strerror(reason) + "); " + write_failure_advice());
  check_exodus_write(status, path, what);
}
} // namespace

ExodusResultsFile::ExodusResultsFile(const std::string &path, const Mesh &mesh,
                                     const std::vector<int> &cell_rank,
                                     const std::string &run_fingerprint)
    : path_(path), n_nodes_(mesh.n_nodes()), n_cells_(mesh.n_cells()),
      columns_(history_columns(mesh.gap_side_sets, mesh.contact_pair_names()))
{
  const std::filesystem::path parent = std::filesystem::path(path_).parent_path();
  std::error_code ignored;
  KILN_CHECK_INPUT(parent.empty() || std::filesystem::is_directory(parent, ignored), path_,
                   "cannot create the results file: the folder \""
                       << parent.string()
                       << "\" does not exist; create it or choose another output path");
  int comp_ws = sizeof(double), io_ws = sizeof(double);
  // Classic netCDF (not netCDF-4/HDF5): a reader sees the steps up to the last flush,
  // and a writer that dies between flushes leaves them readable.
  exo_ = ex_create(path_.c_str(), EX_CLOBBER | EX_LARGE_MODEL, &comp_ws, &io_ws);
  KILN_CHECK_INPUT(exo_ >= 0, path_,
                   "cannot create the results file; check that its folder is writable, or "
                   "choose another output path");
  try
  {
    layout_ = exodus_layout(mesh, mesh.gap_side_sets);
    put_exodus_mesh(exo_, path_, mesh, layout_, "Kiln results", ExodusVariables::max_name_length,
                    &cell_rank);
    if (!run_fingerprint.empty())
    {
      // Exodus 6 has no call for a file attribute: netCDF's own, on the same id.
      const int defining = nc_redef(exo_);
      const int put = defining == NC_NOERR
                          ? nc_put_att_text(exo_, NC_GLOBAL, "run_fingerprint",
                                            run_fingerprint.size(), run_fingerprint.data())
                          : defining;
      const int ended = defining == NC_NOERR ? nc_enddef(exo_) : NC_NOERR;
      check_results_write(put == NC_NOERR && ended == NC_NOERR ? 0 : -1, path_,
                          "writing the attribute run_fingerprint");
    }
    check_results_write(ex_update(exo_), path_, "flushing the file");
    size_before_step_ = std::filesystem::file_size(path_, ignored);
    // Before the first step, a guess: a step's fields take about a quarter of the mesh's bytes.
    largest_step_ = size_before_step_ / 4;
  }
  catch (...)
  {
    ex_close(exo_); // the destructor does not run for a constructor that throws
    throw;
  }
}

ExodusResultsFile::~ExodusResultsFile()
{
  ex_close(exo_);
}

void ExodusResultsFile::define_variables(const ExodusVariables &variables) const
{
  std::vector<std::string> global_names;
  for (const HistoryColumn &column : columns_)
    global_names.push_back(column.name);
  const int n_globals = static_cast<int>(global_names.size());
  ExodusNames globals(global_names);
  check_results_write(ex_put_variable_param(exo_, EX_GLOBAL, n_globals), path_,
                      "defining the global variables");
  check_results_write(ex_put_variable_names(exo_, EX_GLOBAL, n_globals, globals.data()), path_,
                      "naming the global variables");
  for (const Center center : {Center::node, Center::cell})
  {
    const std::vector<std::string> names = variables.names_of(center);
    if (names.empty())
      continue;
    const ex_entity_type type = center == Center::node ? EX_NODAL : EX_ELEM_BLOCK;
    const int n = static_cast<int>(names.size());
    const std::string what = std::string("defining the ") + kind_of(center) + " variables";
    check_results_write(ex_put_variable_param(exo_, type, n), path_, what);
    ExodusNames buffers(names);
    check_results_write(ex_put_variable_names(exo_, type, n, buffers.data()), path_, what);
    if (type == EX_ELEM_BLOCK)
    {
      // Every element variable on every block.
      const int n_blocks = static_cast<int>(layout_.block_ids.size());
      std::vector<int> truth(static_cast<std::size_t>(n_blocks) * n, 1);
      check_results_write(ex_put_truth_table(exo_, EX_ELEM_BLOCK, n_blocks, n, truth.data()), path_,
                          "writing the element variable truth table");
    }
  }
}

void ExodusResultsFile::write_step(const Step &step, const ExodusVariables &variables) const
{
  const int exodus_step = step.index + 1; // Exodus counts from 1
  const std::string what = "writing output step " + std::to_string(step.index);
  // Room for twice the largest step so far (a guess before the first), and the header's
  // growth (netCDF classic: the variables' definitions at the first step; 16 KiB).
  const std::string shortfall =
      room_shortfall(path_, 2 * largest_step_ + (std::uintmax_t{16} << 10));
  if (!shortfall.empty())
    throw WriteError(path_ + ": the next step cannot be written (" + shortfall + "); " +
                     write_failure_advice());
  check_results_write(ex_put_time(exo_, exodus_step, &step.time), path_, what);
  KILN_ASSERT(step.globals.size() == columns_.size(), "one global per history column");
  check_results_write(ex_put_var(exo_, exodus_step, EX_GLOBAL, 1, 0,
                                 static_cast<int64_t>(step.globals.size()), step.globals.data()),
                      path_, what);
  for (std::size_t f = 0; f < step.fields.size(); ++f)
  {
    const FieldSpec &field = step.fields[f];
    const std::vector<double> &values = step.values[f];
    const int first = variables.first_index(field);
    const std::vector<int> components = ExodusVariables::components(field.n_components);
    const std::string field_what = what + ", field \"" + field.name + "\"";
    const std::size_t n_rows = field.center == Center::node ? n_nodes_ : n_cells_;
    for (int k = 0; k < field.n_components; ++k)
    {
      const double *data = values.data() + static_cast<std::size_t>(components[k]) * n_rows;
      if (field.center == Center::node)
        check_results_write(ex_put_var(exo_, exodus_step, EX_NODAL, first + k, 1, n_nodes_, data),
                            path_, field_what);
      else
        write_cell_variable(exodus_step, first + k, data, field_what);
    }
  }
  check_results_write(ex_update(exo_), path_, "flushing the file after " + what);
  std::error_code ignored;
  const std::uintmax_t size = std::filesystem::file_size(path_, ignored);
  largest_step_ = std::max(largest_step_, size - std::min(size, size_before_step_));
  size_before_step_ = size;
}

void ExodusResultsFile::write_globals(const int index, const std::vector<double> &globals) const
{
  KILN_ASSERT(globals.size() == columns_.size(), "one global per history column");
  const std::string what = "writing the global variables of output step " + std::to_string(index);
  check_results_write(ex_put_var(exo_, index + 1, EX_GLOBAL, 1, 0,
                                 static_cast<int64_t>(globals.size()), globals.data()),
                      path_, what);
  check_results_write(ex_update(exo_), path_, "flushing the file after " + what);
}

/// The values of all cells, block after block.
void ExodusResultsFile::write_cell_variable(const int step, const int variable,
                                            const double *values, const std::string &what) const
{
  for (std::size_t b = 0; b < layout_.block_ids.size(); ++b)
  {
    std::vector<double> block_values;
    for (const int c : layout_.block_cells[b])
      block_values.push_back(values[c]);
    check_results_write(ex_put_var(exo_, step, EX_ELEM_BLOCK, variable, layout_.block_ids[b],
                                   static_cast<int64_t>(block_values.size()), block_values.data()),
                        path_, what);
  }
}
} // namespace internal
} // namespace kiln
