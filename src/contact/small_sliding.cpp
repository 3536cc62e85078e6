#include "contact/small_sliding.hpp"

#include "base/errors.hpp"
#include "contact/pair_research.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <cmath>
#include <sstream>

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

void check_small_sliding(const ContactInterface &interface, const std::function<Point(int node)> &u,
                         const double time, const Teuchos::Comm<int> &comm)
{
  int worst = -1;
  double worst_ratio = 1.0;
  double worst_slip = 0.0;
  for (const int r : interface.owned_rows())
  {
    const ContactRow &row = interface.rows()[r];
    if (!(row.slip_limit > 0.0))
      continue;
    const double slip = row_slip(row, u);
    // Not finite (a diverged state) is past the limit too.
    if (!(slip <= worst_ratio * row.slip_limit))
    {
      worst = r;
      worst_slip = slip;
      worst_ratio = slip / row.slip_limit;
    }
  }
  std::ostringstream message;
  if (worst >= 0)
  {
    const ContactRow &row = interface.rows()[worst];
    const Point &X = interface.mesh().coordinates[row.node];
    message << interface.name() << ": at t = " << time << " s secondary node " << row.node + 1
            << " (reference position (" << X[0] << ", " << X[1] << ", " << X[2] << ") m) has slid "
            << worst_slip
            << " m along the surface relative to its twin point on the primary surface, beyond "
               "the small-sliding limit "
            << row.slip_limit << " m (\"Search Update Fraction\" " << row.slip_limit / row.face_size
            << " times its faces' size " << row.face_size
            << " m). The rows of a pair with a Heat Transfer term (partners, weights, normals) are "
               "built once, in the reference configuration, since its heat cells are not "
               "searched again during a run, and the answer would be wrong beyond the limit. Keep "
               "the bodies' sliding along this pair below the "
               "limit (a smaller imposed motion or load), or, if the slip is expected and a "
               "coarser answer acceptable, raise the pair's \"Search Update Fraction\" (at most "
               "1); a finer mesh lowers the limit. The results up to the last accepted step "
               "are kept";
  }
  check_run_collectively(comm, worst < 0, message.str());
}
} // namespace kiln
