#include "physics/coupled_problem.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"
#include "discretization/element_values.hpp"
#include "discretization/face_values.hpp"
#include "mesh/hex_geometry.hpp"
#include "physics/boundary_input.hpp"
#include "physics/heat/convection_kernel.hpp"
#include "physics/heat/heat_flux_kernel.hpp"
#include "physics/mechanics/traction_kernel.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_TimeMonitor.hpp>

#include <algorithm>
#include <cmath>

namespace kiln
{
namespace internal
{
Point read_vector(const Teuchos::ParameterList &p, const std::string &name,
                  const std::string &where)
{
  const auto &v = p.get<Teuchos::Array<double>>(name);
  KILN_CHECK_INPUT(v.size() == 3, where + "/\"" + name + "\"",
                   "must have 3 entries (x, y, z), has " << v.size());
  return {v[0], v[1], v[2]};
}
} // namespace internal

Teuchos::ParameterList CoupledProblem::valid_thermal_parameters()
{
  Teuchos::ParameterList p("Thermal");
  p.set("Initial Temperature", 298.0, "the uniform initial temperature, must be > 0 [K]",
        positive_double_validator());
  p.set("Gap Conductance", 1.0e4,
        "h, the heat-transfer coefficient between the two sides of the split gap: flux "
        "h (T_a - T_b) from side a to side b; must be >= 0 [W/(m^2 K)]",
        nonnegative_double_validator());
  p.set("Gap Conductance Model", "Constant",
        "\"Constant\": h = \"Gap Conductance\" whatever the contact state (as Truchas); "
        "\"Contact Dependent\": h = h0 L/(L + g) while the gap is open by g, h0 + h_p p "
        "while pressed together with the normal stress p (h0: \"Gap Conductance\"; needs "
        "Physics Thermo-Elasticity with Mechanics/Contact enabled; doc/contact.md)",
        choice_validator({"Constant", "Contact Dependent"}));
  p.set("Gap Width Scale", 1.0e-5,
        "L of the Contact Dependent model: the opening at which h has fallen to h0/2, must be "
        "> 0 [m]",
        positive_double_validator());
  p.set("Gap Pressure Coefficient", 1.0e-3,
        "h_p of the Contact Dependent model: the rise of h per contact pressure, must be >= 0 "
        "[W/(m^2 K Pa)]",
        nonnegative_double_validator());
  set_named_sublists(p, "Boundary Conditions",
                     "thermal boundary conditions on side sets; faces in none are insulated",
                     ThermalBoundaryCondition::valid_parameters());
  return p;
}

Teuchos::ParameterList CoupledProblem::valid_mechanics_parameters()
{
  Teuchos::ParameterList p("Mechanics");
  p.set("Body Force", Teuchos::Array<double>(3, 0.0),
        "a force per volume f = (fx, fy, fz), added to rho g [N/m^3]");
  p.set("Gravity", Teuchos::Array<double>(3, 0.0),
        "the acceleration of gravity g = (gx, gy, gz); the body force is rho g + f [m/s^2]");
  set_named_sublists(p, "Boundary Conditions",
                     "mechanical boundary conditions on side sets; faces in none are free of "
                     "traction",
                     MechanicalBoundaryCondition::valid_parameters());
  p.set("Contact", valid_contact_parameters(),
        "frictionless contact across the gap (Kiln/Mesh/\"Gap Side Set\"); doc/contact.md");
  return p;
}

Teuchos::ParameterList CoupledProblem::valid_contact_parameters()
{
  Teuchos::ParameterList p("Contact");
  p.set("Enabled", true,
        "true: the two sides of the gap may separate but not interpenetrate, and carry a "
        "compressive normal traction when in contact (frictionless); false: they are separate "
        "bodies that pass through each other [-]");
  p.set("Complementarity Function", "Min",
        "how g >= 0, p >= 0, p g = 0 enters the Newton solve: \"Min\", p - max(0, p - c g) "
        "(semismooth Newton: an active-set method); \"Fischer-Burmeister\", p + c g - "
        "sqrt(p^2 + (c g)^2). After an active-set cycle a step switches to Fischer-Burmeister "
        "anyway",
        choice_validator({"Min", "Fischer-Burmeister"}));
  p.set("Complementarity Scale", 1.0,
        "s in c = s (lambda + 2G) / sqrt(A), A the pair's area: weighs the gap against the "
        "pressure; it changes the Newton path, not the converged answer; must be > 0 [-]",
        positive_double_validator());
  return p;
}

CoupledProblem::CoupledProblem(const Mesh &mesh, const DofManager &dofs, const Material &material,
                               const Teuchos::ParameterList &thermal,
                               const Teuchos::ParameterList &mechanics, const std::string &where)
    : mesh_(mesh), dofs_(dofs), assembler_(mesh, dofs), F_(dofs.n_node_fields()),
      T_slot_(dofs.layout().slot(Field::T)), u_slot_(dofs.layout().slot(Field::ux)),
      overlap_index_(mesh.n_nodes(), -1), dirichlet_bc_(mesh.n_nodes(), -1),
      temperature_scale_(mesh.n_nodes(), 0.0), prescribed_temperature_(mesh.n_nodes(), 0.0),
      frame_of_node_(mesh.n_nodes(), -1), displacement_row_scale_(mesh.n_nodes(), 0.0),
      pair_of_node_(mesh.n_nodes(), -1)
{
  KILN_ASSERT(T_slot_ <= 0, "the temperature must be the first unknown of a node");
  const auto &overlap_nodes = dofs.overlap_nodes();
  for (std::size_t i = 0; i < overlap_nodes.size(); ++i)
  {
    overlap_index_[overlap_nodes[i]] = static_cast<int>(i);
    KILN_ASSERT(assembler_.lid(dofs.node_dof(overlap_nodes[i], 0)) == static_cast<LO>(F_ * i),
                "the overlap map is not node-major");
  }
  std::vector<char> owns_cell(mesh.n_cells(), 0);
  for (const int c : dofs.owned_cells())
    owns_cell[c] = 1;
  const InteriorFaceCheck interior(mesh);
  if (T_slot_ >= 0)
    setup_thermal(material, thermal, owns_cell, interior, where + "/Thermal");
  if (u_slot_ >= 0)
    setup_mechanics(material, mechanics, owns_cell, interior, where + "/Mechanics");

  x_overlap_ = assembler_.make_overlap_vector();
  b_overlap_ = assembler_.make_overlap_vector();
  f_work_ = Teuchos::rcp(new Vector(dofs.owned_dof_map()));
  T_state_.assign(overlap_nodes.size(), material.reference_temperature());
  T_dot_state_.assign(overlap_nodes.size(), 0.0);
  u_state_.assign(overlap_nodes.size(), Point{});
  setup_solver_data(material);
  update_prescribed(0.0);
}

void CoupledProblem::setup_thermal(const Material &material, const Teuchos::ParameterList &thermal,
                                   const std::vector<char> &owns_cell,
                                   const InteriorFaceCheck &interior, const std::string &where)
{
  conduction_.emplace(material.heat_capacity(), material.conductivity());
  gap_ = GapConductanceKernel(thermal.get<double>("Gap Conductance"));
  if (thermal.get<std::string>("Gap Conductance Model") == "Contact Dependent")
  {
    KILN_CHECK_INPUT(dofs_.layout().contact && u_slot_ >= 0, where + "/\"Gap Conductance Model\"",
                     "is \"Contact Dependent\", which needs the contact state: set Kiln/"
                     "\"Physics\" to \"Thermo-Elasticity\" with Mechanics/Contact/\"Enabled\" "
                     "true, or use \"Constant\"");
    ContactConductanceKernel::Parameters k;
    k.h0 = thermal.get<double>("Gap Conductance");
    k.length = thermal.get<double>("Gap Width Scale");
    k.pressure_coefficient = thermal.get<double>("Gap Pressure Coefficient");
    k.lambda = material.lame_lambda();
    k.shear_modulus = material.shear_modulus();
    k.beta = (3.0 * k.lambda + 2.0 * k.shear_modulus) * material.thermal_expansion();
    k.reference_temperature = material.reference_temperature();
    contact_conductance_.emplace(k);
  }
  else
    for (const char *key : {"Gap Width Scale", "Gap Pressure Coefficient"})
      KILN_CHECK_INPUT(!given_in_input(thermal, key), where + "/\"" + key + "\"",
                       "is given but \"Gap Conductance Model\" is \"Constant\"; remove it "
                       "or set the model to \"Contact Dependent\"");
  initial_temperature_ = thermal.get<double>("Initial Temperature");
  KILN_CHECK_INPUT(mesh_.gap_side_set != 0 || !given_in_input(thermal, "Gap Conductance"),
                   where + "/\"Gap Conductance\"",
                   "is given but the mesh has no gap (Kiln/Mesh/\"Gap Side Set\" is 0); remove "
                   "it or name the side set to split at");
  const std::string bc_where = where + "/Boundary Conditions";
  const auto &bc_list = thermal.sublist("Boundary Conditions");
  for (auto it = bc_list.begin(); it != bc_list.end(); ++it)
  {
    bcs_.emplace_back(bc_list.name(it), bc_list.sublist(bc_list.name(it)), mesh_, bc_where);
    interior.check(bcs_.back().side_sets(), bc_where + "/" + bcs_.back().name() + "/\"Side Sets\"");
  }
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
  for (int k = 0; k < static_cast<int>(mesh_.gap_faces.size()); ++k)
    if (owns_cell[mesh_.gap_faces[k].cell_a])
      owned_gap_faces_.push_back(k);
}

void CoupledProblem::setup_mechanics(const Material &material,
                                     const Teuchos::ParameterList &mechanics,
                                     const std::vector<char> &owns_cell,
                                     const InteriorFaceCheck &interior, const std::string &where)
{
  elasticity_.emplace(material.lame_lambda(), material.shear_modulus(),
                      material.thermal_expansion(), material.reference_temperature());
  const Point f = internal::read_vector(mechanics, "Body Force", where);
  const Point g = internal::read_vector(mechanics, "Gravity", where);
  for (int d = 0; d < 3; ++d)
    body_force_[d] = f[d] + material.density() * g[d];

  const std::string bc_where = where + "/Boundary Conditions";
  const auto &bc_list = mechanics.sublist("Boundary Conditions");
  for (auto it = bc_list.begin(); it != bc_list.end(); ++it)
  {
    mechanical_bcs_.emplace_back(bc_list.name(it), bc_list.sublist(bc_list.name(it)), mesh_,
                                 bc_where);
    interior.check(mechanical_bcs_.back().side_sets(),
                   bc_where + "/" + mechanical_bcs_.back().name() + "/\"Side Sets\"");
  }
  for (int b = 0; b < static_cast<int>(mechanical_bcs_.size()); ++b)
    if (!mechanical_bcs_[b].is_constraint())
      for (const int id : mechanical_bcs_[b].side_sets())
      {
        const SideSet &set = *mesh_.find_side_set(id);
        for (int s = 0; s < set.n_sides(); ++s)
          if (owns_cell[set.cells[s]])
            load_faces_.push_back({set.cells[s], set.faces[s], b});
      }
  build_frames();
  modulus_ = material.lame_lambda() + 2.0 * material.shear_modulus();
  KILN_CHECK_INPUT(mesh_.gap_side_set != 0 || !given_in_input(mechanics, "Contact"),
                   where + "/Contact",
                   "is given but the mesh has no gap (Kiln/Mesh/\"Gap Side Set\" is 0); remove "
                   "it or name the side set to split at");
  if (dofs_.layout().contact)
    setup_contact(mechanics.sublist("Contact"), where + "/Contact");
}

void CoupledProblem::build_frames()
{
  // Per node, the constraint directions in input order: (condition, direction).
  std::vector<std::vector<std::pair<int, Point>>> directions(mesh_.n_nodes());
  FaceValues fv;
  for (int b = 0; b < static_cast<int>(mechanical_bcs_.size()); ++b)
  {
    const MechanicalBoundaryCondition &bc = mechanical_bcs_[b];
    if (bc.type() == MechanicalBoundaryCondition::Type::displacement)
    {
      for (const int id : bc.side_sets())
      {
        const SideSet &set = *mesh_.find_side_set(id);
        std::vector<char> seen(mesh_.n_nodes(), 0);
        for (int s = 0; s < set.n_sides(); ++s)
          for (const int i : hex_face_nodes[set.faces[s]])
          {
            const int node = mesh_.connectivity[set.cells[s]][i];
            if (seen[node]++)
              continue;
            for (const int c : bc.components())
            {
              Point e{};
              e[c] = 1.0;
              directions[node].emplace_back(b, e);
            }
          }
      }
    }
    else if (bc.type() == MechanicalBoundaryCondition::Type::normal_displacement)
    {
      // The node's normal on each side set of this condition: the area-weighted outward
      // normals of the set's faces there (exact on a plane face, the usual average at a
      // crease within one set). Side sets meeting at an edge give one constraint each.
      for (const int id : bc.side_sets())
      {
        std::vector<Point> normal(mesh_.n_nodes(), Point{});
        std::vector<int> touched;
        const SideSet &set = *mesh_.find_side_set(id);
        for (int s = 0; s < set.n_sides(); ++s)
        {
          fv.reinit(face_nodes(mesh_, set.cells[s], set.faces[s]));
          for (int i = 0; i < 4; ++i)
          {
            const int node = mesh_.connectivity[set.cells[s]][hex_face_nodes[set.faces[s]][i]];
            if (dot(normal[node], normal[node]) == 0.0)
              touched.push_back(node);
            for (int q = 0; q < fv.n_qpoints(); ++q)
              for (int d = 0; d < 3; ++d)
                normal[node][d] += fv.shape(i, q) * fv.normal(q)[d] * fv.JxW(q);
          }
        }
        for (const int node : touched)
        {
          Point n = normal[node];
          const double length = std::sqrt(dot(n, n));
          for (double &x : n)
            x /= length;
          directions[node].emplace_back(b, n);
        }
      }
    }
  }
  for (int node = 0; node < mesh_.n_nodes(); ++node)
  {
    if (directions[node].empty())
      continue;
    NodeFrame frame;
    std::vector<Point> basis;
    for (const auto &[b, n] : directions[node])
      if (basis.size() < 3 && append_orthonormal(basis, n))
      {
        frame.bc[frame.n_constrained] = b;
        frame.n[frame.n_constrained] = n;
        ++frame.n_constrained;
      }
    for (int d = 0; d < 3 && basis.size() < 3; ++d)
    {
      Point e{};
      e[d] = 1.0;
      append_orthonormal(basis, e);
    }
    std::copy(basis.begin(), basis.end(), frame.q.begin());
    frame_of_node_[node] = static_cast<int>(frames_.size());
    frames_.push_back(frame);
  }
}

std::vector<double> CoupledProblem::stiffness_sums() const
{
  std::vector<double> sum(mesh_.n_nodes(), 0.0);
  ElementValues fe;
  const auto constrained = [&](const int n)
  { return dirichlet_bc_[n] >= 0 || frame_of_node_[n] >= 0; };
  for (int c = 0; c < mesh_.n_cells(); ++c)
  {
    const auto &nodes = mesh_.connectivity[c];
    if (std::none_of(nodes.begin(), nodes.end(), constrained))
      continue;
    fe.reinit(cell_nodes(mesh_, c));
    for (int i = 0; i < n_hex_nodes; ++i)
      if (constrained(nodes[i]))
        for (int q = 0; q < fe.n_qpoints(); ++q)
          sum[nodes[i]] += dot(fe.grad(i, q), fe.grad(i, q)) * fe.JxW(q);
  }
  return sum;
}

void CoupledProblem::setup_solver_data(const Material &material)
{
  const std::vector<double> sums = stiffness_sums();
  const double k0 = T_slot_ >= 0 ? material.conductivity().value(initial_temperature_) : 0.0;
  const double modulus = material.lame_lambda() + 2.0 * material.shear_modulus();
  for (int n = 0; n < mesh_.n_nodes(); ++n)
  {
    if (dirichlet_bc_[n] >= 0)
      temperature_scale_[n] = k0 * sums[n];
    if (frame_of_node_[n] >= 0)
      displacement_row_scale_[n] = modulus * sums[n];
  }
  // Symmetric scaling: with both fields, displacements by sqrt(k / (lambda + 2G)), so
  // that the diagonal of the force rows (~ (lambda + 2G) h) becomes that of the heat rows
  // (~ k h); see doc/mechanics.md.
  if (T_slot_ >= 0 && u_slot_ >= 0)
    displacement_scale_ = std::sqrt(k0 / modulus);

  const auto owned_map = dofs_.owned_dof_map();
  const auto &owned_nodes = dofs_.owned_nodes();
  coordinates_ = Teuchos::rcp(new Tpetra::MultiVector<double>(dofs_.owned_node_map(), 3));
  Point centre{};
  for (const Point &x : mesh_.coordinates)
    for (int d = 0; d < 3; ++d)
      centre[d] += x[d] / mesh_.n_nodes();
  const int n_modes = (T_slot_ >= 0 ? 1 : 0) + (u_slot_ >= 0 ? 6 : 0);
  near_null_space_ = Teuchos::rcp(new Tpetra::MultiVector<double>(owned_map, n_modes));
  unknown_scale_ = Teuchos::rcp(new Vector(owned_map));
  time_error_mask_ = Teuchos::rcp(new Vector(owned_map));
  for (std::size_t i = 0; i < owned_nodes.size(); ++i)
  {
    const int n = owned_nodes[i];
    const Point &x = mesh_.coordinates[n];
    for (int d = 0; d < 3; ++d)
      coordinates_->replaceLocalValue(static_cast<LO>(i), d, x[d]);
    const LO row = static_cast<LO>(F_ * i);
    int mode = 0;
    if (T_slot_ >= 0)
    {
      near_null_space_->replaceLocalValue(row + T_slot_, mode++, 1.0);
      unknown_scale_->replaceLocalValue(row + T_slot_, 1.0);
      time_error_mask_->replaceLocalValue(row + T_slot_, 1.0);
    }
    if (u_slot_ >= 0)
    {
      // Rigid-body modes in the node's unknowns (û = Q^T u where it has a frame).
      const Point r{x[0] - centre[0], x[1] - centre[1], x[2] - centre[2]};
      const std::array<Point, 6> modes = {Point{1, 0, 0},        Point{0, 1, 0},
                                          Point{0, 0, 1},        Point{0, -r[2], r[1]},
                                          Point{r[2], 0, -r[0]}, Point{-r[1], r[0], 0}};
      const int f = frame_of_node_[n];
      for (const Point &u : modes)
      {
        for (int k = 0; k < 3; ++k)
          near_null_space_->replaceLocalValue(row + u_slot_ + k, mode,
                                              f < 0 ? u[k] : dot(frames_[f].q[k], u));
        ++mode;
      }
      for (int k = 0; k < 3; ++k)
        unknown_scale_->replaceLocalValue(row + u_slot_ + k, displacement_scale_);
    }
  }
}

void CoupledProblem::update_prescribed(const double time)
{
  for (int n = 0; n < mesh_.n_nodes(); ++n)
    if (dirichlet_bc_[n] >= 0)
      prescribed_temperature_[n] = bcs_[dirichlet_bc_[n]].value(time);
  for (NodeFrame &frame : frames_)
    frame.prescribed = prescribed_components(frame, time);
}

std::array<double, 3> CoupledProblem::prescribed_components(const NodeFrame &frame,
                                                            const double time) const
{
  // n_l . u = g_l with u = sum_k û_k q_k and n_l . q_k = 0 for k > l: forward substitution.
  std::array<double, 3> u_hat{};
  for (int l = 0; l < frame.n_constrained; ++l)
  {
    double g = mechanical_bcs_[frame.bc[l]].value(time);
    for (int k = 0; k < l; ++k)
      g -= dot(frame.n[l], frame.q[k]) * u_hat[k];
    u_hat[l] = g / dot(frame.n[l], frame.q[l]);
  }
  return u_hat;
}

void CoupledProblem::set_time_derivative(const double time, const double a, const Vector &b)
{
  time_ = time;
  a_ = a;
  assembler_.gather(b, *b_overlap_);
  update_prescribed(time);
  history_.clear();
  jacobians_ = 0;
  cycle_fallback_ = false;
}

void CoupledProblem::initial_condition(const double time, Vector &x) const
{
  x.putScalar(0.0);
  const auto &owned_nodes = dofs_.owned_nodes();
  for (std::size_t i = 0; i < owned_nodes.size(); ++i)
  {
    const int n = owned_nodes[i];
    const LO row = static_cast<LO>(F_ * i);
    if (T_slot_ >= 0)
      x.replaceLocalValue(row + T_slot_, dirichlet_bc_[n] >= 0 ? bcs_[dirichlet_bc_[n]].value(time)
                                                               : initial_temperature_);
    if (frame_of_node_[n] >= 0)
    {
      const NodeFrame &frame = frames_[frame_of_node_[n]];
      const std::array<double, 3> u_hat = prescribed_components(frame, time);
      for (int l = 0; l < frame.n_constrained; ++l)
        x.replaceLocalValue(row + u_slot_ + l, u_hat[l]);
    }
  }
}

void CoupledProblem::build_state()
{
  const auto x = x_overlap_->getData();
  const auto b = b_overlap_->getData();
  const auto &overlap_nodes = dofs_.overlap_nodes();
  const double T_ref = elasticity_ ? elasticity_->reference_temperature() : 0.0;
  for (std::size_t i = 0; i < overlap_nodes.size(); ++i)
  {
    const int n = overlap_nodes[i];
    const std::size_t row = F_ * i;
    if (T_slot_ >= 0)
    {
      const double T = dirichlet_bc_[n] >= 0 ? prescribed_temperature_[n] : x[row + T_slot_];
      T_state_[i] = T;
      T_dot_state_[i] = a_ * T + b[row + T_slot_];
    }
    else
      T_state_[i] = T_ref;
    if (u_slot_ < 0)
      continue;
    Point u_hat{x[row + u_slot_], x[row + u_slot_ + 1], x[row + u_slot_ + 2]};
    const int f = frame_of_node_[n];
    if (f < 0)
    {
      u_state_[i] = u_hat;
      continue;
    }
    const NodeFrame &frame = frames_[f];
    for (int k = 0; k < frame.n_constrained; ++k)
      u_hat[k] = frame.prescribed[k];
    for (int d = 0; d < 3; ++d)
      u_state_[i][d] =
          frame.q[0][d] * u_hat[0] + frame.q[1][d] * u_hat[1] + frame.q[2][d] * u_hat[2];
  }
}

void CoupledProblem::evaluate(const Vector &x, Vector *f, Matrix *J)
{
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer(
      J != nullptr ? "Kiln: 5 assembly (residual and Jacobian)" : "Kiln: 5 assembly (residual)"));
  assembler_.gather(x, *x_overlap_);
  build_state();
  const auto assemble = [&](Vector *residual, Matrix *jacobian)
  {
    assembler_.begin(residual != nullptr, jacobian != nullptr);
    add_cells();
    add_boundary_faces();
    add_gap_faces();
    add_constraint_rows();
    assembler_.finish(residual, jacobian);
  };
  if (pairs_.empty() && frozen_temperature_.empty())
  {
    assemble(f, J);
    return;
  }
  // Contact needs the assembled elastic rows first (the pressure P of every pair), then
  // combines rows: the residual from the assembled rows, the Jacobian element by element.
  Vector &residual = f != nullptr ? *f : *f_work_;
  assemble(&residual, nullptr);
  update_contact(residual);
  if (J != nullptr)
  {
    combine_rows_ = true;
    assemble(nullptr, J);
    combine_rows_ = false;
    add_contact_jacobian(*J);
    if (!pairs_.empty())
      track_active_set();
  }
}

