// Kiln's hand-written least_norm_shift() (a primal active-set QP, src/physics/mechanics/) against
// ROL (Debian's Trilinos 13.2) on the same problems: min c^T M c + 2 b^T c with A c >= h.
// doc/contact.md, "Free motions while pairs open", has the figures; run by
// benchmarks/least_norm_qp.sh, which compiles this file with Kiln's least_norm_shift.cpp.
//
// ROL is given the problem as ROL::Problem with a linear inequality constraint (A c - s = 0,
// s >= h) and solved by
//   - TypeG "Augmented Lagrangian" (finalize(lumpConstraints = true): general constraints),
//   - TypeG "Interior Point",
//   - TypeB "Trust Region" (Lin-More) with the polyhedral projection onto {A c >= h} done by
//     ROL ("Semismooth Newton"; finalize(lumpConstraints = false)),
// each with every tolerance at 1e-14 (ROL's default 1e-8 is far from the tests' 1e-10).
// For each problem and solver: |c - c_hand|_inf / |c_hand|_inf, the infeasibility
// max(0, h - A c), the objective against the hand-written one, the KKT residual (|M c + b -
// A_W^T mu|_inf with mu the least-squares multipliers of the rows active to 1e-9, and the
// smallest mu), the time per solve (best of a few) and ROL's exit status. A ROL solve runs in a
// child process killed after 10 s: some never end.
//
//   least_norm_qp [--interior-point] [repeat] [dump files...]
//
// A dump (benchmarks/least_norm_qp/*.qp): k m, then M (k x k, column-major), b, A (m x k,
// row-major), h, whitespace separated.
#include "physics/mechanics/least_norm_shift.hpp"

#include <ROL_Bounds.hpp>
#include <ROL_Problem.hpp>
#include <ROL_Solver.hpp>
#include <ROL_StdConstraint.hpp>
#include <ROL_StdObjective.hpp>
#include <ROL_StdVector.hpp>
#include <Teuchos_LAPACK.hpp>
#include <Teuchos_ParameterList.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

