#pragma once
/// The values a material property may take (a modulus > 0, Poisson's ratio in (-1, 0.5)).
#include <Teuchos_ParameterEntryValidator.hpp>
#include <Teuchos_RCP.hpp>

#include <limits>
#include <string>

namespace kiln
{
/// An interval of allowed values, each end open or closed (or absent: +-infinity). A property
/// that is a function of T must lie in its range at every temperature Kiln checks
/// (TemperatureFunction says which).
class PropertyRange
{
public:
  /// Any finite value.
  static PropertyRange any() { return {}; }
  /// value > 0 (a modulus, a conductivity, a density, a specific heat).
  static PropertyRange positive() { return {0.0, false, infinity, false}; }
  /// value >= 0 (the expansion coefficient).
  static PropertyRange nonnegative() { return {0.0, true, infinity, false}; }
  /// lower < value < upper (Poisson's ratio: (-1, 0.5)).
  static PropertyRange open(const double lower, const double upper)
  {
    return {lower, false, upper, false};
  }

  /// Whether `value` is finite and inside the range.
  bool contains(double value) const;
  /// The requirement as the messages and the input reference say it: "must be > 0",
  /// "must be > -1 and < 0.5", "must be finite".
  std::string text() const;
  /// A validator for a plain number with the same requirement (kiln's positive or nonnegative
  /// validators, so that the messages stay those of every other number), or null for a range
  /// the caller checks itself.
  Teuchos::RCP<const Teuchos::ParameterEntryValidator> validator() const;

private:
  static constexpr double infinity = std::numeric_limits<double>::infinity();
  PropertyRange() = default;
  PropertyRange(const double lower, const bool lower_closed, const double upper,
                const bool upper_closed)
      : lower_(lower), lower_closed_(lower_closed), upper_(upper), upper_closed_(upper_closed)
  {
  }

  double lower_ = -infinity;
  bool lower_closed_ = false;
  double upper_ = infinity;
  bool upper_closed_ = false;
};
} // namespace kiln
