#include "physics/coupled_problem.hpp"

#include "base/errors.hpp"
#include "discretization/element_values.hpp"
#include "mesh/hex_geometry.hpp"
#include "physics/mechanics/free_motions.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_TimeMonitor.hpp>

#include <algorithm>
#include <array>
#include <limits>
#include <sstream>

namespace kiln
{
CoupledProblem::CoupledProblem(const Mesh &mesh, const DofManager &dofs, const Material &material,
                               const Teuchos::ParameterList &thermal,
                               const Teuchos::ParameterList &mechanics, const std::string &where)
    : mesh_(mesh), dofs_(dofs), slots_{dofs.layout().slot(Field::T), dofs.layout().slot(Field::ux)},
      constraints_(mesh, dofs)
{
  KILN_ASSERT(slots_.T <= 0, "the temperature must be the first unknown of a node");
  const InteriorFaceCheck interior(mesh);
  if (slots_.T >= 0)
    thermal_.emplace(thermal, material, mesh, dofs.layout(), interior, where + "/Thermal");
  if (slots_.u >= 0)
    mechanics_.emplace(mechanics, material, mesh, interior, where + "/Mechanics");

  // Constraints: the conditions', then the free axes of contact; then the frames are final.
  for (const auto *physics_conditions : {thermal_ ? &thermal_->conditions() : nullptr,
                                         mechanics_ ? &mechanics_->conditions() : nullptr})
    if (physics_conditions != nullptr)
      for (const auto &condition : *physics_conditions)
        condition->add_constraints(mesh, constraints_);
  const double modulus = material.lame_lambda() + 2.0 * material.shear_modulus();
  const Teuchos::ParameterList &contact = mechanics.sublist("Contact");
  if (dofs.layout().contact && mechanics_ && !mesh.gap_pairs.empty())
    interface_ = std::make_unique<ContactInterface>(mesh, dofs, constraints_, modulus,
                                                    contact.get<double>("Complementarity Scale"),
                                                    where + "/Mechanics/Contact");
  const double conductivity = thermal_ ? thermal_->conductivity_scale() : 0.0;
  constraints_.close(conductivity, modulus);
  if (mechanics_)
    check_free_motions(mechanics, where + "/Mechanics");

  // What couples in the Jacobian, and what this rank assembles.
  Couplings couplings;
  const InterfaceKernel *gap = thermal_ ? thermal_->gap_kernel() : nullptr;
  if (gap != nullptr)
    couplings.gap_face_nodes = [&mesh, gap](const int k)
    { return gap->nodes(mesh, mesh.gap_faces[k]); };
  couplings.twins = interface_ != nullptr;
  // The heat equation's cell and boundary terms do not read u (Assembler::add throws if one
  // puts a T-u entry outside the graph); the gap's may.
  couplings.temperature_depends_on_displacement = gap != nullptr && gap->depends_on_displacement();
  assembler_ = std::make_unique<Assembler>(mesh, dofs, couplings);
  if (interface_)
    contact_ =
        std::make_unique<NormalContact>(*interface_, dofs, *assembler_, constraints_, contact);
  fields_ = std::make_unique<NodalFields>(dofs, *assembler_, constraints_,
                                          material.reference_temperature());
  hints_ = std::make_unique<SolverHints>(mesh, dofs, constraints_, conductivity, modulus);

  terms_ = std::make_unique<ResidualTerms>(mesh, dofs, slots_);
  if (thermal_)
  {
    for (const CellKernel *kernel : thermal_->cell_kernels())
      terms_->add_cell_kernel(*kernel);
    terms_->add_boundary_conditions(thermal_->conditions());
    if (gap != nullptr)
      terms_->set_interface_kernel(*gap);
  }
  if (mechanics_)
  {
    for (const CellKernel *kernel : mechanics_->cell_kernels())
      terms_->add_cell_kernel(*kernel);
    terms_->add_boundary_conditions(mechanics_->conditions());
  }

  x_overlap_ = assembler_->make_overlap_vector();
  residual_work_ = Teuchos::rcp(new Vector(dofs.owned_dof_map()));
  constraints_.set_time(0.0);
}

CoupledProblem::~CoupledProblem() = default;

void CoupledProblem::check_free_motions(const Teuchos::ParameterList &mechanics,
                                        const std::string &where)
{
  free_ = std::make_unique<FreeMotions>(mesh_, dofs_, constraints_, interface_ != nullptr);
  const FreeMotions &free = *free_;
  if (free.empty())
    return;
  KILN_CHECK_INPUT(
      mechanics.get<std::string>("Free Motions") == "Minimum Norm", where,
      "the displacement conditions leave rigid motions free, so the displacement is not "
      "determined: "
          << free.description() << ". Add a displacement condition that holds "
          << (free.size() == 1 ? "it" : "them")
          << " (Type \"Normal Displacement\" or \"Displacement\" on a face of the body), or "
             "set Kiln/Mechanics/\"Free Motions\" = \"Minimum Norm\" for the displacement "
             "with no component in them (doc/mechanics.md, \"Free motions\")"
          << (interface_ ? "; contact across the gap holds the two sides together along "
                           "its normal only"
                         : ""));
  free_motions_ = free.basis();
  free_motion_names_ = free.names();
}

void CoupledProblem::set_log(Teuchos::RCP<Teuchos::FancyOStream> out)
{
  if (contact_)
    contact_->monitor().set_log(std::move(out));
}

void CoupledProblem::set_time_derivative(const double time, const double a, const Vector &b)
{
  fields_->set_time_derivative(time, a, b);
  constraints_.set_time(time);
  if (contact_)
  {
    contact_->invalidate();
    contact_->monitor().start_step();
  }
}

void CoupledProblem::freeze_temperature(const Vector *x)
{
  constraints_.hold_temperature(x);
  if (contact_)
    contact_->invalidate();
}

void CoupledProblem::initial_condition(const double time, Vector &x) const
{
  x.putScalar(0.0);
  const auto &owned_nodes = dofs_.owned_nodes();
  const int F = dofs_.n_node_fields();
  for (std::size_t i = 0; i < owned_nodes.size(); ++i)
  {
    const int n = owned_nodes[i];
    const LO row = static_cast<LO>(F * i);
    if (thermal_)
      x.replaceLocalValue(row + slots_.T,
                          constraints_.has_temperature(n)
                              ? constraints_.prescribed_temperature(n, time)
                              : thermal_->initial_temperature(mesh_.coordinates[n]));
    const std::array<double, 3> u_hat = constraints_.prescribed_components(n, time);
    for (int l = 0; l < constraints_.n_constrained(n); ++l)
      x.replaceLocalValue(row + slots_.u + l, u_hat[l]);
  }
}

void CoupledProblem::prepare(const Vector &x)
{
  assembler_->gather(x, *x_overlap_);
  fields_->update(*x_overlap_);
}

void CoupledProblem::decide(const Vector &x)
{
  prepare(x);
  if (contact_->decided_at(x))
    return;
  // The pressure of every pair comes from the assembled rows without contact.
  assemble(residual_work_.get(), nullptr);
  contact_->decide(x, *residual_work_, [this](const int node) { return fields_->u(node); });
}

void CoupledProblem::evaluate(const Vector &x, Vector *f, Matrix *J)
{
  if (!contact_)
  {
    prepare(x);
    assemble(f, J);
    return;
  }
  decide(x);
  if (f != nullptr)
    Tpetra::deep_copy(*f, contact_->residual());
  if (J != nullptr)
  {
    assemble(nullptr, J);
    contact_->jacobian_evaluated();
  }
}

std::vector<double> CoupledProblem::jacobian_dependencies(const Vector &x)
{
  if (!terms_->constant_jacobian())
    return {};
  std::vector<double> d{fields_->a(), constraints_.holds_temperature() ? 1.0 : 0.0};
  if (contact_)
  {
    decide(x);
    const std::vector<double> c = contact_->jacobian_dependencies();
    d.insert(d.end(), c.begin(), c.end());
  }
  return d;
}

bool CoupledProblem::jacobian_with(const std::vector<double> &smooth, const Vector &x, Matrix &J)
{
  if (!terms_->constant_jacobian() || smooth.size() != 1 || (contact_ && !contact_->decided_at(x)))
    return false;
  const double a = fields_->a();
  fields_->set_a(smooth[0]);
  prepare(x);
  assemble(nullptr, &J);
  fields_->set_a(a);
  prepare(x);
  return true;
}

void CoupledProblem::jacobian_kept(const Vector &x)
{
  if (!contact_)
    return;
  decide(x);
  contact_->jacobian_evaluated();
}

void CoupledProblem::assemble(Vector *f, Matrix *J)
{
  const bool jacobian = J != nullptr;
  // One timer per kind of pass: their call counts are the assemblies (doc/architecture.md).
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer(
      jacobian ? "Kiln: 5 assembly (Jacobian)" : "Kiln: 5 assembly (residual)"));
  assembler_->begin(f != nullptr, J);
  terms_->evaluate(*fields_, jacobian,
                   [this](const std::vector<int> &nodes, LocalSystem &local)
                   { add_local(nodes, local); });
  constraints_.add_rows(*x_overlap_, *assembler_, jacobian);
  if (contact_ && jacobian)
    contact_->add_pair_terms(*assembler_);
  assembler_->finish(f, J);
}

