#include "io/input_reader.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_StringInputSource.hpp>
#include <Teuchos_XMLObject.hpp>
#include <Teuchos_XMLParameterListReader.hpp>

#include <algorithm>
#include <cerrno>
#include <cfloat>
#include <chrono>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>
#include <vector>

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

namespace kiln
{
namespace internal
{
namespace // file-local helpers of the input reader
{
// ---------------------------------------------------------------------------
// The text: size, emptiness, binary content, nesting depth.

/// One start tag as the pre-scan saw it: its line and attribute names, in document
/// order, which is also the pre-order of the tree Teuchos builds from the same text.
struct StartTag
{
  int line = 0;
  std::vector<std::string> attributes;
};

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

// ---------------------------------------------------------------------------
// Numbers, written in full.

std::string trimmed(const std::string &s)
{
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string::npos)
    return "";
  const auto last = s.find_last_not_of(" \t\r\n");
  return s.substr(first, last - first + 1);
}

/// Whether `s` is a decimal number: [+-] digits [. digits] [e [+-] digits] (or .digits).
bool is_decimal(const std::string &s, const bool integer)
{
  std::size_t i = 0;
  const auto digits = [&]()
  {
    const std::size_t from = i;
    while (i < s.size() && s[i] >= '0' && s[i] <= '9')
      ++i;
    return i - from;
  };
  if (i < s.size() && (s[i] == '+' || s[i] == '-'))
    ++i;
  std::size_t mantissa = digits();
  if (!integer && i < s.size() && s[i] == '.')
  {
    ++i;
    mantissa += digits();
  }
  if (mantissa == 0)
    return false;
  if (!integer && i < s.size() && (s[i] == 'e' || s[i] == 'E'))
  {
    ++i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-'))
      ++i;
    if (digits() == 0)
      return false;
  }
  return i == s.size();
}

std::string lowered(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(),
                 [](const unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

struct IntegerRange
{
  long double lo, hi;
};

/// The integer types Teuchos' converters know, with their ranges.
const std::map<std::string, IntegerRange> &integer_types()
{
  static const std::map<std::string, IntegerRange> types = {
      {"int", {INT_MIN, INT_MAX}},
      {"short", {SHRT_MIN, SHRT_MAX}},
      {"long", {static_cast<long double>(LONG_MIN), static_cast<long double>(LONG_MAX)}},
      {"long long", {static_cast<long double>(LLONG_MIN), static_cast<long double>(LLONG_MAX)}},
      {"unsigned int", {0, UINT_MAX}},
      {"unsigned short", {0, USHRT_MAX}},
      {"unsigned long", {0, static_cast<long double>(ULONG_MAX)}},
      {"unsigned long long", {0, static_cast<long double>(ULLONG_MAX)}},
  };
  return types;
}

bool is_floating_type(const std::string &type)
{
  return type == "double" || type == "float";
}

/// Why `text` is not a value of the numeric scalar type `type`, with what to write
/// instead; "" if it is one.
std::string number_problem(const std::string &raw, const std::string &type)
{
  const std::string text = trimmed(raw);
  const std::string article =
      type.front() == 'a' || type.front() == 'i' || type.front() == 'u' ? "an " : "a ";
  const std::string low = lowered(text);
  const std::string sign_free =
      !low.empty() && (low[0] == '+' || low[0] == '-') ? low.substr(1) : low;
  if (sign_free == "inf" || sign_free == "infinity" || sign_free == "nan")
    return "is not a finite number; write a finite number, in SI units";
  if (sign_free.rfind("0x", 0) == 0)
    return "is written in hexadecimal; write the number in decimal";
  if (is_floating_type(type))
  {
    if (!is_decimal(text, false))
      return "is not " + article + type +
             "; write the number alone, in SI units, without a unit (e.g. 2.7e3)";
    errno = 0;
    const double value = std::strtod(text.c_str(), nullptr);
    const bool is_float = type == "float";
    const double max = is_float ? FLT_MAX : DBL_MAX, min = is_float ? FLT_MIN : DBL_MIN;
    if ((errno == ERANGE && std::abs(value) > 1.0) || std::abs(value) > max)
      return "is beyond the range of " + article + type + " (magnitudes up to about " +
             (is_float ? "3.4e38" : "1.8e308") + "); write a finite number, in SI units";
    if (errno == ERANGE || (value != 0.0 && std::abs(value) < min))
      return "is too small for " + article + type + ": below about " +
             (is_float ? "1.2e-38" : "2.2e-308") +
             " it loses its digits or becomes 0; write 0 or a larger number";
    return "";
  }
  const IntegerRange range = integer_types().at(type);
  if (!is_decimal(text, true))
    return "is not " + article + type + "; write a whole number, e.g. 4";
  const long double value = std::strtold(text.c_str(), nullptr);
  if (value < range.lo || value > range.hi)
  {
    std::ostringstream s;
    s << "is outside the range of " << article << type << ", " << std::fixed << std::setprecision(0)
      << range.lo << " to " << range.hi << "; write a smaller number";
    return s.str();
  }
  return "";
}

// ---------------------------------------------------------------------------
// Types and values.

const std::vector<std::string> &kiln_types()
{
  static const std::vector<std::string> types = {
      "double", "int", "bool", "string", "Array(double)", "Array(int)", "Array(string)"};
  return types;
}

/// Every type Teuchos reads (its ParameterEntryXMLConverterDB): the scalars, and arrays
/// and 2D arrays of all but char and bool.
bool is_known_type(const std::string &type)
{
  static const std::vector<std::string> scalars = {"double",        "float",
                                                   "int",           "short",
                                                   "long",          "long long",
                                                   "unsigned int",  "unsigned short",
                                                   "unsigned long", "unsigned long long",
                                                   "string",        "char",
                                                   "bool"};
  for (const auto &s : scalars)
  {
    if (type == s)
      return true;
    if (s != "char" && s != "bool" &&
        (type == "Array(" + s + ")" || type == "TwoDArray(" + s + ")"))
      return true;
  }
  return false;
}

std::string suggested_type(const std::string &type)
{
  static const std::map<std::string, std::string> aliases = {
      {"float64", "double"},     {"float32", "double"},     {"real", "double"},
      {"number", "double"},      {"integer", "int"},        {"int32", "int"},
      {"int64", "int"},          {"boolean", "bool"},       {"logical", "bool"},
      {"str", "string"},         {"std::string", "string"}, {"text", "string"},
      {"array", "Array(double)"}};
  const auto it = aliases.find(lowered(type));
  if (it != aliases.end())
    return it->second;
  return closest_name(type, kiln_types());
}

std::string quoted_list(const std::vector<std::string> &names)
{
  std::string s;
  for (const auto &n : names)
    s += (s.empty() ? "\"" : ", \"") + n + "\"";
  return s;
}

/// Why `value` is not a `type` (one of is_known_type); "" if it is one.
std::string value_problem(const std::string &value, const std::string &type)
{
  if (type == "bool")
  {
    const std::string v = lowered(trimmed(value));
    return v == "true" || v == "false" || v == "yes" || v == "no" || v == "1" || v == "0"
               ? ""
               : "is not a bool; write true or false";
  }
  if (is_floating_type(type) || integer_types().count(type) > 0)
    return number_problem(value, type);
  if (type.rfind("Array(", 0) != 0)
    return ""; // string, char, TwoDArray: Teuchos reads any text or checks it itself
  const std::string element = type.substr(6, type.size() - 7);
  const std::string text = trimmed(value);
  const std::string intro = "is not an " + type + ": ";
  if (text.size() < 2 || text.front() != '{' || text.back() != '}')
    return intro + "write the entries in braces, separated by commas, e.g. {1.0, 2.0}";
  const std::string inner = text.substr(1, text.size() - 2);
  if (trimmed(inner).empty())
    return "";
  std::vector<std::string> entries;
  std::size_t from = 0;
  while (true)
  {
    const std::size_t comma = inner.find(',', from);
    entries.push_back(
        inner.substr(from, comma == std::string::npos ? std::string::npos : comma - from));
    if (comma == std::string::npos)
      break;
    from = comma + 1;
  }
  for (std::size_t k = 0; k < entries.size(); ++k)
  {
    const std::string entry = trimmed(entries[k]);
    const std::string which = "entry " + std::to_string(k + 1);
    if (entry.empty())
      return intro + which + " is empty; remove the " +
             (k + 1 == entries.size() ? std::string("trailing comma")
              : k == 0                ? std::string("leading comma")
                                      : std::string("extra comma"));
    if (entry.find_first_of("{}") != std::string::npos)
      return intro + which + ", \"" + entry +
             "\", holds a brace; an array is one list {a, b, c}, not nested";
    if (element == "string" || element == "char")
      continue;
    const std::string problem = value_problem(entry, element);
    if (!problem.empty())
      return intro + which + ", \"" + entry + "\", " + problem;
  }
  return "";
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

/// The XML tree of `xml`, or an InputError with the parser's message on one line.
Teuchos::XMLObject parse_xml(const std::string &xml, const std::string &where)
{
  try
  {
    return Teuchos::StringInputSource(xml).getObject();
  }
  catch (const std::exception &e)
  {
    std::string message = one_line_library_message(e.what());
    const auto line = message.find("XML parse error");
    if (line != std::string::npos)
      message = message.substr(line);
    throw InputError(where + ": not a well-formed XML file: " + message);
  }
}
} // namespace

std::string read_input_text(const std::string &path, std::string &text)
{
  // open(2) rather than std::ifstream: its errno names the reason (not found, permission
  // denied, not a directory), O_NONBLOCK keeps a FIFO without a writer from blocking the
  // open, and poll(2) bounds the wait for a pipe or device that never sends anything.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0)
  {
    const int error = errno;
    return std::string("cannot open the input file (") + std::strerror(error) +
           (error == ENOENT || error == ENOTDIR ? "); check the path"
            : error == EACCES                   ? "); check that it is readable by this user"
                                                : "); check the path and the file");
  }
  struct stat info = {};
  ::fstat(fd, &info);
  if (S_ISDIR(info.st_mode))
  {
    ::close(fd);
    return "is a directory, not an input file; give the path of the XML input";
  }
  const bool regular = S_ISREG(info.st_mode);
  if (regular && static_cast<std::size_t>(info.st_size) > max_input_bytes)
  {
    ::close(fd);
    return "the file holds " + std::to_string(info.st_size) + " bytes, more than the " +
           std::to_string(max_input_bytes) +
           " an input may have (a Kiln input is a few kB of XML): check that this is the "
           "input file and not a mesh or a result";
  }
  // Every kind of file is read up to one byte past the limit, so that /dev/zero or a
  // pipe that never ends stops there and is reported by parse_input's size check.
  std::string problem;
  std::vector<char> chunk(65536);
  const auto deadline = std::chrono::steady_clock::now() + input_wait;
  while (text.size() <= max_input_bytes)
  {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    pollfd ready = {fd, POLLIN, 0};
    const int polled = ::poll(&ready, 1, static_cast<int>(std::max<long long>(0, left.count())));
    if (polled < 0 && errno == EINTR)
      continue;
    if (polled == 0)
    {
      problem =
          std::string(S_ISFIFO(info.st_mode) ? "is a FIFO (named pipe)" : "is not a regular file") +
          " and sent no end of file within " + std::to_string(input_wait.count()) + " s (" +
          std::to_string(text.size()) +
          " bytes read); give the path of the XML input file, or start the program "
          "that writes the pipe before Kiln";
      break;
    }
    const std::size_t want = std::min(chunk.size(), max_input_bytes + 1 - text.size());
    const ssize_t got = ::read(fd, chunk.data(), want);
    if (got < 0 && (errno == EAGAIN || errno == EINTR))
      continue;
    if (got < 0)
    {
      problem = std::string("cannot read the input file (") + std::strerror(errno) + ")";
      break;
    }
    if (got == 0)
      break;
    text.append(chunk.data(), static_cast<std::size_t>(got));
  }
  ::close(fd);
  return problem;
}
} // namespace internal

Teuchos::ParameterList parse_input(const std::string &xml, const std::string &where)
{
  internal::check_text(xml, where);
  const std::vector<internal::StartTag> tags = internal::scan_start_tags(xml, where);
  KILN_CHECK_INPUT(!tags.empty(), where,
                   "the file holds no XML element (only text or comments); a Kiln input is an "
                   "XML file whose root is <ParameterList name=\"Kiln\">: see inputs/ for "
                   "examples");
  const Teuchos::XMLObject root = internal::parse_xml(xml, where);
  internal::TreeChecker(tags, where).check_root(root);
  try
  {
    Teuchos::XMLParameterListReader reader;
    reader.setAllowsDuplicateSublists(false);
    return reader.toParameterList(root);
  }
  catch (const std::exception &e)
  {
    throw InputError(where +
                     ": cannot read the parameter list: " + one_line_library_message(e.what()));
  }
}

Teuchos::ParameterList read_input(const std::string &path, const Teuchos::Comm<int> &comm)
{
  std::string text;
  std::string problem;
  if (comm.getRank() == 0)
    problem = internal::read_input_text(path, text);
  check_collectively(comm, problem.empty(), path, problem);
  int length = static_cast<int>(std::min(text.size(), max_input_bytes + 1));
  Teuchos::broadcast(comm, 0, Teuchos::outArg(length));
  text.resize(length);
  if (length > 0)
    Teuchos::broadcast(comm, 0, length, text.data());
  return parse_input(text, path);
}
} // namespace kiln
