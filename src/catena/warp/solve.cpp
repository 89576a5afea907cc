// Roller warp (seed 000 §1.4): the primary solver — the displacement method, polished by the force
// method started from its state.
#include <cstddef>

#include "catena/warp/warp.hpp"
#include "internal.hpp"

namespace catena::warp {

using detail::build_result;
using detail::fe_solve;
using detail::FeSolution;
using detail::flexibility_impl;
using detail::law;
using detail::State;

WarpResult solve(const Warp& w, const Load& load, const SolveOptions& options) {
  throw_if_any(validate(w, load));
  // One element per segment between joints and load point: exact for the Euler–Bernoulli
  // beam under point loads (cubic between them).
  const FeSolution sol = fe_solve(w, load, 1, options.tolerance, options.max_iterations);
  State s;
  for (std::size_t i = 0; i < 4; ++i)
    s.r[i] = law(w.supports[i].stiffness, w.exponent,
                 sol.u[static_cast<std::size_t>(2 * sol.joint_node[i])] - w.supports[i].clearance);
  // Below every load w = a + b z: b is the slope, a the intercept at the lowest node.
  s.b = sol.u[1];
  s.a = sol.u[0] - s.b * sol.z[0];
  // Polish: the force method started from this state (active set known) restores equilibrium
  // to round-off of F rather than of K·u; kept only if it converges.
  SolveOptions polish = options;
  polish.max_iterations = 20;
  WarpResult polished = flexibility_impl(w, load, polish, &s);
  if (polished.summary.converged) {
    polished.summary.iterations += sol.iterations;
    polished.summary.termination =
        "energy-descent Newton (displacement method), polished by the force method: " +
        polished.summary.termination;
    return polished;
  }
  SolverSummary summary;
  summary.iterations = sol.iterations;
  summary.residual = sol.residual;
  summary.tolerance = sol.tolerance;
  summary.converged = sol.converged;
  summary.termination =
      summary.converged
          ? "max |nodal force residual| ≤ tolerance·F + round-off floor (energy-descent Newton)"
          : "iteration limit";
  return build_result(w, load, s, summary, options);
}

}  // namespace catena::warp