void CoupledProblem::add_local(const std::vector<int> &nodes, LocalSystem &local)
{
  if (!pairs_.empty())
  {
    // A gap node's twin joins the system (its rows and columns start at zero).
    const std::vector<int> extended_nodes = assembler_.with_twins(nodes);
    if (extended_nodes.size() > nodes.size())
    {
      LocalSystem extended(static_cast<int>(extended_nodes.size()), F_);
      const int m = local.size();
      for (int a = 0; a < m; ++a)
      {
        extended.residual(a % F_, a / F_) = local.residual_values()[a];
        for (int b = 0; b < m; ++b)
          extended.jacobian(a % F_, a / F_, b % F_, b / F_) =
              local.jacobian_values()[static_cast<std::size_t>(a) * m + b];
      }
      transform_and_add(extended_nodes, extended);
      return;
    }
  }
  transform_and_add(nodes, local);
}

void CoupledProblem::transform_and_add(const std::vector<int> &nodes, LocalSystem &local)
{
  const int n_local = local.n_nodes();
  if (u_slot_ >= 0)
    for (int i = 0; i < n_local; ++i)
    {
      const int f = frame_of_node_[nodes[i]];
      if (f < 0)
        continue;
      const auto &q = frames_[f].q;
      // Rows: R̂_k = q_k . R; columns: dR/dû_k = dR/du . q_k.
      Point r{};
      for (int k = 0; k < 3; ++k)
        for (int d = 0; d < 3; ++d)
          r[k] += q[k][d] * local.residual(u_slot_ + d, i);
      for (int k = 0; k < 3; ++k)
        local.residual(u_slot_ + k, i) = r[k];
      for (int j = 0; j < n_local; ++j)
        for (int fj = 0; fj < F_; ++fj)
        {
          Point row{};
          for (int k = 0; k < 3; ++k)
            for (int d = 0; d < 3; ++d)
              row[k] += q[k][d] * local.jacobian(u_slot_ + d, i, fj, j);
          for (int k = 0; k < 3; ++k)
            local.jacobian(u_slot_ + k, i, fj, j) = row[k];
        }
      for (int j = 0; j < n_local; ++j)
        for (int fj = 0; fj < F_; ++fj)
        {
          Point column{};
          for (int k = 0; k < 3; ++k)
            for (int d = 0; d < 3; ++d)
              column[k] += local.jacobian(fj, j, u_slot_ + d, i) * q[k][d];
          for (int k = 0; k < 3; ++k)
            local.jacobian(fj, j, u_slot_ + k, i) = column[k];
        }
    }
  // Contact pairs in contact: row a += row b, and row b := 0 ("Min") or
  // (dP/2)(row b - row a) (Fischer-Burmeister); add_contact_jacobian() adds the rest.
  if (combine_rows_)
  {
    const int m = local.size();
    auto &jac = local.jacobian_values();
    for (int i = 0; i < n_local; ++i)
    {
      const int k = pair_of_node_[nodes[i]];
      if (k < 0 || nodes[i] != pairs_[k].a || contact_mode_[k] == ContactMode::open)
        continue;
      const int j =
          static_cast<int>(std::find(nodes.begin(), nodes.end(), pairs_[k].b) - nodes.begin());
      KILN_ASSERT(j < n_local, "a local system lacks the twin of node " << nodes[i]);
      const std::size_t ia = local.index(u_slot_ + pairs_[k].slot_a, i);
      const std::size_t ib = local.index(u_slot_ + pairs_[k].slot_b, j);
      const double w = contact_mode_[k] == ContactMode::closed ? 0.0 : 0.5 * contact_dP_[k];
      for (int c = 0; c < m; ++c)
      {
        const double va = jac[ia * m + c], vb = jac[ib * m + c];
        jac[ia * m + c] = va + vb;
        jac[ib * m + c] = w * (vb - va);
      }
    }
  }
  const auto eliminate = [&](const int field, const int i)
  {
    local.residual(field, i) = 0.0;
    for (int j = 0; j < n_local; ++j)
      for (int fj = 0; fj < F_; ++fj)
        local.jacobian(field, i, fj, j) = local.jacobian(fj, j, field, i) = 0.0;
  };
  for (int i = 0; i < n_local; ++i)
  {
    if (T_slot_ >= 0 && dirichlet_bc_[nodes[i]] >= 0)
      eliminate(T_slot_, i);
    if (u_slot_ >= 0 && frame_of_node_[nodes[i]] >= 0)
      for (int k = 0; k < frames_[frame_of_node_[nodes[i]]].n_constrained; ++k)
        eliminate(u_slot_ + k, i);
  }
  assembler_.add(assembler_.node_lids(nodes), local);
}

