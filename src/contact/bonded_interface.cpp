#include "contact/bonded_interface.hpp"

namespace kiln
{
std::string BondedInterface::description()
{
  return "tied: the two sides move together, the interface carries tension and shear as well as "
         "pressure";
}

BondedInterface::BondedInterface(const ContactInterface &interface, const DofManager &dofs,
                                 NodalConstraints &constraints, const Teuchos::ParameterList &,
                                 const std::string &where)
    : TiedPairs(interface, dofs, constraints)
{
  claim_free_axes(constraints, where);
  finish_claims();
}
} // namespace kiln
