#include "contact/pair_search_again.hpp"

#include "base/errors.hpp"
#include "contact/surface_displacement.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <sstream>
#include <string>
#include <unordered_map>

namespace kiln
{
std::vector<ContactRow>
search_pair_again(const std::vector<std::unique_ptr<ContactInterface>> &pairings,
                  const std::size_t p, const PairResearch &research, const Mesh &mesh,
                  const std::function<Point(int node)> &u, const std::vector<int> &node_owner,
                  const Teuchos::Comm<int> &comm, const double time)
{
  const ContactInterface &pairing = *pairings[p];
  // The displacement of the two surfaces on every rank (O(surface), not per mesh node).
  std::vector<ContactRow> rows =
      research.rows_at(std::vector<ContactRow>(pairing.rows().begin(), pairing.rows().end()),
                       gather_displacement(research.surface_nodes(), u, node_owner, comm), time);
  // A new partner may not be a node of another pair or gap (the rows of one would overwrite
  // the other's), as at set-up.
  std::unordered_map<int, std::size_t> other; // node -> its other pair or gap
  for (std::size_t q = 0; q < pairings.size(); ++q)
    if (q != p)
      for (const ContactRow &row : pairings[q]->rows())
      {
        other[row.node] = q;
        for (const int k : row.partners)
          other[k] = q;
      }
  for (const ContactRow &row : rows)
    for (const int k : row.partners)
      if (const auto found = other.find(k); found != other.end())
      {
        const Point &X = mesh.coordinates[k];
        std::ostringstream message;
        message << pairing.name() << ": at t = " << time
                << " s the search redone pairs secondary node " << row.node + 1 << " with node "
                << k + 1 << " at (" << X[0] << ", " << X[1] << ", " << X[2] << ") m, which is on "
                << pairings[found->second]->name()
                << ": a node of a pair between separately meshed bodies cannot be on another pair "
                   "or gap (the rows of one would overwrite the other's); keep the sliding away "
                   "from the other pair or gap, or give the pairs and gaps side sets without "
                   "common nodes. The results up to the last accepted step are kept";
        throw RunError(message.str());
      }
  return rows;
}
} // namespace kiln
