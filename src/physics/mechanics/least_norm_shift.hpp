#pragma once
/// The small quadratic programme of the minimum-norm solution with contact (doc/contact.md,
/// "Free motions while pairs open").

#include <vector>

namespace kiln
{
/// min over c of c^T M c + 2 b^T c subject to A c >= h, for k unknowns and m constraints: M
/// (k x k, symmetric positive definite, column-major), b (k), A (m x k, row-major: row i is
/// constraint i), h (m) with h <= 0, so that c = 0 is feasible. A primal active-set method
/// (Nocedal and Wright, Algorithm 16.3) from c = 0 with an empty working set; a blocking
/// constraint joins it (it is independent of those in it), one with a negative multiplier
/// leaves it. The result is exact to round-off: the problem is solved, not regularized.
/// "Zero" is relative to max |b| and max |c|: scale the unknowns so that M's diagonal is 1.
/// Throws std::runtime_error after 10 (k + m) + 100 iterations (a degenerate cycle).
///
/// Hand-written, not ROL (Trilinos 13.2, header-only): measured by benchmarks/least_norm_qp.sh
/// on the unit test's problems, the QPs of Truchas' contact-1 and contact-2 (k 6, m 15) and
/// random ones up to k 50, m 150 (doc/contact.md, "Free motions while pairs open": the figures).
/// ROL's TypeG Augmented Lagrangian and TypeB Trust Region with its polyhedral projection, every
/// tolerance 1e-14, the problem scaled to order 1 (ROL's tolerances are absolute), are
/// iterative and end at a tolerance, not at the solution: 3e-5 to 0.17 off on contact-1/-2's
/// QPs (the tests ask 1e-10), 60 to 1,000,000 times slower (this: 3 us on those QPs), and the
/// trust region does not converge on 12 of the 16 problems (it hangs inside an iteration on
/// most; degenerate rows, as on a gap between free bodies, among them).
std::vector<double> least_norm_shift(int k, const std::vector<double> &M,
                                     const std::vector<double> &b, int m,
                                     const std::vector<double> &A, const std::vector<double> &h);
} // namespace kiln
