#include "physics/materials/time_function.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_Tuple.hpp>

#include <cmath>

namespace kiln
{
Teuchos::ParameterList TimeFunction::valid_parameters()
{
  Teuchos::ParameterList p("Time Function");
  p.set("Type", "Constant",
        "\"Constant\": f = Value; \"Smooth Step\": from Start Value at Start Time to End Value "
        "at End Time, y0 + (y1 - y0) s^2 (3 - 2 s) in between; \"Table\": piecewise linear "
        "through (Times, Values), constant beyond the ends; \"Expression\": a formula in x, y, "
        "z [m] and t [s] (Expression)",
        choice_validator({"Constant", "Smooth Step", "Table", "Expression"}));
  p.set("Value", 0.0, "f for Type \"Constant\" [unit of the quantity: K for a temperature]");
  p.set("Start Time", 0.0, "x0 for Type \"Smooth Step\": f = Start Value for t <= x0 [s]");
  p.set("End Time", 1.0,
        "x1 for Type \"Smooth Step\", > Start Time: f = End Value for t >= x1 [s]");
  p.set("Start Value", 0.0,
        "y0 for Type \"Smooth Step\" [unit of the quantity: K for a temperature]");
  p.set("End Value", 0.0,
        "y1 for Type \"Smooth Step\" [unit of the quantity: K for a temperature]");
  p.set("Times", Teuchos::Array<double>(Teuchos::tuple(0.0)),
        "for Type \"Table\": at least one time, strictly increasing [s]",
        double_array_validator(0));
  p.set("Values", Teuchos::Array<double>(Teuchos::tuple(0.0)),
        "for Type \"Table\": f at each of Times, as many as Times [unit of the quantity: K for "
        "a temperature]",
        double_array_validator(0));
  p.set("Expression", "0",
        "for Type \"Expression\": f as a formula in x, y, z (the point's reference coordinates "
        "[m]) and t [s], e.g. \"1 + x + 2*y + 3*z\" or \"300 + 10*sin(pi*t/60)\"; operators "
        "+ - * / ^, functions such as sin, cos, exp, log, sqrt, abs, min, max, constant pi "
        "(muparser) [unit of the quantity: K for a temperature]");
  return p;
}

TimeFunction::TimeFunction(const Teuchos::ParameterList &p, const std::string &where)
{
  const std::string type = p.get<std::string>("Type");
  if (type == "Constant")
  {
    kind_ = Kind::constant;
    values_ = {p.get<double>("Value")};
  }
  else if (type == "Smooth Step")
  {
    kind_ = Kind::smooth_step;
    times_ = {p.get<double>("Start Time"), p.get<double>("End Time")};
    values_ = {p.get<double>("Start Value"), p.get<double>("End Value")};
    KILN_CHECK_INPUT(times_[1] > times_[0], where + "/\"End Time\"",
                     "= " << times_[1] << " must be > \"Start Time\" = " << times_[0]
                          << "; for a sudden change use Type \"Table\" with two close times");
  }
  else if (type == "Expression")
    *this = expression(p.get<std::string>("Expression"), where + "/\"Expression\"");
  else
  {
    kind_ = Kind::table;
    const auto &times = p.get<Teuchos::Array<double>>("Times");
    const auto &values = p.get<Teuchos::Array<double>>("Values");
    KILN_CHECK_INPUT(!times.empty(), where + "/\"Times\"", "must have at least one entry");
    table_ = PiecewiseLinear({times.begin(), times.end()}, {values.begin(), values.end()},
                             {where, "Times", "Values", ""});
  }
}

TimeFunction TimeFunction::expression(const std::string &text, const std::string &where)
{
  TimeFunction f;
  f.kind_ = Kind::expression;
  f.expression_ = std::make_shared<const Expression>(text, where);
  return f;
}

TimeFunction TimeFunction::constant(const double value)
{
  TimeFunction f;
  f.kind_ = Kind::constant;
  f.values_ = {value};
  return f;
}

double TimeFunction::value(const double t) const
{
  switch (kind_)
  {
  case Kind::constant:
    return values_[0];
  case Kind::smooth_step:
  {
    if (t <= times_[0])
      return values_[0];
    if (t >= times_[1])
      return values_[1];
    const double s = (t - times_[0]) / (times_[1] - times_[0]);
    return values_[0] + (values_[1] - values_[0]) * s * s * (3 - 2 * s);
  }
  case Kind::table:
    return table_.value(t);
  case Kind::expression:
    KILN_ASSERT(!expression_->depends_on_space(), "value(t) of a function of space");
    return (*expression_)(0.0, 0.0, 0.0, t);
  }
  return values_[0];
}

void TimeFunction::check_finite(const std::vector<Point> &points, const double t,
                                const std::string &where) const
{
  if (kind_ != Kind::expression)
    return;
  for (const Point &x : points)
  {
    const double f = value(t, x);
    KILN_CHECK_INPUT(std::isfinite(f), where + "/\"Expression\"",
                     "= \"" << expression_->text() << "\" is " << f << " at (" << x[0] << ", "
                            << x[1] << ", " << x[2] << ") m, t = " << t
                            << " s; give a formula that is finite wherever it applies");
  }
}
} // namespace kiln
