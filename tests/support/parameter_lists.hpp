#pragma once
/// Building input parameter lists in C++: arrays from brace lists, the time functions of
/// boundary conditions, and the text of the InputError a bad list gives.
#include <Teuchos_Array.hpp>
#include <Teuchos_ParameterList.hpp>

#include <functional>
#include <string>
#include <vector>

namespace kiln_test
{
/// An "Array(int)" value: ids({1, 3, 5}).
Teuchos::Array<int> ids(const std::vector<int> &v);
/// An "Array(double)" value: values({0.0, 10.0}).
Teuchos::Array<double> values(const std::vector<double> &v);

/// A TimeFunction list of Type "Constant".
Teuchos::ParameterList constant_function(double value);
/// A TimeFunction list of Type "Smooth Step" from start_value at start_time to end_value at
/// end_time (default: over [0, 10] s).
Teuchos::ParameterList smooth_step(double start_value, double end_value, double start_time = 0.0,
                                   double end_time = 10.0);

/// The message of the kiln::InputError that `action` throws, or "" if it throws none.
std::string input_error_message(const std::function<void()> &action);
} // namespace kiln_test
