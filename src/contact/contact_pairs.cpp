#include "contact/contact_pairs.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"

#include <cctype>

namespace kiln
{
Teuchos::ParameterList contact_pair_parameters()
{
  const MortarPairingOptions defaults;
  Teuchos::ParameterList p;
  p.set("Primary Side Set", 0,
        "the side set of one body's surface: the primary side, whose nodes the secondary's "
        "rows couple to; required [-]",
        nonnegative_int_validator());
  p.set("Secondary Side Set", 0,
        "the side set of the other body's surface, facing the primary one: the secondary "
        "side, on whose nodes the contact pressure lives; name the finer or softer of the two "
        "surfaces; required [-]",
        nonnegative_int_validator());
  p.set("Search Distance", defaults.search_distance,
        "the reach of the search: a primary face is integrated against a secondary face when "
        "their bounding boxes are within this distance; 0: the secondary surface's largest "
        "face diameter. Raise it when the bodies start apart by more than a face [m]",
        nonnegative_double_validator());
  p.set("Penetration Tolerance", defaults.penetration_tolerance,
        "how far a secondary node may start inside the primary body (-g0) before the input is "
        "refused; the default is above the round-off of touching surfaces and below any "
        "physical gap. Curved surfaces meshed apart that touch overlap by the facets' sag, "
        "about h^2 / (8 R) (h the face size, R the radius): raise it to that [m]",
        nonnegative_double_validator());
  p.set("Search Update Fraction", defaults.search_update_fraction,
        "when the search is redone: after an accepted step where a secondary node has slid "
        "relative to its twin point on the primary surface by more than this fraction of the "
        "size of its faces (their smallest diameter) since the last search, the pair's rows "
        "(partners, weights, areas), and the cells of its Heat Transfer term, are rebuilt in "
        "the current configuration (doc/contact.md, \"Small sliding\"); in (0, 1] [-]",
        double_range_validator(0.0, 1.0));
  p.set("Sliding Distance", defaults.sliding_distance,
        "the small-sliding limit: how far the pair may slide in all. The rows (and heat cells) "
        "redone during a run may only take partners among the primary nodes linked at set-up: "
        "those of the primary faces within \"Search Distance\" plus this of each secondary "
        "node's faces; a "
        "run that slides further ends with an error (exit 2) naming the pair and the node, its "
        "results up to the last accepted step kept. 0: the faces the search finds (about a "
        "ring of faces around the overlap). A larger distance costs a larger matrix graph [m]",
        nonnegative_double_validator());
  return p;
}

std::vector<ContactPairInput> contact_pairs(const Teuchos::ParameterList &contact,
                                            const std::string &path)
{
  std::vector<ContactPairInput> pairs;
  if (!contact.isSublist("Pairs"))
    return pairs;
  const Teuchos::ParameterList &list = contact.sublist("Pairs");
  for (auto it = list.begin(); it != list.end(); ++it)
  {
    const std::string &name = list.name(it);
    const Teuchos::ParameterList &entry = list.sublist(name);
    ContactPairInput pair;
    pair.name = name;
    pair.where = path + "/Pairs/\"" + name + "\"";
    // The name names its surface and history columns in the results (HDF5 groups, Exodus
    // variables, file names).
    bool plain = !name.empty();
    for (const char c : name)
      plain = plain &&
              (std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.');
    KILN_CHECK_INPUT(plain, pair.where,
                     "the pair's name names its surface (pair_NAME) and history columns "
                     "(normal_force_NAME) in the results; use letters, digits, '_', '-' and '.'");
    for (const auto &[key, id] :
         {std::pair<const char *, int *>{"Primary Side Set", &pair.primary_side_set},
          std::pair<const char *, int *>{"Secondary Side Set", &pair.secondary_side_set}})
    {
      *id = entry.get<int>(key);
      KILN_CHECK_INPUT(*id > 0, pair.where + "/\"" + key + "\"",
                       "is missing (or 0); name the side set of the body's surface in the mesh");
    }
    pair.options.search_distance = entry.get<double>("Search Distance");
    pair.options.penetration_tolerance = entry.get<double>("Penetration Tolerance");
    pair.options.search_update_fraction = entry.get<double>("Search Update Fraction");
    pair.options.sliding_distance = entry.get<double>("Sliding Distance");
    KILN_CHECK_INPUT(pair.options.search_update_fraction > 0.0,
                     pair.where + "/\"Search Update Fraction\"",
                     "is 0; give the fraction of a face the secondary nodes may slide, in (0, 1] "
                     "(default 0.25)");
    if (entry.isSublist("Heat Transfer"))
      pair.heat_transfer = entry.sublist("Heat Transfer");
    pairs.push_back(pair);
  }
  return pairs;
}
} // namespace kiln