namespace
{
struct Qp
{
  std::string name;
  int k = 0, m = 0;
  std::vector<double> M, b, A, h;
};

/// c^T M c + 2 b^T c.
double objective(const Qp &qp, const std::vector<double> &c)
{
  double f = 0.0;
  for (int i = 0; i < qp.k; ++i)
  {
    f += 2.0 * qp.b[i] * c[i];
    for (int j = 0; j < qp.k; ++j)
      f += c[i] * qp.M[i + qp.k * j] * c[j];
  }
  return f;
}

class QuadraticObjective final : public ROL::StdObjective<double>
{
public:
  explicit QuadraticObjective(const Qp &qp) : qp_(qp) {}
  double value(const std::vector<double> &x, double &) override { return objective(qp_, x); }
  void gradient(std::vector<double> &g, const std::vector<double> &x, double &) override
  {
    for (int i = 0; i < qp_.k; ++i)
    {
      g[i] = 2.0 * qp_.b[i];
      for (int j = 0; j < qp_.k; ++j)
        g[i] += 2.0 * qp_.M[i + qp_.k * j] * x[j];
    }
  }
  void hessVec(std::vector<double> &hv, const std::vector<double> &v, const std::vector<double> &,
               double &) override
  {
    for (int i = 0; i < qp_.k; ++i)
    {
      hv[i] = 0.0;
      for (int j = 0; j < qp_.k; ++j)
        hv[i] += 2.0 * qp_.M[i + qp_.k * j] * v[j];
    }
  }

private:
  const Qp &qp_;
};

/// A c (m values): the linear constraint, its bounds h are ROL's.
class RowsConstraint final : public ROL::StdConstraint<double>
{
public:
  explicit RowsConstraint(const Qp &qp) : qp_(qp) {}
  void value(std::vector<double> &c, const std::vector<double> &x, double &) override
  {
    multiply(c, x);
  }
  void applyJacobian(std::vector<double> &jv, const std::vector<double> &v,
                     const std::vector<double> &, double &) override
  {
    multiply(jv, v);
  }
  void applyAdjointJacobian(std::vector<double> &ajv, const std::vector<double> &v,
                            const std::vector<double> &, double &) override
  {
    for (int j = 0; j < qp_.k; ++j)
    {
      ajv[j] = 0.0;
      for (int i = 0; i < qp_.m; ++i)
        ajv[j] += qp_.A[static_cast<std::size_t>(i) * qp_.k + j] * v[i];
    }
  }
  void applyAdjointHessian(std::vector<double> &ahuv, const std::vector<double> &,
                           const std::vector<double> &, const std::vector<double> &,
                           double &) override
  {
    std::fill(ahuv.begin(), ahuv.end(), 0.0);
  }

private:
  void multiply(std::vector<double> &y, const std::vector<double> &x) const
  {
    for (int i = 0; i < qp_.m; ++i)
    {
      y[i] = 0.0;
      for (int j = 0; j < qp_.k; ++j)
        y[i] += qp_.A[static_cast<std::size_t>(i) * qp_.k + j] * x[j];
    }
  }
  const Qp &qp_;
};

/// Stops ROL after a time (a solve that does not end is one of the failures measured).
class TimeLimit final : public ROL::StatusTest<double>
{
public:
  explicit TimeLimit(const double seconds)
      : end_(std::chrono::steady_clock::now() +
             std::chrono::milliseconds(static_cast<long>(1000 * seconds)))
  {
  }
  bool check(ROL::AlgorithmState<double> &state) override
  {
    if (std::chrono::steady_clock::now() < end_)
      return true;
    state.statusFlag = ROL::EXITSTATUS_USERDEFINED;
    return false;
  }

private:
  std::chrono::steady_clock::time_point end_;
};

struct RolSolver
{
  std::string name, type;
  bool lump;
  std::string projection;
};

/// ROL's answer (and its exit status) for one problem.
std::vector<double> solve_unit_scale(const Qp &qp, const RolSolver &solver, std::string &status)
{
  auto x = ROL::makePtr<ROL::StdVector<double>>(qp.k, 0.0);
  auto g = ROL::makePtr<ROL::StdVector<double>>(qp.k, 0.0);
  auto problem = ROL::makePtr<ROL::Problem<double>>(ROL::makePtr<QuadraticObjective>(qp), x, g);
  if (qp.m > 0)
  {
    auto lower = ROL::makePtr<ROL::StdVector<double>>(ROL::makePtr<std::vector<double>>(qp.h));
    const ROL::Ptr<ROL::BoundConstraint<double>> bounds =
        ROL::makePtr<ROL::Bounds<double>>(*lower, true);
    const ROL::Ptr<ROL::Vector<double>> multiplier =
        ROL::makePtr<ROL::StdVector<double>>(qp.m, 0.0);
    const ROL::Ptr<ROL::Constraint<double>> rows = ROL::makePtr<RowsConstraint>(qp);
    problem->addLinearConstraint("A c >= h", rows, multiplier, bounds);
  }
  ROL::ParameterList list;
  list.sublist("General").set("Output Level", 0);
  list.sublist("General").sublist("Polyhedral Projection").set("Type", solver.projection);
  list.sublist("General").sublist("Polyhedral Projection").set("Absolute Tolerance", 1e-14);
  list.sublist("General").sublist("Polyhedral Projection").set("Relative Tolerance", 1e-14);
  list.sublist("General").sublist("Polyhedral Projection").set("Iteration Limit", 1000);
  list.sublist("Step").set("Type", solver.type);
  list.sublist("Status Test").set("Gradient Tolerance", 1e-14);
  list.sublist("Status Test").set("Constraint Tolerance", 1e-14);
  list.sublist("Status Test").set("Step Tolerance", 1e-16);
  list.sublist("Status Test").set("Iteration Limit", 200);
  problem->setProjectionAlgorithm(list);
  problem->finalize(solver.lump, false);
  ROL::Solver<double> rol(problem, list);
  std::ostringstream quiet;
  rol.solve(quiet, ROL::makePtr<TimeLimit>(2.0));
  const auto state = rol.getAlgorithmState();
  status = (state->statusFlag == ROL::EXITSTATUS_USERDEFINED
                ? std::string("stopped after 2 s")
                : ROL::EExitStatusToString(state->statusFlag)) +
           ", " + std::to_string(state->iter) + " it";
  return *x->getVector();
}

/// ROL's tolerances are absolute: it is given b and h over s = max(|b|, |h|) (the contact
/// decks' are about 1e-9), and its answer is multiplied by s.
std::vector<double> solve_with_rol(const Qp &qp, const RolSolver &solver, std::string &status)
{
  double s = 0.0;
  for (const auto *v : {&qp.b, &qp.h})
    for (const double x : *v)
      s = std::max(s, std::abs(x));
  s = s > 0.0 ? s : 1.0;
  Qp scaled = qp;
  for (auto *v : {&scaled.b, &scaled.h})
    for (double &x : *v)
      x /= s;
  std::vector<double> c = solve_unit_scale(scaled, solver, status);
  for (double &x : c)
    x *= s;
  return c;
}

/// solve_with_rol in a child process, killed after `seconds`: some of ROL's solves never end
/// (the loop is inside one iteration, where no status test is asked). False if killed.
bool solve_with_rol_in_time(const Qp &qp, const RolSolver &solver, const double seconds,
                            std::vector<double> &c, std::string &status)
{
  int fds[2];
  if (pipe(fds) != 0)
    throw std::runtime_error("pipe failed");
  const pid_t child = fork();
  if (child == 0)
  {
    close(fds[0]);
    std::string s;
    std::vector<double> x;
    try
    {
      x = solve_with_rol(qp, solver, s);
    }
    catch (const std::exception &e)
    {
      s = std::string("threw: ") + e.what();
      x.assign(qp.k, std::numeric_limits<double>::quiet_NaN());
    }
    const std::size_t n = s.size();
    [[maybe_unused]] ssize_t w = write(fds[1], &n, sizeof n);
    w = write(fds[1], s.data(), n);
    w = write(fds[1], x.data(), sizeof(double) * x.size());
    close(fds[1]);
    _exit(0);
  }
  close(fds[1]);
  pollfd p{fds[0], POLLIN, 0};
  const bool ended = poll(&p, 1, static_cast<int>(1000 * seconds)) > 0;
  if (!ended)
  {
    kill(child, SIGKILL);
    status = "did not end in " + std::to_string(static_cast<int>(seconds)) + " s (killed)";
    c.assign(qp.k, std::numeric_limits<double>::quiet_NaN());
  }
  else
  {
    std::size_t n = 0;
    bool ok = read(fds[0], &n, sizeof n) == static_cast<ssize_t>(sizeof n);
    status.resize(n);
    ok = ok && read(fds[0], status.data(), n) == static_cast<ssize_t>(n);
    c.resize(qp.k);
    std::size_t got = 0;
    while (ok && got < sizeof(double) * c.size())
    {
      const ssize_t r =
          read(fds[0], reinterpret_cast<char *>(c.data()) + got, sizeof(double) * c.size() - got);
      ok = r > 0;
      got += ok ? static_cast<std::size_t>(r) : 0;
    }
  }
  close(fds[0]);
  waitpid(child, nullptr, 0);
  return ended;
}

double row_times(const Qp &qp, const int i, const std::vector<double> &c)
{
  double s = 0.0;
  for (int j = 0; j < qp.k; ++j)
    s += qp.A[static_cast<std::size_t>(i) * qp.k + j] * c[j];
  return s;
}

struct Kkt
{
  double infeasible = 0.0, stationarity = 0.0, smallest_mu = 0.0;
};

/// The KKT residual of c: the rows active to 1e-9 (relative), their least-squares multipliers.
Kkt kkt(const Qp &qp, const std::vector<double> &c)
{
  Kkt result;
  std::vector<int> active;
  double scale = 0.0;
  for (const double v : c)
    scale = std::max(scale, std::abs(v));
  for (int i = 0; i < qp.m; ++i)
  {
    const double s = row_times(qp, i, c) - qp.h[i];
    result.infeasible = std::max(result.infeasible, -s);
    if (s <= 1e-9 * std::max(1.0, scale))
      active.push_back(i);
  }
  std::vector<double> grad(qp.k);
  for (int i = 0; i < qp.k; ++i)
  {
    grad[i] = qp.b[i];
    for (int j = 0; j < qp.k; ++j)
      grad[i] += qp.M[i + qp.k * j] * c[j];
  }
  const int w = static_cast<int>(active.size());
  if (w > 0)
  {
    // min |A_W^T mu - grad| (k equations, w unknowns), by LAPACK's least squares.
    const int rows = std::max(qp.k, w);
    std::vector<double> AT(static_cast<std::size_t>(qp.k) * w), rhs(rows, 0.0);
    for (int r = 0; r < w; ++r)
      for (int j = 0; j < qp.k; ++j)
        AT[j + static_cast<std::size_t>(qp.k) * r] =
            qp.A[static_cast<std::size_t>(active[r]) * qp.k + j];
    std::copy(grad.begin(), grad.end(), rhs.begin());
    std::vector<double> sv(std::min(qp.k, w)), work(1);
    int rank = 0, info = 0;
    Teuchos::LAPACK<int, double> lapack;
    lapack.GELSS(qp.k, w, 1, AT.data(), qp.k, rhs.data(), rows, sv.data(), 1e-12, &rank,
                 work.data(), -1, nullptr, &info);
    work.resize(static_cast<std::size_t>(work[0]));
    lapack.GELSS(qp.k, w, 1, AT.data(), qp.k, rhs.data(), rows, sv.data(), 1e-12, &rank,
                 work.data(), static_cast<int>(work.size()), nullptr, &info);
    result.smallest_mu = *std::min_element(rhs.begin(), rhs.begin() + w);
    for (int i = 0; i < qp.k; ++i)
      for (int r2 = 0; r2 < w; ++r2)
        grad[i] -= qp.A[static_cast<std::size_t>(active[r2]) * qp.k + i] * rhs[r2];
  }
  for (const double v : grad)
    result.stationarity = std::max(result.stationarity, std::abs(v));
  return result;
}

/// Microseconds per call of f (best of 3 runs of `repeat` calls).
double microseconds(const int repeat, const std::function<void()> &f)
{
  double best = 1e300;
  for (int run = 0; run < 3; ++run)
  {
    const auto start = std::chrono::steady_clock::now();
    for (int r = 0; r < repeat; ++r)
      f();
    const std::chrono::duration<double, std::micro> t = std::chrono::steady_clock::now() - start;
    best = std::min(best, t.count() / repeat);
  }
  return best;
}

/// M = L L^T + I/2 scaled to a unit diagonal (as pairs_held_shut scales it), b, A uniform in
/// [-1, 1], h in [-0.3, 0] (c = 0 feasible), as unit_least_norm_shift's random problems.
Qp random_qp(const int k, const int m, const unsigned seed)
{
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Qp qp;
  qp.name =
      "random k " + std::to_string(k) + " m " + std::to_string(m) + " #" + std::to_string(seed);
  qp.k = k;
  qp.m = m;
  std::vector<double> L(static_cast<std::size_t>(k) * k);
  for (double &v : L)
    v = uniform(random) * 0.5;
  qp.M.assign(static_cast<std::size_t>(k) * k, 0.0);
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j)
    {
      for (int l = 0; l < k; ++l)
        qp.M[i + k * j] += L[i + k * l] * L[j + k * l];
      qp.M[i + k * j] += i == j ? 0.5 : 0.0;
    }
  std::vector<double> d(k);
  for (int i = 0; i < k; ++i)
    d[i] = 1.0 / std::sqrt(qp.M[i + k * i]);
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j)
      qp.M[i + k * j] *= d[i] * d[j];
  qp.b.resize(k);
  for (double &v : qp.b)
    v = uniform(random) * 2.0;
  qp.A.resize(static_cast<std::size_t>(m) * k);
  for (double &v : qp.A)
    v = uniform(random);
  qp.h.resize(m);
  for (double &v : qp.h)
    v = -0.3 * std::abs(uniform(random));
  return qp;
}

