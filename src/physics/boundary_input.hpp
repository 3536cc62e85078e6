#pragma once
/// Input checks shared by the thermal and mechanical boundary conditions.
#include "mesh/mesh.hpp"

#include <Teuchos_ParameterList.hpp>

#include <map>
#include <string>
#include <vector>

namespace kiln
{
/// Throws InputError if `p` (a validated boundary-condition sublist at `path`) gives a
/// parameter that belongs to another Type: `parameters_of_type` maps each Type to the
/// parameters it reads besides Type and Side Sets.
void check_parameters_of_type(
    const Teuchos::ParameterList &p, const std::string &type,
    const std::map<std::string, std::vector<std::string>> &parameters_of_type,
    const std::string &path);

/// The ids of p's "Side Sets" (Array(int)): at least one, each in the mesh and not the gap
/// side set; `gap_note` tells the user what happens at the gap instead. Throws InputError.
std::vector<int> read_boundary_side_sets(const Teuchos::ParameterList &p, const Mesh &mesh,
                                         const std::string &path, const std::string &gap_note);

/// Finds side sets with faces inside the body (faces shared by two cells).
class InteriorFaceCheck
{
public:
  /// Counts, once, the cells that have each face of the mesh's side sets.
  explicit InteriorFaceCheck(const Mesh &mesh);
  /// Throws InputError if a side set of `ids` has a face shared by two cells; `path` names
  /// the "Side Sets" parameter of the condition.
  void check(const std::vector<int> &ids, const std::string &path) const;

private:
  const Mesh &mesh_;
  std::vector<FaceKey> side_faces_;  ///< of every side set, sorted, unique
  std::vector<int> cells_with_face_; ///< the cells that have side_faces_[i]
};
} // namespace kiln
