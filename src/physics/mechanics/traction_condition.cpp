#include "physics/mechanics/traction_condition.hpp"

#include "base/errors.hpp"
#include "physics/mechanics/traction_kernel.hpp"

#include <Teuchos_Array.hpp>

namespace kiln
{
std::string TractionCondition::description()
{
  return "a load vector per area";
}

Teuchos::ParameterList TractionCondition::valid_parameters()
{
  Teuchos::ParameterList p;
  p.set("Traction", Teuchos::Array<double>(),
        "for Type \"Traction\", where it is required: the load per area (tx, ty, tz) [Pa]");
  return p;
}

TractionCondition::TractionCondition(const BoundaryConditionInput &input) : BoundaryCondition(input)
{
  const auto &t = input.params.get<Teuchos::Array<double>>("Traction");
  KILN_CHECK_INPUT(t.size() == 3, input.path + "/\"Traction\"",
                   "must have 3 entries (tx, ty, tz) [Pa], has " << t.size());
  traction_ = {t[0], t[1], t[2]};
}

void TractionCondition::evaluate(const FaceState &state, LocalSystem &local) const
{
  TractionKernel::evaluate(state.fv, traction_, state.slots.u, local);
}
} // namespace kiln
