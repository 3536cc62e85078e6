#include "io/input_reader.hpp"

#include "base/errors.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_StringInputSource.hpp>
#include <Teuchos_XMLObject.hpp>
#include <Teuchos_XMLParameterListCoreHelpers.hpp>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <vector>

namespace kiln
{
namespace internal
{
bool parses_as(const std::string &text, const bool integer)
{
  const char *begin = text.c_str();
  char *end = nullptr;
  if (integer)
    std::strtoll(begin, &end, 10);
  else
    std::strtod(begin, &end);
  if (end == begin)
    return false;
  while (*end == ' ' || *end == '\t')
    ++end;
  return *end == '\0';
}

/// `{1, 2.5, 3}` -> its entries; every entry must parse.
bool array_parses_as(std::string text, const bool integer)
{
  const auto first = text.find_first_not_of(" \t");
  const auto last = text.find_last_not_of(" \t");
  if (first == std::string::npos || text[first] != '{' || text[last] != '}')
    return false;
  text = text.substr(first + 1, last - first - 1);
  if (text.find_first_not_of(" \t") == std::string::npos)
    return true; // {}
  std::stringstream s(text);
  std::string entry;
  while (std::getline(s, entry, ','))
    if (!parses_as(entry, integer))
      return false;
  return true;
}

void check_numbers(const Teuchos::XMLObject &node, const std::string &path,
                   const std::string &where)
{
  if (node.getTag() == "Parameter" && node.hasAttribute("type") && node.hasAttribute("value"))
  {
    const std::string type = node.getAttribute("type");
    const std::string value = node.getAttribute("value");
    const std::string name = node.hasAttribute("name") ? node.getAttribute("name") : "?";
    bool ok = true;
    if (type == "double" || type == "float")
      ok = parses_as(value, false);
    else if (type == "int" || type == "long long" || type == "short")
      ok = parses_as(value, true);
    else if (type == "Array(double)" || type == "Array(float)")
      ok = array_parses_as(value, false);
    else if (type == "Array(int)")
      ok = array_parses_as(value, true);
    KILN_CHECK_INPUT(ok, where + ": " + path + "/\"" + name + "\"",
                     "value \"" << value << "\" is not a" << (type[0] == 'A' ? "n " : " ") << type
                                << (type[0] == 'A' ? " like {1.0, 2.0}" : "")
                                << "; write the number alone, in SI units, without a unit");
  }
  const std::string child_path =
      node.getTag() == "ParameterList" && !path.empty() && node.hasAttribute("name")
          ? path + "/" + node.getAttribute("name")
          : (path.empty() && node.hasAttribute("name") ? node.getAttribute("name") : path);
  for (int i = 0; i < node.numChildren(); ++i)
    check_numbers(node.getChild(i), child_path, where);
}
} // namespace internal

Teuchos::ParameterList parse_input(const std::string &xml, const std::string &where)
{
  Teuchos::XMLObject root;
  try
  {
    root = Teuchos::StringInputSource(xml).getObject();
  }
  catch (const std::exception &e)
  {
    // Teuchos prefixes the parser's message with its own source location.
    std::string message = e.what();
    const auto line = message.find("XML parse error");
    throw InputError(where + ": not a well-formed XML file: " +
                     (line == std::string::npos ? message : message.substr(line)));
  }
  KILN_CHECK_INPUT(root.getTag() == "ParameterList", where,
                   "the root element is <" << root.getTag()
                                           << ">; a Kiln input is a <ParameterList name=\"Kiln\">");
  internal::check_numbers(root, "", where);
  try
  {
    Teuchos::ParameterList params;
    Teuchos::updateParametersFromXmlString(xml, Teuchos::ptrFromRef(params));
    return params;
  }
  catch (const std::exception &e)
  {
    throw InputError(where + ": cannot read the parameter list: " + e.what());
  }
}

Teuchos::ParameterList read_input(const std::string &path, const Teuchos::Comm<int> &comm)
{
  std::string text;
  bool ok = true;
  if (comm.getRank() == 0)
  {
    std::ifstream file(path);
    ok = static_cast<bool>(file);
    std::stringstream buffer;
    buffer << file.rdbuf();
    text = buffer.str();
  }
  check_collectively(comm, ok, path, "cannot open the input file; check the path");
  int length = static_cast<int>(text.size());
  Teuchos::broadcast(comm, 0, Teuchos::outArg(length));
  text.resize(length);
  if (length > 0)
    Teuchos::broadcast(comm, 0, length, text.data());
  return parse_input(text, path);
}
} // namespace kiln
