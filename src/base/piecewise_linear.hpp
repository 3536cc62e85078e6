#pragma once
/// y(x) piecewise linear through the points (x_i, y_i), constant beyond the
/// ends: the table behind TimeFunction ("Times"/"Values") and
/// TemperatureFunction ("Temperatures"/"Values").
#include <string>
#include <vector>

namespace kiln
{
class PiecewiseLinear
{
public:
  /// How the table's two arrays are named in messages.
  struct Names
  {
    std::string where;  ///< the block: "in.xml: Kiln/..."
    std::string x_name; ///< e.g. "Temperatures"
    std::string y_name; ///< e.g. "Values"
    std::string x_unit; ///< appended to x values in messages, e.g. " K" (may be empty)
  };

  PiecewiseLinear() = default;
  /// Throws InputError naming `names` if the arrays differ in length or x is
  /// not strictly increasing. The caller checks the number of points it needs.
  PiecewiseLinear(std::vector<double> x, std::vector<double> y, const Names &names);

  std::size_t n_points() const { return x_.size(); }
  /// y(x); the first (last) y before (after) the table.
  double value(double x) const;
  /// dy/dx: the slope of the interval [x_k, x_{k+1}) holding x (so at a
  /// breakpoint, the interval to its right); 0 outside [x_0, x_last).
  double slope(double x) const;

private:
  /// k with x_k <= x < x_{k+1}, for x inside the table.
  std::size_t interval(double x) const;

  std::vector<double> x_;
  std::vector<double> y_;
};
} // namespace kiln
