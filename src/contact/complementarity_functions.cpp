// The registration list of the complementarity functions: a new function is a new class in
// its own files and one line here.
#include "contact/complementarity_function.hpp"
#include "contact/fischer_burmeister_complementarity.hpp"
#include "contact/min_complementarity.hpp"

namespace kiln
{
const Registry<ComplementarityFunction> &complementarity_functions()
{
  static const Registry<ComplementarityFunction> registry = []
  {
    Registry<ComplementarityFunction> r;
    r.add<MinComplementarity>("Min");
    r.add<FischerBurmeisterComplementarity>("Fischer-Burmeister");
    return r;
  }();
  return registry;
}
} // namespace kiln
