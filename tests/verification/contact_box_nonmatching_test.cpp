// The contact box with its halves meshed apart (issue 30, step 4 of doc/contact.md's order of
// work): inputs/contact-box-nonmatching.xml, the closing deck (variant A of
// ../shared/spec/contact-box.md) with the half x < 0 in 4 x 4 x 4 cells and the half x > 0 in
// 5 x 3 x 6, touching, coupled by the mortar pairing "cut" (rows with weighted partners),
// each half heated by its own end face (no heat crosses the pair yet). Run with the
// verification tolerances (contact_box_deck: Newton 1e-12 relative, GMRES 1e-13, steps of at
// most 2 s) to 150 s: at 0 s the open-gap state at 288 K, at 150 s 308 K to 1e-9 of dT and the
// spec's closed-gap state, every cell's stress, strain and thermal strain to 1e-9 of the
// tensor's largest component and every node's displacement to 1e-9 of the largest: the
// contact patch test across non-matching meshes. The same at np 1 and np 2 (the cut faces
// split across the ranks by METIS).
// KILN_TEST_NP: 1 2
#include "support/contact_box.hpp"
#include "support/contact_box_runs.hpp"
#include "support/results_files.hpp"

#include <Teuchos_DefaultComm.hpp>
#include <gtest/gtest.h>

#include <string>

namespace
{
using namespace kiln_test;
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
  }
  remove_results(base, *comm);
}
