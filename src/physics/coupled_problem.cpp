#include "physics/coupled_problem.hpp"

#include "base/errors.hpp"
#include "contact/interface_parameters.hpp"
#include "contact/pair_rows_state.hpp"
#include "contact/pair_search_again.hpp"
#include "contact/small_sliding.hpp"
#include "contact/surface_displacement.hpp"
#include "discretization/element_values.hpp"
#include "mesh/hex_geometry.hpp"
#include "physics/heat/pair_gap_heat.hpp"
#include "physics/heat/pair_heat_state.hpp"
#include "physics/mechanics/free_motions.hpp"
#include "physics/mechanics/pairs_held_shut.hpp"
#include "physics/quadrature_state_setup.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_TimeMonitor.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <optional>
#include <sstream>

namespace kiln
{
CoupledProblem::CoupledProblem(const Mesh &mesh, const DofManager &dofs, const Material &material,
                               const Teuchos::ParameterList &thermal,
                               const Teuchos::ParameterList &mechanics, const std::string &where,
                               const MaterialMap *materials,
                               const std::vector<PairingRows> &pairings)
    : mesh_(mesh), dofs_(dofs), slots_{dofs.layout().slot(Field::T), dofs.layout().slot(Field::ux)},
      constraints_(mesh, dofs)
{
  KILN_ASSERT(slots_.T <= 0, "the temperature must be the first unknown of a node");
  const InteriorFaceCheck interior(mesh);
  if (slots_.T >= 0)
    thermal_.emplace(thermal, material, mesh, dofs.layout(), interior, where + "/Thermal",
                     materials);
  if (slots_.u >= 0)
    mechanics_.emplace(mechanics, material, mesh, interior, where + "/Mechanics", materials);

  // Constraints: the conditions', then the free axes of contact; then the frames are final.
  for (const auto *physics_conditions : {thermal_ ? &thermal_->conditions() : nullptr,
                                         mechanics_ ? &mechanics_->conditions() : nullptr})
    if (physics_conditions != nullptr)
      for (const auto &condition : *physics_conditions)
        condition->add_constraints(mesh, constraints_);
  const double T_ref = material.reference_temperature();
  const double modulus = material.lame_lambda(T_ref) + 2.0 * material.shear_modulus(T_ref);
  const Teuchos::ParameterList &contact = mechanics.sublist("Contact");
  // One interface per gap, each of its Kind (Contact/Gaps, else Contact's).
  if (dofs.layout().contact && mechanics_)
    for (std::size_t g = 0; g < mesh.gap_side_sets.size(); ++g)
    {
      // The gap's parameters: Contact's, replaced by its own entry of Contact/Gaps.
      const Teuchos::ParameterList parameters =
          gap_interface_parameters(contact, mesh.gap_side_sets[g]);
      pairings_.push_back(
          std::make_unique<ContactInterface>(mesh, dofs, static_cast<int>(g), modulus,
                                             parameters.get<double>("Complementarity Scale")));
      if (pairings_.back()->n_rows() == 0)
      {
        pairings_.pop_back();
        continue;
      }
      interfaces_.push_back(interface_kinds().create(parameters.get<std::string>("Kind"),
                                                     *pairings_.back(), dofs, constraints_,
                                                     parameters, where + "/Mechanics/Contact"));
    }
  // One interface per pairing of two side sets (rows with weighted partners), after the split
  // gaps. A pairing's nodes (its rows' and their partners) are on no other interface: its rows
  // are written whole, and another interface's would overwrite them (doc/contact.md).
  if (dofs.layout().contact && mechanics_)
  {
    std::vector<std::string> owner_name; // per interface so far
    std::vector<int> first(static_cast<std::size_t>(mesh.n_nodes()), -1);
    const auto visit =
        [&](const std::vector<ContactRow> &rows, const std::string &name, const bool split)
    {
      const int s = static_cast<int>(owner_name.size());
      owner_name.push_back(name);
      for (const ContactRow &row : rows)
        for (std::size_t i = 0; i <= row.partners.size(); ++i)
        {
          const int node = i == 0 ? row.node : row.partners[i - 1];
          int &f = first[node];
          if (f < 0)
            f = s;
          const Point &x = mesh.coordinates[node];
          KILN_CHECK_INPUT(f == s || (split && f < static_cast<int>(pairings_.size())),
                           where + "/Mechanics/Contact",
                           "node " << node << " at (" << x[0] << ", " << x[1] << ", " << x[2]
                                   << ") is on " << owner_name[f] << " and on " << name
                                   << ": a node of a pair between separately meshed bodies "
                                      "cannot be on another pair or gap (the rows of one would "
                                      "overwrite the other's); give the pairs and gaps side sets "
                                      "without common nodes");
        }
    };
    for (const auto &gap : pairings_)
      visit(std::vector<ContactRow>(gap->rows().begin(), gap->rows().end()), gap->name(), true);
    for (const PairingRows &pairing : pairings)
      visit(pairing.rows, pairing.name, false);
  }
  if (dofs.layout().contact && mechanics_)
    for (const PairingRows &pairing : pairings)
    {
      if (pairing.rows.empty())
        continue;
      pairings_.push_back(std::make_unique<ContactInterface>(
          mesh, dofs, pairing.rows, modulus,
          pairing.parameters.get<double>("Complementarity Scale"), pairing.name));
      research_.resize(pairings_.size());
      research_.back() = pairing.research;
      pairing_heat_.resize(pairings_.size());
      if (thermal_)
        pairing_heat_.back() = pairing.heat;
      interfaces_.push_back(interface_kinds().create(
          pairing.parameters.get<std::string>("Kind"), *pairings_.back(), dofs, constraints_,
          pairing.parameters, where + "/Mechanics/Contact (" + pairing.name + ")"));
    }
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
  couplings.partners = !interfaces_.empty();
  // The heat equation's cell and boundary terms do not read u (Assembler::add throws if one
  // puts a T-u entry outside the graph); the gap's may.
  couplings.temperature_depends_on_displacement = gap != nullptr && gap->depends_on_displacement();
  // The heat across the pairs' gaps: a block per cell a search within the margins can make,
  // assembled without partners.
  for (const PairingRows &pairing : pairings)
    if (thermal_ && pairing.heat != nullptr)
    {
      couplings.temperature_depends_on_displacement =
          couplings.temperature_depends_on_displacement || pairing.heat->depends_on_displacement();
      auto blocks = pairing.heat->margin_blocks();
      couplings.cell_blocks.insert(couplings.cell_blocks.end(),
                                   std::make_move_iterator(blocks.begin()),
                                   std::make_move_iterator(blocks.end()));
    }
  assembler_ = std::make_unique<Assembler>(mesh, dofs, couplings);
  if (!interfaces_.empty())
  {
    x_decided_ = Teuchos::rcp(new Vector(dofs.owned_dof_map()));
    F_decided_ = Teuchos::rcp(new Vector(dofs.owned_dof_map()));
    r_overlap_ = assembler_->make_overlap_vector();
  }
  fields_ = std::make_unique<NodalFields>(dofs, *assembler_, constraints_,
                                          material.reference_temperature());
  fields_->keep_history(thermal_ && thermal_->needs_temperature_history());
  hints_ = std::make_unique<SolverHints>(mesh, dofs, constraints_, conductivity, modulus,
                                         material.thermal_expansion(T_ref));

  if (mechanics_ && materials != nullptr)
  {
    // The state of the models at the points of their cells (none if no model has state).
    const BlockElasticityKernel &blocks = mechanics_->block_elasticity();
    std::vector<const ConstitutiveModel *> models;
    for (const ElasticityKernel &kernel : blocks.kernels())
      models.push_back(kernel.model());
    set_quadrature_state(make_quadrature_state(
        models, dofs.owned_cells(),
        [&blocks](const int cell) { return blocks.of_cell(cell).model(); },
        [&mesh](const int cell)
        {
          ElementValues fe;
          fe.reinit(mesh, cell);
          return fe.n_qpoints();
        },
        where + "/Materials"));
  }
  terms_ = std::make_unique<ResidualTerms>(mesh, dofs, slots_);
  if (thermal_)
  {
    for (const CellKernel *kernel : thermal_->cell_kernels())
      terms_->add_cell_kernel(*kernel);
    terms_->add_boundary_conditions(thermal_->conditions());
    if (gap != nullptr)
      terms_->set_interface_kernel(*gap);
    std::size_t pair_index = 0; // among the pairings with rows (each an interface)
    for (const PairingRows &pairing : pairings)
    {
      if (pairing.heat != nullptr)
      {
        pair_heat_.push_back(pairing.heat);
        pair_heat_pair_.push_back(pairing.rows.empty() ? std::size_t(-1) : pair_index);
        terms_->add_pair_heat(*pairing.heat);
      }
      pair_index += pairing.rows.empty() ? 0 : 1;
    }
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

std::vector<FreeMotions::HeldDirection> CoupledProblem::held_directions(const bool all) const
{
  std::vector<FreeMotions::HeldDirection> held;
  for (const auto &strategy : interfaces_)
  {
    const auto h = strategy->held_directions(all);
    held.insert(held.end(), h.begin(), h.end());
  }
  return held;
}

void CoupledProblem::check_free_motions(const Teuchos::ParameterList &mechanics,
                                        const std::string &where)
{
  free_ = std::make_unique<FreeMotions>(mesh_, dofs_, constraints_, held_directions(true));
  minimum_norm_ =
      !interfaces_.empty() && mechanics.get<std::string>("Free Motions") == "Minimum Norm";
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
          << (interfaces_.empty() ? ""
                                  : "; contact across the gap holds the two sides together along "
                                    "its normal only"));
  free_motions_ = free.basis();
  free_motion_names_ = free.names();
}

void CoupledProblem::set_log(Teuchos::RCP<Teuchos::FancyOStream> out)
{
  log_ = out;
  for (const auto &strategy : interfaces_)
    strategy->set_log(out);
}

void CoupledProblem::set_time_derivative(const double time, const double a, const Vector &b)
{
  if (mechanics_)
    mechanics_->block_elasticity().set_time_step(
        std::isnan(accepted_time_) ? 0.0 : std::max(0.0, time - accepted_time_));
  fields_->set_time_derivative(time, a, b);
  constraints_.set_time(time);
  decided_ = false;
  for (const auto &strategy : interfaces_)
    strategy->start_step();
}

void CoupledProblem::set_time_history(const std::vector<double> &weights,
                                      const std::vector<const Vector *> &past)
{
  fields_->set_time_history(weights, past);
}

void CoupledProblem::freeze_temperature(const Vector *x)
{
  constraints_.hold_temperature(x);
  decided_ = false;
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

bool CoupledProblem::decided_at(const Vector &x) const
{
  int same = decided_ ? 1 : 0;
  if (same == 1)
  {
    const auto a = x.getData(), b = x_decided_->getData();
    same = std::equal(a.begin(), a.end(), b.begin()) ? 1 : 0;
  }
  int everywhere = 0;
  Teuchos::reduceAll(*dofs_.owned_dof_map()->getComm(), Teuchos::REDUCE_MIN, same,
                     Teuchos::outArg(everywhere));
  return everywhere == 1;
}

void CoupledProblem::decide(const Vector &x)
{
  prepare(x);
  if (decided_at(x))
    return;
  // The multipliers of every pair come from the assembled rows without interface terms; each
  // strategy reads them and writes the rows of its pairs.
  assemble(residual_work_.get(), nullptr);
  assembler_->gather(*residual_work_, *r_overlap_);
  const auto u = [this](const int node) { return fields_->u(node); };
  for (const auto &strategy : interfaces_)
  {
    if (minimum_norm_)
      strategy->hold_shut({});
    strategy->decide(*assembler_, *r_overlap_, *residual_work_, u);
  }
  if (minimum_norm_) // the bodies held as at set-up while pairs open (doc/contact.md)
    hold_pairs_shut(
        *free_, interfaces_,
        [&](InterfaceStrategy &strategy)
        { strategy.decide(*assembler_, *r_overlap_, *residual_work_, u); },
        *dofs_.owned_dof_map()->getComm());
  Tpetra::deep_copy(*x_decided_, x);
  Tpetra::deep_copy(*F_decided_, *residual_work_);
  decided_ = true;
}

void CoupledProblem::evaluate(const Vector &x, Vector *f, Matrix *J)
{
  if (interfaces_.empty())
  {
    prepare(x);
    assemble(f, J);
    return;
  }
  decide(x);
  if (f != nullptr)
    Tpetra::deep_copy(*f, *F_decided_);
  if (J != nullptr)
  {
    assemble(nullptr, J);
    jacobian_seen();
  }
}

bool CoupledProblem::jacobian_varies() const
{
  return !terms_->constant_jacobian();
}

std::vector<double> CoupledProblem::jacobian_dependencies(const Vector &x)
{
  if (!terms_->constant_jacobian())
    return {};
  return preconditioner_dependencies(x);
}

std::vector<double> CoupledProblem::preconditioner_dependencies(const Vector &x)
{
  std::vector<double> d{fields_->a(), constraints_.holds_temperature() ? 1.0 : 0.0};
  if (!interfaces_.empty())
    decide(x);
  for (const auto &strategy : interfaces_)
  {
    const std::vector<double> c = strategy->jacobian_dependencies();
    d.insert(d.end(), c.begin(), c.end());
  }
  // A pairing searched again has new rows (partners, weights): another Jacobian.
  for (const auto &pairing : pairings_)
    if (!pairing->split())
      d.push_back(pairing->searches());
  return d;
}

bool CoupledProblem::jacobian_with(const std::vector<double> &smooth, const Vector &x, Matrix &J)
{
  if (!terms_->constant_jacobian() || smooth.size() != 1 ||
      (!interfaces_.empty() && !decided_at(x)))
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
  if (interfaces_.empty())
    return;
  decide(x);
  jacobian_seen();
}

void CoupledProblem::jacobian_seen()
{
  // Each strategy sees the Jacobian; one that changes its law (a fallback after an active-set
  // cycle) has the next state decided anew.
  bool changed = false;
  for (const auto &strategy : interfaces_)
    changed = strategy->jacobian_evaluated() || changed;
  if (changed)
    decided_ = false;
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
  terms_->evaluate_pair_heat(*fields_, jacobian,
                             [this](const std::vector<int> &nodes, LocalSystem &local)
                             { distribute_and_add(nodes, local); });
  constraints_.add_rows(*x_overlap_, *assembler_, jacobian);
  if (jacobian)
    for (const auto &strategy : interfaces_)
      strategy->add_terms(*assembler_);
  assembler_->finish(f, J);
}

std::optional<std::pair<std::vector<int>, LocalSystem>>
CoupledProblem::with_partners(const std::vector<int> &nodes, const LocalSystem &local) const
{
  // Most cells have no contact node: no copy of their nodes (an allocation per cell).
  if (std::none_of(nodes.begin(), nodes.end(),
                   [this](const int node)
                   {
                     const auto [begin, end] = dofs_.partners(node);
                     return begin != end;
                   }))
    return std::nullopt;
  std::vector<int> extended_nodes = assembler_->with_partners(nodes);
  if (extended_nodes.size() == nodes.size())
    return std::nullopt;
  const int F = local.n_fields();
  LocalSystem extended(static_cast<int>(extended_nodes.size()), F, local.has_jacobian());
  const int m = local.size();
  for (int i = 0; i < m; ++i)
  {
    extended.residual(i % F, i / F) = local.residual_values()[i];
    if (local.has_jacobian())
      for (int j = 0; j < m; ++j)
        extended.jacobian(i % F, i / F, j % F, j / F) =
            local.jacobian_values()[static_cast<std::size_t>(i) * m + j];
  }
  return std::make_pair(std::move(extended_nodes), std::move(extended));
}

void CoupledProblem::add_local(const std::vector<int> &nodes, LocalSystem &local)
{
  // The twins of the system's own nodes join it (once: not the twins' twins, as the
  // Assembler's coupling blocks).
  if (!interfaces_.empty())
    if (auto extended = with_partners(nodes, local))
    {
      distribute_and_add(extended->first, extended->second);
      return;
    }
  distribute_and_add(nodes, local);
}

void CoupledProblem::distribute_and_add(const std::vector<int> &nodes, LocalSystem &local)
{
  constraints_.distribute(nodes, local);
  if (local.has_jacobian())
    for (const auto &strategy : interfaces_)
      strategy->combine_rows(nodes, local);
  assembler_->add(assembler_->node_lids(nodes), local);
}

void CoupledProblem::step_accepted(const double time, const Vector &x)
{
  // A pairing whose rows have slid beyond the fraction of a face since its last search is
  // searched again in the current configuration, its rows and heat cells (within its
  // margins, else a RunError), before anything is committed. A state refused after a search
  // (another pairing's limit, an open gap) gets the rows and cells back as they were, so
  // that the last accepted state's checkpoint has its own.
  struct Before
  {
    std::size_t pairing;
    std::vector<ContactRow> rows;
    int searches;
    std::optional<PairGapHeat::CellSet> cells;
  };
  std::vector<Before> searched;
  try
  {
    if (std::any_of(pairings_.begin(), pairings_.end(),
                    [](const auto &pairing) { return !pairing->split(); }))
    {
      prepare(x);
      const auto u = [this](const int node) { return fields_->u(node); };
      const auto &comm = *dofs_.owned_dof_map()->getComm();
      for (std::size_t p = 0; p < pairings_.size(); ++p)
      {
        if (pairings_[p]->split() || p >= research_.size() || research_[p] == nullptr)
          continue;
        if (slid_beyond_limit(*pairings_[p], u, comm))
        {
          searched.push_back(
              {p, std::vector<ContactRow>(pairings_[p]->rows().begin(), pairings_[p]->rows().end()),
               pairings_[p]->searches(), std::nullopt});
          if (pairing_heat_[p] != nullptr)
            searched.back().cells = pairing_heat_[p]->cell_set();
          search_again(p, time);
        }
      }
    }
    accepted_time_ = time;
    if (quadrature_state_)
      quadrature_state_->commit();
    if (models_read_old_temperature())
      fields_->set_accepted(x);
    if (interfaces_.empty())
      return;
    decide(x);
    for (const auto &strategy : interfaces_)
      strategy->step_accepted(time);
    check_open_gap(time);
  }
  catch (...)
  {
    for (Before &before : searched)
    {
      pairings_[before.pairing]->replace_rows(std::move(before.rows));
      pairings_[before.pairing]->set_searches(before.searches);
      if (before.cells)
        pairing_heat_[before.pairing]->restore(std::move(*before.cells));
    }
    if (!searched.empty())
      decided_ = false;
    throw;
  }
}

void CoupledProblem::search_again(const std::size_t p, const double time)
{
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("Kiln: contact search again"));
  ContactInterface &pairing = *pairings_[p];
  pairing.replace_rows(search_pair_again(
      pairings_, p, *research_[p], mesh_, [this](const int node) { return fields_->u(node); },
      dofs_.node_owner(), *dofs_.owned_dof_map()->getComm(), time));
  if (pairing_heat_[p] != nullptr)
  {
    // The heat cells on the same search (their u as the rows'; within the margins).
    PairGapHeat &heat = *pairing_heat_[p];
    heat.rebuild(gather_displacement(
                     heat.surface_nodes(), [this](const int node) { return fields_->u(node); },
                     dofs_.node_owner(), *dofs_.owned_dof_map()->getComm()),
                 time, pairing.name());
  }
  decided_ = false;
  if (log_ != Teuchos::null)
    *log_ << "  " << pairing.name() << ": search " << pairing.searches() << " at t = " << time
          << " s (a row slid beyond its \"Search Update Fraction\" since the last search)\n";
}

std::vector<double> CoupledProblem::pair_rows_state() const
{
  return kiln::pair_rows_state(pairings_);
}

void CoupledProblem::restore_pair_rows(const std::vector<double> &state, const std::string &where)
{
  if (kiln::restore_pair_rows(pairings_, state, where))
    decided_ = false;
}

std::vector<double> CoupledProblem::pair_heat_state() const
{
  return kiln::pair_heat_state(pair_heat_);
}

void CoupledProblem::restore_pair_heat(const std::vector<double> &state, const std::string &where)
{
  kiln::restore_pair_heat(pair_heat_, pairings_, pairing_heat_, state, where);
}

bool CoupledProblem::models_read_old_temperature() const
{
  if (!thermal_ || !mechanics_)
    return false; // without a temperature T_old = T = T_ref
  const auto &kernels = mechanics_->block_elasticity().kernels();
  return std::any_of(kernels.begin(), kernels.end(),
                     [](const ElasticityKernel &kernel) { return kernel.general(); });
}

void CoupledProblem::step_rejected()
{
  if (quadrature_state_)
    quadrature_state_->restore();
}

double CoupledProblem::inelastic_strain_increment() const
{
  // Null, or without the component, on every rank alike (one state layout per run).
  if (!quadrature_state_)
    return 0.0;
  const QuadratureState &qs = *quadrature_state_;
  const auto &names = qs.names();
  const auto it = std::find(names.begin(), names.end(), "equivalent_plastic_strain");
  if (it == names.end())
    return 0.0;
  const auto k = static_cast<std::size_t>(it - names.begin());
  double local = 0.0;
  for (int c = 0; c < qs.n_cells(); ++c)
    for (int q = 0; q < qs.n_points(c); ++q)
      local = std::max(local, qs.current(c, q)[k] - qs.old(c, q)[k]);
  double global = 0.0;
  Teuchos::reduceAll(*solution_map()->getComm(), Teuchos::REDUCE_MAX, local,
                     Teuchos::outArg(global));
  return global;
}

void CoupledProblem::to_minimum_norm(Vector &x)
{
  if (!minimum_norm_)
    return;
  decide(x);
  shift_to_minimum_norm(*free_, interfaces_, x);
}

void CoupledProblem::check_open_gap(const double time)
{
  const std::string free = free_->more_free_with(held_directions(false));
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
  // The checkpoint's time is that of its last accepted step: the models' next time step
  // starts there (without it the first step after a restart would have dt = 0, no flow).
  accepted_time_ = time;
  constraints_.set_time(time);
  if (models_read_old_temperature())
    fields_->set_accepted(x);
  if (interfaces_.empty())
    return 0;
  decide(x);
  int active = 0;
  for (const auto &strategy : interfaces_)
  {
    strategy->resume();
    active += strategy->count_active();
  }
  return active;
}

StateOutput CoupledProblem::output() const
{
  return StateOutput(mesh_, dofs_, slots_, *fields_, thermal_ ? &*thermal_ : nullptr,
                     mechanics_ ? &*mechanics_ : nullptr, *terms_, interfaces_);
}

std::vector<double> CoupledProblem::gap_heat_flow(const Vector &x)
{
  if (thermal_ && !mesh_.gap_pairs.empty())
    prepare(x);
  return output().gap_heat_flow();
}

std::vector<double> CoupledProblem::pair_heat_flow(const Vector &x)
{
  if (!pair_heat_.empty())
    prepare(x);
  return terms_->pair_heat_flow(*fields_);
}

std::vector<double> CoupledProblem::pair_node_heat_flow(const Vector &x)
{
  if (!pair_heat_.empty())
    prepare(x);
  return terms_->pair_node_heat_flow(*fields_);
}

StateSummary CoupledProblem::summary(const Vector &x)
{
  if (!interfaces_.empty())
    decide(x);
  else
    prepare(x);
  StateSummary s = output().summary();
  if (!pair_heat_.empty())
  {
    const std::vector<double> flow = terms_->pair_heat_flow(*fields_);
    for (std::size_t h = 0; h < flow.size(); ++h)
      if (pair_heat_pair_[h] < s.pairs.size())
        s.pairs[pair_heat_pair_[h]].heat_flow = flow[h];
  }
  return s;
}

int CoupledProblem::n_pairs() const
{
  int n = 0;
  for (const auto &pairing : pairings_)
    n += pairing->n_rows();
  return n;
}

int CoupledProblem::n_active_pairs(const Vector &x)
{
  if (interfaces_.empty())
    return 0;
  decide(x);
  int active = 0;
  for (const auto &strategy : interfaces_)
    active += strategy->count_active();
  return active;
}

CoupledProblem::ContactOutput CoupledProblem::contact_output(const Vector &x)
{
  if (!interfaces_.empty())
    decide(x);
  return output().contact_output();
}

std::vector<double> CoupledProblem::node_temperatures(const Vector &x)
{
  prepare(x);
  return output().node_temperatures();
}

std::vector<Point> CoupledProblem::node_displacements(const Vector &x)
{
  prepare(x);
  return output().node_displacements();
}

std::vector<ElasticityKernel::CellAverages> CoupledProblem::cell_averages(const Vector &x)
{
  prepare(x);
  return output().cell_averages();
}

std::vector<ElasticityKernel::PointAverages> CoupledProblem::point_averages(const Vector &x)
{
  prepare(x);
  return output().point_averages();
}
} // namespace kiln
