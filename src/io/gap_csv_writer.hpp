#pragma once
/// The gaps at each output step as tables: BASE.gap-NNNNNN.csv, BASE.gap_ID-NNNNNN.csv
/// (doc/output-format.md).
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

/// A ResultsWriter that keeps, of each output step, the gaps: one CSV file per step and gap,
/// BASE.NAME-NNNNNN.csv (NAME: Mesh::gap_name(), "gap" for the first gap side set, "gap_ID"
/// for the others; NNNNNN: the output step, as /steps/NNNNNN of the HDF5 file), one
/// row per pair of the gap (side a) with the time, the pair's position (x, y, z and the
/// in-plane s, t of internal::GapSurface), the gap opening, the contact pressure (positive in
/// compression), the heat flux across the gap, the contact state, the temperatures of
/// both sides and the pair's area (its share of the gap's area: the normal force across the
/// gap is the sum of contact_pressure x area); "nan" for what the run does not have. Each header is
/// "NAME [UNIT]". The gap fields are the pairs' (write_gap_field()), else their nodes a's. The node
/// fields are gathered to rank 0, which writes each file under a temporary name and renames it.
/// A contact pair of Mesh::contact_pairs has a table too, BASE.pair_NAME-NNNNNN.csv: a row per
/// node of its secondary side set's faces (the node fields there; temperature_b "nan", area
/// each face's share).
/// Collective; InputError on every rank when a file cannot be written.
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
  void write_gap_field(const std::string &name, const std::vector<double> &per_pair) override;
  void end_step() override;
  void finish(const std::string &) override {}

  /// The file of output step `step` of the first gap (`gap`: of gap `gap`, an index into
  /// Mesh::gap_side_sets).
  std::string path(int step, int gap = 0) const;
  /// The number of gaps (a table each).
  int n_gaps() const { return static_cast<int>(gaps_.size()); }
  /// The output step of the next file (the files so far are first_step ... next_step - 1).
  int next_step() const { return step_; }

private:
  /// The table of one gap at the step (rank 0 writes `file`).
  void write_table(const internal::GapSurface &gap, const std::string &file) const;

  MPI_Comm comm_;
  std::string base_;
  std::vector<std::string> names_; ///< Mesh::gap_name() of each gap
  std::vector<std::unique_ptr<internal::GapSurface>> gaps_;
  std::unique_ptr<internal::RowGather> gather_;
  int step_;
  double time_ = 0.0;
  std::map<std::string, std::vector<double>> fields_;      ///< rank 0: every node's value
  std::map<std::string, std::vector<double>> pair_fields_; ///< every pair's value
};
} // namespace kiln
