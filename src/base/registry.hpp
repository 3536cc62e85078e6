#pragma once
/// The types of one kind of object (boundary conditions, complementarity functions), by the
/// name an input gives in "Type": each type is a class of its own with
///   static std::string description();              // one line for the "Type" doc
///   static Teuchos::ParameterList valid_parameters(); // its own parameters
/// and a constructor taking Args, registered by one line, add<TheClass>("Name"). This is
/// MOOSE's registerMooseObject made explicit: the list of a kind's types is one function, so
/// no static-initialisation order or linker dead-stripping decides what exists.
#include "base/errors.hpp"

#include <Teuchos_ParameterList.hpp>

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace kiln
{
template <typename Base, typename... Args> class Registry
{
public:
  struct Entry
  {
    std::string name;
    std::string description;
    Teuchos::ParameterList parameters; ///< the type's own parameters
    std::function<std::unique_ptr<Base>(Args...)> create;
  };

  /// Registers T under `name` (names are unique; the first registered is the default).
  template <typename T> Registry &add(const std::string &name)
  {
    if (find(name) != nullptr)
      throw InternalError("type \"" + name + "\" registered twice");
    entries_.push_back({name, T::description(), T::valid_parameters(),
                        [](Args... args) -> std::unique_ptr<Base>
                        { return std::make_unique<T>(std::forward<Args>(args)...); }});
    return *this;
  }

  const std::vector<Entry> &entries() const { return entries_; }
  std::vector<std::string> names() const
  {
    std::vector<std::string> result;
    for (const Entry &e : entries_)
      result.push_back(e.name);
    return result;
  }
  /// The entry registered as `name`, or nullptr.
  const Entry *find(const std::string &name) const
  {
    for (const Entry &e : entries_)
      if (e.name == name)
        return &e;
    return nullptr;
  }
  /// A new object of the type registered as `name` (which must be registered: the input's
  /// "Type" has been validated against names()).
  std::unique_ptr<Base> create(const std::string &name, Args... args) const
  {
    const Entry *entry = find(name);
    if (entry == nullptr)
      throw InternalError("no type \"" + name + "\" registered");
    return entry->create(std::forward<Args>(args)...);
  }
  /// "\"A\": description of A; \"B\": ..." for a "Type" parameter's doc string.
  std::string describe() const
  {
    std::string doc;
    for (const Entry &e : entries_)
      doc += (doc.empty() ? "\"" : "; \"") + e.name + "\": " + e.description;
    return doc;
  }

private:
  std::vector<Entry> entries_;
};
} // namespace kiln
