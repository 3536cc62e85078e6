#include "physics/mechanics/normal_displacement_condition.hpp"

#include "discretization/face_values.hpp"
#include "mesh/hex_geometry.hpp"
#include "mesh/side_set_nodes.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace kiln
{
std::string NormalDisplacementCondition::description()
{
  return "u.n = Displacement(t) along the outward normal, free in the face's plane";
}

Teuchos::ParameterList NormalDisplacementCondition::valid_parameters()
{
  Teuchos::ParameterList p;
  p.sublist("Displacement", false,
            "for Type \"Normal Displacement\": u.n(t) (default 0) [m], a function of time "
            "(doc/heat.md, Input)")
      .setParameters(TimeFunction::valid_parameters());
  return p;
}

NormalDisplacementCondition::NormalDisplacementCondition(const BoundaryConditionInput &input)
    : BoundaryCondition(input),
      displacement_(input.params.sublist("Displacement"), input.path + "/Displacement")
{
}

void NormalDisplacementCondition::add_constraints(const Mesh &mesh,
                                                  NodalConstraints &constraints) const
{
  NodalConstraintValues values(mesh, constraints, name(), displacement_);
  FaceValues fv;
  for (const int id : side_sets())
  {
    const SideSet &set = *mesh.find_side_set(id);
    // The side set's own nodes (increasing) and their normals: nothing sized to the mesh.
    const std::vector<int> nodes = side_set_nodes(mesh, set);
    const auto index_of = [&nodes](const int node)
    {
      return static_cast<std::size_t>(std::lower_bound(nodes.begin(), nodes.end(), node) -
                                      nodes.begin());
    };
    std::vector<Point> normal(nodes.size(), Point{});
    std::vector<std::size_t> touched; // indices into nodes, in the order the faces reach them
    for (int s = 0; s < set.n_sides(); ++s)
    {
      fv.reinit(mesh, set.cells[s], set.faces[s]);
      for (int i = 0; i < fv.n_shape(); ++i)
      {
        const std::size_t k = index_of(mesh.face_node(set.cells[s], set.faces[s], i));
        if (dot(normal[k], normal[k]) == 0.0)
          touched.push_back(k);
        // The node's normal: its faces' normals weighted by |N_i| (N_i itself for linear
        // faces; a TRI6 corner's N_i integrates to 0 and a QUAD8 corner's to a negative
        // share of the area, which would give it no normal or the inward one).
        for (int q = 0; q < fv.n_qpoints(); ++q)
          for (int d = 0; d < 3; ++d)
            normal[k][d] += std::abs(fv.shape(i, q)) * fv.normal(q)[d] * fv.JxW(q);
      }
    }
    for (const std::size_t k : touched)
    {
      Point n = normal[k];
      const double length = std::sqrt(dot(n, n));
      for (double &x : n)
        x /= length;
      constraints.constrain_direction(nodes[k], n, values.at(nodes[k]));
    }
  }
}
} // namespace kiln
