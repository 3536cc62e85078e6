#include "io/row_gather.hpp"

namespace kiln
{
namespace internal
{
RowGather::RowGather(const MPI_Comm comm, const std::vector<int> &owned, const int n_rows)
    : comm_(comm), n_owned_(owned.size()), n_rows_(static_cast<std::size_t>(n_rows))
{
  int size = 0;
  MPI_Comm_rank(comm, &rank_);
  MPI_Comm_size(comm, &size);
  const int n_owned = static_cast<int>(owned.size());
  if (rank_ == 0)
    counts_.resize(size);
  MPI_Gather(&n_owned, 1, MPI_INT, counts_.data(), 1, MPI_INT, 0, comm);
  if (rank_ == 0)
  {
    displs_.resize(size);
    int total = 0;
    for (int r = 0; r < size; ++r)
    {
      displs_[r] = total;
      total += counts_[r];
    }
    ids_.resize(total);
  }
  MPI_Gatherv(owned.data(), n_owned, MPI_INT, ids_.data(), counts_.data(), displs_.data(), MPI_INT,
              0, comm);
}

std::vector<double> RowGather::to_rank_zero(const std::vector<double> &values,
                                            const int n_components) const
{
  std::vector<int> counts, displs;
  std::vector<double> received;
  if (rank_ == 0)
  {
    for (std::size_t r = 0; r < counts_.size(); ++r)
    {
      counts.push_back(counts_[r] * n_components);
      displs.push_back(displs_[r] * n_components);
    }
    received.resize(ids_.size() * n_components);
  }
  MPI_Gatherv(values.data(), static_cast<int>(values.size()), MPI_DOUBLE, received.data(),
              counts.data(), displs.data(), MPI_DOUBLE, 0, comm_);
  std::vector<double> by_component;
  if (rank_ == 0)
  {
    by_component.resize(n_rows_ * n_components);
    for (std::size_t k = 0; k < ids_.size(); ++k)
      for (int c = 0; c < n_components; ++c)
        by_component[c * n_rows_ + ids_[k]] = received[k * n_components + c];
  }
  return by_component;
}
} // namespace internal
} // namespace kiln