std::vector<Qp> unit_test_problems()
{
  std::vector<Qp> problems;
  problems.push_back({"unit: unconstrained", 2, 0, {1, 0, 0, 1}, {-1, 2}, {}, {}});
  problems.push_back({"unit: one binds", 2, 1, {1, 0, 0, 1}, {-1, -1}, {-1, -1}, {-1}});
  problems.push_back({"unit: dependent, active at 0 (degenerate)",
                      2,
                      4,
                      {1, 0, 0, 1},
                      {1, -1},
                      {1, 0, 1, 0, 2, 0, 1, 1},
                      {0, 0, 0, 0}});
  return problems;
}

Qp read_dump(const std::string &file)
{
  std::ifstream in(file);
  Qp qp;
  qp.name = file.substr(file.find_last_of('/') + 1);
  in >> qp.k >> qp.m;
  qp.M.resize(static_cast<std::size_t>(qp.k) * qp.k);
  qp.b.resize(qp.k);
  qp.A.resize(static_cast<std::size_t>(qp.m) * qp.k);
  qp.h.resize(qp.m);
  for (auto *v : {&qp.M, &qp.b, &qp.A, &qp.h})
    for (double &x : *v)
      in >> x;
  if (!in)
    throw std::runtime_error("cannot read the problem in " + file);
  return qp;
}

