// A planar chain of N links as a constant Model and a mutable State (docs/models/dynamics.md).
//
// The chain is N nodes (the roller or pin centres) joined by axial spring–dampers of rest length
// p, the pitch: link j joins node j to node j + 1, and in a closed loop link N − 1 joins node
// N − 1 back to node 0. Each node carries the mass of one link. Pinned nodes stay where the state
// puts them. State is a structure of arrays (x, y, vx, vy).
#pragma once

#include <array>
#include <bit>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "catena/contact/roller_tooth.hpp"
#include "catena/core/error.hpp"
#include "catena/dynamics/hinge_friction.hpp"

namespace catena::dynamics {

/// A roller's line contact as a force law of its penetration g (docs/models/dynamics.md,
/// "Contact law"), shared by the ISO seats and the guides' rails: the force Q(g) = width · q with
/// δ(q) = g (`law`, Johnson's plane-strain approach), up to the cap law.cap_load(); beyond it the
/// tangent there (C¹), its energy the integral of the force. make_line_law sets the cap's
/// constants; line_force evaluates it.
struct LineLaw {
  contact::LineApproach law;
  double width = 0.0;  ///< [m] the line's length (the roller's inner width b1)
  /// the cap's approach [m], force [N], tangent dQ/dg [N/m] and energy [J]
  double cap_depth = 0.0, cap_force = 0.0, cap_stiffness = 0.0, cap_energy = 0.0;
};
/// The law `law` over `width`, with its cap's constants.
LineLaw make_line_law(const contact::LineApproach& law, double width);
/// The line law's elastic part at penetration g ≥ 0: force [N], ∂force/∂g [N/m] and energy [J].
struct LineForce {
  double force = 0.0, stiffness = 0.0, energy = 0.0;
};
LineForce line_force(const LineLaw& l, double g);

namespace detail {
/// Whether two numbers are the same bit for bit (the step starts' memos, PocketStart and
/// SeatStart, compare their keys so: NaN and −0 as any other number)
inline bool same_bits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}
/// The penalty's C¹ ramp over the first ε (docs/models/dynamics.md, "Contact law"), the one
/// written-out form the seats, the rails and the take-up's stops share: at the gap g with the
/// stiffness k, the force k g²/2ε within the ramp (g < ε) and k (g − ε/2) past it, its slope
/// k g/ε | k and its energy k g³/6ε | k (g²/2 − ε g/2 + ε²/6). With the damping c_c for k the
/// force is the ramped damper's integral C(g) = ∫₀^g c_c min(1, s/ε) ds. For g > 0 only: the
/// caller keeps g ≤ 0 out (the formulas are not 0 there).
inline LineForce penalty_ramp(double k, double eps, double g) {
  LineForce e;
  e.force = g < eps ? 0.5 * k * g * g / eps : k * (g - 0.5 * eps);
  e.stiffness = g < eps ? k * g / eps : k;
  e.energy =
      g < eps ? k * g * g * g / (6.0 * eps) : k * (0.5 * g * g - 0.5 * eps * g + eps * eps / 6.0);
  return e;
}
/// The ramped damper's integral C(g) = ∫₀^g c min(1, s/ε) ds with c the damping for k: the
/// penalty's force with c for k, 0 for g ≤ 0 (the seats' and links' dampers over a step)
inline double damper_integral(double c, double eps, double g) {
  return g > 0.0 ? penalty_ramp(c, eps, g).force : 0.0;
}
}  // namespace detail

/// A rigid sprocket: its rollers' seats on the ISO 606 tooth form (seat i's centre on the pitch
/// circle at the angle ψ + 2π i/z, the seating arc of radius ri about it). Roller–seat contact is a
/// unilateral linear penalty with damping (or, with line_law, the Hertz line contact's law). A
/// driver turns at a prescribed speed; a driven wheel has inertia and a constant load torque
/// against counter-clockwise rotation.
struct Sprocket {
  double centre_x = 0.0;       ///< [m]
  double centre_y = 0.0;       ///< [m]
  int teeth = 0;               ///< z
  double pitch_radius = 0.0;   ///< [m] R = p / (2 sin(π/z))
  double seat_radius = 0.0;    ///< [m] ri, the seating arc's radius (≥ roller radius)
  double roller_radius = 0.0;  ///< [m] d1/2
  double seating_angle = 0.0;  ///< [rad] α, the seating arc's extent; flanks beyond it
  /// [m] Ra, the tooth tip: each tooth is bounded by its two straight flanks and the tip circle
  /// of radius Ra about the centre (or, where the flanks meet below it, by their apex), and a
  /// roller meets the tip's arc and the flank/tip corner as a disc (docs/models/dynamics.md,
  /// "Tooth tip"). 0: no tip — the flanks run on to the reach R + r (the form before the tip,
  /// whose reach cuts the flanks with a jump of the force); iso606_sprocket sets the ISO tip.
  double tip_radius = 0.0;
  /// [m] re, the flank: the ISO arc of this radius tangent to the seating arc at its end, convex
  /// (centred on the tooth's side at ri + re from the seat centre); 0: the straight line tangent
  /// there (the form before the tip). iso606_sprocket sets the minimum gap's re,max.
  double flank_radius = 0.0;
  double contact_stiffness = 0.0;  ///< [N/m] k_c, the penalty on the roller's penetration
  double contact_damping = 0.0;    ///< [N·s/m] c_c, on the penetration rate (never pulls)
  /// [m] ε: the force rises as k_c g²/2ε over the first ε of penetration, then k_c (g − ε/2),
  /// and the damping ramps in over the same ε, so that the force is C¹ at first touch (Newton
  /// does not cycle on a roller touching and leaving its seat within one step)
  double contact_smoothing = 1e-6;
  /// The seats' elastic law (docs/models/dynamics.md, "Contact law"). false: the linear penalty
  /// above. true: the Hertz line contact `line` (LineLaw) over the width b1: the force Q(g) with
  /// δ(Q/b1) = g, up to the cap, beyond it the tangent there; contact_stiffness then serves only
  /// a take-up's end stops (slide_stop). The damping is the same in both.
  bool line_law = false;
  LineLaw line;
  /// The seats' elastic force over a step (docs/models/dynamics.md, "Sprockets: the discrete
  /// gradient"): true, the discrete gradient f_e = (E(g₁) − E(g₀))/(g₁ − g₀) of the law's energy
  /// between the gaps in the θ point's seat at the step's start (roller x₀, wheel angle ψ₀) and
  /// end (x₁, ψ₁) (seat_contact_at with a SeatStep), with a correction along the step so that its
  /// work over the step is −ΔE on the curved seats and a turning wheel too; false, the default:
  /// the force at the θ point. On a pocket wheel: the discrete gradient of the pocket's energy
  /// over the step (pocket_step_contact; docs "Pocket wheel: the discrete gradient").
  /// use_line_law leaves it as it is (the case key discrete_gradient sets it).
  bool discrete_gradient = false;
  bool driver = false;       ///< prescribed speed (true) or inertia + load (false)
  double speed = 0.0;        ///< [rad/s] a driver's speed, counter-clockwise positive
  double inertia = 0.0;      ///< [kg·m²] a driven wheel's moment of inertia
  double load_torque = 0.0;  ///< [N·m] on a driven wheel, against counter-clockwise turning
  /// Pocket wheel for round-link chain (seed 003; docs/models/dynamics.md, "Pocket wheel"):
  /// instead of the tooth gaps, a pocket for each joint at the vertices of the bi-regular polygon,
  /// ψ + 2πm/z and ψ + 2πm/z + δ1 on the pitch circle, holding the joint within its clearance
  /// (pocket_contact). roller_radius, seat_radius and seating_angle are then unused.
  bool pocket = false;
  double pocket_angle = 0.0;      ///< [rad] δ1, the central angle of the p + a side
  double pocket_clearance = 0.0;  ///< [m] c: a joint within c of its vertex is free
  /// [m] w: the pocket's mouth ramp (docs/models/dynamics.md, "Pocket wheel: the mouth"). 0 (the
  /// default) is the sharp mouth: the contact acts within |q − O| ≤ R + c/2 and is cut there.
  /// w > 0 adds a ramp over R + c/2 < |q − O| < R + c/2 + w in which the contact's energy is
  /// E₀(g) W(g) s(h): s a C² step in the depth h = R + c/2 + w − |q − O|, W a C² step from 1 at
  /// g ≤ c to 0 at g ≥ 2c; a joint within 2c of its vertex then meets the force and its
  /// derivative continuously where it crosses the mouth. Not the default: see the docs.
  double pocket_mouth = 0.0;
  /// The pocket's release (docs/models/dynamics.md, "Pocket wheel: unwinding"): the contact's
  /// energy is E₀(g) S(u), u = cos of the angle between e = q − C and the outward radial, S a C²
  /// step from 1 at u ≤ u₁ = sin(δ1/2 + 5°) to 0 at u ≥ u₀ = sin(δ1/2 + 35°); a joint that has
  /// been within the mouth (State::held_*) stays held by its pocket beyond the mouth until S or
  /// g reaches 0, so a leaving joint's force falls to zero continuously in its position. An
  /// option (false, the default, is the sharp mouth's release; false is required with
  /// pocket_mouth > 0): with the contact's damping Newton stalls (docs, "Pocket wheel: unwinding").
  bool pocket_release = false;
  /// The wheel's body between its pockets (docs/models/dynamics.md, "Pocket wheel: the body
  /// between the pockets"): within the mouth, a joint more than 10c from its nearest vertex is
  /// not that pocket's but meets the rim R + c/2, which pushes it radially out (penetration
  /// R + c/2 − |q − O|, the seats' law, no friction); the two blend over 10c–20c, the pocket's
  /// friction fading with them. false leaves the nearest vertex's pull however far the joint is
  /// (the law before; kept for the tests).
  bool pocket_body = true;
  /// [-] μ of the roller–seat contact: Coulomb friction against the roller's slip along the seat
  /// surface relative to the wheel (0: frictionless seats, the default)
  double friction = 0.0;
  /// [m/s] v_ε: the seat friction is −μ f v_t/√(v_t² + v_ε²), as on a guide
  double friction_band = 1e-3;
  /// Take-up (docs/models/dynamics.md, "Take-up"): the wheel's centre slides along the unit
  /// direction e = (takeup_dx, takeup_dy) from (centre_x, centre_y), at the displacement s
  /// (State::slide), pushed by F(s, ṡ) = takeup_force − takeup_stiffness s − takeup_damping ṡ
  /// along e (a constant force: stiffness 0; a spring: its preload at s = 0). The slide carries
  /// takeup_mass (the idler and its carriage). Only on a wheel that is not a driver.
  bool takeup = false;
  double takeup_dx = 0.0, takeup_dy = 0.0;  ///< [-] e, a unit vector
  double takeup_force = 0.0;                ///< [N] F₀, along e at s = 0
  double takeup_stiffness = 0.0;            ///< [N/m] k_t ≥ 0
  double takeup_damping = 0.0;              ///< [N·s/m] c_t ≥ 0
  double takeup_mass = 0.0;                 ///< [kg] m_t > 0, the sliding mass
  /// [m] the slide's travel, s_min ≤ 0 ≤ s_max (±∞: unbounded): beyond either end an end stop
  /// pushes back, unilateral, with the wheel's own contact law (contact_stiffness,
  /// contact_damping, contact_smoothing: slide_stop)
  double takeup_travel_min = -std::numeric_limits<double>::infinity();
  double takeup_travel_max = std::numeric_limits<double>::infinity();
};

