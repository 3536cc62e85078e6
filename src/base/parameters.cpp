#include "base/parameters.hpp"

#include "base/errors.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_StrUtils.hpp>

#include <algorithm>
#include <cctype>
#include <functional>
#include <sstream>

namespace kiln
{
namespace internal
{
/// A validator given by a predicate on the entry and a sentence for the docs
/// and for the message ("must be > 0").
class PredicateValidator final : public Teuchos::ParameterEntryValidator
{
public:
  using Predicate = std::function<bool(const Teuchos::ParameterEntry &)>;
  PredicateValidator(std::string xml_name, std::string requirement, Predicate predicate,
                     ValidStringsList valid_strings = Teuchos::null)
      : xml_name_(std::move(xml_name)), requirement_(std::move(requirement)),
        predicate_(std::move(predicate)), valid_strings_(std::move(valid_strings))
  {
  }

  const std::string getXMLTypeName() const override { return xml_name_; }
  void printDoc(const std::string &doc, std::ostream &out) const override
  {
    Teuchos::StrUtils::printLines(out, "# ", doc);
    out << "#   " << requirement_ << "\n";
  }
  ValidStringsList validStringValues() const override { return valid_strings_; }
  void validate(const Teuchos::ParameterEntry &entry, const std::string &,
                const std::string &) const override
  {
    if (!predicate_(entry))
      throw Teuchos::Exceptions::InvalidParameterValue(requirement_);
  }

private:
  std::string xml_name_;
  std::string requirement_;
  Predicate predicate_;
  ValidStringsList valid_strings_;
};

template <typename T> bool holds(const Teuchos::ParameterEntry &e)
{
  return e.getAny(false).type() == typeid(T);
}

std::string lower(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

std::size_t edit_distance(const std::string &a, const std::string &b)
{
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j)
    row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i)
  {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j)
    {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::string value_text(const Teuchos::ParameterEntry &entry)
{
  std::ostringstream s;
  entry.leftshift(s, false);
  return s.str();
}

std::string joined(const std::vector<std::string> &names)
{
  std::string s;
  for (const auto &n : names)
    s += (s.empty() ? "\"" : ", \"") + n + "\"";
  return s;
}

const std::string pass_through_marker = " [passed as is to ";

bool is_pass_through(const Teuchos::ParameterEntry &valid_entry)
{
  return valid_entry.docString().find(pass_through_marker) != std::string::npos;
}

const std::string named_sublists_marker = " [any number of sublists, each named by the user]";
const std::string named_sublist_template = "<any name>";

bool holds_named_sublists(const Teuchos::ParameterEntry &valid_entry)
{
  return valid_entry.docString().find(named_sublists_marker) != std::string::npos;
}

const std::string number_or_sublist_marker =
    " [a number (Type \"Constant\" with that Value) or this sublist]";

bool is_number_or_sublist(const Teuchos::ParameterEntry &valid_entry)
{
  return valid_entry.isList() &&
         valid_entry.docString().find(number_or_sublist_marker) != std::string::npos;
}

/// A parameter (not a sublist) against its valid entry: the type, then the validator.
void check_value(const Teuchos::ParameterEntry &entry, const Teuchos::ParameterEntry &valid_entry,
                 const std::string &at, const std::string &name, const std::string &path)
{
  const std::string expected_type = valid_entry.getAny(false).typeName();
  KILN_CHECK_INPUT(entry.getAny(false).type() == valid_entry.getAny(false).type(), at,
                   "expected type \"" << expected_type << "\", got type \""
                                      << entry.getAny(false).typeName() << "\" (value "
                                      << value_text(entry) << "); write type=\"" << expected_type
                                      << "\"");
  if (const auto validator = valid_entry.validator(); !validator.is_null())
  {
    try
    {
      validator->validate(entry, name, path);
    }
    catch (const std::exception &e)
    {
      throw InputError(at + " = " + value_text(entry) + ": " + e.what());
    }
  }
}

void check_list(const Teuchos::ParameterList &user, const Teuchos::ParameterList &valid,
                const std::string &where, const std::string &path);

/// Every entry of `user` must be a sublist matching the template.
void check_named_sublists(const Teuchos::ParameterList &user, const Teuchos::ParameterList &valid,
                          const std::string &where, const std::string &path)
{
  const Teuchos::ParameterList &tmpl = valid.sublist(named_sublist_template);
  for (auto it = user.begin(); it != user.end(); ++it)
  {
    const std::string &name = user.name(it);
    KILN_CHECK_INPUT(user.entry(it).isList(), parameter_path(where, path, name),
                     "expected a sublist (<ParameterList name=\"" << name
                                                                  << "\">), got a parameter");
    check_list(Teuchos::getValue<Teuchos::ParameterList>(user.entry(it)), tmpl, where,
               path + "/" + name);
  }
}

void check_list(const Teuchos::ParameterList &user, const Teuchos::ParameterList &valid,
                const std::string &where, const std::string &path)
{
  std::vector<std::string> valid_names;
  for (auto it = valid.begin(); it != valid.end(); ++it)
    valid_names.push_back(valid.name(it));

  for (auto it = user.begin(); it != user.end(); ++it)
  {
    const std::string &name = user.name(it);
    const Teuchos::ParameterEntry &entry = user.entry(it);
    const std::string at = parameter_path(where, path, name);
    const Teuchos::ParameterEntry *valid_entry = valid.getEntryPtr(name);
    if (valid_entry == nullptr)
    {
      const std::string guess = closest_name(name, valid_names);
      std::ostringstream msg;
      msg << at << ": unknown " << (entry.isList() ? "sublist" : "parameter") << ".";
      if (!guess.empty())
        msg << " Did you mean \"" << guess << "\"?";
      msg << " Valid names in " << path << ": " << joined(valid_names) << ".";
      throw InputError(msg.str());
    }
    if (is_number_or_sublist(*valid_entry) && !entry.isList())
    {
      check_value(entry, Teuchos::getValue<Teuchos::ParameterList>(*valid_entry).getEntry("Value"),
                  at, name, path);
      continue;
    }
    if (valid_entry->isList())
    {
      KILN_CHECK_INPUT(entry.isList(), at,
                       "expected a sublist (<ParameterList name=\"" << name
                                                                    << "\">), got a parameter");
      if (is_pass_through(*valid_entry))
        continue;
      if (holds_named_sublists(*valid_entry))
      {
        check_named_sublists(Teuchos::getValue<Teuchos::ParameterList>(entry),
                             Teuchos::getValue<Teuchos::ParameterList>(*valid_entry), where,
                             path + "/" + name);
        continue;
      }
      check_list(Teuchos::getValue<Teuchos::ParameterList>(entry),
                 Teuchos::getValue<Teuchos::ParameterList>(*valid_entry), where, path + "/" + name);
      continue;
    }
    KILN_CHECK_INPUT(!entry.isList(), at,
                     "expected a parameter of type " << valid_entry->getAny(false).typeName()
                                                     << ", got a sublist");
    check_value(entry, *valid_entry, at, name, path);
  }
}
/// Adds every entry of `valid` missing from `list` (recursively; in
/// pass-through sublists too, so Kiln's defaults for NOX and Stratimikos
/// apply unless the input overrides them).
void set_defaults(Teuchos::ParameterList &list, const Teuchos::ParameterList &valid)
{
  for (auto it = valid.begin(); it != valid.end(); ++it)
  {
    const std::string &name = valid.name(it);
    const Teuchos::ParameterEntry &entry = valid.entry(it);
    if (entry.isList() && holds_named_sublists(entry))
    {
      Teuchos::ParameterList &named = list.sublist(name, false, entry.docString());
      const Teuchos::ParameterList &tmpl =
          Teuchos::getValue<Teuchos::ParameterList>(entry).sublist(named_sublist_template);
      for (auto n = named.begin(); n != named.end(); ++n)
        set_defaults(named.sublist(named.name(n)), tmpl);
    }
    else if (entry.isList())
    {
      if (is_number_or_sublist(entry) && list.isParameter(name) && !list.isSublist(name))
      {
        // A plain number: the sublist with Type "Constant" and that Value (given in input).
        const Teuchos::ParameterEntry number = list.getEntry(name);
        list.remove(name);
        list.sublist(name, false, entry.docString()).setEntry("Value", number);
      }
      set_defaults(list.sublist(name, false, entry.docString()),
                   Teuchos::getValue<Teuchos::ParameterList>(entry));
    }
    else if (!list.isParameter(name))
    {
      list.setEntry(name, entry);
      list.getEntryRCP(name)->setAnyValue(entry.getAny(false), true); // marks it a default
    }
  }
}
} // namespace internal

void set_pass_through_sublist(Teuchos::ParameterList &parent, const std::string &name,
                              const std::string &package, const std::string &doc,
                              const Teuchos::ParameterList &defaults)
{
  parent
      .sublist(name, false,
               doc + internal::pass_through_marker + package +
                   "; its names and types are checked at kiln --check and when a run starts]")
      .setParameters(defaults);
}

bool given_in_input(const Teuchos::ParameterList &list, const std::string &name)
{
  const Teuchos::ParameterEntry *entry = list.getEntryPtr(name);
  if (entry == nullptr)
    return false;
  if (!entry->isList())
    return !entry->isDefault();
  const auto &sub = Teuchos::getValue<Teuchos::ParameterList>(*entry);
  for (auto it = sub.begin(); it != sub.end(); ++it)
    if (given_in_input(sub, sub.name(it)))
      return true;
  return false;
}

void set_named_sublists(Teuchos::ParameterList &parent, const std::string &name,
                        const std::string &doc, const Teuchos::ParameterList &each)
{
  parent.sublist(name, false, doc + internal::named_sublists_marker)
      .sublist(internal::named_sublist_template, false, "one of them")
      .setParameters(each);
}

void set_number_or_sublist(Teuchos::ParameterList &parent, const std::string &name,
                           const std::string &doc, const Teuchos::ParameterList &each)
{
  parent.sublist(name, false, doc + internal::number_or_sublist_marker).setParameters(each);
}

std::string parameter_path(const std::string &where, const std::string &path,
                           const std::string &name)
{
  return (where.empty() ? "" : where + ": ") + path + "/\"" + name + "\"";
}

std::string closest_name(const std::string &name, const std::vector<std::string> &candidates)
{
  std::string best;
  std::size_t best_distance = std::string::npos;
  for (const auto &c : candidates)
  {
    const std::size_t d = internal::edit_distance(internal::lower(name), internal::lower(c));
    if (d < best_distance)
    {
      best_distance = d;
      best = c;
    }
  }
  // Accept up to a third of the name's length in edits (at least 2).
  const std::size_t limit = std::max<std::size_t>(2, name.size() / 3);
  return best_distance <= limit ? best : std::string();
}

Teuchos::ParameterList validated(const Teuchos::ParameterList &user,
                                 const Teuchos::ParameterList &valid, const std::string &where,
                                 const std::string &path)
{
  internal::check_list(user, valid, where, path);
  Teuchos::ParameterList result(user);
  internal::set_defaults(result, valid);
  return result;
}

using internal::holds;
using internal::PredicateValidator;
using Validator = Teuchos::RCP<const Teuchos::ParameterEntryValidator>;

Validator positive_double_validator()
{
  return Teuchos::rcp(new PredicateValidator(
      "kilnPositiveDouble", "must be > 0",
      [](const auto &e) { return holds<double>(e) && Teuchos::getValue<double>(e) > 0.0; }));
}

Validator nonnegative_double_validator()
{
  return Teuchos::rcp(new PredicateValidator(
      "kilnNonnegativeDouble", "must be >= 0",
      [](const auto &e) { return holds<double>(e) && Teuchos::getValue<double>(e) >= 0.0; }));
}

Validator double_range_validator(const double lo, const double hi)
{
  std::ostringstream req;
  req << "must be in [" << lo << ", " << hi << "]";
  return Teuchos::rcp(new PredicateValidator("kilnDoubleRange", req.str(),
                                             [lo, hi](const auto &e)
                                             {
                                               return holds<double>(e) &&
                                                      Teuchos::getValue<double>(e) >= lo &&
                                                      Teuchos::getValue<double>(e) <= hi;
                                             }));
}

Validator positive_int_validator()
{
  return Teuchos::rcp(new PredicateValidator(
      "kilnPositiveInt", "must be > 0",
      [](const auto &e) { return holds<int>(e) && Teuchos::getValue<int>(e) > 0; }));
}

Validator nonnegative_int_validator()
{
  return Teuchos::rcp(new PredicateValidator(
      "kilnNonnegativeInt", "must be >= 0",
      [](const auto &e) { return holds<int>(e) && Teuchos::getValue<int>(e) >= 0; }));
}

namespace internal
{
template <typename T>
Validator array_validator(const int size, const bool positive, const std::string &xml_name)
{
  std::ostringstream req;
  req << "must have "
      << (size > 0 ? "exactly " + std::to_string(size) + " entries" : "at least 1 entry")
      << (positive ? ", each > 0" : "");
  return Teuchos::rcp(new PredicateValidator(
      xml_name, req.str(),
      [size, positive](const auto &e)
      {
        if (!holds<Teuchos::Array<T>>(e))
          return false;
        const auto &a = Teuchos::getValue<Teuchos::Array<T>>(e);
        if ((size > 0 && a.size() != size) || a.size() == 0)
          return false;
        return !positive || std::all_of(a.begin(), a.end(), [](const T v) { return v > T(0); });
      }));
}
} // namespace internal

Validator positive_double_array_validator(const int size)
{
  return internal::array_validator<double>(size, true, "kilnPositiveDoubleArray");
}
Validator positive_int_array_validator(const int size)
{
  return internal::array_validator<int>(size, true, "kilnPositiveIntArray");
}
Validator double_array_validator(const int size)
{
  return internal::array_validator<double>(size, false, "kilnDoubleArray");
}

Validator choice_validator(const std::vector<std::string> &choices)
{
  const std::string req = "must be one of " + internal::joined(choices);
  auto strings = Teuchos::rcp(new Teuchos::Array<std::string>(choices.begin(), choices.end()));
  return Teuchos::rcp(new PredicateValidator(
      "kilnChoice", req,
      [choices](const auto &e)
      {
        return holds<std::string>(e) &&
               std::find(choices.begin(), choices.end(), Teuchos::getValue<std::string>(e)) !=
                   choices.end();
      },
      strings));
}
} // namespace kiln