/// max |a - b| / max |b| (or / 1 where b = 0).
double largest_difference(const std::vector<double> &a, const std::vector<double> &b)
{
  double d = 0.0, size = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
  {
    d = std::max(d, std::abs(a[i] - b[i]));
    size = std::max(size, std::abs(b[i]));
  }
  return d / (size > 0.0 ? size : 1.0);
}

void compare(const Qp &qp, const int repeat, const std::vector<RolSolver> &solvers)
{
  std::printf("\n%s (k %d, m %d)\n", qp.name.c_str(), qp.k, qp.m);
  std::printf("  %-26s %9s %9s %10s %9s %9s %11s  %s\n", "solver", "|dc|", "infeas", "f - f_hand",
              "|KKT|", "min mu", "us/solve", "status");
  std::vector<double> hand;
  std::string hand_status = "ok";
  try
  {
    hand = kiln::least_norm_shift(qp.k, qp.M, qp.b, qp.m, qp.A, qp.h);
  }
  catch (const std::exception &e)
  {
    hand_status = e.what();
    hand.assign(qp.k, std::numeric_limits<double>::quiet_NaN());
  }
  const double f_hand = objective(qp, hand);
  const auto row = [&](const std::string &name, const std::vector<double> &c, const double t,
                       const std::string &status)
  {
    const Kkt r = kkt(qp, c);
    std::printf("  %-26s %9.1e %9.1e %10.1e %9.1e %9.1e %11.1f  %s\n", name.c_str(),
                largest_difference(c, hand), r.infeasible, objective(qp, c) - f_hand,
                r.stationarity, r.smallest_mu, t, status.c_str());
  };
  const double t_hand =
      hand_status == "ok" ? microseconds(repeat * 100,
                                         [&]
                                         {
                                           const auto c = kiln::least_norm_shift(qp.k, qp.M, qp.b,
                                                                                 qp.m, qp.A, qp.h);
                                           (void)c;
                                         })
                          : 0.0;
  row("hand-written active set", hand, t_hand, hand_status);
  for (const RolSolver &solver : solvers)
  {
    std::string status;
    std::vector<double> c;
    const auto start = std::chrono::steady_clock::now();
    if (!solve_with_rol_in_time(qp, solver, 10.0, c, status))
    {
      row(solver.name, c, 0.0, status);
      continue;
    }
    const std::chrono::duration<double, std::micro> first =
        std::chrono::steady_clock::now() - start;
    // A slow solve (over 0.1 s) is timed once (with the fork).
    const double t = first.count() > 1e5
                         ? first.count()
                         : microseconds(repeat,
                                        [&]
                                        {
                                          std::string s;
                                          const auto x = solve_with_rol(qp, solver, s);
                                          (void)x;
                                        });
    row(solver.name, c, t, status);
  }
}
} // namespace

