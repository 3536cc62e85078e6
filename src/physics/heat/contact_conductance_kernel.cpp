#include "physics/heat/contact_conductance_kernel.hpp"

#include "base/errors.hpp"
#include "contact/gap_opening.hpp"
#include "physics/materials/material_map.hpp"

#include <algorithm>
#include <cmath>
#include <set>

namespace kiln
{
namespace
{
/// The Voigt index of tensor component (d, k).
constexpr int voigt_index[3][3] = {{0, 3, 4}, {3, 1, 5}, {4, 5, 2}};

/// One side of the gap: the contribution of its cell to p = (p_a + p_b)/2 and to dp/du, dp/dT
/// per local node, point by point (doc/contact.md, "Contact Dependent with materials").
class SidePressure
{
public:
  SidePressure(const Point &normal, const std::vector<Point> &u, const std::vector<double> &T,
               std::vector<Point> &dp_du, std::vector<double> &dp_dT)
      : u_(u), T_(T), dp_du_(dp_du), dp_dT_(dp_dT)
  {
    // n.σ n = m . σ in Voigt form (shear components counted twice).
    for (int d = 0; d < 3; ++d)
      for (int k = 0; k < 3; ++k)
        m_[voigt_index[d][k]] += normal[d] * normal[k];
  }

  /// Adds −(w/2) n.σ n of a point where the cell's node j (local node cell[j]) has the shape
  /// value phi[j] and gradient grad[j], σ the model's at the point's ε and T.
  void add_point(const ConstitutiveModel &model, const double w, const Span<const int> cell,
                 const double *phi, const Point *grad)
  {
    const int n = cell.size();
    PointInput in;
    std::array<std::array<double, 3>, 3> grad_u{};
    for (int j = 0; j < n; ++j)
    {
      const int l = cell[j];
      in.temperature += phi[j] * T_[l];
      for (int d = 0; d < 3; ++d)
        for (int k = 0; k < 3; ++k)
          grad_u[d][k] += u_[l][d] * grad[j][k];
    }
    for (int d = 0; d < 3; ++d)
      for (int k = d; k < 3; ++k)
        in.strain[voigt_index[d][k]] = 0.5 * (grad_u[d][k] + grad_u[k][d]);
    in.temperature_old = in.temperature;
    PointResponse r;
    model.evaluate(in, nullptr, nullptr, r);
    const double s = -0.5 * w;
    // v = m^T C: d(m.σ)/dε_J; dT = m . ∂σ/∂T.
    Voigt v{};
    double dT = 0.0;
    for (int I = 0; I < 6; ++I)
    {
      pressure_ += s * m_[I] * r.stress[I];
      dT += m_[I] * r.stress_temperature_derivative[I];
      for (int J = 0; J < 6; ++J)
        v[J] += m_[I] * r.tangent[I][J];
    }
    for (int j = 0; j < n; ++j)
    {
      const int l = cell[j];
      const Point &g = grad[j];
      // ∂ε_dk/∂u_{j,e} = (δ_de g_k + δ_ke g_d) / 2 (tensor shear strains).
      for (int e = 0; e < 3; ++e)
      {
        double value = v[e] * g[e];
        for (int k = 0; k < 3; ++k)
          if (k != e)
            value += 0.5 * v[voigt_index[e][k]] * g[k];
        dp_du_[l][e] += s * value;
      }
      dp_dT_[l] += s * dT * phi[j];
    }
  }

