/// TETRA4: the linear tetrahedron on the unit simplex. The 4-point rule of degree 2
/// (exact for the mass matrix; the stiffness needs degree 0).
#include "elements/elements.hpp"
#include "elements/quadrature_rules.hpp"

namespace kiln::elements
{
namespace
{
class Tet4 final : public FiniteElement
{
public:
  CellType type() const override { return CellType::tet4; }
  void values(const Point &xi, double *N) const override { simplex1_values(xi, 3, N); }
  void gradients(const Point &xi, Point *dN) const override
  {
    (void)xi;
    simplex1_gradients(3, dN);
  }
  const Quadrature &quadrature() const override
  {
    static const Quadrature q = quadrature::tetrahedron_degree2();
    return q;
  }
};
} // namespace

std::unique_ptr<FiniteElement> make_tet4()
{
  return std::make_unique<Tet4>();
}
} // namespace kiln::elements
