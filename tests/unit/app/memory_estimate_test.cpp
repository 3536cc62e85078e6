// Tests src/app/memory_estimate.cpp: the estimate's terms (the mesh held whole on every rank,
// the unknowns shared among the ranks, the Krylov basis of the chosen Belos solver), its text,
// and check_memory(): a box that cannot fit is the same InputError on every rank, naming
// "Cells", before anything is allocated; one that fits prints the estimate.
// KILN_TEST_NP: 1 2
#include "app/memory_estimate.hpp"

#include "app/simulation.hpp"
#include "base/parameters.hpp"
#include "support/parameter_lists.hpp"

#include <Teuchos_DefaultComm.hpp>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sstream>
#include <string>

namespace
{
using kiln::MemoryEstimate;
using testing::HasSubstr;

/// The validated root list of an input with a box of `cells`^3 and the default solvers.
Teuchos::ParameterList input(const int cells)
{
  Teuchos::ParameterList p;
  p.sublist("Mesh").sublist("Box").set("Cells", kiln_test::ids({cells, cells, cells}));
  return kiln::validated(p, kiln::Simulation::valid_parameters(), "in.xml", "Kiln");
}

TEST(MemoryEstimate, TheMeshIsOnEveryRankTheUnknownsAreShared)
{
  const MemoryEstimate one(1000, 1331, 4, 0, 1), two(1000, 1331, 4, 0, 2);
  EXPECT_EQ(one.unknowns(), 4 * 1331);
  EXPECT_DOUBLE_EQ(two.mesh_bytes(), one.mesh_bytes());
  EXPECT_DOUBLE_EQ(two.unknown_bytes(), 0.5 * one.unknown_bytes());
  // The calibrated figures: 3140 bytes per cell and 2787 per unknown for 4 unknowns per node,
  // 3100 and 2052 for 3 (elasticity), 480 and 551 for one; a Krylov vector is 8 bytes per
  // unknown; another number of unknowns per node takes the line through 1 and 4.
  EXPECT_NEAR(one.mesh_bytes(), 1000 * 3140.0, 1000 * 1.0);
  EXPECT_NEAR(one.unknown_bytes(), 4 * 1331 * 2787.0, 4 * 1331 * 1.0);
  const MemoryEstimate heat(1000, 1331, 1, 0, 1), krylov(1000, 1331, 1, 101, 1);
  const MemoryEstimate elastic(1000, 1331, 3, 0, 1), two_fields(1000, 1331, 2, 0, 1);
  EXPECT_NEAR(heat.mesh_bytes(), 1000 * 480.0, 1000 * 1.0);
  EXPECT_NEAR(heat.unknown_bytes(), 1331 * 551.0, 1331 * 1.0);
  EXPECT_NEAR(elastic.mesh_bytes(), 1000 * 3100.0, 1000 * 1.0);
  EXPECT_NEAR(elastic.unknown_bytes(), 3 * 1331 * 2052.0, 3 * 1331 * 1.0);
  EXPECT_NEAR(two_fields.mesh_bytes(), 1000 * (480.0 + (3140.0 - 480.0) / 3), 1000 * 1.0);
  EXPECT_DOUBLE_EQ(krylov.unknown_bytes() - heat.unknown_bytes(), 1331 * 8.0 * 101);
  EXPECT_GT(heat.bytes_per_rank(), 90e6); // the program, Trilinos and MPI
}

TEST(MemoryEstimate, TheKrylovBasisIsTheChosenSolvers)
{
  const kiln::MeshFactory::Counts counts{1000, 1331, "box"};
  const kiln::DofLayout heat{true, false, false};
  // Kiln's flexible GMRES of 100 blocks keeps 101 vectors and the 100 preconditioned ones.
  Teuchos::ParameterList solver = input(4).sublist("Solver");
  EXPECT_THAT(MemoryEstimate::of(counts, heat, solver, 1).summary(),
              HasSubstr("with a Krylov basis of 201 vectors"));
  Teuchos::ParameterList &belos =
      solver.sublist("Linear Solver").sublist("Linear Solver Types").sublist("Belos");
  belos.sublist("Solver Types").sublist("Block GMRES").set("Flexible Gmres", false);
  EXPECT_THAT(MemoryEstimate::of(counts, heat, solver, 1).summary(),
              HasSubstr("with a Krylov basis of 101 vectors"));
  belos.set("Solver Type", "Pseudo Block CG");
  EXPECT_THAT(MemoryEstimate::of(counts, heat, solver, 1).summary(),
              HasSubstr("with a Krylov basis of 8 vectors"));
  belos.set("Solver Type", "Pseudo Block GMRES"); // not set in the input: Belos' default 300
  EXPECT_THAT(MemoryEstimate::of(counts, heat, solver, 1).summary(),
              HasSubstr("with a Krylov basis of 301 vectors"));
}

TEST(MemoryEstimate, PartsAddUpToTheTotal)
{
  const MemoryEstimate e(110592, 120050, 1, 201, 2);
  EXPECT_DOUBLE_EQ(e.bytes_per_rank(), e.base_bytes() + e.mesh_bytes() + e.unknown_bytes());
  EXPECT_THAT(e.summary(), HasSubstr(kiln::memory_text(e.base_bytes()) +
                                     " the program, its libraries and MPI; "));
}

TEST(MemoryEstimate, Text)
{
  EXPECT_EQ(kiln::memory_text(870e6), "870 MB");
  EXPECT_EQ(kiln::memory_text(1.234e9), "1.23 GB");
  EXPECT_EQ(kiln::memory_text(3.07e12), "3.07 TB");
  EXPECT_EQ(kiln::memory_text(4.28e3), "4.28 kB");
  EXPECT_EQ(MemoryEstimate(64, 150, 4, 201, 2).summary(),
            "about " + kiln::memory_text(MemoryEstimate(64, 150, 4, 201, 2).bytes_per_rank()) +
                " per rank (94 MB the program, its libraries and MPI; 201 kB on every rank for the "
                "64 cells (what more ranks do not divide: ghost "
                "rows, maps, the mesh); " +
                kiln::memory_text(MemoryEstimate(64, 150, 4, 201, 2).unknown_bytes()) +
                " for 1/2 of the 600 unknowns, with a Krylov basis of 201 vectors)");
}

TEST(CheckMemory, ABoxThatCannotFitIsRefusedNamingCells)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  std::ostringstream out;
  const std::string message = kiln_test::input_error_message(
      [&]
      {
        kiln::check_memory(input(1200), kiln::DofLayout{true, false, false}, "in.xml", "", *comm,
                           out);
      });
  EXPECT_THAT(message, testing::StartsWith("in.xml: Kiln/Mesh/Box/\"Cells\" = {1200, 1200, "
                                           "1200}: the run needs about "));
  EXPECT_THAT(message, HasSubstr("but this machine gives a rank about "));
  EXPECT_THAT(message, HasSubstr("use fewer cells (a coarser mesh), or more ranks on more nodes"));
  EXPECT_THAT(message, HasSubstr(", or a shorter Krylov basis (\"Num Blocks\" of the Belos solver "
                                 "in Kiln/Solver/Linear Solver: the estimate counts all 201 "
                                 "vectors of its basis"));
  EXPECT_EQ(out.str(), "");
  // CG keeps a few vectors: no basis to shorten.
  Teuchos::ParameterList cg = input(1200);
  cg.sublist("Solver")
      .sublist("Linear Solver")
      .sublist("Linear Solver Types")
      .sublist("Belos")
      .set("Solver Type", "Pseudo Block CG");
  EXPECT_THAT(
      kiln_test::input_error_message(
          [&] {
            kiln::check_memory(cg, kiln::DofLayout{true, false, false}, "in.xml", "", *comm, out);
          }),
      testing::Not(HasSubstr("Krylov basis (")));
}

TEST(CheckMemory, ABoxThatFitsIsPrinted)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  std::ostringstream out;
  kiln::check_memory(input(4), kiln::DofLayout{true, true, true}, "in.xml", "", *comm, out);
  if (comm->getRank() == 0)
  {
    EXPECT_THAT(out.str(), testing::StartsWith("memory: about "));
  }
  EXPECT_GT(kiln::peak_resident_memory(*comm), 0.0);
}
} // namespace
