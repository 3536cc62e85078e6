#pragma once
/// The Fischer-Burmeister complementarity function: smooth but at the origin.
#include "contact/complementarity_function.hpp"

namespace kiln
{
/// C(P, c g) = P + c g - sqrt(P^2 + (c g)^2), zero exactly where P >= 0, c g >= 0 and
/// P c g = 0. Every pair's rows are combined. dC/dP = 1 - P/rho, dC/d(cg) = 1 - c g/rho with
/// rho = sqrt(P^2 + (c g)^2); at the origin, the generalized derivative along (1, 1).
class FischerBurmeisterComplementarity final : public ComplementarityFunction
{
public:
  static std::string description();
  static Teuchos::ParameterList valid_parameters() { return {}; }
  Value evaluate(double P, double cg) const override;
};
} // namespace kiln
