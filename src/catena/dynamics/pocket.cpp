// The pocket wheel's joint contact (docs/models/dynamics.md, "Pocket wheel").
#include <algorithm>
#include <cmath>
#include <numbers>

#include "catena/dynamics/chain.hpp"
#include "catena/dynamics/pocket_wheel.hpp"
#include "catena/pocketwheel/geometry.hpp"

namespace catena::dynamics {

Sprocket pocket_wheel(double pitch, double wire, int teeth, double centre_x, double centre_y,
                      double clearance, double contact_stiffness, double contact_damping) {
  const pocketwheel::WheelGeometry g =
      pocketwheel::wheel_geometry({.pitch = pitch, .wire = wire, .teeth = teeth});
  Sprocket s;
  s.pocket = true;
  s.centre_x = centre_x;
  s.centre_y = centre_y;
  s.teeth = teeth;
  s.pitch_radius = g.pitch_radius;
  s.pocket_angle = g.delta1;
  s.pocket_clearance = clearance;
  s.contact_stiffness = contact_stiffness;
  s.contact_damping = contact_damping;
  s.contact_smoothing = std::min(s.contact_smoothing, clearance);
  return s;
}

PocketVertex nearest_pocket(const Sprocket& w, double polar, double angle) {
  // Within one tooth period [ψ + mτ, ψ + (m + 1)τ) the vertices are at 0, δ1 and τ; the nearest
  // is decided by the two mid-angles δ1/2 and δ1 + δ2/2.
  const double tau = 2.0 * std::numbers::pi / w.teeth;
  const double d1 = w.pocket_angle, d2 = tau - d1;
  const double m = std::floor((polar - angle) / tau);
  const double b = polar - angle - m * tau;
  const int k = 2 * static_cast<int>(m);
  if (b < 0.5 * d1) return {k, angle + m * tau};
  if (b < d1 + 0.5 * d2) return {k + 1, angle + m * tau + d1};
  return {k + 2, angle + (m + 1.0) * tau};
}

namespace {
// The C² step s = x³(10 − 15x + 6x²), x = (t − a)/(b − a) clamped to [0, 1], with its
// derivatives in t.
struct Step {
  double s = 0.0, ds = 0.0, dds = 0.0;
};
Step smooth_step(double t, double a, double b) {
  const double l = b - a, x = std::clamp((t - a) / l, 0.0, 1.0);
  return {x * x * x * (10.0 - 15.0 * x + 6.0 * x * x), 30.0 * x * x * (1.0 - x) * (1.0 - x) / l,
          60.0 * x * (1.0 - x) * (1.0 - 2.0 * x) / (l * l)};
}
}  // namespace

namespace {
// What an evaluation of the contact sets: its energy and `active` alone (the discrete gradient's
// step start), with the elastic force's size, direction and torque (its end), with its ∂F/∂q as
// well (stiffness, curvature, dq_extra: the θ point's elastic contact), or everything (depth,
// dv_extra and the friction's blocks too). The fields a mode names are the same numbers as kAll's;
// the others it may leave half done, not to be read.
enum class Need { kEnergy, kForce, kJacobian, kAll };

// The pocket's elastic law at the gap g > 0: the seats' penalty with its ramp (force, slope,
// energy)
LineForce elastic(const Sprocket& w, double g) {
  return detail::penalty_ramp(w.contact_stiffness, w.contact_smoothing, g);
}

// Its inverse, the gap whose elastic force is fe ≥ 0: the depth a contact reports for a force
// that is not one gap's (the mouth's ramp, the release)
double elastic_depth(const Sprocket& w, double fe) {
  const double eps = w.contact_smoothing, kc = w.contact_stiffness;
  return fe < 0.5 * kc * eps ? std::sqrt(2.0 * eps * fe / kc) : fe / kc + 0.5 * eps;
}

// The contact's friction_dq and friction_dv (SeatContact) from the exact Jacobians jq = ∂F/∂q
// and jv = ∂F/∂v of its force F = −f n on the joint, with the velocity w = v − ω perp(q − O)
// relative to the wheel: what seat_friction does not read from the fields.
void set_friction_rest(const double jq[4], const double jv[4], double wx, double wy, double speed,
                       SeatContact& c) {
  const double m[2] = {c.nx, c.ny}, t[2] = {-c.ny, c.nx};
  const double turn = c.damping * (speed + c.curvature * (wx * t[0] + wy * t[1]));
  const double fk = c.force * c.curvature;
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      const double fields = -m[i] * (c.stiffness * m[j] + turn * t[j]) - fk * t[i] * t[j];
      c.friction_dq[2 * i + j] = jq[2 * i + j] - fields;
      c.friction_dv[2 * i + j] = jv[2 * i + j] + c.damping * m[i] * m[j];
    }
  }
}

// The ∂F/∂q (row-major) the contact's fields give, −[k m mᵀ + f κ (I − m mᵀ)], from the normal
// stiffness `kn`, ft = f κ and the force's direction m: what dq_extra adds to
void fields_jacobian(double kn, double ft, double mx, double my, double out[4]) {
  out[0] = -(kn * mx * mx + ft * (1 - mx * mx));
  out[1] = out[2] = -(kn - ft) * mx * my;
  out[3] = -(kn * my * my + ft * (1 - my * my));
}

// The angle of pocket vertex k (even k: ψ + (k/2) τ; odd: ψ + ((k − 1)/2) τ + δ1).
double vertex_angle(const Sprocket& w, int k, double angle) {
  const double tau = 2.0 * std::numbers::pi / w.teeth;
  const int m = k >= 0 ? k / 2 : -((1 - k) / 2);  // floor(k/2)
  return angle + m * tau + (k - 2 * m == 1 ? w.pocket_angle : 0.0);
}

