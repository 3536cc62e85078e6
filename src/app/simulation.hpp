#pragma once
/// Puts the pieces together, deal.II-tutorial style:
///   run() { setup(); output(); }   (the time loop joins with the solver)
#include "discretization/dof_manager.hpp"
#include "mesh/mesh.hpp"

#include <Teuchos_Comm.hpp>
#include <Teuchos_FancyOStream.hpp>
#include <Teuchos_ParameterList.hpp>

#include <memory>
#include <string>
#include <vector>

namespace kiln
{
class Simulation
{
public:
  /// The whole valid input tree (kiln --print-parameters prints it).
  static Teuchos::ParameterList valid_parameters();

  /// `input` is the unvalidated list read from `input_path`; it is validated
  /// here. `mesh_file` overrides the input's mesh (kiln --mesh FILE).
  Simulation(const Teuchos::ParameterList &input, const std::string &input_path,
             const Teuchos::RCP<const Teuchos::Comm<int>> &comm, const std::string &mesh_file = "");
  ~Simulation();

  /// Mesh, gap split, partition, unknowns; prints the header.
  void setup();
  /// setup(), then the initial state written to the output file.
  void run();
  /// The mesh before the split, as Exodus II (rank 0 writes).
  void write_mesh(const std::string &path) const;

  const Mesh &mesh() const { return mesh_; }
  const std::vector<int> &cell_rank() const { return cell_rank_; }
  const DofManager &dofs() const { return *dofs_; }
  /// The output file path without extension.
  std::string output_base() const;

private:
  void print_header() const;
  void output(double time, int cycle, double dt) const;

  Teuchos::ParameterList params_;
  std::string input_path_;
  std::string mesh_file_;
  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  Teuchos::RCP<Teuchos::FancyOStream> out_;
  Mesh mesh_;
  std::vector<int> cell_rank_;
  std::unique_ptr<DofManager> dofs_;
};
} // namespace kiln
