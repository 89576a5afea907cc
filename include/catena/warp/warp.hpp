// Roller warp in the vertical plane (seed 000 §1.4, figs. 12–18).
//
// The thesis describes the model in words and figures only: the roller (pin) is carried by the
// lower/upper inner and outer plates through cylindrical contacts with clearance, the sprocket
// tooth loads it with F at height L1, and it tilts. Our reconstruction (docs/models/warp.md):
// the roller is an Euler–Bernoulli beam (free ends) on four unilateral supports at the plates'
// mid-planes; each support closes a radial clearance c_i and then resists with the contact law
//   R_i = k_i · max(0, w(z_i) − c_i)^n                                   (power-law joint)
// n = 1 is a linear joint stiffness (Johnson's line contact is linear up to a logarithm);
// n = 1/m = 2 is Levina & Reshetov's joint law y = C·p^m with m = 0.5 (Contact stiffness of
// machines, 1971), written for the force. Heights z share one datum chosen by the caller (the
// CLI uses the lower outer plate's mid-plane, z = 0).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "catena/core/error.hpp"

namespace catena::warp {

/// Index of the four joints, in the thesis' notation F_{plate, level}: first index 1 = inner
/// plate, 2 = outer plate; second index 1 = lower, 2 = upper (fig. 13 caption).
enum Joint : int { kF21 = 0, kF11 = 1, kF12 = 2, kF22 = 3 };  // bottom → top order

struct Support {
  double height = 0.0;     ///< [m] z of the plate mid-plane along the roller
  double clearance = 0.0;  ///< [m] radial clearance c_i closed before the joint carries load
  double stiffness = 0.0;  ///< [N/m^n] k_i of R = k·g^n
  double width = 0.0;      ///< [m] plate thickness B_i (contact length, for the stresses)
};

enum class HingeKind { kSliding, kRolling };

struct Warp {
  std::array<Support, 4> supports{};  ///< in Joint order: lower outer, lower inner, upper inner,
                                      ///< upper outer (heights strictly increasing)
  double exponent = 1.0;              ///< [-] n of the joint law, 1 ≤ n ≤ 3
  double roller_diameter = 0.0;       ///< [m] d of the roller (bending section, sliding pressure)
  double modulus = 210e9;             ///< [Pa] E of roller and plates
  double poisson = 0.3;               ///< [-] ν
  HingeKind kind = HingeKind::kSliding;
  double r1 = 0.0;  ///< [m] plate convex working radius R1 (rolling hinge)
  double r2 = 0.0;  ///< [m] roller concave working radius R2 > R1 (rolling hinge)
};

struct Load {
  double force = 0.0;   ///< [N] tooth load F
  double height = 0.0;  ///< [m] L1, the height at which F acts (same datum as the supports)
};

/// Every problem with the inputs (field, value, expected range).
std::vector<Issue> validate(const Warp& w, const Load& load);

/// `converged` means both residual tests passed: the solver's (`residual` ≤ `tolerance`) and
/// the equilibrium of the reported joint forces (`equilibrium_residual` ≤
/// `equilibrium_tolerance`), all finite.
struct SolverSummary {
  bool converged = false;
  int iterations = 0;
  double residual = 0.0;   ///< [N] max |residual| of the support laws and force equilibrium
  double tolerance = 0.0;  ///< [N] the solver's bound on `residual`
  /// [N] max(|F − ΣR|, |F·L1 − ΣR z|/(z4 − z1)) of the reported joint forces
  double equilibrium_residual = 0.0;
  double equilibrium_tolerance = 0.0;  ///< [N] kEquilibriumTolerance·F
  std::string termination;
};

/// [-] relative to F: the reported joint forces balance F (and its moment) to this.
inline constexpr double kEquilibriumTolerance = 1e-6;
/// [N] the largest tooth load accepted (far above any chain's; keeps the joint laws finite).
inline constexpr double kMaxForce = 1e9;
/// [m] the largest joint clearance accepted (a clearance is micrometres to a millimetre).
inline constexpr double kMaxClearance = 0.1;

struct WarpResult {
  std::array<double, 4> force{};           ///< [N] R_i ≥ 0 (F21, F11, F12, F22)
  std::array<double, 4> deflection{};      ///< [m] w(z_i), roller axis displacement at the joint
  std::array<double, 4> deformation{};     ///< [m] contact approach δ_i = max(0, w_i − c_i)
  std::array<double, 4> moment{};          ///< [N·m] bending moment in the roller at z_i
  std::array<double, 4> contact_stress{};  ///< [Pa] sliding: p = R/(d·B); rolling: Hertz p0
  double offset = 0.0;                     ///< [m] a: rigid translation at z = 0
  double rotation = 0.0;                   ///< [rad] b: rigid rotation (w = a + b z + bending)
  double tilt = 0.0;                       ///< [rad] γ: chord slope between the outer joints
  double moment_max = 0.0;                 ///< [N·m] max |M| along the roller
  double bending_stress = 0.0;             ///< [Pa] σ_b = M_max·(d/2)/I
  double upper_share = 0.0;                ///< [-] (F12 + F22)/(F11 + F21) − 1
  double force_residual = 0.0;             ///< [N] |F − ΣR|
  double moment_residual = 0.0;            ///< [N·m] |F·L1 − ΣR z|
  SolverSummary summary;
  std::vector<Diagnostic> diagnostics;
};

struct SolveOptions {
  int max_iterations = 200;
  double tolerance = 1e-10;  ///< [-] relative to F
};

/// Solves the beam on four unilateral joints: displacement method (Hermite beam elements between
/// the joints and the load point, exact for point loads), Newton descent on the convex total
/// potential energy. Throws InputError on invalid input.
WarpResult solve(const Warp& w, const Load& load, const SolveOptions& options = {});

/// Independent check: a force method — Macaulay's closed-form deflection of the free roller,
/// unknowns (a, b, R_i), damped Newton with load continuation. Less robust (the active set can
/// chatter for a flexible roller): it reports converged = false then.
WarpResult solve_flexibility(const Warp& w, const Load& load, const SolveOptions& options = {});

/// Independent check: the same problem by a Hermite-cubic finite-element model of the roller
/// with `elements` elements between consecutive feature points, penalty-free, unilateral springs
/// handled by an active-set loop. Returns the four joint forces.
std::array<double, 4> solve_fe(const Warp& w, const Load& load, int elements = 20);

/// Closed form for a rigid roller, linear joints (n = 1), zero clearance, all joints in contact:
/// R_i = k_i (a + b z_i) with ΣR = F, ΣR z = F L1.
std::array<double, 4> rigid_linear(const Warp& w, const Load& load);

/// [Pa] the contact stress of one joint carrying `force` (sliding: p = R/(d·B); rolling: Hertz
/// p0 of R1 in R2 over the plate thickness B).
double contact_stress(const Warp& w, int joint, double force);

}  // namespace catena::warp
