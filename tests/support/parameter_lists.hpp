#pragma once
/// Building input parameter lists in C++: arrays from brace lists, the time functions of
/// boundary conditions, the fragments of a Kiln deck (named as tests/support/kiln_deck.py's, its
/// Python twin) and the text of the InputError a bad list gives.
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

// Deck fragments: each a list to set into a deck under the name Kiln reads it by.

/// A deck "Kiln" with its Physics (none if empty: Kiln's default), its Mesh and Time
/// Stepping/Method "Steady"; the test adds the rest.
Teuchos::ParameterList steady_deck(const std::string &physics, const Teuchos::ParameterList &mesh);

/// Mesh of the box generator: Size [m] and Cells (Type left to its default, Box), no gap
/// (Gap Side Set 0) unless one is given.
Teuchos::ParameterList box_mesh(const std::vector<double> &size, const std::vector<int> &cells,
                                int gap_side_set = 0);
/// Mesh read from the Exodus II file `path`, no gap unless one is given.
Teuchos::ParameterList exodus_mesh(const std::string &path, int gap_side_set = 0);

/// Elastic constants (of a Material list) as Young's modulus [Pa] and Poisson's ratio.
Teuchos::ParameterList young(double youngs_modulus, double poissons_ratio);
/// Elastic constants (of a Material list) as Lame's lambda and the shear modulus [Pa].
Teuchos::ParameterList lame(double lame_lambda, double shear_modulus);

/// Boundary condition of Type "Temperature" on the side sets: the time function `function`
/// (constant_function(), a table, ...).
Teuchos::ParameterList temperature(const std::vector<int> &side_sets,
                                   const Teuchos::ParameterList &function);
/// The same of a constant value [K].
Teuchos::ParameterList temperature(const std::vector<int> &side_sets, double value);
/// Boundary condition of Type "Displacement" on the side sets: the `components` ("x", "y", "z")
/// held at 0.
Teuchos::ParameterList displacement(const std::vector<int> &side_sets,
                                    const std::vector<std::string> &components);
/// The same held at the constant `value` [m].
Teuchos::ParameterList displacement(const std::vector<int> &side_sets,
                                    const std::vector<std::string> &components, double value);
/// Boundary condition of Type "Normal Displacement" (rollers) on the side sets.
Teuchos::ParameterList normal_displacement(const std::vector<int> &side_sets);
/// A contact pair (an entry of Mechanics/Contact/Pairs) of the two side sets.
Teuchos::ParameterList contact_pair(int primary_side_set, int secondary_side_set);
/// A Solver list with Newton's "Absolute Tolerance" and "Relative Tolerance".
Teuchos::ParameterList newton_tolerances(double absolute, double relative);

/// The lists of a deck that hold its conditions and pairs by name (made if missing):
/// Thermal/Boundary Conditions, Mechanics/Boundary Conditions and Mechanics/Contact/Pairs.
Teuchos::ParameterList &thermal_conditions(Teuchos::ParameterList &deck);
Teuchos::ParameterList &mechanical_conditions(Teuchos::ParameterList &deck);
Teuchos::ParameterList &contact_pairs(Teuchos::ParameterList &deck);

/// The message of the kiln::InputError that `action` throws, or "" if it throws none.
std::string input_error_message(const std::function<void()> &action);
} // namespace kiln_test
