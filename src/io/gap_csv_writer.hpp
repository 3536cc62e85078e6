#pragma once
/// The gap at each output step as a table: BASE.gap-NNNNNN.csv (doc/output-format.md).
#include "io/results_writer.hpp"
#include "mesh/mesh.hpp"

#include <mpi.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace kiln
{
namespace internal
{
struct GapSurface;
class RowGather;
} // namespace internal

/// A ResultsWriter that keeps, of each output step, the gap: one CSV file per step,
/// BASE.gap-NNNNNN.csv (NNNNNN: the output step, as /steps/NNNNNN of the HDF5 file), one
/// row per gap pair (side a) with the time, the pair's position (x, y, z and the in-plane
/// s, t of internal::GapSurface), the gap opening, the contact pressure (positive in
/// compression), the heat flux across the gap, the contact state and the temperatures of
/// both sides; "nan" for what the run does not have. Each header is "NAME [UNIT]". The node
/// fields are gathered to rank 0,
/// which writes each file under a temporary name and renames it. Collective; InputError on
/// every rank when a file cannot be written.
class GapCsvWriter final : public ResultsWriter
{
public:
  /// `first_step`: the number of the first output step it is given (the steps written
  /// before by an earlier run, when they are not given again).
  GapCsvWriter(MPI_Comm comm, const std::string &base_path, const Mesh &mesh,
               const std::vector<int> &owned_nodes, int first_step = 0);
  ~GapCsvWriter() override;
  GapCsvWriter(const GapCsvWriter &) = delete;
  GapCsvWriter &operator=(const GapCsvWriter &) = delete;

  void begin_step(double time, int cycle, double dt) override;
  void write_node_field(const std::string &name, int n_components,
                        const std::vector<double> &values) override;
  void write_cell_field(const std::string &, int, const std::vector<double> &) override {}
  void end_step() override;
  void finish(const std::string &) override {}

  /// The file of output step `step`.
  std::string path(int step) const;
  /// The output step of the next file (the files so far are first_step ... next_step - 1).
  int next_step() const { return step_; }

private:
  MPI_Comm comm_;
  std::string base_;
  std::unique_ptr<internal::GapSurface> gap_;
  std::unique_ptr<internal::RowGather> gather_;
  int step_;
  double time_ = 0.0;
  std::map<std::string, std::vector<double>> fields_; ///< rank 0: every node's value
};
} // namespace kiln
