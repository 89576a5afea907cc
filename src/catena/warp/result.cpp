// Roller warp (seed 000 §1.4): what a solved state gives — joint forces, roller moments, contact
// and bending stresses, tilt, equilibrium residuals and diagnostics.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>

#include "catena/core/hertz.hpp"
#include "catena/warp/warp.hpp"
#include "internal.hpp"

namespace catena::warp {

double contact_stress(const Warp& w, int joint, double force) {
  const Support& s = w.supports[static_cast<std::size_t>(joint)];
  if (w.kind == HingeKind::kSliding)  // specific pressure on the projected area, cf. 000 eq. (23)
    return force / (w.roller_diameter * s.width);
  const Elastic e{w.modulus, w.poisson};
  // Johnson (1985) §4.2, R1 convex in R2 concave (fig. 12c), load per length R/B.
  return line_contact(force / s.width, conformal_radius(w.r1, w.r2), contact_modulus(e, e))
      .peak_pressure;
}

namespace detail {
namespace {

// Bending moment at z from the forces below it: M(z) = Σ_{z_j < z} P_j (z − z_j).
double moment_at(const Warp& w, const Load& load, const std::array<double, 4>& r, double z) {
  double m = load.height < z ? load.force * (z - load.height) : 0.0;
  for (int j = 0; j < 4; ++j) {
    const double zj = w.supports[static_cast<std::size_t>(j)].height;
    if (zj < z) m -= r[static_cast<std::size_t>(j)] * (z - zj);
  }
  return m;
}

}  // namespace

// Joint forces, deflections, moments, stresses and diagnostics of a solved state.
WarpResult build_result(const Warp& w, const Load& load, const State& s,
                        const SolverSummary& summary, const SolveOptions& options) {
  const double f = load.force;
  const double n = w.exponent;
  WarpResult out;
  out.summary = summary;
  // Results.
  out.offset = s.a;
  out.rotation = s.b;
  double sum = 0, mom = 0;
  for (std::size_t i = 0; i < 4; ++i) {
    const Support& sp = w.supports[i];
    out.deflection[i] = deflection(w, load, s, sp.height);
    out.deformation[i] = std::max(0.0, out.deflection[i] - sp.clearance);
    // The joint law evaluated at the converged deflection (never a tension); the residuals
    // below then measure how well these forces balance F.
    out.force[i] = law(sp.stiffness, n, out.deflection[i] - sp.clearance);
    sum += out.force[i];
    mom += out.force[i] * sp.height;
  }
  for (std::size_t i = 0; i < 4; ++i) {
    out.moment[i] = moment_at(w, load, out.force, w.supports[i].height);
    out.contact_stress[i] = contact_stress(w, static_cast<int>(i), std::max(0.0, out.force[i]));
  }
  // |M| is piecewise linear: its maximum is at a load point.
  out.moment_max = std::abs(moment_at(w, load, out.force, load.height));
  for (double m : out.moment) out.moment_max = std::max(out.moment_max, std::abs(m));
  out.bending_stress = out.moment_max * 0.5 * w.roller_diameter / second_moment(w.roller_diameter);
  out.tilt = std::atan((out.deflection[3] - out.deflection[0]) /
                       (w.supports[3].height - w.supports[0].height));
  const double lower = out.force[kF11] + out.force[kF21];
  out.upper_share = lower > 0 ? (out.force[kF12] + out.force[kF22]) / lower - 1.0 : INFINITY;
  out.force_residual = std::abs(f - sum);
  out.moment_residual = std::abs(f * load.height - mom);
  // Converged means the residual tests passed: the solver's, and the equilibrium of the forces
  // reported (a solver residual measured on overflowing or cancelling terms can pass alone).
  SolverSummary& sum_up = out.summary;
  const double span = w.supports[3].height - w.supports[0].height;
  sum_up.equilibrium_residual = std::max(out.force_residual, out.moment_residual / span);
  sum_up.equilibrium_tolerance = kEquilibriumTolerance * f;
  const bool solver_passed = std::isfinite(sum_up.residual) && sum_up.converged;
  const bool balanced = std::isfinite(sum_up.equilibrium_residual) &&
                        sum_up.equilibrium_residual <= sum_up.equilibrium_tolerance;
  sum_up.converged = solver_passed && balanced;
  if (solver_passed && !balanced) sum_up.termination += "; but the joint forces do not balance F";
  // Diagnostics.
  (void)options;
  if (!sum_up.converged) {
    const bool solver = !solver_passed;
    out.diagnostics.push_back(
        {Diagnostic::Severity::kError, "warp.not_converged",
         "the joint-force solver did not converge (" + sum_up.termination + "): " +
             (solver
                  ? "residual " + check::format_si(sum_up.residual, "N") + " > tolerance " +
                        check::format_si(sum_up.tolerance, "N")
                  : "equilibrium residual " + check::format_si(sum_up.equilibrium_residual, "N") +
                        " > tolerance " + check::format_si(sum_up.equilibrium_tolerance, "N")) +
             "; results are not valid",
         solver ? sum_up.residual : sum_up.equilibrium_residual,
         solver ? sum_up.tolerance : sum_up.equilibrium_tolerance, "N"});
  }
  for (std::size_t i = 0; i < 4; ++i) {
    if (out.force[i] <= 0.0)
      out.diagnostics.push_back(
          {Diagnostic::Severity::kInfo, std::string("warp.joint_open.") + kJointName[i],
           std::string("joint ") + kJointName[i] +
               " carries no load: its clearance is not closed (approach ≤ clearance)",
           out.deflection[i], w.supports[i].clearance, "m"});
    if (w.kind == HingeKind::kRolling && out.force[i] > 0) {
      const Elastic e{w.modulus, w.poisson};
      const double b = line_contact(out.force[i] / w.supports[i].width,
                                    conformal_radius(w.r1, w.r2), contact_modulus(e, e))
                           .half_width;
      constexpr double kHertzWidthLimit = 0.1;  // [-] b/R1 beyond which conformal Hertz is rough
      if (b > kHertzWidthLimit * w.r1)
        out.diagnostics.push_back(
            {Diagnostic::Severity::kWarning, std::string("warp.hertz_conformal.") + kJointName[i],
             std::string("joint ") + kJointName[i] +
                 ": Hertz half-width exceeds 0.1·R1, the conformal contact is outside Hertz' "
                 "small-contact assumption (Persson's conformal theory would apply)",
             b, kHertzWidthLimit * w.r1, "m"});
    }
  }
  return out;
}

}  // namespace detail
}  // namespace catena::warp
