#pragma once
/// A scalar function of time (constant, smooth step, piecewise linear table) or of space and
/// time (a formula in x, y, z, t).
#include "base/expression.hpp"
#include "base/piecewise_linear.hpp"
#include "mesh/mesh.hpp"

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
/// - "Expression": a formula in x, y, z [m] (the reference coordinates, after any Coordinate
///   Scale) and t [s] (base/expression.hpp).
/// A caller that evaluates at points asks value(t, x); value(t) is for functions that do not
/// vary in space (every kind but a formula naming x, y or z).
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
  /// f = the formula `text` in x, y, z, t; `where` names it in messages (InputError if it
  /// cannot be read).
  static TimeFunction expression(const std::string &text, const std::string &where);

  /// f(t) [unit of the quantity: K for a temperature]; t in [s]. Not for a function that
  /// varies in space.
  double value(double t) const;
  /// f(x, t): x [m] a point of the reference configuration, t [s].
  double value(double t, const Point &x) const
  {
    return kind_ == Kind::expression ? (*expression_)(x[0], x[1], x[2], t) : value(t);
  }
  /// Whether f depends on x, y or z (a formula that names them).
  bool varies_in_space() const
  {
    return kind_ == Kind::expression && expression_->depends_on_space();
  }
  /// Throws InputError naming `where` if f is not finite at any of `points` at time t.
  void check_finite(const std::vector<Point> &points, double t, const std::string &where) const;

private:
  enum class Kind
  {
    constant,
    smooth_step,
    table,
    expression
  };
  Kind kind_ = Kind::constant;
  /// Constant: values_ = {value}. Smooth step: times_ = {x0, x1}, values_ = {y0, y1}.
  std::vector<double> times_;
  std::vector<double> values_{0.0};
  PiecewiseLinear table_;                        ///< Table
  std::shared_ptr<const Expression> expression_; ///< Expression
};

/// A boundary value during one evaluation, at the points a kernel asks for: f(t, x) of a
/// function that varies in space, else f(t) computed once (or a constant). Holds f by
/// address: f must outlive it (it lives for one kernel call).
class ValueAt
{
public:
  /// A constant [unit of the quantity].
  ValueAt(const double constant) : value_(constant) {} // NOLINT: implicit, as a plain value
  /// f at time t [s].
  ValueAt(const TimeFunction &f, const double t)
      : f_(f.varies_in_space() ? &f : nullptr), t_(t), value_(f_ ? 0.0 : f.value(t))
  {
  }
  /// The value at x [m].
  double operator()(const Point &x) const { return f_ ? f_->value(t_, x) : value_; }

private:
  const TimeFunction *f_ = nullptr;
  double t_ = 0.0;
  double value_;
};
} // namespace kiln
