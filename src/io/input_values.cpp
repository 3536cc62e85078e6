#include "io/input_values.hpp"

#include "base/parameters.hpp"

#include <algorithm>
#include <cerrno>
#include <cfloat>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <map>
#include <sstream>

namespace kiln::internal
{
namespace
{
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
} // namespace

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
} // namespace kiln::internal
