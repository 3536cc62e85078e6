// The contact box with its halves meshed apart (issue 30, step 4 of doc/contact.md's order of
// work): inputs/contact-box-nonmatching.xml, the closing deck (variant A of
// ../shared/spec/contact-box.md) with the half x < 0 in 4 x 4 x 4 cells and the half x > 0 in
// 5 x 3 x 6, touching, coupled by the mortar pairing "cut" (rows with weighted partners),
// heat crossing it by the seed's gap conductance (Heat Transfer/Conductance 1e4 W/(m^2 K)). Run
// with the verification tolerances (contact_box_deck: Newton 1e-12 relative, GMRES 1e-13, steps of
// at most 2 s) to 150 s: at 0 s the open-gap state at 288 K, at 150 s 308 K to 1e-9 of dT and the
// spec's closed-gap state, every cell's stress, strain and thermal strain to 1e-9 of the
// tensor's largest component and every node's displacement to 1e-9 of the largest: the
// contact patch test across non-matching meshes. The same at np 1 and np 2 (the cut faces
// split across the ranks by METIS).
// inputs/contact-box-finite-gap.xml, the same with the half x > 0 moved away by g0 = 3.52e-6 m:
// open at 55 s (the end faces at 299.50 K) and closed at 66 s (302.64 K), the hand
// calculation's closing temperature being 301 K (the deck's comment; the halves' mean lags the
// end faces by about 0.4 K while they heat at 0.29 K/s, so nearer times would test the lag:
// at 61.5 s, 301.39 K at the ends, 7 of the 28 rows are closed); at 150 s the closed
// state with eps_xx = g0 / L instead of 0: the spec's closed state at 308 K plus 0.3 of the
// difference to the open state (g0 / (L (1 + nu) alpha dT) = 3.52e-6 / (1.17333e-6 * 10)), to
// 1e-9 as above.
// KILN_TEST_NP: 1 2
#include "app/simulation.hpp"
#include "physics/coupled_problem.hpp"
#include "support/contact_box.hpp"
#include "support/contact_box_runs.hpp"
#include "support/results_files.hpp"

#include <Teuchos_DefaultComm.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace
{
using namespace kiln_test;

/// The number of pairs in contact and of pairs at the end of `deck` run to `t` [s].
std::pair<int, int> active_at(const std::string &deck, const double t)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string base = temporary_base("finite_gap_to_" + std::to_string(t), *comm);
  std::pair<int, int> counts;
  {
    kiln::Simulation sim(contact_box_deck(deck, MeshKind::generated, base, {0.0, t}), deck, comm);
    sim.run();
    kiln::NonlinearProblem::Vector x(sim.solution(), Teuchos::Copy);
    counts = {sim.problem().n_active_pairs(x), sim.problem().n_pairs()};
  }
  remove_results(base, *comm);
  return counts;
}

/// a + f (b - a) for the stress, strain and box-frame strains; a's thermal strain and rotation.
UniformState mix(const UniformState &a, const UniformState &b, const double f)
{
  UniformState s = a;
  for (int k = 0; k < 6; ++k)
  {
    s.stress[k] += f * (b.stress[k] - a.stress[k]);
    s.strain[k] += f * (b.strain[k] - a.strain[k]);
  }
  s.eps_xx += f * (b.eps_xx - a.eps_xx);
  s.eps_yy += f * (b.eps_yy - a.eps_yy);
  s.contact_pressure += f * (b.contact_pressure - a.contact_pressure);
  return s;
}
} // namespace

TEST(ContactBoxNonmatching, ClosedStateAcrossNonMatchingHalves)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string deck = "contact-box-nonmatching.xml";
  const std::string label = deck + " on the generated halves";
  const std::string base = temporary_base("nonmatching", *comm);
  const kiln_test::Run r = run(
      contact_box_deck(deck, MeshKind::generated, base, {0.0, 50.0, 53.0, 150.0}), label, false);
  EXPECT_EQ(r.mesh.n_cells(), 64 + 90);
  if (comm->getRank() == 0)
  {
    const std::string h5 = base + ".h5";
    check_uniform_state(label, h5, 0, 0.0, 288.0, spec_open_gap_state(288.0), false, 1e-9, r);
    check_uniform_state(label, h5, 3, 150.0, 308.0, spec_closed_gap_state(308.0), true, 1e-9, r);
    check_pair_output(label, base, spec_closed_gap_state(308.0).contact_pressure);
  }
  remove_results(base, *comm);
}

TEST(ContactBoxNonmatching, FiniteGapClosesAtTheHandTemperature)
{
  const std::string deck = "contact-box-finite-gap.xml";
  const auto open = active_at(deck, 55.0);
  EXPECT_GT(open.second, 0);
  EXPECT_EQ(open.first, 0) << "pairs in contact at 55 s (299.50 K)";
  const auto closed = active_at(deck, 66.0);
  EXPECT_EQ(closed.first, closed.second) << "pairs in contact at 66 s (302.64 K)";

  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string label = deck + " on the generated halves";
  const std::string base = temporary_base("finite_gap", *comm);
  const kiln_test::Run r =
      run(contact_box_deck(deck, MeshKind::generated, base, {0.0, 150.0}), label, false);
  if (comm->getRank() == 0)
  {
    // g0 / (L (1 + nu) alpha dT): the share of the open state's eps_xx that the gap leaves.
    const double f = 3.52e-6 / (0.04 * (1.0 + spec_nu) * spec_alpha * 10.0);
    EXPECT_NEAR(f, 0.3, 1e-12);
    check_uniform_state(label, base + ".h5", 1, 150.0, 308.0,
                        mix(spec_closed_gap_state(308.0), spec_open_gap_state(308.0), f), true,
                        1e-9, r);
  }
  remove_results(base, *comm);
}
