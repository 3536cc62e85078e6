#pragma once
/// Where the output steps go: a results file format (Hdf5XdmfWriter; others alike).
#include <string>
#include <vector>

namespace kiln
{
/// One results file, written step after step. Every member function is collective; values
/// are this rank's owned nodes or cells in increasing order, n_components values each.
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
  /// Completes the step on disk (a run that stops later leaves it readable).
  virtual void end_step() = 0;
};
} // namespace kiln
