#include "contact/surface_displacement.hpp"

#include <Teuchos_CommHelpers.hpp>

namespace kiln
{
std::vector<Point> gather_displacement(const std::vector<int> &nodes,
                                       const std::function<Point(int node)> &u,
                                       const std::vector<int> &node_owner,
                                       const Teuchos::Comm<int> &comm)
{
  const int rank = comm.getRank();
  std::vector<double> mine(3 * nodes.size(), 0.0), all(mine.size(), 0.0);
  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (node_owner[static_cast<std::size_t>(nodes[i])] == rank)
    {
      const Point value = u(nodes[i]);
      for (std::size_t c = 0; c < 3; ++c)
        mine[3 * i + c] = value[c];
    }
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, static_cast<int>(mine.size()), mine.data(),
                     all.data());
  std::vector<Point> result(nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i)
    result[i] = {all[3 * i], all[3 * i + 1], all[3 * i + 2]};
  return result;
}
} // namespace kiln
