#include "contact/contact_interface.hpp"

#include "base/errors.hpp"

#include <cmath>
#include <utility>
#include <vector>

namespace kiln
{
ContactInterface::ContactInterface(const Mesh &mesh, const DofManager &dofs, const int gap,
                                   const double modulus, const double scale)
    : mesh_(mesh), gap_(gap), name_("gap side set " + std::to_string(mesh.gap_side_sets[gap])),
      modulus_(modulus)
{
  for (const GapPair &gap_pair : mesh.gap_pairs)
  {
    if (gap_pair.gap != gap)
      continue;
    Row row;
    row.node = gap_pair.node_b;
    row.partners = {gap_pair.node_a};
    row.weights = {1.0};
    row.area = gap_pair.area;
    row.c = scale * modulus / std::sqrt(gap_pair.area);
    row.normal = gap_pair.normal;
    rows_.push_back(std::move(row));
  }
  index(dofs);
}

ContactInterface::ContactInterface(const Mesh &mesh, const DofManager &dofs,
                                   std::vector<ContactRow> rows, const double modulus,
                                   const double scale, std::string name)
    : mesh_(mesh), name_(std::move(name)), modulus_(modulus), c_scale_(scale * modulus)
{
  for (ContactRow &given : rows)
  {
    KILN_ASSERT(given.area > 0.0 && given.partners.size() == given.weights.size() &&
                    !given.partners.empty(),
                "a row of " << name_ << " at node " << given.node << " is malformed");
    Row row;
    static_cast<ContactRow &>(row) = std::move(given);
    row.c = c_scale_ / std::sqrt(row.area);
    rows_.push_back(std::move(row));
  }
  index(dofs);
}

void ContactInterface::index(const DofManager &dofs)
{
  const int rank = dofs.owned_dof_map()->getComm()->getRank();
  const int n_nodes = mesh_.n_nodes();
  row_of_node_.assign(n_nodes, -1);
  for (std::size_t k = 0; k < rows_.size(); ++k)
  {
    const Row &row = rows_[k];
    KILN_ASSERT(split() || row_of_node_[row.node] < 0,
                "node " << row.node << " has two rows in " << name_);
    row_of_node_[row.node] = static_cast<int>(k);
    if (dofs.node_owner()[row.node] == rank)
      owned_rows_.push_back(static_cast<int>(k));
  }
  index_partners();
}

void ContactInterface::index_partners()
{
  const int n_nodes = mesh_.n_nodes();
  offsets_.assign(n_nodes + 1, 0);
  for (const Row &row : rows_)
    for (const int p : row.partners)
      ++offsets_[p + 1];
  for (int n = 0; n < n_nodes; ++n)
    offsets_[n + 1] += offsets_[n];
  rows_of_partner_.resize(offsets_.back());
  std::vector<int> next(offsets_.begin(), offsets_.end() - 1);
  for (std::size_t k = 0; k < rows_.size(); ++k)
    for (const int p : rows_[k].partners)
      rows_of_partner_[next[p]++] = static_cast<int>(k);
}

void ContactInterface::replace_rows(std::vector<ContactRow> rows)
{
  KILN_ASSERT(!split() && rows.size() == rows_.size(),
              "the rows of " << name_ << " replaced by " << rows.size() << " rows");
  for (std::size_t k = 0; k < rows.size(); ++k)
  {
    ContactRow &given = rows[k];
    Row &row = rows_[k];
    KILN_ASSERT(given.node == row.node && given.area > 0.0 &&
                    given.partners.size() == given.weights.size() && !given.partners.empty(),
                "a new row of " << name_ << " at node " << given.node << " is malformed");
    static_cast<ContactRow &>(row) = std::move(given);
    row.c = c_scale_ / std::sqrt(row.area);
  }
  index_partners();
  ++searches_;
}

std::vector<std::pair<int, int>> partner_links(const std::vector<ContactRow> &rows)
{
  std::vector<std::pair<int, int>> links;
  for (const ContactRow &row : rows)
    for (const int k : row.partners)
      links.emplace_back(row.node, k);
  return links;
}
} // namespace kiln
