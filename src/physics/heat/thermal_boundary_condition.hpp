#pragma once
/// One thermal boundary condition of the input, on a set of side sets.
#include "mesh/mesh.hpp"
#include "physics/materials/time_function.hpp"

#include <Teuchos_ParameterList.hpp>

#include <string>
#include <vector>

namespace kiln
{
/// A sublist of Kiln/Thermal/"Boundary Conditions", named by the user:
/// - "Temperature": T = Temperature(t) on the faces' nodes (rows replaced);
/// - "Heat Flux": flux Heat Flux(t) into the body [W/m^2];
/// - "Convection": outward flux Coefficient (T - Ambient Temperature(t)).
/// Faces in no condition are insulated. Side sets must exist and must not be the gap
/// side set (the gap has its own conductance).
class ThermalBoundaryCondition
{
public:
  enum class Type
  {
    temperature,
    heat_flux,
    convection
  };
  static Teuchos::ParameterList valid_parameters();
  /// `p` (validated against valid_parameters()) is the sublist called `name`; `where`
  /// names the block ("in.xml: Kiln/Thermal/Boundary Conditions"). Throws InputError for
  /// an empty or unknown side set, the gap side set, or a parameter that does not apply
  /// to the Type.
  ThermalBoundaryCondition(const std::string &name, const Teuchos::ParameterList &p,
                           const Mesh &mesh, const std::string &where);

  const std::string &name() const { return name_; }
  Type type() const { return type_; }
  const std::vector<int> &side_sets() const { return side_sets_; }
  /// Temperature [K], Heat Flux [W/m^2] or Ambient Temperature [K] at t [s].
  double value(const double t) const { return value_.value(t); }
  /// Convection: h [W/(m^2 K)].
  double coefficient() const { return coefficient_; }

private:
  std::string name_;
  Type type_ = Type::temperature;
  std::vector<int> side_sets_;
  TimeFunction value_;
  double coefficient_ = 0.0;
};
} // namespace kiln
