#include "contact/small_sliding.hpp"

#include "contact/pair_research.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <cmath>

namespace kiln
{
double row_slip(const ContactRow &row, const std::function<Point(int node)> &u)
{
  Point d = row_relative_displacement(row, u);
  for (int i = 0; i < 3; ++i)
    d[i] -= row.slip0[i];
  const Point &n = row.normal;
  const double dn = dot(d, n);
  for (int i = 0; i < 3; ++i)
    d[i] -= dn * n[i];
  return std::sqrt(dot(d, d));
}

bool slid_beyond_limit(const ContactInterface &interface, const std::function<Point(int node)> &u,
                       const Teuchos::Comm<int> &comm)
{
  int beyond = 0;
  for (const int r : interface.owned_rows())
  {
    const ContactRow &row = interface.rows()[r];
    // Not finite (a diverged state) is past the limit too.
    if (row.slip_limit > 0.0 && !(row_slip(row, u) <= row.slip_limit))
      beyond = 1;
  }
  int anywhere = 0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, beyond, Teuchos::outArg(anywhere));
  return anywhere == 1;
}
} // namespace kiln
