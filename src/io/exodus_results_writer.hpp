#pragma once
/// Results in one Exodus II file, BASE.exo, for Exodus-based tools (ParaView's Exodus
/// readers, SEACAS, Cubit, meshio). The layout is in doc/output-format.md:
/// - the mesh as exodus_layout() names it: element blocks "block_<id>" (with the element
///   attribute "cell_rank"), side sets with their names ("gap" for the gap), one node set
///   per side set with the same id and name, the info record that the coordinates are in
///   metres;
/// - per output step: the time, one global variable per column of the time history
///   (history_columns(mesh.gap_side_sets), named as the columns: the row of the step written, whose
///   "step" is the output step's cycle; NaN but step, time and dt until that row comes, see
///   write_history()), one nodal or element
///   variable per component of each field: a 1-component field keeps its name, 3
///   components get _x _y _z, 6-component Voigt tensors (Kiln order xx yy zz xy xz yz)
///   become _xx _yy _zz _xy _yz _xz, other counts _0, _1, ...; NaN values stay NaN;
///   element variables are defined on every block (truth table all ones).
/// Exodus defines its variables once, before the first step: the fields written in the
/// first step are the file's variables, and every later step must write the same fields
/// (name, node or cell, number of components), in any order; anything else is an
/// InternalError.
/// The values are gathered to rank 0, which writes the file alone (fine for the meshes Kiln
/// holds, which are replicated on every rank anyway). Each step goes to the file in
/// end_step() and is flushed (ex_update) there: after end_step() the file on disk holds
/// every step so far, complete, and can be read while the run goes on; a run that dies
/// later leaves it so.
/// Every member function is collective on the communicator, which must outlive the writer;
/// errors are thrown on all ranks alike (kiln::InputError when the file cannot be created
/// or written, naming it; kiln::InternalError for a misuse), and the destructor closes the
/// file.

#include "io/results_writer.hpp"
#include "mesh/mesh.hpp"

#include <mpi.h>

#include <memory>
#include <string>
#include <vector>

namespace kiln
{
class ExodusResultsWriter final : public ResultsWriter
{
public:
  /// Creates `base_path`.running.exo (collective on `comm`) and writes the mesh; finish()
  /// renames it `base_path`.exo. `owned_nodes` and `owned_cells` are this rank's rows, in
  /// increasing order; every node and cell is owned by exactly one rank. `cell_rank` is the
  /// owner of every cell (replicated). Of the metadata only the run fingerprint is written
  /// (the netCDF global attribute run_fingerprint; Exodus info records hold 80 characters
  /// each): the QA record names Kiln and the date.
  ExodusResultsWriter(MPI_Comm comm, const std::string &base_path, const Mesh &mesh,
                      const std::vector<int> &owned_nodes, const std::vector<int> &owned_cells,
                      const std::vector<int> &cell_rank, const ResultsMetadata &metadata = {});
  ~ExodusResultsWriter() override;
  ExodusResultsWriter(const ExodusResultsWriter &) = delete;
  ExodusResultsWriter &operator=(const ExodusResultsWriter &) = delete;

  /// Starts output step k (k = number of steps written before; Exodus time step k + 1).
  void begin_step(double time, int cycle, double dt) override;
  /// `values` holds n_components values per owned node, node after node. The name
  /// (letters, digits, '_', '-', '.') must be new in this step.
  void write_node_field(const std::string &name, int n_components,
                        const std::vector<double> &values) override;
  /// `values` holds n_components values per owned cell, cell after cell.
  void write_cell_field(const std::string &name, int n_components,
                        const std::vector<double> &values) override;
  /// Writes the step (the first one also defines the variables) and flushes the file.
  void end_step() override;
  /// Keeps `row` (history_columns(mesh.gap_side_sets) order) for the global variables of the next
  /// step of its cycle; if steps of its cycle were written before it (the earlier steps of a
  /// continued run come before their rows), writes their global variables now and flushes the file.
  void write_history(const std::vector<double> &row) override;
  /// Closes the file and renames it BASE.exo (the status shows in the log only).
  void finish(const std::string &status) override;
  void set_final_base(const std::string &final_base) override;

  /// The file's current path (BASE.running.exo until finish(), then BASE.exo).
  std::string exo_path() const;

  /// The Exodus variable names of a field: {name} for 1 component, name_x/_y/_z for 3,
  /// name_xx/_yy/_zz/_xy/_yz/_xz for 6, name_0 ... otherwise.
  static std::vector<std::string> variable_names(const std::string &name, int n_components);
  /// The component of the field (0-based, Kiln's order) each variable of variable_names()
  /// holds: identity except for 6 components, where _yz is Voigt index 5 and _xz index 4.
  static std::vector<int> variable_components(int n_components);

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};
} // namespace kiln