/// A take-up's end stop at the slide's displacement s and speed ṡ (docs/models/dynamics.md,
/// "Take-up"): past an end by g it pushes back along the slide like a seat on its roller —
/// k_c g²/2ε over the first ε, then k_c (g − ε/2), plus the damping c_c ṡ ramped in over ε,
/// never pulling.
struct SlideStop {
  double penetration = 0.0;    ///< [m] g ≥ 0, past the nearer end (0 within the travel)
  double force = 0.0;          ///< [N] along e (toward the travel)
  double stiffness = 0.0;      ///< [N/m] −∂force/∂s
  double damping = 0.0;        ///< [N·s/m] −∂force/∂ṡ
  double energy = 0.0;         ///< [J] the stop's elastic energy at g
  double damping_power = 0.0;  ///< [W] the stop's damper's power on the slide (≤ 0)
};

inline SlideStop slide_stop(const Sprocket& w, double s, double rate) {
  SlideStop out;
  if (!w.takeup) return out;
  double dir = 0.0;  // the stop's push along e
  if (s > w.takeup_travel_max) {
    out.penetration = s - w.takeup_travel_max;
    dir = -1.0;
  } else if (s < w.takeup_travel_min) {
    out.penetration = w.takeup_travel_min - s;
    dir = 1.0;
  } else {
    return out;
  }
  const double g = out.penetration, eps = w.contact_smoothing, k = w.contact_stiffness;
  const double c = w.contact_damping, gdot = -dir * rate;  // the penetration's rate
  const bool ramp = g < eps;
  const LineForce el = detail::penalty_ramp(k, eps, g);  // g > 0 here
  const double r = ramp ? g / eps : 1.0, dr = ramp ? 1.0 / eps : 0.0;
  out.energy = el.energy;
  const double f = el.force + c * r * gdot;
  if (!(f > 0.0)) return out;  // separating faster than the spring pushes: no force
  out.force = dir * f;
  out.stiffness = el.stiffness + c * dr * gdot;
  out.damping = c * r;
  out.damping_power = -c * r * gdot * gdot;
  return out;
}

/// The wheel `w` with its centre where the slide puts it: moved by `slide` along the take-up's
/// direction (the wheel itself when it has no take-up).
inline Sprocket at_slide(const Sprocket& w, double slide) {
  Sprocket moved = w;
  if (w.takeup) {
    moved.centre_x += slide * w.takeup_dx;
    moved.centre_y += slide * w.takeup_dy;
  }
  return moved;
}

/// A constant force on one node (a dead load, or the far end of a span held by a tension source
/// instead of a wheel). Its potential is −f·x (in Energy::potential).
struct NodeLoad {
  std::size_t node = 0;  ///< index of the node it acts on
  double fx = 0.0;       ///< [N]
  double fy = 0.0;       ///< [N]
};

/// A rigid rail the chain's rollers slide on (docs/models/dynamics.md, "Guides"): one-sided — it
/// pushes a roller out to its free side and never pulls — with a unilateral penalty contact of the
/// sprockets' form and Coulomb friction against the roller's sliding, regularised over a small
/// speed band. The rail is the surface the roller touches: the roller's centre rides at one roller
/// radius from it on the free side.
struct Guide {
  enum class Kind { kStraight, kArc };
  Kind kind = Kind::kStraight;
  /// straight: the surface from (x0, y0) to (x1, y1); the free side is on the left going from the
  /// first end to the second (a rail from left to right carries the rollers on top)
  double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;  ///< [m]
  /// arc: the surface is the circle of `radius` about the centre from `start_angle` to
  /// `end_angle` counter-clockwise; the rollers ride outside it (convex) or, if `inside`, inside
  double centre_x = 0.0, centre_y = 0.0;  ///< [m]
  double radius = 0.0;                    ///< [m]
  double start_angle = 0.0;               ///< [rad]
  double end_angle = 0.0;                 ///< [rad] > start_angle, at most start_angle + 2π
  bool inside = false;
  double roller_radius = 0.0;       ///< [m] d1/2
  double contact_stiffness = 0.0;   ///< [N/m] k_c on the roller's penetration into the rail
  double contact_damping = 0.0;     ///< [N·s/m] c_c on the penetration rate (never pulls)
  double contact_smoothing = 1e-6;  ///< [m] ε: the C¹ ramp of force and damping, as on a sprocket
  double friction = 0.0;            ///< [-] μ, Coulomb: the sliding force is μ × normal force
  /// [m/s] v_ε: the friction force is −μ f v_t/√(v_t² + v_ε²), within 1/(2 (v_t/v_ε)²) of the
  /// Coulomb value when sliding faster than v_ε (1e-4 relative at 70 v_ε)
  double friction_band = 1e-3;
  /// [kg/m] q_L: conveyed material riding on the chain along the rail, straight or arc (docs/
  /// models/dynamics.md, "A conveyed load"; rail_load); 0, the default: none.
  double load_per_metre = 0.0;
  /// The load's inertia, loading and discharge (docs/models/dynamics.md, "A conveyed load: its
  /// inertia, loading and discharge"; only with load_per_metre > 0): each node carries the load's
  /// mass q_L p w(s) besides its own (load_mass), material joining a node arrives at rest (the
  /// catch's reaction) and material leaving it leaves at the node's velocity. false, the default:
  /// the load is weight only.
  bool load_inertia = false;
  /// [m/s] u: the speed of the material arriving on the chain (docs/models/dynamics.md, "A
  /// conveyed load: its inertia, loading and discharge"; only with load_inertia): a chute or
  /// feeder's delivery, along the rail's direction from (x0, y0) to (x1, y1) on a straight rail,
  /// along the arc's counter-clockwise sense (from start_angle to end_angle) at the node on an
  /// arc; negative: the other way. The catch's reaction is Δm_L (u − v). 0, the default: the
  /// material arrives at rest.
  double load_speed = 0.0;
  /// [N/m] k_t: sticking (docs/models/dynamics.md, "Guides: sticking"). 0, the default: the
  /// regularised friction above. > 0 (a guide with friction > 0 only, straight or arc): each
  /// roller in contact carries an anchor a (State::stick_anchor) and the friction is the
  /// elasto-plastic spring f_t = −clamp(k_t (s − a), −μ f, μ f), s the roller's position along t
  /// (guide_position); while the spring's force is below μ f the roller sticks (no creep), beyond
  /// it slides at μ f and the anchor follows (updated once per accepted step,
  /// update_stick_anchors).
  double stick_stiffness = 0.0;
  /// The rail's elastic law (docs/models/dynamics.md, "Guides: the line law"). false: the linear
  /// penalty contact_stiffness above. true: the roller's line contact on the rail (LineLaw, set by
  /// use_line_law from the geometry and `rail`), the seats' law with ρ = r on a straight rail,
  /// 1/ρ = 1/r + 1/R outside an arc, 1/r − 1/R inside; contact_stiffness is then unused. The
  /// damping is the same in both.
  bool line_law = false;
  LineLaw line;
  Elastic rail;  ///< the rail's material (steel, as the rollers, by default)
  /// [N·s/m] c_t: a damper beside the stick law's spring (needs stick_stiffness > 0): while
  /// sticking f_t = −k_t (s − a) − c_t ṡ, ṡ = ∂s/∂q · v the roller's speed along the rail's
  /// parametrisation; the roller slides when that exceeds μ f. 0, the default: the bare spring.
  double stick_damping = 0.0;
  /// The normal force's elastic part over a step (docs/models/dynamics.md, "Guides: the discrete
  /// gradient"): true, the discrete gradient f_e = (E(g₁) − E(g₀))/(g₁ − g₀) of the contact's
  /// energy between the gaps at the step's start and end (guide_contact with a GuideStep), so that
  /// its work over the step is −ΔE (on a straight rail at any θ; on an arc at θ = ½, the force
  /// along the radial ν, to the gaps' rounding), and the damper over the step,
  /// (C(g₁) − C(g₀))/h (C the integral of the ramped damping coefficient; its work never
  /// positive); false: the force and the damper at the θ point.
  /// use_line_law sets it (the line law's default); the linear penalty keeps the θ point's.
  bool discrete_gradient = false;
};

/// Turns a guide's rail to the line law over the roller's inner width `width` (b1): the roller
/// (steel, radius roller_radius, R_ref = the roller radius as in the seats) on the rail of
/// material `rail`, flat or of its arc's curvature. Call it after the geometry is set.
void use_line_law(Guide& g, double width);

/// The range of Guide::rail's modulus validate accepts [Pa].
inline constexpr double kLeastRailModulus = 1e8, kMostRailModulus = 1e12;

