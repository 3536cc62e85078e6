#include "elements/element_types.hpp"

#include <cmath>

namespace kiln
{
namespace
{
/// Bilinear Lagrange basis on [-1,1]^2 (a face): N_i = (1 + r_i s)(1 + t_i t) / 4.
class Quad4 final : public FiniteElement
{
public:
  CellType type() const override { return CellType::quad4; }
  void values(const Point &xi, double *N) const override
  {
    const ReferenceCell &cell = this->cell();
    for (int i = 0; i < cell.n_nodes(); ++i)
    {
      const Point &r = cell.node(i);
      N[i] = 0.25 * (1 + r[0] * xi[0]) * (1 + r[1] * xi[1]);
    }
  }
  void gradients(const Point &xi, Point *dN) const override
  {
    const ReferenceCell &cell = this->cell();
    for (int i = 0; i < cell.n_nodes(); ++i)
    {
      const Point &r = cell.node(i);
      dN[i] = {0.25 * r[0] * (1 + r[1] * xi[1]), 0.25 * r[1] * (1 + r[0] * xi[0]), 0.0};
    }
  }
  /// 2x2 Gauss, points ordered as the nodes, weights 1.
  const Quadrature &quadrature() const override
  {
    static const Quadrature rule = [this]
    {
      Quadrature q;
      const double g = 1.0 / std::sqrt(3.0);
      for (int i = 0; i < cell().n_nodes(); ++i)
      {
        const Point &r = cell().node(i);
        q.points.push_back({g * r[0], g * r[1], 0.0});
        q.weights.push_back(1.0);
      }
      return q;
    }();
    return rule;
  }
};
} // namespace

const FiniteElement &quad4_element()
{
  static const Quad4 element;
  return element;
}
} // namespace kiln
