#include "io/collective_checks.hpp"

#include "base/errors.hpp"
#include "mesh/mesh.hpp"

#include <Teuchos_DefaultMpiComm.hpp>

#include <cctype>
#include <sstream>

namespace kiln
{
namespace internal
{
namespace
{
/// True on every rank if `local_ok` is true on every rank.
bool all_ok(const MPI_Comm comm, const bool local_ok)
{
  int ok = local_ok ? 1 : 0;
  int global_ok = 0;
  MPI_Allreduce(&ok, &global_ok, 1, MPI_INT, MPI_MIN, comm);
  return global_ok == 1;
}

/// Whether `rows` is increasing with every entry in [0, n).
bool is_sorted_in_range(const std::vector<int> &rows, const int n)
{
  for (std::size_t i = 0; i < rows.size(); ++i)
    if (rows[i] < 0 || rows[i] >= n || (i > 0 && rows[i] <= rows[i - 1]))
      return false;
  return true;
}
} // namespace

void check_usage(const bool ok, const char *condition, const std::string &message)
{
  if (!ok)
    throw_internal_error(__FILE__, __LINE__, condition, message);
}

void check_internal_collectively(const MPI_Comm comm, const bool local_ok, const char *condition,
                                 const std::string &message)
{
  if (!all_ok(comm, local_ok))
    throw_internal_error(__FILE__, __LINE__, condition, message);
}

void check_input_collectively(const MPI_Comm comm, const bool local_ok, const std::string &where,
                              const std::string &message)
{
  const Teuchos::MpiComm<int> teuchos_comm(comm);
  check_collectively(teuchos_comm, local_ok, where, message);
}

void run_on_rank_zero(const MPI_Comm comm, const std::function<void()> &work)
{
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  std::string error, write_error;
  if (rank == 0)
  {
    try
    {
      work();
    }
    catch (const InputError &e)
    {
      error = e.what();
    }
    catch (const WriteError &e)
    {
      write_error = e.what();
    }
  }
  // The message already says where.
  check_input_collectively(comm, error.empty(), "", error);
  const Teuchos::MpiComm<int> teuchos_comm(comm);
  check_write_collectively(teuchos_comm, write_error.empty(), "", write_error);
}

void check_begin_step(const bool in_step)
{
  check_usage(!in_step, "!in_step", "begin_step() called twice without end_step()");
}

void check_write_field(const bool in_step, const FieldSpec &field)
{
  check_usage(in_step, "in_step",
              std::string("write_") + kind_of(field.center) + "_field(\"" + field.name +
                  "\") called outside begin_step()/end_step()");
}

void check_end_step(const bool in_step)
{
  check_usage(in_step, "in_step", "end_step() called without begin_step()");
}

bool is_valid_field_name(const std::string &name)
{
  if (name.empty())
    return false;
  for (const char c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.'))
      return false;
  return true;
}

void check_row_partition(const MPI_Comm comm, const Mesh &mesh, const std::vector<int> &owned_nodes,
                         const std::vector<int> &owned_cells, const std::vector<int> &cell_rank)
{
  const int n_nodes = mesh.n_nodes();
  const int n_cells = mesh.n_cells();
  long long counts[2] = {static_cast<long long>(owned_nodes.size()),
                         static_cast<long long>(owned_cells.size())};
  MPI_Allreduce(MPI_IN_PLACE, counts, 2, MPI_LONG_LONG, MPI_SUM, comm);
  check_internal_collectively(
      comm,
      is_sorted_in_range(owned_nodes, n_nodes) && is_sorted_in_range(owned_cells, n_cells) &&
          counts[0] == n_nodes && counts[1] == n_cells &&
          cell_rank.size() == static_cast<std::size_t>(n_cells) &&
          mesh.block_id.size() == static_cast<std::size_t>(n_cells),
      "owned rows form a partition",
      "owned_nodes/owned_cells must be increasing, in range and own every row once; "
      "cell_rank and block_id need one entry per cell");
}

void check_field_size(const MPI_Comm comm, const FieldSpec &field, const std::size_t n_owned,
                      const std::size_t n_values)
{
  const char *kind = kind_of(field.center);
  std::ostringstream message;
  message << kind << " field \"" << field.name << "\" has " << n_values
          << " values on some rank, expected " << field.n_components << " per owned " << kind;
  check_internal_collectively(comm,
                              n_values == n_owned * static_cast<std::size_t>(field.n_components),
                              "values.size() == n_owned * n_components", message.str());
}
} // namespace internal
} // namespace kiln
