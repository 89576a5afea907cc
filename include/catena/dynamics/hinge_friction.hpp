// Friction in the chain's hinges (docs/models/dynamics.md, "Hinges").
//
// A hinge at node i is the articulation between link i − 1 (node i − 1 → node i) and link i
// (node i → node i + 1). Its friction is a torque M = −e F s(ω) between the two links: e the
// equivalent lever arm (μ r for a sliding pin of radius r with friction coefficient μ; c_r R* for
// the rolling hinge of seed 000, see rolling_hinge_arm), F the pin load (by default the mean of
// the two links' elastic tensions, or the pin-holding link's: PinLoad; never below 0), ω the
// links' relative rotation rate and
// s(ω) = ω/√(ω² + ω_ε²) the sign regularised over a rate band ω_ε. As forces it is a couple on
// each link: M ∂β/∂x on the three nodes, β the relative angle (link i's angle less link i − 1's).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "catena/core/error.hpp"

namespace catena::dynamics {

/// Which tension loads a hinge's pin (docs/models/dynamics.md, "Hinges").
enum class PinLoad {
  kMean,  ///< the mean of the two links' elastic tensions (the default)
  /// the tension of the outer (pin) link of the two: links alternate inner (roller) and outer
  /// along the chain, link 0 an outer link, so at the hinge of node i link i holds the pin when i
  /// is even and link i − 1 when i is odd (pin_link_side). A closed loop needs an even count.
  kPinLink,
};

/// The hinges' friction (one law for every hinge of the chain). arm = 0: frictionless.
struct HingeFriction {
  double arm = 0.0;  ///< [m] e: the friction torque is e × the pin load (μ r, or c_r R*)
  /// [rad/s] ω_ε: the torque is −e F ω/√(ω² + ω_ε²), within 1/(2 (ω/ω_ε)²) of Coulomb's e F
  /// once the links turn relative to each other faster than ω_ε
  double rate_band = 5.0;
  PinLoad pin_load = PinLoad::kMean;  ///< F: the two links' mean, or the pin link's tension
  /// [N·m/rad] k_t: sticking (docs/models/dynamics.md, "Hinges: sticking"). 0, the default: the
  /// regularised law above. > 0 (needs arm > 0): each hinge carries the deflection d = φ − a of
  /// its relative angle from an anchor (State::hinge_deflection) and the torque is the spring's
  /// −k_t d_θ − c_t ω while that is within e F (sticking: no creep), else e F against it
  /// (sliding, Coulomb's torque at any rate, no band); the anchor follows after each accepted
  /// step so that the spring is left at most at its reach e F/k_t.
  double stick_stiffness = 0.0;
  /// [N·m·s/rad] c_t: a damper beside the stick spring (needs stick_stiffness > 0)
  double stick_damping = 0.0;
  bool active() const { return arm > 0.0; }
  bool sticks() const { return arm > 0.0 && stick_stiffness > 0.0; }
};

/// Every problem with the hinge law, fields "hinge.arm", "hinge.rate_band",
/// "hinge.stick_stiffness", "hinge.stick_damping".
std::vector<Issue> validate(const HingeFriction& hinge, double pitch);
/// With PinLoad::kPinLink and friction on a closed loop of an odd `links` count, the issue
/// "links" (an even count: the inner and outer links alternate round the loop); none otherwise.
std::vector<Issue> validate_pin_links(const HingeFriction& hinge, std::size_t links, bool closed);

/// The link whose tension is the pin load at the hinge of node `node` (between link node − 1,
/// the hinge's first, and link node, its second): −1 both (PinLoad::kMean: their mean), 0 the
/// first, 1 the second (PinLoad::kPinLink: the outer link, the even-numbered of the two).
inline int pin_link_side(const HingeFriction& hinge, std::size_t node) {
  if (hinge.pin_load == PinLoad::kMean) return -1;
  return node % 2 == 0 ? 1 : 0;
}

/// [m] the rolling hinge's equivalent lever arm (seed 000; docs/models/dynamics.md, "Hinges"):
/// rolling without slip, a turn φ of the hinge turns the roller by φ/2 on each plate (eq. 3) and
/// the contact runs R1 Ψ1 = φ/2 · R1 R2/(R2 − R1) along each face (eqs. 1–2); a rolling resistance
/// c_r F on each of the two contacts along that path dissipates c_r F R* φ, R* = R1 R2/(R2 − R1),
/// so e = c_r R*. A flat face (face_radius = ∞) gives R* = R1.
double rolling_hinge_arm(double rolling_coefficient, double plate_radius, double face_radius);

/// The friction couple of one hinge over the step from x₀ to the iterate x₁ at the θ point, for
/// the three nodes a = i − 1, b = i, c = i + 1 (positions at the start, x0/y0, and the iterate,
/// x1/y1, in that order). The relative rotation over the step is Δβ = Δα_c − Δα_a with
/// Δα = (d₀ × d₁)/|d_θ|² per link (its turn to third order), ω = Δβ/h; the force on node k is
/// M g_k with g = ∂β/∂x at the θ point, so the couple's work over the step is exactly M Δβ ≤ 0.
struct HingeCouple {
  double load = 0.0;    ///< [N] F, the pin load
  double rate = 0.0;    ///< [rad/s] ω
  double torque = 0.0;  ///< [N·m] M on the second link (−M on the first)
  double turn = 0.0;    ///< [rad] Δβ over the step
  double work = 0.0;    ///< [J] M Δβ (≤ 0 but with the stick law, whose spring stores energy)
  /// the stick law's spring holds (|−k_t d_θ − c_t ω| ≤ e F; HingeFriction::stick_stiffness)
  bool sticking = false;
  /// [N·m] the stick law's trial torque −k_t d_θ − c_t ω, before the projection onto
  /// |M| ≤ e F (0 without the stick law): the integrator's line search cuts a step at a hinge
  /// whose trial crosses from one slide over the whole stick band to the other
  double trial = 0.0;
  double gx[3] = {0, 0, 0}, gy[3] = {0, 0, 0};  ///< [1/m] g = ∂β/∂x_k at the θ point
  double fx[3] = {0, 0, 0}, fy[3] = {0, 0, 0};  ///< [N] M g_k
  /// [N·m·s/rad] −∂M/∂ω ≥ 0 at the fixed load: e F s'(ω) (the regularised law), k_t θ h + c_t
  /// (the stick law, sticking) or 0 (sliding); −∂(h f)/∂x₁ ≈ this × g gᵀ (the rate term alone)
  double rate_stiffness = 0.0;
  /// [N/m] the exact ∂f/∂x₁ (f = M g on the three nodes, x₁ the end-of-step positions): row
  /// 2k + r is f_k's component r (x, y), column 2q + c is x₁ of node q, component c. Three terms:
  /// g ⊗ ∂M/∂x₁ with ∂M/∂x₁ = −e s(ω) ∂F/∂x₁ − e F s'(ω) ∂Δβ/∂x₁ / h (the rate through the
  /// exact turn Δβ = Δα_c − Δα_a, the load through the links' θ-point lengths) and M ∂g/∂x₁ (the
  /// direction). Not symmetric: g ≠ ∂Δβ/∂x₁ off the midpoint geometry, and the load's and the
  /// direction's terms are not.
  double jacobian[6][6] = {};
};
/// `rest` holds the two links' rest lengths (they differ on an alternating round-link chain,
/// Model::alternation); the pin load is the mean of their elastic tensions k (l_θ − rest), or
/// with PinLoad::kPinLink the pin link's (pin_link_side at `node`, the hinge's node index along
/// the chain: only its parity counts). `node` has no default on any overload: a default would
/// take every hinge as node 0 with the pin link's load, wrong at every odd node.
/// `deflection`: the stick law's d₀ = φ − a at the step's start (hinge_couple_blocks; 0, a hinge
/// anchored where it starts the step, and unused without the stick law). No default either: a
/// default would anchor every hinge where it starts the step, dropping the spring's stored turn.
HingeCouple hinge_couple(const HingeFriction& hinge, double axial_stiffness, const double rest[2],
                         const double x0[3], const double y0[3], const double x1[3],
                         const double y1[3], double theta, double step, std::size_t node,
                         double deflection);
/// The same with the two links' chord lengths given: `length0` at the start of the step
/// (|d₀|), `length1` at the end (|d₁|), as the integrator has them from its links (each link
/// serves two hinges; the square roots are taken once). They must be the square roots of the
/// chords' squared lengths for the result to equal the overload above. `jacobian` false: the
/// couple alone (`jacobian` left zero; every other field the same, bit for bit), for a Newton
/// iteration that reuses an earlier factorisation.
HingeCouple hinge_couple(const HingeFriction& hinge, double axial_stiffness, const double rest[2],
                         const double x0[3], const double y0[3], const double x1[3],
                         const double y1[3], double theta, double step, const double length0[2],
                         const double length1[2], bool jacobian, std::size_t node,
                         double deflection);
/// The same into `out`: every field is written but `jacobian`, which is written only when
/// `jacobian` is true (else left as it was). For the integrator's hinge loop, which keeps one
/// HingeCouple for all hinges rather than zeroing a fresh one (its 36-entry Jacobian) per hinge.
void hinge_couple(const HingeFriction& hinge, double axial_stiffness, const double rest[2],
                  const double x0[3], const double y0[3], const double x1[3], const double y1[3],
                  double theta, double step, const double length0[2], const double length1[2],
                  HingeCouple& out, bool jacobian, std::size_t node, double deflection);
/// What one link contributes to the couples of the two hinges at its ends (each link serves two
/// hinges: the integrator computes these once per link and iteration, then combines them per
/// hinge with the hinge_couple overload below). From the link's chord at the start of the step
/// d₀ and at the iterate d₁, their lengths l₀ = |d₀|, l₁ = |d₁|, its rest length, k and θ.
/// `jacobian` false: turn, P and tension only (the derivatives left as they were), for
/// hinge_couple(…, jacobian = false).
struct HingeLink {
  double turn = 0.0;  ///< [rad] Δα = (d₀ × d₁)/|d_θ|², the link's turn over the step
  double px = 0.0, py = 0.0;    ///< [1/m] P = perp(d_θ)/|d_θ|²
  double tension = 0.0;         ///< [N] k (l_θ − rest), the elastic tension at the θ point
  double tx = 0.0, ty = 0.0;    ///< [1/m] ∂Δα/∂d₁
  double ex = 0.0, ey = 0.0;    ///< [N/m] ∂(½ k l_θ)/∂d₁
  double dp[4] = {0, 0, 0, 0};  ///< [1/m²] ∂P/∂d₁, row-major 2×2
};

inline void hinge_link(double d0x, double d0y, double d1x, double d1y, double length0,
                       double length1, double rest, double axial_stiffness, double theta,
                       HingeLink& out, bool jacobian = true) {
  const double mx = (1.0 - theta) * d0x + theta * d1x, my = (1.0 - theta) * d0y + theta * d1y;
  const double m2 = mx * mx + my * my, im2 = 1.0 / m2;
  const double turn = (d0x * d1y - d0y * d1x) * im2;  // d_θ × (d₁ − d₀) = d₀ × d₁
  out.turn = turn;
  out.px = -my * im2;
  out.py = mx * im2;
  // the elastic tension at the θ point, with the integrator's interpolated length
  const double lt = (1.0 - theta) * length0 + theta * length1;
  out.tension = axial_stiffness * (lt - rest);
  if (!jacobian) return;  // the derivatives below are the couple Jacobian's alone
  // ∂turn/∂d₁ = perp(d₀)/|d_θ|² − turn 2θ d_θ/|d_θ|²
  out.tx = (-d0y - 2.0 * theta * turn * mx) * im2;
  out.ty = (d0x - 2.0 * theta * turn * my) * im2;
  // ∂(½ k l_θ)/∂d₁ = ½ k θ d₁/l₁
  const double e = length1 > 0.0 ? 0.5 * axial_stiffness * theta / length1 : 0.0;
  out.ex = e * d1x;
  out.ey = e * d1y;
  // ∂(perp(m)/|m|²)/∂d₁ = θ (R/|m|² − 2 perp(m) mᵀ/|m|⁴), R = [[0, −1], [1, 0]]
  const double s2 = theta * im2, s4 = 2.0 * s2 * im2;
  out.dp[0] = s4 * my * mx;
  out.dp[1] = -s2 + s4 * my * my;
  out.dp[2] = s2 - s4 * mx * mx;
  out.dp[3] = -s4 * mx * my;
}

/// The hinge's load F (unclamped) and its weights w₀, w₁ on ½ T₀, ½ T₁ at `node`
/// (pin_link_side): the mean ½ (T₀ + T₁) with 1 and 1, or the pin link's T with 2 and 0 or 0 and
/// 2 (exact, so the mean's arithmetic is the mean's). hinge_couple_blocks' and
/// hinge_branch_moment_gradient's, so the two cannot disagree on the rule.
struct PinLoadWeights {
  double w0, w1, load;
};
inline PinLoadWeights pin_load_weights(const HingeFriction& hinge, std::size_t node,
                                       const HingeLink& l0, const HingeLink& l1) {
  const int side = pin_link_side(hinge, node);
  const double w0 = side < 0 ? 1.0 : (side == 0 ? 2.0 : 0.0);
  const double w1 = side < 0 ? 1.0 : 2.0 - w0;
  const double load =
      side < 0 ? 0.5 * (l0.tension + l1.tension) : (side == 0 ? l0.tension : l1.tension);
  return {w0, w1, load};
}

/// ∂M/∂x₁ on the hinge's three nodes (dmx, dmy) from its links' HingeLink terms (with their
/// derivatives), the load's weights w₀, w₁ (pin_link_side) and the torque's two partials:
/// `load_factor` ∂M/∂F and `rate_factor` ∂M/∂Δβ. The turn Δβ = turn₁ − turn₀ has the node
/// gradient (T₀, −T₀ − T₁, T₁) (as g); the load F = Σ w_j ½ k (l_θ − rest)_j has
/// (−w₀ E₀, w₀ E₀ − w₁ E₁, w₁ E₁) (zero where the load is clamped at 0: load_factor 0 there).
inline void hinge_moment_gradient(const HingeLink& l0, const HingeLink& l1, double w0, double w1,
                                  double load_factor, double rate_factor, double dmx[3],
                                  double dmy[3]) {
  const double nturn_x[3] = {l0.tx, -l0.tx - l1.tx, l1.tx};
  const double nturn_y[3] = {l0.ty, -l0.ty - l1.ty, l1.ty};
  const double e0x = w0 * l0.ex, e0y = w0 * l0.ey, e1x = w1 * l1.ex, e1y = w1 * l1.ey;
  const double nload_x[3] = {-e0x, e0x - e1x, e1x};
  const double nload_y[3] = {-e0y, e0y - e1y, e1y};
  for (int q = 0; q < 3; ++q) {
    dmx[q] = load_factor * nload_x[q] + rate_factor * nturn_x[q];
    dmy[q] = load_factor * nload_y[q] + rate_factor * nturn_y[q];
  }
}

/// The stick law's ∂M/∂x₁ on the hinge's three nodes on a given branch, whichever branch the
/// hinge is on: `branch` 0 sticking (∂M/∂Δβ = −(k_t θ h + c_t)/h), +1 or −1 sliding with
/// M = ±e F (∂M/∂F = ±e on a loaded hinge); the links' terms with their derivatives (hinge_link
/// with `jacobian`). hinge_couple_blocks' term on the hinge's own branch, bit for bit: the
/// integrator's chord iterations correct their kept factors by the difference of two branches'
/// at a hinge that switched (g ⊗ the difference, a rank-1 change of the Newton matrix).
inline void hinge_branch_moment_gradient(const HingeFriction& hinge, const HingeLink& l0,
                                         const HingeLink& l1, double step, std::size_t node,
                                         double theta, int branch, double dmx[3], double dmy[3]) {
  const auto [w0, w1, load] = pin_load_weights(hinge, node, l0, l1);
  const double loaded = load > 0.0 ? 1.0 : 0.0;
  const double load_factor = branch == 0 ? 0.0 : branch * hinge.arm * loaded;
  const double rate_factor =
      branch == 0 ? -(hinge.stick_stiffness * theta * step + hinge.stick_damping) / step : -0.0;
  hinge_moment_gradient(l0, l1, w0, w1, load_factor, rate_factor, dmx, dmy);
}

/// The couple of the hinge between links `l0` (a → b) and `l1` (b → c) from their HingeLink
/// terms, as hinge_couple below, with the Jacobian handed out block by block rather than stored:
/// with `jacobian`, `block(k, q, a, b, c, d)` is called for each of the nine 2×2 blocks (k, q)
/// of ∂f/∂x₁ (rows of node k, columns of node q; a b / c d row-major), in the order (0, 0),
/// (0, 1), …, (2, 2). `out.jacobian` is not touched. For the integrator's hinge loop, which adds
/// −h × each block into its band without the 6×6 array in between (the same arithmetic).
/// `node`: the hinge's node index along the chain, whose parity picks the pin link
/// (pin_link_side; unused with PinLoad::kMean). With the stick law (HingeFriction::sticks):
/// `deflection` is the spring's d₀ = φ − a at the step's start (State::hinge_deflection) and
/// `theta` the θ of the links' terms, the spring's torque −k_t (d₀ + θ Δβ) − c_t Δβ/h; both unused
/// without it.
template <class Block>
inline void hinge_couple_blocks(const HingeFriction& hinge, const HingeLink& l0,
                                const HingeLink& l1, double step, HingeCouple& hc, bool jacobian,
                                Block&& block, std::size_t node, double theta, double deflection) {
  // F: ½ (T₀ + T₁) (the mean), or the pin link's T (weights w₀, w₁ of ½ T₀, ½ T₁: 1 and 1, or
  // 2 and 0, or 0 and 2; exact, so the mean's arithmetic is what it was)
  const auto [w0, w1, load] = pin_load_weights(hinge, node, l0, l1);
  hc.load = std::max(0.0, load);
  hc.turn = l1.turn - l0.turn;
  hc.rate = hc.turn / step;
  // g = ∂β/∂x: (+P₀, −P₀ − P₁, +P₁), P = perp(d_θ)/|d_θ|²
  const double g1x = -l0.px - l1.px, g1y = -l0.py - l1.py;
  hc.gx[0] = l0.px;
  hc.gy[0] = l0.py;
  hc.gx[1] = g1x;
  hc.gy[1] = g1y;
  hc.gx[2] = l1.px;
  hc.gy[2] = l1.py;
  const double limit = hinge.arm * hc.load;  // e F
  const double loaded = load > 0.0 ? 1.0 : 0.0;
  double load_factor = 0.0;  // ∂M/∂F
  if (hinge.sticks()) {
    // the stick law: the spring and damper −k_t d_θ − c_t ω (d_θ = d₀ + θ Δβ) while within e F,
    // else e F against them (sliding); ∂M/∂Δβ = −(k_t θ + c_t/h) sticking, ∂M/∂F = ±e sliding
    const double kt = hinge.stick_stiffness, ct = hinge.stick_damping;
    const double spring = -kt * (deflection + theta * hc.turn) - ct * hc.rate;
    hc.trial = spring;
    hc.sticking = std::abs(spring) <= limit;
    if (hc.sticking) {
      hc.torque = spring;
      hc.rate_stiffness = kt * theta * step + ct;
    } else {
      const double sign = spring > 0.0 ? 1.0 : -1.0;
      hc.torque = sign * limit;
      hc.rate_stiffness = 0.0;
      load_factor = sign * hinge.arm * loaded;
    }
  } else {
    const double band = hinge.rate_band;
    const double root = std::sqrt(hc.rate * hc.rate + band * band);
    hc.sticking = false;  // trial stays 0: only the stick law writes it, and reads it
    hc.torque = -limit * hc.rate / root;
    hc.rate_stiffness = limit * band * band / (root * root * root);
    load_factor = -hinge.arm * (hc.rate / root) * loaded;  // −e s(ω)
  }
  hc.work = hc.torque * hc.turn;
  // M g on the three nodes, written out (as a loop the compiler kept the loop and read g back)
  const double torque = hc.torque;
  hc.fx[0] = torque * l0.px;
  hc.fy[0] = torque * l0.py;
  hc.fx[1] = torque * g1x;
  hc.fy[1] = torque * g1y;
  hc.fx[2] = torque * l1.px;
  hc.fy[2] = torque * l1.py;
  if (!jacobian) return;
  // The exact ∂f/∂x₁. Node gradients of a per-link quantity q(d₁) of links 0 (a → b) and 1
  // (b → c): the turn Δβ = turn₁ − turn₀ gives (T₀, −T₀ − T₁, T₁) (as g); the load F = Σ w_j ½ k
  // (l_θ − rest)_j gives (−w₀ E₀, w₀ E₀ − w₁ E₁, w₁ E₁) (zero where the load is clamped at 0):
  // the pin link's alone with PinLoad::kPinLink.
  const double rate_factor = -hc.rate_stiffness / step;  // ∂M/∂Δβ (−e F s'/h regularised)
  double dmx[3], dmy[3];                                 // ∂M/∂x₁ per node
  hinge_moment_gradient(l0, l1, w0, w1, load_factor, rate_factor, dmx, dmy);
  // The load and rate terms g_k ⊗ ∂M/∂x_q on every block, plus the direction term M ∂g_k/∂x_q:
  // g = (P₀, −P₀ − P₁, P₁), ∂P_j/∂x of its link's end node is DP_j, of its start node −DP_j, so
  // (blocks k, q) −DP₀ +DP₀ 0 / +DP₀ −DP₀+DP₁ −DP₁ / 0 −DP₁ +DP₁ (the blocks (0, 2) and (2, 0)
  // have no direction term).
  const double m = hc.torque;
  double p0[4], p1[4], p01[4];
  for (int e = 0; e < 4; ++e) {
    p0[e] = m * l0.dp[e];
    p1[e] = m * l1.dp[e];
    p01[e] = m * (-l0.dp[e] + l1.dp[e]);
  }
  const double* gx = hc.gx;
  const double* gy = hc.gy;
  // sign: +1 adds the direction block d, −1 subtracts it, 0 none
  const auto emit = [&](int k, int q, int sign, const double* d) {
    const double a = gx[k] * dmx[q], b = gx[k] * dmy[q], c = gy[k] * dmx[q], e = gy[k] * dmy[q];
    if (sign > 0) {
      block(k, q, a + d[0], b + d[1], c + d[2], e + d[3]);
    } else if (sign < 0) {
      block(k, q, a - d[0], b - d[1], c - d[2], e - d[3]);
    } else {
      block(k, q, a, b, c, e);
    }
  };
  emit(0, 0, -1, p0);
  emit(0, 1, +1, p0);
  emit(0, 2, 0, p0);
  emit(1, 0, +1, p0);
  emit(1, 1, +1, p01);
  emit(1, 2, -1, p1);
  emit(2, 0, 0, p1);
  emit(2, 1, -1, p1);
  emit(2, 2, +1, p1);
}

/// The couple of the hinge between links `l0` (a → b) and `l1` (b → c) from their HingeLink
/// terms, into `out` as above: bit for bit what the overloads above give.
/// `theta` and `deflection` as for hinge_couple_blocks (the stick law's).
inline void hinge_couple(const HingeFriction& hinge, const HingeLink& l0, const HingeLink& l1,
                         double step, HingeCouple& hc, bool jacobian, std::size_t node,
                         double theta, double deflection) {
  hinge_couple_blocks(
      hinge, l0, l1, step, hc, jacobian,
      [&hc](int k, int q, double a, double b, double c, double d) {
        hc.jacobian[2 * k][2 * q] = a;
        hc.jacobian[2 * k][2 * q + 1] = b;
        hc.jacobian[2 * k + 1][2 * q] = c;
        hc.jacobian[2 * k + 1][2 * q + 1] = d;
      },
      node, theta, deflection);
}

/// Both links of rest length `pitch`.
inline HingeCouple hinge_couple(const HingeFriction& hinge, double axial_stiffness, double pitch,
                                const double x0[3], const double y0[3], const double x1[3],
                                const double y1[3], double theta, double step, std::size_t node,
                                double deflection) {
  const double rest[2] = {pitch, pitch};
  return hinge_couple(hinge, axial_stiffness, rest, x0, y0, x1, y1, theta, step, node, deflection);
}

}  // namespace catena::dynamics
