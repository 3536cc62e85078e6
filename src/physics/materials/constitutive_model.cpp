#include "physics/materials/constitutive_model.hpp"

namespace kiln
{
void ConstitutiveModel::initial_state(double *state) const
{
  for (int i = 0; i < n_state(); ++i)
    state[i] = 0.0;
}
} // namespace kiln
