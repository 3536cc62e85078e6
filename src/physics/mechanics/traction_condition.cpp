#include "physics/mechanics/traction_condition.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"
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
        "for Type \"Traction\", where it is required unless Traction Expressions is given: the "
        "load per area (tx, ty, tz) [Pa]");
  p.set("Traction Expressions", Teuchos::Array<std::string>(),
        "for Type \"Traction\", instead of Traction: the load per area as three formulas "
        "(tx, ty, tz) in x, y, z [m] and t [s], e.g. {1e5*z, 0, 0}, evaluated at the Gauss "
        "points (muparser, as Type \"Expression\" of a boundary value; doc/mechanics.md) [Pa]");
  return p;
}

TractionCondition::TractionCondition(const BoundaryConditionInput &input) : BoundaryCondition(input)
{
  if (given_in_input(input.params, "Traction Expressions"))
  {
    const std::string where = input.path + "/\"Traction Expressions\"";
    KILN_CHECK_INPUT(!given_in_input(input.params, "Traction"), where,
                     "and \"Traction\" are both given; remove one");
    const auto &texts = input.params.get<Teuchos::Array<std::string>>("Traction Expressions");
    KILN_CHECK_INPUT(texts.size() == 3, where,
                     "must have 3 formulas (tx, ty, tz) [Pa], has " << texts.size());
    const std::vector<Point> points = condition_node_points(input);
    for (std::size_t d = 0; d < 3; ++d)
    {
      const std::string component = where + "[" + "xyz"[d] + "]";
      formulas_.push_back(TimeFunction::expression(texts[d], component));
      formulas_.back().check_finite(points, 0.0, component);
    }
    return;
  }
  const auto &t = input.params.get<Teuchos::Array<double>>("Traction");
  KILN_CHECK_INPUT(t.size() == 3, input.path + "/\"Traction\"",
                   "must have 3 entries (tx, ty, tz) [Pa], has " << t.size());
  traction_ = {t[0], t[1], t[2]};
}

void TractionCondition::evaluate(const FaceState &state, LocalSystem &local) const
{
  if (formulas_.empty())
    TractionKernel::evaluate(state.fv, traction_, state.slots.u, local);
  else
    TractionKernel::evaluate(state.fv,
                             {ValueAt(formulas_[0], state.time), ValueAt(formulas_[1], state.time),
                              ValueAt(formulas_[2], state.time)},
                             state.slots.u, local);
}
} // namespace kiln