/// The largest Guide::load_per_metre validate accepts [kg/m].
inline constexpr double kMaxRailLoad = 1e4;
/// [m/s] the largest |Guide::load_speed| accepted
inline constexpr double kMaxLoadSpeed = 100.0;

/// One roller's contact with one guide at position q and velocity v: the force on the roller,
/// F = f n + f_t t (n the rail's normal to the free side, t = (−n_y, n_x); f ν in place of f n on
/// an arc with the discrete gradient, guide_contact with a GuideStep), and its derivatives
/// ∂F/∂q and ∂F/∂v (2×2, row-major [[a, b], [c, d]]) for the Newton matrix.
struct GuideContact {
  bool active = false;
  double penetration = 0.0;     ///< [m] g > 0 when active
  double normal_force = 0.0;    ///< [N] f ≥ 0
  double friction_force = 0.0;  ///< [N] f_t along t (opposes the sliding speed)
  double slip = 0.0;            ///< [m/s] v_t = v·t, the roller's sliding speed along the rail
  double energy = 0.0;          ///< [J] the elastic contact energy
  /// [W] the power of the normal force's damping part on the roller, −(f − f_el) ġ ≤ 0 (f_el the
  /// elastic part; with f clamped at 0 the damper cancels f_el): the contact damper's dissipation;
  /// over a step (the discrete gradient) −(f − f_el) Δg/h, Δg = g₁ − g₀
  double damping_power = 0.0;
  /// [m] s along t (guide_position; stick law only, else 0)
  double position = 0.0;
  /// σ in ∂s/∂q = σ t: ρ_c/|q − C| on an arc, 1 on a straight rail (stick law only, else 1); the
  /// spring's force along t is σ k_t (s − a)
  double position_scale = 1.0;
  /// the stick spring holds (|σ (k_t (s − a) + c_t ṡ)| ≤ μ f; stick law only)
  bool sticking = false;
  double nx = 0.0, ny = 0.0;    ///< unit normal to the free side
  double fx = 0.0, fy = 0.0;    ///< [N] F
  double dq[4] = {0, 0, 0, 0};  ///< [N/m] ∂F/∂q
  double dv[4] = {0, 0, 0, 0};  ///< [N·s/m] ∂F/∂v
};
GuideContact guide_contact(const Guide& g, double x, double y, double vx, double vy);
/// A straight rail's unit direction from its first end to its second and its length (zeros for
/// an arc): what guide_contact computes from the ends on each call, computed once.
struct GuideFrame {
  double ux = 0.0, uy = 0.0;  ///< unit direction
  double length = 0.0;        ///< [m]
};
GuideFrame guide_frame(const Guide& g);
/// guide_contact with the rail's frame given (frame = guide_frame(g)): the same result, bit for
/// bit.
GuideContact guide_contact(const Guide& g, const GuideFrame& frame, double x, double y, double vx,
                           double vy);
/// guide_contact with the stick law (Guide::stick_stiffness > 0) about the anchor a [m] along t:
/// the friction is −clamp(σ (k_t (s − a) + c_t ṡ), −μ f, μ f) instead of the regularised law
/// (s − a taken by stick_stretch; c_t = Guide::stick_damping; ∂s/∂q = σ tᵀ, σ = 1 on a straight
/// rail and ρ_c/|q − C| on an arc, so that while it sticks the force is exactly −∂/∂q of
/// ½ k_t (s − a)² plus the damper's −c_t ṡ ∂s/∂q), and its derivatives enter dq and dv (on an arc
/// with σ's gradient and t turning with the roller). A NaN anchor or k_t = 0: the regularised
/// contact above, bit for bit.
GuideContact guide_contact(const Guide& g, const GuideFrame& frame, double x, double y, double vx,
                           double vy, double anchor);
/// A step's ends for the discrete gradient (Guide::discrete_gradient): the roller's centre at the
/// step's start x₀ (the state) and at its end x₁ (the iterate) [m], and the step h [s].
struct GuideStep {
  double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;
  double h = 0.0;
};
/// guide_contact over the step `step` (nullptr, or a guide without Guide::discrete_gradient: the
/// θ point's force above, bit for bit). With it the elastic part is the discrete gradient
/// (E(g₁) − E(g₀))/(g₁ − g₀) of the law's energy between the gaps g₀ at x₀ and g₁ at x₁, taken in
/// the same rail's geometry (no end test; E = 0 for g ≤ 0), E'((g₀ + g₁)/2) where |g₁ − g₀| is
/// below 1e-6 of the larger gap; the damper is taken over the step too, f_d = (C(g₁) − C(g₀))/h
/// with C(g) = ∫₀^g c(s) ds, c(g) = c_c min(1, g/ε) (0 for g ≤ 0), the seats' (∂f_d/∂g₁ = c(g₁)/h
/// ≥ 0, its work −c̄ Δg²/h ≤ 0), f = max(0, f_e + f_d); the ends' test and the far side's
/// (g < 2r) stay at the θ point (x, y), and so does the direction n on a straight rail. On an arc
/// f acts along ν = s (q_θ − C)/ρ̄, ρ̄ = (ρ₀ + ρ₁)/2 (ρ = |q − C| at x₀ and x₁, s = ±1 as
/// n = s (q − C)/|q − C|): at θ = ½ ν·(x₁ − x₀) = −Δg, its work −f Δg to the gaps' rounding
/// (`nx`, `ny` still report n; ∂(f ν)/∂q_θ = f (s/ρ̄) I, ∂ν/∂x₁ = −(s/2ρ̄) ν ⊗ n₁). It is active
/// while the larger of g₀ and g₁ is positive (a roller dropping in from g₀ ≤ 0 is pushed on the
/// step it enters; `penetration` is the θ point's gap, then ≤ 0 possibly). ∂f/∂x₁ = −(∂f_e/∂g₁ +
/// ∂f_d/∂g₁) n₁ enters dv as h ∂f/∂x₁ (the velocity is (x₁ − x₀)/h), so that −(hθ dq + dv) is still
/// the step's exact block.
GuideContact guide_contact(const Guide& g, const GuideFrame& frame, double x, double y, double vx,
                           double vy, double anchor, const GuideStep* step);
/// [m] s, the tangential position along the contact's tangent t = (−n_y, n_x): on a straight rail
/// (q − P₀)·t from its first end (t = −u, u the direction from the first end to the second); on
/// an arc ρ_c φ outside (t counter-clockwise) and −ρ_c φ inside (t clockwise), ρ_c φ the conveyed
/// load's place along the roller centres' line (rail_load: φ from start_angle, within π of the
/// arc's middle, ρ_c = R ± r).
double guide_position(const Guide& g, const GuideFrame& frame, double x, double y);
/// Where (x, y) lies against the guide g, with no test of its sides: whether it is between the
/// rail's ends (guide_contact's test), its place along the rail (from (x0, y0) along a straight
/// rail [m], the angle from start_angle round an arc's centre in [0, 2π) [rad]) and its gap g
/// [m] (guide_contact's penetration, which is active between the ends at 0 < g < 2r).
struct GuideSpot {
  bool between = false;
  double along = 0.0;
  double gap = 0.0;
};
GuideSpot guide_spot(const Guide& g, const GuideFrame& frame, double x, double y);
/// [m] the stick spring's stretch s − a: on a straight rail s − a; on an arc taken within half
/// the circumference 2π ρ_c of the rollers' line (a closed arc's seam, where s jumps by 2π ρ_c, is
/// no slip), s − a itself when it is within that.
double stick_stretch(const Guide& g, double s, double anchor);
/// The anchor after a step whose contact (at the step's θ point, about the anchor `anchor`) was
/// `c` and that ends at the position `end` [m] along t (s₁, guide_position): unchanged while
/// |s₁ − a| (stick_stretch) is within the spring's reach μ f/(k_t σ) (f and σ the θ point's
/// normal force and GuideContact::position_scale; the spring's force along t is σ k_t (s − a)),
/// else moved to s₁ ∓ μ f/(k_t σ) (the slip), so that the spring is left stretched by at most its
/// reach. NaN (released) when the contact is inactive or carries no normal force; `end` for a NaN
/// anchor.
double stick_anchor_after(const Guide& g, const GuideContact& c, double anchor, double end);
/// A rail's load (Guide::load_per_metre q_L) on one node at q (dynamics.md, "A conveyed load"):
/// F = q_L p g w(s), g the gravity, p the pitch, s the node's place along the rail from its first
/// end (straight: (q − P₀)·u; arc: ρ_c φ, φ its angle from the start, ρ_c = R ± r the rollers'
/// line's radius; frame unused), w(s) = |[s − p/2, s + p/2] ∩ [0, L]|/p: nodes a pitch apart carry
/// q_L L g. Only a node from a roller radius behind the rollers' line to a pitch off it carries it;
/// validate wants n·g < 0 (n the free side's normal; over the whole arc on an arc).
/// ∂F/∂q = q_L p g w' (∂s/∂q)ᵀ, ∂s/∂q = u (straight) or ρ_c t/|q − C| (arc, t the ccw tangent).
struct RailLoad {
  bool active = false;
  double share = 0.0;           ///< [-] w(s)
  double fx = 0.0, fy = 0.0;    ///< [N] F
  double dq[4] = {0, 0, 0, 0};  ///< [N/m] ∂F/∂q
};
RailLoad rail_load(const Guide& g, const GuideFrame& frame, double pitch, double gravity_x,
                   double gravity_y, double x, double y);
