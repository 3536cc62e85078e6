#pragma once
/// A scalar function of time: constant, smooth step or piecewise linear table.
#include "base/piecewise_linear.hpp"

#include <Teuchos_ParameterList.hpp>

#include <string>
#include <vector>

namespace kiln
{
/// f(t) for boundary values and loads. Its unit is the caller's (K for a temperature).
/// - "Constant": f = "Value".
/// - "Smooth Step" from (x0, y0) to (x1, y1): y0 for t <= x0, y1 for t >= x1, and
///   y0 + (y1 - y0) s^2 (3 - 2 s), s = (t - x0) / (x1 - x0), in between (the contact-box spec);
///   continuous with a continuous first derivative.
/// - "Table": piecewise linear through ("Times", "Values"), constant beyond the first and the
///   last time.
class TimeFunction
{
public:
  static Teuchos::ParameterList valid_parameters();
  /// `validated_params` must have been through kiln::validated() against valid_parameters();
  /// `where` names the list in messages ("in.xml: Kiln/Boundary Conditions/Left/Value").
  /// Throws InputError if End Time <= Start Time, or if the table times are not strictly
  /// increasing or differ in length from the values.
  TimeFunction(const Teuchos::ParameterList &validated_params, const std::string &where);
  /// f = 0.
  TimeFunction() = default;
  /// f = value [unit of the quantity].
  static TimeFunction constant(double value);

  /// f(t) [unit of the quantity: K for a temperature]; t in [s].
  double value(double t) const;

private:
  enum class Kind
  {
    constant,
    smooth_step,
    table
  };
  Kind kind_ = Kind::constant;
  /// Constant: values_ = {value}. Smooth step: times_ = {x0, x1}, values_ = {y0, y1}.
  std::vector<double> times_;
  std::vector<double> values_{0.0};
  PiecewiseLinear table_; ///< Table
};
} // namespace kiln