void CoupledProblem::add_local(const std::vector<int> &nodes, LocalSystem &local)
{
  if (contact_)
    if (auto extended = contact_->with_twins(nodes, local))
    {
      add_local(extended->first, extended->second);
      return;
    }
  constraints_.distribute(nodes, local);
  if (contact_ && local.has_jacobian())
    contact_->combine_rows(nodes, local);
  assembler_->add(assembler_->node_lids(nodes), local);
}

void CoupledProblem::step_accepted(const double time, const Vector &x)
{
  if (!contact_)
    return;
  decide(x);
  contact_->monitor().step_accepted(time, contact_->active());
  check_open_gap(time);
}

void CoupledProblem::check_open_gap(const double time)
{
  std::vector<FreeMotions::HoldingPair> holding;
  const auto &owned = interface_->owned_pairs();
  for (std::size_t i = 0; i < owned.size(); ++i)
    if (contact_->active()[i])
    {
      const ContactInterface::Pair &pair = interface_->pairs()[owned[i]];
      holding.push_back({pair.a, pair.b, pair.normal});
    }
  const std::string free = free_->more_free_with(holding);
  if (free.empty())
    return;
  std::ostringstream message;
  message << "at t = " << time
          << " s the gap is open where only contact held a body, so the displacement is not "
             "determined (the solution found is one of many): "
          << free
          << ". Hold the body with a displacement condition (doc/mechanics.md, \"Free "
             "motions\")";
  throw RunError(message.str());
}

