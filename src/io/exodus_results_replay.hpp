#pragma once
/// Exodus-only output: a continued run's .exo holds the whole time series, as the .h5 does.
#include "io/results_replay.hpp"
#include "mesh/mesh.hpp"

namespace kiln
{
/// The summary of the Exodus results file `path` (ResultsSummary, as results_summary() gives it
/// for HDF5): its netCDF global attribute run_fingerprint ("" if it has none, as files of a Kiln
/// before changelog 0049, or cannot be read) and the time of its last output step. Reads only;
/// every rank reads the file.
ResultsSummary exodus_results_summary(const std::string &path);

/// Writes every output step of the Exodus results file `path` (an earlier run of `mesh`) up to
/// the time `until` [s] into each of `writers`: the step's time, its cycle and dt (the global
/// variables "step" and "dt") and its fields (the variables grouped back into fields as
/// ExodusVariables::names() splits them). Returns the number of steps. Throws InputError naming
/// the file (on every rank) when it cannot be read or does not fit the mesh. Collective.
int replay_exodus_results(const std::string &path, double until, const Mesh &mesh,
                          const ReplayRows &rows, const std::vector<ResultsWriter *> &writers,
                          const Teuchos::Comm<int> &comm);
} // namespace kiln
