// The registration list of the constitutive models: a new model is a new class in its own
// files and one line here.
#include "physics/materials/constitutive_models.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"
#include "physics/materials/linear_elastic_model.hpp"
#include "physics/materials/mts_viscoplastic_model.hpp"
#include "physics/materials/power_law_viscoplastic_model.hpp"

namespace kiln
{
const ConstitutiveModelRegistry &constitutive_models()
{
  static const ConstitutiveModelRegistry registry = []
  {
    ConstitutiveModelRegistry r;
    r.add<LinearElasticModel>("Linear Elastic");
    r.add<PowerLawViscoplasticModel>("Power Law");
    r.add<MtsViscoplasticModel>("MTS");
    return r;
  }();
  return registry;
}

Teuchos::ParameterList constitutive_model_parameters()
{
  const ConstitutiveModelRegistry &registry = constitutive_models();
  Teuchos::ParameterList p("Model");
  p.set("Type", registry.names().front(), registry.describe(), choice_validator(registry.names()));
  for (const auto &entry : registry.entries())
    for (auto it = entry.parameters.begin(); it != entry.parameters.end(); ++it)
      if (!p.isParameter(entry.parameters.name(it)))
        p.setEntry(entry.parameters.name(it), entry.parameters.entry(it));
  return p;
}

std::unique_ptr<ConstitutiveModel> create_constitutive_model(const Teuchos::ParameterList &user,
                                                             const std::string &where,
                                                             const std::string &path)
{
  const Teuchos::ParameterList p = validated(user, constitutive_model_parameters(), where, path);
  const std::string &type = p.get<std::string>("Type");
  const ConstitutiveModelRegistry::Entry &entry = *constitutive_models().find(type);
  for (auto it = p.begin(); it != p.end(); ++it)
  {
    const std::string &name = p.name(it);
    if (name == "Type" || entry.parameters.isParameter(name) || !given_in_input(p, name))
      continue;
    std::string own;
    for (auto e = entry.parameters.begin(); e != entry.parameters.end(); ++e)
      own += (own.empty() ? "\"" : ", \"") + entry.parameters.name(e) + "\"";
    KILN_CHECK_INPUT(false, parameter_path(where, path, name),
                     "is not a parameter of the \"" << type
                                                    << "\" model (\"Type\"); its "
                                                       "parameters are "
                                                    << own << "; remove it or change \"Type\"");
  }
  const std::string place = (where.empty() ? "" : where + ": ") + path;
  return constitutive_models().create(type, p, place);
}
} // namespace kiln