void CoupledProblem::add_cells()
{
  ElementValues fe;
  LocalSystem local(n_hex_nodes, F_);
  std::vector<int> nodes(n_hex_nodes);
  HeatConductionKernel::NodalValues T{}, T_dot{};
  ElasticityKernel::NodalDisplacements u{};
  for (const int c : dofs_.owned_cells())
  {
    for (int i = 0; i < n_hex_nodes; ++i)
    {
      nodes[i] = mesh_.connectivity[c][i];
      const int k = overlap_index_[nodes[i]];
      T[i] = T_state_[k];
      T_dot[i] = T_dot_state_[k];
      u[i] = u_state_[k];
    }
    fe.reinit(cell_nodes(mesh_, c));
    local.clear();
    if (conduction_)
      conduction_->evaluate(fe, T, T_dot, a_, local);
    if (elasticity_)
      elasticity_->evaluate(fe, u, T, body_force_, u_slot_, T_slot_, local);
    add_local(nodes, local);
  }
}

void CoupledProblem::add_boundary_faces()
{
  FaceValues fv;
  LocalSystem local(4, F_);
  std::vector<int> nodes(4);
  std::array<double, 4> T{};
  for (const auto &face : boundary_faces_)
  {
    for (int i = 0; i < 4; ++i)
    {
      nodes[i] = mesh_.connectivity[face.cell][hex_face_nodes[face.face][i]];
      T[i] = T_state_[overlap_index_[nodes[i]]];
    }
    fv.reinit(face_nodes(mesh_, face.cell, face.face));
    local.clear();
    const ThermalBoundaryCondition &bc = bcs_[face.bc];
    if (bc.type() == ThermalBoundaryCondition::Type::convection)
      ConvectionKernel(bc.coefficient()).evaluate(fv, T, bc.value(time_), local);
    else
      HeatFluxKernel::evaluate(fv, bc.value(time_), local);
    add_local(nodes, local);
  }
  for (const auto &face : load_faces_)
  {
    for (int i = 0; i < 4; ++i)
      nodes[i] = mesh_.connectivity[face.cell][hex_face_nodes[face.face][i]];
    fv.reinit(face_nodes(mesh_, face.cell, face.face));
    local.clear();
    const MechanicalBoundaryCondition &bc = mechanical_bcs_[face.bc];
    if (bc.type() == MechanicalBoundaryCondition::Type::traction)
      TractionKernel::evaluate(fv, bc.traction(), u_slot_, local);
    else
      TractionKernel::evaluate_pressure(fv, bc.value(time_), u_slot_, local);
    add_local(nodes, local);
  }
}

