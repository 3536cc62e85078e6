/// QUAD9: the biquadratic Lagrange quadrilateral (faces of HEX27; corners, mid-edges,
/// centre). 3x3 Gauss: degree 5 per coordinate.
#include "elements/elements.hpp"
#include "elements/quadrature_rules.hpp"

namespace kiln::elements
{
namespace
{
class Quad9 final : public FiniteElement
{
public:
  CellType type() const override { return CellType::quad9; }
  void values(const Point &xi, double *N) const override { tensor2_values(ref_, xi, N); }
  void gradients(const Point &xi, Point *dN) const override { tensor2_gradients(ref_, xi, dN); }
  const Quadrature &quadrature() const override
  {
    static const Quadrature q = quadrature::gauss_tensor(2, 3);
    return q;
  }

private:
  const ReferenceCell &ref_ = ReferenceCell::of(CellType::quad9);
};
} // namespace

std::unique_ptr<FiniteElement> make_quad9()
{
  return std::make_unique<Quad9>();
}
} // namespace kiln::elements
