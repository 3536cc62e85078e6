#include "physics/nodal_fields.hpp"

#include "base/errors.hpp"

namespace kiln
{
NodalFields::NodalFields(const DofManager &dofs, const Assembler &assembler,
                         const NodalConstraints &constraints, const double reference_temperature)
    : dofs_(dofs), assembler_(assembler), constraints_(constraints), F_(dofs.n_node_fields()),
      T_slot_(dofs.layout().slot(Field::T)), u_slot_(dofs.layout().slot(Field::ux)),
      reference_temperature_(reference_temperature), overlap_index_(dofs.node_owner().size(), -1),
      b_overlap_(assembler.make_overlap_vector())
{
  const auto &overlap_nodes = dofs.overlap_nodes();
  for (std::size_t i = 0; i < overlap_nodes.size(); ++i)
  {
    overlap_index_[overlap_nodes[i]] = static_cast<int>(i);
    KILN_ASSERT(assembler.lid(dofs.node_dof(overlap_nodes[i], 0)) == static_cast<LO>(F_ * i),
                "the overlap map is not node-major");
  }
  T_.assign(overlap_nodes.size(), reference_temperature);
  T_dot_.assign(overlap_nodes.size(), 0.0);
  u_.assign(overlap_nodes.size(), Point{});
}

void NodalFields::set_time_derivative(const double time, const double a, const Vector &b)
{
  time_ = time;
  a_ = a;
  assembler_.gather(b, *b_overlap_);
  weights_.clear();
}

void NodalFields::set_time_history(const std::vector<double> &weights,
                                   const std::vector<const Vector *> &past)
{
  weights_.clear();
  if (!keep_history_ || T_slot_ < 0)
    return;
  KILN_ASSERT(weights.size() == past.size() && past.size() <= 2,
              "a time history of " << past.size() << " states");
  if (past_overlap_.is_null())
    past_overlap_ = assembler_.make_overlap_vector();
  T_past_.resize(past.size());
  for (std::size_t k = 0; k < past.size(); ++k)
  {
    assembler_.gather(*past[k], *past_overlap_);
    const auto x = past_overlap_->getData();
    T_past_[k].resize(T_.size());
    for (std::size_t i = 0; i < T_.size(); ++i)
      T_past_[k][i] = x[F_ * i + T_slot_];
  }
  weights_ = weights;
}

void NodalFields::set_accepted(const Vector &x)
{
  if (T_slot_ < 0)
    return;
  if (past_overlap_.is_null())
    past_overlap_ = assembler_.make_overlap_vector();
  assembler_.gather(x, *past_overlap_);
  const auto values = past_overlap_->getData();
  const auto &overlap_nodes = dofs_.overlap_nodes();
  T_accepted_.resize(overlap_nodes.size());
  for (std::size_t i = 0; i < overlap_nodes.size(); ++i)
    T_accepted_[i] = constraints_.temperature(overlap_nodes[i], values.getRawPtr() + F_ * i);
}

void NodalFields::update(const Vector &x_overlap)
{
  const auto x = x_overlap.getData();
  const auto b = b_overlap_->getData();
  const auto &overlap_nodes = dofs_.overlap_nodes();
  for (std::size_t i = 0; i < overlap_nodes.size(); ++i)
  {
    const int n = overlap_nodes[i];
    const double *unknowns = x.getRawPtr() + F_ * i;
    if (T_slot_ >= 0)
    {
      T_[i] = constraints_.temperature(n, unknowns);
      T_dot_[i] = a_ * T_[i] + b[F_ * i + T_slot_];
    }
    else
      T_[i] = reference_temperature_;
    if (u_slot_ >= 0)
      u_[i] = constraints_.displacement(n, unknowns);
  }
}
} // namespace kiln