void CoupledProblem::add_gap_faces()
{
  if (T_slot_ < 0)
    return;
  FaceValues fv;
  if (contact_conductance_)
  {
    ElementValues fe_a, fe_b;
    std::vector<double> T;
    std::vector<Point> u;
    for (const int k : owned_gap_faces_)
    {
      const GapFace &face = mesh_.gap_faces[k];
      const std::vector<int> nodes = assembler_.gap_face_nodes(k);
      const auto local_of = [&](const int node)
      { return static_cast<int>(std::find(nodes.begin(), nodes.end(), node) - nodes.begin()); };
      std::array<int, 8> cell_a{}, cell_b{};
      for (int i = 0; i < 8; ++i)
      {
        cell_a[i] = local_of(mesh_.connectivity[face.cell_a][i]);
        cell_b[i] = local_of(mesh_.connectivity[face.cell_b][i]);
      }
      T.resize(nodes.size());
      u.resize(nodes.size());
      for (std::size_t i = 0; i < nodes.size(); ++i)
      {
        T[i] = T_state_[overlap_index_[nodes[i]]];
        u[i] = u_state_[overlap_index_[nodes[i]]];
      }
      fv.reinit(face_nodes(mesh_, face.cell_a, face.face_a));
      fe_a.reinit(cell_nodes(mesh_, face.cell_a));
      fe_b.reinit(cell_nodes(mesh_, face.cell_b));
      LocalSystem local(static_cast<int>(nodes.size()), F_);
      contact_conductance_->evaluate(fv, fe_a, fe_b, cell_a, cell_b, T, u, T_slot_, u_slot_, local);
      add_local(nodes, local);
    }
    return;
  }
  LocalSystem local(8, F_);
  std::vector<int> nodes(8);
  std::array<double, 4> T_a{}, T_b{};
  for (const int k : owned_gap_faces_)
  {
    const GapFace &face = mesh_.gap_faces[k];
    for (int i = 0; i < 4; ++i)
    {
      nodes[i] = mesh_.connectivity[face.cell_a][hex_face_nodes[face.face_a][i]];
      nodes[4 + i] = face.node_b[i];
      T_a[i] = T_state_[overlap_index_[nodes[i]]];
      T_b[i] = T_state_[overlap_index_[nodes[4 + i]]];
    }
    fv.reinit(face_nodes(mesh_, face.cell_a, face.face_a));
    local.clear();
    gap_.evaluate(fv, T_a, T_b, local);
    add_local(nodes, local);
  }
}

