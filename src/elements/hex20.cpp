/// HEX20: the quadratic serendipity hexahedron on [-1,1]^3 (Exodus node order: corners,
/// then the mid-edge nodes of the bottom, vertical and top edges). 3x3x3 Gauss: degree 5 per
/// coordinate.
#include "elements/elements.hpp"
#include "elements/quadrature_rules.hpp"

namespace kiln::elements
{
namespace
{
class Hex20 final : public FiniteElement
{
public:
  CellType type() const override { return CellType::hex20; }
  void values(const Point &xi, double *N) const override { serendipity_values(ref_, xi, N); }
  void gradients(const Point &xi, Point *dN) const override { serendipity_gradients(ref_, xi, dN); }
  const Quadrature &quadrature() const override
  {
    static const Quadrature q = quadrature::gauss_tensor(3, 3);
    return q;
  }

private:
  const ReferenceCell &ref_ = ReferenceCell::of(CellType::hex20);
};
} // namespace

std::unique_ptr<FiniteElement> make_hex20()
{
  return std::make_unique<Hex20>();
}
} // namespace kiln::elements
