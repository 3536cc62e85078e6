// What Moertel (Debian's Trilinos 13.2, libtrilinos-moertel-dev) gives a mortar contact code:
// two non-matching surfaces, projection, clipping and integration of D and M with a dual basis,
// then the checks a mortar code needs. Built twice: moertel_probe (the Epetra classes,
// MOERTEL::Interface and Manager) and moertelt_probe (-DPROBE_MOERTELT: the Tpetra port,
// MoertelT::InterfaceT and ManagerT).
//
//   moertel_probe NX0 NY0 NX1 NY1 [--offset D] [--curve R] [--tri] [--boundary] [--gauss N]
//                 [--scale S] [--flat-frame]
//
// Side 0 (primary, Moertel's "mortar side"): NX0 x NY0 quadrilaterals on the unit square at
// z = 0 (outward normal +z). Side 1 (secondary, carries the multiplier): NX1 x NY1 at z = D
// (outward normal -z). Then both are rotated (rotate(); --flat-frame: not). --curve R: both
// lie on the cylinder z = R - sqrt(R^2 - (x - 1/2)^2) (+ D on side 1). --tri: both sides made
// of triangles (each quadrilateral cut in two). --gauss N: points per triangle (3, 6, 12, 13,
// 16, 19, 27; default 12). --scale S: every length times S. --boundary: the nodes on the edge of
// the square flagged "on boundary" (Moertel then gives them no multiplier). With mpirun -np P
// the faces and nodes are split over the ranks by x, each added once, by its owner.
//
// Prints the rows of D (secondary nodes with a multiplier), the off-diagonal entries of D
// (above 1e-8 of the row's diagonal; a dual basis: 0), sum D (the secondary area: 1 on the
// unit square), max |row sum M -+ row sum D| (partition of unity; Moertel stores -M),
// max |weighted gap / D_ii - D| (the weighted gap of the offset along the rotated normal) and
// the times of Complete() and Mortar_Integrate(). PROBE_BAD=1: the rows whose gap is off.
#include <mpi.h>
#include <mrtr_segment_bilinearquad.H>
#include <mrtr_segment_bilineartri.H>
#ifdef PROBE_MOERTELT
#include <Moertel_ManagerT.hpp>
#include <Teuchos_DefaultMpiComm.hpp>
#include <Tpetra_Core.hpp>
#else
#include <Epetra_CrsMatrix.h>
#include <Epetra_Map.h>
#include <Epetra_MpiComm.h>
#include <mrtr_manager.H>
#endif

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

