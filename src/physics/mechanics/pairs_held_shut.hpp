#pragma once
/// With "Free Motions" = "Minimum Norm": the open pairs held shut so that the bodies stay held
/// as at set-up (doc/contact.md, "Free motions while pairs open").
#include "contact/interface_strategy.hpp"
#include "physics/mechanics/free_motions.hpp"

#include <functional>
#include <memory>
#include <vector>

namespace kiln
{
/// After the interfaces decided a state: while the pairs that hold leave the bodies more free
/// motions than the set-up's (`free`), holds shut one more open pair, the least open of those
/// that one of the extra motions would open or close (ties: the lowest interface, then pair
/// index), and has its interface decide again (`decide_again`, which must not assemble). Each
/// pair held shut takes away at least one motion, so there are at most as many as extra
/// motions. A pair held shut has g = 0 and the multiplier its rows balance: zero when the
/// pairs held shut hold only what nothing else does (the load has no part along those
/// motions). Returns how many were held shut. Collective.
int hold_pairs_shut(const FreeMotions &free,
                    const std::vector<std::unique_ptr<InterfaceStrategy>> &interfaces,
                    const std::function<void(InterfaceStrategy &)> &decide_again,
                    const Teuchos::Comm<int> &comm);

/// At a solution x (the set-up's free motions already projected out, the interfaces decided
/// at x): the minimum-norm solution. The solutions differ by the rigid motions W that the
/// pairs holding with their law at a pressure above round-off (1e-9 of the largest; not
/// those held shut) leave free and that open no pair to a
/// negative g: x + B c (B: W in the unknowns) with d_i.(r_b - r_a)(c) + g_i >= min(g_i, 0)
/// at each open or held-shut pair i, which moves no holding pair and leaves F unchanged. The
/// least |x + B c| is a small quadratic programme in c (least_norm_shift(): k unknowns, one
/// row per pair that W moves, gathered on every rank); x += B c. Nothing if W holds no more
/// than the set-up's motions. Returns max |B c| [unit of x]. Collective.
double shift_to_minimum_norm(const FreeMotions &free,
                             const std::vector<std::unique_ptr<InterfaceStrategy>> &interfaces,
                             Tpetra::Vector<> &x);
} // namespace kiln
