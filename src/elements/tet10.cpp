/// TETRA10: the quadratic tetrahedron on the unit simplex (Exodus mid-edge order 01, 12,
/// 20, 03, 13, 23). Walkington's 14-point rule of degree 5 (mass: degree 4).
#include "elements/elements.hpp"
#include "elements/quadrature_rules.hpp"

namespace kiln::elements
{
namespace
{
/// The edges in mid-edge node order (ReferenceCell::of(tet10)).
constexpr int edges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};

class Tet10 final : public FiniteElement
{
public:
  CellType type() const override { return CellType::tet10; }
  void values(const Point &xi, double *N) const override { simplex2_values(xi, 3, edges, N); }
  void gradients(const Point &xi, Point *dN) const override
  {
    simplex2_gradients(xi, 3, edges, dN);
  }
  const Quadrature &quadrature() const override
  {
    static const Quadrature q = quadrature::tetrahedron_degree5();
    return q;
  }
};
} // namespace

std::unique_ptr<FiniteElement> make_tet10()
{
  return std::make_unique<Tet10>();
}
} // namespace kiln::elements
