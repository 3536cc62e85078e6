#pragma once
// Intrepid2's HGRAD bases (Debian's Trilinos 13.2) for the Kiln element types they cover, to
// compare Kiln's hand-written bases with (tests/unit/discretization/intrepid2_basis_test.cpp)
// and time against them (benchmarks/element_tabulation.cpp). Header-only; the caller keeps
// Kokkos initialised (Kokkos::ScopeGuard) while it uses them.
#include "elements/reference_cell.hpp"

#include <Teuchos_RCP.hpp> // before Intrepid2: its getSubCellRefBasis() instantiates rcp()

#include <Intrepid2_HGRAD_HEX_C1_FEM.hpp>
#include <Intrepid2_HGRAD_HEX_C2_FEM.hpp>
#include <Intrepid2_HGRAD_PYR_C1_FEM.hpp>
#include <Intrepid2_HGRAD_QUAD_C1_FEM.hpp>
#include <Intrepid2_HGRAD_QUAD_C2_FEM.hpp>
#include <Intrepid2_HGRAD_TET_C1_FEM.hpp>
#include <Intrepid2_HGRAD_TET_C2_FEM.hpp>
#include <Intrepid2_HGRAD_TRI_C1_FEM.hpp>
#include <Intrepid2_HGRAD_TRI_C2_FEM.hpp>
#include <Intrepid2_HGRAD_WEDGE_C1_FEM.hpp>
#include <Kokkos_DynRankView.hpp>

#include <memory>
#include <vector>

namespace kiln_test
{
using Intrepid2Device = Kokkos::HostSpace::device_type;
using Intrepid2Basis = Intrepid2::Basis<Intrepid2Device, double, double>;
using Intrepid2View = Kokkos::DynRankView<double, Intrepid2Device>;

/// Intrepid2's basis of `type`, null where it has none (HEX20, QUAD8: serendipity).
inline std::unique_ptr<Intrepid2Basis> intrepid2_basis(const kiln::CellType type)
{
  using namespace Intrepid2;
  using D = Intrepid2Device;
  switch (type)
  {
  case kiln::CellType::hex8:
    return std::make_unique<Basis_HGRAD_HEX_C1_FEM<D>>();
  case kiln::CellType::tet4:
    return std::make_unique<Basis_HGRAD_TET_C1_FEM<D>>();
  case kiln::CellType::wedge6:
    return std::make_unique<Basis_HGRAD_WEDGE_C1_FEM<D>>();
  case kiln::CellType::pyramid5:
    return std::make_unique<Basis_HGRAD_PYR_C1_FEM<D>>();
  case kiln::CellType::tet10:
    return std::make_unique<Basis_HGRAD_TET_C2_FEM<D>>();
  case kiln::CellType::hex27:
    return std::make_unique<Basis_HGRAD_HEX_C2_FEM<D>>();
  case kiln::CellType::quad4:
    return std::make_unique<Basis_HGRAD_QUAD_C1_FEM<D>>();
  case kiln::CellType::tri3:
    return std::make_unique<Basis_HGRAD_TRI_C1_FEM<D>>();
  case kiln::CellType::quad9:
    return std::make_unique<Basis_HGRAD_QUAD_C2_FEM<D>>();
  case kiln::CellType::tri6:
    return std::make_unique<Basis_HGRAD_TRI_C2_FEM<D>>();
  default:
    return nullptr;
  }
}

/// `points` (dim coordinates each) as an Intrepid2 point view (P, dim).
inline Intrepid2View intrepid2_points(const std::vector<kiln::Point> &points, const int dim)
{
  Intrepid2View view("points", points.size(), dim);
  for (std::size_t p = 0; p < points.size(); ++p)
    for (int k = 0; k < dim; ++k)
      view(p, k) = points[p][k];
  return view;
}
} // namespace kiln_test
