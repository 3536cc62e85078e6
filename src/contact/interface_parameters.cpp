#include "contact/interface_parameters.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"
#include "contact/contact_pairs.hpp"
#include "contact/interface_strategy.hpp"

#include <algorithm>

namespace kiln
{
Teuchos::ParameterList interface_parameters()
{
  Teuchos::ParameterList p("Contact");
  p.set("Enabled", true,
        "true: the two sides of the gap interact as \"Kind\" says; false: they are separate "
        "bodies that pass through each other [-]");
  const InterfaceKinds &kinds = interface_kinds();
  p.set("Kind", kinds.names().front(),
        "how the two sides of the gap interact (doc/contact.md, \"Interface kinds\"): " +
            kinds.describe() + " [-]",
        choice_validator(kinds.names()));
  p.set("Complementarity Scale", 1.0,
        "s in c = s (lambda + 2G) / sqrt(A), A the pair's area: weighs the gap against the "
        "pressure in each pair's condition; it changes the Newton path, not the converged "
        "answer; must be > 0 [-]",
        positive_double_validator());
  for (const auto &kind : kinds.entries())
    p.setParameters(kind.parameters);
  // Per gap: the same parameters (those given replace the ones above) and its side set.
  Teuchos::ParameterList each = p;
  each.remove("Enabled");
  each.set("Side Set", 0,
           "the gap side set these parameters are for (one of Mesh/\"Gap Side Sets\"); "
           "required [-]",
           nonnegative_int_validator());
  set_named_sublists(p, "Gaps",
                     "per gap, any name: the parameters above that differ for the gap at its "
                     "\"Side Set\" (with several gaps, Mesh/\"Gap Side Sets\")",
                     each);
  set_named_sublists(p, "Pairs",
                     "per contact pair between bodies meshed apart (issue 30; doc/contact.md, "
                     "\"Separately meshed bodies\"), any name: its two side sets and the "
                     "options of its mortar pairing",
                     contact_pair_parameters());
  return p;
}

namespace
{
/// Throws InputError unless `list` gives only parameters of its "Kind".
void check_kind_parameters(const Teuchos::ParameterList &list, const std::string &path)
{
  const std::string kind = list.get<std::string>("Kind");
  for (const auto &other : interface_kinds().entries())
    if (other.name != kind)
      for (auto it = other.parameters.begin(); it != other.parameters.end(); ++it)
      {
        const std::string &name = other.parameters.name(it);
        KILN_CHECK_INPUT(interface_kinds().find(kind)->parameters.isParameter(name) ||
                             !given_in_input(list, name),
                         path + "/\"" + name + "\"",
                         "applies to Kind \"" << other.name << "\", not to Kind \"" << kind
                                              << "\"; remove it or change the Kind");
      }
}
} // namespace

Teuchos::ParameterList pair_interface_parameters(const Teuchos::ParameterList &contact)
{
  Teuchos::ParameterList merged(contact);
  merged.remove("Gaps", false);
  merged.remove("Pairs", false);
  return merged;
}

Teuchos::ParameterList gap_interface_parameters(const Teuchos::ParameterList &contact,
                                                const int side_set)
{
  Teuchos::ParameterList merged(contact);
  merged.remove("Gaps");
  merged.remove("Pairs", false);
  const Teuchos::ParameterList &gaps = contact.sublist("Gaps");
  for (auto it = gaps.begin(); it != gaps.end(); ++it)
  {
    const Teuchos::ParameterList &gap = gaps.sublist(gaps.name(it));
    if (gap.get<int>("Side Set") != side_set)
      continue;
    for (auto entry = gap.begin(); entry != gap.end(); ++entry)
      if (gap.name(entry) != "Side Set" && given_in_input(gap, gap.name(entry)))
        merged.setEntry(gap.name(entry), gap.entry(entry));
  }
  return merged;
}

void check_interface_parameters(const Teuchos::ParameterList &contact,
                                const std::vector<int> &gap_side_sets, const std::string &path)
{
  check_kind_parameters(contact, path);
  const Teuchos::ParameterList &gaps = contact.sublist("Gaps");
  std::vector<int> named;
  for (auto it = gaps.begin(); it != gaps.end(); ++it)
  {
    const std::string where = path + "/Gaps/" + gaps.name(it);
    const Teuchos::ParameterList &gap = gaps.sublist(gaps.name(it));
    const int id = gap.get<int>("Side Set");
    std::string listed;
    for (const int g : gap_side_sets)
      listed += (listed.empty() ? "" : ", ") + std::to_string(g);
    KILN_CHECK_INPUT(std::find(gap_side_sets.begin(), gap_side_sets.end(), id) !=
                         gap_side_sets.end(),
                     where + "/\"Side Set\"",
                     (id == 0 ? std::string("is missing") : "is " + std::to_string(id))
                         << "; it must be one of the gap side sets ("
                         << (listed.empty() ? "none" : listed) << ", Kiln/Mesh)");
    KILN_CHECK_INPUT(std::find(named.begin(), named.end(), id) == named.end(),
                     where + "/\"Side Set\"",
                     "names side set " << id
                                       << ", which another entry of Gaps names already; "
                                          "give each gap one entry");
    named.push_back(id);
    check_kind_parameters(gap_interface_parameters(contact, id), where);
  }
}
} // namespace kiln
