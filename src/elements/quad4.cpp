/// QUAD4: the bilinear quadrilateral on [-1,1]^2 (faces of HEX8, WEDGE6, PYRAMID5), 2x2 Gauss
/// with the points in corner order (as FaceValues has always used). Degree 3 per coordinate.
#include "elements/elements.hpp"
#include "elements/quadrature_rules.hpp"

namespace kiln::elements
{
namespace
{
class Quad4 final : public FiniteElement
{
public:
  CellType type() const override { return CellType::quad4; }
  void values(const Point &xi, double *N) const override
  {
    for (int i = 0; i < 4; ++i)
    {
      const Point &r = ref_.node(i);
      N[i] = 0.25 * (1 + r[0] * xi[0]) * (1 + r[1] * xi[1]);
    }
  }
  void gradients(const Point &xi, Point *dN) const override
  {
    for (int i = 0; i < 4; ++i)
    {
      const Point &r = ref_.node(i);
      dN[i] = {0.25 * r[0] * (1 + r[1] * xi[1]), 0.25 * r[1] * (1 + r[0] * xi[0]), 0.0};
    }
  }
  const Quadrature &quadrature() const override
  {
    static const Quadrature q = quadrature::gauss_at_corners(cell());
    return q;
  }

private:
  const ReferenceCell &ref_ = ReferenceCell::of(CellType::quad4);
};
} // namespace

std::unique_ptr<FiniteElement> make_quad4()
{
  return std::make_unique<Quad4>();
}
} // namespace kiln::elements
