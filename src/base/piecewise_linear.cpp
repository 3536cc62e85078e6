#include "base/piecewise_linear.hpp"

#include "base/errors.hpp"

#include <algorithm>

namespace kiln
{
PiecewiseLinear::PiecewiseLinear(std::vector<double> x, std::vector<double> y, const Names &names)
    : x_(std::move(x)), y_(std::move(y))
{
  const std::string at_x = names.where + "/\"" + names.x_name + "\"";
  KILN_CHECK_INPUT(y_.size() == x_.size(), names.where + "/\"" + names.y_name + "\"",
                   "has " << y_.size() << " entries but \"" << names.x_name << "\" has "
                          << x_.size() << "; give one value per entry of \"" << names.x_name
                          << "\"");
  for (std::size_t i = 1; i < x_.size(); ++i)
    KILN_CHECK_INPUT(x_[i] > x_[i - 1], at_x,
                     "must be strictly increasing (entries counted from 1), but entry "
                         << i + 1 << " (" << x_[i] << names.x_unit << ") <= entry " << i << " ("
                         << x_[i - 1] << names.x_unit << ")");
}

std::size_t PiecewiseLinear::interval(const double x) const
{
  const auto upper = std::upper_bound(x_.begin(), x_.end(), x);
  return static_cast<std::size_t>(std::distance(x_.begin(), upper)) - 1;
}

double PiecewiseLinear::value(const double x) const
{
  if (x <= x_.front())
    return y_.front();
  if (x >= x_.back())
    return y_.back();
  const std::size_t k = interval(x);
  const double w = (x - x_[k]) / (x_[k + 1] - x_[k]);
  return (1 - w) * y_[k] + w * y_[k + 1];
}

double PiecewiseLinear::slope(const double x) const
{
  if (x_.size() < 2 || x < x_.front() || x >= x_.back())
    return 0.0;
  const std::size_t k = interval(x);
  return (y_[k + 1] - y_[k]) / (x_[k + 1] - x_[k]);
}
} // namespace kiln
