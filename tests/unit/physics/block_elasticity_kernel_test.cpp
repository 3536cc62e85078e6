// Tests src/physics/mechanics/block_elasticity_kernel.cpp: a cell's model on the general path
// reads as PointInput::temperature_old the temperatures of the last accepted state the cell
// state carries (CellState::history.T_old), not the current ones; without an accepted state,
// the current T.
// KILN_TEST_NP: 1
#include "physics/mechanics/block_elasticity_kernel.hpp"

#include "discretization/element_values.hpp"
#include "discretization/local_system.hpp"
#include "physics/materials/constitutive_model.hpp"
#include "support/problem_fixture.hpp"

#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <vector>

namespace
{
using kiln::Point;

/// Records the temperature and temperature_old of every point it evaluates; σ = ε.
class RecordingModel final : public kiln::ConstitutiveModel
{
public:
  mutable std::vector<double> temperature, temperature_old;
  double thermal_strain(double /*temperature*/) const override { return 0.0; }
  void evaluate(const kiln::PointInput &in, const double * /*old_state*/, double * /*new_state*/,
                kiln::PointResponse &out) const override
  {
    temperature.push_back(in.temperature);
    temperature_old.push_back(in.temperature_old);
    out = kiln::PointResponse{};
    for (int i = 0; i < 6; ++i)
    {
      out.stress[i] = in.strain[i];
      out.tangent[i][i] = 1.0;
    }
  }
};

TEST(BlockElasticityKernel, TheModelReadsTheLastAcceptedTemperatureAsTemperatureOld)
{
  const kiln::Mesh mesh = kiln_test::box_mesh({{2.0, 1.0, 1.0}, {2, 1, 1}}, 0);
  const auto model = std::make_shared<RecordingModel>();
  std::vector<kiln::ElasticityKernel> kernels;
  kernels.emplace_back(model, Point{});
  std::map<int, int> kernel_of_block;
  for (const int block : mesh.block_ids())
    kernel_of_block[block] = 0;
  const kiln::BlockElasticityKernel block(mesh, std::move(kernels), kernel_of_block);

  kiln::ElementValues fe;
  fe.reinit(mesh, 0);
  const int n = fe.n_shape();
  const std::vector<double> T(n, 400.0), T_dot(n, 0.0), T_old(n, 300.0);
  const std::vector<Point> u(n, Point{});
  const auto evaluate = [&](const kiln::TemperatureHistory &history)
  {
    model->temperature.clear();
    model->temperature_old.clear();
    const kiln::CellState state{
        fe, {T.data(), n}, {T_dot.data(), n}, {u.data(), n}, 0.0, 1.0, {0, 1}, 0, 0, history};
    kiln::LocalSystem local(n, 4, true);
    block.evaluate(state, local);
    ASSERT_EQ(static_cast<int>(model->temperature_old.size()), fe.n_qpoints());
  };

  kiln::TemperatureHistory accepted;
  accepted.T_old = T_old.data();
  evaluate(accepted);
  for (int q = 0; q < fe.n_qpoints(); ++q)
  {
    EXPECT_NEAR(model->temperature[q], 400.0, 1e-9);
    EXPECT_NEAR(model->temperature_old[q], 300.0, 1e-9);
  }
  // No accepted state yet (the initial equilibrium): T itself.
  evaluate(kiln::TemperatureHistory{});
  for (int q = 0; q < fe.n_qpoints(); ++q)
    EXPECT_NEAR(model->temperature_old[q], 400.0, 1e-9);
}
} // namespace
