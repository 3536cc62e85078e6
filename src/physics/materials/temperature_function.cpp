#include "physics/materials/temperature_function.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_Tuple.hpp>

#include <sstream>

namespace kiln
{
Teuchos::ParameterList TemperatureFunction::valid_parameters(const double default_value,
                                                             const std::string &symbol_and_unit,
                                                             const PropertyRange &range)
{
  Teuchos::ParameterList p("Property");
  p.set("Type", "Constant",
        "\"Constant\": the property is Value; \"Table\": piecewise linear in T through "
        "(Temperatures, Values), constant beyond the ends; \"Expression\": a formula in T [K] "
        "(doc/materials.md)",
        choice_validator({"Constant", "Table", "Expression"}));
  p.set("Value", default_value, "for Type \"Constant\": " + symbol_and_unit + ", " + range.text(),
        range.validator());
  p.set("Temperatures", Teuchos::Array<double>(Teuchos::tuple(273.15, 373.15)),
        "for Type \"Table\": at least 2 temperatures, strictly increasing, each > 0; for Type "
        "\"Expression\": the sample temperatures at which the formula is checked at set-up "
        "(give the run's range) [K]",
        positive_double_array_validator(0));
  p.set("Values", Teuchos::Array<double>(Teuchos::tuple(default_value, default_value)),
        "for Type \"Table\": " + symbol_and_unit +
            " at each of Temperatures, as many as "
            "Temperatures, each " +
            range.text().substr(8)); // "must be > 0" -> "> 0"
  p.set("Expression", "",
        "for Type \"Expression\": " + symbol_and_unit +
            " as a formula in T [K], e.g. \"240 - 0.05*(T - 300)\"; operators and functions as "
            "for boundary values (doc/heat.md), " +
            range.text().substr(8) + " at each of Temperatures");
  return p;
}

namespace
{
/// `where/"name" entry i (at T K) = value` (i counted from 1): how a message names a value.
std::string at_entry(const std::string &where, const std::string &name, const std::size_t i,
                     const double T, const double value)
{
  std::ostringstream s;
  s << where << "/\"" << name << "\" entry " << i + 1 << " (at " << T << " K) = " << value;
  return s.str();
}
} // namespace

TemperatureFunction::TemperatureFunction(const Teuchos::ParameterList &p, const std::string &where,
                                         const PropertyRange &range)
{
  const std::string type = p.get<std::string>("Type");
  if (type == "Constant")
  {
    const double value = p.get<double>("Value");
    std::ostringstream at;
    at << where << " = " << value;
    KILN_CHECK_INPUT(range.contains(value), at.str(), range.text());
    *this = constant(value);
    return;
  }
  const auto &temperatures = p.get<Teuchos::Array<double>>("Temperatures");
  checked_temperatures_.assign(temperatures.begin(), temperatures.end());
  if (type == "Expression")
  {
    expression_ = std::make_shared<const Expression>(p.get<std::string>("Expression"),
                                                     where + "/\"Expression\"",
                                                     Expression::Variables::temperature);
    constant_ = !expression_->depends_on_temperature();
    for (std::size_t i = 0; i < checked_temperatures_.size(); ++i)
    {
      const double T = checked_temperatures_[i];
      const double value = expression_->of_temperature(T);
      KILN_CHECK_INPUT(range.contains(value), where + "/\"Expression\"",
                       "= \"" << expression_->text() << "\" is " << value << " at T = " << T
                              << " K (" << where << "/\"Temperatures\" entry " << i + 1
                              << "), but the property " << range.text()
                              << " at every temperature; correct the formula, or the sample "
                                 "temperatures if the run never reaches "
                              << T << " K");
    }
    return;
  }
  const auto &values = p.get<Teuchos::Array<double>>("Values");
  KILN_CHECK_INPUT(temperatures.size() >= 2, where + "/\"Temperatures\"",
                   "has " << temperatures.size()
                          << " entry but a table needs at least 2; for a constant use Type "
                             "\"Constant\"");
  table_ = PiecewiseLinear({temperatures.begin(), temperatures.end()},
                           {values.begin(), values.end()}, {where, "Temperatures", "Values", " K"});
  constant_ = false;
  for (std::size_t i = 0; i < checked_temperatures_.size(); ++i)
    KILN_CHECK_INPUT(range.contains(table_.value(checked_temperatures_[i])),
                     at_entry(where, "Values", i, checked_temperatures_[i],
                              table_.value(checked_temperatures_[i])),
                     range.text() << " at every temperature of the table");
}

TemperatureFunction TemperatureFunction::constant(const double value)
{
  TemperatureFunction f;
  f.table_ = PiecewiseLinear({0.0}, {value}, {});
  return f;
}
} // namespace kiln
