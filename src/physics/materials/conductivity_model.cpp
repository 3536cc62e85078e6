#include "physics/materials/conductivity_model.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_Tuple.hpp>

namespace kiln
{
Teuchos::ParameterList ConductivityModel::valid_parameters()
{
  Teuchos::ParameterList p("Conductivity");
  p.set("Type", "Constant",
        "\"Constant\": k = Value; \"Table\": piecewise linear in T through (Temperatures, "
        "Values), constant beyond the ends",
        choice_validator({"Constant", "Table"}));
  p.set("Value", 1.0, "k for Type \"Constant\", must be > 0 [W/(m K)]",
        positive_double_validator());
  p.set("Temperatures", Teuchos::Array<double>(Teuchos::tuple(273.15, 373.15)),
        "for Type \"Table\": at least 2 temperatures, strictly increasing, each > 0 [K]",
        positive_double_array_validator(0));
  p.set("Values", Teuchos::Array<double>(Teuchos::tuple(1.0, 1.0)),
        "for Type \"Table\": k at each of Temperatures, as many as Temperatures, each > 0 "
        "[W/(m K)]",
        positive_double_array_validator(0));
  return p;
}

ConductivityModel::ConductivityModel(const Teuchos::ParameterList &p, const std::string &where)
{
  if (p.get<std::string>("Type") == "Constant")
  {
    *this = constant(p.get<double>("Value"));
    return;
  }
  const auto &temperatures = p.get<Teuchos::Array<double>>("Temperatures");
  const auto &values = p.get<Teuchos::Array<double>>("Values");
  KILN_CHECK_INPUT(temperatures.size() >= 2, where + "/\"Temperatures\"",
                   "has " << temperatures.size()
                          << " entry but a table needs at least 2; for a constant k use Type "
                             "\"Constant\"");
  k_of_T_ =
      PiecewiseLinear({temperatures.begin(), temperatures.end()}, {values.begin(), values.end()},
                      {where, "Temperatures", "Values", " K"});
}

ConductivityModel ConductivityModel::constant(const double k)
{
  ConductivityModel m;
  m.k_of_T_ = PiecewiseLinear({0.0}, {k}, {});
  return m;
}

double ConductivityModel::value(const double T) const
{
  return k_of_T_.value(T);
}

double ConductivityModel::derivative(const double T) const
{
  return k_of_T_.slope(T);
}

bool ConductivityModel::is_constant() const
{
  return k_of_T_.n_points() == 1;
}
} // namespace kiln
