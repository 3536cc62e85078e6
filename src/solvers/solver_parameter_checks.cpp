#include "solvers/solver_parameter_checks.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"
#include "solvers/nox_parameter_names.hpp"
#include "solvers/package_errors.hpp"
#include "solvers/package_parameters.hpp"

#include <MueLu_ParameterListInterpreter.hpp>
#include <NOX_Solver_SolverUtils.H>
#include <Teuchos_Array.hpp>
#include <Tpetra_Map.hpp>

#include <algorithm>
#include <iostream>
#include <map>
#include <sstream>
#include <utility>
#include <vector>

namespace kiln
{
namespace internal
{
namespace
{
using Teuchos::ParameterEntry;
using Teuchos::ParameterList;
using Teuchos::RCP;
using Node = Tpetra::Map<>::node_type;

/// Types of value an input file can give (those of the input reader).
bool settable_in_input(const ParameterEntry &e)
{
  if (e.isList())
    return true;
  const std::type_info &t = e.getAny(false).type();
  return t == typeid(int) || t == typeid(double) || t == typeid(bool) || t == typeid(std::string) ||
         t == typeid(Teuchos::Array<int>) || t == typeid(Teuchos::Array<double>) ||
         t == typeid(Teuchos::Array<std::string>);
}

std::string quoted(const std::vector<std::string> &names)
{
  std::string s;
  for (const auto &n : names)
    s += (s.empty() ? "\"" : ", \"") + n + "\"";
  return s;
}

std::string value_text(const ParameterEntry &entry)
{
  std::ostringstream s;
  entry.leftshift(s, false);
  return s.str();
}

/// How one package's list is checked and named in messages.
struct PackageList
{
  std::string package; ///< "Belos", "NOX"
  /// Sentences added to the message for an unknown name.
  std::map<std::string, std::string> hints;
  /// Parameters that may also be given as a sublist, with the sublist's valid names.
  std::map<std::string, ParameterList> list_forms;
};

void check_list(const ParameterList &user, const ParameterList &valid, const std::string &at,
                const PackageList &p);

[[noreturn]] void unknown_name(const std::string &here, const std::string &name, const bool list,
                               const std::vector<std::string> &names, const PackageList &p)
{
  std::ostringstream m;
  m << here << ": unknown " << (list ? "sublist" : "parameter") << " of " << p.package << ".";
  const std::string guess = closest_name(name, names);
  if (!guess.empty())
    m << " Did you mean \"" << guess << "\"?";
  if (const auto hint = p.hints.find(name); hint != p.hints.end())
    m << " " << hint->second << ".";
  m << " Valid names here: " << quoted(names) << ". " << p.package
    << " does not know this name: it would be ignored (the setting would have no effect) or "
       "refused later; correct it or remove it";
  throw InputError(m.str());
}

/// A string value against the choices of the valid entry's validator, if it has some.
void check_choice(const ParameterEntry &entry, const ParameterEntry &valid_entry,
                  const std::string &here, const PackageList &p)
{
  const auto validator = valid_entry.validator();
  if (validator.is_null() || validator->validStringValues().is_null() ||
      entry.getAny(false).type() != typeid(std::string))
    return;
  const auto &choices = *validator->validStringValues();
  const std::string value = Teuchos::getValue<std::string>(entry);
  if (std::find(choices.begin(), choices.end(), value) != choices.end())
    return;
  const std::vector<std::string> names(choices.begin(), choices.end());
  std::ostringstream m;
  m << here << " = " << value << ": not one of the choices of " << p.package << ".";
  const std::string guess = closest_name(value, names);
  if (!guess.empty())
    m << " Did you mean \"" << guess << "\"?";
  m << " Choices: " << quoted(names);
  throw InputError(m.str());
}

void check_entry(const std::string &name, const ParameterEntry &entry,
                 const ParameterEntry &valid_entry, const std::string &at, const PackageList &p)
{
  const std::string here = at + "/\"" + name + "\"";
  if (valid_entry.isList())
  {
    KILN_CHECK_INPUT(entry.isList(), here,
                     "expected a sublist (<ParameterList name=\"" << name
                                                                  << "\">), got a parameter");
    check_list(Teuchos::getValue<ParameterList>(entry),
               Teuchos::getValue<ParameterList>(valid_entry), at + "/" + name, p);
    return;
  }
  KILN_CHECK_INPUT(settable_in_input(valid_entry), here,
                   "is set by Kiln or by a program (type "
                       << valid_entry.getAny(false).typeName()
                       << "), not from an input file: remove it");
  const std::string expected = valid_entry.getAny(false).typeName();
  if (entry.isList())
  {
    const auto form = p.list_forms.find(name);
    KILN_CHECK_INPUT(form != p.list_forms.end(), here,
                     "expected a parameter of type \"" << expected << "\", got a sublist");
    check_list(Teuchos::getValue<ParameterList>(entry), form->second, at + "/" + name, p);
    return;
  }
  KILN_CHECK_INPUT(entry.getAny(false).type() == valid_entry.getAny(false).type(), here,
                   "expected type \"" << expected << "\", got type \""
                                      << entry.getAny(false).typeName() << "\" (value "
                                      << value_text(entry) << "); write type=\"" << expected
                                      << "\"");
  check_choice(entry, valid_entry, here, p);
}

/// Every entry of `user` against `valid`; an empty valid list takes any names.
void check_list(const ParameterList &user, const ParameterList &valid, const std::string &at,
                const PackageList &p)
{
  if (valid.numParams() == 0)
    return;
  std::vector<std::string> names;
  for (auto it = valid.begin(); it != valid.end(); ++it)
    if (settable_in_input(valid.entry(it)) && valid.entry(it).docString() != written_by_nox)
      names.push_back(valid.name(it));
  for (auto it = user.begin(); it != user.end(); ++it)
  {
    const std::string &name = user.name(it);
    const ParameterEntry *valid_entry = valid.getEntryPtr(name);
    if (valid_entry == nullptr)
      unknown_name(at + "/\"" + name + "\"", name, user.entry(it).isList(), names, p);
    check_entry(name, user.entry(it), *valid_entry, at, p);
  }
}

/// `list` with the content of its sublist `name` left unchecked (any names).
void leave_unchecked(ParameterList &list, const std::string &name)
{
  list.remove(name, false);
  list.sublist(name);
}

/// NOX's own valid list of the one sublist it validates that an input can use.
void add_nox_validated_lists(ParameterList &valid)
{
  ParameterList options;
  NOX::Solver::validateSolverOptionsSublist(options); // sets every valid name's default
  valid.sublist("Solver Options").setParameters(options);
}

PackageList nox_package()
{
  PackageList p{"NOX", {}, {}};
  p.hints["Status Tests"] =
      "Kiln sets NOX's status tests itself, from Solver/\"Absolute Tolerance\", \"Relative "
      "Tolerance\" and \"Maximum Iterations\"";
  p.hints["Thyra Group Options"] = "Kiln builds NOX's Thyra group itself and does not read it";
  ParameterList &information = p.list_forms["Output Information"];
  for (const char *name :
       {"Error", "Warning", "Outer Iteration", "Inner Iteration", "Parameters", "Details",
        "Outer Iteration StatusTest", "Linear Solver Details", "Test Details", "Stepper Iteration",
        "Stepper Details", "Stepper Parameters", "Debug"})
    information.set(name, false);
  return p;
}
} // namespace

namespace
{
/// A MueLu list, checked as MueLu reads it; `where` names it.
void check_muelu_list(ParameterList muelu, const RCP<const Teuchos::Comm<int>> &comm,
                      const std::string &where)
{
  // MueLu's reuse of a hierarchy for new values inserts into the Jacobian's static graph in
  // Trilinos 13.2 (both "RP" and "tP" stop the first re-setup); Kiln keeps an unchanged
  // hierarchy itself (Solver/"Reuse").
  if (muelu.isType<std::string>("reuse: type") && muelu.get<std::string>("reuse: type") != "none")
    throw_input_error(where, "\"reuse: type\" = \"" + muelu.get<std::string>("reuse: type") +
                                 "\" fails in Debian's Trilinos 13.2 (MueLu inserts into the "
                                 "Jacobian's static graph); remove it (or set \"none\"): Kiln "
                                 "keeps the preconditioner while the Jacobian is unchanged "
                                 "(Solver/Reuse, doc/solvers.md)");
  // MueLu prints its distance to every valid name on std::cout; the message
  // has the closest one.
  std::ostringstream muelu_chatter;
  std::streambuf *const cout_buffer = std::cout.rdbuf(muelu_chatter.rdbuf());
  try
  {
    as_input_error(
        *comm, where,
        [&] { MueLu::ParameterListInterpreter<double, int, long long, Node> check(muelu, comm); });
  }
  catch (...)
  {
    std::cout.rdbuf(cout_buffer);
    throw;
  }
  std::cout.rdbuf(cout_buffer);
}

/// The value of the string `type` of `list` ("Solver Type"), and whether the input gave it.
std::pair<std::string, bool> chosen_type(const ParameterList &list, const std::string &type)
{
  if (!list.isType<std::string>(type))
    return {"", false};
  return {list.get<std::string>(type), given_in_input(list, type)};
}

/// Packages read only the sublist of `types` ("Solver Types") named by the choice `type`
/// ("Solver Type"); a sublist the input fills for another name would be ignored without a
/// word. `read`: the names read with that choice (the choice itself; "MueLu" and "Block
/// Triangular" where either may be). An empty `types`: the sublists are `list`'s own, beside
/// the choice (NOX's "Line Search"/"Method" and "Backtrack").
void check_only_chosen_sublists(const ParameterList &list, const std::string &type,
                                const std::string &types, const std::vector<std::string> &read,
                                const std::string &where, const std::string &package)
{
  const auto [choice, given] = chosen_type(list, type);
  if ((!types.empty() && !list.isSublist(types)) || choice.empty())
    return;
  const ParameterList &sublists = types.empty() ? list : list.sublist(types);
  const std::string at = types.empty() ? where : where + "/" + types;
  const std::string beside = types.empty() ? "beside them" : "beside \"" + types + "\"";
  const std::string to = types.empty() ? "\"" + choice + "\"" : types + "/\"" + choice + "\"";
  for (auto it = sublists.begin(); it != sublists.end(); ++it)
  {
    const std::string &name = sublists.name(it);
    if (!sublists.entry(it).isList() || !given_in_input(sublists, name) ||
        std::find(read.begin(), read.end(), name) != read.end())
      continue;
    std::ostringstream m;
    m << at << "/" << name << ": parameters for \"" << name << "\", but the \"" << type << "\" "
      << beside << " is \"" << choice << "\"" << (given ? "" : " (Kiln's default)") << ", so "
      << package << " would ignore them; set \"" << type << "\" to \"" << name
      << "\" or move them to " << to;
    throw InputError(m.str());
  }
}
} // namespace

void check_muelu_parameters(const ParameterList &stratimikos,
                            const RCP<const Teuchos::Comm<int>> &comm, const std::string &where)
{
  const bool block_triangular =
      stratimikos.isType<std::string>("Preconditioner Type") &&
      stratimikos.get<std::string>("Preconditioner Type") == "Block Triangular";
  const std::string types = "Preconditioner Types";
  if (uses_muelu(stratimikos) || block_triangular)
  {
    ParameterList muelu;
    if (stratimikos.isSublist(types) && stratimikos.sublist(types).isSublist("MueLu"))
      muelu = stratimikos.sublist(types).sublist("MueLu");
    check_muelu_list(muelu, comm, where + "/" + types + "/MueLu");
  }
  // The blocks' own MueLu lists (BlockTriangularPreconditionerFactory), also where Kiln picks
  // another type (fewer than 50,000 unknowns): a misspelling there is not left for later.
  if (stratimikos.isSublist(types) && stratimikos.sublist(types).isSublist("Block Triangular"))
  {
    const ParameterList &blocks = stratimikos.sublist(types).sublist("Block Triangular");
    for (const char *block : {"Temperature", "Displacement"})
      if (blocks.isSublist(block))
        check_muelu_list(blocks.sublist(block), comm,
                         where + "/" + types + "/Block Triangular/" + block);
  }
}

void check_stratimikos_parameters(const ParameterList &stratimikos, const ParameterList &valid,
                                  const std::string &where)
{
  // Stratimikos' own names; the lists of its solvers and preconditioners below are left to
  // the packages (MueLu: check_muelu_parameters), but for Belos'.
  ParameterList top(valid);
  leave_unchecked(top, "Preconditioner Types");
  ParameterList &solvers = top.sublist("Linear Solver Types");
  std::vector<std::string> names;
  for (auto it = solvers.begin(); it != solvers.end(); ++it)
    names.push_back(solvers.name(it));
  for (const std::string &name : names)
    leave_unchecked(solvers, name);
  check_list(stratimikos, top, where, PackageList{"Stratimikos", {}, {}});
  const std::string belos = "Linear Solver Types";
  if (stratimikos.isSublist(belos) && stratimikos.sublist(belos).isSublist("Belos"))
    check_list(stratimikos.sublist(belos).sublist("Belos"), valid.sublist(belos).sublist("Belos"),
               where + "/" + belos + "/Belos", PackageList{"Belos", {}, {}});
  // Only the chosen solver's and preconditioner's sublists are read.
  check_only_chosen_sublists(stratimikos, "Linear Solver Type", belos,
                             {chosen_type(stratimikos, "Linear Solver Type").first}, where,
                             "Stratimikos");
  if (stratimikos.isSublist(belos) && stratimikos.sublist(belos).isSublist("Belos"))
  {
    const ParameterList &solver = stratimikos.sublist(belos).sublist("Belos");
    check_only_chosen_sublists(solver, "Solver Type", "Solver Types",
                               {chosen_type(solver, "Solver Type").first},
                               where + "/" + belos + "/Belos", "Belos");
  }
  // Block Triangular reads the MueLu list too; unless the input names the type, Kiln picks
  // MueLu, Block Triangular or Direct by the problem (create_linear_solver), so any of their
  // lists is read.
  const auto [preconditioner, given] = chosen_type(stratimikos, "Preconditioner Type");
  std::vector<std::string> read{preconditioner};
  if (!given)
    read = {"MueLu", "Block Triangular", "Direct"};
  else if (preconditioner == "Block Triangular")
    read = {"MueLu", "Block Triangular"};
  check_only_chosen_sublists(stratimikos, "Preconditioner Type", "Preconditioner Types", read,
                             where, "Stratimikos");
  // Kiln's block triangular preconditioner: its two sublists are MueLu's
  // (check_muelu_parameters).
  const std::string types = "Preconditioner Types";
  if (stratimikos.isSublist(types) && stratimikos.sublist(types).isSublist("Block Triangular") &&
      valid.sublist(types).isSublist("Block Triangular"))
  {
    ParameterList blocks(valid.sublist(types).sublist("Block Triangular"));
    leave_unchecked(blocks, "Temperature");
    leave_unchecked(blocks, "Displacement");
    check_list(stratimikos.sublist(types).sublist("Block Triangular"), blocks,
               where + "/" + types + "/Block Triangular",
               PackageList{"Kiln's Block Triangular preconditioner", {}, {}});
  }
}

void check_nox_parameters(const ParameterList &nox, const std::string &where)
{
  ParameterList valid = nox_known_parameters();
  add_nox_validated_lists(valid);
  // The tensor method reads its own direction and line search names ("Tensor", "Curvilinear").
  const bool tensor = nox.isType<std::string>("Nonlinear Solver") &&
                      nox.get<std::string>("Nonlinear Solver") == "Tensor Based";
  if (tensor)
  {
    leave_unchecked(valid, "Direction");
    leave_unchecked(valid, "Line Search");
  }
  check_list(nox, valid, where, nox_package());
  if (tensor)
    return;
  // The line search and the direction read the sublist of their "Method" (NOX's "NonlinearCG"
  // direction reads "Nonlinear CG"); the NonlinearCG line search reads none.
  if (nox.isSublist("Line Search"))
  {
    const ParameterList &line_search = nox.sublist("Line Search");
    check_only_chosen_sublists(line_search, "Method", "",
                               {chosen_type(line_search, "Method").first}, where + "/Line Search",
                               "NOX");
  }
  if (nox.isSublist("Direction"))
  {
    const ParameterList &direction = nox.sublist("Direction");
    const std::string method = chosen_type(direction, "Method").first;
    check_only_chosen_sublists(direction, "Method", "",
                               {method == "NonlinearCG" ? std::string("Nonlinear CG") : method},
                               where + "/Direction", "NOX");
  }
}

void check_solver_parameters(const ParameterList &solver, const ParameterList &stratimikos,
                             const ParameterList &stratimikos_valid,
                             const RCP<const Teuchos::Comm<int>> &comm, const std::string &where)
{
  check_nox_parameters(solver.sublist("Nonlinear Solver"), where + "/Nonlinear Solver");
  check_stratimikos_parameters(stratimikos, stratimikos_valid, where + "/Linear Solver");
  check_muelu_parameters(stratimikos, comm, where + "/Linear Solver");
}
} // namespace internal
} // namespace kiln
