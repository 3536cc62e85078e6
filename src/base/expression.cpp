#include "base/expression.hpp"

#include "base/errors.hpp"

#include <muParser.h>

namespace kiln
{
struct Expression::Parser
{
  mu::Parser parser;
  // Bound by address: the parser reads them at every Eval.
  double x = 0.0, y = 0.0, z = 0.0, t = 0.0;
};

Expression::Expression(const std::string &text, const std::string &where)
    : parser_(std::make_shared<Parser>()), text_(text)
{
  KILN_CHECK_INPUT(text.find_first_not_of(" \t\n\r") != std::string::npos, where,
                   "is empty; give a formula in x, y, z [m] and t [s], e.g. \"1 + x + 2*y\"");
  Parser &p = *parser_;
  try
  {
    p.parser.DefineVar("x", &p.x);
    p.parser.DefineVar("y", &p.y);
    p.parser.DefineVar("z", &p.z);
    p.parser.DefineVar("t", &p.t);
    p.parser.DefineConst("pi", 3.14159265358979323846); // as deal.II's FunctionParser
    p.parser.SetExpr(text);
    // GetUsedVar parses the whole formula: syntax errors and unknown names surface here.
    const mu::varmap_type used = p.parser.GetUsedVar();
    for (const auto &[name, address] : used)
    {
      (void)address;
      depends_on_space_ = depends_on_space_ || name == "x" || name == "y" || name == "z";
      depends_on_time_ = depends_on_time_ || name == "t";
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
                            << e.GetPos() + 1
                            << "); use x, y, z [m], t [s], numbers, pi, + - * / ^ and "
                               "functions such as sin, exp, sqrt, min, max");
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
} // namespace kiln
