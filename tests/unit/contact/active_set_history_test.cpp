// ActiveSetHistory: a contact active set that comes back after a different one is a cycle;
// an unchanged set, or a new one, is not. Each rank holds its own part of the set, and a
// cycle needs the same set on every rank.
// KILN_TEST_NP: 1 2
#include "contact/active_set_history.hpp"

#include <Teuchos_DefaultComm.hpp>
#include <gtest/gtest.h>

namespace
{
using Set = std::vector<char>;
}

TEST(ActiveSetHistory, ARepeatedEarlierSetIsACycle)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  kiln::ActiveSetHistory h;
  EXPECT_EQ(h.record(Set{0, 0, 1}, *comm), 0);
  EXPECT_EQ(h.record(Set{1, 0, 1}, *comm), 0);
  EXPECT_EQ(h.record(Set{0, 0, 1}, *comm), 1); // A -> B -> A
  EXPECT_EQ(h.size(), 3);
}

TEST(ActiveSetHistory, UnchangedOrNewSetsAreNoCycle)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  kiln::ActiveSetHistory h;
  EXPECT_EQ(h.record(Set{0, 0}, *comm), 0);
  EXPECT_EQ(h.record(Set{1, 0}, *comm), 0);
  EXPECT_EQ(h.record(Set{1, 1}, *comm), 0);
  EXPECT_EQ(h.record(Set{1, 1}, *comm), 0); // settled, not cycling
  EXPECT_EQ(h.record(Set{1, 1}, *comm), 0);
  h.clear();
  EXPECT_EQ(h.size(), 0);
  EXPECT_EQ(h.record(Set{0, 0}, *comm), 0); // a new step starts afresh
}

TEST(ActiveSetHistory, ACycleNeedsTheSameSetOnEveryRank)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const bool last = comm->getRank() == comm->getSize() - 1;
  kiln::ActiveSetHistory h;
  EXPECT_EQ(h.record(Set{0}, *comm), 0);
  EXPECT_EQ(h.record(Set{1}, *comm), 0);
  // Back to the first set everywhere but on the last rank (which goes on to a new set):
  // a cycle only on one rank.
  // On one rank that is just a new set.
  EXPECT_EQ(h.record(Set{last ? char(2) : char(0)}, *comm), 0);
  // Then the first set on every rank: a cycle back to iteration 1.
  EXPECT_EQ(h.record(Set{0}, *comm), 1);
}
