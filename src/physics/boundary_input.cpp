#include "physics/boundary_input.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"
#include "mesh/hex_geometry.hpp"

#include <Teuchos_Array.hpp>

#include <algorithm>
#include <sstream>

namespace kiln
{
void check_parameters_of_type(
    const Teuchos::ParameterList &p, const std::string &type,
    const std::map<std::string, std::vector<std::string>> &parameters_of_type,
    const std::string &path)
{
  const auto &uses = parameters_of_type.at(type);
  for (const auto &[other_type, parameters] : parameters_of_type)
    for (const auto &parameter : parameters)
      KILN_CHECK_INPUT(std::find(uses.begin(), uses.end(), parameter) != uses.end() ||
                           !given_in_input(p, parameter),
                       path + "/\"" + parameter + "\"",
                       "applies to Type \"" << other_type << "\", not to Type \"" << type
                                            << "\"; remove it or change the Type");
}

std::vector<int> read_boundary_side_sets(const Teuchos::ParameterList &p, const Mesh &mesh,
                                         const std::string &path, const std::string &gap_note)
{
  const auto &ids = p.get<Teuchos::Array<int>>("Side Sets");
  KILN_CHECK_INPUT(!ids.empty(), path + "/\"Side Sets\"",
                   "is missing or empty; list the side set ids the condition applies to, "
                   "e.g. <Parameter name=\"Side Sets\" type=\"Array(int)\" value=\"{1, 2}\"/>");
  std::ostringstream available;
  for (const auto &s : mesh.side_sets)
    if (!mesh.is_gap_side_set(s.id))
      available << (available.tellp() > 0 ? ", " : "") << s.id;
  std::vector<int> result;
  for (const int id : ids)
  {
    KILN_CHECK_INPUT(!mesh.is_gap_side_set(id), path + "/\"Side Sets\"",
                     "side set " << id << " is the gap; " << gap_note
                                 << ". Boundary side sets of this mesh: " << available.str());
    KILN_CHECK_INPUT(mesh.find_side_set(id) != nullptr, path + "/\"Side Sets\"",
                     "side set " << id << " is not in the mesh; its boundary side sets are "
                                 << available.str()
                                 << ". Use one of these ids, or check the mesh file");
    KILN_CHECK_INPUT(std::find(result.begin(), result.end(), id) == result.end(),
                     path + "/\"Side Sets\"",
                     "side set " << id
                                 << " is listed twice; its faces would take the condition twice "
                                    "(a flux doubled). List each side set once");
    result.push_back(id);
  }
  return result;
}

InteriorFaceCheck::InteriorFaceCheck(const Mesh &mesh) : mesh_(mesh)
{
  // The faces of every side set, and one pass over every cell face counting the cells that
  // have each (sorting all 6 n_cells faces instead took a tenth of the set-up at 60^3 cells).
  for (const auto &set : mesh.side_sets)
    for (int s = 0; s < set.n_sides(); ++s)
      side_faces_.push_back(mesh.face_key(set.cells[s], set.faces[s]));
  std::sort(side_faces_.begin(), side_faces_.end());
  side_faces_.erase(std::unique(side_faces_.begin(), side_faces_.end()), side_faces_.end());
  cells_with_face_.assign(side_faces_.size(), 0);
  if (side_faces_.empty())
    return;
  for (int c = 0; c < mesh.n_cells(); ++c)
    for (int f = 0; f < mesh.reference_cell(c).n_faces(); ++f)
    {
      const FaceKey key = mesh.face_key(c, f);
      if (key < side_faces_.front() || side_faces_.back() < key)
        continue;
      const auto it = std::lower_bound(side_faces_.begin(), side_faces_.end(), key);
      if (it != side_faces_.end() && *it == key)
        ++cells_with_face_[static_cast<std::size_t>(it - side_faces_.begin())];
    }
}

void InteriorFaceCheck::check(const std::vector<int> &ids, const std::string &path) const
{
  for (const int id : ids)
  {
    const SideSet &set = *mesh_.find_side_set(id);
    for (int s = 0; s < set.n_sides(); ++s)
    {
      const FaceKey key = mesh_.face_key(set.cells[s], set.faces[s]);
      const auto it = std::lower_bound(side_faces_.begin(), side_faces_.end(), key);
      KILN_CHECK_INPUT(cells_with_face_[static_cast<std::size_t>(it - side_faces_.begin())] == 1,
                       path,
                       "side set " << id << " has faces inside the body (cell " << set.cells[s] + 1
                                   << ", side " << set.faces[s] + 1
                                   << " is shared with another cell); boundary conditions "
                                      "apply to boundary faces only. To make it a gap, set "
                                      "Kiln/Mesh/\"Gap Side Set\" to "
                                   << id);
    }
  }
}
} // namespace kiln
