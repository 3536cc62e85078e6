#pragma once
/// The min complementarity function: semismooth Newton is an active-set method.
#include "contact/complementarity_function.hpp"

namespace kiln
{
/// C(P, c g) = P - max(0, P - c g). Where P - c g > 0 the pair is in contact: C = c g (its
/// rows are combined; dC/dP = 0, dC/d(cg) = 1); elsewhere C = P = 0, the pair's rows stay.
class MinComplementarity final : public ComplementarityFunction
{
public:
  static std::string description();
  static Teuchos::ParameterList valid_parameters() { return {}; }
  Value evaluate(double P, double cg) const override;
};
} // namespace kiln
