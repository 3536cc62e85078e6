/// QUAD8: the quadratic serendipity quadrilateral (faces of HEX20). 3x3 Gauss: degree 5
/// per coordinate.
#include "elements/elements.hpp"
#include "elements/quadrature_rules.hpp"

namespace kiln::elements
{
namespace
{
class Quad8 final : public FiniteElement
{
public:
  CellType type() const override { return CellType::quad8; }
  void values(const Point &xi, double *N) const override { serendipity_values(ref_, xi, N); }
  void gradients(const Point &xi, Point *dN) const override { serendipity_gradients(ref_, xi, dN); }
  const Quadrature &quadrature() const override
  {
    static const Quadrature q = quadrature::gauss_tensor(2, 3);
    return q;
  }

private:
  const ReferenceCell &ref_ = ReferenceCell::of(CellType::quad8);
};
} // namespace

std::unique_ptr<FiniteElement> make_quad8()
{
  return std::make_unique<Quad8>();
}
} // namespace kiln::elements