// The release law (Sprocket::pocket_release) on a contact whose seat, normal n = e/|e| and
// curvature are set: energy E₀(g) S(u), u = e·r̂/|e|, S falling from 1 at u₁ to 0 at u₀.
// F = −S f₀ n − E₀ S′ ∇u, ∇u = (r̂ − u n)/|e| + (n − u r̂)/ρ. The torque is −∂E/∂ψ through the
// vertex C(ψ) only.
void apply_release(const Sprocket& w, double g, double dist, double rx, double ry, double vx,
                   double vy, double speed, Need need, SeatContact& c) {
  const double rho = std::hypot(rx, ry);
  const double nx = c.nx, ny = c.ny, ux = rx / rho, uy = ry / rho;
  const double u = nx * ux + ny * uy;
  const ReleaseBand band = release_band(w);
  const Step st = smooth_step(u, band.full, band.none);
  const double sv = 1.0 - st.s, s1 = -st.ds, s2 = -st.dds;
  if (!(sv > 0.0)) return;  // inactive
  apply_seat_law(w, g, rx, ry, vx, vy, speed, c);
  if (need == Need::kEnergy) {
    c.energy *= sv;
    return;
  }
  const double fel = elastic(w, g).force;
  // the seats' law's f₀ = max(0, f_el + c(g) ġ), ∂f₀/∂g and c(g) (all 0 where f₀ is clamped)
  const double e0 = c.energy, f0 = c.force, kf = c.stiffness, cf = c.damping;
  const double gu[2] = {(ux - u * nx) / dist + (nx - u * ux) / rho,
                        (uy - u * ny) / dist + (ny - u * uy) / rho};
  const double ge[2] = {(ux - u * nx) / dist, (uy - u * ny) / dist};  // through e only
  const double a = sv * f0, b = e0 * s1;                              // F = −a n − b ∇u
  const double fx = -a * nx - b * gu[0], fy = -a * ny - b * gu[1];
  const double len = std::hypot(fx, fy);
  c.energy = e0 * sv;
  c.damping_power *= sv;
  c.damping *= sv;
  c.stiffness *= sv;
  // −∂E/∂ψ = −F_e·∂C/∂ψ, F_e = −a n − b ∇_e u, ∂C/∂ψ = ẑ × (C − O)
  const double fex = -a * nx - b * ge[0], fey = -a * ny - b * ge[1];
  const double cx = c.seat_x - w.centre_x, cy = c.seat_y - w.centre_y;
  c.torque = -(fex * -cy + fey * cx);
  if (!(len > 0.0)) {
    c.force = c.depth = 0.0;
    c.stiffness = c.damping = 0.0;
    return;
  }
  c.nx = -fx / len;
  c.ny = -fy / len;
  c.force = len;
  if (need == Need::kForce) return;
  if (need == Need::kAll) {  // the depth reported: the seats' law's depth for the elastic force
    const double ae = sv * fel;
    c.depth = elastic_depth(w, std::hypot(ae * nx + b * gu[0], ae * ny + b * gu[1]));
  }
  // The exact ∂F/∂q and ∂F/∂v, the damper's share included, less the blocks the fields give
  // (dq_extra, dv_extra): F = −A n − B ∇u, A = S f₀, B = E₀ S′, with f₀ = f_el + c(g) ġ unclamped
  // (else A = 0 and its derivatives 0, which kf = cf = f₀ = 0 give);
  // ∇A = S (∂f₀/∂g n + c ∇ġ) + f₀ S′ ∇u, ∂A/∂v = S c n, ∇ġ = P_n v_rel/|e| + ω (−n_y, n_x)
  // (v_rel = v − ω ẑ × r); ∇B = f_el S′ n + E₀ S″ ∇u; ∂n/∂q = P_n/|e|, ∂r̂/∂q = P_r/ρ,
  // ∂|e|/∂q = nᵀ, ∂ρ/∂q = r̂ᵀ. (Without the damper's share the Newton matrix was wrong by
  // c ∂ġ/∂g-type terms wherever ġ ≠ 0 and Newton stalled: docs/models/dynamics.md, "Pocket
  // wheel: unwinding".)
  const double A = sv * f0, B = e0 * s1;
  const double n[2] = {nx, ny}, r[2] = {ux, uy};
  const double wx = vx + speed * ry, wy = vy - speed * rx;  // v_rel
  const double wn = wx * nx + wy * ny;
  const double dgq[2] = {(wx - wn * nx) / dist - speed * ny, (wy - wn * ny) / dist + speed * nx};
  const double dA[2] = {sv * (kf * nx + cf * dgq[0]) + f0 * s1 * gu[0],
                        sv * (kf * ny + cf * dgq[1]) + f0 * s1 * gu[1]};
  const double dB[2] = {fel * s1 * nx + e0 * s2 * gu[0], fel * s1 * ny + e0 * s2 * gu[1]};
  const double t1[2] = {ux - u * nx, uy - u * ny}, t2[2] = {nx - u * ux, ny - u * uy};
  double exact[4];
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      const double id = i == j ? 1.0 : 0.0;
      const double pn = id - n[i] * n[j], pr = id - r[i] * r[j];
      // ∂(∇u)_i/∂q_j
      const double dgu =
          (pr / rho - n[i] * gu[j] - u * pn / dist) / dist - t1[i] * n[j] / (dist * dist) +
          (pn / dist - r[i] * gu[j] - u * pr / rho) / rho - t2[i] * r[j] / (rho * rho);
      exact[2 * i + j] = -n[i] * dA[j] - A * pn / dist - gu[i] * dB[j] - B * dgu;
    }
  }
  const double mx = c.nx, my = c.ny;
  double fields[4];
  fields_jacobian(c.stiffness, c.force * c.curvature, mx, my, fields);
  for (int i = 0; i < 4; ++i) c.dq_extra[i] = exact[i] - fields[i];
  if (need == Need::kJacobian) return;
  // ∂F/∂v = −S c n nᵀ; the fields give −(S c) m mᵀ, m the force's direction
  const double cn = sv * cf;
  const double m[2] = {mx, my};
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) c.dv_extra[2 * i + j] = -cn * (n[i] * n[j] - m[i] * m[j]);
  // for the friction: exact is the whole ∂F/∂q, ∂F/∂v = −S c n nᵀ
  const double jv[4] = {-cn * nx * nx, -cn * nx * ny, -cn * ny * nx, -cn * ny * ny};
  set_friction_rest(exact, jv, wx, wy, speed, c);
}
}  // namespace

