#pragma once
/// How a contact pair's conditions enter the Newton solve: a complementarity function.
#include "base/registry.hpp"

#include <Teuchos_ParameterList.hpp>

#include <string>

namespace kiln
{
/// For one pair, g >= 0, p >= 0, p g = 0 (g the opening, p the pressure) is written as
/// C(P, c g) = 0, with P the pressure that balances the pair's assembled rows and c g the
/// opening scaled to a pressure (doc/contact.md). evaluate() gives C, its derivatives and
/// whether the pair's rows are combined (row a := R_a + R_b, row b := A C(P, c g)) or stay as
/// they are, which says p = 0: the sides move apart freely.
class ComplementarityFunction
{
public:
  struct Value
  {
    bool combined = false; ///< the rows are combined (else they stay: p = 0)
    double C = 0.0;        ///< C(P, c g) [Pa]
    double dC_dP = 0.0;    ///< [-]
    double dC_dcg = 0.0;   ///< [-]
  };
  virtual ~ComplementarityFunction() = default;
  /// P [Pa], cg = c g [Pa].
  virtual Value evaluate(double P, double cg) const = 0;
};

/// Every complementarity function Kiln has, by the name of Contact/"Complementarity Function"
/// (complementarity_functions.cpp: one line per function).
const Registry<ComplementarityFunction> &complementarity_functions();
} // namespace kiln
