/// WEDGE6: the linear wedge, the unit triangle (x, y) times [-1, 1] (z): N = l_a (1 ± z) / 2,
/// l the triangle's barycentric coordinates, bottom nodes 0-2 (z = -1), top 3-5. Quadrature:
/// the 3-point triangle rule (degree 2) times 2-point Gauss in z (degree 3): exact for the
/// mass and stiffness integrands on affine wedges.
#include "elements/elements.hpp"
#include "elements/quadrature_rules.hpp"

namespace kiln::elements
{
namespace
{
class Wedge6 final : public FiniteElement
{
public:
  CellType type() const override { return CellType::wedge6; }
  void values(const Point &xi, double *N) const override
  {
    double l[3];
    barycentric(xi, 2, l);
    for (int i = 0; i < 6; ++i)
      N[i] = l[i % 3] * 0.5 * (i < 3 ? 1 - xi[2] : 1 + xi[2]);
  }
  void gradients(const Point &xi, Point *dN) const override
  {
    double l[3];
    barycentric(xi, 2, l);
    for (int i = 0; i < 6; ++i)
    {
      const Point g = barycentric_gradient(i % 3, 2);
      const double h = 0.5 * (i < 3 ? 1 - xi[2] : 1 + xi[2]);
      dN[i] = {g[0] * h, g[1] * h, l[i % 3] * (i < 3 ? -0.5 : 0.5)};
    }
  }
  const Quadrature &quadrature() const override
  {
    static const Quadrature q = quadrature::wedge(quadrature::triangle_degree2(), 2);
    return q;
  }
};
} // namespace

std::unique_ptr<FiniteElement> make_wedge6()
{
  return std::make_unique<Wedge6>();
}
} // namespace kiln::elements