struct Model;
/// The conveyed load's mass on a node at q: Σ q_L p w(s) over the guides with load_inertia
/// (rail_load's share w, ramp and gate), and its gradient ∂m_L/∂q = Σ q_L p w' (∂s/∂q)ᵀ.
/// `frames`: guide_frame of each of model.guides.
/// With Guide::load_speed also p = Σ m_L,g u_g (u_g the guide's arriving velocity at q:
/// load_speed along the rail's direction, or the arc's counter-clockwise tangent) and ∂p/∂q; with
/// one loaded piece at a node the material joining it arrives with p/m_L = u_g (the integrator
/// takes the pieces' increments where two overlap: LoadPiece).
struct LoadMass {
  double mass = 0.0;          ///< [kg] m_L
  double dx = 0.0, dy = 0.0;  ///< [kg/m] ∂m_L/∂q
  double px = 0.0, py = 0.0;  ///< [kg·m/s] p (0 without load_speed)
  /// [kg/s] ∂p/∂q row-major: ∂p_x/∂x, ∂p_x/∂y, ∂p_y/∂x, ∂p_y/∂y
  double dp[4] = {0, 0, 0, 0};
};
/// One guide's part of load_mass at q: its mass m_L,g = q_L p w(s), ∇m_L,g, and the direction t
/// of its arriving velocity u_g = load_speed t with ∂t/∂q (t = 0 without load_speed).
struct LoadPiece {
  bool active = false;
  double mass = 0.0;                    ///< [kg] m_L,g
  double dx = 0.0, dy = 0.0;            ///< [kg/m] ∂m_L,g/∂q
  double tx = 0.0, ty = 0.0;            ///< [-] t
  double dt[4] = {0.0, 0.0, 0.0, 0.0};  ///< [1/m] ∂t/∂q row-major
};
/// `pieces` (empty, or one per model.guides): also each guide's part (inactive for a guide
/// without load_inertia or without a share at q).
LoadMass load_mass(const Model& model, std::span<const GuideFrame> frames, double x, double y,
                   std::span<LoadPiece> pieces = {});
/// Some guide with load_inertia and load_per_metre > 0 (a model's or a case's guides).
bool any_load_inertia(std::span<const Guide> guides);

/// An axis-aligned box that holds every roller centre a guide can touch: guide_contact(g, x, y,
/// …) is active only if guide_touch_possible(guide_bounds(g), x, y). A straight rail's segment
/// widened by the roller radius, an arc's whole circle of radius + roller radius, each padded by
/// 1e-9 of its size against rounding: a cheap, exact cull before guide_contact.
struct GuideBounds {
  double x_lo = 0.0, x_hi = 0.0, y_lo = 0.0, y_hi = 0.0;  ///< [m]
};
GuideBounds guide_bounds(const Guide& g);
inline bool guide_touch_possible(const GuideBounds& b, double x, double y) {
  return x >= b.x_lo && x <= b.x_hi && y >= b.y_lo && y <= b.y_hi;
}

/// A lead-in at the ends of a guide, straight or arc (docs/models/dynamics.md, "Lead-ins"): an arc
/// rail of surface radius R and sweep α tangent to the rail at its end, bending away from the free
/// side, so that a roller arriving a little below the rail's surface meets the arc's gentle slope
/// instead of the rail's square end. At the joint the arc's surface point, its normal and so the
/// contact's penetration and force are those of the rail (the contact's stiffness jumps by the
/// curvatures' share, f/R against the rail's, across it); on a straight rail the arc ends
/// R (1 − cos α) below the surface, R sin α past the end. On an arc rail of surface radius ρ and
/// centre C the lead-in's centre lies on the line from C through the end, at C + (ρ − R) e with
/// the rollers outside the rail (R < ρ: inside the rail's circle), C + (ρ + R) e with the rollers
/// `inside` (outside the rail's circle), e the end's direction from C; the rollers ride outside
/// the lead-in in both.
struct LeadIn {
  double radius = 0.0;   ///< [m] R > 0: the arc's surface radius
  double angle = 0.0;    ///< [rad] α in (0, π/2]: the arc's sweep
  bool at_start = true;  ///< at (x0, y0), or an arc's start_angle
  bool at_end = true;    ///< at (x1, y1), or an arc's end_angle
};
/// The lead-in's values out of range, named "lead_in_radius" and "lead_in_angle".
std::vector<Issue> validate(const LeadIn& lead);
/// The lead-in's problems on `rail`: validate(lead)'s, then an arc rail's (when its centre, radius
/// and sweep are valid; else its own checks name them): with the rollers outside it R < ρ
/// ("lead_in_radius": the lead-in bends away from the rail's circle only curving more sharply),
/// and the lead-in's reach round C (lead_in_cover) at each end it is laid at within the arc's open
/// part 2π − (end_angle − start_angle) ("lead_in_angle": no roller meets the rail and its lead-in,
/// or both lead-ins, at once; the message names the largest lead_in_angle at this radius and
/// lead_in_radius at this angle that fit, rounded down), none on a closed ring ("lead_in_radius").
std::vector<Issue> validate(const LeadIn& lead, const Guide& rail);
/// [rad] The angle round an arc rail's centre C, from the rail's end, that a lead-in's contact
/// covers: the roller centres it touches lie within R + r of its centre, in its sweep (r the
/// roller radius), and seen from C they span, outside (R < ρ),
/// atan2((R + r) sin α, ρ − R + (R + r) cos α); inside, atan2((R + r) sin α, ρ + R − (R + r) cos α)
/// up to the tangent from C, asin((R + r)/(ρ + R)), where α passes acos((R + r)/(ρ + R)). NaN
/// for a straight rail or one where these do not apply (outside R ≥ ρ, inside ρ ≤ r).
double lead_in_cover(const Guide& rail, const LeadIn& lead);
/// [rad] The largest sweep α in [0, π/2] whose lead_in_cover at lead.radius on `rail` is at most
/// `cover` (lead.angle unused): lead_in_cover solved for α, outside α = β + asin((ρ − R) sin β /
/// (R + r)), inside α = asin((ρ + R) sin β / (R + r)) − β, β = `cover`; π/2 when every sweep
/// fits. NaN where lead_in_cover is, or for a negative `cover`.
double lead_in_angle_limit(const Guide& rail, const LeadIn& lead, double cover);
/// The arc guides of the lead-in on a rail (first the start's, then the end's, as asked), with the
/// rail's contact law, roller radius and friction. None for a lead-in that does not validate on
/// the rail (validate(lead, rail)), or a rail whose geometry is invalid.
std::vector<Guide> lead_in_arcs(const Guide& rail, const LeadIn& lead);

struct Model {
  bool closed = false;               ///< closed loop (link N − 1 joins node N − 1 to node 0)
  double pitch = 0.0;                ///< [m] p, the unstretched length of one link
  double axial_stiffness = 0.0;      ///< [N/m] k of one link: tension = k (l − p) + c l̇
  double axial_damping = 0.0;        ///< [N·s/m] c of one link
  double drag = 0.0;                 ///< [1/s] α: a force −α m v on each node (to settle)
  double gravity_x = 0.0;            ///< [m/s²] g, x component
  double gravity_y = 0.0;            ///< [m/s²] g, y component
  std::vector<double> mass;          ///< [kg] per node; its size is N
  std::vector<std::uint8_t> pinned;  ///< per node, 1 = held fixed; empty = none pinned
  std::vector<Sprocket> sprockets;   ///< rigid wheels the rollers seat on
  std::vector<NodeLoad> loads;       ///< constant forces on single nodes; empty = none
  std::vector<Guide> guides;         ///< rails the rollers slide on
  /// [m] a: link j's rest length is p + a for even j and p − a for odd j (round-link chain on a
  /// pocket wheel: the joint polygon's sides t + d and t − d, a = d); 0 = every link p
  double alternation = 0.0;
  HingeFriction hinge;  ///< friction in every hinge; arm 0 = frictionless
  /// true (the default): every link is the bilateral spring–damper above, pushing as it pulls (a
  /// roller chain's plates carry compression). false: a tension-only link (a round link, whose
  /// neighbour slides inside the ring when the joints come closer than its inner length;
  /// docs/models/dynamics.md, "Tension-only links"): the tension is link_force's, never negative.
  /// Hinge friction needs the bilateral links (validated).
  bool links_carry_compression = true;
  /// [m] ε of a tension-only link: its spring's tension rises as k (s + ε/2)²/2ε over
  /// −ε/2 < s < ε/2 (s = l − rest length) and is k s beyond, 0 below, and its damper ramps in
  /// over the same ε (link_force); unused with links_carry_compression
  double link_smoothing = 1e-6;
  /// A tension-only link's force over a step (docs/models/dynamics.md, "Tension-only links: the
  /// discrete gradient"): true, link_step_force (the discrete gradient of its energy between the
  /// stretches at the step's ends, and its damper over the step), so that at θ = ½ its spring's
  /// work over the step is exactly −ΔE; false, the default: link_force at the θ point. The case
  /// key discrete_gradient sets it with wheel = "pocket". Only with tension-only links
  /// (validated: the bilateral link's θ = ½ force is that discrete gradient already).
  bool links_discrete_gradient = false;
  /// [m] l_jam of a tension-only link: the joint-to-joint distance below which it pushes back
  /// (docs/models/dynamics.md, "Tension-only links: the jam"): [0] for the even links (rest
  /// length p + a), [1] for the odd (p − a); 0 = no jam (the joints close and pass each other
  /// unchecked). Below l_jam the link pushes with k (l − l_jam), C¹-smoothed over the same ε as
  /// the tension side (link_force). A round-link chain on a pocket wheel (a = d): the odd link
  /// jams at d (its neighbours' wires meet inside it); the even link, one rigid link's own tips,
  /// is rigid, but not by a jam here (at p + a − ε the two ramps meet with no stiffness at zero
  /// tension): link_bilateral. Each 0 or in (0, jam_length_bound] (validated: the jam's ramp below
  /// the tension's); 0 with links_carry_compression or with its parity's link_bilateral
  /// (validated).
  std::array<double, 2> link_jam_length{0.0, 0.0};
  /// With links_carry_compression false: [0] makes the even links (rest length p + a), [1] the
  /// odd (p − a), the bilateral spring–damper (link_force's T = k s + c ṡ, E = ½ k s²: k through
  /// s = 0, no ε ramps, no jam) while the other parity stays tension-only (docs/models/dynamics.md,
  /// "Tension-only links: the jam", "The flat links"). A round-link chain on a pocket wheel: the
  /// even (t + d) link is one flat link between its own two tips, rigid. Harmless with
  /// links_carry_compression (every link bilateral already). Parity is the link's index j % 2,
  /// so on a closed loop of an odd number of links links N − 1 and 0 are both even and the flag
  /// (as link_jam_length) does not alternate across the seam. Such a loop is refused with
  /// alternation > 0 (validated: alternation), so a round-link chain's loop (alternation d) is
  /// even; with alternation 0 the flag is accepted and means the link's index parity only.
  std::array<bool, 2> link_bilateral{false, false};

