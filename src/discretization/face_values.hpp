#pragma once
/// Values of the bilinear shape functions of a quadrilateral face at the 2x2 Gauss points.
#include "mesh/hex_geometry.hpp"

#include <array>

namespace kiln
{
/// The four bilinear shape functions of a quad face, nodes ordered as hex_face_nodes and
/// face_nodes() give them (counterclockwise seen from outside: the right-hand rule gives the
/// outward normal), at the 2x2 Gauss points (s, t) = (+-1/sqrt(3), +-1/sqrt(3)), in node
/// order. With dx/ds x dx/dt = a_q: JxW(q) = |a_q| w_q [m^2] (w_q = 1) and
/// normal(q) = a_q / |a_q|. The face may be warped; the normal is then per point.
class FaceValues
{
public:
  static constexpr int n_points = 4;

  /// Maps the face with these nodes. Throws InternalError if the area element vanishes at a
  /// Gauss point (a degenerate face).
  void reinit(const QuadNodes &x);

  int n_qpoints() const { return n_points; }
  int n_shape() const { return 4; }
  /// N_i at Gauss point q [-].
  double shape(const int i, const int q) const { return (*shape_)[q][i]; }
  /// The area element times the Gauss weight at point q [m^2].
  double JxW(const int q) const { return JxW_[q]; }
  /// The unit outward normal at point q [-].
  const Point &normal(const int q) const { return normal_[q]; }
  /// The physical position of Gauss point q [m].
  const Point &quadrature_point(const int q) const { return quadrature_point_[q]; }

private:
  using ShapeTable = std::array<std::array<double, 4>, n_points>;
  using GradTable = std::array<std::array<std::array<double, 2>, 4>, n_points>;
  /// N_i(s_q, t_q), indexed [q][i].
  static const ShapeTable &reference_shape();
  /// (dN_i/ds, dN_i/dt) at (s_q, t_q), indexed [q][i].
  static const GradTable &reference_grad();

  /// reference_shape(), looked up once: shape() is inlined in the kernels' loops.
  const ShapeTable *shape_ = &reference_shape();
  std::array<double, n_points> JxW_{};
  std::array<Point, n_points> normal_{};
  std::array<Point, n_points> quadrature_point_{};
};
} // namespace kiln
