// The closing contact box with E(T) and alpha(T) (issue 31: "the closed state against the spec's
// formulas evaluated at the final temperature"): tests/regression/report/contact-box-close-ET.xml,
// inputs/contact-box-close.xml with E a table (7.2e10 Pa at 280 K, 6.4e10 Pa at 320 K, linear
// between), nu = 1/3 and alpha the expression 2.0e-5 + 1.5e-7 (T - 280) 1/K (the secant
// coefficient from T_ref = 298 K, doc/materials.md), run with contact_box_deck's tolerances
// (steps of at most 2 s, Newton 1e-12): at 0 s the open-gap state at 288 K and at 150 s the
// closed-gap state at 308 K, each with E and alpha evaluated here by hand at that temperature,
// to 1e-9 (every cell's stress and strain, every node's displacement, every gap node's pressure
// and opening, and the thermal strain, which the general path of the elasticity kernel takes from
// the model: alpha(T) (T - T_ref), the secant definition); open at
// 50 s, closed at 53 s. A uniform state at T is the constant-property state with the material's
// values at T; E(T_ref) instead of E(308 K), or alpha read as the instantaneous coefficient,
// would each be off by 3%.
// KILN_TEST_NP: 1 2
#include "support/contact_box.hpp"
#include "support/contact_box_runs.hpp"
#include "support/results_files.hpp"

#include <Teuchos_DefaultComm.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace
{
using namespace kiln_test;

const std::string deck =
    std::string(KILN_SOURCE_DIR) + "/tests/regression/report/contact-box-close-ET.xml";

/// E(T) of the deck's table: linear between (280 K, 7.2e10 Pa) and (320 K, 6.4e10 Pa).
double youngs_modulus(const double T)
{
  return 7.2e10 + (6.4e10 - 7.2e10) * (T - 280.0) / (320.0 - 280.0);
}

/// alpha(T) of the deck's expression [1/K].
double thermal_expansion(const double T)
{
  return 2.0e-5 + 1.5e-7 * (T - 280.0);
}

constexpr double nu = 1.0 / 3.0;
} // namespace

TEST(ContactBoxTemperatureDependent, ClosedStateAtTheFinalTemperature)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string label = "contact-box-close-ET.xml";
  const std::string base = temporary_base("close_ET", *comm);
  const kiln_test::Run r = kiln_test::run(
      contact_box_deck(deck, MeshKind::generated, base, {0.0, 50.0, 53.0, 150.0}), label);
  if (comm->getRank() == 0)
  {
    const std::string h5 = base + ".h5";
    const UniformState open = open_gap_state(youngs_modulus(288.0), nu, thermal_expansion(288.0),
                                             288.0 - spec_T_ref, 0.02, 45.0, -30.0);
    const UniformState closed = closed_gap_state(
        youngs_modulus(308.0), nu, thermal_expansion(308.0), 308.0 - spec_T_ref, 45.0, -30.0);
    EXPECT_NEAR(closed.contact_pressure, 6.64e10 * 2.42e-5 * 10.0 / (1.0 - nu), 1e-3);
    const auto exact = [](const double T)
    {
      return StateTolerance{1e-9, zero_stress_tolerance, zero_strain_tolerance,
                            1e-9 * std::abs(T - spec_T_ref)};
    };
    check_uniform_state(label, h5, 0, 0.0, 288.0, open, false, exact(288.0), r);
    check_gap(label, h5, 1, 50.0, false, r);
    check_gap(label, h5, 2, 53.0, true, r);
    check_uniform_state(label, h5, 3, 150.0, 308.0, closed, true, exact(308.0), r);
  }
  remove_results(base, *comm);
}
