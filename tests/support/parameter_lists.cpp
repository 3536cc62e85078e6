#include "support/parameter_lists.hpp"

#include "base/errors.hpp"

namespace kiln_test
{
Teuchos::Array<int> ids(const std::vector<int> &v)
{
  return Teuchos::Array<int>(v.begin(), v.end());
}

Teuchos::Array<double> values(const std::vector<double> &v)
{
  return Teuchos::Array<double>(v.begin(), v.end());
}

Teuchos::ParameterList constant_function(const double value)
{
  Teuchos::ParameterList f;
  f.set("Type", "Constant");
  f.set("Value", value);
  return f;
}

Teuchos::ParameterList smooth_step(const double start_value, const double end_value,
                                   const double start_time, const double end_time)
{
  Teuchos::ParameterList f;
  f.set("Type", "Smooth Step");
  f.set("Start Time", start_time);
  f.set("End Time", end_time);
  f.set("Start Value", start_value);
  f.set("End Value", end_value);
  return f;
}

std::string input_error_message(const std::function<void()> &action)
{
  try
  {
    action();
  }
  catch (const kiln::InputError &e)
  {
    return e.what();
  }
  return "";
}
} // namespace kiln_test
