// The registration list of the interface kinds: a new kind is a new class in its own files
// and one line here.
#include "contact/bonded_interface.hpp"
#include "contact/interface_strategy.hpp"
#include "contact/normal_contact.hpp"
#include "contact/sliding_interface.hpp"

namespace kiln
{
const InterfaceKinds &interface_kinds()
{
  static const InterfaceKinds registry = []
  {
    InterfaceKinds r;
    r.add<NormalContact>("Contact");
    r.add<SlidingInterface>("Sliding");
    r.add<BondedInterface>("Bonded");
    return r;
  }();
  return registry;
}
} // namespace kiln