  std::size_t nodes() const { return mass.size(); }
  /// Links: N in a closed loop, N − 1 in an open chain.
  std::size_t links() const { return closed ? mass.size() : mass.size() - 1; }
  bool is_pinned(std::size_t i) const { return !pinned.empty() && pinned[i] != 0; }
  /// [m] the rest length of link j: p ± a (see alternation)
  double rest_length(std::size_t j) const {
    return j % 2 == 0 ? pitch + alternation : pitch - alternation;
  }
  /// [m] the jam length of link j (link_jam_length by its parity; 0 = none)
  double jam_length(std::size_t j) const { return link_jam_length[j % 2]; }
  /// link j is the bilateral spring–damper (links_carry_compression, or its parity's
  /// link_bilateral)
  bool bilateral(std::size_t j) const { return links_carry_compression || link_bilateral[j % 2]; }
  /// [m] the largest jam length of link j: its rest length less ε (the jam's ramp below the
  /// tension's, validated)
  double jam_length_bound(std::size_t j) const { return rest_length(j) - link_smoothing; }
};

/// Every problem with the model, fields "nodes", "pitch", "axial_stiffness", "axial_damping",
/// "drag", "gravity", "mass", "pinned", "sprocket[i].<field>", "guide[i].<field>",
/// "load[i].node", "load[i].force", "hinge.arm", "hinge.rate_band", "hinge.stick_stiffness",
/// "hinge.stick_damping", "link_smoothing", "link_jam_length[0]", "link_jam_length[1]",
/// "links_carry_compression", "links" (an odd closed loop with the pin link's hinge load).
std::vector<Issue> validate(const Model& model);

/// One link's law at the stretch s = l − rest length and the rate ṡ = l̇ (docs/models/dynamics.md,
/// "Model" and "Tension-only links").
struct LinkForce {
  double tension = 0.0;    ///< [N] T, along the link (pulling its two nodes together when > 0)
  double elastic = 0.0;    ///< [N] the spring's part T_e(s) = dE/ds (T − T_e is the damper's)
  double stiffness = 0.0;  ///< [N/m] ∂T/∂s
  double damping = 0.0;    ///< [N·s/m] ∂T/∂ṡ
  double energy = 0.0;     ///< [J] E(s), the spring's energy
};

/// link_force's side below the tension's ramp with a jam (Model::jam_length(link) > 0): out of
/// line, so that link_force stays small enough to be inlined where the links run.
LinkForce link_jam_force(const Model& model, double s, double rate, std::size_t link);

/// The bilateral link (Model::bilateral(link)): T = k s + c ṡ, E = ½ k s². The
/// tension-only link: with u = s + ε/2 (ε = Model::link_smoothing), T_e = 0 for u ≤ 0,
/// k u²/2ε for 0 < u < ε, k s for u ≥ ε — C¹, ≥ 0, and equal to the bilateral spring in tension
/// beyond s = ε/2 — with E = k u³/6ε, then ½ k s² + k ε²/24; the damper c r ṡ with r = u/ε
/// ramped in over the same ε (the seats' gating), and T = 0 wherever T_e + c r ṡ ≤ 0 (a link
/// shortening faster than its spring pulls goes slack: it never pushes) — unless it jams
/// (Model::jam_length(link) > 0): with s_j = l_jam − rest length and v = s_j − s + ε/2, the
/// mirror image below s_j: T_e = −k v²/2ε for 0 < v < ε, −k (s_j − s) for v ≥ ε, E = k v³/6ε, then
/// ½ k (s_j − s)² + k ε²/24, the damper c (v/ε) ṡ ramped in over the same ε, and T = 0 wherever
/// T_e + c r ṡ ≥ 0 (a jammed link lengthening faster than it pushes comes free: it never pulls).
/// `link` picks the jam length (its parity) and whether it is bilateral (its parity's
/// Model::link_bilateral).
inline LinkForce link_force(const Model& model, double s, double rate, std::size_t link = 0);

/// link_force of a link that is not bilateral (!Model::bilateral(link)): the tension-only law
/// alone, small enough to be inlined where the links run (the integrator's tension-only branch).
inline LinkForce tension_only_link_force(const Model& model, double s, double rate,
                                         std::size_t link) {
  const double k = model.axial_stiffness, c = model.axial_damping;
  LinkForce out;
  const double eps = model.link_smoothing, u = s + 0.5 * eps;
  if (!(u > 0.0)) {
    // slack (the joints closer than the rest length less ε/2), unless the link jams there
    if (!(model.jam_length(link) > 0.0)) return out;
    return link_jam_force(model, s, rate, link);
  }
  const bool ramp = u < eps;
  out.elastic = ramp ? k * u * u / (2.0 * eps) : k * s;
  out.energy = ramp ? k * u * u * u / (6.0 * eps) : 0.5 * k * s * s + k * eps * eps / 24.0;
  const double r = ramp ? u / eps : 1.0;
  const double tension = out.elastic + c * r * rate;
  if (!(tension > 0.0)) return out;  // shortening faster than the spring pulls: slack
  out.tension = tension;
  out.stiffness = (ramp ? k * u / eps : k) + (ramp ? c * rate / eps : 0.0);
  out.damping = c * r;
  return out;
}

inline LinkForce link_force(const Model& model, double s, double rate, std::size_t link) {
  if (!model.bilateral(link)) return tension_only_link_force(model, s, rate, link);
  const double k = model.axial_stiffness, c = model.axial_damping;
  LinkForce out;
  out.elastic = k * s;
  out.tension = k * s + c * rate;
  out.stiffness = k;
  out.damping = c;
  out.energy = 0.5 * k * s * s;
  return out;
}

/// A link's force over a step (Model::links_discrete_gradient): a tension-only link's, or a
/// bilateral link's (Model::bilateral).
struct LinkStep {
  double tension = 0.0;  ///< [N] T = max(0, T_dg + f_d) (with a jam, see link_step_force)
  double elastic = 0.0;  ///< [N] T_dg, the discrete gradient of E (T − T_dg is the damper's)
  double slope = 0.0;    ///< [N/m] ∂T/∂s₁ (0 where T is clamped at 0)
};

/// A tension-only link's force over the step from the stretch s₀ to s₁ (s = l − rest length) in
/// the time h (docs/models/dynamics.md, "Tension-only links: the discrete gradient"): the spring's
/// T_dg = (E(s₁) − E(s₀))/(s₁ − s₀) of link_force's energy E (its T_e at the mean stretch for
/// |s₁ − s₀| ≤ 1e-6 max(ε, |s₀|, |s₁|)), the damper f_d = (C(u₁) − C(u₀))/h with C(u) = ∫ c r
/// the ramped damper's integral (u = s + ε/2, as the seats'), and T = max(0, T_dg + f_d). Along
/// d_θ/l_θ at θ = ½ the spring's work over the step is −(E(s₁) − E(s₀)) and the damper's
/// −(T − T_dg)(s₁ − s₀) ≤ 0. With a jam (Model::jam_length(link) > 0) E is link_force's over
/// the jam too, the jam's damper over the step is the mirror image's (its C of v = s_j − s + ε/2),
/// the threshold's |s| is measured from s_j when the step's mean is nearer the jam, and T may
/// push only on a step that touches the jam's ramp, pull only on one that touches the tension's
/// (else T = 0). A bilateral link (Model::bilateral(link)): T_dg = k (s₀ + s₁)/2, the quotient of
/// ½ k s² exactly, and T = T_dg + c (s₁ − s₀)/h, never clamped. The integrator does not call it
/// for a bilateral link: its own bilateral branch at θ = ½ is this force already; the branch
/// keeps the step law defined for every link the model holds
/// (tests/dynamics/tension_only_test.cpp).
LinkStep link_step_force(const Model& model, double s0, double s1, double h, std::size_t link = 0);
/// What link_step_force reads of the step's start stretch s₀ alone: the energy E(s₀), the
/// damper's integral C(u₀) (u₀ = s₀ + ε/2) and, with a jam, the jam's C(v₀) (v₀ = s_j − s₀ + ε/2),
/// which do not move within a step.
struct LinkStart {
  double energy = 0.0;      ///< [J] E(s₀)
  double damper = 0.0;      ///< [N] C(u₀), 0 for u₀ ≤ 0
  double jam_damper = 0.0;  ///< [N] C(v₀), 0 for v₀ ≤ 0 or without a jam
};
inline LinkStart link_step_start(const Model& model, double s0, std::size_t link) {
  const double eps = model.link_smoothing, jam = model.jam_length(link);
  const double sj = jam > 0.0 ? jam - model.rest_length(link) : 0.0;
  return {link_force(model, s0, 0.0, link).energy,
          detail::damper_integral(model.axial_damping, eps, s0 + 0.5 * eps),
          jam > 0.0 ? detail::damper_integral(model.axial_damping, eps, sj - s0 + 0.5 * eps) : 0.0};
}
/// link_step_force with the start's `start` = link_step_start(model, s0, link) given (the
/// integrator takes it once a step for each link): the same result, bit for bit.
LinkStep link_step_force(const Model& model, double s0, double s1, double h, std::size_t link,
                         const LinkStart& start);

/// N nodes of equal mass; an open chain gets its two end nodes pinned when `pin_ends`.
Model uniform_chain(std::size_t nodes, bool closed, double pitch, double node_mass,
                    double axial_stiffness, double axial_damping, bool pin_ends);

