#include "contact/sliding_interface.hpp"

namespace kiln
{
std::string SlidingInterface::description()
{
  return "the normal gap held at zero in tension and compression, the sides free to slide along it "
         "(frictionless)";
}

SlidingInterface::SlidingInterface(const ContactInterface &interface, const DofManager &dofs,
                                   NodalConstraints &constraints, const Teuchos::ParameterList &,
                                   const std::string &where)
    : TiedPairs(interface, dofs, constraints)
{
  claim_normals(constraints, where);
  finish_claims();
}
} // namespace kiln
