#pragma once
/// Jacobians as dense matrices, and their finite-difference counterparts, for the checks that a
/// Jacobian is the derivative of its residual (style.md sec. 3):
/// - of a local system (a kernel on one cell or face): local_jacobian, and
///   finite_difference_jacobian of a residual function, column by column;
/// - of any assembled kiln::NonlinearProblem: dense_rows of J (the owned rows over all global
///   columns), and finite_difference_rows, the same rows by central differences of evaluate(),
///   column by column with every rank in lock step.
/// What counts as close enough, and against which scale, stays with each test.
#include "discretization/local_system.hpp"
#include "discretization/nonlinear_problem.hpp"

#include <functional>
#include <vector>

namespace kiln_test
{
/// A dense matrix, row by row.
using Dense = std::vector<std::vector<double>>;
using GO = kiln::NonlinearProblem::Map::global_ordinal_type; ///< = kiln::GO

/// The largest |entry|.
double max_abs(const Dense &m);
double max_abs(const std::vector<double> &values);
/// max |a_rc - b_rc| over the entries of a (b at least as large).
double max_difference(const Dense &a, const Dense &b);

/// The Jacobian of a local system as a dense matrix in its local-index order.
Dense local_jacobian(const kiln::LocalSystem &local);

/// Central differences of residual(state), column by column: column c is
/// (R(state + eps(c) e_c) - R(state - eps(c) e_c)) / (2 eps(c)).
Dense finite_difference_jacobian(
    const std::function<std::vector<double>(const std::vector<double> &)> &residual,
    const std::vector<double> &state, const std::function<double(int column)> &eps);
/// The same with one step eps for every column.
Dense finite_difference_jacobian(
    const std::function<std::vector<double>(const std::vector<double> &)> &residual,
    const std::vector<double> &state, double eps);

/// The owned rows of J as dense rows over all n_columns global columns (local row i is global
/// row J.getRowMap()->getGlobalElement(i)).
Dense dense_rows(const kiln::NonlinearProblem::Matrix &J, GO n_columns);
/// The whole of J (n x n) on every rank (collective).
Dense dense_matrix(const kiln::NonlinearProblem::Matrix &J, GO n);

/// Central differences of problem.evaluate() at x, in the layout of dense_rows: for every
/// global unknown j in turn, on every rank (evaluate() is collective), x_j is moved by +eps(j)
/// and by -eps(j) and then put back, and column j is (F(x + eps e_j) - F(x - eps e_j)) / (2
/// eps) on the owned rows. `after_evaluate`, if given, is called after each perturbed
/// evaluation with the perturbed x (to look at what else the state decided, e.g. the contact
/// active set). x is as on entry on return.
Dense finite_difference_rows(
    kiln::NonlinearProblem &problem, kiln::NonlinearProblem::Vector &x,
    const std::function<double(GO column)> &eps,
    const std::function<void(const kiln::NonlinearProblem::Vector &)> &after_evaluate = {});

/// The blocks of the Thermo-Elasticity layout (T, u_x, u_y, u_z at each node, global id 4 n +
/// slot): 0 T-T, 1 T-u, 2 u-T, 3 u-u for (row, column).
inline int thermo_mechanical_block(const GO row, const GO column)
{
  return 2 * (row % 4 != 0) + (column % 4 != 0);
}
inline constexpr const char *thermo_mechanical_block_names[4] = {"T-T", "T-u", "u-T", "u-u"};
} // namespace kiln_test
