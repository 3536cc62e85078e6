// The manufactured elasticity solution of mms_elastic_convergence_test.cpp on the quadratic
// types TETRA10, HEX20, HEX27, on n = 2, 4, 8 cells per edge: the orders of the last refinement
// must be at least 2.8 (L2) and 1.8 (H1 seminorm). The observed orders:
// doc/verification/manufactured-solutions.md.
// KILN_TEST_NP: 1
#include "support/manufactured_solutions.hpp"

#include <gtest/gtest.h>

using kiln_test::mms::Case;

class MmsElasticQuadratic : public ::testing::TestWithParam<Case>
{
};

TEST_P(MmsElasticQuadratic, ConvergenceOrders)
{
  kiln_test::mms::check_orders(kiln_test::mms::Problem::elasticity, "elasticity", GetParam());
}

INSTANTIATE_TEST_SUITE_P(QuadraticTypes, MmsElasticQuadratic,
                         ::testing::ValuesIn(kiln_test::mms::quadratic_types()),
                         kiln_test::mms::case_name);
