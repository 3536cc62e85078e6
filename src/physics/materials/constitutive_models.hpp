#pragma once
/// The constitutive models Kiln has, by name (constitutive_models.cpp: one line per model).
#include "base/registry.hpp"
#include "physics/materials/constitutive_model.hpp"

#include <Teuchos_ParameterList.hpp>

#include <memory>
#include <string>

namespace kiln
{
/// A model's constructor reads its validated list and the list's place in messages
/// ("in.xml: Kiln/Materials/steel/Model").
using ConstitutiveModelRegistry =
    Registry<ConstitutiveModel, const Teuchos::ParameterList &, const std::string &>;

/// Every model, by the name of its "Type": "Linear Elastic" (the default), "Power Law", "MTS".
const ConstitutiveModelRegistry &constitutive_models();

/// The valid list of a model block: "Type" and every model's parameters (a parameter that
/// several models read, the elastic constants, appears once).
Teuchos::ParameterList constitutive_model_parameters();

/// The model of `user` (a model block: "Type" and that model's parameters), checked: unknown
/// names, values out of range and a parameter of another Type are InputErrors naming
/// `where: path/"parameter"`.
std::unique_ptr<ConstitutiveModel> create_constitutive_model(const Teuchos::ParameterList &user,
                                                             const std::string &where,
                                                             const std::string &path);
} // namespace kiln
