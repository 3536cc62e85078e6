#include "base/expression.hpp"

#include "base/errors.hpp"

#include <muParser.h>

#include <algorithm>
#include <cmath>

namespace kiln
{
struct Expression::Parser
{
  mu::Parser parser;
  // Bound by address: the parser reads them at every Eval.
  double x = 0.0, y = 0.0, z = 0.0, t = 0.0, T = 0.0;
};

Expression::Expression(const std::string &text, const std::string &where, const Variables variables)
    : parser_(std::make_shared<Parser>()), text_(text)
{
  const bool of_T = variables == Variables::temperature;
  KILN_CHECK_INPUT(text.find_first_not_of(" \t\n\r") != std::string::npos, where,
                   "is empty; give a formula in "
                       << (of_T ? "T [K], e.g. \"240 - 0.05*(T - 300)\""
                                : "x, y, z [m] and t [s], e.g. \"1 + x + 2*y\""));
  Parser &p = *parser_;
  try
  {
    if (of_T)
      p.parser.DefineVar("T", &p.T);
    else
    {
      p.parser.DefineVar("x", &p.x);
      p.parser.DefineVar("y", &p.y);
      p.parser.DefineVar("z", &p.z);
      p.parser.DefineVar("t", &p.t);
    }
    p.parser.DefineConst("pi", 3.14159265358979323846); // as deal.II's FunctionParser
    p.parser.SetExpr(text);
    // GetUsedVar parses the whole formula: syntax errors and unknown names surface here.
    const mu::varmap_type used = p.parser.GetUsedVar();
    for (const auto &[name, address] : used)
    {
      (void)address;
      depends_on_space_ = depends_on_space_ || name == "x" || name == "y" || name == "z";
      depends_on_time_ = depends_on_time_ || name == "t";
      depends_on_temperature_ = depends_on_temperature_ || name == "T";
    }
    p.parser.Eval();
  }
  catch (const mu::Parser::exception_type &e)
  {
    std::string reason = e.GetMsg();
    if (e.GetCode() == mu::ecUNASSIGNABLE_TOKEN || e.GetCode() == mu::ecUNEXPECTED_VAR)
      reason = "\"" + e.GetToken() + "\" is not a variable or function Kiln knows";
    KILN_CHECK_INPUT(false, where,
                     "= \"" << text << "\" cannot be read: " << reason << " (at character "
                            << e.GetPos() + 1 << "); use "
                            << (of_T ? "T [K]" : "x, y, z [m], t [s]")
                            << ", numbers, pi, + - * / ^ and functions such as sin, exp, sqrt, "
                               "min, max");
  }
}

double Expression::operator()(const double x, const double y, const double z, const double t) const
{
  Parser &p = *parser_;
  p.x = x;
  p.y = y;
  p.z = z;
  p.t = t;
  return p.parser.Eval();
}

double Expression::of_temperature(const double T) const
{
  Parser &p = *parser_;
  p.T = T;
  return p.parser.Eval();
}

double Expression::temperature_derivative(const double T) const
{
  Parser &p = *parser_;
  const double h = 1e-4 * std::max(std::abs(T), 1.0);
  return p.parser.Diff(&p.T, T, h);
}
} // namespace kiln
