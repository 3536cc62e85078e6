#include "elements/element_types.hpp"

#include <cmath>

namespace kiln
{
namespace
{
/// Trilinear Lagrange basis on [-1,1]^3: N_i = (1 + r_i x)(1 + s_i y)(1 + t_i z) / 8, with
/// (r_i, s_i, t_i) the reference node.
class Hex8 final : public FiniteElement
{
public:
  CellType type() const override { return CellType::hex8; }
  void values(const Point &xi, double *N) const override
  {
    const ReferenceCell &cell = this->cell();
    for (int i = 0; i < cell.n_nodes(); ++i)
    {
      const Point &r = cell.node(i);
      N[i] = 0.125 * (1 + r[0] * xi[0]) * (1 + r[1] * xi[1]) * (1 + r[2] * xi[2]);
    }
  }
  void gradients(const Point &xi, Point *dN) const override
  {
    const ReferenceCell &cell = this->cell();
    for (int i = 0; i < cell.n_nodes(); ++i)
    {
      const Point &r = cell.node(i);
      const double f[3] = {1 + r[0] * xi[0], 1 + r[1] * xi[1], 1 + r[2] * xi[2]};
      dN[i] = {0.125 * r[0] * f[1] * f[2], 0.125 * r[1] * f[0] * f[2], 0.125 * r[2] * f[0] * f[1]};
    }
  }
  /// 2x2x2 Gauss, the points ordered as the nodes (the point nearest node i is point i),
  /// weights 1: exact for trilinear volumes and affine stiffness integrals.
  const Quadrature &quadrature() const override
  {
    static const Quadrature rule = [this]
    {
      Quadrature q;
      const double g = 1.0 / std::sqrt(3.0);
      for (int i = 0; i < cell().n_nodes(); ++i)
      {
        const Point &r = cell().node(i);
        q.points.push_back({g * r[0], g * r[1], g * r[2]});
        q.weights.push_back(1.0);
      }
      return q;
    }();
    return rule;
  }
};
} // namespace

const FiniteElement &hex8_element()
{
  static const Hex8 element;
  return element;
}
} // namespace kiln