  /// The sum of the points' −(w/2) n.σ n so far [Pa].
  double pressure() const { return pressure_; }

private:
  double pressure_ = 0.0;
  Voigt m_{};
  const std::vector<Point> &u_;
  const std::vector<double> &T_;
  std::vector<Point> &dp_du_;
  std::vector<double> &dp_dT_;
};
} // namespace

ContactConductanceKernel::ContactConductanceKernel(
    const Parameters &p, const Mesh &mesh,
    std::vector<std::shared_ptr<const ConstitutiveModel>> models, std::map<int, int> model_of_block)
    : p_(p), models_(std::move(models)),
      model_of_cell_(mesh, std::move(model_of_block), static_cast<int>(models_.size()))
{
  KILN_ASSERT(std::all_of(models_.begin(), models_.end(),
                          [](const auto &model)
                          { return model != nullptr && model->n_state() == 0; }),
              "the contact conductance takes models without state");
}

ContactConductanceKernel
ContactConductanceKernel::for_materials(const Parameters &p, const Material &material,
                                        const Mesh &mesh, const MaterialMap *materials,
                                        const std::vector<int> &cells, const std::string &parameter,
                                        const std::string &asked_by, const std::string &remedy)
{
  std::vector<std::shared_ptr<const ConstitutiveModel>> models;
  std::map<int, int> model_of_block;
  if (materials == nullptr)
    models.push_back(material.mechanical_model());
  else
  {
    for (int i = 0; i < materials->n_materials(); ++i)
      models.push_back(materials->material(i).mechanical_model());
    for (const int block : mesh.block_ids())
      model_of_block[block] = materials->index_of_block(block);
  }
  std::set<int> at_gap;
  for (const int cell : cells)
    if (cell >= 0)
      at_gap.insert(materials != nullptr ? model_of_block.at(mesh.block_id[cell]) : 0);
  for (const int i : at_gap)
    KILN_CHECK_INPUT(models[i]->n_state() == 0, parameter,
                     asked_by << ", whose contact pressure takes the stress of the cells beside "
                                 "the gap from their material's elastic law, but material \""
                              << (materials != nullptr ? materials->name(i) : "Material")
                              << "\" beside the gap has a viscoplastic Model, whose stress needs "
                                 "the state at its quadrature points, which the gap's terms do "
                                 "not read; "
                              << remedy);
  return ContactConductanceKernel(p, mesh, std::move(models), std::move(model_of_block));
}

std::vector<int> ContactConductanceKernel::nodes(const Mesh &mesh, const GapFace &face) const
{
  std::vector<int> result = InterfaceKernel::nodes(mesh, face);
  for (const int c : {face.cell_a, face.cell_b})
    for (const int n : mesh.cell_nodes(c))
      if (std::find(result.begin(), result.end(), n) == result.end())
        result.push_back(n);
  return result;
}

void ContactConductanceKernel::evaluate(const InterfaceState &state, LocalSystem &local) const
{
  evaluate(state.fv, state.fe_a, state.fe_b, state.cell_a, state.cell_b, state.cells, state.T,
           state.u, state.slots.T, state.slots.u, local);
}

double ContactConductanceKernel::conductance(const double g, const double p) const
{
  return p_.h0 * p_.length / (p_.length + std::max(g, 0.0)) +
         p_.pressure_coefficient * std::max(p, 0.0);
}

double ContactConductanceKernel::conductance_pressure_derivative(const double p) const
{
  return p > 0.0 ? p_.pressure_coefficient : 0.0;
}

double ContactConductanceKernel::pressure(const Point &normal, const ElementValues &fe_a,
                                          const ElementValues &fe_b, const Span<const int> cell_a,
                                          const Span<const int> cell_b,
                                          const std::array<int, 2> &cells,
                                          const std::vector<double> &T, const std::vector<Point> &u,
                                          std::vector<Point> &dp_du,
                                          std::vector<double> &dp_dT) const
{
  SidePressure side(normal, u, T, dp_du, dp_dT);
  std::vector<double> mean_phi;
  std::vector<Point> mean_grad;
  const auto add_cell = [&](const ElementValues &fe, const Span<const int> cell, const int index)
  {
    const ConstitutiveModel &model = *models_[model_of_cell_.of_cell(index)];
    double volume = 0.0;
    for (int q = 0; q < fe.n_qpoints(); ++q)
      volume += fe.JxW(q);
    if (!model.constant_linear())
    {
      for (int q = 0; q < fe.n_qpoints(); ++q)
        side.add_point(model, fe.JxW(q) / volume, cell, fe.shapes(q), fe.grads(q));
      return;
    }
    // σ linear in (ε, T): the average stress is the stress of the average ε and T.
    mean_phi.assign(fe.n_shape(), 0.0);
    mean_grad.assign(fe.n_shape(), Point{});
    for (int q = 0; q < fe.n_qpoints(); ++q)
    {
      const double w = fe.JxW(q) / volume;
      for (int j = 0; j < fe.n_shape(); ++j)
      {
        mean_phi[j] += fe.shape(j, q) * w;
        for (int d = 0; d < 3; ++d)
          mean_grad[j][d] += fe.grad(j, q)[d] * w;
      }
    }
    side.add_point(model, 1.0, cell, mean_phi.data(), mean_grad.data());
  };
  add_cell(fe_a, cell_a, cells[0]);
  add_cell(fe_b, cell_b, cells[1]);
  return side.pressure();
}

void ContactConductanceKernel::evaluate(const FaceValues &fv, const ElementValues &fe_a,
                                        const ElementValues &fe_b, const Span<const int> cell_a,
                                        const Span<const int> cell_b,
                                        const std::array<int, 2> &cells,
                                        const std::vector<double> &T, const std::vector<Point> &u,
                                        const int T_slot, const int u_slot,
                                        LocalSystem &local) const
{
  const int n_local = local.n_nodes();
  const int n_face = fv.n_shape(); // local nodes 0..n_face-1 on side a, then their twins
  // The face's mean normal (a plane face: its normal).
  Point n{};
  for (int q = 0; q < fv.n_qpoints(); ++q)
    for (int d = 0; d < 3; ++d)
      n[d] += fv.normal(q)[d] * fv.JxW(q);
  const double length = std::sqrt(dot(n, n));
  for (double &x : n)
    x /= length;

  // p = (p_a + p_b)/2 from the two cells' materials: dp/du_j (a vector) and dp/dT_j per local
  // node.
  std::vector<Point> dp_du(n_local, Point{});
  std::vector<double> dp_dT(n_local, 0.0);
  const double p = pressure(n, fe_a, fe_b, cell_a, cell_b, cells, T, u, dp_du, dp_dT);
  const double dh_dp = conductance_pressure_derivative(p);

  for (int q = 0; q < fv.n_qpoints(); ++q)
  {
    double jump = 0.0;
    Point u_a{}, u_b{};
    for (int j = 0; j < n_face; ++j)
    {
      jump += fv.shape(j, q) * (T[j] - T[n_face + j]);
      for (int d = 0; d < 3; ++d)
      {
        u_a[d] += fv.shape(j, q) * u[j][d];
        u_b[d] += fv.shape(j, q) * u[n_face + j][d];
      }
    }
    const double g = gap_opening(fv.normal(q), u_a, u_b);
    const double h = conductance(g, p);
    const double dh_dg = g > 0.0 ? -p_.h0 * p_.length / ((p_.length + g) * (p_.length + g)) : 0.0;
    const double JxW = fv.JxW(q);
    for (int i = 0; i < n_face; ++i)
    {
      const double phi = fv.shape(i, q) * JxW;
      local.residual(T_slot, i) += h * jump * phi;
      local.residual(T_slot, n_face + i) -= h * jump * phi;
      if (!local.has_jacobian())
        continue;
      // d/dT of the jump.
      for (int j = 0; j < n_face; ++j)
      {
        const double m = h * fv.shape(j, q) * phi;
        local.jacobian(T_slot, i, T_slot, j) += m;
        local.jacobian(T_slot, i, T_slot, n_face + j) -= m;
        local.jacobian(T_slot, n_face + i, T_slot, j) -= m;
        local.jacobian(T_slot, n_face + i, T_slot, n_face + j) += m;
      }
      // dh/dg dg/du: g depends on the face nodes' u.
      if (dh_dg != 0.0)
        for (int j = 0; j < n_face; ++j)
          for (int d = 0; d < 3; ++d)
          {
            const double v = jump * phi * dh_dg * fv.shape(j, q) * fv.normal(q)[d];
            local.jacobian(T_slot, i, u_slot + d, n_face + j) += v;
            local.jacobian(T_slot, i, u_slot + d, j) -= v;
            local.jacobian(T_slot, n_face + i, u_slot + d, n_face + j) -= v;
            local.jacobian(T_slot, n_face + i, u_slot + d, j) += v;
          }
      // dh/dp dp/d(u, T): p depends on both cells' nodes.
      if (dh_dp != 0.0)
        for (int l = 0; l < n_local; ++l)
        {
          const double s = jump * phi * dh_dp;
          for (int d = 0; d < 3; ++d)
          {
            local.jacobian(T_slot, i, u_slot + d, l) += s * dp_du[l][d];
            local.jacobian(T_slot, n_face + i, u_slot + d, l) -= s * dp_du[l][d];
          }
          local.jacobian(T_slot, i, T_slot, l) += s * dp_dT[l];
          local.jacobian(T_slot, n_face + i, T_slot, l) -= s * dp_dT[l];
        }
    }
  }
}
} // namespace kiln
