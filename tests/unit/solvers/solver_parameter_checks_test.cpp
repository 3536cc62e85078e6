// Tests src/solvers/solver_parameter_checks.cpp: NOX's list checked against the names NOX
// reads (its sublists without a validator) and NOX's own valid list ("Solver Options"):
// unknown names with the closest valid one, wrong types, unknown choices, names an input
// cannot give; Kiln's defaults pass. The Belos and MueLu checks run through NewtonSolver
// (newton_solver_test.cpp) and the bad decks (tests/input_errors).
#include "solvers/solver_parameter_checks.hpp"

#include "solvers/newton_solver.hpp"
#include "support/parameter_lists.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

namespace
{
using kiln::internal::check_nox_parameters;
using testing::HasSubstr;
using testing::StartsWith;
using Teuchos::ParameterList;

/// Kiln's NOX list with its defaults, as NewtonSolver checks it.
ParameterList kiln_nox_list()
{
  return kiln::NewtonSolver::valid_parameters().sublist("Nonlinear Solver");
}

std::string message_for(const ParameterList &nox)
{
  return kiln_test::input_error_message([&] { check_nox_parameters(nox, "in.xml: NOX"); });
}

TEST(NoxParameters, KilnsDefaultsPass)
{
  EXPECT_EQ(message_for(kiln_nox_list()), "");
  EXPECT_EQ(message_for(ParameterList()), "");
}

TEST(NoxParameters, EveryKnownMethodPasses)
{
  for (const char *method : {"Full Step", "Backtrack", "Polynomial", "More'-Thuente"})
  {
    ParameterList nox = kiln_nox_list();
    ParameterList &line_search = nox.sublist("Line Search");
    line_search.set("Method", std::string(method));
    ParameterList &own = line_search.sublist(method);
    if (std::string(method) == "Polynomial")
      own.set("Interpolation Type", "Quadratic");
    else if (std::string(method) == "Full Step")
      own.set("Full Step", 0.5);
    else
      own.set("Max Iters", 10);
    EXPECT_EQ(message_for(nox), "") << method;
  }
  ParameterList nox = kiln_nox_list();
  nox.set("Nonlinear Solver", "Trust Region Based");
  nox.sublist("Trust Region").set("Minimum Trust Region Radius", 1e-8);
  nox.sublist("Direction").sublist("Newton").set("Forcing Term Method", "Type 2");
  nox.sublist("Direction").sublist("Newton").set("Forcing Term Alpha", 1.5);
  nox.sublist("Cauchy Direction").set("Method", "Steepest Descent");
  EXPECT_EQ(message_for(nox), "");
}

TEST(NoxParameters, ASublistOfAnotherMethodIsRefused)
{
  // NOX reads only the sublist of the chosen line search and direction.
  ParameterList nox = kiln_nox_list();
  nox.sublist("Line Search").sublist("Backtrack").set("Max Iters", 10);
  EXPECT_EQ(message_for(nox),
            "in.xml: NOX/Line Search/Backtrack: parameters for \"Backtrack\", but the \"Method\" "
            "beside them is \"Full Step\", so NOX would ignore them; set \"Method\" to "
            "\"Backtrack\" or move them to \"Full Step\"");
  nox.sublist("Line Search").set("Method", "Backtrack");
  EXPECT_EQ(message_for(nox), "");

  nox = kiln_nox_list(); // Method Newton
  nox.sublist("Direction").sublist("Broyden").set("Memory", 5);
  EXPECT_THAT(message_for(nox), StartsWith("in.xml: NOX/Direction/Broyden: parameters for "
                                           "\"Broyden\", but the \"Method\" beside them is "
                                           "\"Newton\""));
  nox = kiln_nox_list();
  nox.sublist("Direction").set("Method", "NonlinearCG"); // reads "Nonlinear CG"
  nox.sublist("Direction").remove("Newton");
  nox.sublist("Direction").sublist("Nonlinear CG").set("Restart Frequency", 5);
  EXPECT_EQ(message_for(nox), "");
  nox.sublist("Direction").sublist("Steepest Descent").set("Scaling Type", "None");
  EXPECT_THAT(message_for(nox), StartsWith("in.xml: NOX/Direction/Steepest Descent: "));

  // The tensor method reads names of its own.
  nox = kiln_nox_list();
  nox.set("Nonlinear Solver", "Tensor Based");
  nox.sublist("Line Search").sublist("Backtrack").set("Max Iters", 10);
  EXPECT_EQ(message_for(nox), "");
}

TEST(NoxParameters, AMisspelledLineSearchKeyNamesTheClosestValidOne)
{
  ParameterList nox = kiln_nox_list();
  nox.sublist("Line Search").set("Methd", "Backtrack");
  const std::string message = message_for(nox);
  EXPECT_THAT(message, StartsWith("in.xml: NOX/Line Search/\"Methd\": unknown parameter of NOX. "
                                  "Did you mean \"Method\"? Valid names here: \"Method\", "
                                  "\"Full Step\", \"Backtrack\""));
  EXPECT_THAT(message, HasSubstr("NOX does not know this name: it would be ignored (the setting "
                                 "would have no effect) or refused later; correct it or "
                                 "remove it"));
  EXPECT_THAT(message, testing::Not(HasSubstr("Adjusted Tolerance"))); // NOX's output values
}

TEST(NoxParameters, KeysDeepDownAreChecked)
{
  ParameterList nox = kiln_nox_list();
  nox.sublist("Direction").sublist("Newton").set("Forcing Term Metod", "Type 1");
  EXPECT_THAT(message_for(nox), StartsWith("in.xml: NOX/Direction/Newton/\"Forcing Term Metod\": "
                                           "unknown parameter of NOX. Did you mean \"Forcing "
                                           "Term Method\"?"));
  nox = kiln_nox_list();
  nox.sublist("Direction").sublist("Newton").sublist("Linear Solver").set("Tolerence", 1e-4);
  EXPECT_THAT(message_for(nox), HasSubstr("Newton/Linear Solver/\"Tolerence\": unknown parameter "
                                          "of NOX. Did you mean \"Tolerance\"?"));
  nox = kiln_nox_list();
  nox.sublist("Line Serch").set("Method", "Full Step");
  EXPECT_THAT(message_for(nox), StartsWith("in.xml: NOX/\"Line Serch\": unknown sublist of NOX. "
                                           "Did you mean \"Line Search\"?"));
}

TEST(NoxParameters, AnUnknownChoiceNamesTheClosestOne)
{
  ParameterList nox = kiln_nox_list();
  nox.sublist("Line Search").set("Method", "Backtrak");
  EXPECT_THAT(message_for(nox), StartsWith("in.xml: NOX/Line Search/\"Method\" = Backtrak: not "
                                           "one of the choices of NOX. Did you mean "
                                           "\"Backtrack\"? Choices: \"Full Step\", "
                                           "\"Backtrack\""));
  nox = kiln_nox_list();
  nox.set("Nonlinear Solver", "Line Search Base");
  EXPECT_THAT(message_for(nox), HasSubstr("Did you mean \"Line Search Based\"?"));
  // Safeguarded Step needs an "Update Limit Vector" object, which an input cannot give.
  nox = kiln_nox_list();
  nox.sublist("Line Search").set("Method", "Safeguarded Step");
  EXPECT_THAT(message_for(nox), HasSubstr("= Safeguarded Step: not one of the choices of NOX"));
}

TEST(NoxParameters, AWrongTypeSaysWhichToWrite)
{
  ParameterList nox = kiln_nox_list();
  nox.sublist("Line Search").sublist("Backtrack").set("Max Iters", 10.0);
  EXPECT_EQ(message_for(nox), "in.xml: NOX/Line Search/Backtrack/\"Max Iters\": expected type "
                              "\"int\", got type \"double\" (value 10); write type=\"int\"");
}

TEST(NoxParameters, OutputInformationMayBeASublistOfFlags)
{
  ParameterList nox = kiln_nox_list();
  nox.sublist("Printing").remove("Output Information"); // Kiln's default is a number
  ParameterList &information = nox.sublist("Printing").sublist("Output Information");
  information.set("Outer Iteration", true);
  information.set("Warning", true);
  EXPECT_EQ(message_for(nox), "");
  information.set("Outer Iterations", true);
  EXPECT_THAT(message_for(nox), HasSubstr("Printing/Output Information/\"Outer Iterations\": "
                                          "unknown parameter of NOX. Did you mean \"Outer "
                                          "Iteration\"?"));
}

TEST(NoxParameters, SolverOptionsAreCheckedAgainstNoxsOwnList)
{
  ParameterList nox = kiln_nox_list();
  nox.sublist("Solver Options").set("Status Test Check Typ", "Complete");
  EXPECT_THAT(message_for(nox), HasSubstr("Solver Options/\"Status Test Check Typ\": unknown "
                                          "parameter of NOX. Did you mean \"Status Test Check "
                                          "Type\"?"));
  nox = kiln_nox_list();
  nox.sublist("Solver Options").set("Status Test Check Type", "Minimum");
  EXPECT_THAT(message_for(nox), HasSubstr("\"Status Test Check Type\" = Minimum: not one of the "
                                          "choices of NOX. Did you mean \"Minimal\"?"));
}

TEST(NoxParameters, WhatKilnSetsItselfIsExplained)
{
  ParameterList nox = kiln_nox_list();
  nox.sublist("Status Tests").set("Test Type", "Combo");
  EXPECT_THAT(message_for(nox), HasSubstr("\"Status Tests\": unknown sublist of NOX. Kiln sets "
                                          "NOX's status tests itself, from Solver/\"Absolute "
                                          "Tolerance\""));
  nox = kiln_nox_list();
  nox.sublist("Printing").set("Output Stream", "cout");
  EXPECT_THAT(message_for(nox), HasSubstr("Printing/\"Output Stream\": is set by Kiln or by a "
                                          "program"));
}

TEST(NoxParameters, TheTensorMethodsOwnNamesAreLeftToNox)
{
  ParameterList nox = kiln_nox_list();
  nox.set("Nonlinear Solver", "Tensor Based");
  nox.sublist("Direction").set("Method", "Tensor");
  nox.sublist("Line Search").set("Method", "Curvilinear");
  EXPECT_EQ(message_for(nox), "");
}
} // namespace
