#include "support/simulation_runs.hpp"

#include "mesh/exodus_io.hpp"
#include "mesh/hex_geometry.hpp"
#include "solvers/newton_solver.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_XMLParameterListHelpers.hpp>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace kiln_test
{
void replace(std::string &text, const std::string &key, const std::string &value)
{
  for (std::size_t at = text.find(key); at != std::string::npos;
       at = text.find(key, at + value.size()))
    text.replace(at, key.size(), value);
}

std::string number(const double value)
{
  std::ostringstream s;
  s << std::setprecision(17) << value;
  return s.str();
}

std::unique_ptr<kiln::Simulation>
make_simulation(const std::string &xml, const Teuchos::RCP<const Teuchos::Comm<int>> &comm)
{
  const auto input = Teuchos::getParametersFromXmlString(xml);
  return make_simulation(*input, comm);
}

std::unique_ptr<kiln::Simulation>
make_simulation(const Teuchos::ParameterList &input,
                const Teuchos::RCP<const Teuchos::Comm<int>> &comm)
{
  auto sim = std::make_unique<kiln::Simulation>(input, "test.xml", comm);
  sim->setup();
  return sim;
}

Vector initial_state(kiln::Simulation &sim)
{
  Vector x(sim.problem().solution_map());
  sim.problem().initial_condition(0.0, x);
  return x;
}

std::string write_mesh_file(const kiln::Mesh &mesh, const std::string &base,
                            const Teuchos::Comm<int> &comm)
{
  const std::string path = base + ".mesh.exo";
  if (comm.getRank() == 0)
    kiln::write_exodus_mesh(mesh, path);
  comm.barrier();
  return path;
}

void set_solver_tolerances(Teuchos::ParameterList &input, const double absolute,
                           const double relative, const double gmres)
{
  Teuchos::ParameterList &solver = input.sublist("Solver");
  solver.set("Absolute Tolerance", absolute);
  solver.set("Relative Tolerance", relative);
  solver.sublist("Linear Solver")
      .sublist("Linear Solver Types")
      .sublist("Belos")
      .sublist("Solver Types")
      .sublist("Block GMRES")
      .set("Convergence Tolerance", gmres);
}

kiln::TimeStepper::Statistics run_from(kiln::Simulation &sim, Vector &x,
                                       const std::vector<double> &times,
                                       const kiln::TimeStepper::OutputFunction &output)
{
  const kiln::TimeStepper::OutputFunction none = [](double, int, double, const Vector &) {};
  return sim.time_stepper().run(sim.problem(), sim.newton_solver(), x, 0.0, times,
                                output ? output : none);
}

std::vector<double> all_node_values(const kiln::Simulation &sim, const Vector &x)
{
  const auto &dofs = sim.dofs();
  std::vector<double> local(sim.mesh().n_nodes(), 0.0), global(local.size(), 0.0);
  const auto values = x.getData();
  for (const int n : dofs.owned_nodes())
    local[n] = values[x.getMap()->getLocalElement(dofs.dof(n, kiln::Field::T))];
  Teuchos::reduceAll(*x.getMap()->getComm(), Teuchos::REDUCE_SUM, static_cast<int>(local.size()),
                     local.data(), global.data());
  return global;
}

void interpolate(const kiln::Simulation &sim, const std::function<double(const kiln::Point &)> &f,
                 Vector &x)
{
  const auto &dofs = sim.dofs();
  for (const int n : dofs.owned_nodes())
    x.replaceGlobalValue(dofs.dof(n, kiln::Field::T), f(sim.mesh().coordinates[n]));
}

double l2_error(const kiln::Simulation &sim, const std::vector<double> &nodal,
                const std::function<double(const kiln::Point &)> &exact)
{
  static const double g[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)};
  static const double w[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  static const int corner[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                   {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  double sum = 0.0;
  for (const int c : sim.dofs().owned_cells())
  {
    const kiln::HexNodes x = kiln::cell_nodes(sim.mesh(), c);
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        for (int d = 0; d < 3; ++d)
        {
          const kiln::Point xi{g[a], g[b], g[d]};
          kiln::Point p{0.0, 0.0, 0.0};
          double T_h = 0.0;
          for (int i = 0; i < 8; ++i)
          {
            const double N = (1 + corner[i][0] * xi[0]) * (1 + corner[i][1] * xi[1]) *
                             (1 + corner[i][2] * xi[2]) / 8.0;
            for (int k = 0; k < 3; ++k)
              p[k] += N * x[i][k];
            T_h += N * nodal[sim.mesh().cell_nodes(c)[i]];
          }
          const double e = T_h - exact(p);
          sum += e * e * w[a] * w[b] * w[d] * kiln::hex_jacobian_determinant(x, xi);
        }
  }
  double global = 0.0;
  Teuchos::reduceAll(*sim.dofs().owned_dof_map()->getComm(), Teuchos::REDUCE_SUM, sum,
                     Teuchos::outArg(global));
  return std::sqrt(global);
}
} // namespace kiln_test
