// Roller warp (seed 000 §1.4), force method: Macaulay's closed-form deflection of the free roller,
// unknowns (a, b, R_i), damped Newton with load continuation. The independent check of solve()
// and its polishing step.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include "catena/warp/warp.hpp"
#include "internal.hpp"

namespace catena::warp {
namespace detail {

// w(z) of the free–free beam by Macaulay's method (Timoshenko & Gere, Mechanics of Materials,
// §9.5): EI w'' = Σ_j P_j <z − z_j>, loads P = +F at L1 and −R_i at z_i, so
// w(z) = a + b z + Σ_j P_j <z − z_j>³ / (6 EI).
double deflection(const Warp& w, const Load& load, const State& s, double z) {
  const double ei = w.modulus * second_moment(w.roller_diameter);
  double bend = load.force * cube_plus(z - load.height);
  for (int j = 0; j < 4; ++j)
    bend -= s.r[static_cast<std::size_t>(j)] *
            cube_plus(z - w.supports[static_cast<std::size_t>(j)].height);
  return s.a + s.b * z + bend / (6.0 * ei);
}

namespace {

// Scaled residual: joint laws (÷F) and equilibrium (÷F, ÷F·span).
std::array<double, 6> residual(const Warp& w, const Load& load, const State& s) {
  std::array<double, 6> res{};
  const double f = load.force;
  const double span = w.supports[3].height - w.supports[0].height;
  double sum = 0, mom = 0;
  for (std::size_t i = 0; i < 4; ++i) {
    const Support& sp = w.supports[i];
    const double g = deflection(w, load, s, sp.height) - sp.clearance;
    res[i] = (s.r[i] - law(sp.stiffness, w.exponent, g)) / f;
    sum += s.r[i];
    mom += s.r[i] * sp.height;
  }
  res[4] = (sum - f) / f;                         // ΣF = 0
  res[5] = (mom - f * load.height) / (f * span);  // ΣM = 0 about z = 0
  return res;
}

double norm_inf(const std::array<double, 6>& r) {
  double m = 0;
  for (double v : r) m = std::max(m, std::abs(v));
  return m;
}

}  // namespace

WarpResult flexibility_impl(const Warp& w, const Load& load, const SolveOptions& options,
                            const State* initial) {
  const double f = load.force;
  const double n = w.exponent;
  const double ei = w.modulus * second_moment(w.roller_diameter);
  WarpResult out;
  // Damped Newton on the scaled residual, from state `s`, for the load `ld`; returns the final
  // max |scaled residual| and counts iterations into `it`.
  auto newton = [&](State& s, const Load& ld, int& it, int max_it) {
    const double fl = ld.force;
    auto res = residual(w, ld, s);
    double rn = norm_inf(res);
    for (int k0 = 0; k0 < max_it && rn > options.tolerance; ++k0, ++it) {
      // Jacobian of the scaled residual in the unknowns (a, b, R_0..R_3).
      std::vector<double> jac(36, 0.0);
      std::vector<double> rhs(6);
      const double span = w.supports[3].height - w.supports[0].height;
      for (std::size_t i = 0; i < 4; ++i) {
        const Support& sp = w.supports[i];
        const double g = deflection(w, ld, s, sp.height) - sp.clearance;
        const double kt =
            std::max(law_slope(sp.stiffness, n, g), kJacobianFloor * secant(sp.stiffness, n, fl));
        jac[i * 6 + 0] = -kt / fl;
        jac[i * 6 + 1] = -kt * sp.height / fl;
        for (std::size_t j = 0; j < 4; ++j) {
          const double dw = -cube_plus(sp.height - w.supports[j].height) / (6.0 * ei);
          jac[i * 6 + 2 + j] = ((i == j ? 1.0 : 0.0) - kt * dw) / fl;
        }
      }
      for (std::size_t j = 0; j < 4; ++j) {
        jac[4 * 6 + 2 + j] = 1.0 / fl;
        jac[5 * 6 + 2 + j] = w.supports[j].height / (fl * span);
      }
      for (std::size_t i = 0; i < 6; ++i) rhs[i] = -res[i];
      if (!solve_dense(jac, rhs, 6)) break;  // reported as not converged
      // Backtracking on the max-norm of the residual.
      double step = 1.0;
      State trial;
      std::array<double, 6> tres{};
      double tn = rn;
      for (int k = 0; k < 40; ++k, step *= 0.5) {
        trial.a = s.a + step * rhs[0];
        trial.b = s.b + step * rhs[1];
        for (std::size_t j = 0; j < 4; ++j) trial.r[j] = s.r[j] + step * rhs[2 + j];
        tres = residual(w, ld, trial);
        tn = norm_inf(tres);
        if (tn < rn * (1 - 1e-4 * step)) break;
      }
      s = trial;
      res = tres;
      rn = tn;
    }
    return rn;
  };
  // Start: every joint closed and sharing F equally, no tilt.
  double cmax = 0;
  for (const Support& sp : w.supports) cmax = std::max(cmax, sp.clearance);
  double kmin = w.supports[0].stiffness;
  for (const Support& sp : w.supports) kmin = std::min(kmin, sp.stiffness);
  auto start = [&](double force) {
    State st;
    st.a = cmax + std::pow(0.25 * force / kmin, 1.0 / n);
    st.r.fill(0.25 * force);
    return st;
  };
  int it = 0;
  State s = initial ? *initial : start(f);
  double rn = newton(s, load, it, options.max_iterations);
  // Fallback when the active set chatters (a flexible roller, joints far apart): load
  // continuation, each increment started from the previous converged state.
  for (int steps : {8, 64}) {
    if (rn <= options.tolerance) break;
    s = start(f / steps);
    for (int k = 1; k <= steps; ++k) {
      const Load part{f * k / steps, load.height};
      rn = newton(s, part, it, options.max_iterations);
      if (rn > options.tolerance) break;
      if (k < steps) {  // scale the forces to the next increment
        for (double& r : s.r) r *= static_cast<double>(k + 1) / k;
      }
    }
  }
  out.summary.converged = rn <= options.tolerance;
  out.summary.termination = out.summary.converged ? "max |scaled residual| ≤ tolerance"
                                                  : "iteration limit (after load continuation)";
  out.summary.iterations = it;
  out.summary.residual = rn * f;
  out.summary.tolerance = options.tolerance * f;
  return build_result(w, load, s, out.summary, options);
}

}  // namespace detail

using detail::flexibility_impl;

WarpResult solve_flexibility(const Warp& w, const Load& load, const SolveOptions& options) {
  throw_if_any(validate(w, load));
  return flexibility_impl(w, load, options, nullptr);
}

}  // namespace catena::warp
