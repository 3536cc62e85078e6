#pragma once
/// Private to src/io: the Exodus II results file, as rank 0 writes it alone (the values come
/// gathered). The mesh as exodus_layout() names it (with the element attribute "cell_rank"),
/// one global variable per column of the time history (history_columns(mesh.gap_side_sets), named
/// as the columns), and the node and element variables of ExodusVariables, element variables on
/// every block. Every member function throws an InputError naming the file when an Exodus call
/// fails, a WriteError when the disk is full or the file-size limit reached (checked before each
/// step, and the system's reason of a failed call); the destructor closes the file.
#include "io/exodus_variables.hpp"
#include "io/history_csv.hpp"
#include "mesh/exodus_io.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace kiln
{
namespace internal
{
class ExodusResultsFile
{
public:
  /// Creates `path` (classic netCDF) and writes the mesh, flushed; `cell_rank` is the owner of
  /// every cell. A `run_fingerprint` that is not empty goes into the netCDF global attribute
  /// run_fingerprint (exodus_results_summary() reads it back).
  ExodusResultsFile(const std::string &path, const Mesh &mesh, const std::vector<int> &cell_rank,
                    const std::string &run_fingerprint = "");
  ~ExodusResultsFile();
  ExodusResultsFile(const ExodusResultsFile &) = delete;
  ExodusResultsFile &operator=(const ExodusResultsFile &) = delete;

  /// Defines the global variables and the node and element variables (once, before the
  /// first step), in the order of `variables`, each field's components together.
  void define_variables(const ExodusVariables &variables) const;

  /// One output step and its values; each field's values are component after component,
  /// each in global-id order.
  struct Step
  {
    int index;                          ///< 0-based (Exodus time step index + 1)
    double time;                        ///< [s]
    const std::vector<double> &globals; ///< one per history column, history_columns(gaps) order
    const std::vector<FieldSpec> &fields;
    const std::vector<std::vector<double>> &values; ///< per field
  };
  /// Writes the step's time, global variables and fields, then flushes the file.
  void write_step(const Step &step, const ExodusVariables &variables) const;
  /// Writes the global variables of the written step `index` (0-based) again, then flushes
  /// the file: a step whose history row comes after it (a continued run's earlier steps).
  void write_globals(int index, const std::vector<double> &globals) const;

private:
  void write_cell_variable(int step, int variable, const double *values,
                           const std::string &what) const;

  std::string path_;
  int exo_ = -1;
  int n_nodes_ = 0;
  int n_cells_ = 0;
  ExodusLayout layout_;
  std::vector<HistoryColumn> columns_; ///< the global variables: history_columns(mesh's gaps)
  /// The file's size after the last step (or the mesh), and the largest growth of a step
  /// [bytes]: each step first checks for room for twice that (a WriteError if there is none).
  mutable std::uintmax_t size_before_step_ = 0;
  mutable std::uintmax_t largest_step_ = 0;
};
} // namespace internal
} // namespace kiln
