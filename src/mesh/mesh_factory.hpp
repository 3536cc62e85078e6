#pragma once
/// The "Mesh" block of the input: which mesh, and where to split it into a gap.
#include "mesh/mesh.hpp"

#include <Teuchos_ParameterList.hpp>

#include <string>

namespace kiln
{
class MeshFactory
{
public:
  static Teuchos::ParameterList valid_parameters();
  /// `params` is the validated "Mesh" block; `where` names it in messages
  /// ("in.xml: Kiln/Mesh"). `mesh_file`, if not empty, overrides the input's
  /// mesh with an Exodus file (kiln --mesh FILE).
  MeshFactory(const Teuchos::ParameterList &params, const std::string &where,
              const std::string &mesh_file = "");

  /// The mesh as generated or read, checked, not yet split.
  Mesh build() const;
  /// The counts of the mesh build() gives after the gap split, without building it: the
  /// box's from "Cells", an Exodus file's from its header (without the twins of the split).
  struct Counts
  {
    long long cells = 0;
    long long nodes = 0;
    std::string source; ///< what sets them, for messages: `where/Box/"Cells" = {...}` or the file
  };
  Counts counts() const;
  /// The side sets to split at (none: empty), and the parameter that gives them.
  const std::vector<int> &gap_side_sets() const { return gap_side_sets_; }
  const std::string &gap_parameter() const { return gap_parameter_; }
  /// A one-line description ("box 4 x 4 x 4" or the Exodus file name).
  std::string description() const;

private:
  Teuchos::ParameterList params_;
  std::string where_;
  std::string type_;
  std::string exodus_file_;
  double scale_;
  std::vector<int> gap_side_sets_;
  std::string gap_parameter_;
};
} // namespace kiln
