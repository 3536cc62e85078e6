#pragma once
/// Heat conduction and quasi-static thermo-elasticity with contact on the split mesh, in one
/// residual and one Jacobian, as a TransientProblem for the Newton solver and the time
/// stepper.
#include "contact/contact_interface.hpp"
#include "contact/interface_strategy.hpp"
#include "contact/pair_research.hpp"
#include "contact/pairing_rows.hpp"
#include "discretization/assembler.hpp"
#include "discretization/nodal_constraints.hpp"
#include "discretization/nonlinear_problem.hpp"
#include "discretization/quadrature_state.hpp"
#include "physics/heat/thermal_physics.hpp"
#include "physics/mechanics/free_motions.hpp"
#include "physics/mechanics/mechanical_physics.hpp"
#include "physics/nodal_fields.hpp"
#include "physics/residual_terms.hpp"
#include "physics/state_output.hpp"
#include "physics/state_summary.hpp"
#include "solvers/solver_hints.hpp"

#include <Teuchos_FancyOStream.hpp>
#include <Teuchos_ParameterList.hpp>

#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace kiln
{
/// F(x) = 0 for the unknowns of the DofManager's layout: temperature, displacement or both
/// (4 per node: T, then u_x, u_y, u_z). It owns the pieces and runs, for each evaluation,
///   gather x -> fields at x~ (NodalFields, NodalConstraints) -> the interfaces decide (once
///   per x) -> terms per cell, boundary face, gap face (ResidualTerms) -> distribute (frames,
///   constraints: NodalConstraints; interface rows: each InterfaceStrategy) -> add
///   (Assembler); constraint rows; the interfaces' terms.
/// The terms and their Jacobians are the kernels' (ThermalPhysics, MechanicalPhysics); the
/// constraints are NodalConstraints'; the gap's conditions are its interface strategies'
/// (the kinds of interface_kinds(); doc/architecture.md).
class CoupledProblem final : public TransientProblem
{
public:
  /// `thermal` and `mechanics` have been validated against ThermalPhysics and
  /// MechanicalPhysics::valid_parameters(); each is read if the layout has its field.
  /// `where` names the root in messages ("in.xml: Kiln"). With `materials` (read during
  /// the construction), the mechanics takes each block's material and model (MechanicalPhysics)
  /// and, if a model has state, the problem makes its QuadratureState; the heat equation and the
  /// scales take `material`. `pairings`: the rows of the pairings of two side sets, each an
  /// interface of its own Kind besides the split gaps' (the DofManager was built with their
  /// partner_links()).
  CoupledProblem(const Mesh &mesh, const DofManager &dofs, const Material &material,
                 const Teuchos::ParameterList &thermal, const Teuchos::ParameterList &mechanics,
                 const std::string &where, const MaterialMap *materials = nullptr,
                 const std::vector<PairingRows> &pairings = {});
  ~CoupledProblem() override;

  Teuchos::RCP<const Map> solution_map() const override { return dofs_.owned_dof_map(); }
  Teuchos::RCP<const Graph> jacobian_graph() const override { return assembler_->owned_graph(); }
  Teuchos::RCP<const Tpetra::MultiVector<double>> node_coordinates() const override
  {
    return hints_->coordinates();
  }
  Teuchos::RCP<const Tpetra::MultiVector<double>> near_null_space() const override
  {
    return hints_->near_null_space();
  }
  Teuchos::RCP<const Vector> unknown_scale() const override { return hints_->unknown_scale(); }
  /// With Mechanics/"Free Motions" = "Minimum Norm": the free rigid motions (FreeMotions).
  Teuchos::RCP<const Tpetra::MultiVector<double>> free_motions() const override
  {
    return free_motions_;
  }
  std::vector<std::string> free_motion_names() const override { return free_motion_names_; }
  /// With "Free Motions" = "Minimum Norm" and interfaces: shift_to_minimum_norm().
  void to_minimum_norm(Vector &x) override;
  Teuchos::RCP<const Vector> time_error_mask() const override { return hints_->time_error_mask(); }
  void evaluate(const Vector &x, Vector *f, Matrix *J) override;
  /// With terms whose Jacobians are all constant (ResidualTerms::constant_jacobian()): a,
  /// whether the temperature is held (freeze_temperature()), the contact decision's
  /// (InterfaceStrategy::jacobian_dependencies()) and the count of searches of each pairing
  /// (its rows); otherwise none.
  std::vector<double> jacobian_dependencies(const Vector &x) override;
  /// Whether some term's Jacobian is not constant (ResidualTerms::constant_jacobian()).
  bool jacobian_varies() const override;
  /// a, whether the temperature is held, the contact decision's and the pairings' searches,
  /// whatever the terms (the dependencies above of a problem with varying terms: viscoplastic
  /// flow, E(T), k(T)).
  std::vector<double> preconditioner_dependencies(const Vector &x) override;
  /// a, the first of the dependencies.
  std::size_t smooth_dependencies() const override { return 1; }
  /// With terms whose Jacobians are all constant: J at x with a = smooth[0], the contact
  /// decision taken at x kept (false if none was taken at x).
  bool jacobian_with(const std::vector<double> &smooth, const Vector &x, Matrix &J) override;
  /// The contact monitor sees the active set as after an evaluation.
  void jacobian_kept(const Vector &x) override;
  void set_time_derivative(double time, double a, const Vector &b) override;
  /// Keeps the past temperatures if a heat kernel reads them (NodalFields::keep_history).
  void set_time_history(const std::vector<double> &weights,
                        const std::vector<const Vector *> &past) override;
  /// Redoes the search of the pairings whose rows slid beyond their limit (their rows and
  /// heat cells; a RunError on every rank beyond the small-sliding limit, before anything is
  /// committed, the rows and cells as they were), commits the quadrature-point state
  /// (QuadratureState::commit), keeps the temperatures of x for the models' T at t_n
  /// (NodalFields::set_accepted, if a model reads it), then the interfaces' hooks.
  void step_accepted(double time, const Vector &x) override;
  /// Restores the quadrature-point state (QuadratureState::restore).
  void step_rejected() override;
  /// The largest current - old of the state component "equivalent_plastic_strain" over the
  /// owned points, reduced over the ranks (0 without it). Collective.
  double inelastic_strain_increment() const override;

  /// The state at the quadrature points of the owned cells (make_quadrature_state), or null
  /// if no model has state (then nothing is kept, committed or written). The models that
  /// read and write it during the assembly are the kernels'; set at set-up, before the
  /// first solve. What step_accepted() commits is what the last assembly wrote: NOX's last
  /// residual evaluation is at the solution it returns (up to the free-motion projection,
  /// a rigid motion, which leaves the strains as they were).
  void set_quadrature_state(std::unique_ptr<QuadratureState> state)
  {
    quadrature_state_ = std::move(state);
    if (mechanics_)
      mechanics_->block_elasticity().set_state(quadrature_state_.get());
  }
  QuadratureState *quadrature_state() { return quadrature_state_.get(); }
  const QuadratureState *quadrature_state() const { return quadrature_state_.get(); }

  /// Log lines (active-set changes, the gap closing or opening) go to `out`.
  void set_log(Teuchos::RCP<Teuchos::FancyOStream> out);
  /// With a state x, holds every temperature at its value in x (rows T - T_x) for an
  /// equilibrium solve of the displacement at fixed temperature; with nullptr, releases it.
  void freeze_temperature(const Vector *x);
  /// A run goes on from the saved state x (a checkpoint) at `time`: the contact monitor
  /// starts from its active set, and `time` and x are the last accepted step's (the
  /// constitutive models' next time step starts there, from its temperature). Returns the
  /// pairs in contact. Collective.
  int resume(double time, const Vector &x);
  /// The rows of the pairs whose search was redone during the run (doc/contact.md, "Small
  /// sliding"), flattened for a checkpoint (the same on every rank): per pairing, its count of
  /// searches and its rows' partners, weights, areas, g0 and slip0, so that a restart
  /// rebuilds the same rows. Empty without pairings.
  std::vector<double> pair_rows_state() const;
  /// Restores the rows of pair_rows_state() (a restart, before resume()). Throws InputError
  /// naming `where` (the checkpoint) if they do not fit this run's pairings.
  void restore_pair_rows(const std::vector<double> &state, const std::string &where);
  /// The displacement of the surfaces of each pair with a heat term at its last search
  /// (PairGapHeat::searched_displacement), flattened for a checkpoint (the same on every
  /// rank): per term, its count of values, then u. Empty without such pairs.
  std::vector<double> pair_heat_state() const;
  /// Rebuilds the heat cells of pair_heat_state() (a restart, after restore_pair_rows()):
  /// the cells in force at the checkpoint. A checkpoint without it (`state` empty, of an
  /// older Kiln) is taken as the set-up cells if no pair with a heat term was searched again,
  /// else an InputError naming `where`, as for a state that does not fit.
  void restore_pair_heat(const std::vector<double> &state, const std::string &where);
  /// x = the initial state at time t [s]: the initial temperature, zero displacement, and
  /// the prescribed values of that time.
  void initial_condition(double time, Vector &x) const;

  // The state at x, for output and tests (collective): the state prepared at x (and with
  // interfaces decided), then its values from StateOutput.
  /// Physical values of the owned nodes (DofManager::owned_nodes() order), with the
  /// prescribed values of the last set time where constrained.
  std::vector<double> node_temperatures(const Vector &x);
  std::vector<Point> node_displacements(const Vector &x);
  /// Volume averages over each owned cell (owned_cells() order).
  std::vector<ElasticityKernel::CellAverages> cell_averages(const Vector &x);
  /// Per owned cell: averages of σ, ε, the von Mises stress and the plastic strain and rate
  /// at the step's end (the state being computed, which the last step accepted).
  std::vector<ElasticityKernel::PointAverages> point_averages(const Vector &x);
  /// Contact per mesh node, on every rank: the normal traction across the gap (-p, negative
  /// in compression) [Pa] and 1/0 for pairs in contact; NaN off the gap. A node where gaps
  /// cross shows its pair of the first gap (Mesh::gap_side_sets order). pair_traction and
  /// pair_active: the same per pair of Mesh::gap_pairs (NaN for a gap without interface).
  using ContactOutput = StateOutput::ContactOutput;
  ContactOutput contact_output(const Vector &x);
  /// The heat across the gap at x per pair of Mesh::gap_pairs, on every rank: what the gap
  /// faces of the pair's gap carry from its node a to side b (negative: heat flows from b to
  /// a) [W]; divided by the pair's area, the gap_heat_flux [W/m^2]. NaN without temperature.
  std::vector<double> gap_heat_flow(const Vector &x);
  /// The heat across the gap at x of each contact pair with a Heat Transfer term on (in the
  /// input's order of the pairs), from the secondary to the primary side, on every rank [W].
  /// Collective.
  std::vector<double> pair_heat_flow(const Vector &x);
  /// The heat across the pairs' gaps at x at each node of their secondary surfaces,
  /// Σ_q w_q N_i(xi_s) q over the cells of node i, secondary to primary side, per mesh node and
  /// on every rank (0 off those surfaces and on pairs without heat transfer) [W]; divided by
  /// the node's share of the surface's area, the gap_heat_flux [W/m^2]. Collective.
  std::vector<double> pair_node_heat_flow(const Vector &x);
  /// The figures of the state x for a time history.
  StateSummary summary(const Vector &x);
  /// Pairs in contact at x (global), and of all pairs.
  int n_active_pairs(const Vector &x);
  int n_pairs() const;
  bool has_contact() const { return !interfaces_.empty(); }
  /// The scale c of the displacement unknowns (the solver sees x / c; doc/mechanics.md).
  double displacement_scale() const { return hints_->displacement_scale(); }
  const NodalConstraints &constraints() const { return constraints_; }

private:
  /// The directions the interfaces hold on this rank (InterfaceStrategy::held_directions):
  /// with `all`, every one their pairs can hold; else those of the last decision.
  std::vector<FreeMotions::HeldDirection> held_directions(bool all) const;
  /// The free rigid motions (FreeMotions): an InputError naming them unless Mechanics/"Free
  /// Motions" is "Minimum Norm", which keeps them for the solver. Collective.
  void check_free_motions(const Teuchos::ParameterList &mechanics, const std::string &where);
  /// With contact, at an accepted state: a RunError if the pairs not in contact leave a body
  /// free that the set-up counted as held by them (the result would be arbitrary). Collective.
  void check_open_gap(double time);
  /// Whether a constitutive model gets T at t_n (PointInput::temperature_old): a temperature
  /// and a block on the general path of the elasticity kernel.
  bool models_read_old_temperature() const;
  /// x into the overlap and the nodal fields at x~.
  void prepare(const Vector &x);
  /// With interfaces: the assembled rows at x and their decisions, unless taken at x already.
  void decide(const Vector &x);
  /// A Jacobian was evaluated from the last decision (InterfaceStrategy::jacobian_evaluated()).
  void jacobian_seen();
  /// Whether the interfaces decided at x (and nothing has changed since). Collective.
  bool decided_at(const Vector &x) const;
  /// With interfaces, a local system that holds a contact node holds its partners (twins across
  /// a gap, a pairing's row node and partners): `nodes` with the partners it lacks appended and
  /// `local` extended alike (their rows and columns zero), or nothing if it lacks none.
  std::optional<std::pair<std::vector<int>, LocalSystem>>
  with_partners(const std::vector<int> &nodes, const LocalSystem &local) const;
  /// One assembly of f and/or J at the prepared state (with J and contact: combined rows).
  void assemble(Vector *f, Matrix *J);
  /// Distributes a local system (nodes[i]: the mesh node of local node i) and adds it, with
  /// the twins of its gap nodes.
  void add_local(const std::vector<int> &nodes, LocalSystem &local);
  void distribute_and_add(const std::vector<int> &nodes, LocalSystem &local);
  /// The output quantities of the state the fields hold (after prepare() or decide()).
  StateOutput output() const;

  const Mesh &mesh_;
  const DofManager &dofs_;
  FieldSlots slots_;
  NodalConstraints constraints_;
  std::optional<ThermalPhysics> thermal_;
  std::optional<MechanicalPhysics> mechanics_;
  std::vector<std::unique_ptr<ContactInterface>>
      pairings_; ///< per gap with pairs, then per pairing
  /// Per entry of pairings_, the search redone during the run, or null (a split gap, or a
  /// test's pairing whose rows are fixed).
  std::vector<std::shared_ptr<const PairResearch>> research_;
  Teuchos::RCP<Teuchos::FancyOStream> log_;
  /// Redoes the search of pairings_[p] at the accepted state the fields hold (time [s]).
  void search_again(std::size_t p, double time);
  /// The heat across the pairs' gaps (those with a term on), kept for terms_.
  std::vector<std::shared_ptr<PairGapHeat>> pair_heat_;
  /// Per entry of pairings_, the heat across its gap (an entry of pair_heat_), or null.
  std::vector<std::shared_ptr<PairGapHeat>> pairing_heat_;
  /// Per term of pair_heat_, its pair's index in StateSummary::pairs.
  std::vector<std::size_t> pair_heat_pair_;
  std::unique_ptr<Assembler> assembler_;
  /// The strategies across the gap (today one, the Contact/"Kind"), and their decision.
  std::vector<std::unique_ptr<InterfaceStrategy>> interfaces_;
  bool decided_ = false;
  Teuchos::RCP<Vector> x_decided_; ///< the x it was taken at
  Teuchos::RCP<Vector> F_decided_; ///< F(x)
  Teuchos::RCP<Vector> r_overlap_; ///< the assembled rows without interface terms (overlap)
  std::unique_ptr<NodalFields> fields_;
  std::unique_ptr<SolverHints> hints_;
  std::unique_ptr<ResidualTerms> terms_;
  Teuchos::RCP<Vector> x_overlap_;
  Teuchos::RCP<Vector> residual_work_;
  std::unique_ptr<FreeMotions> free_; ///< with mechanics
  /// "Free Motions" = "Minimum Norm" with interfaces: open pairs are held shut where the
  /// bodies would be freer than at set-up (hold_pairs_shut()).
  bool minimum_norm_ = false;
  Teuchos::RCP<const Tpetra::MultiVector<double>> free_motions_; ///< Minimum Norm's
  std::vector<std::string> free_motion_names_;
  std::unique_ptr<QuadratureState> quadrature_state_; ///< null: no model with state
  /// The time of the last accepted step (NaN before one): Δt of the next.
  double accepted_time_ = std::numeric_limits<double>::quiet_NaN();
};
} // namespace kiln
