#pragma once
/// A formula in x, y, z and t, parsed once by muparser (libmuparser-dev).
#include <memory>
#include <string>

namespace kiln
{
/// f(x, y, z, t) from a text such as "1 + x + 2*y + 3*z" or "300 + 10*sin(pi*t/60)":
/// muparser's operators (+ - * / ^, comparisons, ?:) and functions (sin, cos, tan, asin, acos,
/// atan, sinh, cosh, tanh, exp, log, ln, log10, log2, sqrt, abs, sign, rint, min, max, sum,
/// avg), the constants pi (and muparser's _pi, _e); x, y, z the reference coordinates [m] and t the
/// time [s]. Copies share the parsed formula (muparser binds its variables by address; Kiln
/// evaluates on one thread per rank).
class Expression
{
public:
  /// Parses `text`; throws InputError naming `where` (the parameter) for a syntax error, a
  /// variable other than x, y, z, t, or an empty text.
  Expression(const std::string &text, const std::string &where);

  /// f at (x, y, z) [m] and t [s].
  double operator()(double x, double y, double z, double t) const;
  /// Whether the formula names x, y or z.
  bool depends_on_space() const { return depends_on_space_; }
  /// Whether the formula names t.
  bool depends_on_time() const { return depends_on_time_; }
  /// The text as given.
  const std::string &text() const { return text_; }

private:
  struct Parser;
  std::shared_ptr<Parser> parser_;
  std::string text_;
  bool depends_on_space_ = false;
  bool depends_on_time_ = false;
};
} // namespace kiln
