// The elastic cube in deal.II 9.4 with Trilinos ML: the reference program of Kiln's issue 12
// target "Elastic cube N = 60: <= 0.7x the wall time of deal.II 9.4 with Trilinos ML, np 1
// and 2, measured side by side" (benchmarks/dealii_cube.py runs both).
//
// The problem is Kiln's inputs/elastic-cube.xml: the unit cube [0,1]^3 cut into N^3 Q1
// hexahedra, linear isotropic elasticity with E = 1, nu = 0.25, u = 0 on z = 0, body force
// (1, 2, 0) per volume, every other face traction free. Written in the style of step-8 and
// step-40: parallel::distributed::Triangulation, FE_Q<3>(1)^3, QGauss<3>(2), Trilinos
// matrices and vectors, CG preconditioned by TrilinosWrappers::PreconditionAMG (ML, smoothed
// aggregation, Chebyshev smoothing, 2 sweeps, aggregation threshold 0) with the six rigid-body
// modes as near-null space, to ||r|| <= 1e-8 ||b||. One thread per MPI rank (Kiln's Kokkos is
// serial). No output files.
//
// usage: mpirun -np P elastic_cube N
// It prints `key: value` lines (rank 0): N, ranks, unknowns, CG iterations, max |u| (the
// largest absolute nodal displacement component over all ranks), and the wall times of
// the set-up (mesh, DoFs, constraints, sparsity, matrix and vectors), the assembly, the
// AMG set-up, the solve and the total (after MPI_Init), each measured with MPI_Wtime
// between barriers.

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/distributed/tria.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>

#include <deal.II/grid/grid_generator.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <deal.II/numerics/vector_tools.h>

#include <Epetra_Map.h>
#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>

using namespace dealii;

namespace
{
constexpr int dim = 3;

// Kiln's inputs/elastic-cube.xml
constexpr double youngs_modulus  = 1.0;
constexpr double poissons_ratio  = 0.25;
constexpr double body_force[dim] = {1.0, 2.0, 0.0};
constexpr double cg_tolerance    = 1e-8; // relative to ||b|| (zero initial guess)
constexpr unsigned int cg_max_iterations = 1000;

// GridGenerator::subdivided_hyper_cube(..., colorize = true) gives the face z = 0 this id.
constexpr types::boundary_id bottom_id = 4;

class ElasticCube
{
public:
  ElasticCube(unsigned int n_cells, MPI_Comm comm);
  void run();

private:
  double lap(double &since) const; // barrier, then the seconds since `since` (reset)
  void setup();
  void assemble();
  void build_preconditioner();
  void solve();

  const unsigned int n_cells;
  MPI_Comm comm;
  ConditionalOStream pcout;

  parallel::distributed::Triangulation<dim> triangulation;
  FESystem<dim> fe;
  DoFHandler<dim> dof_handler;
  IndexSet locally_owned_dofs;
  IndexSet locally_relevant_dofs;
  AffineConstraints<double> constraints;

  TrilinosWrappers::SparseMatrix system_matrix;
  TrilinosWrappers::MPI::Vector solution;
  TrilinosWrappers::MPI::Vector system_rhs;
  TrilinosWrappers::PreconditionAMG preconditioner;
  std::unique_ptr<Epetra_MultiVector> rigid_body_modes;

  unsigned int cg_iterations = 0;
};

ElasticCube::ElasticCube(const unsigned int n_cells_, MPI_Comm comm_)
  : n_cells(n_cells_)
  , comm(comm_)
  , pcout(std::cout, Utilities::MPI::this_mpi_process(comm_) == 0)
  , triangulation(comm_)
  , fe(FE_Q<dim>(1), dim)
  , dof_handler(triangulation)
{}

double ElasticCube::lap(double &since) const
{
  MPI_Barrier(comm);
  const double now = MPI_Wtime();
  const double seconds = now - since;
  since = now;
  return seconds;
}

void ElasticCube::setup()
{
  GridGenerator::subdivided_hyper_cube(triangulation, n_cells, 0.0, 1.0, /*colorize=*/true);
  dof_handler.distribute_dofs(fe);
  locally_owned_dofs = dof_handler.locally_owned_dofs();
  DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant_dofs);