struct State {
  double time = 0.0;           ///< [s]
  std::vector<double> x, y;    ///< [m] node positions
  std::vector<double> vx, vy;  ///< [m/s] node velocities
  std::vector<double> angle;   ///< [rad] per sprocket: ψ, the angle of seat 0
  std::vector<double> speed;   ///< [rad/s] per sprocket
  /// [J] work of the guides' friction on the chain so far (≤ 0); with the stick law minus the
  /// spring–sliders' dissipation (their springs' energy is in Energy::elastic)
  double friction_work = 0.0;
  double damper_work = 0.0;  ///< [J] work of the links' dampers so far (≤ 0 at θ = ½)
  double drag_work = 0.0;    ///< [J] work of the drag −α m v so far (≤ 0)
  /// [J] work of the seats' and guides' contact dampers so far (≤ 0)
  double contact_damping_work = 0.0;
  double seat_friction_work = 0.0;  ///< [J] work of the seats' friction so far (≤ 0)
  /// [J] work of the hinges' friction so far (≤ 0); with the stick law minus the
  /// spring–sliders' dissipation (their springs' energy is in Energy::elastic)
  double hinge_work = 0.0;
  /// [J] work of the rails' loads (Guide::load_per_metre) on the chain so far
  double load_work = 0.0;
  /// [J] the loading's catch so far (Guide::load_inertia): the work of the reaction of material
  /// arriving on the chain, minus the kinetic energy it gains on it. Arriving at rest it is ≤ 0
  /// (half the work the chain does to bring it to speed, lost in the inelastic catch); arriving
  /// at u (Guide::load_speed) it is that loss, −½ Δm_L |v − u|² at a steady speed, plus the
  /// kinetic energy the material brings (load_arrival_work, part of this)
  double load_catch_work = 0.0;
  /// [J] the arriving material's kinetic energy so far (≥ 0; Guide::load_speed): the input part
  /// of load_catch_work (the catch's loss is load_catch_work − this). A step adds ½ Δm_L |u|² on
  /// one loaded piece; where loaded pieces overlap at a node, each growing piece's material its
  /// own, ½ Δm_L Σ⁺ Δm_g |u_g|² / Σ⁺ Δm_g (Σ⁺ over the pieces whose share grows; the overlap
  /// rule of docs/models/dynamics.md, "A conveyed load: its inertia, loading and discharge")
  double load_arrival_work = 0.0;
  /// [J] the discharge so far (Guide::load_inertia): minus the kinetic energy the material
  /// leaving the chain carries away (≤ 0)
  double load_discharge_work = 0.0;
  /// [m] per sprocket: a take-up's slide displacement s along its direction (0 without one)
  std::vector<double> slide;
  std::vector<double> slide_speed;  ///< [m/s] per sprocket: ṡ
  double takeup_damper_work = 0.0;  ///< [J] work of the take-ups' dampers so far (≤ 0)
  /// per node: the pocket wheel (−1: none) and pocket vertex that hold the joint beyond the mouth
  /// (Sprocket::pocket_release), set at the start and end of each step where the joint is within
  /// a mouth (update_held), cleared when its released contact's force is 0
  std::vector<int> held_wheel, held_pocket;
  /// [m] per sticking guide (Guide::stick_stiffness > 0), the k-th of them in the guides' order,
  /// and node i at [k·N + i]: the stick law's anchor a along the rail (NaN: not in contact).
  /// Empty until a step on a model with a sticking guide sizes it (once); set at the end of each
  /// step from the contact at its θ point and the step's end (stick_anchor_after).
  std::vector<double> stick_anchor;
  /// [rad] per node, with the hinges' stick law (HingeFriction::stick_stiffness): the deflection
  /// d = φ − a of the hinge at node i (its relative angle φ from its anchor a, φ accumulated by
  /// the steps' turns Δβ). Empty until a step on such a model sizes it (once, every hinge at 0:
  /// anchored where it starts); set at the end of each step to d₀ + Δβ, or to ±e F/k_t where the
  /// hinge slid past the spring's reach (the anchor dragged along). 0 at the ends of an open chain.
  std::vector<double> hinge_deflection;
  explicit State(std::size_t nodes = 0, std::size_t sprockets = 0)
      : x(nodes),
        y(nodes),
        vx(nodes),
        vy(nodes),
        angle(sprockets),
        speed(sprockets),
        slide(sprockets),
        slide_speed(sprockets),
        held_wheel(nodes, -1),
        held_pocket(nodes, 0) {}
  std::size_t nodes() const { return x.size(); }
};

/// Every problem with a state for this model (sizes, finite values, pinned nodes at rest,
/// no link of zero length), fields "state.x", "state.v", "state.link".
std::vector<Issue> validate(const Model& model, const State& state);

struct Energy {
  /// [J] Σ ½ (m + m_L) v² (m_L the conveyed load's mass with Guide::load_inertia, load_mass)
  /// + Σ ½ J ω² (driven sprockets) + Σ ½ m_t ṡ² (take-ups)
  double kinetic = 0.0;
  /// [J] Σ ½ k (l − p)² (a tension-only link: link_force's E) + the seat and guide contacts'
  /// energies + Σ ½ k_t s² (take-ups) + Σ ½ k_t (s − a)² (the guides' stick springs)
  /// + Σ ½ k_t d² (the hinges' stick springs, State::hinge_deflection)
  double elastic = 0.0;
  /// [J] −Σ m g·x − Σ f·x (gravity and node loads) − Σ (F₀ + m_t g·e) s (take-ups)
  double potential = 0.0;
  double total() const { return kinetic + elastic + potential; }
};

Energy energy(const Model& model, const State& state);

/// A sprocket on the ISO 606 tooth form of catena::drive (pitch radius from the pitch diameter,
/// the seating radius ri,min and seating angle α,max of the minimum tooth gap); role and contact
/// given by the caller. The tip is da,max/2 unless the tooth's corner would then stand in the
/// way of a roller articulating onto (or off) the wheel about its seated neighbour, as at
/// z ≤ 10 for 12B: then it is lowered to articulation_tip_radius (docs/models/dynamics.md,
/// "Tooth tip").
/// Throws InputError for an invalid tooth-form input.
Sprocket iso606_sprocket(double pitch, double roller_diameter, double inner_width, int teeth,
                         double centre_x, double centre_y, double contact_stiffness,
                         double contact_damping);

/// The start of a closed loop over two equal sprockets of `teeth` (even) teeth, wheel 0 at the
/// origin and wheel 1 `span` pitches along +x: teeth + 2·span nodes, every roller seated on the
/// pitch circle (radius `pitch_radius`) or on a straight span, all at the pitch-line speed of
/// both wheels turning at `omega`. Counter-clockwise round the loop: over wheel 0 from its top
/// seat to its bottom seat, the lower span (+x), over wheel 1 from bottom to top, the upper span
/// (−x); wheel angles π/2 and −π/2 (the polygons in phase).
/// The deepest penetration [m] of a roller into the teeth along its articulation path: the
/// roller's centre swung about its neighbour's seat centre at the seats' chord 2R sin(π/z),
/// from its own seat outwards through a quarter turn — the path the chain's next roller takes
/// relative to the wheel as it winds on (and, mirrored, off). ≤ 0: the path clears the tooth.
double articulation_interference(const Sprocket& w);

/// The largest tip radius in (R, w.tip_radius] at which articulation_interference is ≤ 0
/// (bisection to 1e-9 m), less 1 µm (the path is sampled: between samples the corner may stand
/// proud by nanometres); w.tip_radius itself when it already clears, when the wheel has no tip
/// (0), or when even a tip at the pitch circle does not clear (the flanks cut the path).
double articulation_tip_radius(const Sprocket& w);

State two_sprocket_loop(int teeth, int span, double pitch, double pitch_radius, double omega);

/// The links of a two-sprocket loop (wheel centres on y = 0 at x = 0 and x = `centre_distance`,
/// as `two_sprocket_loop` lays them) whose middles are nearest the middle of the upper (y > 0) and
/// of the lower (y < 0) span, measured along x: {upper, lower}. O(N). Where the spans' tensions
/// are sampled (`catena dynamics`, the drive validations).
std::array<std::size_t, 2> span_middle_links(const State& state, double centre_distance);

