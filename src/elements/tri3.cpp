/// TRI3: the linear triangle on the unit simplex (faces of TETRA4, WEDGE6, PYRAMID5).
/// The 3-point rule of degree 2.
#include "elements/elements.hpp"
#include "elements/quadrature_rules.hpp"

namespace kiln::elements
{
namespace
{
class Tri3 final : public FiniteElement
{
public:
  CellType type() const override { return CellType::tri3; }
  void values(const Point &xi, double *N) const override { simplex1_values(xi, 2, N); }
  void gradients(const Point &xi, Point *dN) const override
  {
    (void)xi;
    simplex1_gradients(2, dN);
  }
  const Quadrature &quadrature() const override
  {
    static const Quadrature q = quadrature::triangle_degree2();
    return q;
  }
};
} // namespace

std::unique_ptr<FiniteElement> make_tri3()
{
  return std::make_unique<Tri3>();
}
} // namespace kiln::elements
