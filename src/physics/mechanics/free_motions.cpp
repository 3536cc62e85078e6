#include "physics/mechanics/free_motions.hpp"

#include "mesh/mesh_bodies.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace kiln
{
namespace
{
/// The centre (mean of the nodes), size (diagonal of the bounding box) and, for messages, the
/// element blocks and bounding box of each body, from the owned nodes and cells of every rank.
struct BodyGeometry
{
  std::vector<FreeMotionFinder::Body> bodies;
  std::vector<std::string> summary;
};

BodyGeometry body_geometry(const Mesh &mesh, const DofManager &dofs, const std::vector<int> &body,
                           const int n_bodies)
{
  const auto &comm = *dofs.owned_dof_map()->getComm();
  const double big = std::numeric_limits<double>::max();
  const auto m = static_cast<std::size_t>(n_bodies);
  std::vector<double> sums(4 * m, 0.0), lowest(3 * m, big), highest(3 * m, -big);
  for (const int n : dofs.owned_nodes())
  {
    const int b = body[n];
    if (b < 0)
      continue;
    for (int d = 0; d < 3; ++d)
    {
      sums[4 * b + d] += mesh.coordinates[n][d];
      lowest[3 * b + d] = std::min(lowest[3 * b + d], mesh.coordinates[n][d]);
      highest[3 * b + d] = std::max(highest[3 * b + d], mesh.coordinates[n][d]);
    }
    sums[4 * b + 3] += 1.0;
  }
  const std::vector<int> block_ids = mesh.block_ids();
  std::vector<int> has_block(m * block_ids.size(), 0);
  for (const int c : dofs.owned_cells())
  {
    const auto k =
        std::lower_bound(block_ids.begin(), block_ids.end(), mesh.block_id[c]) - block_ids.begin();
    has_block[body[mesh.cell_nodes(c)[0]] * block_ids.size() + k] = 1;
  }
  std::vector<double> total(sums.size()), low(lowest.size()), high(highest.size());
  std::vector<int> blocks(has_block.size());
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, static_cast<int>(sums.size()), sums.data(),
                     total.data());
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, static_cast<int>(lowest.size()), lowest.data(),
                     low.data());
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, static_cast<int>(highest.size()), highest.data(),
                     high.data());
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, static_cast<int>(has_block.size()),
                     has_block.data(), blocks.data());
  BodyGeometry g;
  for (std::size_t b = 0; b < m; ++b)
  {
    FreeMotionFinder::Body B;
    double diagonal2 = 0.0;
    for (int d = 0; d < 3; ++d)
    {
      B.centre[d] = total[4 * b + d] / total[4 * b + 3];
      diagonal2 += (high[3 * b + d] - low[3 * b + d]) * (high[3 * b + d] - low[3 * b + d]);
    }
    B.size = std::sqrt(diagonal2);
    g.bodies.push_back(B);
    std::ostringstream s;
    s << std::setprecision(6);
    std::vector<int> ids;
    for (std::size_t k = 0; k < block_ids.size(); ++k)
      if (blocks[b * block_ids.size() + k] != 0)
        ids.push_back(block_ids[k]);
    s << (ids.size() == 1 ? "element block " : "element blocks ");
    for (std::size_t k = 0; k < ids.size(); ++k)
      s << (k == 0 ? "" : ", ") << ids[k];
    s << ", the cells between (" << low[3 * b] << ", " << low[3 * b + 1] << ", " << low[3 * b + 2]
      << ") and (" << high[3 * b] << ", " << high[3 * b + 1] << ", " << high[3 * b + 2] << ")";
    g.summary.push_back(s.str());
  }
  return g;
}

/// The motion scaled to a unit translation (no rotation) or a unit rotation of its first
/// rotating body.
RigidMotion unit_motion(RigidMotion motion)
{
  double length = 0.0;
  for (const Point &w : motion.rotation)
    if (length == 0.0 && dot(w, w) > 0.0)
      length = std::sqrt(dot(w, w));
  double largest = 0.0;
  for (const Point &a : motion.translation)
    largest = std::max(largest, std::sqrt(dot(a, a)));
  // A rotation part below round-off of the translation is none.
  double rotation = 0.0;
  for (const Point &w : motion.rotation)
    rotation = std::max(rotation, std::sqrt(dot(w, w)));
  if (rotation == 0.0 || (largest > 0.0 && rotation < 1e-12 * largest))
    length = largest;
  for (auto *parts : {&motion.translation, &motion.rotation})
    for (Point &p : *parts)
      for (double &x : p)
        x /= length;
  return motion;
}
} // namespace

FreeMotions::FreeMotions(const Mesh &mesh, const DofManager &dofs,
                         const NodalConstraints &constraints,
                         const std::vector<HeldDirection> &held)
    : mesh_(mesh), dofs_(dofs), constraints_(constraints), conditions_({}), finder_({})
{
  const MeshBodies bodies = mesh_bodies(mesh);
  body_ = bodies.body;
  BodyGeometry geometry = body_geometry(mesh, dofs, body_, bodies.count);
  summary_ = std::move(geometry.summary);
  conditions_ = FreeMotionFinder(std::move(geometry.bodies));
  for (const int n : dofs.owned_nodes())
    if (body_[n] >= 0)
      for (const NodalConstraints::Direction &d : constraints.directions(n))
        conditions_.add_direction(body_[n], mesh.coordinates[n], d.n);
  finder_ = conditions_;
  for (const HeldDirection &h : held)
    finder_.add_gap(body_[h.a], body_[h.b], h.at, h.direction);
  for (const RigidMotion &m : finder_.find(*dofs.owned_dof_map()->getComm()))
    motions_.push_back(unit_motion(m));
}

