// Tests src/physics/quadrature_state_setup.cpp: no storage for models without state; cells of
// a stateless model get no points, the others as many as they are given (not 8 for all); every
// point starts from the model's initial state, committed; models with different state
// components are an input error.
#include "physics/quadrature_state_setup.hpp"

#include "base/errors.hpp"
#include "support/accumulating_state_model.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

using testing::HasSubstr;

namespace
{
/// No state (as an elastic model).
class Stateless final : public kiln::ConstitutiveModel
{
public:
  void initial_state(double * /*state*/) const override {}
  double thermal_strain(double /*temperature*/) const override { return 0.0; }
  void evaluate(const kiln::PointInput & /*in*/, const double * /*old_state*/,
                double * /*new_state*/, kiln::PointResponse &out) const override
  {
    out = kiln::PointResponse{};
  }
};

/// One component, "eqps".
class OtherState final : public kiln::ConstitutiveModel
{
public:
  int n_state() const override { return 1; }
  void initial_state(double *state) const override { state[0] = 0.0; }
  std::vector<std::string> state_names() const override { return {"eqps"}; }
  double thermal_strain(double /*temperature*/) const override { return 0.0; }
  void evaluate(const kiln::PointInput & /*in*/, const double * /*old_state*/,
                double * /*new_state*/, kiln::PointResponse &out) const override
  {
    out = kiln::PointResponse{};
  }
};
} // namespace

TEST(QuadratureStateSetup, NoModelWithStateKeepsNothing)
{
  const Stateless elastic;
  const auto state = kiln::make_quadrature_state(
      {&elastic, nullptr}, {0, 1, 2}, [&](int) { return &elastic; }, [](int) { return 8; },
      "test.xml: Kiln/Materials");
  EXPECT_EQ(state, nullptr);
}

TEST(QuadratureStateSetup, PointsOfTheStatefulCellsFromTheInitialState)
{
  const Stateless elastic;
  const kiln_test::AccumulatingStateModel accumulating;
  // Owned cells 4, 5, 6, 9: 5 is elastic; the others have 1, 8 or 27 points (their types).
  const auto state = kiln::make_quadrature_state(
      {&elastic, &accumulating}, {4, 5, 6, 9},
      [&](const int cell) -> const kiln::ConstitutiveModel * {
        return cell == 5 ? static_cast<const kiln::ConstitutiveModel *>(&elastic) : &accumulating;
      },
      [](const int cell) { return cell == 4   ? 1
                                  : cell == 6 ? 8
                                              : 27; },
      "test.xml: Kiln/Materials");
  ASSERT_NE(state, nullptr);
  EXPECT_EQ(state->names(), accumulating.state_names());
  EXPECT_EQ(state->n_points(0), 1);
  EXPECT_EQ(state->n_points(1), 0);
  EXPECT_EQ(state->n_points(2), 8);
  EXPECT_EQ(state->n_points(3), 27);
  for (int c = 0; c < state->n_cells(); ++c)
    for (int q = 0; q < state->n_points(c); ++q)
    {
      EXPECT_EQ(state->old(c, q)[2], 1.0); // AccumulatingStateModel's initial integral
      EXPECT_EQ(state->current(c, q)[2], 1.0);
    }
}

TEST(QuadratureStateSetup, ModelsWithOtherStatesAreAnInputError)
{
  const kiln_test::AccumulatingStateModel accumulating;
  const OtherState other;
  try
  {
    kiln::make_quadrature_state(
        {&accumulating, &other}, {0}, [&](int) { return &other; }, [](int) { return 8; },
        "test.xml: Kiln/Materials");
    FAIL() << "no error";
  }
  catch (const kiln::InputError &e)
  {
    EXPECT_THAT(e.what(), HasSubstr("test.xml: Kiln/Materials"));
    EXPECT_THAT(e.what(), HasSubstr("accepted_steps, strain_sum, temperature_time_integral; eqps"));
  }
}
