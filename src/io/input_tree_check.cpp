#include "io/input_tree_check.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"
#include "io/input_reader.hpp"
#include "io/input_values.hpp"

#include <algorithm>
#include <map>
#include <utility>

namespace kiln::internal
{
namespace
{
// ---------------------------------------------------------------------------
// The text: size, emptiness, binary content, nesting depth.

/// Teuchos' XMLParser's letters and name characters (bytes, Latin-1).
bool is_letter(const unsigned char c)
{
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= 0xC0 && c <= 0xD6) ||
         (c >= 0xD8 && c <= 0xF6) || c >= 0xF8;
}

bool is_name_char(const unsigned char c)
{
  return is_letter(c) || (c >= '0' && c <= '9') || c == '.' || c == '-' || c == '_' || c == ':' ||
         c == 0xB7;
}

// ---------------------------------------------------------------------------
// The tree: only <ParameterList name> and <Parameter name type value>, each name once.

class TreeChecker
{
public:
  TreeChecker(const std::vector<StartTag> &tags, const std::string &where)
      : tags_(tags), where_(where)
  {
  }

  void check_root(const Teuchos::XMLObject &root)
  {
    const StartTag &tag = next();
    KILN_CHECK_INPUT(root.getTag() == "ParameterList", where_,
                     "the root element is <" << root.getTag()
                                             << ">; a Kiln input is a <ParameterList "
                                                "name=\"Kiln\">");
    const std::string name = root.hasAttribute("name") ? root.getAttribute("name") : "";
    KILN_CHECK_INPUT(name == "Kiln", at(tag),
                     "the root <ParameterList> "
                         << (root.hasAttribute("name") ? "is named \"" + name + "\""
                                                       : std::string("has no name"))
                         << "; a Kiln input's root is <ParameterList name=\"Kiln\">: "
                            "write that");
    check_attributes(tag, "ParameterList", {"name"}, "Kiln", "");
    check_list(root, "Kiln");
  }

private:
  const StartTag &next()
  {
    static const StartTag unknown;
    return index_ < tags_.size() ? tags_[index_++] : unknown;
  }

  std::string at(const StartTag &tag) const
  {
    return tag.line > 0 ? where_ + ":" + std::to_string(tag.line) : where_;
  }

  void check_attributes(const StartTag &tag, const std::string &element,
                        const std::vector<std::string> &allowed, const std::string &path,
                        const std::string &name) const
  {
    for (const auto &attribute : tag.attributes)
    {
      if (std::find(allowed.begin(), allowed.end(), attribute) != allowed.end())
        continue;
      const std::string guess = closest_name(attribute, allowed);
      KILN_CHECK_INPUT(false, at(tag) + ": " + (name.empty() ? path : path + "/\"" + name + "\""),
                       "unknown attribute \""
                           << attribute << "\" on <" << element << ">"
                           << (guess.empty() ? "" : " (did you mean \"" + guess + "\"?)") << "; a <"
                           << element << "> takes " << quoted_list(allowed));
    }
  }

  void check_no_text(const Teuchos::XMLObject &node, const StartTag &tag, const std::string &where,
                     const std::string &what) const
  {
    if (node.numContentLines() == 0)
      return;
    std::string text;
    for (int i = 0; i < node.numContentLines() && text.size() < 40; ++i)
      text += node.getContentLine(i);
    text = trimmed(text).substr(0, 40);
    KILN_CHECK_INPUT(false, at(tag) + ": " + where,
                     "stray text \"" << text << "\" " << what
                                     << "; remove it (comments go in <!-- -->)");
  }

