#pragma once
/// The rigid motions of bodies that a set of constraints leaves free (doc/mechanics.md, "Free
/// motions").
#include "mesh/mesh.hpp"

#include <Teuchos_Comm.hpp>

#include <string>
#include <vector>

namespace kiln
{
/// A rigid motion of every body b: r_b(x) = a_b + w_b x (x - c_b), c_b the body's centre.
struct RigidMotion
{
  std::vector<Point> translation; ///< a_b per body [m]
  std::vector<Point> rotation;    ///< w_b per body [rad]
};

/// Finds a basis of the rigid motions that constraints leave free. Each constraint is a row of
/// a small system in the 6 unknowns (a_b, w_b) of each body:
/// - a displacement direction d held at a point x of body b: d.(a_b + w_b x (x - c_b)) = 0;
/// - a gap pair across which body a and body b touch with the normal n at x:
///   n.(r_a(x) - r_b(x)) = 0 (the normal only: contact is frictionless).
/// Only the normal matrix A = sum of row^T row is kept (6 x 6 blocks per constraint, in
/// unknowns (a_b, w_b L_b) with L_b the body's size, so that all columns are lengths), so the
/// memory is (6 x bodies)^2 whatever the number of constraints. find() sums A over the ranks
/// (each rank adds the constraints of its owned nodes) and takes its null space from the
/// eigenvalues below 1e-11 times the largest (or 1e-11 with no constraint at all).
class FreeMotionFinder
{
public:
  struct Body
  {
    Point centre{};    ///< c_b [m]
    double size = 1.0; ///< L_b, e.g. the diagonal of its bounding box [m], > 0
  };
  explicit FreeMotionFinder(std::vector<Body> bodies);

  int n_bodies() const { return static_cast<int>(bodies_.size()); }
  const Body &body(const int b) const { return bodies_[b]; }
  /// d.r_b(x) = 0 (d a unit vector).
  void add_direction(int body, const Point &x, const Point &d);
  /// n.(r_a(x) - r_b(x)) = 0 (n a unit vector); nothing if a == b.
  void add_gap(int body_a, int body_b, const Point &x, const Point &n);

  /// A basis of the free motions, the normal matrices of every rank summed (collective). The
  /// basis is chosen to be read: first, per body, the motions of that body alone, translations
  /// (along the coordinate axes where they are free) and then rotations (about axes parallel
  /// to coordinate axes where possible, each without a component in the body's free
  /// translations); then the motions that move several bodies together: the rigid motions
  /// of each group of bodies joined by gaps as one where free, then what remains.
  std::vector<RigidMotion> find(const Teuchos::Comm<int> &comm) const;
  /// The bodies a motion moves (increasing).
  std::vector<int> bodies_moved(const RigidMotion &motion) const;
  /// The motion in words: "translation along z", "rotation about the axis (0, 0, 1) through
  /// (0.5, 0, 0)"; "bodies 1 and 2 together: ..." for one rigid motion of several bodies,
  /// else "body 1: ..., body 2: ..., together".
  std::string describe(const RigidMotion &motion) const;

private:
  /// The six rigid motions (translations along x, y, z, rotations about them through the
  /// group's centre) of each group of at least two bodies that the reduced normal matrix A
  /// couples, in the unknowns (a_b, w_b L_b).
  std::vector<std::vector<double>> group_motions(const std::vector<double> &A) const;
  /// "bodies 1 and 2 together: translation along x" if the motion moves them as one rigid
  /// body, else "".
  std::string describe_as_one(const RigidMotion &motion, const std::vector<int> &moved) const;

  std::vector<Body> bodies_;
  std::vector<double> normal_; ///< A, (6 n_bodies)^2, column-major
};
} // namespace kiln
