/// HEX8: the trilinear hexahedron on [-1,1]^3, 2x2x2 Gauss (points in corner order, exactly
/// hex_gauss_points(): Kiln's results do not change). Degree 3 in each coordinate.
#include "elements/elements.hpp"
#include "elements/quadrature_rules.hpp"

namespace kiln::elements
{
namespace
{
class Hex8 final : public FiniteElement
{
public:
  CellType type() const override { return CellType::hex8; }
  void values(const Point &xi, double *N) const override
  {
    for (int i = 0; i < 8; ++i)
    {
      const Point &r = ref_.node(i);
      N[i] = 0.125 * (1 + r[0] * xi[0]) * (1 + r[1] * xi[1]) * (1 + r[2] * xi[2]);
    }
  }
  void gradients(const Point &xi, Point *dN) const override
  {
    for (int i = 0; i < 8; ++i)
    {
      const Point &r = ref_.node(i);
      const double f[3] = {1 + r[0] * xi[0], 1 + r[1] * xi[1], 1 + r[2] * xi[2]};
      dN[i] = {0.125 * r[0] * f[1] * f[2], 0.125 * r[1] * f[0] * f[2], 0.125 * r[2] * f[0] * f[1]};
    }
  }
  const Quadrature &quadrature() const override
  {
    static const Quadrature q = quadrature::gauss_at_corners(cell());
    return q;
  }

private:
  const ReferenceCell &ref_ = ReferenceCell::of(CellType::hex8);
};
} // namespace

std::unique_ptr<FiniteElement> make_hex8()
{
  return std::make_unique<Hex8>();
}
} // namespace kiln::elements
