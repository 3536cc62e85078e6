#pragma once
/// A formula in x, y, z and t, parsed once by muparser (libmuparser-dev).
#include <memory>
#include <string>

namespace kiln
{
/// f(x, y, z, t) from a text such as "1 + x + 2*y + 3*z" or "300 + 10*sin(pi*t/60)", or, for
/// a material property, f(T) from a text such as "2.4e2 - 0.05*(T - 300)" (Variables::temperature):
/// muparser's operators (+ - * / ^, comparisons, ?:) and functions (sin, cos, tan, asin, acos,
/// atan, sinh, cosh, tanh, exp, log, ln, log10, log2, sqrt, abs, sign, rint, min, max, sum,
/// avg), the constants pi (and muparser's _pi, _e); x, y, z the reference coordinates [m] and t the
/// time [s]. Copies share the parsed formula (muparser binds its variables by address; Kiln
/// evaluates on one thread per rank).
class Expression
{
public:
  /// The variables a formula may name.
  enum class Variables
  {
    space_and_time, ///< x, y, z [m] and t [s]
    temperature     ///< T [K]
  };
  /// Parses `text`; throws InputError naming `where` (the parameter) for a syntax error, a
  /// variable other than those of `variables`, or an empty text.
  Expression(const std::string &text, const std::string &where,
             Variables variables = Variables::space_and_time);

  /// f at (x, y, z) [m] and t [s].
  double operator()(double x, double y, double z, double t) const;
  /// f(T), T [K] (Variables::temperature).
  double of_temperature(double T) const;
  /// df/dT at T [K] (Variables::temperature): muparser's Diff, a 5-point central difference
  /// (f(T-2h) - 8 f(T-h) + 8 f(T+h) - f(T+2h)) / (12 h) with h = 1e-4 max(|T|, 1 K). Its error
  /// is O(h^4) from truncation plus about 1e-16 |f| / h from round-off: near 1e-12 relative
  /// for a property that varies on the scale of T itself (muparser offers no symbolic
  /// derivative). Where f has a kink (min, max, abs, ?:) it is the mean of the two slopes
  /// within 2h of the kink.
  double temperature_derivative(double T) const;
  /// Whether the formula names x, y or z.
  bool depends_on_space() const { return depends_on_space_; }
  /// Whether the formula names t.
  bool depends_on_time() const { return depends_on_time_; }
  /// Whether the formula names T.
  bool depends_on_temperature() const { return depends_on_temperature_; }
  /// The text as given.
  const std::string &text() const { return text_; }

private:
  struct Parser;
  std::shared_ptr<Parser> parser_;
  std::string text_;
  bool depends_on_space_ = false;
  bool depends_on_time_ = false;
  bool depends_on_temperature_ = false;
};
} // namespace kiln
