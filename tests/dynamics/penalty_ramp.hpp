// Test helper: the penalty's C¹ ramp over the first ε (docs/models/dynamics.md, "Contact law"),
// written out here from its formula and not through the library, as the independent reference
// the tests of the seats', the rails' and the pocket's contacts check the library against.
// Header-only: tests/ includes it as "penalty_ramp.hpp".
#pragma once

namespace catena::dynamics::testing {

// The ramp's force at the gap g: k g²/(2ε) within the first ε, k (g − ε/2) past it, 0 for g ≤ 0.
// With a damping c_c for k, the ramped damper's integral C(g) = ∫₀^g c_c min(1, s/ε) ds.
inline double penalty_ramp_force(double k, double eps, double g) {
  if (!(g > 0.0)) return 0.0;
  return g < eps ? 0.5 * k * g * g / eps : k * (g - 0.5 * eps);
}

// The ramp's energy at the gap g, the integral of its force: k g³/(6ε) within the first ε,
// k (g²/2 − ε g/2 + ε²/6) past it, 0 for g ≤ 0.
inline double penalty_ramp_energy(double k, double eps, double g) {
  if (!(g > 0.0)) return 0.0;
  return g < eps ? k * g * g * g / (6.0 * eps)
                 : k * (0.5 * g * g - 0.5 * eps * g + eps * eps / 6.0);
}

}  // namespace catena::dynamics::testing