namespace {
// The body's capture: a joint within the mouth and within `from` of its nearest vertex is that
// pocket's; from `from` to `to` = 2 from the pocket's depth blends into the rim's; beyond, the rim
// alone (docs/models/dynamics.md, "Pocket wheel: the body between the pockets": 10c, twice the
// 4.9c of the deepest joint measured in a test's run, a slack span landing off its vertex, and far
// below the 170–240c of the joints thrown back between the pockets). `to` is at most 0.45 of the
// smallest vertex spacing s (the nearest vertex switches at s/2: the blend ends before it). Within
// `band` = from of the mouth the blend is weighted radially too, so that the depth is the rim's
// on the mouth and the energy 0 there, as beyond it.
constexpr double kCaptureFrom = 10.0, kCaptureTo = 20.0, kSpacingShare = 0.45;
struct Capture {
  double from = 0.0, to = 0.0, band = 0.0;
};
Capture body_capture(const Sprocket& w) {
  const double tau = 2.0 * std::numbers::pi / w.teeth;
  const double spacing =
      2.0 * w.pitch_radius * std::sin(0.5 * std::min(w.pocket_angle, tau - w.pocket_angle));
  const double share = kSpacingShare * spacing;
  const double from =
      std::min(kCaptureFrom * w.pocket_clearance, share * (kCaptureFrom / kCaptureTo));
  return {from, std::min(kCaptureTo * w.pocket_clearance, share), from};
}

// `cap` the wheel's body_capture when the caller has it (else computed here, only with the body)
bool in_body(const Sprocket& w, const Capture* cap, double dist) {
  return w.pocket_body && dist > (cap != nullptr ? cap->from : body_capture(w).from);
}

// The body between the pockets on a contact whose seat and n = e/|e| are set, the joint within
// the mouth M = R + c/2 and more than `from` from its vertex: the seats' law on the depth
// d = h + W (g − h), g = |e| − c the pocket's, h = M − ρ the rim's, W = P Q the pocket's share,
// P = 1 − B, B the C² step in |e| from 0 at `from` to 1 at `to`, Q the C² step in h from 0 on the
// mouth to 1 at `band` within it (d = h on the mouth: the energy ends at 0 there).
// F = −f ∇d, ∇d = −r̂ + W (n + r̂) + (g − h) ∇W, ∇W = Q P′ n − P Q′ r̂, f = f_el(d) + c(d) ∇d·v_rel
// (never pulling); the torque f (r × ∇d) (the rim's part has no moment). The fields carry the
// force's direction and size; stiffness, damping and curvature are 0 and the exact ∂F/∂q and
// ∂F/∂v are dq_extra and dv_extra. surface = 3; its seat friction is the pocket's times P
// (friction_weight).
void apply_body(const Sprocket& w, const Capture& cap, double dist, double rx, double ry, double vx,
                double vy, double speed, Need need, SeatContact& c) {
  const double cl = w.pocket_clearance, rho = std::hypot(rx, ry);
  const double g = dist - cl, h = w.pitch_radius + 0.5 * cl - rho, dd = g - h;
  const Step b = smooth_step(dist, cap.from, cap.to);
  const Step q = smooth_step(h, 0.0, cap.band);
  const double p = 1.0 - b.s, p1 = -b.ds, p2 = -b.dds;  // P and its derivatives in |e|
  const double wt = p * q.s;
  const double d = h + wt * dd;
  const double n[2] = {c.nx, c.ny}, u[2] = {rx / rho, ry / rho};
  const double wn = q.s * p1, wr = -p * q.ds;  // ∇W = wn n + wr r̂
  const double grad[2] = {-u[0] + wt * (n[0] + u[0]) + dd * (wn * n[0] + wr * u[0]),
                          -u[1] + wt * (n[1] + u[1]) + dd * (wn * n[1] + wr * u[1])};
  const double len = std::hypot(grad[0], grad[1]);
  if (!(d > 0.0) || !(len > 0.0)) {
    c = SeatContact{};
    return;
  }
  c.nx = grad[0] / len;
  c.ny = grad[1] / len;
  // the law along m = ∇d/|∇d| with the velocities scaled by |∇d|: its rate is ∇d·v_rel = ḋ
  apply_seat_law(w, d, rx, ry, len * vx, len * vy, len * speed, c);
  if (need == Need::kEnergy) return;
  const double f = c.force, kf = c.stiffness, cf = c.damping;
  if (need != Need::kForce) {  // the exact ∂F/∂q and ∂F/∂v
    // the Hessian of d: ∇∇h = −P_r/ρ, ∇∇(g − h) = P_n/|e| + P_r/ρ, and
    // ∇∇W = Q P″ n nᵀ + Q P′ P_n/|e| − P′ Q′ (n r̂ᵀ + r̂ nᵀ) + P Q″ r̂ r̂ᵀ − P Q′ P_r/ρ
    double hess[4];
    for (int i = 0; i < 2; ++i) {
      for (int j = 0; j < 2; ++j) {
        const double id = i == j ? 1.0 : 0.0;
        const double pn = (id - n[i] * n[j]) / dist, pr = (id - u[i] * u[j]) / rho;
        const double gw[2] = {wn * n[i] + wr * u[i], wn * n[j] + wr * u[j]};  // ∇W_i, ∇W_j
        const double hw = q.s * p2 * n[i] * n[j] + q.s * p1 * pn -
                          p1 * q.ds * (n[i] * u[j] + u[i] * n[j]) + p * q.dds * u[i] * u[j] -
                          p * q.ds * pr;
        hess[2 * i + j] =
            -pr + wt * (pn + pr) + (n[i] + u[i]) * gw[1] + gw[0] * (n[j] + u[j]) + dd * hw;
      }
    }
    // ∂ḋ/∂q = ∇∇d v_rel + (∂v_rel/∂q)ᵀ ∇d, v_rel = v − ω ẑ × r, ∂v_rel/∂q = ω [[0, 1], [−1, 0]]
    const double wx = vx + speed * ry, wy = vy - speed * rx;
    const double rate_q[2] = {hess[0] * wx + hess[2] * wy - speed * grad[1],
                              hess[1] * wx + hess[3] * wy + speed * grad[0]};
    for (int i = 0; i < 2; ++i) {
      for (int j = 0; j < 2; ++j) {
        c.dq_extra[2 * i + j] = -grad[i] * (kf * grad[j] + cf * rate_q[j]) - f * hess[2 * i + j];
        c.dv_extra[2 * i + j] = -cf * grad[i] * grad[j];
      }
    }
  }
  c.force = f * len;
  c.torque = f * (rx * grad[1] - ry * grad[0]);
  c.penetration = d;
  c.depth = d;
  c.stiffness = c.damping = c.curvature = 0.0;
  c.surface = 3;
  if (need != Need::kAll) return;
  // The pocket's friction, faded with P (the pocket's share along |e|, the blend's own weight): on
  // this contact's force and along its surface (seat_friction's n = ∇d/|∇d|), so that at `from`,
  // where d = g and ∇d = n (away from the mouth), it is the pocket's friction; 0 from `to` on.
  // With the fields 0 the normal force's whole exact Jacobians are the friction's rest.
  c.friction_weight = p;
  c.friction_weight_dq[0] = p1 * n[0];  // ∇P = P′ ∇|e|
  c.friction_weight_dq[1] = p1 * n[1];
  std::copy(c.dq_extra, c.dq_extra + 4, c.friction_dq);
  std::copy(c.dv_extra, c.dv_extra + 4, c.friction_dv);
}

// The point of pocket vertex `angle` on the pitch circle.
void vertex_point(const Sprocket& w, double angle, double& x, double& y) {
  x = w.centre_x + w.pitch_radius * std::cos(angle);
  y = w.centre_y + w.pitch_radius * std::sin(angle);
}
}  // namespace

ReleaseBand release_band(const Sprocket& w) {
  constexpr double kDeg = std::numbers::pi / 180.0;
  return {std::sin(0.5 * w.pocket_angle + 5.0 * kDeg),
          std::sin(0.5 * w.pocket_angle + 35.0 * kDeg)};
}