/// One roller's contact with the nearest seat of one sprocket, found in O(1) from the roller's
/// angle about the wheel centre. Inputs are the roller's position and velocity, the wheel's angle
/// and speed.
struct SeatContact {
  bool active = false;
  int seat = 0;              ///< the seat index k (any integer; seat k ≡ k mod z)
  double penetration = 0.0;  ///< [m] g = |e| + r − ri > 0 when active
  /// [m] the depth reported in max_penetration: g, except on a pocket's mouth ramp, where it is
  /// the seats' law's depth for the ramp's elastic force (g there reaches 2c at almost no force)
  double depth = 0.0;
  double force = 0.0;      ///< [N] f ≥ 0, pushing the roller towards the seat centre
  double stiffness = 0.0;  ///< [N/m] ∂f/∂g (0 when f is clamped at 0)
  double damping = 0.0;    ///< [N·s/m] the damping coefficient at this penetration
  double energy = 0.0;     ///< [J] the elastic contact energy
  /// [W] the power of the force's damping part on roller and wheel together, −(f − f_el) ġ ≤ 0
  /// (ġ the rate at the contact point relative to the wheel): the contact damper's dissipation
  double damping_power = 0.0;
  /// [1/m] ∂n/∂q = κ t tᵀ (t = (−n_y, n_x)): 1/|q − C| on the seating arc, 0 on a flank,
  /// −1/|q − O| on the tip's arc and −1/|q − K| at a tooth's corner K (convex: negative)
  double curvature = 0.0;
  /// where the roller touches: 0 the seating arc, 1 a flank, 2 a tooth's corner (the flank/tip
  /// junction, or the flanks' apex), 3 the tip's arc (on a pocket wheel: the body between the
  /// pockets, Sprocket::pocket_body, whose seat friction is the pocket's faded over the capture's
  /// blend: friction_weight)
  int surface = 0;
  double nx = 0.0, ny = 0.0;  ///< unit vector from the seat centre to the roller
  /// The pocket's mouth ramp (pocket_contact; zero elsewhere): the part of the exact elastic
  /// ∂F/∂q (row-major) that the fields above do not give, −[(∂f/∂g) n nᵀ + f κ (I − n nᵀ)].
  double dq_extra[4] = {0.0, 0.0, 0.0, 0.0};
  /// The pocket's release (pocket_release; zero elsewhere): dq_extra is there the rest of the
  /// whole exact ∂F/∂q, the damper's share included, and this the rest of the exact ∂F/∂v
  /// (row-major) beyond the fields' −c n nᵀ: the damper acts along e/|e|, the fields' n is the
  /// force's direction.
  double dv_extra[4] = {0.0, 0.0, 0.0, 0.0};
  /// The pocket's mouth ramp, release and body (zero elsewhere, where the fields are exact): the
  /// rest of the exact ∂F/∂q and ∂F/∂v of the contact force F = −f n on the joint (row-major, the
  /// damper's share included) beyond what seat_friction reads from the fields,
  /// −n [(∂f/∂g) nᵀ + c (ω + κ v_t) tᵀ] − f κ t tᵀ and −c n nᵀ (v_t the slip along t).
  double friction_dq[4] = {0.0, 0.0, 0.0, 0.0};
  double friction_dv[4] = {0.0, 0.0, 0.0, 0.0};
  /// The friction's share P (1 except on a pocket wheel's body between the pockets, where the
  /// pocket's friction fades with the pocket's share of the depth: P from 1 at the capture's
  /// `from` to 0 at `to`) and ∂P/∂q [1/m]: seat_friction gives P times its force, with P's
  /// gradient in the derivatives.
  double friction_weight = 1.0;
  double friction_weight_dq[2] = {0.0, 0.0};
  double torque = 0.0;                ///< [N·m] on the wheel, counter-clockwise positive
  double seat_x = 0.0, seat_y = 0.0;  ///< [m] the seat centre
  /// The discrete gradient (seat_contact_at with a SeatStep; zero elsewhere): ∂f/∂g₁ [N/m], the
  /// force's derivative with respect to the gap g₁ at the step's end, and that gap's derivatives
  /// ∂g₁/∂x₁ = (step_nx, step_ny) (the surface's normal at x₁) and ∂g₁/∂ψ₁ = step_turn [m]
  /// (= −n₁·perp(x₁ − c₁), c₁ the centre at the end): ∂f/∂x₁ = gap_slope (step_nx, step_ny).
  double gap_slope = 0.0;
  double step_nx = 0.0, step_ny = 0.0;
  double step_turn = 0.0;
  /// The discrete gradient's correction along the step (zero elsewhere; docs "Sprockets: the
  /// discrete gradient"): the normal force's part −S Δ on the roller, Δ = (skew_x, skew_y) [m]
  /// its displacement over the step relative to the wheel's centre, and −S R² Δψ in `torque`, so
  /// that the work over the step is −f Δg (−ΔE, the damper's) on any surface and a turning wheel.
  /// S [N/m], its derivatives ∂S/∂x₁ = (skew_dx, skew_dy) [N/m²], ∂S/∂ψ₁ = skew_dpsi [N/m].
  double skew = 0.0;
  double skew_x = 0.0, skew_y = 0.0;
  double skew_dx = 0.0, skew_dy = 0.0, skew_dpsi = 0.0;
};
SeatContact seat_contact(const Sprocket& w, double x, double y, double vx, double vy, double angle,
                         double speed);
/// The constants of one ISO 606 wheel's tooth gap that seat_contact uses, from the wheel's fields
/// alone (not its centre): computed once per wheel and step by the integrator instead of once per
/// roller in reach (two sine/cosine pairs, an arctangent and two hypotenuses on a flank).
struct SeatGeometry {
  double reach = 0.0;  ///< [m] contact_reach(w)
  double tau = 0.0;    ///< [rad] the seat spacing 2π/z
  /// tan(τ/2) (1 − 1e-9): a point q with |(q − c) × u| ≤ it (q − c)·u, u the seat's direction, lies
  /// within the seat's mid-tooth lines (with 0, a default SeatGeometry's, only a point on the
  /// line through c along u, where the cross product is 0, passes)
  double sector_tan = 0.0;
  double ch = 0.0, sh = 0.0;  ///< cos and sin of half the seating angle α/2
  double fa = 0.0, fb = 0.0;  ///< [m] the flank arc's centre F in the seat's mirrored frame
  bool has_corner = false;    ///< the flank ends at a corner K (the tip circle or the apex)
  bool tip_arc = false;       ///< K is on the tip circle (else the flanks' apex)
  double ka = 0.0, kb = 0.0;  ///< [m] K in the seat's mirrored frame
};
SeatGeometry seat_geometry(const Sprocket& w);
/// The nearest seat's index k = nearbyint((atan2(ry, rx) − angle)/τ) of a roller at r = q − centre.
double nearest_seat(double rx, double ry, double angle, double tau);
/// seat_contact with the wheel's geometry `t` = seat_geometry(w) given (the same result).
SeatContact seat_contact(const Sprocket& w, const SeatGeometry& t, double x, double y, double vx,
                         double vy, double angle, double speed);
/// seat_contact's work after the seat is chosen: the contact with seat k, whose direction
/// (cs, sn) = (cos σ, sin σ), σ = angle + k τ, is given (the caller may keep it for the step: a
/// driver's angle is the same in every Newton iteration). No reach test: the caller's.
SeatContact seat_contact_at(const Sprocket& w, const SeatGeometry& t, double x, double y, double vx,
                            double vy, double speed, double k, double cs, double sn);
/// seat_contact_at's memo of a step's start (x₀, ψ₀ do not move within a step): the start's gap
/// g₀ in its own nearest seat (the sector test and the seat's sine and cosine included), the
/// damper's integral C(g₀) and, once the quotient has read it, the law's energy E(g₀), for the θ
/// point's seat k and the inputs they were taken with. A call whose inputs differ from these in
/// any bit takes the start afresh and keeps it here. Valid for one wheel within one step, as
/// PocketStart: the key leaves out the wheel's own parameters and its tooth geometry (the
/// integrator keeps one per roller and wheel and clears them every step). Used so, the result is
/// the same with the memo or without.
struct SeatStart {
  bool set = false;
  double x0 = 0.0, y0 = 0.0, cx0 = 0.0, cy0 = 0.0, angle0 = 0.0, seat = 0.0;
  double gap = 0.0;     ///< [m] g₀
  double damper = 0.0;  ///< [N] C(g₀), the damper's integral (0 for g₀ ≤ 0)
  bool energy_set = false;
  double energy = 0.0;  ///< [J] E(g₀), the law's energy (when energy_set)
};
/// A step's ends for the seats' discrete gradient (Sprocket::discrete_gradient): the roller's
/// centre at the step's start x₀ and end x₁ [m], the wheel's angles ψ₀, ψ₁ [rad] and its centre
/// there [m] (they differ on a take-up's sliding wheel), and the step h [s]. Each end is measured
/// in its own nearest seat (nearest_seat at that end: the θ point's seat k while it lies within
/// k's mid-tooth lines). `start`, optional: the caller's memo of the step's start for this roller
/// and wheel, kept over the step's Newton iterations.
struct SeatStep {
  double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;
  double angle0 = 0.0, angle1 = 0.0;
  double cx0 = 0.0, cy0 = 0.0, cx1 = 0.0, cy1 = 0.0;
  double h = 0.0;
  double turn = 0.0;   ///< [rad] the wheel's turn over the step, ψ₁ − ψ₀
  double theta = 0.5;  ///< the θ point's weight (the θ point's angle ψ₀ + θ (ψ₁ − ψ₀))
  SeatStart* start = nullptr;
  /// false: a call for the step's residual alone (no Newton matrix): the correction's derivatives
  /// skew_dx, skew_dy, skew_dpsi and friction_dv are left 0 and not to be read; every other field
  /// is the same, bit for bit.
  bool jacobian = true;
};
/// seat_contact_at over the step `step` (nullptr, or a wheel without Sprocket::discrete_gradient:
/// the θ point's force above, bit for bit). With it the elastic part is the discrete gradient
/// (E(g₁) − E(g₀))/(g₁ − g₀) of the law's energy between the gaps g₀ at (x₀, ψ₀) and g₁ at
/// (x₁, ψ₁), each in its own nearest seat by the same surfaces (arc, flank, corner, tip; the gap
/// is continuous across a mid-tooth line, where the two seats' gaps are equal), E = 0 for g ≤ 0,
/// E'((g₀ + g₁)/2) where |g₁ − g₀| is below 1e-6 of the larger gap; the damper (C(g₁) − C(g₀))/h
/// over the step too, C(g) = ∫₀^g c_c min(1, s/ε) ds; the direction n and the torque's arm stay
/// at the θ point; the work's miss on a curved surface or a turning wheel, f (Δg − the θ point's
/// linear change), is put back along the step (Gonzalez's discrete gradient: the force −f ∇̄g with
/// ∇̄g = ∇g_θ + (Δg − ∇g_θ·Δz) Δz/|Δz|², z = (x − c, R ψ); the skew fields). Active while the
/// larger of g₀ and g₁ is positive, the θ point's normal being defined (`penetration` and `depth`
/// are then the θ point's gap, ≤ 0 possibly; a θ point inside with both ends clear is no contact);
/// `stiffness` and `damping` are 0 (nothing at the θ point): gap_slope (∂f/∂g₁) and the step_
/// fields carry ∂f/∂x₁ and ∂f/∂ψ₁, and friction_dv holds −h (∂f/∂g₁) n n₁ᵀ so that seat_friction's
/// derivatives see the force's dependence on x₁.
SeatContact seat_contact_at(const Sprocket& w, const SeatGeometry& t, double x, double y, double vx,
                            double vy, double speed, double k, double cs, double sn,
                            const SeatStep* step);
/// The seats' force law (docs/models/dynamics.md, "Sprockets"), shared by the ISO seat and the
/// pocket: on a contact `c` whose normal (c.nx, c.ny) is set, at penetration g > 0, with
/// r = q − centre and the roller's velocity v, sets force, stiffness ∂f/∂g, damping, energy,
/// damping power, torque, penetration and `active` — f = k_c (g − ε/2) with the C¹ ramp
/// k_c g²/2ε over the first ε (with `line_law` the line contact's Q(g), line_force), damping c_c ġ
/// ramped in over ε (ġ relative to the wheel), never pulling.
void apply_seat_law(const Sprocket& w, double g, double rx, double ry, double vx, double vy,
                    double speed, SeatContact& c);

