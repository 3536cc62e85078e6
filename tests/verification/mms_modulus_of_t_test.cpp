// Manufactured solution for thermo-elasticity with E(T) = 2 exp((T - 300) / 20) Pa and
// alpha(T) = 1e-3 (1 + (T - 300) / 20) 1/K (nu = 0.25; issue 31) under the steady
// T = 300 + 20 z solved with it, on HEX8 and TETRA4 (4, 8, 16 cells per edge):
// u = 1e-3 grad p + w(z) e_z, p = sin(2 x + 0.3) exp(2 (y - 1)), w(z) with a uniform
// sigma_zz = 0.05 Pa through E(z) = 2 exp(z) and the thermal strain, prescribed on the faces of
// the unit cube (tests/support/manufactured_solutions.hpp). The orders of the last refinement
// must be at least 1.8 (L2) and 0.9 (H1 seminorm), as for constant properties. (With E taken
// constant the errors stop falling: the exact u_z depends on E(T).)
// KILN_TEST_NP: 1
#include "support/manufactured_solutions.hpp"

#include <gtest/gtest.h>

using kiln_test::mms::Case;

class MmsModulusOfT : public ::testing::TestWithParam<Case>
{
};

TEST_P(MmsModulusOfT, YoungsModulusAndExpansion)
{
  kiln_test::mms::check_orders(kiln_test::mms::Problem::thermoelastic_e_alpha_t, "E(T) alpha(T)",
                               GetParam());
}

INSTANTIATE_TEST_SUITE_P(HexAndTet, MmsModulusOfT,
                         ::testing::ValuesIn(kiln_test::mms::hex_and_tet()),
                         kiln_test::mms::case_name);
