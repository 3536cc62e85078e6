// The closing contact box (../shared/spec/contact-box.md, variant A) on tetrahedra, wedges and
// quadratic hexahedra (inputs/contact-box-{tet,wedge,hex27}.xml, issue 32) against the spec, as
// contact_box_contact tests the HEX8 deck inputs/contact-box-close.xml:
// - exact: each deck with contact_box_deck's tolerances (Newton 1e-12, GMRES 1e-13, steps of at
//   most 2 s, so that the temperature at 150 s is 308 K to ~1e-11 K): the open-gap state at 0 s,
//   open at 50 s, closed at 53 s, and at 150 s the spec's closed state to 1e-9 (every cell's
//   stress, strain, thermal strain, every node's displacement, every gap node's pressure).
//   Linear fields are exact on every cell type, so only round-off remains.
// - as the decks run: each deck (and contact-box-close.xml) with its own solver settings and
//   steps, the state at 150 s against the spec's closed state at 308 K, with a tolerance
//   computed from the run's own temperatures: with delta = max |T - 308 K| over the nodes (the
//   transient is not over: ~1e-6 K), a uniform error of delta in T changes the closed state by
//   delta / dT of itself (dT = 10 K); a non-uniform one changes the stress by at most that of a
//   body held on every side, 3 K alpha delta = E alpha delta / (1 - 2 nu), which is
//   (1 - nu) / (1 - 2 nu) times the closed state's E alpha delta / (1 - nu). Tolerance:
//   (1 - nu) / (1 - 2 nu) delta / dT (2 delta / dT for the spec's nu = 1/3) + 1e-9 (round-off),
//   for every tensor, the displacement and the contact pressure; components that are 0 to that
//   tolerance of the tensor's largest.
// KILN_TEST_NP: 1 2
#include "io/input_reader.hpp"
#include "support/contact_box.hpp"
#include "support/contact_box_runs.hpp"
#include "support/parallel.hpp"
#include "support/results_files.hpp"
#include "support/simulation_runs.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_DefaultComm.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace
{
using namespace kiln_test;

constexpr double T_final = 308.0; // [K] the spec's closed state at 150 s

/// inputs/<deck> as it is (its own solver settings and steps), the results at `base` at 150 s
/// (and 0 s, always written).
Teuchos::ParameterList deck_as_it_runs(const std::string &deck, const std::string &base)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  Teuchos::ParameterList input = kiln::read_input(inputs + deck, *comm);
  input.sublist("Output").set("File Base", base).set("Times", Teuchos::Array<double>(1, 150.0));
  return input;
}

/// inputs/<deck> as it runs, at 150 s: the spec's closed state at 308 K to the tolerance of the
/// run's own temperatures (file comment).
void check_deck_at_150_s(const std::string &deck)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string label = deck + " as it runs";
  const std::string base = temporary_base(deck.substr(0, deck.rfind('.')) + "_as_is", *comm);
  const Run r = run(deck_as_it_runs(deck, base), label);
  if (comm->getRank() == 0)
  {
    const std::string h5 = base + ".h5";
    double time = 0.0;
    const std::vector<double> T = read_last_step(h5, "temperature", time);
    ASSERT_FALSE(T.empty()) << label;
    double delta = 0.0;
    for (const double t : T)
      delta = std::max(delta, std::abs(t - T_final));
    const double dT = T_final - spec_T_ref;
    const double rel = (1.0 - spec_nu) / (1.0 - 2.0 * spec_nu) * delta / dT + 1e-9;
    const UniformState exact = spec_closed_gap_state(T_final);
    double largest_stress = 0.0, largest_strain = 0.0;
    for (int k = 0; k < 6; ++k)
    {
      largest_stress = std::max(largest_stress, std::abs(exact.stress[k]));
      largest_strain = std::max(largest_strain, std::abs(exact.strain[k]));
    }
    rank0_out() << label << ": max |T - " << T_final << " K| = " << delta
                << " K, so the tolerance is " << rel << "\n";
    check_uniform_state(label, h5, -1, 150.0, T_final, exact, true,
                        {rel, rel * largest_stress, rel * largest_strain, delta}, r);
  }
  remove_results(base, *comm);
}
} // namespace

TEST(ContactBoxCellTypes, TetrahedraExact)
{
  check_closing_box("contact-box-tet.xml", MeshKind::generated);
}

TEST(ContactBoxCellTypes, WedgesExact)
{
  check_closing_box("contact-box-wedge.xml", MeshKind::generated);
}

TEST(ContactBoxCellTypes, Hex27Exact)
{
  check_closing_box("contact-box-hex27.xml", MeshKind::generated);
}

TEST(ContactBoxCellTypes, Hex8DeckAsItRuns)
{
  check_deck_at_150_s("contact-box-close.xml");
}

TEST(ContactBoxCellTypes, TetrahedraDeckAsItRuns)
{
  check_deck_at_150_s("contact-box-tet.xml");
}

TEST(ContactBoxCellTypes, WedgesDeckAsItRuns)
{
  check_deck_at_150_s("contact-box-wedge.xml");
}

TEST(ContactBoxCellTypes, Hex27DeckAsItRuns)
{
  check_deck_at_150_s("contact-box-hex27.xml");
}
