#include "physics/residual_terms.hpp"

#include "base/errors.hpp"
#include "discretization/element_values.hpp"
#include "discretization/face_values.hpp"
#include "physics/heat/pair_gap_heat.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <array>
#include <new>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>

namespace kiln
{
namespace internal
{
/// The exception of a term, with the cell or face it was evaluated on; `step_failure`: it was
/// a StepFailure (a smaller step may avoid it).
class TermFailure : public std::runtime_error
{
public:
  TermFailure(const std::string &message, const bool is_step_failure)
      : std::runtime_error(message), step_failure(is_step_failure)
  {
  }
  bool step_failure;
};

/// Runs `evaluate`; an exception (but running out of memory) becomes a TermFailure naming
/// `item()` ("cell 12 (block 2)").
template <typename Evaluate, typename Item> void naming(const Evaluate &evaluate, const Item &item)
{
  try
  {
    evaluate();
  }
  catch (const std::bad_alloc &)
  {
    throw;
  }
  catch (const std::exception &e)
  {
    throw TermFailure(item() + ": " + one_line_library_message(e.what()),
                      dynamic_cast<const StepFailure *>(&e) != nullptr);
  }
}
} // namespace internal

ResidualTerms::ResidualTerms(const Mesh &mesh, const DofManager &dofs, const FieldSlots slots)
    : mesh_(mesh), dofs_(dofs), slots_(slots), owns_cell_(mesh.n_cells(), 0)
{
  for (const int c : dofs.owned_cells())
    owns_cell_[c] = 1;
}

bool ResidualTerms::constant_jacobian() const
{
  for (const CellKernel *kernel : cell_kernels_)
    if (!kernel->constant_jacobian())
      return false;
  for (const BoundaryFace &face : faces_)
    if (!face.condition->constant_jacobian())
      return false;
  // The heat across a pair's gap: nonlinear in T (radiation) and u (the gas term).
  return pair_heat_.empty() &&
         (interface_kernel_ == nullptr || interface_kernel_->constant_jacobian());
}

void ResidualTerms::add_cell_kernel(const CellKernel &kernel)
{
  cell_kernels_.push_back(&kernel);
}

void ResidualTerms::add_boundary_conditions(
    const std::vector<std::unique_ptr<BoundaryCondition>> &conditions)
{
  for (const auto &condition : conditions)
    if (!condition->is_constraint())
    {
      // Two side sets of one condition may share faces: each face takes the condition once.
      std::set<std::pair<int, int>> faces;
      for (const int id : condition->side_sets())
      {
        const SideSet &set = *mesh_.find_side_set(id);
        for (int s = 0; s < set.n_sides(); ++s)
          if (owns_cell_[set.cells[s]] && faces.insert({set.cells[s], set.faces[s]}).second)
            faces_.push_back({set.cells[s], set.faces[s], condition.get()});
      }
    }
}

void ResidualTerms::set_interface_kernel(const InterfaceKernel &kernel)
{
  interface_kernel_ = &kernel;
  for (int k = 0; k < static_cast<int>(mesh_.gap_faces.size()); ++k)
    if (owns_cell_[mesh_.gap_faces[k].cell_a])
    {
      gap_faces_.push_back(k);
      gap_nodes_.push_back(kernel.nodes(mesh_, mesh_.gap_faces[k]));
    }
}

void ResidualTerms::add_pair_heat(const PairGapHeat &heat)
{
  pair_heat_.push_back(&heat);
}

void ResidualTerms::evaluate_pair_heat(const NodalFields &fields, const bool jacobian,
                                       const Sink &sink) const
{
  for (const PairGapHeat *heat : pair_heat_)
    heat->evaluate(fields, slots_, dofs_.n_node_fields(), jacobian, owns_cell_, sink);
}

std::vector<double> ResidualTerms::pair_heat_flow(const NodalFields &fields) const
{
  std::vector<double> local, flow(pair_heat_.size(), 0.0);
  for (const PairGapHeat *heat : pair_heat_)
    local.push_back(heat->heat_flow(fields, slots_, owns_cell_));
  if (!local.empty())
    Teuchos::reduceAll(*dofs_.owned_dof_map()->getComm(), Teuchos::REDUCE_SUM,
                       static_cast<int>(local.size()), local.data(), flow.data());
  return flow;
}

std::vector<double> ResidualTerms::pair_node_heat_flow(const NodalFields &fields) const
{
  const auto n = static_cast<std::size_t>(mesh_.n_nodes());
  std::vector<double> local(n, 0.0), flow(n, 0.0);
  for (const PairGapHeat *heat : pair_heat_)
    heat->add_node_heat_flow(fields, slots_, owns_cell_, local);
  Teuchos::reduceAll(*dofs_.owned_dof_map()->getComm(), Teuchos::REDUCE_SUM, static_cast<int>(n),
                     local.data(), flow.data());
  return flow;
}

void ResidualTerms::evaluate(const NodalFields &fields, const bool jacobian, const Sink &sink) const
{
  // An exception of a term on some ranks must not leave the others waiting in the export that
  // follows: every rank ends its terms, then one reduction decides.
  // A StepFailure stays one (the time stepper cuts the step) if every rank's failure is one.
  std::string failure;
  bool step_failure = false;
  try
  {
    evaluate_cells(fields, jacobian, sink);
    evaluate_faces(fields, jacobian, sink);
    evaluate_gap_faces(fields, jacobian, sink);
  }
  catch (const internal::TermFailure &e)
  {
    const Teuchos::Comm<int> &comm = *dofs_.owned_dof_map()->getComm();
    step_failure = e.step_failure;
    failure = "the assembly of the " + std::string(jacobian ? "Jacobian" : "residual") +
              " failed on rank " + std::to_string(comm.getRank()) + " of " +
              std::to_string(comm.getSize()) + " at " + e.what() +
              (step_failure ? "" : "; every rank stopped");
  }
  check_run_collectively(*dofs_.owned_dof_map()->getComm(), failure.empty(), failure, step_failure);
}

void ResidualTerms::evaluate_cells(const NodalFields &fields, const bool jacobian,
                                   const Sink &sink) const
{
  ElementValues fe;
  LocalSystem local(0, dofs_.n_node_fields(), jacobian);
  std::vector<int> nodes;
  std::array<double, max_cell_nodes> T{}, T_dot{};
  std::array<std::array<double, max_cell_nodes>, 2> T_past{};
  std::array<double, max_cell_nodes> T_old{};
  std::array<Point, max_cell_nodes> u{};
  TemperatureHistory history;
  history.n = fields.n_past();
  for (int k = 0; k < history.n; ++k)
  {
    history.weights[k] = fields.past_weight(k);
    history.T_past[k] = T_past[k].data();
  }
  if (fields.has_accepted())
    history.T_old = T_old.data();
  int cell_local = -1;
  for (const int c : dofs_.owned_cells())
  {
    ++cell_local;
    const Span<const int> cell = mesh_.cell_nodes(c);
    const int n = cell.size();
    // Copied in the loop (a HEX8's 8 ints: assign() would call memmove for each cell).
    nodes.resize(n);
    for (int i = 0; i < n; ++i)
    {
      nodes[i] = cell[i];
      T[i] = fields.T(nodes[i]);
      T_dot[i] = fields.T_dot(nodes[i]);
      u[i] = fields.u(nodes[i]);
      for (int k = 0; k < history.n; ++k)
        T_past[k][i] = fields.T_past(k, nodes[i]);
      if (history.T_old != nullptr)
        T_old[i] = fields.T_accepted(nodes[i]);
    }
    const CellState state{fe,
                          {T.data(), n},
                          {T_dot.data(), n},
                          {u.data(), n},
                          fields.a(),
                          fields.time(),
                          slots_,
                          c,
                          cell_local,
                          history};
    internal::naming(
        [&]
        {
          fe.reinit(mesh_, c);
          local.reset(n);
          for (const CellKernel *kernel : cell_kernels_)
            kernel->evaluate(state, local);
          sink(nodes, local);
        },
        [&] {
          return "cell " + std::to_string(c) + " (block " + std::to_string(mesh_.block_id[c]) + ")";
        });
  }
}

void ResidualTerms::evaluate_faces(const NodalFields &fields, const bool jacobian,
                                   const Sink &sink) const
{
  FaceValues fv;
  LocalSystem local(0, dofs_.n_node_fields(), jacobian);
  std::vector<int> nodes;
  std::array<double, max_cell_nodes> T{};
  std::array<Point, max_cell_nodes> u{};
  for (const BoundaryFace &face : faces_)
  {
    // Mesh::face_nodes()'s nodes, into the reused vector (no allocation per face).
    const std::vector<int> &on_face = mesh_.reference_cell(face.cell).face_nodes(face.face);
    const Span<const int> cell = mesh_.cell_nodes(face.cell);
    const int n = static_cast<int>(on_face.size());
    nodes.resize(on_face.size());
    for (int i = 0; i < n; ++i)
    {
      nodes[i] = cell[on_face[i]];
      T[i] = fields.T(nodes[i]);
      u[i] = fields.u(nodes[i]);
    }
    const FaceState state{fv, {T.data(), n}, {u.data(), n}, fields.time(), slots_};
    internal::naming(
        [&]
        {
          fv.reinit(mesh_, face.cell, face.face);
          local.reset(n);
          face.condition->evaluate(state, local);
          sink(nodes, local);
        },
        [&]
        { return "side " + std::to_string(face.face) + " of cell " + std::to_string(face.cell); });
  }
}

void ResidualTerms::evaluate_gap_faces(const NodalFields &fields, const bool jacobian,
                                       const Sink &sink) const
{
  if (gap_faces_.empty())
    return;
  const InterfaceKernel &kernel = *interface_kernel_;
  FaceValues fv;
  ElementValues fe_a, fe_b;
  std::vector<int> cell_a, cell_b;
  std::vector<double> T;
  std::vector<Point> u;
  for (std::size_t f = 0; f < gap_faces_.size(); ++f)
  {
    const GapFace &face = mesh_.gap_faces[gap_faces_[f]];
    const std::vector<int> &nodes = gap_nodes_[f];
    T.resize(nodes.size());
    u.resize(nodes.size());
    for (std::size_t i = 0; i < nodes.size(); ++i)
    {
      T[i] = fields.T(nodes[i]);
      u[i] = fields.u(nodes[i]);
    }
    internal::naming(
        [&]
        {
          fv.reinit(mesh_, face.cell_a, face.face_a);
          cell_a.clear();
          cell_b.clear();
          if (kernel.needs_cells())
          {
            const auto local_of = [&](const int node)
            {
              const auto at = std::find(nodes.begin(), nodes.end(), node);
              return at == nodes.end() ? -1 : static_cast<int>(at - nodes.begin());
            };
            for (const int node : mesh_.cell_nodes(face.cell_a))
              cell_a.push_back(local_of(node));
            for (const int node : mesh_.cell_nodes(face.cell_b))
              cell_b.push_back(local_of(node));
            fe_a.reinit(mesh_, face.cell_a);
            fe_b.reinit(mesh_, face.cell_b);
          }
          const InterfaceState state{fv, fe_a, fe_b,          cell_a, cell_b,
                                     T,  u,    fields.time(), slots_, {face.cell_a, face.cell_b}};
          LocalSystem local(static_cast<int>(nodes.size()), dofs_.n_node_fields(), jacobian);
          kernel.evaluate(state, local);
          sink(nodes, local);
        },
        [&] { return "gap face " + std::to_string(gap_faces_[f]); });
  }
}
} // namespace kiln