  constraints.clear();
  constraints.reinit(locally_relevant_dofs);
  VectorTools::interpolate_boundary_values(dof_handler, bottom_id,
                                           Functions::ZeroFunction<dim>(dim), constraints);
  constraints.close();

  DynamicSparsityPattern dsp(locally_relevant_dofs);
  DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, /*keep_constrained_dofs=*/false);
  SparsityTools::distribute_sparsity_pattern(dsp, locally_owned_dofs, comm,
                                             locally_relevant_dofs);
  system_matrix.reinit(locally_owned_dofs, locally_owned_dofs, dsp, comm);
  solution.reinit(locally_owned_dofs, comm);
  system_rhs.reinit(locally_owned_dofs, comm);
}

void ElasticCube::assemble()
{
  const double mu = youngs_modulus / (2.0 * (1.0 + poissons_ratio));
  const double lambda = youngs_modulus * poissons_ratio /
                        ((1.0 + poissons_ratio) * (1.0 - 2.0 * poissons_ratio));

  const QGauss<dim> quadrature(2);
  FEValues<dim> fe_values(fe, quadrature,
                          update_values | update_gradients | update_JxW_values);
  const unsigned int dofs_per_cell = fe.n_dofs_per_cell();
  const unsigned int n_q_points = quadrature.size();
  FullMatrix<double> cell_matrix(dofs_per_cell, dofs_per_cell);
  Vector<double> cell_rhs(dofs_per_cell);
  std::vector<types::global_dof_index> local_dof_indices(dofs_per_cell);
  std::vector<unsigned int> component(dofs_per_cell);
  for (unsigned int i = 0; i < dofs_per_cell; ++i)
    component[i] = fe.system_to_component_index(i).first;

  for (const auto &cell : dof_handler.active_cell_iterators())
  {
    if (!cell->is_locally_owned())
      continue;
    cell_matrix = 0;
    cell_rhs = 0;
    fe_values.reinit(cell);
    // step-8's bilinear form: lambda div u div v + mu (grad u : grad v + grad u : grad v^T)
    for (unsigned int q = 0; q < n_q_points; ++q)
    {
      const double JxW = fe_values.JxW(q);
      for (unsigned int i = 0; i < dofs_per_cell; ++i)
      {
        const unsigned int ci = component[i];
        const Tensor<1, dim> &grad_i = fe_values.shape_grad(i, q);
        for (unsigned int j = 0; j < dofs_per_cell; ++j)
        {
          const unsigned int cj = component[j];
          const Tensor<1, dim> &grad_j = fe_values.shape_grad(j, q);
          double a = grad_i[ci] * grad_j[cj] * lambda + grad_i[cj] * grad_j[ci] * mu;
          if (ci == cj)
            a += grad_i * grad_j * mu;
          cell_matrix(i, j) += a * JxW;
        }
        cell_rhs(i) += fe_values.shape_value(i, q) * body_force[ci] * JxW;
      }
    }
    cell->get_dof_indices(local_dof_indices);
    constraints.distribute_local_to_global(cell_matrix, cell_rhs, local_dof_indices,
                                           system_matrix, system_rhs);
  }
  system_matrix.compress(VectorOperation::add);
  system_rhs.compress(VectorOperation::add);
}

