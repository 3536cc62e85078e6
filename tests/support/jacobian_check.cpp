#include "support/jacobian_check.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_OrdinalTraits.hpp>

#include <algorithm>
#include <cmath>

namespace kiln_test
{
using LO = kiln::NonlinearProblem::Map::local_ordinal_type;
using Matrix = kiln::NonlinearProblem::Matrix;
using Vector = kiln::NonlinearProblem::Vector;

double max_abs(const Dense &m)
{
  double v = 0.0;
  for (const auto &row : m)
    for (const double x : row)
      v = std::max(v, std::abs(x));
  return v;
}

double max_abs(const std::vector<double> &values)
{
  double v = 0.0;
  for (const double x : values)
    v = std::max(v, std::abs(x));
  return v;
}

double max_difference(const Dense &a, const Dense &b)
{
  double d = 0.0;
  for (std::size_t r = 0; r < a.size(); ++r)
    for (std::size_t c = 0; c < a[r].size(); ++c)
      d = std::max(d, std::abs(a[r][c] - b[r][c]));
  return d;
}

Dense local_jacobian(const kiln::LocalSystem &local)
{
  const int n = local.size();
  Dense j(n, std::vector<double>(n));
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c)
      j[r][c] = local.jacobian_values()[r * n + c];
  return j;
}

Dense finite_difference_jacobian(
    const std::function<std::vector<double>(const std::vector<double> &)> &residual,
    const std::vector<double> &state, const std::function<double(int column)> &eps)
{
  const int n = static_cast<int>(state.size());
  Dense j(n, std::vector<double>(n));
  for (int c = 0; c < n; ++c)
  {
    const double step = eps(c);
    std::vector<double> plus = state, minus = state;
    plus[c] += step;
    minus[c] -= step;
    const std::vector<double> r_plus = residual(plus), r_minus = residual(minus);
    for (int r = 0; r < n; ++r)
      j[r][c] = (r_plus[r] - r_minus[r]) / (2 * step);
  }
  return j;
}

Dense finite_difference_jacobian(
    const std::function<std::vector<double>(const std::vector<double> &)> &residual,
    const std::vector<double> &state, const double eps)
{
  return finite_difference_jacobian(residual, state, [eps](int) { return eps; });
}

Dense dense_rows(const Matrix &J, const GO n_columns)
{
  const std::size_t n_rows = J.getRowMap()->getNodeNumElements();
  Dense rows(n_rows, std::vector<double>(n_columns, 0.0));
  for (std::size_t i = 0; i < n_rows; ++i)
  {
    const std::size_t n = J.getNumEntriesInLocalRow(static_cast<LO>(i));
    Matrix::nonconst_local_inds_host_view_type cols("cols", n);
    Matrix::nonconst_values_host_view_type entries("values", n);
    std::size_t count = 0;
    J.getLocalRowCopy(static_cast<LO>(i), cols, entries, count);
    for (std::size_t e = 0; e < count; ++e)
      rows[i][J.getColMap()->getGlobalElement(cols(e))] += entries(e);
  }
  return rows;
}

Dense dense_matrix(const Matrix &J, const GO n)
{
  const Dense rows = dense_rows(J, n);
  std::vector<double> local(static_cast<std::size_t>(n * n), 0.0), global(local.size(), 0.0);
  for (std::size_t i = 0; i < rows.size(); ++i)
  {
    const GO gi = J.getRowMap()->getGlobalElement(static_cast<LO>(i));
    std::copy(rows[i].begin(), rows[i].end(), local.begin() + gi * n);
  }
  Teuchos::reduceAll(*J.getRowMap()->getComm(), Teuchos::REDUCE_SUM, static_cast<int>(n * n),
                     local.data(), global.data());
  Dense dense(n, std::vector<double>(n));
  for (GO i = 0; i < n; ++i)
    std::copy(global.begin() + i * n, global.begin() + (i + 1) * n, dense[i].begin());
  return dense;
}

Dense finite_difference_rows(kiln::NonlinearProblem &problem, Vector &x,
                             const std::function<double(GO column)> &eps,
                             const std::function<void(const Vector &)> &after_evaluate)
{
  const auto map = problem.solution_map();
  const GO n_global = static_cast<GO>(map->getGlobalNumElements());
  const std::size_t n_rows = map->getNodeNumElements();
  Vector f_plus(map), f_minus(map);
  Dense fd(n_rows, std::vector<double>(n_global, 0.0));
  for (GO j = 0; j < n_global; ++j)
  {
    const double step = eps(j);
    const LO lj = map->getLocalElement(j);
    const bool mine = lj != Teuchos::OrdinalTraits<LO>::invalid();
    const double x_j = mine ? x.getData()[lj] : 0.0;
    if (mine)
      x.replaceLocalValue(lj, x_j + step);
    problem.evaluate(x, &f_plus, nullptr);
    if (after_evaluate)
      after_evaluate(x);
    if (mine)
      x.replaceLocalValue(lj, x_j - step);
    problem.evaluate(x, &f_minus, nullptr);
    if (after_evaluate)
      after_evaluate(x);
    if (mine)
      x.replaceLocalValue(lj, x_j);
    const auto r_plus = f_plus.getData(), r_minus = f_minus.getData();
    for (std::size_t i = 0; i < n_rows; ++i)
      fd[i][j] = (r_plus[i] - r_minus[i]) / (2.0 * step);
  }
  return fd;
}
} // namespace kiln_test
