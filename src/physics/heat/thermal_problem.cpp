#include "physics/heat/thermal_problem.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"
#include "discretization/element_values.hpp"
#include "discretization/face_values.hpp"
#include "mesh/hex_geometry.hpp"
#include "physics/heat/convection_kernel.hpp"
#include "physics/heat/heat_flux_kernel.hpp"

#include <algorithm>

namespace kiln
{
namespace
{
constexpr int T_field = static_cast<int>(Field::T);
}

Teuchos::ParameterList ThermalProblem::valid_parameters()
{
  Teuchos::ParameterList p("Thermal");
  p.set("Initial Temperature", 298.0, "the uniform initial temperature, must be > 0 [K]",
        positive_double_validator());
  p.set("Gap Conductance", 1.0e4,
        "h, the heat-transfer coefficient between the two sides of the split gap: flux "
        "h (T_a - T_b) from side a to side b; must be >= 0 [W/(m^2 K)]",
        nonnegative_double_validator());
  set_named_sublists(p, "Boundary Conditions",
                     "thermal boundary conditions on side sets; faces in none are insulated",
                     ThermalBoundaryCondition::valid_parameters());
  return p;
}

ThermalProblem::ThermalProblem(const Mesh &mesh, const DofManager &dofs, const Material &material,
                               const Teuchos::ParameterList &thermal, const std::string &where)
    : mesh_(mesh), dofs_(dofs), assembler_(mesh, dofs),
      conduction_(material.heat_capacity(), material.conductivity()),
      gap_(thermal.get<double>("Gap Conductance")),
      initial_temperature_(thermal.get<double>("Initial Temperature")),
      dirichlet_bc_(mesh.n_nodes(), -1), dirichlet_scale_(mesh.n_nodes(), 0.0)
{
  KILN_ASSERT(dofs.n_node_fields() == 1 && !dofs.layout().contact,
              "ThermalProblem needs DofLayout{1, false}");
  KILN_CHECK_INPUT(mesh.gap_side_set != 0 || !given_in_input(thermal, "Gap Conductance"),
                   where + "/\"Gap Conductance\"",
                   "is given but the mesh has no gap (Kiln/Mesh/\"Gap Side Set\" is 0); remove "
                   "it or name the side set to split at");
  const auto &bc_list = thermal.sublist("Boundary Conditions");
  for (auto it = bc_list.begin(); it != bc_list.end(); ++it)
    bcs_.emplace_back(bc_list.name(it), bc_list.sublist(bc_list.name(it)), mesh,
                      where + "/Boundary Conditions");
  std::vector<char> owns_cell(mesh.n_cells(), 0);
  for (const int c : dofs.owned_cells())
    owns_cell[c] = 1;
  find_boundary_faces(owns_cell, where + "/Boundary Conditions");
  compute_dirichlet_scales(material.conductivity().value(initial_temperature_));

  for (int k = 0; k < static_cast<int>(mesh.gap_faces.size()); ++k)
    if (owns_cell[mesh.gap_faces[k].cell_a])
      owned_gap_faces_.push_back(k);

  x_overlap_ = assembler_.make_overlap_vector();
  b_overlap_ = assembler_.make_overlap_vector();
  coordinates_ = Teuchos::rcp(new Tpetra::MultiVector<double>(dofs.owned_node_map(), 3));
  const auto &owned_nodes = dofs.owned_nodes();
  for (std::size_t i = 0; i < owned_nodes.size(); ++i)
    for (int d = 0; d < 3; ++d)
      coordinates_->replaceLocalValue(static_cast<LO>(i), d, mesh.coordinates[owned_nodes[i]][d]);
}

void ThermalProblem::find_boundary_faces(const std::vector<char> &owns_cell,
                                         const std::string &where)
{
  check_faces_on_boundary(where);
  for (int b = 0; b < static_cast<int>(bcs_.size()); ++b)
    for (const int id : bcs_[b].side_sets())
    {
      const SideSet &set = *mesh_.find_side_set(id);
      for (int s = 0; s < set.n_sides(); ++s)
      {
        if (bcs_[b].type() == ThermalBoundaryCondition::Type::temperature)
        {
          for (const int i : hex_face_nodes[set.faces[s]])
          {
            const int node = mesh_.connectivity[set.cells[s]][i];
            if (dirichlet_bc_[node] < 0)
              dirichlet_bc_[node] = b;
          }
        }
        else if (owns_cell[set.cells[s]])
          boundary_faces_.push_back({set.cells[s], set.faces[s], b});
      }
    }
}

void ThermalProblem::check_faces_on_boundary(const std::string &where) const
{
  if (bcs_.empty())
    return;
  // Every cell face by its key; a face listed twice is inside the body.
  std::vector<FaceKey> all_faces;
  all_faces.reserve(static_cast<std::size_t>(mesh_.n_cells()) * n_hex_faces);
  for (int c = 0; c < mesh_.n_cells(); ++c)
    for (int f = 0; f < n_hex_faces; ++f)
      all_faces.push_back(mesh_.face_key(c, f));
  std::sort(all_faces.begin(), all_faces.end());
  for (const auto &bc : bcs_)
    for (const int id : bc.side_sets())
    {
      const SideSet &set = *mesh_.find_side_set(id);
      for (int s = 0; s < set.n_sides(); ++s)
      {
        const FaceKey key = mesh_.face_key(set.cells[s], set.faces[s]);
        const auto range = std::equal_range(all_faces.begin(), all_faces.end(), key);
        KILN_CHECK_INPUT(range.second - range.first == 1,
                         where + "/" + bc.name() + "/\"Side Sets\"",
                         "side set " << id << " has faces inside the body (cell "
                                     << set.cells[s] + 1 << ", side " << set.faces[s] + 1
                                     << " is shared with another cell); boundary conditions "
                                        "apply to boundary faces only. To make it a gap, set "
                                        "Kiln/Mesh/\"Gap Side Set\" to "
                                     << id);
      }
    }
}

void ThermalProblem::compute_dirichlet_scales(const double k)
{
  ElementValues fe;
  for (int c = 0; c < mesh_.n_cells(); ++c)
  {
    const auto &nodes = mesh_.connectivity[c];
    if (std::none_of(nodes.begin(), nodes.end(),
                     [&](const int n) { return dirichlet_bc_[n] >= 0; }))
      continue;
    fe.reinit(cell_nodes(mesh_, c));
    for (int i = 0; i < n_hex_nodes; ++i)
      if (dirichlet_bc_[nodes[i]] >= 0)
        for (int q = 0; q < fe.n_qpoints(); ++q)
        {
          const Point &g = fe.grad(i, q);
          dirichlet_scale_[nodes[i]] += k * (g[0] * g[0] + g[1] * g[1] + g[2] * g[2]) * fe.JxW(q);
        }
  }
}

void ThermalProblem::set_time_derivative(const double time, const double a, const Vector &b)
{
  time_ = time;
  a_ = a;
  assembler_.gather(b, *b_overlap_);
}

void ThermalProblem::initial_condition(const double time, Vector &x) const
{
  x.putScalar(initial_temperature_);
  for (const int n : dofs_.owned_nodes())
    if (dirichlet_bc_[n] >= 0)
      x.replaceGlobalValue(dofs_.dof(n, Field::T), bcs_[dirichlet_bc_[n]].value(time));
}

void ThermalProblem::evaluate(const Vector &x, Vector *f, Matrix *J)
{
  assembler_.gather(x, *x_overlap_);
  assembler_.begin(f != nullptr, J != nullptr);
  {
    const auto T = x_overlap_->getData();
    const auto b = b_overlap_->getData();
    add_cells(T.getRawPtr(), b.getRawPtr());
    add_boundary_faces(T.getRawPtr());
    add_gap_faces(T.getRawPtr());
    add_constraint_rows(T.getRawPtr());
  }
  assembler_.finish(f, J);
}

void ThermalProblem::drop_constrained_rows(const std::vector<int> &node_of_local,
                                           LocalSystem &local) const
{
  for (int i = 0; i < static_cast<int>(node_of_local.size()); ++i)
  {
    if (dirichlet_bc_[node_of_local[i]] < 0)
      continue;
    local.residual(T_field, i) = 0.0;
    for (int j = 0; j < local.n_nodes(); ++j)
      local.jacobian(T_field, i, T_field, j) = 0.0;
  }
}

void ThermalProblem::add_cells(const double *T, const double *b)
{
  ElementValues fe;
  LocalSystem local(n_hex_nodes, 1);
  std::vector<int> nodes(n_hex_nodes);
  HeatConductionKernel::NodalValues T_cell{}, T_dot_cell{};
  for (const int c : dofs_.owned_cells())
  {
    const std::vector<LO> lids = assembler_.cell_lids(c);
    for (int i = 0; i < n_hex_nodes; ++i)
    {
      nodes[i] = mesh_.connectivity[c][i];
      T_cell[i] = T[lids[i]];
      T_dot_cell[i] = a_ * T[lids[i]] + b[lids[i]];
    }
    fe.reinit(cell_nodes(mesh_, c));
    local.clear();
    conduction_.evaluate(fe, T_cell, T_dot_cell, a_, local);
    drop_constrained_rows(nodes, local);
    assembler_.add(lids, local);
  }
}

void ThermalProblem::add_boundary_faces(const double *T)
{
  FaceValues fv;
  LocalSystem local(4, 1);
  std::vector<int> nodes(4);
  std::array<double, 4> T_face{};
  for (const auto &face : boundary_faces_)
  {
    const std::vector<LO> lids = assembler_.face_lids(face.cell, face.face);
    for (int i = 0; i < 4; ++i)
    {
      nodes[i] = mesh_.connectivity[face.cell][hex_face_nodes[face.face][i]];
      T_face[i] = T[lids[i]];
    }
    fv.reinit(face_nodes(mesh_, face.cell, face.face));
    local.clear();
    const ThermalBoundaryCondition &bc = bcs_[face.bc];
    if (bc.type() == ThermalBoundaryCondition::Type::convection)
      ConvectionKernel(bc.coefficient()).evaluate(fv, T_face, bc.value(time_), local);
    else
      HeatFluxKernel::evaluate(fv, bc.value(time_), local);
    drop_constrained_rows(nodes, local);
    assembler_.add(lids, local);
  }
}

void ThermalProblem::add_gap_faces(const double *T)
{
  FaceValues fv;
  LocalSystem local(8, 1);
  std::vector<int> nodes(8);
  std::array<double, 4> T_a{}, T_b{};
  for (const int k : owned_gap_faces_)
  {
    const GapFace &face = mesh_.gap_faces[k];
    const std::vector<LO> lids = assembler_.gap_face_lids(k);
    for (int i = 0; i < 4; ++i)
    {
      nodes[i] = mesh_.connectivity[face.cell_a][hex_face_nodes[face.face_a][i]];
      nodes[4 + i] = face.node_b[i];
      T_a[i] = T[lids[i]];
      T_b[i] = T[lids[4 + i]];
    }
    fv.reinit(face_nodes(mesh_, face.cell_a, face.face_a));
    local.clear();
    gap_.evaluate(fv, T_a, T_b, local);
    drop_constrained_rows(nodes, local);
    assembler_.add(lids, local);
  }
}

void ThermalProblem::add_constraint_rows(const double *T)
{
  LocalSystem local(1, 1);
  for (const int n : dofs_.owned_nodes())
  {
    const int bc = dirichlet_bc_[n];
    if (bc < 0)
      continue;
    const LO lid = assembler_.lid(dofs_.dof(n, Field::T));
    local.clear();
    local.residual(T_field, 0) = dirichlet_scale_[n] * (T[lid] - bcs_[bc].value(time_));
    local.jacobian(T_field, 0, T_field, 0) = dirichlet_scale_[n];
    assembler_.add({lid}, local);
  }
}
} // namespace kiln
