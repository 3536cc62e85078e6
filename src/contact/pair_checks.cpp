#include "contact/pair_checks.hpp"

#include "base/errors.hpp"
#include "contact/face_search.hpp"
#include "mesh/contact_surface.hpp"

#include <algorithm>
#include <limits>
#include <sstream>

namespace kiln
{
void check_distinct_side_sets(const int primary_side_set, const int secondary_side_set,
                              const std::string &where)
{
  KILN_CHECK_INPUT(primary_side_set != secondary_side_set, where,
                   "\"Primary Side Set\" and \"Secondary Side Set\" are both side set "
                       << primary_side_set
                       << "; a pair joins two surfaces: name the side set of each body");
}

void check_surfaces_face_each_other(const ContactSurface &primary, const ContactSurface &secondary,
                                    const double reach, const std::string &where)
{
  const FaceSearch search(primary);
  bool within_reach = false;
  for (int s = 0; s < secondary.n_faces(); ++s)
    for (const int p : search.candidates(secondary.face_box(s), reach))
    {
      within_reach = true;
      if (dot(secondary.face_area_vector(s), primary.face_area_vector(p)) < 0.0)
        return;
    }
  const std::string sides = "side sets " + std::to_string(primary.side_set_id()) +
                            " (primary) and " + std::to_string(secondary.side_set_id()) +
                            " (secondary)";
  KILN_CHECK_INPUT(
      within_reach, where,
      [&]
      {
        // Only on the way to the error: every pair of faces.
        double nearest = std::numeric_limits<double>::max();
        for (int s = 0; s < secondary.n_faces(); ++s)
          for (int p = 0; p < primary.n_faces(); ++p)
            nearest = std::min(nearest, secondary.face_box(s).distance(primary.face_box(p)));
        std::ostringstream text;
        text << sides << " do not face each other: no secondary face is within the search "
             << "distance " << reach << " m of a primary face (the nearest face boxes are "
             << nearest << " m apart); check the side set ids, or raise \"Search Distance\"";
        return text.str();
      }());
  KILN_CHECK_INPUT(false, where,
                   sides << " do not face each other: the faces within the search distance "
                         << reach
                         << " m of each other look the same way (their normals out of their "
                            "bodies do not point against each other); name the side sets on "
                            "the two sides of the gap");
}
} // namespace kiln
