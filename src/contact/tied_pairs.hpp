#pragma once
/// The law of the interface kinds that always hold: every claimed axis tied.
#include "contact/condensed_pairs.hpp"

namespace kiln
{
/// C = c g on every axis it claims, always combined: the opening along each is held at zero,
/// whatever the sign of the multiplier (a pressure or a tension). Every pair holds at every
/// state; nothing changes its law. The kinds differ in the axes they claim.
class TiedPairs : public CondensedPairs
{
public:
  bool jacobian_evaluated() override { return false; }

protected:
  using CondensedPairs::CondensedPairs;

private:
  /// C = c g, dC/dP = 0, dC/d(cg) = 1, combined.
  ComplementarityFunction::Value law(bool, double, double cg) const override
  {
    return {true, cg, 0.0, 1.0};
  }
  bool holds(double, double) const override { return true; }
};
} // namespace kiln