void CoupledProblem::add_constraint_rows()
{
  const auto x = x_overlap_->getData();
  LocalSystem local(1, 1);
  for (const int n : dofs_.owned_nodes())
  {
    if (T_slot_ >= 0 && dirichlet_bc_[n] >= 0)
    {
      const LO lid = assembler_.lid(dofs_.dof(n, Field::T));
      local.clear();
      local.residual(0, 0) = temperature_scale_[n] * (x[lid] - prescribed_temperature_[n]);
      local.jacobian(0, 0, 0, 0) = temperature_scale_[n];
      assembler_.add({lid}, local);
    }
    if (u_slot_ < 0 || frame_of_node_[n] < 0)
      continue;
    const NodeFrame &frame = frames_[frame_of_node_[n]];
    for (int k = 0; k < frame.n_constrained; ++k)
    {
      const LO lid = assembler_.lid(dofs_.node_dof(n, u_slot_ + k));
      local.clear();
      local.residual(0, 0) = displacement_row_scale_[n] * (x[lid] - frame.prescribed[k]);
      local.jacobian(0, 0, 0, 0) = displacement_row_scale_[n];
      assembler_.add({lid}, local);
    }
  }
}

std::vector<double> CoupledProblem::node_temperatures(const Vector &x)
{
  assembler_.gather(x, *x_overlap_);
  build_state();
  std::vector<double> T;
  for (const int n : dofs_.owned_nodes())
    T.push_back(T_state_[overlap_index_[n]]);
  return T;
}

std::vector<Point> CoupledProblem::node_displacements(const Vector &x)
{
  assembler_.gather(x, *x_overlap_);
  build_state();
  std::vector<Point> u;
  for (const int n : dofs_.owned_nodes())
    u.push_back(u_state_[overlap_index_[n]]);
  return u;
}

std::vector<ElasticityKernel::CellAverages> CoupledProblem::cell_averages(const Vector &x)
{
  KILN_ASSERT(elasticity_, "cell_averages() needs the displacement");
  assembler_.gather(x, *x_overlap_);
  build_state();
  std::vector<ElasticityKernel::CellAverages> result;
  ElementValues fe;
  HeatConductionKernel::NodalValues T{};
  ElasticityKernel::NodalDisplacements u{};
  for (const int c : dofs_.owned_cells())
  {
    for (int i = 0; i < n_hex_nodes; ++i)
    {
      const int k = overlap_index_[mesh_.connectivity[c][i]];
      T[i] = T_state_[k];
      u[i] = u_state_[k];
    }
    fe.reinit(cell_nodes(mesh_, c));
    result.push_back(elasticity_->cell_averages(fe, u, T));
  }
  return result;
}
} // namespace kiln
