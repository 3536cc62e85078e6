#pragma once
/// Where the output steps go: a results file format (Hdf5XdmfWriter; others alike).
#include <string>
#include <vector>

namespace kiln
{
/// What a results file says of the run that wrote it.
struct ResultsMetadata
{
  std::string kiln_version;
  std::string created;    ///< UTC, ISO 8601
  std::string input_path; ///< the input file
  std::string input;      ///< the input as given (XML)
  /// RunFingerprint::digest() of the run (mesh, physics, start): a restart appends only to
  /// results with its checkpoint's.
  std::string run_fingerprint;
};

/// One results file, written step after step. While the run goes it has a temporary name
/// (BASE.running.*), readable after every step; finish() gives it its final name, so a run
/// that crashes never leaves a half-written file in place of a good one. Every member function is
/// collective; values are this rank's owned nodes or cells in increasing order, n_components values
/// each.
class ResultsWriter
{
public:
  virtual ~ResultsWriter() = default;
  /// Starts an output step at `time` [s] after `cycle` time steps, the last of size dt [s].
  virtual void begin_step(double time, int cycle, double dt) = 0;
  virtual void write_node_field(const std::string &name, int n_components,
                                const std::vector<double> &values) = 0;
  virtual void write_cell_field(const std::string &name, int n_components,
                                const std::vector<double> &values) = 0;
  /// A field of the gap pairs: one value per pair of Mesh::gap_pairs, the same on every rank.
  /// Given before the node field of the same name, it is what the gap surfaces and tables
  /// show at each pair (a node where gaps cross is in a pair of each, and a node field holds
  /// one of them); a writer without gap surfaces ignores it.
  virtual void write_gap_field(const std::string & /*name*/,
                               const std::vector<double> & /*per_pair*/)
  {
  }
  /// Completes the step on disk (a run that stops later leaves it readable).
  virtual void end_step() = 0;
  /// One row of the run's time history (history_columns() order, io/history_csv.hpp), between
  /// steps; a writer that keeps no history ignores it. It may hold rows back until the next
  /// end_step() or finish().
  virtual void write_history(const std::vector<double> & /*row*/) {}
  /// Records `status` ("complete", or why the run stopped) and renames the files to their
  /// final names; nothing can be written after.
  virtual void finish(const std::string &status) = 0;
  /// Makes finish() name the files `final_base`.* instead of the base they were opened with
  /// (a restart that stops short of the earlier run's results keeps those under BASE).
  virtual void set_final_base(const std::string & /*final_base*/) {}
};
} // namespace kiln