void ElasticCube::build_preconditioner()
{
  // deal.II 9.4's AdditionalData::constant_modes holds only 0/1 modes (the translations);
  // the six rigid-body modes (deal.II >= 9.5: DoFTools::extract_rigid_body_modes) are built
  // here on the matrix's row map and handed to ML as its pre-computed null space.
  TrilinosWrappers::PreconditionAMG::AdditionalData data;
  data.elliptic = true;              // ML "SA" defaults, Chebyshev smoother
  data.higher_order_elements = false; // Q1
  data.smoother_sweeps = 2;          // Chebyshev degree 2
  data.aggregation_threshold = 0.0;  // ML "aggregation: threshold"
  data.output_details = false;

  const Epetra_Map &map = system_matrix.trilinos_matrix().RowMap();
  rigid_body_modes = std::make_unique<Epetra_MultiVector>(map, 6, /*zero_out=*/true);
  std::vector<types::global_dof_index> local_dof_indices(fe.n_dofs_per_cell());
  for (const auto &cell : dof_handler.active_cell_iterators())
  {
    if (!cell->is_locally_owned())
      continue;
    cell->get_dof_indices(local_dof_indices);
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
    {
      const int lid = map.LID(static_cast<TrilinosWrappers::types::int_type>(local_dof_indices[i]));
      if (lid < 0)
        continue; // owned by another rank
      const unsigned int c = fe.system_to_component_index(i).first;
      const Point<dim> x = cell->vertex(i / fe.n_dofs_per_vertex());
      (*rigid_body_modes)[c][lid] = 1.0; // translation in direction c
      // rotations about z, x, y: (-y, x, 0), (0, -z, y), (z, 0, -x)
      const double rz[dim] = {-x[1], x[0], 0.0};
      const double rx[dim] = {0.0, -x[2], x[1]};
      const double ry[dim] = {x[2], 0.0, -x[0]};
      (*rigid_body_modes)[3][lid] = rz[c];
      (*rigid_body_modes)[4][lid] = rx[c];
      (*rigid_body_modes)[5][lid] = ry[c];
    }
  }

  Teuchos::ParameterList ml_parameters;
  std::unique_ptr<Epetra_MultiVector> translations; // unused: no constant_modes given
  data.set_parameters(ml_parameters, translations, system_matrix);
  ml_parameters.set("PDE equations", dim);
  ml_parameters.set("null space: type", "pre-computed");
  ml_parameters.set("null space: dimension", rigid_body_modes->NumVectors());
  ml_parameters.set("null space: vectors", rigid_body_modes->Values());
  preconditioner.initialize(system_matrix, ml_parameters);
}

void ElasticCube::solve()
{
  SolverControl control(cg_max_iterations, cg_tolerance * system_rhs.l2_norm());
  TrilinosWrappers::SolverCG cg(control);
  cg.solve(system_matrix, solution, system_rhs, preconditioner);
  constraints.distribute(solution);
  cg_iterations = control.last_step();
}

void ElasticCube::run()
{
  double start = 0.0, since = 0.0;
  lap(start);
  since = start;
  setup();
  const double t_setup = lap(since);
  assemble();
  const double t_assembly = lap(since);
  build_preconditioner();
  const double t_amg = lap(since);
  solve();
  const double t_solve = lap(since);
  const double max_u = solution.linfty_norm(); // global over the ranks
  const double t_total = since - start;

  char umax[32];
  std::snprintf(umax, sizeof umax, "%.6g", max_u);
  pcout << "N: " << n_cells << "\n"
        << "ranks: " << Utilities::MPI::n_mpi_processes(comm) << "\n"
        << "cells: " << triangulation.n_global_active_cells() << "\n"
        << "unknowns: " << dof_handler.n_dofs() << "\n"
        << "CG iterations: " << cg_iterations << "\n"
        << "max |u|: " << umax << "\n"
        << "time setup [s]: " << t_setup << "\n"
        << "time assembly [s]: " << t_assembly << "\n"
        << "time AMG setup [s]: " << t_amg << "\n"
        << "time solve [s]: " << t_solve << "\n"
        << "time total [s]: " << t_total << std::endl;
}
} // namespace

int main(int argc, char **argv)
{
  try
  {
    // One thread per rank (step-40): Kiln runs one serial (Kokkos Serial) process per rank.
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    if (argc != 2 || std::atoi(argv[1]) < 1)
    {
      if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        std::cerr << "usage: mpirun -np P " << argv[0] << " N   (N^3 cells)\n";
      return 2;
    }
    ElasticCube cube(static_cast<unsigned int>(std::atoi(argv[1])), MPI_COMM_WORLD);
    cube.run();
  }
  catch (const std::exception &e)
  {
    std::cerr << "elastic_cube: error: " << e.what() << std::endl;
    return 1;
  }
  return 0;
}
