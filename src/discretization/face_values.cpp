#include "discretization/face_values.hpp"

#include "base/errors.hpp"

#include <cmath>
#include <sstream>

namespace kiln
{
void FaceValues::reinit(const Mesh &mesh, const int c, const int face)
{
  const ReferenceCell &cell = mesh.reference_cell(c);
  const std::vector<int> &local = cell.face_nodes(face);
  const Span<const int> nodes = mesh.cell_nodes(c);
  x_.resize(local.size());
  for (std::size_t i = 0; i < local.size(); ++i)
    x_[i] = mesh.coordinates[nodes[local[i]]];
  reinit(cell.face_type(face), x_.data());
}

void FaceValues::reinit(const CellType type, const Point *x)
{
  const ReferenceValues &ref = ReferenceValues::of(type);
  KILN_ASSERT(ref.n_shape > 0 && ReferenceCell::of(type).dim() == 2,
              "no face basis for " << ReferenceCell::of(type).name());
  if (shape_ == nullptr || type != type_)
  {
    type_ = type;
    n_shape_ = ref.n_shape;
    n_qpoints_ = ref.n_qpoints;
    shape_ = ref.shape.data();
    JxW_.resize(n_qpoints_);
    normal_.resize(n_qpoints_);
    quadrature_point_.resize(n_qpoints_);
  }
  const int n = n_shape_;
  for (int q = 0; q < n_qpoints_; ++q)
  {
    const double *N = shape_ + q * n;
    const Point *dN = ref.grad.data() + q * n;
    Point xq{0, 0, 0}, dx_ds{0, 0, 0}, dx_dt{0, 0, 0};
    for (int i = 0; i < n; ++i)
      for (int d = 0; d < 3; ++d)
      {
        xq[d] += N[i] * x[i][d];
        dx_ds[d] += dN[i][0] * x[i][d];
        dx_dt[d] += dN[i][1] * x[i][d];
      }
    const Point a{dx_ds[1] * dx_dt[2] - dx_ds[2] * dx_dt[1],
                  dx_ds[2] * dx_dt[0] - dx_ds[0] * dx_dt[2],
                  dx_ds[0] * dx_dt[1] - dx_ds[1] * dx_dt[0]};
    const double area = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    if (!(area > 0.0))
    {
      std::ostringstream msg;
      msg << "FaceValues::reinit: zero area element at quadrature point " << q << " of a "
          << ReferenceCell::of(type).name() << " (a degenerate face; node 0 at (" << x[0][0] << ", "
          << x[0][1] << ", " << x[0][2] << "))";
      throw InternalError(msg.str());
    }
    JxW_[q] = area * ref.weights[q];
    normal_[q] = {a[0] / area, a[1] / area, a[2] / area};
    quadrature_point_[q] = xq;
  }
}
} // namespace kiln