/// The roller in an ISO seat as a line contact (docs/models/dynamics.md, "Contact stiffness
/// default"): the roller d1 = 2 r in the seating arc ri (concave), over the inner width b1,
/// steel on steel. The Hertz default's secant and the line law both evaluate its approach.
contact::RollerTooth seat_line_contact(const Sprocket& w, double width);
/// Turns an ISO wheel's seats to the line law over the inner width b1 = `width` (line_law, and
/// line from seat_line_contact with its cap's constants).
void use_line_law(Sprocket& w, double width);

/// One joint's contact with the nearest pocket of a pocket wheel (`Sprocket::pocket`), found in
/// O(1) from the joint's angle about the centre. The pocket holds the joint at its vertex C: with
/// e = q − C, the penetration is g = |e| − c (c the clearance), with the seats' force law
/// (f ≥ 0 towards C, C¹ ramp over ε, damping on ġ relative to the wheel). Active only within the
/// pocket's mouth, |q − O| ≤ R + c/2: a joint enters from outside force-free when it comes within
/// 60° of the radial, and leaves if pulled out along the radial. With `pocket_mouth` w > 0, the
/// ramp above the mouth (Sprocket::pocket_mouth): there the force −∇(E₀ W s) has a radial part,
/// and the result's n is the force's direction, its force the magnitude, dq_extra the rest of
/// the elastic ∂F/∂q. Same result fields as seat_contact (curvature 1/|e|, the normal n = e/|e|).
/// The release band of Sprocket::pocket_release: S = 1 for u ≤ full, 0 for u ≥ none.
struct ReleaseBand {
  double full = 0.0, none = 0.0;
};
ReleaseBand release_band(const Sprocket& w);
/// `held`: the vertex index of the pocket that holds the joint (State::held_pocket) with
/// pocket_release, kNoPocket otherwise; beyond the mouth a held joint keeps that pocket's contact.
inline constexpr int kNoPocket = -2147483647 - 1;
SeatContact pocket_contact(const Sprocket& w, double x, double y, double vx, double vy,
                           double angle, double speed, int held = kNoPocket);
/// pocket_step_contact's memo of a step's start (x₀, ψ₀ do not move within a step): the start's
/// place for the jumps and its energy E_k, for the pocket k, the hold and the inputs it was taken
/// with (the wheel's centre included: a take-up's moves with the iterate). A call whose inputs
/// differ from these in any bit takes the start afresh and keeps it here. Valid for one wheel
/// within one step: the key leaves out the wheel's own parameters (stiffness, smoothing,
/// clearance, radius, pocket angle, mouth, release, body, teeth), so a memo must not be carried
/// to another wheel or to a wheel whose parameters changed (the integrator keeps one per joint
/// and wheel and clears them every step). Used so, the result is the same with the memo or
/// without.
struct PocketStart {
  bool set = false;
  double x0 = 0.0, y0 = 0.0, cx0 = 0.0, cy0 = 0.0, angle0 = 0.0, centre_x = 0.0, centre_y = 0.0;
  int pocket = 0, held = 0;
  double energy = 0.0;  ///< [J] Ẽ_k(x₀, ψ₀), E_k with the mouth's band's share, 0 out of it
};
/// A step's ends for the pocket's discrete gradient (Sprocket::discrete_gradient on a pocket
/// wheel): the joint at the step's start x₀ and end x₁ [m], the wheel's centre there [m] (they
/// differ on a take-up's sliding wheel), its angles ψ₀ and ψ₁ [rad], and the θ point's weight.
/// `start`, optional: the caller's memo of the step's start for this joint and wheel, kept over
/// the step's Newton iterations.
struct PocketStep {
  double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;
  double cx0 = 0.0, cy0 = 0.0, cx1 = 0.0, cy1 = 0.0;
  double angle0 = 0.0, angle1 = 0.0;
  double theta = 0.5;
  PocketStart* start = nullptr;
  /// false: a call for the step's residual alone (no Newton matrix): the correction's
  /// derivatives skew_dx, skew_dy, skew_dpsi (the θ point's Hessian) are left 0 and not to be
  /// read; every other field is the same, bit for bit (the θ point's contact keeps its blocks).
  bool jacobian = true;
};
/// pocket_contact at the θ point (x, y, angle, its speeds) over the step `step` (docs/models/
/// dynamics.md, "Pocket wheel: the discrete gradient"). Without Sprocket::discrete_gradient the
/// θ point's contact, bit for bit. With it, the energy Ẽ_k the step takes for the θ point's
/// pocket k (the nearest, or the held one beyond the mouth; the same law at every point: pocket,
/// mouth's ramp, release or body as the point's own place decides): E_k less (1 − φ) of E_k's
/// jump J on the mouth within the mouth's band (c/2 inside it; J with the hold the point gets,
/// 0 for a joint the release holds). Ẽ_k at the step's ends puts the work's miss ΔẼ − ∇E_θ·Δz
/// back along the
/// step z = (q − O, R ψ), metric (1, R²): the skew fields as the seats' (the joint gains −S Δ,
/// the torque −S R² Δψ, S = (ΔẼ − ∇E_θ·Δz − s J)/|Δz|²), so that the elastic work over the
/// step is −(ΔẼ_k − s J). J the signed sum of the jumps of Ẽ_k the step's ends lie across (the
/// body's capture, its shadow in the band, the release's mouth for a joint not held), s(r) a C²
/// step from 0 at r = |J| / (|Δz| k c) = 1 to 1 at r = 2 (the share left to the work balance's
/// numerical term, so that the jump's force stays below 2 k c). Within the band the force is
/// not −∇Ẽ_k: S Δz carries the band's gradient's part along the step alone (docs). Not where
/// |Δz| < 1e-9 R (the θ point's force, −∇E_θ, alone). The damper, friction and the release's hold
/// stay at the θ point; where the θ point's force is 0 (out of contact, or the damper's clamp) its
/// derivative fields are 0 and the contact is active with the correction alone.
SeatContact pocket_step_contact(const Sprocket& w, double x, double y, double vx, double vy,
                                double angle, double speed, int held, const PocketStep& step);
/// At the start and the end of a step (Integrator::step; the same flags for the same state, so
/// the start's call changes nothing after a step, but sets them on a state no step has ended
/// in): a joint within a pocket wheel's mouth (with pocket_release)
/// is held by its nearest pocket; a held joint beyond the mouth is let go when its contact's
/// force is 0 (S(u) = 0 or g ≤ 0). Sizes the state's held arrays if they do not fit.
void update_held(const Model& model, State& s);
/// The pocket a state holds node i in on wheel w (kNoPocket: none).
inline int held_pocket(const State& s, std::size_t i, std::size_t w) {
  return i < s.held_wheel.size() && i < s.held_pocket.size() &&
                 s.held_wheel[i] == static_cast<int>(w)
             ? s.held_pocket[i]
             : kNoPocket;
}

/// The contact of a node with a wheel of either kind, and the distance from the centre beyond
/// which there is none.
inline SeatContact wheel_contact(const Sprocket& w, double x, double y, double vx, double vy,
                                 double angle, double speed, int held = kNoPocket) {
  return w.pocket ? pocket_contact(w, x, y, vx, vy, angle, speed, held)
                  : seat_contact(w, x, y, vx, vy, angle, speed);
}
inline double contact_reach(const Sprocket& w) {
  if (w.pocket) return w.pitch_radius + 0.5 * w.pocket_clearance + w.pocket_mouth;
  return (w.tip_radius > 0.0 ? w.tip_radius : w.pitch_radius) + w.roller_radius;
}

/// The friction of one roller's seat contact (docs/models/dynamics.md, "Seat friction"): with
/// n the contact's normal (SeatContact::nx, ny) and t = (−n_y, n_x), the roller's slip
/// v_t = (v − ω perp(q − c))·t relative to the wheel's material point under its centre, and the
/// force on the roller F = f_t t, f_t = −μ f v_t/√(v_t² + v_ε²) (f the normal force); its
/// reaction −F acts on the wheel at q. Derivatives of F and of the wheel's torque with respect
/// to the roller's position q and velocity v and to the wheel's angle ψ and speed ω, for the
/// Newton matrix (2×2 row-major [[∂Fx/∂qx, ∂Fx/∂qy], [∂Fy/∂qx, ∂Fy/∂qy]]). The normal force's
/// derivatives are the fields' (exact on an ISO seat and within a pocket's mouth) plus the
/// contact's friction_dq and friction_dv (a pocket's mouth ramp and release), so that these are
/// exact on every contact.
struct SeatFriction {
  double friction_force = 0.0;   ///< [N] f_t along t
  double slip = 0.0;             ///< [m/s] v_t
  double power = 0.0;            ///< [W] f_t v_t ≤ 0: on roller and wheel together
  double fx = 0.0, fy = 0.0;     ///< [N] F on the roller
  double torque = 0.0;           ///< [N·m] on the wheel, (q − c) × (−F)
  double dq[4] = {0, 0, 0, 0};   ///< [N/m] ∂F/∂q
  double dv[4] = {0, 0, 0, 0};   ///< [N·s/m] ∂F/∂v
  double dpsi[2] = {0, 0};       ///< [N/rad] ∂F/∂ψ
  double domega[2] = {0, 0};     ///< [N·s/rad] ∂F/∂ω
  double torque_dq[2] = {0, 0};  ///< [N] ∂τ/∂q
  double torque_dv[2] = {0, 0};  ///< [N·s] ∂τ/∂v
  double torque_dpsi = 0.0;      ///< [N·m/rad] ∂τ/∂ψ
  double torque_domega = 0.0;    ///< [N·m·s/rad] ∂τ/∂ω
};
/// The friction of the contact `c` = seat_contact(w, x, y, vx, vy, angle, speed) (zero when it
/// is inactive or carries no force, or w.friction = 0).
SeatFriction seat_friction(const Sprocket& w, const SeatContact& c, double x, double y, double vx,
                           double vy, double speed);

/// [N] the tension of each link, k (l − p) + c l̇ (a tension-only link: link_force's T, ≥ 0)
/// (size links()).
void link_tensions(const Model& model, const State& state, std::span<double> tension);

}  // namespace catena::dynamics