namespace {
// A point about the wheel: r = q − O, ρ² = |r|² and whether it is beyond the reach
struct Where {
  double rx = 0.0, ry = 0.0, rho2 = 0.0;
  bool beyond = false;
};
Where where_rel(const Sprocket& w, double rx, double ry) {
  const double reach = contact_reach(w);  // the mouth R + c/2, or its ramp's top
  const double rho2 = rx * rx + ry * ry;
  return {rx, ry, rho2, rho2 > reach * reach};
}
Where where(const Sprocket& w, double x, double y) {
  return where_rel(w, x - w.centre_x, y - w.centre_y);
}

// Whether a point `p` is out of every pocket's reach: beyond it and not held there
bool free_of(const Sprocket& w, const Where& p, int held) {
  return p.beyond && !(w.pocket_release && held != kNoPocket);
}

// Whether a point `p` is within the mouth R + c/2 as the pocket's law takes it (contact_at: within
// the reach by ρ², and with the mouth's ramp by ρ within the mouth): the band's side (band_at)
// decided by the same rounding, so that a point on the mouth has one side for both
bool within_mouth(const Sprocket& w, const Where& p) {
  return !p.beyond && (!(w.pocket_mouth > 0.0) ||
                       std::sqrt(p.rho2) <= w.pitch_radius + 0.5 * w.pocket_clearance);
}

// The contact of (x, y) at `p` (not free_of the wheel) with pocket `index` whose vertex is
// (sx, sy): what `need` asks; `cap` the wheel's body_capture if the caller has it, else nullptr.
// Inlined: a call of its own cost pocket_contact 1.7 % more instructions on the example.
[[gnu::always_inline]] inline SeatContact contact_at(const Sprocket& w, double x, double y,
                                                     double vx, double vy, double speed,
                                                     const Where& p, int index, double sx,
                                                     double sy, const Capture* cap, Need need) {
  SeatContact c;
  const double rx = p.rx, ry = p.ry, rho2 = p.rho2;
  const bool beyond = p.beyond;
  c.seat = index;
  c.seat_x = sx;
  c.seat_y = sy;
  const double ex = x - c.seat_x, ey = y - c.seat_y;
  const double dist = std::sqrt(ex * ex + ey * ey);
  const double g = dist - w.pocket_clearance;
  if (!(g > 0.0)) return c;
  const double nx = ex / dist, ny = ey / dist;
  c.nx = nx;
  c.ny = ny;
  c.curvature = 1.0 / dist;
  const double mouth = w.pitch_radius + 0.5 * w.pocket_clearance;
  if (!beyond && in_body(w, cap, dist)) {  // between the pockets, within the mouth: the body
    if (rho2 <= mouth * mouth)
      apply_body(w, cap != nullptr ? *cap : body_capture(w), dist, rx, ry, vx, vy, speed, need, c);
    else
      c = SeatContact{};  // over a ramp (its W is 0 from 3c on)
    return c;
  }
  if (w.pocket_release) {
    apply_release(w, g, dist, rx, ry, vx, vy, speed, need, c);
    return c;
  }
  if (within_mouth(w, p)) {                          // within the mouth: the pocket as it was
    apply_seat_law(w, g, rx, ry, vx, vy, speed, c);  // the seats' force law
    return c;
  }
  // The mouth's ramp, R + c/2 < ρ < R + c/2 + w: the energy E₀(g) W(g) s(h), h = R + c/2 + w − ρ,
  // s the C² step from 0 at the ramp's top to 1 at the mouth, W the C² step from 1 at g ≤ c to 0
  // at g ≥ 2c (a joint more than 3c from its vertex is not held over the mouth: bounded forces).
  // With Φ = E₀ W (Φ' = f_el W + E₀ W'), ∇g = n, ∇h = −r̂: F = −[s (Φ' + damping)] n + Φ s' r̂.
  const double cl = w.pocket_clearance, rho = std::sqrt(rho2);
  const Step ws = smooth_step(g, cl, 2.0 * cl);
  const double wg = 1.0 - ws.s, dwg = -ws.ds, ddwg = -ws.dds;
  if (!(wg > 0.0)) return c;
  const Step ss = smooth_step(contact_reach(w) - rho, 0.0, w.pocket_mouth);
  if (!(ss.s > 0.0)) return c;
  apply_seat_law(w, g, rx, ry, vx, vy, speed, c);  // f₀ = f_el + c ġ ≥ 0, E₀, …
  const double k0 = c.stiffness, c0 = c.damping;  // ∂f₀/∂g and c(g) (0 where f₀ is clamped)
  const LineForce el = elastic(w, g);
  const double fel = el.force, kel = el.stiffness;
  const double e0 = c.energy, f0 = c.force;
  const double phi = e0 * wg;
  if (need == Need::kEnergy) {
    c.energy = phi * ss.s;
    return c;
  }
  const double dphi = fel * wg + e0 * dwg;
  const double ddphi = kel * wg + 2.0 * fel * dwg + e0 * ddwg;
  const double along = ss.s * (wg * f0 + e0 * dwg);  // A: the force −A n
  const double radial = phi * ss.ds;                 // B: the force +B r̂
  const double ux = rx / rho, uy = ry / rho;
  const double vxn = along * nx - radial * ux, vyn = along * ny - radial * uy;  // F = −V
  const double len = std::hypot(vxn, vyn);
  c.energy = phi * ss.s;
  c.damping_power *= ss.s * wg;
  c.torque = along * (rx * ny - ry * nx);  // the radial part has no moment
  c.damping *= ss.s * wg;
  c.stiffness *= ss.s * wg;
  if (!(len > 0.0)) {
    c.force = c.depth = 0.0;
    c.stiffness = c.damping = 0.0;
    return c;
  }
  c.nx = vxn / len;
  c.ny = vyn / len;
  c.force = len;
  if (need == Need::kForce) return c;
  if (need == Need::kAll) {
    // the depth reported (max_penetration): the seats' law's depth for the ramp's elastic force
    // |F_el| (the same vector with the damping left out) — g reaches 2c over the ramp, where the
    // force is nearly 0
    const double ael = ss.s * (wg * fel + e0 * dwg);
    c.depth = elastic_depth(w, std::hypot(ael * nx - radial * ux, ael * ny - radial * uy));
  }
  // the exact elastic ∂F/∂q = −Φ'' s n nᵀ + Φ' s' (n r̂ᵀ + r̂ nᵀ) − Φ' s P_n/|e| − Φ s'' r̂ r̂ᵀ
  // + Φ s' P_r/ρ, less the block the fields give
  const double s0 = ss.s, s1 = ss.ds, s2 = ss.dds, pe = dphi * s0 / dist, pr = phi * s1 / rho;
  const double n[2] = {nx, ny}, u[2] = {ux, uy};
  double exact[4];
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      const double id = i == j ? 1.0 : 0.0;
      exact[2 * i + j] = -ddphi * s0 * n[i] * n[j] + dphi * s1 * (n[i] * u[j] + u[i] * n[j]) -
                         pe * (id - n[i] * n[j]) - phi * s2 * u[i] * u[j] + pr * (id - u[i] * u[j]);
    }
  }
  double fields[4];
  fields_jacobian(c.stiffness, c.force * c.curvature, c.nx, c.ny, fields);
  for (int i = 0; i < 4; ++i) c.dq_extra[i] = exact[i] - fields[i];
  if (need == Need::kJacobian) return c;
  // For the friction, the whole ∂F/∂q: `exact` is the elastic part, with the force's A = s Φ';
  // the actual A = s (W f₀ + E₀ W') differs by Q = s W (f₀ − f_el) (the damper's c ġ, or −f_el
  // where the damper's pull clamps f₀ at 0), whose share is −n ∇Qᵀ − Q P_n/|e|, with
  // ∇Q = −s' W (f₀ − f_el) r̂ + s W' (f₀ − f_el) n + s W (∇f₀ − k_el n),
  // ∇f₀ = ∂f₀/∂g n + c ∇ġ, ∇ġ = (ω + v_rel·t/|e|) t, t = perp(n); ∂F/∂v = −s W c n nᵀ.
  const double wx = vx + speed * ry, wy = vy - speed * rx;  // v_rel
  const double te[2] = {-ny, nx};
  const double dgt = speed + (wx * te[0] + wy * te[1]) / dist;  // ∇ġ = dgt t
  const double extra = f0 - fel, q = s0 * wg * extra;
  double jq[4], jv[4];
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      const double id = i == j ? 1.0 : 0.0;
      const double dq = -s1 * wg * extra * u[j] + s0 * dwg * extra * n[j] +
                        s0 * wg * ((k0 - kel) * n[j] + c0 * dgt * te[j]);
      jq[2 * i + j] = exact[2 * i + j] - n[i] * dq - q * (id - n[i] * n[j]) / dist;
      jv[2 * i + j] = -s0 * wg * c0 * n[i] * n[j];
    }
  }
  set_friction_rest(jq, jv, wx, wy, speed, c);
  return c;
}

// pocket_contact: the nearest pocket within the mouth, the held one beyond it; `cap` as
// contact_at's
SeatContact contact_with(const Sprocket& w, double x, double y, double vx, double vy, double angle,
                         double speed, int held, const Capture* cap) {
  const Where p = where(w, x, y);
  if (free_of(w, p, held)) return SeatContact{};
  const int fixed = p.beyond ? held : kNoPocket;
  const PocketVertex v = fixed != kNoPocket ? PocketVertex{fixed, vertex_angle(w, fixed, angle)}
                                            : nearest_pocket(w, std::atan2(p.ry, p.rx), angle);
  double sx = 0.0, sy = 0.0;
  vertex_point(w, v.angle, sx, sy);
  return contact_at(w, x, y, vx, vy, speed, p, v.index, sx, sy, cap, Need::kAll);
}
}  // namespace

SeatContact pocket_contact(const Sprocket& w, double x, double y, double vx, double vy,
                           double angle, double speed, int held) {
  return contact_with(w, x, y, vx, vy, angle, speed, held, nullptr);
}

