#pragma once
/// Scalar measures of a stress tensor.
#include "physics/mechanics/elasticity_kernel.hpp"

#include <array>

namespace kiln
{
/// sigma_vM = sqrt(3/2 s : s), s the deviator of sigma (Voigt xx yy zz xy xz yz, tensor
/// shears) [unit of sigma].
double von_mises(const Voigt &sigma);
/// p = -tr(sigma)/3, positive in compression.
double pressure(const Voigt &sigma);
/// The eigenvalues of sigma, largest first (the principal stresses).
std::array<double, 3> principal_values(const Voigt &sigma);
} // namespace kiln