int main(int argc, char **argv)
{
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  std::vector<std::string> args(argv + 1, argv + argc);
  // ROL's interior point only with --interior-point: seconds per solve, and inexact.
  const auto ip = std::find(args.begin(), args.end(), "--interior-point");
  const bool interior_point = ip != args.end();
  if (interior_point)
    args.erase(ip);
  const int repeat = !args.empty() ? std::max(1, std::atoi(args[0].c_str())) : 3;
  std::vector<RolSolver> solvers{
      {"ROL G Augmented Lagrangian", "Augmented Lagrangian", true, "Semismooth Newton"},
      {"ROL B Trust Region (proj.)", "Trust Region", false, "Semismooth Newton"},
  };
  if (interior_point)
    solvers.push_back({"ROL G Interior Point", "Interior Point", true, "Semismooth Newton"});
  std::vector<Qp> problems = unit_test_problems();
  for (std::size_t a = 1; a < args.size(); ++a)
    problems.push_back(read_dump(args[a]));
  for (const auto &[k, m] : std::vector<std::pair<int, int>>{{3, 7}, {6, 40}, {20, 60}, {50, 150}})
    for (unsigned seed = 1; seed <= 2; ++seed)
      problems.push_back(random_qp(k, m, seed));
  // Infeasible (h > 0 with no feasible c: c0 >= 1 and -c0 >= 0), outside least_norm_shift's
  // contract (h <= 0): what each does.
  problems.push_back({"infeasible (outside the contract)", 1, 2, {1}, {0}, {1, -1}, {1, 0}});
  for (const Qp &qp : problems)
    compare(qp, repeat, solvers);
  return 0;
}
