#pragma once
/// A material property as a function of temperature: constant, a table in T, or a formula in T.
#include "base/expression.hpp"
#include "base/piecewise_linear.hpp"
#include "physics/materials/property_range.hpp"

#include <Teuchos_ParameterList.hpp>

#include <memory>
#include <string>
#include <vector>

namespace kiln
{
/// p(T), T [K], in the unit of the property (doc/materials.md, "Properties"):
/// - "Constant": p = "Value", dp/dT = 0. The input may give the property as a plain number
///   (set_number_or_sublist), which means this.
/// - "Table": piecewise linear through ("Temperatures", "Values"), constant beyond the first
///   and the last temperature. derivative() is the slope of the interval containing T; at a
///   breakpoint T_i it is the slope of the interval to its right [T_i, T_{i+1}] (0 at and
///   beyond the last temperature, 0 below the first): the one-sided derivative that Newton
///   sees when T increases.
/// - "Expression": a formula in T (base/expression.hpp, Variables::temperature);
///   derivative() is Expression::temperature_derivative (a 5-point central difference with
///   h = 1e-4 max(|T|, 1 K), about 1e-12 relative: muparser has no symbolic derivative).
/// Range: a table must lie in the property's PropertyRange at each of its points, which is
/// the whole table (a linear interpolant of values in an interval stays in it). A formula is
/// checked, once at set-up, at its "Temperatures" (the sample temperatures, which the user
/// sets to cover the run's range): a formula can leave the range between or beyond them, and
/// that is not checked while the run evaluates it (a check per quadrature point and Newton
/// iteration would cost on the hottest path).
class TemperatureFunction
{
public:
  /// The input of one property: "Type", "Value" (default `default_value`, with `range`'s
  /// validator), "Temperatures", "Values", "Expression"; `symbol_and_unit` names the property
  /// in the doc strings, e.g. "k [W/(m K)]". Without arguments: a property > 0, default 1 (the
  /// conductivity's list, ConductivityModel).
  static Teuchos::ParameterList
  valid_parameters(double default_value = 1.0, const std::string &symbol_and_unit = "k [W/(m K)]",
                   const PropertyRange &range = PropertyRange::positive());
  /// `validated_params` must have been through kiln::validated() against valid_parameters();
  /// `where` names the property in messages ("in.xml: Kiln/Materials/steel/Density").
  /// Throws InputError if a table has fewer than 2 points, temperatures that are not strictly
  /// increasing, a different number of values than temperatures, or a value outside `range`;
  /// if a formula cannot be read, or is outside `range` (or not finite) at one of its sample
  /// temperatures.
  TemperatureFunction(const Teuchos::ParameterList &validated_params, const std::string &where,
                      const PropertyRange &range = PropertyRange::positive());
  /// p = 1.
  TemperatureFunction() = default;
  /// p constant, in the property's unit.
  static TemperatureFunction constant(double value);

  /// p(T); T in [K].
  double value(double T) const
  {
    if (expression_)
      return expression_->of_temperature(T);
    return table_.value(T);
  }
  /// dp/dT [unit of p / K]; T in [K]. At a table breakpoint, the slope to the right.
  double derivative(double T) const
  {
    if (expression_)
      return constant_ ? 0.0 : expression_->temperature_derivative(T);
    return table_.slope(T);
  }
  /// Whether p does not depend on T ("Constant", or a formula that does not name T; a "Table"
  /// counts as varying).
  bool is_constant() const { return constant_; }
  /// Whether p is a formula ("Expression"), smooth between any temperatures, rather than a
  /// table or a number.
  bool is_expression() const { return expression_ != nullptr; }
  /// The temperatures [K] where the range was checked: a table's points, a formula's sample
  /// temperatures, none for a constant. Material checks combinations of properties there.
  const std::vector<double> &checked_temperatures() const { return checked_temperatures_; }

private:
  /// Table (at least 2 points), or the single point (0 K, value) of a constant.
  PiecewiseLinear table_{{0.0}, {1.0}, {}};
  std::shared_ptr<const Expression> expression_; ///< Expression, else null
  bool constant_ = true;
  std::vector<double> checked_temperatures_;
};
} // namespace kiln
