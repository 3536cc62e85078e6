#include "physics/materials/constitutive_model.hpp"

namespace kiln
{
VoigtMatrix IsotropicTangent::matrix() const
{
  VoigtMatrix C{};
  for (int I = 0; I < 6; ++I)
    for (int J = 0; J < 6; ++J)
      C[I][J] = (I < 3 && J < 3 ? lambda : 0.0) + (I == J ? 2.0 * shear : 0.0) +
                rank_one * n[I] * n[J] * (J < 3 ? 1.0 : 2.0);
  return C;
}

void ConstitutiveModel::initial_state(double *state) const
{
  for (int i = 0; i < n_state(); ++i)
    state[i] = 0.0;
}
} // namespace kiln
