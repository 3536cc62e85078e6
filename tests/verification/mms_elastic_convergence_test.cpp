// Manufactured solution for linear elasticity (constant E = 2 Pa, nu = 0.25, no body force) on
// the linear element types of the box generator and on its mixed mesh (HEX8 + PYRAMID5 +
// TETRA4); the quadratic types: mms_elastic_quadratic_test.cpp (each test below 30 s on one
// core). u = 1e-3 grad h, h = sin(1.2 x + 0.3) cos(1.6 y + 0.2) exp(2 (z - 1)) harmonic (so
// that div u = 0 and Laplace u = 0: Navier's equation holds), prescribed on the faces of the
// unit cube (tests/support/manufactured_solutions.hpp). The L2 and H1-seminorm errors of u on
// n = 4, 8, 16 cells per edge are printed; the orders of the last refinement must be at least
// 1.8 and 0.9. The observed orders: doc/verification/manufactured-solutions.md.
// KILN_TEST_NP: 1
#include "support/manufactured_solutions.hpp"

#include <gtest/gtest.h>

using kiln_test::mms::Case;

class MmsElastic : public ::testing::TestWithParam<Case>
{
};

TEST_P(MmsElastic, ConvergenceOrders)
{
  kiln_test::mms::check_orders(kiln_test::mms::Problem::elasticity, "elasticity", GetParam());
}

INSTANTIATE_TEST_SUITE_P(LinearTypes, MmsElastic,
                         ::testing::ValuesIn(kiln_test::mms::linear_types()),
                         kiln_test::mms::case_name);
