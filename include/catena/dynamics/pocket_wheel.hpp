// The pocket wheel of a round-link chain in the chain-loop dynamics (docs/models/dynamics.md,
// "Pocket wheel"): a Sprocket whose seats are pockets at the vertices of the bi-regular joint
// polygon of seed 003 (catena::pocketwheel). The contact itself is pocket_contact in chain.hpp.
#pragma once

#include <string>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/dynamics/chain.hpp"

namespace catena::dynamics {

/// A pocket wheel for round-link chain of pitch t and wire diameter d with z pockets (teeth):
/// pitch radius R and central angle δ1 of 003 eqs. (6)–(7) (catena::pocketwheel::wheel_geometry),
/// the joints' pockets of clearance c. Role and inertia are left to the caller (a wheel at rest
/// and not a driver). The chain for it has pitch t and alternation d (Model::alternation).
/// Throws InputError for an invalid chain or wheel (pocketwheel::validate).
Sprocket pocket_wheel(double pitch, double wire, int teeth, double centre_x, double centre_y,
                      double clearance, double contact_stiffness, double contact_damping);

/// The nearest pocket vertex to the polar angle `polar` of a point about the centre, for a wheel
/// at angle ψ: its index k (even k: ψ + (k/2)·2π/z; odd: ψ + ((k − 1)/2)·2π/z + δ1) and angle.
/// O(1): one floor and two comparisons.
struct PocketVertex {
  int index = 0;
  double angle = 0.0;  ///< [rad]
};
PocketVertex nearest_pocket(const Sprocket& w, double polar, double angle);

/// [N/m] The mouth's ramp's largest softening κ (docs/models/dynamics.md, "Pocket wheel: the
/// ramp's fold"): the largest −λ_min(∇²E) of the contact's elastic energy over the ramp's region,
/// the largest eigenvalue of its exact elastic ∂F/∂q sampled on a grid (64 radii × 256 polar
/// angles about a vertex, two zooms about the largest). A joint's step matrix
/// M/(hθ) + hθ ∇²E (the θ point's force) stays definite while κ < M/(θh)², i.e.
/// h < √(M/κ)/θ. 0 without a ramp.
double pocket_ramp_softening(const Sprocket& w);

/// The pocket fields' problems ("<prefix>pocket_angle", "pocket_clearance", "contact_stiffness",
/// "contact_smoothing"), appended to `out`; called by validate(Model) for a pocket wheel.
void pocket_issues(std::vector<Issue>& out, const Sprocket& w, const std::string& prefix);

}  // namespace catena::dynamics
