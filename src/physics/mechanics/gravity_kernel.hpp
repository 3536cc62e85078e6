#pragma once
/// The weight of materials whose density depends on temperature.
#include "mesh/mesh.hpp"
#include "physics/kernel.hpp"
#include "physics/kernel_of_block.hpp"
#include "physics/materials/temperature_function.hpp"

#include <map>
#include <vector>

namespace kiln
{
/// The body force ρ(T) g of the cells whose material's density is a function of T
/// (doc/materials.md, "Gravity with a density of T"); ρ at the point's temperature, per
/// reference volume:
///
///   R_{i,d}       = −∫ ρ(T) g_d φ_i dΩ
///   dR_{i,d}/dT_j = −∫ ρ'(T) g_d φ_j φ_i dΩ       (the u–T coupling block)
///
/// with T = Σ_j φ_j T_j at the quadrature point. Nothing depends on u. The cells of a material
/// with a constant density take no term here: their weight ρ g is in the elasticity kernel's
/// constant body force (its fast path). Only the displacement rows are touched, and the
/// temperature columns only when the layout has a temperature.
class GravityKernel final : public CellKernel
{
public:
  /// `densities[i]` is material i's ρ(T) [kg/m^3], `weighed[i]` whether its cells take the term
  /// here (ρ depends on T); `kernel_of_block` maps every block id of the mesh to a material
  /// (it may be empty with one material); `gravity` g [m/s^2].
  GravityKernel(const Mesh &mesh, std::vector<TemperatureFunction> densities,
                std::vector<char> weighed, std::map<int, int> kernel_of_block,
                const Point &gravity);
  void evaluate(const CellState &state, LocalSystem &local) const override;

private:
  std::vector<TemperatureFunction> densities_;
  std::vector<char> weighed_;
  KernelOfBlock material_of_cell_;
  Point gravity_;
};
} // namespace kiln
