#pragma once
/// Values of a face's shape functions at its quadrature points.
#include "discretization/element_values.hpp"

#include <vector>

namespace kiln
{
/// The shape functions of one face (a triangle or a quadrilateral, of any degree) at its
/// quadrature points, nodes ordered as ReferenceCell::face_nodes gives them (corners
/// counterclockwise seen from outside: the right-hand rule gives the outward normal). With
/// dx/ds x dx/dt = a_q: JxW(q) = |a_q| w_q [m^2] and normal(q) = a_q / |a_q|. The face may
/// be warped; the normal is then per point.
class FaceValues
{
public:
  /// Maps local face `face` of cell c of `mesh`.
  void reinit(const Mesh &mesh, int c, int face);
  /// Maps a face of `type` with these node coordinates. Throws InternalError if the area
  /// element vanishes at a quadrature point (a degenerate face).
  void reinit(CellType type, const Point *x);

  CellType type() const { return type_; }
  int n_qpoints() const { return n_qpoints_; }
  int n_shape() const { return n_shape_; }
  /// N_i at quadrature point q [-].
  double shape(const int i, const int q) const { return shape_[q * n_shape_ + i]; }
  /// The area element times the quadrature weight at point q [m^2].
  double JxW(const int q) const { return JxW_[q]; }
  /// The unit outward normal at point q [-].
  const Point &normal(const int q) const { return normal_[q]; }
  /// The physical position of quadrature point q [m].
  const Point &quadrature_point(const int q) const { return quadrature_point_[q]; }

private:
  CellType type_ = CellType::quad4;
  int n_shape_ = 0;
  int n_qpoints_ = 0;
  const double *shape_ = nullptr;
  std::vector<double> JxW_;
  std::vector<Point> normal_;
  std::vector<Point> quadrature_point_;
  std::vector<Point> x_; ///< the node coordinates of reinit(mesh, c, face)
};
} // namespace kiln