namespace
{
using V3 = std::array<double, 3>;

struct Options
{
  int n[2][2] = {{4, 4}, {5, 3}};
  double offset = 0.0;
  double radius = 0.0;
  bool tri = false;
  bool boundary = false;
  bool rotated = true;
  int gauss = 12;
  double scale = 1.0;
};

/// About x by 0.3 rad, then about y by 0.2 rad, so that the weighted gap tests all three
/// coordinates.
V3 rotate(const Options &o, const V3 &p)
{
  const double a = o.rotated ? 0.3 : 0.0, b = o.rotated ? 0.2 : 0.0;
  const double y1 = std::cos(a) * p[1] - std::sin(a) * p[2];
  const double z1 = std::sin(a) * p[1] + std::cos(a) * p[2];
  return {std::cos(b) * p[0] + std::sin(b) * z1, y1, -std::sin(b) * p[0] + std::cos(b) * z1};
}

/// Node (i, j) of side `side`.
V3 point(const Options &o, const int side, const int i, const int j)
{
  const int nx = o.n[side][0], ny = o.n[side][1];
  const double x = static_cast<double>(i) / nx, d = x - 0.5;
  const double z = (o.radius > 0.0 ? o.radius - std::sqrt(o.radius * o.radius - d * d) : 0.0) +
                   (side == 1 ? o.offset : 0.0);
  return rotate(o, {o.scale * x, o.scale * static_cast<double>(j) / ny, o.scale * z});
}

/// One row of D and M: (column, value) pairs.
struct Row
{
  int id = 0;
  std::vector<std::pair<int, double>> D, M;
};

/// Adds this rank's nodes and faces of both sides; returns every node's position and fills
/// the dofs (= node ids) this rank owns.
template <class Interface>
std::vector<V3> add_surfaces(const Options &o, const int rank, const int size, Interface &interface,
                             std::vector<int> &my_dofs)
{
  const int first_node[2] = {0, (o.n[0][0] + 1) * (o.n[0][1] + 1)};
  std::vector<V3> X(first_node[1] + (o.n[1][0] + 1) * (o.n[1][1] + 1));
  const auto owner = [&](double x) { return std::min(size - 1, static_cast<int>(x * size)); };
  int segment_id = 0;
  for (int side = 0; side < 2; ++side)
  {
    const int nx = o.n[side][0], ny = o.n[side][1];
    const auto id = [&](int i, int j) { return first_node[side] + j * (nx + 1) + i; };
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
      {
        int node = id(i, j);
        X[node] = point(o, side, i, j);
        if (owner(static_cast<double>(i) / nx) != rank)
          continue;
        my_dofs.push_back(node);
        const bool on_edge = i == 0 || j == 0 || i == nx || j == ny;
        MOERTEL::Node n(node, X[node].data(), 1, &node, o.boundary && on_edge, 0);
        interface.AddNode(n, side);
      }
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i, segment_id += o.tri ? 2 : 1)
      {
        int c[4] = {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)};
        if (side == 1)
          std::swap(c[1], c[3]); // outward normal -z
        if (owner((i + 0.5) / nx) != rank)
          continue;
        if (o.tri)
        {
          int t0[3] = {c[0], c[1], c[2]}, t1[3] = {c[0], c[2], c[3]};
          MOERTEL::Segment_BiLinearTri s0(segment_id, 3, t0, 0), s1(segment_id + 1, 3, t1, 0);
          interface.AddSegment(s0, side);
          interface.AddSegment(s1, side);
        }
        else
        {
          MOERTEL::Segment_BiLinearQuad s(segment_id, 4, c, 0);
          interface.AddSegment(s, side);
        }
      }
  }
  interface.SetMortarSide(0);
  if (o.tri)
    interface.SetFunctionTypes(MOERTEL::Function::func_LinearTri,
                               MOERTEL::Function::func_DualLinearTri);
  else
    interface.SetFunctionTypes(MOERTEL::Function::func_BiLinearQuad,
                               MOERTEL::Function::func_DualBiLinearQuad);
  return X;
}

void fail(const char *what)
{
  std::fprintf(stderr, "%s failed\n", what);
  MPI_Abort(MPI_COMM_WORLD, 1);
}

double seconds(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b)
{
  return std::chrono::duration<double>(b - a).count();
}
} // namespace

