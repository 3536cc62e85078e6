#include "physics/heat/mortar_gap_heat.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"
#include "contact/face_search.hpp"
#include "contact/gap_opening.hpp"
#include "elements/finite_element.hpp"
#include "mesh/contact_surface.hpp"

#include <algorithm>
#include <array>
#include <sstream>

namespace kiln
{
Teuchos::ParameterList MortarGapHeat::valid_parameters()
{
  Teuchos::ParameterList p("Heat Transfer");
  p.set("Conductance", 0.0,
        "h_c, a constant conductance across the gap whatever its width (as Thermal/\"Gap "
        "Conductance\" on a split gap): flux h_c (T_s - T_m) from the secondary to the primary "
        "side; must be >= 0; 0: no such term [W/(m^2 K)]",
        nonnegative_double_validator());
  set_number_or_sublist(
      p, "Gas Conductivity",
      "k_gas(T) of the gas in the gap, at the mean of the two sides' temperatures: flux "
      "k_gas (T_s - T_m) / (g + \"Jump Distance\"), g the local gap width (0 where closed); "
      "must be >= 0; a number, or a sublist for a table or a formula in T as material "
      "properties (doc/materials.md); 0: no gas conduction [W/(m K)]",
      TemperatureFunction::valid_parameters(0.0, "k_gas [W/(m K)]", PropertyRange::nonnegative()));
  p.set("Jump Distance", 0.0,
        "g_jump, the temperature jump distance added to the gap width in the gas term (it "
        "bounds the conductance k_gas/g_jump of a closed gap); must be > 0 with a \"Gas "
        "Conductivity\" [m]",
        nonnegative_double_validator());
  p.set("Primary Emissivity", 0.0,
        "eps_m of the primary surface, 0 <= eps_m <= 1: radiation sigma eps (T_s^4 - T_m^4) "
        "across the gap with eps = 1/(1/eps_s + 1/eps_m - 1) (view factor 1); 0 with "
        "\"Secondary Emissivity\" 0: no radiation [-]",
        double_range_validator(0.0, 1.0));
  p.set("Secondary Emissivity", 0.0,
        "eps_s of the secondary surface, 0 <= eps_s <= 1 (see \"Primary Emissivity\") [-]",
        double_range_validator(0.0, 1.0));
  p.set("Gap Pressure Coefficient", 0.0,
        "h_p, the contact conductance's rise per contact pressure, as in Thermal/\"Gap "
        "Conductance Model\" \"Contact Dependent\" on a split gap: h_p max(p, 0) adds to the "
        "conductance, p the normal compression of the two cells at the faces (the mean of their "
        "volume-averaged stresses, from their materials; about 0 while the gap is open); must "
        "be >= 0; 0: no such term [W/(m^2 K Pa)]",
        nonnegative_double_validator());
  return p;
}

namespace
{
/// Whether k_gas is other than the constant 0 (the default: no gas term).
bool has_gas(const TemperatureFunction &k_gas)
{
  return !(k_gas.is_constant() && k_gas.value(0.0) == 0.0);
}

MortarGapHeat::Parameters read_parameters(const Teuchos::ParameterList &p, const std::string &where)
{
  MortarGapHeat::Parameters r;
  r.conductance = p.get<double>("Conductance");
  r.gas_conductivity = TemperatureFunction(
      p.sublist("Gas Conductivity"), where + "/Gas Conductivity", PropertyRange::nonnegative());
  r.jump_distance = p.get<double>("Jump Distance");
  r.primary_emissivity = p.get<double>("Primary Emissivity");
  r.secondary_emissivity = p.get<double>("Secondary Emissivity");
  r.pressure_coefficient = p.get<double>("Gap Pressure Coefficient");
  const bool gas = has_gas(r.gas_conductivity);
  std::ostringstream jump;
  jump << where << "/\"Jump Distance\" = " << r.jump_distance;
  KILN_CHECK_INPUT(!gas || r.jump_distance > 0.0, jump.str(),
                   "must be > 0 with a \"Gas Conductivity\": the gas term k_gas / (g + g_jump) "
                   "needs g_jump > 0, or a closed gap (g = 0) would conduct without bound; give "
                   "the temperature jump distance, e.g. 1e-6 m");
  const std::array<const char *, 2> names{"Primary Emissivity", "Secondary Emissivity"};
  const std::array<double, 2> values{r.primary_emissivity, r.secondary_emissivity};
  for (int side = 0; side < 2; ++side)
    KILN_CHECK_INPUT(!(values[side] > 0.0) || given_in_input(p, names[1 - side]),
                     where + "/\"" + names[1 - side] + "\"",
                     "must be given with \"" << names[side] << "\" = " << values[side]
                                             << ": radiation across the gap needs both "
                                                "surfaces' emissivities (0 on either side "
                                                "means none crosses), e.g. 0.8");
  return r;
}
} // namespace

MortarGapHeat::MortarGapHeat(const Teuchos::ParameterList &validated_params,
                             const std::string &where)
    : MortarGapHeat(read_parameters(validated_params, where))
{
}

MortarGapHeat::MortarGapHeat(const Parameters &p)
    : p_(p), gas_(has_gas(p.gas_conductivity)),
      sigma_eps_(stefan_boltzmann *
                 effective_emissivity(p.secondary_emissivity, p.primary_emissivity))
{
  KILN_ASSERT(!gas_ || p_.jump_distance > 0.0, "MortarGapHeat: a gas term needs g_jump > 0");
}

double MortarGapHeat::effective_emissivity(const double secondary, const double primary)
{
  if (!(secondary > 0.0) || !(primary > 0.0))
    return 0.0;
  return 1.0 / (1.0 / secondary + 1.0 / primary - 1.0);
}

bool MortarGapHeat::active() const
{
  return p_.conductance > 0.0 || gas_ || sigma_eps_ > 0.0 || p_.pressure_coefficient > 0.0;
}

MortarGapHeat::PointFlux MortarGapHeat::flux(const double T_s, const double T_m, const double g,
                                             const double h_contact) const
{
  const double jump = T_s - T_m;
  const double h_constant = p_.conductance + h_contact;
  PointFlux f;
  f.q = h_constant * jump;
  f.dq_dTs = h_constant;
  f.dq_dTm = -h_constant;
  if (gas_)
  {
    const double width = std::max(g, 0.0) + p_.jump_distance;
    const double T_mean = 0.5 * (T_s + T_m);
    const double h = p_.gas_conductivity.value(T_mean) / width;
    const double dh_dT_mean = p_.gas_conductivity.derivative(T_mean) / width;
    f.q += h * jump;
    f.dq_dTs += h + 0.5 * dh_dT_mean * jump;
    f.dq_dTm += -h + 0.5 * dh_dT_mean * jump;
    if (g > 0.0)
      f.dq_dg = -h / width * jump;
  }
  if (sigma_eps_ > 0.0)
  {
    f.q += sigma_eps_ * (T_s * T_s * T_s * T_s - T_m * T_m * T_m * T_m);
    f.dq_dTs += 4.0 * sigma_eps_ * T_s * T_s * T_s;
    f.dq_dTm -= 4.0 * sigma_eps_ * T_m * T_m * T_m;
  }
  return f;
}

std::vector<MortarGapCell> MortarGapHeat::cells(const ContactSurface &secondary,
                                                const ContactSurface &primary,
                                                const FaceSearch &search, const double reach)
{
  const auto face_positions = [](const ContactSurface &surface, const int f)
  {
    std::vector<Point> x;
    for (const int j : surface.face_nodes(f))
      x.push_back(surface.positions()[j]);
    return x;
  };
  std::vector<MortarGapCell> result;
  for (int s = 0; s < secondary.n_faces(); ++s)
  {
    const std::vector<Point> x_s = face_positions(secondary, s);
    const MortarFace face_s{secondary.face_type(s), x_s};
    for (const int m : search.candidates(secondary.face_box(s), reach))
    {
      const std::vector<Point> x_m = face_positions(primary, m);
      const MortarSegments segments(face_s, MortarFace{primary.face_type(m), x_m});
      if (segments.empty())
        continue;
      const Point &outward = segments.normal();
      result.push_back({s, m, secondary.face_type(s), primary.face_type(m),
                        Point{-outward[0], -outward[1], -outward[2]}, segments.points()});
    }
  }
  return result;
}

std::vector<int> MortarGapHeat::nodes(const ContactSurface &secondary,
                                      const ContactSurface &primary, const MortarGapCell &cell)
{
  std::vector<int> result;
  for (const int j : secondary.face_nodes(cell.secondary_face))
    result.push_back(secondary.nodes()[j]);
  for (const int k : primary.face_nodes(cell.primary_face))
    result.push_back(primary.nodes()[k]);
  return result;
}

namespace
{
/// One point of a cell: the signed shape values s_a of the local nodes (N_i(xi_s) for the
/// secondary face's, -N_k(xi_m) for the primary face's: the row weights of q and dg/dx_a / n),
/// the two sides' temperatures and the gap.
struct PointState
{
  std::array<double, 2 * max_cell_nodes> signed_shape{};
  int n_secondary = 0;
  int n_local = 0;
  double T_s = 0.0;
  double T_m = 0.0;
  double gap = 0.0;
};

PointState point_state(const MortarGapCell &cell, const MortarPoint &point,
                       const std::vector<double> &T, const std::vector<Point> &x)
{
  const FiniteElement &fe_s = FiniteElement::of(cell.secondary_type);
  const FiniteElement &fe_m = FiniteElement::of(cell.primary_type);
  PointState s;
  s.n_secondary = fe_s.n_shape();
  s.n_local = fe_s.n_shape() + fe_m.n_shape();
  KILN_ASSERT(static_cast<int>(T.size()) >= s.n_local && static_cast<int>(x.size()) >= s.n_local,
              "MortarGapHeat: a value per local node");
  std::array<double, max_cell_nodes> N{};
  fe_s.values(point.xi_s, N.data());
  std::copy(N.begin(), N.begin() + s.n_secondary, s.signed_shape.begin());
  fe_m.values(point.xi_m, N.data());
  for (int k = 0; k < fe_m.n_shape(); ++k)
    s.signed_shape[s.n_secondary + k] = -N[k];
  Point x_s{0, 0, 0}, x_m{0, 0, 0};
  for (int a = 0; a < s.n_local; ++a)
  {
    const bool on_secondary = a < s.n_secondary;
    const double shape = on_secondary ? s.signed_shape[a] : -s.signed_shape[a];
    (on_secondary ? s.T_s : s.T_m) += shape * T[a];
    Point &y = on_secondary ? x_s : x_m;
    for (int d = 0; d < 3; ++d)
      y[d] += shape * x[a][d];
  }
  s.gap = gap_opening(cell.normal, x_m, x_s);
  return s;
}
} // namespace

void MortarGapHeat::evaluate(const MortarGapCell &cell, const std::vector<double> &T,
                             const std::vector<Point> &x, const FieldSlots &slots,
                             LocalSystem &local, const ContactTerm *contact) const
{
  const int T_slot = slots.T;
  const double h_contact = contact != nullptr ? contact->h : 0.0;
  KILN_ASSERT(contact == nullptr || (static_cast<int>(contact->dh_dT.size()) == local.n_nodes() &&
                                     static_cast<int>(contact->dh_du.size()) == local.n_nodes()),
              "MortarGapHeat: the contact term's derivatives per local node");
  for (const MortarPoint &point : cell.points)
  {
    const PointState s = point_state(cell, point, T, x);
    KILN_ASSERT(local.n_nodes() >= s.n_local, "MortarGapHeat: a local system of both faces");
    const PointFlux f = flux(s.T_s, s.T_m, s.gap, h_contact);
    const double jump = s.T_s - s.T_m;
    for (int a = 0; a < s.n_local; ++a)
    {
      const double row = s.signed_shape[a] * point.weight;
      local.residual(T_slot, a) += row * f.q;
      if (!local.has_jacobian())
        continue;
      for (int b = 0; b < s.n_local; ++b)
      {
        const double dq_dT =
            b < s.n_secondary ? f.dq_dTs * s.signed_shape[b] : -f.dq_dTm * s.signed_shape[b];
        local.jacobian(T_slot, a, T_slot, b) += row * dq_dT;
        if (slots.u >= 0 && f.dq_dg != 0.0)
          for (int d = 0; d < 3; ++d)
            local.jacobian(T_slot, a, slots.u + d, b) +=
                row * f.dq_dg * s.signed_shape[b] * cell.normal[d];
      }
      // The contact conductance: q = h jump, h = h_p max(p, 0) with p from the cells' nodes.
      if (contact != nullptr)
        for (int l = 0; l < local.n_nodes(); ++l)
        {
          local.jacobian(T_slot, a, T_slot, l) += row * jump * contact->dh_dT[l];
          if (slots.u >= 0)
            for (int d = 0; d < 3; ++d)
              local.jacobian(T_slot, a, slots.u + d, l) += row * jump * contact->dh_du[l][d];
        }
    }
  }
}

double MortarGapHeat::heat_flow(const MortarGapCell &cell, const std::vector<double> &T,
                                const std::vector<Point> &x, const ContactTerm *contact) const
{
  const double h_contact = contact != nullptr ? contact->h : 0.0;
  double total = 0.0;
  for (const MortarPoint &point : cell.points)
  {
    const PointState s = point_state(cell, point, T, x);
    total += point.weight * flux(s.T_s, s.T_m, s.gap, h_contact).q;
  }
  return total;
}
} // namespace kiln
