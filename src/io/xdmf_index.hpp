#pragma once
/// Private to src/io: the XDMF file beside a results HDF5 file, which tells ParaView what the
/// HDF5 file holds (doc/output-format.md). Before the first step it shows the mesh alone
/// (one Uniform grid, no time); after, a Temporal collection with one Uniform grid per step:
/// the mesh, the mesh attributes block_id and cell_rank, and the step's fields. With gaps,
/// a Temporal collection per gap comes first, named as the gap's HDF5 group ("gap", "gap_ID":
/// Mesh::gap_name()): per step the gap surface (its faces' corners) with the step's node fields
/// at its points.
#include "io/field_spec.hpp"
#include "mesh/mesh.hpp"

#include <mpi.h>

#include <optional>
#include <string>
#include <vector>

namespace kiln
{
namespace internal
{
/// The HDF5 group of output step `step` under /steps: its number in six digits.
std::string step_group_name(int step);

/// How the cells are listed for XDMF: one type (`type` an XDMF TopologyType name, the
/// dataset (cells x nodes_per_element)) or several ("Mixed": the 1-D dataset of n_entries
/// values, each cell's XDMF type code followed by its nodes).
struct XdmfTopology
{
  std::string type;
  int nodes_per_element = 0; ///< one type only
  long long n_entries = 0;   ///< "Mixed" only
  std::string dataset;       ///< e.g. "/mesh/connectivity"
};

/// The XDMF topology of `mesh`: its one type's name, or "Mixed" (xdmf_index.cpp has the
/// names). `needs_own_dataset` is set when XDMF cannot read /mesh/connectivity (Exodus order,
/// padded with -1): several types, or a type whose XDMF node order differs from Exodus'.
XdmfTopology xdmf_topology(const Mesh &mesh, bool &needs_own_dataset);

class XdmfIndex
{
public:
  /// The index `xmf_path` of the HDF5 file `h5_path` (named by its file name alone, so the two
  /// files stay together) of a mesh of `n_nodes` nodes and `n_cells` cells.
  XdmfIndex(MPI_Comm comm, const std::string &xmf_path, const std::string &h5_path, int n_nodes,
            int n_cells, XdmfTopology topology);
  const std::string &path() const { return xmf_path_; }
  /// From now on the index is `xmf_path` and points at `h5_path` (the final names).
  void rename(const std::string &xmf_path, const std::string &h5_path);

  /// A gap surface, the HDF5 group /NAME, of `n_points` points and `n_faces` faces, all of
  /// type `face_type` (TRI3, QUAD4, TRI6, QUAD8, QUAD9; /NAME/connectivity is n_faces x its
  /// nodes), or of several types (none: "Mixed", /NAME/connectivity the `n_entries` values of
  /// each face's XDMF type code and nodes). None: not shown.
  void add_gap(const std::string &name, int n_points, int n_faces,
               std::optional<CellType> face_type, long long n_entries);
  /// Adds an output step at `time` [s]; add_field() adds its fields.
  void add_step(double time);
  /// Adds a field to the last step.
  void add_field(const FieldSpec &field);
  int n_steps() const { return static_cast<int>(steps_.size()); }
  /// Whether the last step has a field named `name`.
  bool has_field(const std::string &name) const;

  /// The XDMF text of the steps added so far.
  std::string text() const;
  /// Rank 0 writes text() under a temporary name and renames it, so a reader never sees a
  /// half-written file. Collective; an InputError on every rank if it cannot.
  void write() const;

private:
  struct Step
  {
    double time = 0.0;
    std::vector<FieldSpec> fields;
  };
  void write_grid(std::ostream &out, const std::string &indent, const Step *step, int index) const;
  struct Gap
  {
    std::string name;
    int n_points = 0;
    int n_faces = 0;
    std::optional<CellType> face_type; ///< none: mixed
    long long n_entries = 0;           ///< mixed only
  };
  void write_gap_grid(std::ostream &out, const std::string &indent, const Gap &gap,
                      const Step &step, int index) const;
  void write_attribute(std::ostream &out, const std::string &indent, const FieldSpec &f,
                       const std::string &rows, const std::string &path) const;
  void write_data_item(std::ostream &out, const std::string &indent, const std::string &path,
                       const std::string &dimensions, const char *number_type, int precision) const;

  MPI_Comm comm_;
  std::string xmf_path_;
  std::string h5_name_; ///< the HDF5 file's name, relative to the XDMF file's folder
  int n_nodes_;
  int n_cells_;
  XdmfTopology topology_;
  std::vector<Gap> gaps_;
  std::vector<Step> steps_;
};
} // namespace internal
} // namespace kiln