int main(int argc, char **argv)
{
#ifdef PROBE_MOERTELT
  Tpetra::ScopeGuard tpetra(&argc, &argv);
  const auto comm = Tpetra::getDefaultComm();
  const int rank = comm->getRank(), size = comm->getSize();
  const char *name = "moertelT";
#else
  MPI_Init(&argc, &argv);
  Epetra_MpiComm comm(MPI_COMM_WORLD);
  const int rank = comm.MyPID(), size = comm.NumProc();
  const char *name = "moertel";
#endif
  Options o;
  int positional = 0;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--offset")
      o.offset = std::atof(argv[++i]);
    else if (a == "--curve")
      o.radius = std::atof(argv[++i]);
    else if (a == "--tri")
      o.tri = true;
    else if (a == "--boundary")
      o.boundary = true;
    else if (a == "--gauss")
      o.gauss = std::atoi(argv[++i]);
    else if (a == "--scale")
      o.scale = std::atof(argv[++i]);
    else if (a == "--flat-frame")
      o.rotated = false;
    else if (positional < 4)
    {
      o.n[positional / 2][positional % 2] = std::atoi(argv[i]);
      ++positional;
    }
  }
  std::vector<int> my_dofs;
  std::vector<Row> rows;
  double t_complete = 0.0, t_integrate = 0.0;
  std::vector<V3> X;
  {
#ifdef PROBE_MOERTELT
    using Interface = MoertelT::InterfaceT<double, int, long long, Tpetra::Map<>::node_type>;
    using Manager = MoertelT::ManagerT<double, int, long long, Tpetra::Map<>::node_type>;
#else
    using Interface = MOERTEL::Interface;
    using Manager = MOERTEL::Manager;
#endif
    const auto interface_ptr = Teuchos::rcp(new Interface(0, false, comm, 0));
    Interface &interface = *interface_ptr;
    X = add_surfaces(o, rank, size, interface, my_dofs);
    MPI_Barrier(MPI_COMM_WORLD);
    const auto t0 = std::chrono::steady_clock::now();
    if (!interface.Complete())
      fail("Complete()");
    const auto t1 = std::chrono::steady_clock::now();
    Manager manager(comm, Manager::manager_3D, 0);
#ifdef PROBE_MOERTELT
    manager.AddInterface(interface_ptr);
#else
    manager.AddInterface(interface);
#endif
#ifdef PROBE_MOERTELT
    std::vector<long long> gids(my_dofs.begin(), my_dofs.end());
    const auto map = Teuchos::rcp(
        new Tpetra::Map<int, long long>(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                                        gids.data(), gids.size(), 0, comm));
    manager.SetProblemMap(map);
#else
    Epetra_Map map(-1, static_cast<int>(my_dofs.size()), my_dofs.data(), 0, comm);
    manager.SetProblemMap(&map);
#endif
    Teuchos::ParameterList &p = manager.Default_Parameters();
    p.set("exact values at gauss points", true);
    p.set("number gaussian points 2D", o.gauss);
    if (!manager.Mortar_Integrate())
      fail("Mortar_Integrate()");
    MPI_Barrier(MPI_COMM_WORLD);
    const auto t2 = std::chrono::steady_clock::now();
    t_complete = seconds(t0, t1);
    t_integrate = seconds(t1, t2);
    // D: rows = the multipliers of side-1 nodes (ids after the problem's), columns = side-1
    // dofs; M: the same rows, columns = side-0 dofs.
    const auto &D = *manager.D();
    const auto &M = *manager.M();
#ifdef PROBE_MOERTELT
    const auto row_map = D.getRowMap();
    if (std::getenv("PROBE_DEBUG"))
      std::printf("rank %d: D %zu rows, %zu entries (global %zu); M %zu entries (global %zu)\n",
                  rank, static_cast<std::size_t>(D.getNodeNumRows()),
                  static_cast<std::size_t>(D.getNodeNumEntries()),
                  static_cast<std::size_t>(D.getGlobalNumEntries()),
                  static_cast<std::size_t>(M.getNodeNumEntries()),
                  static_cast<std::size_t>(M.getGlobalNumEntries()));
    for (std::size_t r = 0; r < D.getNodeNumRows(); ++r)
    {
      Row row;
      row.id = static_cast<int>(row_map->getGlobalElement(r));
      const auto extract = [&](const auto &A, std::vector<std::pair<int, double>> &to)
      {
        const long long gid = row_map->getGlobalElement(r);
        const std::size_t n = A.getNumEntriesInGlobalRow(gid);
        if (n == Teuchos::OrdinalTraits<std::size_t>::invalid() || n == 0)
          return;
        std::vector<long long> cols(n);
        std::vector<double> vals(n);
        std::size_t got = 0;
        A.getGlobalRowCopy(gid, cols, vals, got);
        for (std::size_t k = 0; k < got; ++k)
          to.emplace_back(static_cast<int>(cols[k]), vals[k]);
      };
      extract(D, row.D);
      extract(M, row.M);
      if (!row.D.empty() || !row.M.empty())
        rows.push_back(row);
    }
#else
    for (int r = 0; r < D.NumMyRows(); ++r)
    {
      Row row;
      row.id = D.GRID(r);
      int n = 0, *c = nullptr;
      double *v = nullptr;
      D.ExtractMyRowView(r, n, v, c);
      for (int k = 0; k < n; ++k)
        row.D.emplace_back(D.GCID(c[k]), v[k]);
      if (M.LRID(row.id) >= 0)
      {
        M.ExtractMyRowView(M.LRID(row.id), n, v, c);
        for (int k = 0; k < n; ++k)
          row.M.emplace_back(M.GCID(c[k]), v[k]);
      }
      if (!row.D.empty() || !row.M.empty())
        rows.push_back(row);
    }
#endif
  }
  const V3 normal = rotate(o, {0.0, 0.0, 1.0});
  const auto z = [&](int node)
  { return X[node][0] * normal[0] + X[node][1] * normal[1] + X[node][2] * normal[2]; };
  double local[4] = {0, 0, static_cast<double>(rows.size()), 0}, local_max[2] = {0, 0};
  for (const Row &row : rows)
  {
    double row_D = 0.0, row_M = 0.0, gD = 0.0, gM = 0.0, diag = 0.0;
    int diag_node = -1;
    for (const auto &[col, v] : row.D)
    {
      row_D += v;
      gD += v * z(col);
      if (std::abs(v) > std::abs(diag))
      {
        diag = v;
        diag_node = col;
      }
    }
    for (const auto &[col, v] : row.D)
      local[3] += col != diag_node && std::abs(v) > 1e-8 * std::abs(diag);
    for (const auto &[col, v] : row.M)
    {
      row_M += v;
      gM += v * z(col);
    }
    local[0] += row_D;
    local[1] += row_M;
    local_max[0] =
        std::max(local_max[0], std::min(std::abs(row_M - row_D), std::abs(row_M + row_D)));
    if (diag == 0.0)
      continue;
    // Moertel stores -M: the weighted gap is D x_s - (-M) x_m = D x_s + M x_m along n.
    const double g = (gD - (row_M * row_D < 0 ? -gM : gM)) / diag / o.scale;
    local_max[1] = std::max(local_max[1], std::abs(g - o.offset));
    if (std::getenv("PROBE_BAD") && std::abs(g - o.offset) > 1e-6)
      std::printf("bad row %d, node %d at (%g, %g, %g): D_ii %.6g, row sum %.6g, gap %.6g\n",
                  row.id, diag_node, X[diag_node][0], X[diag_node][1], X[diag_node][2], diag, row_D,
                  g);
  }
  double global[4], global_max[2];
  MPI_Allreduce(local, global, 4, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  MPI_Allreduce(local_max, global_max, 2, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  if (rank == 0)
    std::printf(
        "%s %dx%d vs %dx%d%s%s%s%s offset %g gauss %d np %d: rows of D %g, off-diagonal %g, "
        "sum D %.15g, sum M %.15g, max|rowsum M -+ rowsum D| %.3g, "
        "max|gap - offset| %.3g, Complete %.3f s, Mortar_Integrate %.3f s\n",
        name, o.n[0][0], o.n[0][1], o.n[1][0], o.n[1][1], o.rotated ? "" : " flat-frame",
        o.radius > 0 ? " curved" : "", o.tri ? " tri" : "", o.boundary ? " boundary" : "", o.offset,
        o.gauss, size, global[2], global[3], global[0], global[1], global_max[0], global_max[1],
        t_complete, t_integrate);
#ifndef PROBE_MOERTELT
  MPI_Finalize();
#endif
  return 0;
}
