#pragma once
/// Thermal conductivity as a function of temperature, k(T).
#include "base/piecewise_linear.hpp"

#include <Teuchos_ParameterList.hpp>

#include <string>

namespace kiln
{
/// k(T) [W/(m K)], T [K]:
/// - "Constant": k = "Value", dk/dT = 0.
/// - "Table": piecewise linear through ("Temperatures", "Values"), constant beyond the first
///   and the last temperature. derivative() is the slope of the interval containing T; at a
///   breakpoint T_i it is the slope of the interval to its right [T_i, T_{i+1}] (0 at and
///   beyond the last temperature, 0 below the first): the one-sided derivative that Newton
///   sees when T increases.
class ConductivityModel
{
public:
  static Teuchos::ParameterList valid_parameters();
  /// `validated_params` must have been through kiln::validated() against valid_parameters();
  /// `where` names the list in messages ("in.xml: Kiln/Physics/Heat/Conductivity").
  /// Throws InputError if the table has fewer than 2 points, temperatures that are not
  /// strictly increasing, or a different number of values than temperatures.
  ConductivityModel(const Teuchos::ParameterList &validated_params, const std::string &where);
  /// k = 1 W/(m K).
  ConductivityModel() = default;
  /// k constant [W/(m K)].
  static ConductivityModel constant(double k);

  /// k(T) [W/(m K)]; T in [K].
  double value(double T) const;
  /// dk/dT [W/(m K^2)]; T in [K]. At a breakpoint, the slope of the interval to the right.
  double derivative(double T) const;
  /// Whether k does not depend on T ("Constant"; a "Table" counts as varying).
  bool is_constant() const;

private:
  /// Table: the table (at least 2 points). Constant: the single point (0 K, k).
  PiecewiseLinear k_of_T_{{0.0}, {1.0}, {}};
};
} // namespace kiln