// The pocket's discrete gradient (docs/models/dynamics.md, "Pocket wheel: the discrete
// gradient"), a block of its own: the θ point's contact, and the elastic energy E_k of its pocket
// k at the step's ends (Ẽ_k, the mouth's jump spread over its band), put back along the step
// z = (q − O, R ψ) in the metric (1, R²).
namespace {
// A step's end q (relative to the wheel's centre there, put about w's centre) for pocket k
// (held: hk ≠ kNoPocket) with the wheel at `angle`: the point, where it is, whether it is free of
// the wheel and pocket k's vertex there (read only where its contact reads it)
struct End {
  double x = 0.0, y = 0.0;
  Where at;
  bool free = true;
  double sx = 0.0, sy = 0.0;
};
End end_of(const Sprocket& w, double qx, double qy, double angle, int k, int hk) {
  End e;
  e.x = qx + w.centre_x;
  e.y = qy + w.centre_y;
  e.at = where(w, e.x, e.y);
  e.free = free_of(w, e.at, hk);
  if (!e.free) vertex_point(w, vertex_angle(w, k, angle), e.sx, e.sy);
  return e;
}

// The mouth's jump spread over a band (docs/models/dynamics.md, "Pocket wheel: the discrete
// gradient", "The mouth's band"): the energy the step takes at a point is Ẽ_k = E_k + B,
// B = −(1 − φ) J within ℓ = c/2 inside the mouth ρ = R + c/2, φ the C² step from 0 on the mouth to
// 1 at depth ℓ (the pitch circle), J = E_k's jump on the mouth on the point's radial ray (each side
// 1e-9 c off, carried to the mouth along its radial slope): Ẽ_k is E_k's outer side's on the
// mouth, so it has no jump there, and E_k itself from ℓ in. J is taken with the hold the point
// gets (update_held): with the release, a point within the mouth and off the body is held by
// pocket k, so J = 0 there and a joint's entry is a jump crossed on the mouth (crossed_jump).
// B's gradient, ∇_q B = −φ′ J q/ρ − (1 − φ) ∇_q J and ∂B/∂ψ = −(1 − φ) ∂J/∂ψ, with J's from the
// two sides' forces and torques: ∇_q J = (M/ρ)(I − q̂q̂ᵀ)(f n|in − f n|out), ∂J/∂ψ = −(τ_in − τ_out)
// (the carry's own slope, O(1e-9 c), not taken). 0 outside the band.
struct Band {
  double e = 0.0, gx = 0.0, gy = 0.0, gpsi = 0.0;
};
Band band_at(const Sprocket& w, const Capture& cap, double qx, double qy, double angle, int k,
             int hk) {
  const double mouth = w.pitch_radius + 0.5 * w.pocket_clearance, band = 0.5 * w.pocket_clearance;
  const double rho = std::hypot(qx, qy);
  // within the mouth as the point's contact takes it (its ρ² about the wheel's centre, end_of's):
  // with ρ's own rounding a point on the mouth that the contact puts beyond it (E = 0) took
  // Ẽ = −J, J off its neighbours (up to 37 J 9.8c off the vertex). ρ, within rounding of the
  // contact's, first decides the points 1e-9 c or more beyond the mouth (most of the calls)
  if (!(rho > mouth - band && rho <= mouth + 1e-9 * w.pocket_clearance)) return {};
  if (!within_mouth(w, where(w, qx + w.centre_x, qy + w.centre_y))) return {};
  int hold = hk;
  if (w.pocket_release) {
    const End at = end_of(w, qx, qy, angle, k, k);
    double vx = 0.0, vy = 0.0;
    vertex_point(w, vertex_angle(w, k, angle), vx, vy);
    if (!in_body(w, &cap, std::hypot(at.x - vx, at.y - vy))) hold = k;
  }
  const double ux = qx / rho, uy = qy / rho, del = 1e-9 * w.pocket_clearance;
  // each side's E carried to the mouth (as jump_on does), and its ∇_q E = f n, ∂E/∂ψ = −τ
  auto side = [&](double at) {
    const End e = end_of(w, ux * at, uy * at, angle, k, hold);
    if (e.free) return Band{};
    const SeatContact c =
        contact_at(w, e.x, e.y, 0.0, 0.0, 0.0, e.at, k, e.sx, e.sy, &cap, Need::kForce);
    if (!c.active) return Band{};
    return Band{c.energy + (mouth - at) * c.force * (c.nx * ux + c.ny * uy), c.force * c.nx,
                c.force * c.ny, -c.torque};
  };
  const Band in = side(mouth - del), out = side(mouth + del);
  const double jump = in.e - out.e, dgx = in.gx - out.gx, dgy = in.gy - out.gy;
  // no jump within the sides' own error, O(k del²) and their rounding (one law on both sides: a
  // held joint's release, the body, whose energy is 0 on the mouth)
  const double floor = 4.0 * w.contact_stiffness * del * del;
  if (!(std::abs(jump) > std::max(1e-9 * (std::abs(in.e) + std::abs(out.e)), floor))) return {};
  const double along = ux * dgx + uy * dgy, scale = mouth / rho;
  const Step phi = smooth_step(mouth - rho, 0.0, band);
  const double keep = 1.0 - phi.s;
  const double jx = scale * (dgx - along * ux), jy = scale * (dgy - along * uy);
  return {-keep * jump, -phi.ds * jump * ux - keep * jx, -phi.ds * jump * uy - keep * jy,
          -keep * (in.gpsi - out.gpsi)};
}

// Ẽ_k at an end q: E_k (the contact at zero velocity, 0 free of the wheel) and B
double banded_energy(const Sprocket& w, const Capture& cap, double qx, double qy, double angle,
                     int k, int hk) {
  const End e = end_of(w, qx, qy, angle, k, hk);
  double en = 0.0;
  if (!e.free) {
    const SeatContact c =
        contact_at(w, e.x, e.y, 0.0, 0.0, 0.0, e.at, k, e.sx, e.sy, &cap, Need::kEnergy);
    if (c.active) en = c.energy;
  }
  return en + band_at(w, cap, qx, qy, angle, k, hk).e;
}

// The step's start for pocket k (held: hk ≠ kNoPocket) from the memo `m`, taken afresh there
// unless it holds this start, wheel's centre, pocket and hold: its energy Ẽ_k. The start does not
// move within a step, so the integrator's Newton iterations take it once a step, unless the θ
// point's pocket changes.
const PocketStart& step_start(const Sprocket& w, const Capture& cap, const PocketStep& step, int k,
                              int hk, PocketStart& m) {
  using detail::same_bits;
  if (m.set && m.pocket == k && m.held == hk && same_bits(m.x0, step.x0) &&
      same_bits(m.y0, step.y0) && same_bits(m.cx0, step.cx0) && same_bits(m.cy0, step.cy0) &&
      same_bits(m.angle0, step.angle0) && same_bits(m.centre_x, w.centre_x) &&
      same_bits(m.centre_y, w.centre_y))
    return m;
  m = PocketStart{.set = true,
                  .x0 = step.x0,
                  .y0 = step.y0,
                  .cx0 = step.cx0,
                  .cy0 = step.cy0,
                  .angle0 = step.angle0,
                  .centre_x = w.centre_x,
                  .centre_y = w.centre_y,
                  .pocket = k,
                  .held = hk};
  m.energy = banded_energy(w, cap, step.x0 - step.cx0, step.y0 - step.cy0, step.angle0, k, hk);
  return m;
}

// E_k's jumps (docs/models/dynamics.md, "Pocket wheel: the discrete gradient", "The jumps") lie
// on two surfaces: the mouth's circle ρ = R + c/2 (the sharp mouth's E₀(g) against 0, the
// release's E₀(g) S(u) for a joint not held, the ramp's leftover E₀(g) (1 − W(g)); 0 within
// about 0.87c of the vertex, where g ≤ 0 on the mouth), spread over the mouth's band in the
// energy the step takes (Ẽ_k, above), and, with the body, the capture |q − C_k| = `from` (the
// pocket's law against the body's blended depth: 0 beyond the body's radial band of the mouth). The
// step's path in (q − O, ψ) is the straight one, q(t) = q₀ + t Δq, ψ(t) = ψ₀ + t Δψ, its θ point at
// t = θ.
struct Path {
  double q0x = 0.0, q0y = 0.0, dx = 0.0, dy = 0.0, psi0 = 0.0, dpsi = 0.0, theta = 0.5;
};

// Ẽ_k (E_k beyond the mouth's band) and its rate at the path's point t: the contact at zero
// velocity, whose elastic force gives ∇_q E = f n and whose torque ∂E/∂ψ = −τ (0 free of the wheel)
struct Slope {
  double e = 0.0, de = 0.0;
};
Slope slope_along(const Sprocket& w, const Capture& cap, const Path& p, double t, int k, int hk) {
  const double qx = p.q0x + t * p.dx, qy = p.q0y + t * p.dy, psi = p.psi0 + t * p.dpsi;
  const End e = end_of(w, qx, qy, psi, k, hk);
  Slope out;
  if (!e.free) {
    const SeatContact c =
        contact_at(w, e.x, e.y, 0.0, 0.0, 0.0, e.at, k, e.sx, e.sy, &cap, Need::kForce);
    if (c.active) out = {c.energy, c.force * (c.nx * p.dx + c.ny * p.dy) - c.torque * p.dpsi};
  }
  // within the mouth's band, Ẽ_k and its rate
  const Band b = band_at(w, cap, qx, qy, psi, k, hk);
  return {out.e + b.e, out.de + b.gx * p.dx + b.gy * p.dy + b.gpsi * p.dpsi};
}

// The jump of E_k on the surface f(t) = 0 (f > 0 on its outer side) where the step's two ends lie
// on its opposite sides (else 0: E at both ends is then one continuous branch's, and a dip across
// the surface and back, which ΔE never sees, needs no share of its own): the crossing bracketed by
// bisection to [a, b], b − a ≤ `span`, and each side's E, taken a `span` beyond the bracket,
// carried to the bracket's middle m along its own slope, E(b⁺) − E'(b⁺)(b⁺ − m) − E(a⁻) −
// E'(a⁻)(m − a⁻), signed as the path crosses (from the start's side to the end's). The
// continuous part's share is then E''s over the 3 spans (and a jump of the slope alone over half
// a span), not |∇E| over 3 spans: a crossing with no jump reads as none at any c and ε.
template <class Side>
double jump_on(const Sprocket& w, const Capture& cap, const Path& p, int k, int hk, double span,
               Side outer) {
  const bool at = outer(0.0);
  if (at == outer(1.0)) return 0.0;
  double a = 0.0, b = 1.0;
  for (int it = 0; it < 200 && b - a > span; ++it) {
    const double m = 0.5 * (a + b);
    (outer(m) == at ? a : b) = m;
  }
  double ta = std::max(0.0, a - span), tb = std::min(1.0, b + span);
  // a path meeting the surface at a grazing angle stays within its rounding a span beyond the
  // bracket (a chord of 0.2c from a point on the mouth: 1e-13 m along it, 1e-17 m across), where
  // both points took the outer side's E and the jump read 0 (37 J on the release's mouth): each
  // point is taken farther out until its side is its own (at worst the end, whose side is)
  for (double d = 2.0 * span; outer(tb) == at && tb < 1.0; d *= 2.0) tb = std::min(1.0, b + d);
  for (double d = 2.0 * span; outer(ta) != at && ta > 0.0; d *= 2.0) ta = std::max(0.0, a - d);
  const double m = 0.5 * (a + b);
  const Slope ea = slope_along(w, cap, p, ta, k, hk), eb = slope_along(w, cap, p, tb, k, hk);
  return eb.e - eb.de * (tb - m) - ea.e - ea.de * (m - ta);
}

// The jumps a step crosses end to end: their sum as ΔE holds it (signed) and their sizes' sum
struct Jumps {
  double sum = 0.0, size = 0.0;
  void add(double j) {
    sum += j;
    size += std::abs(j);
  }
};

// Ẽ_k's jumps the step crosses end to end: the capture's (the mouth's is spread over its band),
// where the ends lie on its opposite sides, bracketed to 1e-9 c of the path (crossed an odd
// number of times, of which bisection finds one). `dist` the θ point's |q − C_k| if known (else <
// 0): |q − C_k| moves by at most |Δq| + R |Δψ| over the path, so the capture is sought only where
// that reaches `from` from it. Inlined: out of line it cost pocket_step_contact 0.39 % more
// instructions on the keyed example, 0.15 % of the run's (docs/performance.md, "The pocket
// mouth's side at rounding").
[[gnu::always_inline]] inline Jumps crossed_jump(const Sprocket& w, const Capture& cap,
                                                 const Path& p, int k, int hk, double dist) {
  const double r = w.pitch_radius;
  const double len = std::hypot(p.dx, p.dy) + r * std::abs(p.dpsi);  // ≥ the points' |dz/dt|
  const double span = 1e-9 * w.pocket_clearance / len;
  Jumps sum;
  const double from = cap.from, mouth = r + 0.5 * w.pocket_clearance;
  auto radius = [&](double t) { return std::hypot(p.q0x + t * p.dx, p.q0y + t * p.dy); };
  // whether the path's point at t, or its ray's point on the mouth (`on_mouth`), lies beyond the
  // capture, |q − C_k| > from
  auto beyond = [&](double t, bool on_mouth) {
    const double a = vertex_angle(w, k, p.psi0 + t * p.dpsi);
    const double s = on_mouth ? mouth / radius(t) : 1.0;
    return std::hypot(s * (p.q0x + t * p.dx) - r * std::cos(a),
                      s * (p.q0y + t * p.dy) - r * std::sin(a)) > from;
  };
  // whether it lies beyond the mouth as its energy takes it (the ends' contacts and band_at:
  // where() and within_mouth(); by ρ's own rounding a step from a point on the mouth took a 37 J
  // jump on the release's mouth for none)
  auto outside = [&](double t) {
    return !within_mouth(w, where(w, p.q0x + t * p.dx + w.centre_x, p.q0y + t * p.dy + w.centre_y));
  };
  const double reach = std::max(p.theta, 1.0 - p.theta) * len + 1e-9 * w.pocket_clearance;
  if (w.pocket_body && (dist < 0.0 || std::abs(dist - from) <= reach))
    sum.add(jump_on(w, cap, p, k, hk, span, [&](double t) { return beyond(t, false); }));
  // the release's mouth for a joint not held: free beyond it, held within it (band_at), so Ẽ_k
  // jumps there by E_k's inner side's
  if (w.pocket_release && hk == kNoPocket) sum.add(jump_on(w, cap, p, k, hk, span, outside));
  // and the capture's shadow in the mouth's band: J jumps where the point's ray meets the mouth
  // at `from` (a jump of Ẽ only within the band; its ends' sides decide, as above), sought only
  // where the path's |q| range, [its distance from O, the ends' larger], meets the band (R, M]
  const double foot = -(p.q0x * p.dx + p.q0y * p.dy) / std::max(p.dx * p.dx + p.dy * p.dy, 1e-300);
  if (w.pocket_body && radius(std::clamp(foot, 0.0, 1.0)) <= mouth &&
      std::max(radius(0.0), radius(1.0)) > r)
    sum.add(jump_on(w, cap, p, k, hk, span, [&](double t) { return beyond(t, true); }));
  return sum;
}

// The elastic ∂F/∂q (row-major) of an elastic contact (no velocity): the fields' and dq_extra
void elastic_jacobian(const SeatContact& e, double out[4]) {
  const double f = e.active ? e.force : 0.0;
  fields_jacobian(e.active ? e.stiffness : 0.0, f * e.curvature, e.nx, e.ny, out);
  if (e.active)
    for (int i = 0; i < 4; ++i) out[i] += e.dq_extra[i];
}
}  // namespace

