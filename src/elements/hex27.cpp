/// HEX27: the triquadratic Lagrange hexahedron on [-1,1]^3 (Exodus node order: corners,
/// mid-edges, centroid, face centres -z, +z, -x, +x, -y, +y). 3x3x3 Gauss: degree 5 per
/// coordinate, exact for mass (degree 4) and stiffness on affine cells.
#include "elements/elements.hpp"
#include "elements/quadrature_rules.hpp"

namespace kiln::elements
{
namespace
{
class Hex27 final : public FiniteElement
{
public:
  CellType type() const override { return CellType::hex27; }
  void values(const Point &xi, double *N) const override { tensor2_values(ref_, xi, N); }
  void gradients(const Point &xi, Point *dN) const override { tensor2_gradients(ref_, xi, dN); }
  const Quadrature &quadrature() const override
  {
    static const Quadrature q = quadrature::gauss_tensor(3, 3);
    return q;
  }

private:
  const ReferenceCell &ref_ = ReferenceCell::of(CellType::hex27);
};
} // namespace

std::unique_ptr<FiniteElement> make_hex27()
{
  return std::make_unique<Hex27>();
}
} // namespace kiln::elements
