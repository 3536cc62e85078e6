// Tests src/solvers/package_parameters.cpp: the smoother parameters Kiln adds for the chosen
// MueLu smoother and Krylov method.
#include "solvers/package_parameters.hpp"

#include <gtest/gtest.h>

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
