#pragma once
/// A continued run's results hold the whole time series: the earlier run's steps, then its own.
#include "io/results_writer.hpp"

#include <Teuchos_Comm.hpp>

#include <string>
#include <utility>
#include <vector>

namespace kiln
{
/// This rank's rows of the mesh.
struct ReplayRows
{
  int n_nodes = 0;
  int n_cells = 0;
  std::vector<int> owned_nodes; ///< increasing
  std::vector<int> owned_cells; ///< increasing
  /// (node_a, node_b) of each pair of Mesh::gap_pairs: the gap surfaces' fields of the HDF5
  /// file are replayed per pair (ResultsWriter::write_gap_field).
  std::vector<std::pair<int, int>> gap_pairs;
};

namespace internal
{
/// A field of an earlier output step: this rank's rows.
struct ReplayField
{
  std::string name;
  bool on_nodes;
  int n_components;
  std::vector<double> values;
};
/// An earlier output step.
struct ReplayStep
{
  double time, dt;
  int cycle;
  std::vector<ReplayField> fields;
  /// The gap fields per pair of Mesh::gap_pairs (NaN where the file has none), by name.
  std::vector<std::pair<std::string, std::vector<double>>> gap_fields;
};
/// Checks (collectively) that the steps were read without `error` (else InputError naming
/// `path`), then writes them into each of `writers`; returns their number. Collective.
int write_replayed(const std::string &path, const std::string &error,
                   const std::vector<ReplayStep> &steps,
                   const std::vector<ResultsWriter *> &writers, const Teuchos::Comm<int> &comm);
} // namespace internal

/// What a restart needs to know of the earlier HDF5 results before it touches them.
struct ResultsSummary
{
  /// The attribute run_fingerprint (RunFingerprint::digest() of the run that wrote them), or ""
  /// if they have none (results of a Kiln before 0043) or cannot be read.
  std::string run_fingerprint;
  /// The time of their last output step [s] (-infinity if none).
  double end_time = 0.0;
};

/// The summary of the HDF5 results file `path`. Reads only; every rank reads the file.
ResultsSummary results_summary(const std::string &path);

/// Writes every output step of the HDF5 results file `path` (an earlier run of the same mesh)
/// up to the time `until` [s] into each of `writers`, with the earlier step's time, cycle, dt
/// and fields. Returns the number of steps. Throws InputError naming the file (on every rank)
/// when it cannot be read or does not fit the mesh. Collective.
int replay_results(const std::string &path, double until, const ReplayRows &rows,
                   const std::vector<ResultsWriter *> &writers, const Teuchos::Comm<int> &comm);
} // namespace kiln
