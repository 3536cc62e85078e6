#include "physics/materials/property_range.hpp"

#include "base/parameters.hpp"

#include <cmath>
#include <sstream>

namespace kiln
{
bool PropertyRange::contains(const double value) const
{
  if (!std::isfinite(value))
    return false;
  const bool above = lower_closed_ ? value >= lower_ : value > lower_;
  const bool below = upper_closed_ ? value <= upper_ : value < upper_;
  return above && below;
}

std::string PropertyRange::text() const
{
  std::ostringstream s;
  const bool has_lower = std::isfinite(lower_);
  const bool has_upper = std::isfinite(upper_);
  if (!has_lower && !has_upper)
    return "must be finite";
  s << "must be";
  if (has_lower)
    s << (lower_closed_ ? " >= " : " > ") << lower_;
  if (has_lower && has_upper)
    s << " and";
  if (has_upper)
    s << (upper_closed_ ? " <= " : " < ") << upper_;
  return s.str();
}

Teuchos::RCP<const Teuchos::ParameterEntryValidator> PropertyRange::validator() const
{
  if (lower_ == 0.0 && !std::isfinite(upper_))
    return lower_closed_ ? nonnegative_double_validator() : positive_double_validator();
  return Teuchos::null;
}
} // namespace kiln