SeatContact pocket_step_contact(const Sprocket& w, double x, double y, double vx, double vy,
                                double angle, double speed, int held, const PocketStep& step) {
  if (!w.discrete_gradient) return contact_with(w, x, y, vx, vy, angle, speed, held, nullptr);
  const Capture cap = body_capture(w);  // once for the step's contacts and jumps
  const Where p = where(w, x, y);
  const double rx = p.rx, ry = p.ry;
  // the θ point's pocket k (the nearest, or the held one beyond the mouth) and its vertex there,
  // taken once for the θ point's contact and its elastic contact (neither of which reads
  // it where the point is free of the wheel); E_k at the ends with k held there too if it is held
  // at the θ point
  const PocketVertex v = p.beyond && held != kNoPocket
                             ? PocketVertex{held, vertex_angle(w, held, angle)}
                             : nearest_pocket(w, std::atan2(ry, rx), angle);
  const int k = v.index, hk = held != kNoPocket ? k : kNoPocket;
  const bool free = free_of(w, p, held);
  double sx = 0.0, sy = 0.0;
  if (!free) vertex_point(w, v.angle, sx, sy);
  SeatContact c =
      free ? SeatContact{} : contact_at(w, x, y, vx, vy, speed, p, k, sx, sy, &cap, Need::kAll);
  // the ends relative to the wheel's centre there (a take-up's slides), put about w's centre
  const double q0x = step.x0 - step.cx0, q0y = step.y0 - step.cy0;
  const double q1x = step.x1 - step.cx1, q1y = step.y1 - step.cy1;
  const double dx = q1x - q0x, dy = q1y - q0y, dpsi = step.angle1 - step.angle0;
  const double r = w.pitch_radius, r2 = r * r;
  const double den = dx * dx + dy * dy + r2 * dpsi * dpsi;
  // below |Δz| = 1e-9 R the mismatch is the ends' rounding over |Δz|² (as the seats')
  if (!(den > 1e-18 * r2)) return c;
  PocketStart own;  // without the caller's memo, this call's
  const PocketStart& start = step_start(w, cap, step, k, hk, step.start ? *step.start : own);
  const End end = end_of(w, q1x, q1y, step.angle1, k, hk);
  // the end's energy and elastic force, the θ point's elastic force and ∂F/∂q (zero velocity)
  const SeatContact e1 = end.free ? SeatContact{}
                                  : contact_at(w, end.x, end.y, 0.0, 0.0, 0.0, end.at, k, end.sx,
                                               end.sy, &cap, Need::kForce);
  const SeatContact et =
      free ? SeatContact{}
           : contact_at(w, x, y, 0.0, 0.0, 0.0, p, k, sx, sy, &cap, Need::kJacobian);
  const Band b1 = band_at(w, cap, q1x, q1y, step.angle1, k, hk);
  const double en0 = start.energy, en1 = (e1.active ? e1.energy : 0.0) + b1.e;
  // ∇E at the θ point: G_q = f n, G_ψ = −τ (the elastic force −∇_q E, torque −∂E/∂ψ; not the
  // band's ∇B: within the band S Δz takes ∇B's part along the step alone, docs)
  const double gx = et.active ? et.force * et.nx : 0.0, gy = et.active ? et.force * et.ny : 0.0;
  const double gpsi = et.active ? -et.torque : 0.0;
  const double mismatch = en1 - en0 - (gx * dx + gy * dy) - gpsi * dpsi;
  if (!(en0 != 0.0 || en1 != 0.0 || et.active)) return c;  // Ẽ_k = 0 at all three
  // the jumps of Ẽ_k the step crosses (the capture's and its shadow's in the mouth's band; the
  // mouth's own is spread over the band), J, are taken over it as the rest of ΔE is, a force J/|Δz|
  // along the step, up to r = |J| / (|Δz| k c) = 1 (k c the pocket law's force at a depth of one
  // clearance); from r = 1 to 2 a C² step s(r) leaves the share s J of it to the work balance's
  // numerical term (all of it from r = 2 on), so that the jump's force stays below 2 k c on a
  // slow step and no threshold switches it (docs)
  const Path path{q0x, q0y, dx, dy, step.angle0, dpsi, step.theta};
  const double dist = free ? -1.0 : std::hypot(x - sx, y - sy);
  const Jumps jumps = crossed_jump(w, cap, path, k, hk, dist);
  const double ratio = jumps.size / (std::sqrt(den) * w.contact_stiffness * w.pocket_clearance);
  const Step left = smooth_step(ratio, 1.0, 2.0);
  const double cc = (mismatch - left.s * jumps.sum) / den;
  // the damper's clamp: where the θ point's force is 0 its blocks are 0 (only the correction's)
  if (!c.active) {
    c = SeatContact{};
    c.active = true;
    c.seat = k;
  } else if (!(c.force > 0.0)) {
    c.stiffness = c.damping = c.curvature = 0.0;
    for (int i = 0; i < 4; ++i)
      c.dq_extra[i] = c.dv_extra[i] = c.friction_dq[i] = c.friction_dv[i] = 0.0;
  }
  c.skew = cc;
  c.skew_x = dx;
  c.skew_y = dy;
  c.torque -= cc * r2 * dpsi;
  // a call for the residual alone (PocketStep::jacobian false): not the correction's derivatives
  if (!step.jacobian) return c;
  // E's Hessian at the θ point: H = −∂F/∂q; E(q, ψ) = E(Rq, ψ + δ) gives ∂E/∂ψ = −G_q·Jq
  // (Jq = perp q), so ∂²E/∂ψ∂q = a = −(H Jq + Jᵀ G_q) and ∂²E/∂ψ² = −a·Jq
  double jf[4];
  elastic_jacobian(et, jf);
  const double hq[4] = {-jf[0], -jf[1], -jf[2], -jf[3]};
  const double px = -ry, py = rx;
  const double ax = -(hq[0] * px + hq[1] * py + gy), ay = -(hq[2] * px + hq[3] * py - gx);
  const double hpp = -(ax * px + ay * py);
  // ∂cc = (∂mismatch − cc ∂den)/den; the θ point moves by θ with x₁ and ψ₁:
  // ∂mismatch/∂x₁ = ∇_q E₁ − G_q − θ (H Δq + a Δψ), ∂/∂ψ₁ = ∂E₁/∂ψ − G_ψ − θ (a·Δq + E_ψψ Δψ)
  const double th = step.theta;
  const double f1x = (e1.active ? e1.force * e1.nx : 0.0) + b1.gx,
               f1y = (e1.active ? e1.force * e1.ny : 0.0) + b1.gy;
  const double f1psi = (e1.active ? -e1.torque : 0.0) + b1.gpsi;
  // and the share left, s(r) J, by r ∝ 1/|Δz| (J's own change with the crossing's place is not
  // taken: exact for r ≤ 1, where no share is left, quasi-Newton beyond)
  const double dleft = left.ds * jumps.sum * ratio / den;
  const double mx = f1x - gx - th * (hq[0] * dx + hq[1] * dy + ax * dpsi) + dleft * dx;
  const double my = f1y - gy - th * (hq[2] * dx + hq[3] * dy + ay * dpsi) + dleft * dy;
  const double mpsi = f1psi - gpsi - th * (ax * dx + ay * dy + hpp * dpsi) + dleft * r2 * dpsi;
  c.skew_dx = (mx - 2.0 * cc * dx) / den;
  c.skew_dy = (my - 2.0 * cc * dy) / den;
  c.skew_dpsi = (mpsi - 2.0 * cc * r2 * dpsi) / den;
  return c;
}