std::vector<std::string> FreeMotions::names() const
{
  std::vector<std::string> names;
  for (const RigidMotion &m : motions_)
    names.push_back(finder_.describe(m));
  return names;
}

std::string FreeMotions::more_free_with(const std::vector<HeldDirection> &held) const
{
  FreeMotionFinder finder = conditions_;
  for (const HeldDirection &h : held)
    finder.add_gap(body_[h.a], body_[h.b], h.at, h.direction);
  const std::vector<RigidMotion> motions = finder.find(*dofs_.owned_dof_map()->getComm());
  return motions.size() > motions_.size() ? description(motions) : "";
}

std::vector<RigidMotion> FreeMotions::motions_with(const std::vector<HeldDirection> &held) const
{
  FreeMotionFinder finder = conditions_;
  for (const HeldDirection &h : held)
    finder.add_gap(body_[h.a], body_[h.b], h.at, h.direction);
  return finder.find(*dofs_.owned_dof_map()->getComm());
}

double FreeMotions::opening_rate(const RigidMotion &motion, const HeldDirection &h) const
{
  double size = 0.0;
  for (int b = 0; b < finder_.n_bodies(); ++b)
    size = std::max(size, std::sqrt(dot(motion.translation[b], motion.translation[b])) +
                              std::sqrt(dot(motion.rotation[b], motion.rotation[b])) *
                                  finder_.body(b).size);
  return size == 0.0 ? 0.0 : std::abs(opening_along(motion, h)) / size;
}

double FreeMotions::opening_along(const RigidMotion &motion, const HeldDirection &h) const
{
  const auto displacement = [&](const int b, const Point &x)
  {
    const Point &a = motion.translation[b];
    const Point &w = motion.rotation[b];
    const Point &c = finder_.body(b).centre;
    const Point r{x[0] - c[0], x[1] - c[1], x[2] - c[2]};
    return Point{a[0] + w[1] * r[2] - w[2] * r[1], a[1] + w[2] * r[0] - w[0] * r[2],
                 a[2] + w[0] * r[1] - w[1] * r[0]};
  };
  const int ba = body_[h.a], bb = body_[h.b];
  if (ba < 0 || bb < 0 || ba == bb)
    return 0.0;
  const Point &x = h.at;
  const Point ra = displacement(ba, x), rb = displacement(bb, x);
  const Point d{rb[0] - ra[0], rb[1] - ra[1], rb[2] - ra[2]};
  return dot(h.direction, d);
}

std::string FreeMotions::description(const std::vector<RigidMotion> &motions) const
{
  std::string text;
  const int n_bodies = finder_.n_bodies();
  std::vector<std::vector<std::string>> of_body(n_bodies);
  std::vector<std::string> together;
  for (const RigidMotion &m : motions)
  {
    const std::vector<int> moved = finder_.bodies_moved(m);
    if (moved.size() == 1)
      of_body[moved.front()].push_back(finder_.describe(m));
    else
      together.push_back(finder_.describe(m));
  }
  const auto join = [](const std::vector<std::string> &parts)
  {
    std::string s;
    for (const std::string &p : parts)
      s += (s.empty() ? "" : "; ") + p;
    return s;
  };
  for (int b = 0; b < n_bodies; ++b)
    if (!of_body[b].empty())
      text += (text.empty() ? "" : "; and ") + std::string("body ") + std::to_string(b + 1) +
              " of " + std::to_string(n_bodies) + " (" + summary_[b] + "): " + join(of_body[b]);
  if (!together.empty())
    text += (text.empty() ? "" : "; and ") + join(together);
  return text;
}

Teuchos::RCP<Tpetra::MultiVector<double>>
FreeMotions::basis(const std::vector<RigidMotion> &motions) const
{
  const int F = dofs_.n_node_fields();
  const int u_slot = dofs_.layout().slot(Field::ux);
  const int n_motions = static_cast<int>(motions.size());
  auto basis = Teuchos::rcp(new Tpetra::MultiVector<double>(dofs_.owned_dof_map(), n_motions));
  const auto &owned = dofs_.owned_nodes();
  for (int j = 0; j < n_motions; ++j)
  {
    const RigidMotion &motion = motions[j];
    for (std::size_t i = 0; i < owned.size(); ++i)
    {
      const int n = owned[i];
      const int b = body_[n];
      if (b < 0)
        continue;
      const Point &a = motion.translation[b];
      const Point &w = motion.rotation[b];
      const Point &c = finder_.body(b).centre;
      const Point x{mesh_.coordinates[n][0] - c[0], mesh_.coordinates[n][1] - c[1],
                    mesh_.coordinates[n][2] - c[2]};
      const Point r{a[0] + w[1] * x[2] - w[2] * x[1], a[1] + w[2] * x[0] - w[0] * x[2],
                    a[2] + w[0] * x[1] - w[1] * x[0]};
      const auto &q = constraints_.axes(n);
      const bool framed = constraints_.has_frame(n);
      for (int k = 0; k < 3; ++k)
      {
        // A constrained component holds the motion: zero (to round-off) by construction.
        const double value =
            k < constraints_.n_constrained(n) ? 0.0 : (framed ? dot(q[k], r) : r[k]);
        basis->replaceLocalValue(static_cast<LO>(F * i + u_slot + k), j, value);
      }
    }
  }
  return basis;
}
} // namespace kiln
