/// PYRAMID5: the rational pyramid of Intrepid2's HGRAD_PYR_C1 (base [-1,1]^2 at z = 0, apex
/// (0,0,1)): base node (r_x, r_y, 0): N = ((1 - z) + r_x x + r_y y + r_x r_y x y / (1 - z)) / 4,
/// apex N = z. In the collapsed coordinates x = a (1 - z), y = b (1 - z) it is the polynomial
/// (1 - z)(1 + r_x a)(1 + r_y b)/4, so the collapsed rule (quadrature::pyramid_collapsed(),
/// 8 points) integrates its mass and stiffness on affine pyramids exactly. At the apex the
/// rational term's gradient has no limit; there (|1 - z| < 1e-12) it is taken as 0, as
/// Intrepid2 does.
#include "elements/elements.hpp"
#include "elements/quadrature_rules.hpp"

#include <cmath>

namespace kiln::elements
{
namespace
{
/// 1 - z, kept away from 0 (the apex).
double apex_distance(const Point &xi)
{
  const double d = 1 - xi[2];
  constexpr double eps = 1e-12;
  return std::abs(d) < eps ? eps : d;
}

class Pyramid5 final : public FiniteElement
{
public:
  CellType type() const override { return CellType::pyramid5; }
  void values(const Point &xi, double *N) const override
  {
    const double d = apex_distance(xi);
    const double q = xi[0] * xi[1] / d;
    for (int i = 0; i < 4; ++i)
    {
      const Point &r = ref_.node(i);
      N[i] = 0.25 * ((1 - xi[2]) + r[0] * xi[0] + r[1] * xi[1] + r[0] * r[1] * q);
    }
    N[4] = xi[2];
  }
  void gradients(const Point &xi, Point *dN) const override
  {
    const double d = apex_distance(xi);
    const double x = xi[0] / d, y = xi[1] / d;
    for (int i = 0; i < 4; ++i)
    {
      const Point &r = ref_.node(i);
      const double s = r[0] * r[1];
      dN[i] = {0.25 * (r[0] + s * y), 0.25 * (r[1] + s * x), 0.25 * (-1 + s * x * y)};
    }
    dN[4] = {0, 0, 1};
  }
  const Quadrature &quadrature() const override
  {
    static const Quadrature q = quadrature::pyramid_collapsed();
    return q;
  }

private:
  const ReferenceCell &ref_ = ReferenceCell::of(CellType::pyramid5);
};
} // namespace

std::unique_ptr<FiniteElement> make_pyramid5()
{
  return std::make_unique<Pyramid5>();
}
} // namespace kiln::elements
