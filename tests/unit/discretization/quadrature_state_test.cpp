// Tests src/discretization/quadrature_state.cpp: the layout (cells with their own numbers of
// points, none for some), the two copies and their semantics (a model writes current from
// old; commit() on an accepted step, restore() on a rejected one), components by name read and
// set in cell and point order.
#include "discretization/quadrature_state.hpp"

#include <gtest/gtest.h>

namespace
{
/// Three owned cells (global 7, 2, 9) with 8, 0 and 27 points, two components.
kiln::QuadratureState three_cells()
{
  return kiln::QuadratureState({"plastic_strain", "hardening"}, {7, 2, 9}, {8, 0, 27});
}
} // namespace

TEST(QuadratureState, LayoutPerOwnedCellWithItsOwnNumberOfPoints)
{
  const kiln::QuadratureState s = three_cells();
  EXPECT_EQ(s.n_state(), 2);
  EXPECT_EQ(s.n_cells(), 3);
  EXPECT_EQ(s.cells(), (std::vector<int>{7, 2, 9}));
  EXPECT_EQ(s.n_points(0), 8);
  EXPECT_EQ(s.n_points(1), 0);
  EXPECT_EQ(s.n_points(2), 27);
  EXPECT_EQ(s.n_points(), 35);
  EXPECT_EQ(s.names(), (std::vector<std::string>{"plastic_strain", "hardening"}));
  // Consecutive points are n_state() apart; the cell without points takes no room.
  EXPECT_EQ(s.old(0, 1) - s.old(0, 0), 2);
  EXPECT_EQ(s.old(2, 0) - s.old(0, 7), 2);
  for (int c = 0; c < s.n_cells(); ++c)
    for (int q = 0; q < s.n_points(c); ++q)
      for (int k = 0; k < 2; ++k)
      {
        EXPECT_EQ(s.old(c, q)[k], 0.0);
        EXPECT_EQ(s.current(c, q)[k], 0.0);
      }
}

TEST(QuadratureState, CommitOnAcceptanceRestoreOnRejection)
{
  kiln::QuadratureState s = three_cells();
  // An attempted step writes current; old is what was committed.
  s.current(2, 26)[1] = 3.5;
  s.current(0, 0)[0] = -1.0;
  EXPECT_EQ(s.old(2, 26)[1], 0.0);
  // Rejected: current is old again.
  s.restore();
  EXPECT_EQ(s.current(2, 26)[1], 0.0);
  EXPECT_EQ(s.current(0, 0)[0], 0.0);
  // Retried and accepted: old takes current.
  s.current(2, 26)[1] = 4.5;
  s.commit();
  EXPECT_EQ(s.old(2, 26)[1], 4.5);
  EXPECT_EQ(s.current(2, 26)[1], 4.5);
  // The next step starts from it; rejected, it goes back to the committed value, not to 0.
  s.current(2, 26)[1] = 9.0;
  s.restore();
  EXPECT_EQ(s.current(2, 26)[1], 4.5);
  EXPECT_EQ(s.old(2, 26)[1], 4.5);
}

TEST(QuadratureState, ComponentsInCellAndPointOrder)
{
  kiln::QuadratureState s = three_cells();
  for (int c = 0; c < s.n_cells(); ++c)
    for (int q = 0; q < s.n_points(c); ++q)
    {
      s.current(c, q)[0] = 100.0 * c + q;
      s.current(c, q)[1] = -(100.0 * c + q);
    }
  // Only the committed state is a component.
  EXPECT_EQ(s.old_component(0), std::vector<double>(35, 0.0));
  s.commit();
  const std::vector<double> first = s.old_component(0), second = s.old_component(1);
  ASSERT_EQ(first.size(), 35u);
  EXPECT_EQ(first[0], 0.0);
  EXPECT_EQ(first[7], 7.0);
  EXPECT_EQ(first[8], 200.0);
  EXPECT_EQ(first[34], 226.0);
  EXPECT_EQ(second[34], -226.0);
  // A restart sets both copies.
  std::vector<double> values(35);
  for (std::size_t p = 0; p < values.size(); ++p)
    values[p] = 0.5 * static_cast<double>(p);
  s.set_component(1, values);
  EXPECT_EQ(s.old(2, 0)[1], 4.0);
  EXPECT_EQ(s.current(2, 0)[1], 4.0);
  EXPECT_EQ(s.old(2, 0)[0], 200.0); // the other component is untouched
  EXPECT_EQ(s.old_component(1), values);
}

TEST(QuadratureState, NoOwnedPointsIsEmptyButValid)
{
  kiln::QuadratureState s({"a"}, {}, {});
  EXPECT_EQ(s.n_cells(), 0);
  EXPECT_EQ(s.n_points(), 0);
  s.commit();
  s.restore();
  EXPECT_TRUE(s.old_component(0).empty());
}
