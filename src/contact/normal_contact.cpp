#include "contact/normal_contact.hpp"

#include "base/parameters.hpp"

namespace kiln
{
std::string NormalContact::description()
{
  return "frictionless contact: the sides may separate but not interpenetrate, and carry a "
         "compressive normal traction when in contact";
}

Teuchos::ParameterList NormalContact::valid_parameters()
{
  Teuchos::ParameterList p;
  const auto &functions = complementarity_functions();
  p.set("Complementarity Function", functions.names().front(),
        "Kind \"Contact\": how g >= 0, p >= 0, p g = 0 enters the Newton solve: " +
            functions.describe() +
            ". After an active-set cycle a step switches to Fischer-Burmeister anyway",
        choice_validator(functions.names()));
  return p;
}

NormalContact::NormalContact(const ContactInterface &interface, const DofManager &dofs,
                             NodalConstraints &constraints, const Teuchos::ParameterList &contact,
                             const std::string &where)
    : CondensedPairs(interface, dofs, constraints),
      function_(
          complementarity_functions().create(contact.get<std::string>("Complementarity Function"))),
      fallback_(complementarity_functions().create("Fischer-Burmeister")),
      monitor_(dofs.owned_dof_map()->getComm(), interface.n_rows(),
               static_cast<int>(interface.owned_rows().size()))
{
  claim_normals(constraints, where);
  finish_claims();
  const Mesh &mesh = interface.mesh();
  if (!interface.split())
    monitor_.set_pair_name(" (" + interface.name() + ")");
  else if (mesh.gap_side_sets.size() > 1 || !mesh.contact_pairs.empty()) // named beside a pair
    monitor_.set_gap_name(" (" + interface.name() + ")");
}

ComplementarityFunction::Value NormalContact::law(bool, const double P, const double cg) const
{
  return (monitor_.fallback() ? *fallback_ : *function_).evaluate(P, cg);
}

bool NormalContact::holds(const double P, const double cg) const
{
  return P - cg > 0.0;
}

bool NormalContact::jacobian_evaluated()
{
  const bool fallback = monitor_.fallback();
  monitor_.jacobian_evaluated(active());
  return monitor_.fallback() != fallback;
}

void NormalContact::set_log(Teuchos::RCP<Teuchos::FancyOStream> out)
{
  monitor_.set_log(std::move(out));
}

void NormalContact::start_step()
{
  monitor_.start_step();
}

void NormalContact::step_accepted(const double time)
{
  monitor_.step_accepted(time, active(), loaded());
}

void NormalContact::resume()
{
  monitor_.resume(active(), loaded());
}

std::vector<char> NormalContact::loaded() const
{
  std::vector<char> loaded(active().size(), 0);
  for (std::size_t i = 0; i < loaded.size(); ++i)
    loaded[i] = active()[i] && carries_load(pressure()[i], interface().modulus());
  return loaded;
}
} // namespace kiln
