// Manufactured solution for steady heat conduction with k(T) = 1 + 0.02 (T - 300) W/(m K)
// (issue 31), given as an Expression in T and as a Table of two points, on HEX8 and TETRA4 (4, 8,
// 16 cells per edge): T = 300 + (sqrt(1 + 0.4 h) - 1) / 0.02, whose Kirchhoff transform 10 h is
// harmonic (h as in mms_heat_convergence_test.cpp), prescribed on the faces of the unit cube
// (tests/support/manufactured_solutions.hpp). The orders of the last refinement must be at
// least 1.8 (L2) and 0.9 (H1 seminorm), as for constant k.
// KILN_TEST_NP: 1
#include "support/manufactured_solutions.hpp"

#include <gtest/gtest.h>

using kiln_test::mms::Case;
using kiln_test::mms::Problem;

class MmsConductivityOfT : public ::testing::TestWithParam<Case>
{
};

TEST_P(MmsConductivityOfT, Expression)
{
  kiln_test::mms::check_orders(Problem::heat_k_expression, "k(T) expression", GetParam());
}

TEST_P(MmsConductivityOfT, Table)
{
  kiln_test::mms::check_orders(Problem::heat_k_table, "k(T) table", GetParam());
}

INSTANTIATE_TEST_SUITE_P(HexAndTet, MmsConductivityOfT,
                         ::testing::ValuesIn(kiln_test::mms::hex_and_tet()),
                         kiln_test::mms::case_name);