void update_held(const Model& model, State& s) {
  const std::size_t n = s.nodes();
  if (s.held_wheel.size() != n || s.held_pocket.size() != n) {
    s.held_wheel.assign(n, -1);
    s.held_pocket.assign(n, 0);
  }
  for (std::size_t w = 0; w < model.sprockets.size() && w < s.angle.size(); ++w) {
    if (!model.sprockets[w].pocket || !model.sprockets[w].pocket_release) continue;
    const Sprocket wheel = at_slide(
        model.sprockets[w], model.sprockets[w].takeup && w < s.slide.size() ? s.slide[w] : 0.0);
    const double mouth = wheel.pitch_radius + 0.5 * wheel.pocket_clearance;
    const int wi = static_cast<int>(w);
    for (std::size_t i = 0; i < n; ++i) {
      const double rx = s.x[i] - wheel.centre_x, ry = s.y[i] - wheel.centre_y;
      if (rx * rx + ry * ry <= mouth * mouth) {
        // within the mouth: held by the nearest pocket, unless the joint is on the body between
        // the pockets (not held: beyond the mouth it is free)
        const PocketVertex v = nearest_pocket(wheel, std::atan2(ry, rx), s.angle[w]);
        double vx = 0.0, vy = 0.0;
        vertex_point(wheel, v.angle, vx, vy);
        if (!in_body(wheel, nullptr, std::hypot(s.x[i] - vx, s.y[i] - vy))) {
          s.held_wheel[i] = wi;
          s.held_pocket[i] = v.index;
        } else if (s.held_wheel[i] == wi) {
          s.held_wheel[i] = -1;
        }
      } else if (s.held_wheel[i] == wi &&
                 !pocket_contact(wheel, s.x[i], s.y[i], 0.0, 0.0, s.angle[w], 0.0, s.held_pocket[i])
                      .active) {
        s.held_wheel[i] = -1;
      }
    }
  }
}

