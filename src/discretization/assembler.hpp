#pragma once
/// Gathers and scatters between the owned system and element-local systems.
///
/// The sparsity graph is built once from coupling blocks: every unknown of a block's nodes
/// couples with every other (but the temperature rows' displacement columns, unless the
/// physics says a heat term reads u). The blocks are the cells and, as the physics says
/// (Couplings), the nodes of each gap face's terms; with `partners`, every block also holds the
/// partners of its contact nodes (twins across a gap, a pairing's rows). A rank assembles its own
/// cells and the gap faces whose side-a cell it owns: the residual into an overlap vector exported
/// (ADD) to the owned one; the Jacobian's owned rows straight into the owned Jacobian, the rows of
/// other ranks' nodes into a ghost matrix exported (ADD) to it, so no second copy of the matrix is
/// kept.
#include "discretization/dof_manager.hpp"
#include "discretization/local_system.hpp"
#include "mesh/mesh.hpp"

#include <Tpetra_CrsGraph.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include <functional>
#include <utility>
#include <vector>

namespace kiln
{
/// Which nodes couple in the Jacobian beyond each cell's own.
struct Couplings
{
  /// The nodes of gap face k's terms; by default its 4 side-a nodes (hex_face_nodes order)
  /// and their 4 twins. An empty function: no gap-face terms.
  std::function<std::vector<int>(int gap_face)> gap_face_nodes;
  /// Every block that holds a contact node also holds its partners (DofManager::partners():
  /// a split gap's twins, a pairing's row node and partners, both ways; contact mixes their
  /// rows).
  bool partners = false;
  /// Whether the temperature rows have displacement columns (terms of the heat equation that
  /// depend on u, such as the contact-dependent gap conductance). Without them the node
  /// blocks store 13 of 16 entries (T-u left out), and a term that puts a nonzero there is a
  /// bug (Assembler::add throws).
  bool temperature_depends_on_displacement = true;
  /// Blocks of other terms (cell, nodes), assembled by the owner of the cell and without the
  /// partners of their nodes (the heat across a pair's gap: a secondary face's nodes with a
  /// primary face's, whose partners the rank may not hold).
  std::vector<std::pair<int, std::vector<int>>> cell_blocks;
  /// The default: the side-a nodes and the twins of every gap face, no twin closure.
  static Couplings gap_faces(const Mesh &mesh);
};

class Assembler
{
public:
  using Vector = Tpetra::Vector<>;
  using Matrix = Tpetra::CrsMatrix<>;
  using Graph = Tpetra::CrsGraph<>;

  /// Builds the graphs; `couplings` defaults to Couplings::gap_faces(mesh).
  Assembler(const Mesh &mesh, const DofManager &dofs);
  Assembler(const Mesh &mesh, const DofManager &dofs, Couplings couplings);

  /// The owned Jacobian graph (fill-complete; domain and range: owned map).
  Teuchos::RCP<const Graph> owned_graph() const { return owned_graph_; }

  /// The overlap copy of an owned vector (Import); ghosts included.
  void gather(const Vector &owned, Vector &overlap) const;
  Teuchos::RCP<Vector> make_overlap_vector() const;

  /// Starts an assembly: zeroes the overlap residual and/or J (built on owned_graph(),
  /// fill-complete; the owned rows are summed into it directly, those of other ranks'
  /// nodes in a ghost matrix exported by finish()).
  void begin(bool residual, Matrix *J);
  /// Adds a local system whose local index k is the unknown with overlap
  /// local id lids[k] (see cell_lids, gap_face_lids).
  void add(const std::vector<LO> &lids, const LocalSystem &local);
  /// Exports to the owned residual f and/or adds the ghost rows to J (the J of begin();
  /// fill-complete on exit).
  void finish(Vector *f, Matrix *J);

  /// Overlap local ids of a cell's unknowns (node-major, n_node_fields each).
  std::vector<LO> cell_lids(int cell) const;
  /// Overlap local ids of the unknowns of a cell face's 4 nodes (hex_face_nodes order).
  std::vector<LO> face_lids(int cell, int face) const;
  /// The nodes of a gap face's block: Couplings::gap_face_nodes, then with_partners().
  std::vector<int> gap_face_nodes(int gap_face) const;
  /// What couples beyond each cell's own nodes.
  const Couplings &couplings() const { return couplings_; }
  /// Overlap local ids of gap_face_nodes() (node-major).
  std::vector<LO> gap_face_lids(int gap_face) const;
  /// `nodes` followed by the partners of its nodes that it lacks (with Couplings::partners;
  /// else as is).
  std::vector<int> with_partners(std::vector<int> nodes) const;
  /// Overlap local ids of the unknowns of `nodes` (node-major, n_node_fields each).
  std::vector<LO> node_lids(const std::vector<int> &nodes) const;
  /// Overlap local id of an unknown.
  LO lid(GO gid) const;

private:
  const Mesh &mesh_;
  const DofManager &dofs_;
  Couplings couplings_;
  /// pattern_[s * F + t]: whether rows of slot s have columns of slot t (F unknowns a node).
  std::vector<char> pattern_;
  std::vector<LO> row_columns_;    ///< add(): work
  std::vector<double> row_values_; ///< add(): work
  /// Sums a row (overlap local ids) into J or the ghost matrix.
  void add_row(LO lid, const LO *columns, const double *values, LO n);

  Teuchos::RCP<Graph> ghost_graph_; ///< rows: other ranks' dofs this rank assembles into
  Teuchos::RCP<Graph> owned_graph_;
  Teuchos::RCP<Matrix> ghost_matrix_;
  Teuchos::RCP<const Tpetra::Export<>> ghost_exporter_;
  std::vector<LO> owned_row_;    ///< per overlap local id: J's row, or invalid
  std::vector<LO> ghost_row_;    ///< per overlap local id: the ghost matrix's row, or invalid
  std::vector<LO> owned_column_; ///< per overlap local id: J's local column, or invalid
  /// Per global unknown id (F per node of the whole mesh, which every rank holds): its
  /// overlap local id, or invalid. lid() reads it: the overlap map's own lookup hashes on
  /// more than one rank, and took 1.5-2% of a run on two.
  std::vector<LO> overlap_lid_;
  Teuchos::RCP<Vector> overlap_residual_;
  /// overlap_residual_'s values while a residual is assembled (between begin() and finish()):
  /// taken once, not per add().
  Teuchos::ArrayRCP<double> residual_values_;
  bool assembling_residual_ = false;
  Matrix *J_ = nullptr; ///< the Jacobian being assembled
  /// J_'s local rows while it is assembled (begin() to finish()): its owned rows are summed
  /// into directly, without a Tpetra call per row (sumIntoLocalValues' views and checks
  /// took as long as the element kernels).
  Matrix::local_matrix_host_type local_J_;
};
} // namespace kiln
