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
  return Teuchos::ParameterList().set("Type", "Constant").set("Value", value);
}

Teuchos::ParameterList smooth_step(const double start_value, const double end_value,
                                   const double start_time, const double end_time)
{
  return Teuchos::ParameterList()
      .set("Type", "Smooth Step")
      .set("Start Time", start_time)
      .set("End Time", end_time)
      .set("Start Value", start_value)
      .set("End Value", end_value);
}

Teuchos::ParameterList steady_deck(const std::string &physics, const Teuchos::ParameterList &mesh)
{
  Teuchos::ParameterList deck("Kiln");
  if (!physics.empty())
    deck.set("Physics", physics);
  deck.set("Mesh", mesh);
  deck.sublist("Time Stepping").set("Method", "Steady");
  return deck;
}

Teuchos::ParameterList box_mesh(const std::vector<double> &size, const std::vector<int> &cells,
                                const int gap_side_set)
{
  Teuchos::ParameterList mesh;
  mesh.set("Gap Side Set", gap_side_set);
  mesh.sublist("Box").set("Size", values(size)).set("Cells", ids(cells));
  return mesh;
}

Teuchos::ParameterList exodus_mesh(const std::string &path, const int gap_side_set)
{
  Teuchos::ParameterList mesh;
  mesh.set("Type", "Exodus");
  mesh.set("Gap Side Set", gap_side_set);
  mesh.sublist("Exodus").set("File", path);
  return mesh;
}

Teuchos::ParameterList young(const double youngs_modulus, const double poissons_ratio)
{
  return Teuchos::ParameterList()
      .set("Young's Modulus", youngs_modulus)
      .set("Poisson's Ratio", poissons_ratio);
}

Teuchos::ParameterList lame(const double lame_lambda, const double shear_modulus)
{
  return Teuchos::ParameterList()
      .set("Lame Lambda", lame_lambda)
      .set("Shear Modulus", shear_modulus);
}

namespace
{
Teuchos::ParameterList condition(const std::string &type, const std::vector<int> &side_sets)
{
  return Teuchos::ParameterList().set("Type", type).set("Side Sets", ids(side_sets));
}
} // namespace

Teuchos::ParameterList temperature(const std::vector<int> &side_sets,
                                   const Teuchos::ParameterList &function)
{
  Teuchos::ParameterList c = condition("Temperature", side_sets);
  c.set("Temperature", function);
  return c;
}

Teuchos::ParameterList temperature(const std::vector<int> &side_sets, const double value)
{
  return temperature(side_sets, constant_function(value));
}

Teuchos::ParameterList displacement(const std::vector<int> &side_sets,
                                    const std::vector<std::string> &components)
{
  Teuchos::ParameterList c = condition("Displacement", side_sets);
  c.set("Components", Teuchos::Array<std::string>(components.begin(), components.end()));
  return c;
}

Teuchos::ParameterList displacement(const std::vector<int> &side_sets,
                                    const std::vector<std::string> &components, const double value)
{
  Teuchos::ParameterList c = displacement(side_sets, components);
  c.set("Displacement", constant_function(value));
  return c;
}

Teuchos::ParameterList normal_displacement(const std::vector<int> &side_sets)
{
  return condition("Normal Displacement", side_sets);
}

Teuchos::ParameterList contact_pair(const int primary_side_set, const int secondary_side_set)
{
  return Teuchos::ParameterList()
      .set("Primary Side Set", primary_side_set)
      .set("Secondary Side Set", secondary_side_set);
}

Teuchos::ParameterList newton_tolerances(const double absolute, const double relative)
{
  return Teuchos::ParameterList()
      .set("Absolute Tolerance", absolute)
      .set("Relative Tolerance", relative);
}

Teuchos::ParameterList &thermal_conditions(Teuchos::ParameterList &deck)
{
  return deck.sublist("Thermal").sublist("Boundary Conditions");
}

Teuchos::ParameterList &mechanical_conditions(Teuchos::ParameterList &deck)
{
  return deck.sublist("Mechanics").sublist("Boundary Conditions");
}

Teuchos::ParameterList &contact_pairs(Teuchos::ParameterList &deck)
{
  return deck.sublist("Mechanics").sublist("Contact").sublist("Pairs");
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
