#pragma once
/// Private to src/io: the values of the rows (nodes or cells) every rank owns, gathered to
/// rank 0 in global-row order. Collective on the communicator, which must outlive it.
#include <mpi.h>

#include <cstddef>
#include <vector>

namespace kiln
{
namespace internal
{
class RowGather
{
public:
  /// `owned`: this rank's rows (in any order; each row owned by one rank); `n_rows`: the rows
  /// of all ranks.
  RowGather(MPI_Comm comm, const std::vector<int> &owned, int n_rows);
  std::size_t n_owned() const { return n_owned_; }
  /// On rank 0 the values of every row, component after component (component c of row r at
  /// c * n_rows + r); empty elsewhere. `values`: n_components values per owned row.
  std::vector<double> to_rank_zero(const std::vector<double> &values, int n_components) const;

private:
  MPI_Comm comm_;
  int rank_ = 0;
  std::size_t n_owned_;
  std::size_t n_rows_;
  // Rank 0 only: who owns which rows.
  std::vector<int> counts_; ///< rows per rank
  std::vector<int> displs_; ///< first position of each rank's rows in `ids_`
  std::vector<int> ids_;    ///< the owned rows of rank 0, then rank 1, ...
};
} // namespace internal
} // namespace kiln