int CoupledProblem::resume(const double time, const Vector &x)
{
  constraints_.set_time(time);
  if (!contact_)
    return 0;
  decide(x);
  contact_->monitor().resume(contact_->active());
  return contact_->monitor().count(contact_->active());
}

std::vector<double> CoupledProblem::gap_heat_flux(const Vector &x)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> flux(mesh_.n_nodes(), nan);
  if (!thermal_ || mesh_.gap_pairs.empty())
    return flux;
  prepare(x);
  // The gap terms' heat rows at the side-a nodes [W], summed over the ranks.
  std::vector<double> local(mesh_.n_nodes(), 0.0), flow(local.size(), 0.0);
  terms_->evaluate_gap_faces(*fields_, false,
                             [&](const std::vector<int> &nodes, LocalSystem &system)
                             {
                               for (int i = 0; i < 4; ++i)
                                 local[nodes[i]] += system.residual(slots_.T, i);
                             });
  Teuchos::reduceAll(*dofs_.owned_dof_map()->getComm(), Teuchos::REDUCE_SUM,
                     static_cast<int>(local.size()), local.data(), flow.data());
  for (const GapPair &pair : mesh_.gap_pairs)
    flux[pair.node_a] = flux[pair.node_b] = flow[pair.node_a] / pair.area;
  return flux;
}

StateSummary CoupledProblem::summary(const Vector &x)
{
  StateSummary s;
  if (contact_)
  {
    decide(x);
    summarize_contact(*interface_, *contact_, *fields_, *dofs_.owned_dof_map()->getComm(), s);
  }
  else
    prepare(x);
  if (thermal_)
    summarize_temperature(mesh_, dofs_, *fields_, thermal_->conduction().heat_capacity(), s);
  summarize_displacement(dofs_, *fields_, s);
  return s;
}

int CoupledProblem::n_active_pairs(const Vector &x)
{
  if (!contact_)
    return 0;
  decide(x);
  return contact_->monitor().count(contact_->active());
}

CoupledProblem::ContactOutput CoupledProblem::contact_output(const Vector &x)
{
  if (!contact_)
  {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return {std::vector<double>(mesh_.n_nodes(), nan), std::vector<double>(mesh_.n_nodes(), nan)};
  }
  decide(x);
  return contact_->node_values();
}

std::vector<double> CoupledProblem::node_temperatures(const Vector &x)
{
  prepare(x);
  std::vector<double> T;
  for (const int n : dofs_.owned_nodes())
    T.push_back(fields_->T(n));
  return T;
}

std::vector<Point> CoupledProblem::node_displacements(const Vector &x)
{
  prepare(x);
  std::vector<Point> u;
  for (const int n : dofs_.owned_nodes())
    u.push_back(fields_->u(n));
  return u;
}

std::vector<ElasticityKernel::CellAverages> CoupledProblem::cell_averages(const Vector &x)
{
  KILN_ASSERT(mechanics_, "cell_averages() needs the displacement");
  prepare(x);
  std::vector<ElasticityKernel::CellAverages> result;
  ElementValues fe;
  ElasticityKernel::NodalValues T{};
  ElasticityKernel::NodalDisplacements u{};
  for (const int c : dofs_.owned_cells())
  {
    for (int i = 0; i < n_hex_nodes; ++i)
    {
      T[i] = fields_->T(mesh_.connectivity[c][i]);
      u[i] = fields_->u(mesh_.connectivity[c][i]);
    }
    fe.reinit(cell_nodes(mesh_, c));
    result.push_back(mechanics_->elasticity().cell_averages(fe, u, T));
  }
  return result;
}
} // namespace kiln
