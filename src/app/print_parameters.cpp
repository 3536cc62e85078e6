#include "app/print_parameters.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_StrUtils.hpp>

#include <charconv>
#include <cmath>
#include <sstream>

namespace kiln
{
namespace internal
{
namespace
{
std::string double_text(const double value)
{
  if (!std::isfinite(value))
    return std::isnan(value) ? "nan" : (value > 0 ? "inf" : "-inf");
  char text[64];
  const auto result = std::to_chars(text, text + sizeof text, value);
  return std::string(text, result.ptr);
}

template <typename T, typename Format>
std::string array_text(const Teuchos::Array<T> &values, const Format &format)
{
  std::string text = "{";
  for (int i = 0; i < values.size(); ++i)
    text += (i == 0 ? "" : ", ") + format(values[i]);
  return text + "}";
}

/// Each line of `text` with `indent` spaces before it.
void print_indented(std::ostream &out, const std::string &text, const int indent)
{
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line))
    out << std::string(static_cast<std::size_t>(indent), ' ') << line << "\n";
}
} // namespace
} // namespace internal

std::string parameter_value_text(const Teuchos::ParameterEntry &entry)
{
  using Teuchos::Array;
  const auto &any = entry.getAny(false);
  if (any.type() == typeid(double))
    return internal::double_text(Teuchos::any_cast<double>(any));
  if (any.type() == typeid(bool))
    return Teuchos::any_cast<bool>(any) ? "true" : "false";
  if (any.type() == typeid(Array<double>))
    return internal::array_text(Teuchos::any_cast<Array<double>>(any), internal::double_text);
  if (any.type() == typeid(Array<int>))
    return internal::array_text(Teuchos::any_cast<Array<int>>(any),
                                [](const int v) { return std::to_string(v); });
  if (any.type() == typeid(Array<std::string>))
    return internal::array_text(Teuchos::any_cast<Array<std::string>>(any),
                                [](const std::string &v) { return v; });
  std::ostringstream text;
  entry.leftshift(text, false);
  return text.str();
}

void print_parameters(const Teuchos::ParameterList &list, std::ostream &out, const int indent)
{
  const std::string in(static_cast<std::size_t>(indent), ' ');
  if (list.begin() == list.end())
  {
    out << in << "[empty list]\n";
    return;
  }
  // Parameters first, then sublists, as Teuchos prints them.
  for (auto i = list.begin(); i != list.end(); ++i)
  {
    const Teuchos::ParameterEntry &entry = list.entry(i);
    if (entry.isList())
      continue;
    out << in << list.name(i) << " : " << entry.getAny(false).typeName() << " = "
        << parameter_value_text(entry) << "\n";
    std::ostringstream doc;
    if (!entry.validator().is_null())
      entry.validator()->printDoc(entry.docString(), doc);
    else if (!entry.docString().empty())
      Teuchos::StrUtils::printLines(doc, "# ", entry.docString());
    internal::print_indented(out, doc.str(), indent + 1);
  }
  for (auto i = list.begin(); i != list.end(); ++i)
  {
    const Teuchos::ParameterEntry &entry = list.entry(i);
    if (!entry.isList())
      continue;
    out << in << list.name(i) << " -> \n";
    if (!entry.docString().empty())
    {
      std::ostringstream doc;
      Teuchos::StrUtils::printLines(doc, "# ", entry.docString());
      internal::print_indented(out, doc.str(), indent + 1);
    }
    print_parameters(list.sublist(list.name(i)), out, indent + 1);
  }
}
} // namespace kiln
