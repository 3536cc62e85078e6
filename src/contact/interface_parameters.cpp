#include "contact/interface_parameters.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"
#include "contact/interface_strategy.hpp"

namespace kiln
{
Teuchos::ParameterList interface_parameters()
{
  Teuchos::ParameterList p("Contact");
  p.set("Enabled", true,
        "true: the two sides of the gap interact as \"Kind\" says; false: they are separate "
        "bodies that pass through each other [-]");
  const InterfaceKinds &kinds = interface_kinds();
  p.set("Kind", kinds.names().front(),
        "how the two sides of the gap interact (doc/contact.md, \"Interface kinds\"): " +
            kinds.describe() + " [-]",
        choice_validator(kinds.names()));
  p.set("Complementarity Scale", 1.0,
        "s in c = s (lambda + 2G) / sqrt(A), A the pair's area: weighs the gap against the "
        "pressure in each pair's condition; it changes the Newton path, not the converged "
        "answer; must be > 0 [-]",
        positive_double_validator());
  for (const auto &kind : kinds.entries())
    p.setParameters(kind.parameters);
  return p;
}

void check_interface_parameters(const Teuchos::ParameterList &contact, const std::string &path)
{
  const std::string kind = contact.get<std::string>("Kind");
  for (const auto &other : interface_kinds().entries())
    if (other.name != kind)
      for (auto it = other.parameters.begin(); it != other.parameters.end(); ++it)
      {
        const std::string &name = other.parameters.name(it);
        KILN_CHECK_INPUT(interface_kinds().find(kind)->parameters.isParameter(name) ||
                             !given_in_input(contact, name),
                         path + "/\"" + name + "\"",
                         "applies to Kind \"" << other.name << "\", not to Kind \"" << kind
                                              << "\"; remove it or change the Kind");
      }
}
} // namespace kiln