  void check_list(const Teuchos::XMLObject &list, const std::string &path)
  {
    const StartTag &list_tag = index_ > 0 ? tags_[index_ - 1] : tags_.front();
    check_no_text(list, list_tag, path, "in the list, outside any <Parameter>");
    std::map<std::string, std::pair<int, bool>> first_of_name; // line, whether a list
    for (int i = 0; i < list.numChildren(); ++i)
    {
      const Teuchos::XMLObject &child = list.getChild(i);
      const StartTag &tag = next();
      const std::string &element = child.getTag();
      if (element != "Parameter" && element != "ParameterList")
      {
        const std::string guess = closest_name(element, {"Parameter", "ParameterList"});
        KILN_CHECK_INPUT(false, at(tag) + ": " + path,
                         "unexpected element <"
                             << element << ">"
                             << (guess.empty() ? "" : " (did you mean <" + guess + ">?)")
                             << "; a list holds <Parameter name=\"...\" type=\"...\" "
                                "value=\"...\"/> and <ParameterList name=\"...\"> elements only");
      }
      const bool is_list = element == "ParameterList";
      KILN_CHECK_INPUT(
          child.hasAttribute("name") && !child.getAttribute("name").empty(), at(tag) + ": " + path,
          "a <" << element << "> "
                << (child.hasAttribute("name") ? "with an empty name" : "without a name attribute")
                << "; write <" << element << " name=\"...\""
                << (is_list ? ">" : " type=\"...\" value=\"...\"/>"));
      const std::string name = child.getAttribute("name");
      const auto [previous, inserted] =
          first_of_name.emplace(name, std::make_pair(tag.line, is_list));
      const bool both_lists = is_list && previous->second.second;
      KILN_CHECK_INPUT(inserted, at(tag) + ": " + path + "/\"" + name + "\"",
                       "is given twice in "
                           << path << " (lines " << previous->second.first << " and " << tag.line
                           << "); only one can apply: "
                           << (both_lists ? "merge the two lists into one" : "remove one"));
      if (is_list)
      {
        check_attributes(tag, element, {"name"}, path, name);
        check_list(child, path + "/" + name);
      }
      else
        check_parameter(child, tag, path, name);
    }
  }

  void check_parameter(const Teuchos::XMLObject &p, const StartTag &tag, const std::string &path,
                       const std::string &name)
  {
    const std::string where = at(tag) + ": " + path + "/\"" + name + "\"";
    check_attributes(tag, "Parameter",
                     {"name", "type", "value", "docString", "isDefault", "isUsed"}, path, name);
    KILN_CHECK_INPUT(p.hasAttribute("type"), where,
                     "has no type attribute; write type=\"...\", one of "
                         << quoted_list(kiln_types())
                         << " (kiln --print-parameters shows each parameter's type)");
    const std::string type = p.getAttribute("type");
    if (!is_known_type(type))
    {
      const std::string guess = suggested_type(type);
      KILN_CHECK_INPUT(false, where,
                       "unknown type \""
                           << type << "\""
                           << (guess.empty() ? "" : " (did you mean \"" + guess + "\"?)")
                           << "; Kiln's parameters have the types " << quoted_list(kiln_types())
                           << " (kiln --print-parameters shows each one's type)");
    }
    KILN_CHECK_INPUT(p.numChildren() == 0, where,
                     "holds a <" << p.getChild(0).getTag()
                                 << "> element; a <Parameter> holds its value in value=\"...\" "
                                    "and nothing else: close it with />");
    check_no_text(p, tag, path + "/\"" + name + "\"",
                  "inside the <Parameter>; its value goes in value=\"...\"");
    KILN_CHECK_INPUT(p.hasAttribute("value"), where,
                     "has no value attribute; write value=\"...\" (type " << type << ")");
    const std::string value = p.getAttribute("value");
    const std::string problem = value_problem(value, type);
    KILN_CHECK_INPUT(problem.empty(), where, "value \"" << value << "\" " << problem);
  }

  const std::vector<StartTag> &tags_;
  std::string where_;
  std::size_t index_ = 0;
};
} // namespace

