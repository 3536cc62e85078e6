// Tests src/solvers/package_parameters.cpp: the smoother parameters Kiln adds for the chosen
// MueLu smoother and Krylov method.
#include "solvers/package_parameters.hpp"

#include <gtest/gtest.h>

#include <string>
#include <utility>

namespace
{
using Teuchos::ParameterList;

/// Kiln's default Stratimikos list with the Belos solver `krylov`.
ParameterList with_krylov(const std::string &krylov)
{
  ParameterList p = kiln::internal::linear_solver_defaults();
  p.sublist("Linear Solver Types").sublist("Belos").set("Solver Type", krylov);
  return p;
}

std::string relaxation(ParameterList p)
{
  kiln::internal::add_smoother_defaults(p);
  return p.sublist("Preconditioner Types")
      .sublist("MueLu")
      .sublist("smoother: params")
      .get<std::string>("relaxation: type");
}

TEST(SmootherDefaults, ForwardGaussSeidelUnderGmres)
{
  EXPECT_EQ(relaxation(kiln::internal::linear_solver_defaults()), "Gauss-Seidel");
  EXPECT_EQ(relaxation(with_krylov("Pseudo Block GMRES")), "Gauss-Seidel");
  EXPECT_EQ(relaxation(with_krylov("TFQMR")), "Gauss-Seidel");
}

TEST(SmootherDefaults, SymmetricGaussSeidelUnderCgAndMinres)
{
  for (const char *krylov : {"Pseudo Block CG", "Block CG", "MINRES"})
    EXPECT_EQ(relaxation(with_krylov(krylov)), "Symmetric Gauss-Seidel") << krylov;
}

TEST(SmootherDefaults, SymmetricGaussSeidelForOneUnknownPerNode)
{
  ParameterList p = kiln::internal::linear_solver_defaults();
  ParameterList &muelu = p.sublist("Preconditioner Types").sublist("MueLu");
  muelu.set("number of equations", 1);
  EXPECT_EQ(relaxation(p), "Symmetric Gauss-Seidel");
  muelu.set("number of equations", 4);
  EXPECT_EQ(relaxation(p), "Gauss-Seidel");
}

TEST(SmootherDefaults, TheInputsChoiceIsKept)
{
  ParameterList p = with_krylov("Pseudo Block CG");
  p.sublist("Preconditioner Types")
      .sublist("MueLu")
      .sublist("smoother: params")
      .set("relaxation: type", "Jacobi");
  EXPECT_EQ(relaxation(p), "Jacobi");
}

TEST(SmootherDefaults, L1GaussSeidelUnlessTheInputSaysOtherwise)
{
  const auto l1 = [](ParameterList p)
  {
    kiln::internal::add_smoother_defaults(p);
    const ParameterList &params =
        p.sublist("Preconditioner Types").sublist("MueLu").sublist("smoother: params");
    return params.isType<bool>("relaxation: use l1") && params.get<bool>("relaxation: use l1");
  };
  EXPECT_TRUE(l1(kiln::internal::linear_solver_defaults()));
  EXPECT_TRUE(l1(with_krylov("Pseudo Block CG")));
  ParameterList p = kiln::internal::linear_solver_defaults();
  p.sublist("Preconditioner Types")
      .sublist("MueLu")
      .sublist("smoother: params")
      .set("relaxation: use l1", false);
  EXPECT_FALSE(l1(p));
  // Not a relaxation smoother: nothing added.
  p = kiln::internal::linear_solver_defaults();
  p.sublist("Preconditioner Types").sublist("MueLu").set("smoother: type", "CHEBYSHEV");
  kiln::internal::add_smoother_defaults(p);
  EXPECT_FALSE(p.sublist("Preconditioner Types")
                   .sublist("MueLu")
                   .sublist("smoother: params")
                   .isParameter("relaxation: use l1"));
}

/// The Chebyshev smoother's eigenvalue analysis Kiln adds: (type, iterations).
std::pair<std::string, int> chebyshev_eigen_analysis(ParameterList p)
{
  p.sublist("Preconditioner Types").sublist("MueLu").set("smoother: type", "CHEBYSHEV");
  kiln::internal::add_smoother_defaults(p);
  const ParameterList &c =
      p.sublist("Preconditioner Types").sublist("MueLu").sublist("smoother: params");
  return {c.isType<std::string>("eigen-analysis: type") ? c.get<std::string>("eigen-analysis: type")
                                                        : std::string("(Ifpack2's default)"),
          c.get<int>("chebyshev: eigenvalue max iterations")};
}

TEST(SmootherDefaults, ChebyshevEigenvaluesByCgUnderCg)
{
  using Analysis = std::pair<std::string, int>;
  for (const char *krylov : {"Pseudo Block CG", "Block CG"})
    EXPECT_EQ(chebyshev_eigen_analysis(with_krylov(krylov)), Analysis("cg", 10)) << krylov;
  // Not symmetric positive definite: the power method, 30 iterations.
  for (const char *krylov : {"Pseudo Block GMRES", "MINRES"})
    EXPECT_EQ(chebyshev_eigen_analysis(with_krylov(krylov)), Analysis("power method", 30))
        << krylov;
  // The input's choice of either is kept, the other not added.
  ParameterList p = with_krylov("Pseudo Block CG");
  ParameterList &params =
      p.sublist("Preconditioner Types").sublist("MueLu").sublist("smoother: params");
  params.set("chebyshev: eigenvalue max iterations", 50);
  EXPECT_EQ(chebyshev_eigen_analysis(p), Analysis("(Ifpack2's default)", 50));
  params.remove("chebyshev: eigenvalue max iterations");
  params.set("eigen-analysis: type", "power method");
  EXPECT_EQ(chebyshev_eigen_analysis(p), Analysis("power method", 30));
}

TEST(MueLuDefaults, ImplicitTransposeForAggregationNotPetrovGalerkin)
{
  const auto implicit = [](ParameterList p)
  {
    kiln::internal::add_smoother_defaults(p);
    const ParameterList &muelu = p.sublist("Preconditioner Types").sublist("MueLu");
    return muelu.isType<bool>("transpose: use implicit") &&
           muelu.get<bool>("transpose: use implicit");
  };
  ParameterList p = kiln::internal::linear_solver_defaults();
  EXPECT_TRUE(implicit(p));
  ParameterList &muelu = p.sublist("Preconditioner Types").sublist("MueLu");
  muelu.set("multigrid algorithm", "pg");
  EXPECT_FALSE(implicit(p));
  muelu.set("multigrid algorithm", "sa");
  muelu.set("transpose: use implicit", false); // the input's choice
  EXPECT_FALSE(implicit(p));
}
} // namespace
