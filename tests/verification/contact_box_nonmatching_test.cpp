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
// inputs/contact-box-finite-gap.xml, the same with the half x > 0 moved away by g0 = 3.52e-6 m,
// one run with outputs every 10 s to 50 s, then at 55, 58, 59.5, 61, 62.5, 64, 66 and 150 s:
// while every row is open, the secondary surface's mean opening sum_j D_jj g_j / A (D_jj the
// pair output's nodal "area") against the hand calculation g0 - L (1 + nu) alpha (T_mean -
// T_ref), T_mean the history's volume average, to 1e-9 of g0 (measured within 3.7e-18 m, 1e-12
// of g0, at every open output): exact for the discretization although the temperature is not
// uniform (each half heated at its end face), since the rollers leave the sections free of
// resultant force (doc/contact.md, "The finite gap's closing"). So the mean opening vanishes at
// T_mean = 301 K, the deck's hand temperature, near 61.5 s: every row open at 61 s (T_mean
// 300.86 K; the rows' openings spread about their mean, 6.6e-8 to 1.9e-7 m, as the halves bend
// a little under their non-uniform temperature) and every row closed (|g_j| < 1e-15 m) at 62.5 s
// (301.29 K); at 150 s the closed state with eps_xx = g0 / L instead of 0: the spec's closed
// state at 308 K plus 0.3 of the difference to the open state (g0 / (L (1 + nu) alpha dT) =
// 3.52e-6 / (1.17333e-6 * 10)), to 1e-9 as above.
// KILN_TEST_NP: 1 2
#include "support/contact_box.hpp"
#include "support/contact_box_runs.hpp"
#include "support/results_files.hpp"

#include <Teuchos_DefaultComm.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using namespace kiln_test;

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
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string deck = "contact-box-finite-gap.xml";
  const std::string label = deck + " on the generated halves";
  const std::string base = temporary_base("finite_gap", *comm);
  // Output every 10 s while open, then every 1.5 s about the closing (301 K by hand, near 60 s).
  const std::vector<double> times = {0, 10, 20, 30, 40, 50, 55, 58, 59.5, 61, 62.5, 64, 66, 150};
  const kiln_test::Run r =
      run(contact_box_deck(deck, MeshKind::generated, base, times), label, false);
  if (comm->getRank() == 0)
  {
    const std::string h5 = base + ".h5";
    // The pair's opening against the hand calculation while open: g0 - L (1 + nu) alpha
    // (T_mean - T_ref), for the secondary surface's mean opening sum_j D_jj g_j / A (D_jj: the
    // output's "area" of the node, its share of the flat faces), T_mean the history's volume
    // average. Exact for the discretization (doc/contact.md, "The finite gap's closing"), so to
    // 1e-9 of g0.
    const double g0 = 3.52e-6, L = 0.04, A = L * L, T_ref = 298.0;
    const double slope = L * (1.0 + spec_nu) * spec_alpha; // [m/K]
    const std::vector<double> D = read_dataset(h5, "/pair_cut/area");
    const std::vector<double> history_time = read_dataset(h5, "/history/time");
    const std::vector<double> T_mean = read_dataset(h5, "/history/T_mean");
    ASSERT_EQ(T_mean.size(), history_time.size());
    const auto mean_temperature = [&](const double t)
    {
      for (std::size_t k = 0; k < history_time.size(); ++k)
        if (history_time[k] == t)
          return T_mean[k];
      ADD_FAILURE() << "no history row at " << t << " s";
      return std::nan("");
    };
    double last_open = -1.0, first_closed = -1.0;
    for (std::size_t step = 0; step < times.size(); ++step)
    {
      char at[64];
      std::snprintf(at, sizeof at, "/pair_cut/steps/%06zu/", step);
      const std::vector<double> g = read_dataset(h5, std::string(at) + "gap_opening");
      const std::vector<double> active = read_dataset(h5, std::string(at) + "contact_active");
      ASSERT_EQ(g.size(), D.size());
      int rows = 0, closed = 0;
      double mean = 0.0, g_min = 1.0, g_max = -1.0;
      for (std::size_t p = 0; p < g.size(); ++p)
        if (!std::isnan(active[p]))
        {
          ++rows;
          closed += active[p] == 1.0;
          mean += D[p] * g[p] / A;
          g_min = std::min(g_min, g[p]);
          g_max = std::max(g_max, g[p]);
        }
      EXPECT_EQ(rows, 28) << "rows at " << times[step] << " s";
      const double T = mean_temperature(times[step]);
      const double hand = g0 - slope * (T - T_ref);
      std::printf("%6.1f s: T_mean %.6f K, %2d of %d rows closed, mean opening %.9e m, hand "
                  "%.9e m (difference %.2e m), rows' openings in [%.4e, %.4e] m\n",
                  times[step], T, closed, rows, mean, hand, mean - hand, g_min, g_max);
      if (closed == 0)
      {
        EXPECT_NEAR(mean, hand, 1e-9 * g0) << "at " << times[step] << " s";
        last_open = times[step];
      }
      else if (closed == rows)
      {
        EXPECT_LT(std::max(-g_min, g_max), 1e-15) << "at " << times[step] << " s";
        if (first_closed < 0.0)
          first_closed = times[step];
      }
    }
    // The hand closing: T_mean = T_ref + g0 / slope = 301 K, between the last output with every
    // row open and the first with every row closed (the rows close over about 2 s: the halves
    // bend a little under their non-uniform temperature, so that the openings spread about
    // their mean).
    EXPECT_NEAR(T_ref + g0 / slope, 301.0, 1e-9);
    EXPECT_EQ(last_open, 61.0);
    EXPECT_EQ(first_closed, 62.5);
    EXPECT_LT(mean_temperature(last_open), 301.0);
    EXPECT_GT(mean_temperature(first_closed), 301.0);

    // g0 / (L (1 + nu) alpha dT): the share of the open state's eps_xx that the gap leaves.
    const double f = 3.52e-6 / (0.04 * (1.0 + spec_nu) * spec_alpha * 10.0);
    EXPECT_NEAR(f, 0.3, 1e-12);
    check_uniform_state(label, h5, static_cast<int>(times.size()) - 1, 150.0, 308.0,
                        mix(spec_closed_gap_state(308.0), spec_open_gap_state(308.0), f), true,
                        1e-9, r);
  }
  remove_results(base, *comm);
}