double pocket_ramp_softening(const Sprocket& w) {
  if (!(w.pocket_mouth > 0.0)) return 0.0;
  // The largest eigenvalue of the contact's own exact elastic ∂F/∂q = −∇²E (elastic_jacobian, at
  // rest: no damping) over the ramp's region about pocket 0's vertex, the wheel at angle 0:
  // R + c/2 < ρ < R + c/2 + w and |p − vertex| < 3c (W = 0 from g = 2c on), so polar angles up to
  // asin(3c/R). E depends on (ρ, g) alone there, so this covers every pocket. A grid, then two
  // zooms about its largest cell.
  const double cl = w.pocket_clearance, r = w.pitch_radius, low = r + 0.5 * cl;
  const double top = std::asin(std::min(1.0, 3.0 * cl / r));
  auto softening = [&](double rho, double polar) {
    const double x = w.centre_x + rho * std::cos(polar), y = w.centre_y + rho * std::sin(polar);
    const SeatContact k = pocket_contact(w, x, y, 0.0, 0.0, 0.0, 0.0);
    double j[4];
    elastic_jacobian(k, j);
    const double mean = 0.5 * (j[0] + j[3]), half = 0.5 * (j[0] - j[3]);
    const double off = 0.5 * (j[1] + j[2]);
    return mean + std::sqrt(half * half + off * off);
  };
  constexpr int kRho = 64, kPolar = 256, kZoom = 16;
  double rho_from = low, rho_step = w.pocket_mouth / kRho;
  double polar_from = -top, polar_step = 2.0 * top / kPolar;
  int ni = kRho, nj = kPolar;
  double best = 0.0, best_rho = low + 0.5 * w.pocket_mouth, best_polar = 0.0;
  for (int pass = 0; pass < 3; ++pass) {
    for (int i = 0; i <= ni; ++i) {
      const double rho = std::clamp(rho_from + i * rho_step, low, low + w.pocket_mouth);
      for (int j = 0; j <= nj; ++j) {
        const double polar = polar_from + j * polar_step, v = softening(rho, polar);
        if (v > best) {
          best = v;
          best_rho = rho;
          best_polar = polar;
        }
      }
    }
    // the next pass: ±1 cell about the largest, in kZoom cells each way
    rho_from = best_rho - rho_step;
    polar_from = best_polar - polar_step;
    rho_step *= 2.0 / kZoom;
    polar_step *= 2.0 / kZoom;
    ni = nj = kZoom;
  }
  return best;
}

void pocket_issues(std::vector<Issue>& out, const Sprocket& w, const std::string& f) {
  constexpr double kPi = std::numbers::pi;
  const double tau = w.teeth > 0 ? 2.0 * kPi / w.teeth : 0.0;
  const double top = std::min(tau, kPi / 3.0);
  if (!std::isfinite(w.pocket_angle) || !(w.pocket_angle > 0.0) || !(w.pocket_angle < top)) {
    out.push_back({f + "pocket_angle", check::format_si(w.pocket_angle, "rad"),
                   "an angle in (0, min(2 pi/z, pi/3)) rad (delta1 < 2 pi/z; below 60 deg the "
                   "pocket's mouth R + c/2 admits a joint and holds the crank)"});
  }
  const double r = w.pitch_radius;
  if (!std::isfinite(w.pocket_clearance) || !(w.pocket_clearance > 0.0) ||
      !(std::isfinite(r) && w.pocket_clearance <= 0.1 * r)) {
    out.push_back({f + "pocket_clearance", check::format_si(w.pocket_clearance, "m"),
                   "a length in (0, R/10] (R the pitch radius)"});
  }
  if (w.pocket_body && std::isfinite(r) && w.pocket_clearance > 0.0 && w.pocket_angle > 0.0 &&
      w.pocket_angle < top && !(body_capture(w).from >= 2.0 * w.pocket_clearance)) {
    // the body's capture (at most 0.45 s, s the smallest vertex spacing) no longer clears the
    // pocket: its blend would start within 2c of the vertex
    out.push_back({f + "pocket_clearance", check::format_si(w.pocket_clearance, "m"),
                   "at most 0.1125 s with the body between the pockets (pocket_body; s the "
                   "smallest vertex spacing 2 R sin(min(delta1, 2 pi/z - delta1)/2): the body "
                   "takes over at min(10c, 0.225 s) from a vertex)"});
  }
  if (!std::isfinite(w.pocket_mouth) || !(w.pocket_mouth >= 0.0) ||
      !(w.pocket_mouth <= w.pocket_clearance)) {
    out.push_back({f + "pocket_mouth", check::format_si(w.pocket_mouth, "m"),
                   "a length in [0, pocket clearance] (the mouth's ramp; 0 a sharp mouth)"});
  } else if (w.pocket_mouth > 0.0 && w.pocket_release) {
    out.push_back({f + "pocket_mouth", check::format_si(w.pocket_mouth, "m"),
                   "0 with the pocket's release (pocket_release): the ramp is the sharp "
                   "mouth's option"});
  }
  check::finite_positive(out, (f + "contact_stiffness").c_str(), w.contact_stiffness, "N/m");
  if (!std::isfinite(w.contact_smoothing) || !(w.contact_smoothing > 0.0) ||
      !(w.contact_smoothing <= w.pocket_clearance)) {
    out.push_back({f + "contact_smoothing", check::format_si(w.contact_smoothing, "m"),
                   "a length in (0, pocket clearance]"});
  }
}

}  // namespace catena::dynamics