/// Follows the tokens of Teuchos' XMLParser (comments, <?xml ?> declarations, start,
/// empty and end tags, quoted attribute values) far enough to count how deeply the
/// elements nest and to note each start tag's line and attributes. It stops where
/// the text stops looking like XML (Teuchos' parser reports that) but never before
/// Teuchos would, so that a text nested deeper than max_input_depth is refused before
/// Teuchos builds (and recursively destroys) a tree that deep.
std::vector<StartTag> scan_start_tags(const std::string &xml, const std::string &where)
{
  std::vector<StartTag> tags;
  const std::size_t n = xml.size();
  std::size_t i = 0;
  int line = 1, depth = 0;
  const auto advance = [&](const std::size_t to)
  {
    for (; i < to && i < n; ++i)
      if (xml[i] == '\n')
        ++line;
  };
  while (i < n)
  {
    if (xml[i] != '<')
    {
      advance(i + 1);
      continue;
    }
    const std::size_t start = i;
    if (xml.compare(start, 4, "<!--") == 0)
    {
      const std::size_t end = xml.find("-->", start + 4);
      advance(end == std::string::npos ? n : end + 3);
      continue;
    }
    if (xml.compare(start, 2, "<?") == 0)
    {
      const std::size_t end = xml.find("?>", start + 2);
      advance(end == std::string::npos ? n : end + 2);
      continue;
    }
    if (xml.compare(start, 2, "</") == 0)
    {
      const std::size_t end = xml.find('>', start + 2);
      advance(end == std::string::npos ? n : end + 1);
      depth = std::max(0, depth - 1);
      continue;
    }
    if (start + 1 >= n ||
        !(is_letter(xml[start + 1]) || xml[start + 1] == '_' || xml[start + 1] == ':'))
      break; // not XML that Teuchos reads: its parser stops here too
    StartTag tag;
    tag.line = line;
    std::size_t k = start + 1;
    while (k < n && is_name_char(xml[k]))
      ++k;
    bool empty_element = false, closed = false;
    while (k < n && !closed)
    {
      const unsigned char c = xml[k];
      if (c == '"' || c == '\'')
      {
        const std::size_t end = xml.find(static_cast<char>(c), k + 1);
        k = end == std::string::npos ? n : end + 1;
      }
      else if (c == '>')
      {
        closed = true;
        empty_element = k > start && xml[k - 1] == '/';
        ++k;
      }
      else if (is_letter(c) || c == '_' || c == ':')
      {
        const std::size_t name_start = k;
        while (k < n && is_name_char(xml[k]))
          ++k;
        tag.attributes.push_back(xml.substr(name_start, k - name_start));
      }
      else
        ++k;
    }
    advance(k);
    tags.push_back(std::move(tag));
    if (!empty_element)
      ++depth;
    KILN_CHECK_INPUT(depth <= max_input_depth, where + ":" + std::to_string(tags.back().line),
                     "elements are nested more than "
                         << max_input_depth
                         << " deep here; a Kiln input nests about 8 lists (Kiln/Solver/NOX/...): "
                            "look for a <ParameterList ...> written where </ParameterList> or "
                            "<ParameterList .../> was meant");
    if (!closed)
      break;
  }
  return tags;
}

void check_text(const std::string &xml, const std::string &where)
{
  KILN_CHECK_INPUT(xml.size() <= max_input_bytes, where,
                   "the file holds " << xml.size() << " bytes, more than the " << max_input_bytes
                                     << " an input may have (a Kiln input is a few kB of XML): "
                                        "check that this is the input file and not a mesh or "
                                        "a result");
  KILN_CHECK_INPUT(xml.find_first_not_of(" \t\r\n") != std::string::npos, where,
                   "the file is empty; a Kiln input is an XML file whose root is "
                   "<ParameterList name=\"Kiln\">: see inputs/ for examples");
  const std::size_t nul = xml.find('\0');
  KILN_CHECK_INPUT(nul == std::string::npos, where,
                   "the file holds binary data (a zero byte at offset "
                       << nul
                       << "); it is not an XML input: check that this is the input file and "
                          "not a mesh or a result");
}

void check_tree(const Teuchos::XMLObject &root, const std::vector<StartTag> &tags,
                const std::string &where)
{
  TreeChecker(tags, where).check_root(root);
}
} // namespace kiln::internal
