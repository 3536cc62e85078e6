#include "contact/interface_strategy.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <limits>

namespace kiln
{
int InterfaceStrategy::count_active() const
{
  int local = 0, global = 0;
  for (const char a : active())
    local += a ? 1 : 0;
  Teuchos::reduceAll(*dofs_.owned_dof_map()->getComm(), Teuchos::REDUCE_SUM, local,
                     Teuchos::outArg(global));
  return global;
}

InterfaceStrategy::NodeValues InterfaceStrategy::node_values() const
{
  const auto &comm = *dofs_.owned_dof_map()->getComm();
  const int n = interface_.n_rows();
  const int n_nodes = static_cast<int>(dofs_.node_owner().size());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  NodeValues out{std::vector<double>(n_nodes, nan), std::vector<double>(n_nodes, nan), {}, {}, {}};
  std::vector<double> local(2 * static_cast<std::size_t>(n), 0.0), global(local.size(), 0.0);
  const auto &owned = interface_.owned_rows();
  for (std::size_t i = 0; i < owned.size(); ++i)
  {
    local[owned[i]] = active()[i] ? -pressure()[i] : 0.0;
    local[n + owned[i]] = active()[i] ? 1.0 : 0.0;
  }
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, 2 * n, local.data(), global.data());
  // A split gap's pair shows at both its nodes, a pairing's row at its node j.
  for (int k = 0; k < n; ++k)
    for (const int node : {interface_.rows()[k].a(), interface_.rows()[k].node})
      if (interface_.split() || node == interface_.rows()[k].node)
      {
        out.traction[node] = global[k];
        out.active[node] = global[n + k];
      }
  out.pair_traction.assign(global.begin(), global.begin() + n);
  out.pair_active.assign(global.begin() + n, global.end());
  return out;
}
} // namespace kiln
