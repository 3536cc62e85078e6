/// TRI6: the quadratic triangle on the unit simplex (faces of TETRA10; mid-edge order
/// 01, 12, 20). Radon's 7-point rule of degree 5.
#include "elements/elements.hpp"
#include "elements/quadrature_rules.hpp"

namespace kiln::elements
{
namespace
{
/// The edges in mid-edge node order (ReferenceCell::of(tri6)).
constexpr int edges[3][2] = {{0, 1}, {1, 2}, {2, 0}};

class Tri6 final : public FiniteElement
{
public:
  CellType type() const override { return CellType::tri6; }
  void values(const Point &xi, double *N) const override { simplex2_values(xi, 2, edges, N); }
  void gradients(const Point &xi, Point *dN) const override
  {
    simplex2_gradients(xi, 2, edges, dN);
  }
  const Quadrature &quadrature() const override
  {
    static const Quadrature q = quadrature::triangle_degree5();
    return q;
  }
};
} // namespace

std::unique_ptr<FiniteElement> make_tri6()
{
  return std::make_unique<Tri6>();
}
} // namespace kiln::elements
