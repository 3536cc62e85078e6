// Manufactured solution for steady heat conduction (constant k) on every element type of the
// box generator and on its mixed mesh (HEX8 + PYRAMID5 + TETRA4): the harmonic field
// T = 300 + 10 sin(1.2 x + 0.3) cos(1.6 y + 0.2) exp(2 (z - 1)) prescribed on the faces of
// the unit cube (tests/support/manufactured_solutions.hpp). The L2 and H1-seminorm errors on
// n = 4, 8, 16 cells per edge (quadratic types 2, 4, 8) are printed; the orders of the last
// refinement must be at least 1.8 and 0.9 (linear), 2.8 and 1.8 (quadratic). The observed
// orders: doc/verification/manufactured-solutions.md.
// KILN_TEST_NP: 1
#include "support/manufactured_solutions.hpp"

#include <gtest/gtest.h>

using kiln_test::mms::Case;

class MmsHeat : public ::testing::TestWithParam<Case>
{
};

TEST_P(MmsHeat, ConvergenceOrders)
{
  kiln_test::mms::check_orders(kiln_test::mms::Problem::heat, "heat", GetParam());
}

INSTANTIATE_TEST_SUITE_P(EveryType, MmsHeat, ::testing::ValuesIn(kiln_test::mms::every_type()),
                         kiln_test::mms::case_name);
