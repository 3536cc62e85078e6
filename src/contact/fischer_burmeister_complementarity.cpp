#include "contact/fischer_burmeister_complementarity.hpp"

#include <cmath>

namespace kiln
{
std::string FischerBurmeisterComplementarity::description()
{
  return "p + c g - sqrt(p^2 + (c g)^2)";
}

ComplementarityFunction::Value FischerBurmeisterComplementarity::evaluate(const double P,
                                                                          const double cg) const
{
  const double rho = std::hypot(P, cg);
  Value v;
  v.combined = true;
  v.C = P + cg - rho;
  v.dC_dP = rho > 0.0 ? 1.0 - P / rho : 1.0 - 1.0 / std::sqrt(2.0);
  v.dC_dcg = rho > 0.0 ? 1.0 - cg / rho : 1.0 - 1.0 / std::sqrt(2.0);
  return v;
}
} // namespace kiln
