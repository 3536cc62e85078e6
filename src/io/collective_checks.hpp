#pragma once
/// Private to src/io: the checks every ResultsWriter makes, each raised alike on every rank of
/// the writer's communicator (a failure found on some ranks only must not leave the others
/// hanging in the next collective call).
/// - The calls of a writer are collective with the same arguments (but the values), so the
///   checks of the order of calls and of the arguments throw alike without communication.
/// - A check of this rank's values, or of a file operation, reduces its result first.
#include "io/field_spec.hpp"

#include <mpi.h>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace kiln
{
struct Mesh;

namespace internal
{
/// Throws an InternalError if `ok` is false (a check every rank makes alike).
void check_usage(bool ok, const char *condition, const std::string &message);
/// Throws the same InternalError on every rank if `local_ok` is false on any rank.
void check_internal_collectively(MPI_Comm comm, bool local_ok, const char *condition,
                                 const std::string &message);
/// Throws the same InputError, "where: message" with the message of the lowest rank that
/// failed, on every rank if `local_ok` is false on any rank (kiln::check_collectively).
void check_input_collectively(MPI_Comm comm, bool local_ok, const std::string &where,
                              const std::string &message);
/// Runs `work` on rank 0 alone; an InputError or a WriteError it throws is thrown again, of
/// the same type and with the same message, on every rank. Collective.
void run_on_rank_zero(MPI_Comm comm, const std::function<void()> &work);

/// The order begin_step(), write_node_field()/write_cell_field() ..., end_step():
/// InternalError when a call comes out of turn (`in_step`: a step was begun, not ended).
void check_begin_step(bool in_step);
void check_write_field(bool in_step, const FieldSpec &field);
void check_end_step(bool in_step);

/// Not empty, and only letters, digits, '_', '-' and '.': a name that is a plain HDF5 link
/// name, XML attribute value and Exodus variable name.
bool is_valid_field_name(const std::string &name);

/// Checks (collective; InternalError on every rank) that `owned_nodes` and `owned_cells`, this
/// rank's rows, are increasing and in range and own every node and cell of `mesh` once over
/// the ranks, and that `cell_rank` and the mesh's block ids have one entry per cell.
void check_row_partition(MPI_Comm comm, const Mesh &mesh, const std::vector<int> &owned_nodes,
                         const std::vector<int> &owned_cells, const std::vector<int> &cell_rank);
/// Checks (collective; InternalError on every rank naming the field) that `n_values` is
/// `field`.n_components values for each of the `n_owned` rows this rank owns.
void check_field_size(MPI_Comm comm, const FieldSpec &field, std::size_t n_owned,
                      std::size_t n_values);
} // namespace internal
} // namespace kiln
