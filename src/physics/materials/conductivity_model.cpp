#include "physics/materials/conductivity_model.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_Tuple.hpp>

#include <algorithm>
#include <iterator>

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
    values_ = {p.get<double>("Value")};
    return;
  }
  const auto &temperatures = p.get<Teuchos::Array<double>>("Temperatures");
  const auto &values = p.get<Teuchos::Array<double>>("Values");
  temperatures_.assign(temperatures.begin(), temperatures.end());
  values_.assign(values.begin(), values.end());
  KILN_CHECK_INPUT(temperatures_.size() >= 2, where + "/\"Temperatures\"",
                   "has " << temperatures_.size()
                          << " entry but a table needs at least 2; for a constant k use Type "
                             "\"Constant\"");
  KILN_CHECK_INPUT(values_.size() == temperatures_.size(), where + "/\"Values\"",
                   "has " << values_.size() << " entries but \"Temperatures\" has "
                          << temperatures_.size() << "; give one value per temperature");
  for (std::size_t i = 1; i < temperatures_.size(); ++i)
    KILN_CHECK_INPUT(temperatures_[i] > temperatures_[i - 1], where + "/\"Temperatures\"",
                     "must be strictly increasing, but entry " << i << " (" << temperatures_[i]
                                                               << " K) <= entry " << i - 1 << " ("
                                                               << temperatures_[i - 1] << " K)");
}

ConductivityModel ConductivityModel::constant(const double k)
{
  ConductivityModel m;
  m.values_ = {k};
  return m;
}

std::size_t ConductivityModel::interval(const double T) const
{
  const auto upper = std::upper_bound(temperatures_.begin(), temperatures_.end(), T);
  return static_cast<std::size_t>(std::distance(temperatures_.begin(), upper)) - 1;
}

double ConductivityModel::value(const double T) const
{
  if (temperatures_.empty() || T <= temperatures_.front())
    return values_.front();
  if (T >= temperatures_.back())
    return values_.back();
  const std::size_t k = interval(T);
  const double w = (T - temperatures_[k]) / (temperatures_[k + 1] - temperatures_[k]);
  return (1 - w) * values_[k] + w * values_[k + 1];
}

double ConductivityModel::derivative(const double T) const
{
  if (temperatures_.empty() || T < temperatures_.front() || T >= temperatures_.back())
    return 0.0;
  const std::size_t k = interval(T);
  return (values_[k + 1] - values_[k]) / (temperatures_[k + 1] - temperatures_[k]);
}
} // namespace kiln
