// Tests app/contact_events (the summary's "closed at" / "opened at"): a real closing and
// opening are events; a row that touches with a pressure of round-off only and flips in and out
// of contact is not (split_and_pair's pair before it closes, with "Free Motions" = "Minimum
// Norm"); loaded rows that unload to round-off before they leave contact open; and the
// round-off threshold of a pressure (carries_load).
#include "app/contact_events.hpp"
#include "physics/state_summary.hpp"

#include <gtest/gtest.h>

using kiln::ContactEvents;

TEST(ContactEvents, ClosesAndOpensWithALoad)
{
  ContactEvents events;
  EXPECT_FALSE(events.started());
  events.start(0, 0);
  EXPECT_TRUE(events.started());
  events.step(1.0, 4, 2, 2);
  events.step(2.0, 4, 4, 4);
  events.step(3.0, 4, 4, 4);
  events.step(4.0, 4, 0, 0);
  EXPECT_EQ(events.closed(), std::vector<double>({2.0}));
  EXPECT_EQ(events.opened(), std::vector<double>({4.0}));
}

TEST(ContactEvents, RoundOffFlipsAreNoEvents)
{
  // One row touches at a pressure of round-off (active, not loaded), leaves contact, comes
  // back; then every row closes with a load.
  ContactEvents events;
  events.start(1, 0);
  events.step(27.0, 28, 0, 0);
  events.step(28.0, 28, 1, 0);
  events.step(35.0, 28, 0, 0);
  events.step(36.0, 28, 1, 0);
  events.step(53.0, 28, 28, 28);
  events.step(60.0, 28, 28, 28);
  EXPECT_EQ(events.closed(), std::vector<double>({53.0}));
  EXPECT_TRUE(events.opened().empty());
}

TEST(ContactEvents, UnloadingToRoundOffOpens)
{
  // The load goes, one row stays in contact at a pressure of round-off: the rows opened then,
  // not when that row leaves contact.
  ContactEvents events;
  events.start(3, 3);
  events.step(1.0, 3, 1, 0);
  events.step(2.0, 3, 0, 0);
  EXPECT_EQ(events.opened(), std::vector<double>({1.0}));
  EXPECT_TRUE(events.closed().empty());
}

TEST(ContactEvents, StartIsTheReference)
{
  // A run (or a restart) that starts closed has not closed; a restart that starts loaded and
  // opens has opened.
  ContactEvents events;
  events.start(5, 5);
  events.step(1.0, 5, 5, 5);
  events.step(2.0, 5, 0, 0);
  EXPECT_TRUE(events.closed().empty());
  EXPECT_EQ(events.opened(), std::vector<double>({2.0}));
}

TEST(ContactEvents, RoundOffPressureThreshold)
{
  const double modulus = 2.7e11;                   // lambda + 2G of steel [Pa]
  EXPECT_FALSE(kiln::carries_load(3e-7, modulus)); // split_and_pair's round-off
  EXPECT_FALSE(kiln::carries_load(0.0, modulus));
  EXPECT_FALSE(kiln::carries_load(-1.0, modulus));   // tension: no load
  EXPECT_TRUE(kiln::carries_load(1.0, modulus));     // 1 Pa is a load
  EXPECT_TRUE(kiln::carries_load(2.288e7, modulus)); // the box's closed state
}
