#include "contact/min_complementarity.hpp"

namespace kiln
{
std::string MinComplementarity::description()
{
  return "p - max(0, p - c g) (semismooth Newton: an active-set method)";
}

ComplementarityFunction::Value MinComplementarity::evaluate(const double P, const double cg) const
{
  Value v;
  v.combined = P - cg > 0.0;
  if (v.combined)
  {
    v.C = cg;
    v.dC_dP = 0.0;
    v.dC_dcg = 1.0;
  }
  return v;
}
} // namespace kiln
