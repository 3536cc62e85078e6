#include "solvers/nox_parameter_names.hpp"

#include "base/parameters.hpp"

#include <Teuchos_RCP.hpp>

#include <algorithm>
#include <ostream>
#include <vector>

namespace kiln
{
namespace internal
{
namespace
{
using Teuchos::ParameterList;

void set_choice(ParameterList &list, const std::string &name,
                const std::vector<std::string> &choices)
{
  list.set(name, choices.front(), "", choice_validator(choices));
}

ParameterList nox_linear_solver()
{
  // NOX::Thyra::Group::applyJacobianInverse; the choices of its getThyraNormType.
  const std::vector<std::string> measures = {"Norm Residual", "Norm Initial Residual", "None",
                                             "Norm Solution", "Norm RHS"};
  ParameterList p;
  p.set("Tolerance", 1e-6);
  set_choice(p, "Solve Measure Numerator", measures);
  set_choice(p, "Solve Measure Denominator", measures);
  p.sublist("Output", false, written_by_nox); // the linear iteration counts
  return p;
}

/// NOX::Direction::Utils::InexactNewton (Newton and Broyden directions).
void add_forcing_terms(ParameterList &p)
{
  set_choice(p, "Forcing Term Method", {"Constant", "Type 1", "Type 2"});
  for (const char *name :
       {"Forcing Term Initial Tolerance", "Forcing Term Minimum Tolerance",
        "Forcing Term Maximum Tolerance", "Forcing Term Alpha", "Forcing Term Gamma"})
    p.set(name, 0.0);
  p.set("Set Tolerance in Parameter List", true);
  p.sublist("Linear Solver").setParameters(nox_linear_solver());
}

ParameterList nox_direction(const std::string &default_method)
{
  std::vector<std::string> methods = {"Newton", "Steepest Descent", "NonlinearCG", "Broyden"};
  std::swap(*std::find(methods.begin(), methods.end(), default_method), methods.front());
  ParameterList p;
  set_choice(p, "Method", methods);
  ParameterList &newton = p.sublist("Newton");
  add_forcing_terms(newton);
  newton.set("Rescue Bad Newton Solve", true);
  set_choice(p.sublist("Steepest Descent"), "Scaling Type",
             {"2-Norm", "Quadratic Model Min", "F 2-Norm", "None"});
  ParameterList &cg = p.sublist("Nonlinear CG");
  cg.set("Restart Frequency", 10);
  set_choice(cg, "Precondition", {"Off", "On"});
  set_choice(cg, "Orthogonalize", {"Fletcher-Reeves", "Polak-Ribiere"});
  ParameterList &broyden = p.sublist("Broyden");
  add_forcing_terms(broyden);
  broyden.set("Restart Frequency", 10);
  broyden.set("Max Convergence Rate", 1.0);
  broyden.set("Memory", 10);
  return p;
}

ParameterList nox_line_search()
{
  ParameterList p;
  // Not from an input file: "User Defined" needs a factory object, "Safeguarded Step" and
  // "Safeguarded Direction" an "Update Limit Vector" (NOX refuses them without one).
  set_choice(p, "Method", {"Full Step", "Backtrack", "Polynomial", "More'-Thuente", "NonlinearCG"});
  p.sublist("Full Step").set("Full Step", 1.0);
  ParameterList &backtrack = p.sublist("Backtrack");
  for (const char *name : {"Default Step", "Minimum Step", "Recovery Step", "Reduction Factor"})
    backtrack.set(name, 0.0);
  backtrack.set("Max Iters", 100);
  const std::vector<std::string> decrease = {"Armijo-Goldstein", "Ared/Pred", "None"};
  const std::vector<std::string> recovery = {"Constant", "Last Computed Step"};
  ParameterList &polynomial = p.sublist("Polynomial");
  for (const char *name : {"Default Step", "Minimum Step", "Recovery Step", "Min Bounds Factor",
                           "Max Bounds Factor", "Alpha Factor", "Allowed Relative Increase"})
    polynomial.set(name, 0.0);
  polynomial.set("Max Iters", 100);
  polynomial.set("Maximum Iteration for Increase", 0);
  polynomial.set("Force Interpolation", false);
  polynomial.set("Use Counters", true);
  set_choice(polynomial, "Recovery Step Type", recovery);
  set_choice(polynomial, "Interpolation Type", {"Cubic", "Quadratic", "Quadratic3"});
  set_choice(polynomial, "Sufficient Decrease Condition", decrease);
  ParameterList &more_thuente = p.sublist("More'-Thuente");
  for (const char *name : {"Sufficient Decrease", "Curvature Condition", "Interval Width",
                           "Maximum Step", "Minimum Step", "Default Step", "Recovery Step"})
    more_thuente.set(name, 0.0);
  more_thuente.set("Max Iters", 20);
  more_thuente.set("Optimize Slope Calculation", false);
  set_choice(more_thuente, "Recovery Step Type", recovery);
  set_choice(more_thuente, "Sufficient Decrease Condition", decrease);
  p.sublist("NonlinearCG"); // reads nothing of its own
  p.set("Adjusted Tolerance", 0.0, written_by_nox);
  p.sublist("Output", false, written_by_nox);
  return p;
}

} // namespace

ParameterList nox_known_parameters()
{
  // NOX 13.2 has no validator for these sublists: each class reads its names with
  // get(name, default) in its constructor or reset() and ignores the others. The names are
  // those of NOX 13.2's sources (NOX_Solver_*.C, NOX_Direction_*.C, NOX_LineSearch_*.C,
  // NOX_Utils.C, NOX_Thyra_Group.C), with the types NOX reads them with, checked against the
  // installed library: every solver, direction and line search built once from an empty list,
  // which NOX fills with the defaults of every name it reads. Keep them in step with NOX.
  ParameterList p("NOX");
  set_choice(p, "Nonlinear Solver",
             {"Line Search Based", "Newton", "Trust Region Based", "Inexact Trust Region Based",
              "Tensor Based", "Anderson Accelerated Fixed-Point", "Single Step",
              "Pseudo-Transient"});
  ParameterList &printing = p.sublist("Printing"); // NOX::Utils
  for (const char *name : {"Output Information", "Output Precision", "Output Processor", "MyPID"})
    printing.set(name, 0);
  printing.set("Output Stream", Teuchos::RCP<std::ostream>()); // set by Kiln
  printing.set("Error Stream", Teuchos::RCP<std::ostream>());
  p.sublist("Line Search").setParameters(nox_line_search());
  p.sublist("Direction").setParameters(nox_direction("Newton"));
  p.sublist("Cauchy Direction").setParameters(nox_direction("Steepest Descent"));
  ParameterList &trust_region = p.sublist("Trust Region"); // both trust region solvers
  set_choice(trust_region, "Inner Iteration Method",
             {"Inexact Trust Region", "Standard Trust Region"});
  for (const char *name :
       {"Minimum Trust Region Radius", "Maximum Trust Region Radius", "Initial Trust Region Radius",
        "Minimum Improvement Ratio", "Contraction Trigger Ratio", "Expansion Trigger Ratio",
        "Contraction Factor", "Expansion Factor", "Recovery Step"})
    trust_region.set(name, 0.0);
  for (const char *name :
       {"Use Ared/Pred Ratio Calculation", "Use Cauchy in Newton Direction",
        "Use Dogleg Segment Minimization", "Use Counters", "Write Output Parameters"})
    trust_region.set(name, false);
  trust_region.sublist("Output", false, written_by_nox);
  ParameterList &anderson = p.sublist("Anderson Parameters");
  for (const char *name :
       {"Storage Depth", "Reorthogonalization Frequency", "Acceleration Start Iteration"})
    anderson.set(name, 0);
  anderson.set("Mixing Parameter", 1.0);
  anderson.set("Condition Number Drop Tolerance", 1e12);
  anderson.set("Adjust Matrix for Condition Number", false);
  anderson.set("Disable Checks for Unit Testing", false);
  anderson.sublist("Preconditioning"); // not checked
  ParameterList &single_step = p.sublist("Single Step Solver");
  for (const char *name :
       {"Ignore Linear Solver Failures", "Update Jacobian", "Print Norms", "Compute Relative Norm"})
    single_step.set(name, false);
  single_step.sublist("Linear Solver").setParameters(nox_linear_solver());
  p.sublist("Pseudo-Transient"); // NOX validates it when the solver is built
  p.sublist("Output", false, written_by_nox);
  return p;
}

} // namespace internal
} // namespace kiln
