// The pocket wheel's discrete gradient (Sprocket::discrete_gradient on a pocket wheel;
// docs/models/dynamics.md, "Pocket wheel: the discrete gradient"): the pocket's elastic force over
// a step is the θ point's −∇E plus the work's miss put back along the step, so that its work on
// joint and wheel is −ΔE of the θ point's pocket. Its work over one step against the change of the
// contact's energy (pocket_contact's, at the ends) in the pocket, on the body's blend and its rim,
// held and turning; the Newton matrix against central differences of the step's residual; and an
// undamped, frictionless wrap on a pocket wheel at θ = ½ whose work balance closes with it and
// not without it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <tuple>
#include <utility>
#include <vector>

#include "catena/dynamics/integrator.hpp"
#include "catena/dynamics/pocket_wheel.hpp"
#include "pocket_setups.hpp"
#include "residual_difference.hpp"

namespace catena::dynamics {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kClearance = 1e-4, kStiffness = 1e8;  // [m], [N/m]

// Ø18×64 on z = 8 (seed 003's example), centre off the origin, the body between the pockets on
Sprocket wheel8(bool gradient, double damping = 0.0) {
  Sprocket w = pocket_wheel(0.064, 0.018, 8, 0.3, -0.2, kClearance, kStiffness, damping);
  w.discrete_gradient = gradient;
  return w;
}

struct Point {
  double x = 0.0, y = 0.0;
};
// The point at `along` [m] along the pitch circle from vertex k (wheel at `angle`), `below` [m]
// inside the mouth R + c/2 radially.
Point near_vertex(const Sprocket& w, double angle, int k, double along, double below) {
  const double tau = 2.0 * kPi / w.teeth;
  const double a = angle + (k / 2) * tau + (k % 2 ? w.pocket_angle : 0.0) + along / w.pitch_radius;
  const double rho = w.pitch_radius + 0.5 * w.pocket_clearance - below;
  return {w.centre_x + rho * std::cos(a), w.centre_y + rho * std::sin(a)};
}

double energy_at(const Sprocket& w, Point q, double angle, int held = kNoPocket) {
  return pocket_contact(w, q.x, q.y, 0.0, 0.0, angle, 0.0, held).energy;
}

// Ẽ, the energy the discrete gradient takes (docs/models/dynamics.md, "Pocket wheel: the discrete
// gradient", "The mouth's band"): within c/2 inside the mouth, E less (1 − φ) of E's jump on the
// mouth along the point's ray (1e-14 m either side), φ = x³(10 − 15x + 6x²), x the depth below
// the mouth over c/2; E elsewhere. The jump with the hold the point gets within the mouth,
// `holds` (update_held's with the release: the pocket, off the body), else `held`.
double banded_at(const Sprocket& w, Point q, double angle, int held = kNoPocket,
                 int holds = kNoPocket) {
  const double mouth = w.pitch_radius + 0.5 * w.pocket_clearance;
  const double rx = q.x - w.centre_x, ry = q.y - w.centre_y, rho = std::hypot(rx, ry);
  const double x = (mouth - rho) / (0.5 * w.pocket_clearance);
  const double e = energy_at(w, q, angle, held);
  if (!(x >= 0.0 && x < 1.0)) return e;
  if (holds != kNoPocket) held = holds;
  auto on = [&](double d) {
    const double a = (mouth + d) / rho;
    return energy_at(w, {w.centre_x + a * rx, w.centre_y + a * ry}, angle, held);
  };
  return e - (1.0 - x * x * x * (10.0 - 15.0 * x + 6.0 * x * x)) * (on(-1e-14) - on(1e-14));
}

// The step p0 → p1 with the wheel turning ψ₀ → ψ₁ about its centre, which stays put, at θ
PocketStep step_over(const Sprocket& w, Point p0, Point p1, double psi0, double psi1,
                     double theta) {
  return {.x0 = p0.x,
          .y0 = p0.y,
          .x1 = p1.x,
          .y1 = p1.y,
          .cx0 = w.centre_x,
          .cy0 = w.centre_y,
          .cx1 = w.centre_x,
          .cy1 = w.centre_y,
          .angle0 = psi0,
          .angle1 = psi1,
          .theta = theta};
}

// The contact over the step p0 → p1 (wheel ψ₀ → ψ₁, h = 0.1 ms, θ = ½)
SeatContact step_contact(const Sprocket& w, Point p0, Point p1, double psi0, double psi1,
                         int held = kNoPocket) {
  const double h = 1e-4, th = 0.5;
  const PocketStep step = step_over(w, p0, p1, psi0, psi1, th);
  const double qx = p0.x + th * (p1.x - p0.x), qy = p0.y + th * (p1.y - p0.y);
  return pocket_step_contact(w, qx, qy, (p1.x - p0.x) / h, (p1.y - p0.y) / h,
                             psi0 + th * (psi1 - psi0), (psi1 - psi0) / h, held, step);
}

// The contact's work over the step on joint and wheel: (−f n − S Δ)·Δ + τ Δψ
double step_work(const Sprocket& w, Point p0, Point p1, double psi0, double psi1, int* surface,
                 int held = kNoPocket) {
  const SeatContact c = step_contact(w, p0, p1, psi0, psi1, held);
  if (surface != nullptr) *surface = c.surface;
  if (!c.active) return 0.0;
  const double dx = p1.x - p0.x, dy = p1.y - p0.y;
  return -c.force * (c.nx * dx + c.ny * dy) - c.skew * (c.skew_x * dx + c.skew_y * dy) +
         c.torque * (psi1 - psi0);
}

// (1) One step's work is −ΔE: in the pocket (pressing in 20 → 60 µm and swinging sideways),
// entering it from the clearance, on the body's blend (12c–18c from the vertex, 20 µm below the
// mouth: the pocket's and the rim's depths blended) and on the rim (30c off), over the mouth's
// ramp and with the release beyond the mouth, the wheel held and turning 3e-3 rad over the step
// (30 rad/s). With the θ point's force (the key off) it misses by
// far (measured, printed).
TEST(DynamicsPocketDiscreteGradient, WorkOverAStepIsTheEnergysChange) {
  const Sprocket on = wheel8(true), off = wheel8(false);
  const double c = kClearance, psi = 0.4;
  struct Move {
    const char* where;
    double along0, below0, along1, below1;
    int surface;  // the θ point's: 0 the pocket, 3 the body
  };
  // (the vertex is at `below` = c/2: 20 µm into the pocket is below = c/2 + c + 20 µm)
  const Move moves[] = {
      {"pocket", 0.3 * c, 1.7 * c + 20e-6, 0.1 * c, 1.5 * c + 60e-6, 0},
      {"pocket, entering", -0.5 * c, 0.5 * c + 0.2 * c, 0.2 * c, 1.5 * c + 30e-6, 0},
      {"pocket, sideways", -0.8 * c, 1.5 * c + 40e-6, 1.2 * c, 1.5 * c + 35e-6, 0},
      {"blend", 12.0 * c, 20e-6, 12.5 * c, 30e-6, 3},
      {"blend, sliding", 14.0 * c, 25e-6, 18.0 * c, 15e-6, 3},
      {"rim", 30.0 * c, 20e-6, 31.0 * c, 40e-6, 3}};
  double worst = 0.0, theta_best = INFINITY;
  for (const double turn : {0.0, 3e-3}) {
    for (const Move& m : moves) {
      const Point p0 = near_vertex(on, psi, 3, m.along0, m.below0);
      const Point p1 = near_vertex(on, psi + turn, 3, m.along1, m.below1);
      int surface = -1;
      const double work = step_work(on, p0, p1, psi, psi + turn, &surface);
      EXPECT_EQ(surface, m.surface) << m.where;
      const double change = energy_at(on, p1, psi + turn) - energy_at(on, p0, psi);
      ASSERT_GT(std::abs(change), 1e-6) << m.where;
      const double err = std::abs(work + change) / std::abs(change);
      EXPECT_LT(err, 1e-9) << m.where << " turn " << turn << ": work " << work << " dE " << change;
      worst = std::max(worst, err);
      const double theta_work = step_work(off, p0, p1, psi, psi + turn, nullptr);
      theta_best = std::min(theta_best, std::abs(theta_work + change) / std::abs(change));
    }
  }
  // the mouth's ramp (w = c) and the release (a joint held by pocket 3 beyond the mouth): a joint
  // 1.5c off its vertex rising over the ramp 10 → 60 µm above the mouth, and a held joint 2c off
  // rising 10 → 30 µm above it, where E₀(g) S(u) falls with the angle u of e to the radial
  Sprocket ramp = wheel8(true), release = wheel8(true);
  ramp.pocket_mouth = c;
  release.pocket_release = true;
  double other = 0.0;
  for (const double turn : {0.0, 3e-3}) {
    for (int j = 0; j < 2; ++j) {
      const Sprocket& w = j == 0 ? ramp : release;
      const int held = j == 0 ? kNoPocket : 3;
      const double along = (j == 0 ? 1.5 : 2.0) * c;
      const Point p0 = near_vertex(w, psi, 3, along, -10e-6);
      const Point p1 = near_vertex(w, psi + turn, 3, along, j == 0 ? -60e-6 : -30e-6);
      const double work = step_work(w, p0, p1, psi, psi + turn, nullptr, held);
      const double change = energy_at(w, p1, psi + turn, held) - energy_at(w, p0, psi, held);
      ASSERT_GT(std::abs(change), 1e-6) << j;
      const double err = std::abs(work + change) / std::abs(change);
      EXPECT_LT(err, 1e-9) << (j == 0 ? "ramp" : "release") << " turn " << turn;
      other = std::max(other, err);
    }
  }
  std::printf(
      "pocket discrete gradient: |work + dE| / |dE| worst %.2e over the pocket, blend and rim, "
      "held and turning (%.2e over the mouth's ramp and the release); the theta point's force at "
      "best %.3g\n",
      worst, other, theta_best);
  EXPECT_GT(theta_best, 1e-4);
}

// The pieces of pocket 3 a step sweeps through, each from (along0, below0) to (along1, below1)
// [m] (near_vertex's) at 8 points, 7 steps: the pocket, the body's blend and rim on `body`, the
// mouth's ramp on `body` with pocket_mouth = c, and the release, held, on `body` with
// pocket_release; each step with the wheel held (ψ₀ = ψ₁ = psi) and turning 3e-3 rad from psi.
// `visit` gets each step; the sweep stops at a fatal failure (an ASSERT in `visit`).
struct SweptStep {
  const char* where;
  const Sprocket* w;
  int held;
  int i;         // the step's first point
  double turn;   // ψ₁ − ψ₀ [rad]
  Point p0, p1;  // the joint at the step's ends, at ψ₀ and ψ₁
};
template <class Visit>
void sweep_pocket_pieces(const Sprocket& body, double psi, Visit visit) {
  const double c = kClearance;
  Sprocket ramp = body, release = body;
  ramp.pocket_mouth = c;
  release.pocket_release = true;
  struct Sweep {
    const char* where;
    const Sprocket* w;
    double along0, below0, along1, below1;  // the ends; at `steps` points between
    int held;
  };
  const Sweep sweeps[] = {
      {"pocket", &body, -0.8 * c, 1.5 * c + 10e-6, 1.2 * c, 1.5 * c + 60e-6, kNoPocket},
      {"blend", &body, 11.0 * c, 15e-6, 19.0 * c, 35e-6, kNoPocket},
      {"rim", &body, 25.0 * c, 10e-6, 35.0 * c, 40e-6, kNoPocket},
      {"ramp", &ramp, 0.5 * c, -5e-6, 2.5 * c, -90e-6, kNoPocket},
      {"release", &release, 1.0 * c, -20e-6, 2.0 * c, -60e-6, 3}};
  const int steps = 8;
  for (const Sweep& sw : sweeps) {
    const Sprocket& w = *sw.w;
    for (int i = 0; i + 1 < steps; ++i) {
      for (const double turn : {0.0, 3e-3}) {
        auto at = [&](int j, double angle) {
          const double t = static_cast<double>(j) / (steps - 1);
          return near_vertex(w, angle, 3, sw.along0 + t * (sw.along1 - sw.along0),
                             sw.below0 + t * (sw.below1 - sw.below0));
        };
        visit(SweptStep{sw.where, &w, sw.held, i, turn, at(i, psi), at(i + 1, psi + turn)});
        if (::testing::Test::HasFatalFailure()) return;
      }
    }
  }
}

// The step's ends are taken cheaper than the θ point's contact (the start's energy alone, once a
// step; the end's energy and force without the derivative blocks; the θ point's elastic contact
// with its ∂F/∂q but without the friction's): the same numbers as pocket_contact's. The
// correction is S = (E₁ − E₀ − ∇E_θ·Δz)/|Δz|² and ∂S/∂x₁ = (∇_q E₁ − ∇_q E_θ − θ (H Δq + a Δψ)
// − 2 S Δq)/|Δz|² (∂S/∂ψ₁ likewise, with a·Δq + E_ψψ Δψ), H = −∂F/∂q of the θ point's elastic
// contact (the fields' block and dq_extra), a = −(H Jq + Jᵀ G_q), E_ψψ = −a·Jq (Jq = perp(q − O)),
// so pocket_contact's energies, forces and ∂F/∂q at the ends and at the θ point (zero velocity)
// give them bit for bit, over a sweep through the pocket, the body's blend and rim, the mouth's
// ramp and the release (held), the wheel held and turning. At θ = 0 the Hessian's terms drop out.
void check_ends_bit_for_bit(double theta) {
  const double psi = 0.4;
  int checked = 0, hessian = 0;
  sweep_pocket_pieces(wheel8(true), psi, [&](const SweptStep& sw) {
    const Sprocket& w = *sw.w;
    const int i = sw.i;
    const double turn = sw.turn;
    const Point p0 = sw.p0, p1 = sw.p1;
    const double psi1 = psi + turn, psit = psi + theta * turn;
    const Point pt{p0.x + theta * (p1.x - p0.x), p0.y + theta * (p1.y - p0.y)};
    const PocketStep step = step_over(w, p0, p1, psi, psi1, theta);
    const SeatContact s = pocket_step_contact(w, pt.x, pt.y, 0.01, -0.02, psit, 5.0, sw.held, step);
    // pocket_contact at the ends (about the centre as pocket_step_contact puts them) and at
    // the θ point, at zero velocity
    const double q0x = step.x0 - step.cx0, q0y = step.y0 - step.cy0;
    const double q1x = step.x1 - step.cx1, q1y = step.y1 - step.cy1;
    const SeatContact e0 =
        pocket_contact(w, q0x + w.centre_x, q0y + w.centre_y, 0.0, 0.0, psi, 0.0, sw.held);
    const SeatContact e1 =
        pocket_contact(w, q1x + w.centre_x, q1y + w.centre_y, 0.0, 0.0, psi1, 0.0, sw.held);
    const SeatContact et = pocket_contact(w, pt.x, pt.y, 0.0, 0.0, psit, 0.0, sw.held);
    ASSERT_TRUE(e0.active || e1.active || et.active) << sw.where << " " << i;
    ASSERT_NE(s.skew, 0.0) << sw.where << " " << i;  // corrected: no jump, a step
    for (const SeatContact* e : {&e0, &e1, &et}) {
      if (e->active) {
        ASSERT_EQ(e->seat, 3) << sw.where << " " << i;  // the θ point's pocket
      }
    }
    const double en0 = e0.active ? e0.energy : 0.0, en1 = e1.active ? e1.energy : 0.0;
    const double gx = et.active ? et.force * et.nx : 0.0;
    const double gy = et.active ? et.force * et.ny : 0.0;
    const double gpsi = et.active ? -et.torque : 0.0;
    const double f1x = e1.active ? e1.force * e1.nx : 0.0;
    const double f1y = e1.active ? e1.force * e1.ny : 0.0;
    const double f1psi = e1.active ? -e1.torque : 0.0;
    const double dx = q1x - q0x, dy = q1y - q0y, dpsi = psi1 - psi;
    const double r2 = w.pitch_radius * w.pitch_radius;
    const double den = dx * dx + dy * dy + r2 * dpsi * dpsi;
    const double cc = (en1 - en0 - (gx * dx + gy * dy) - gpsi * dpsi) / den;
    // H = −∂F/∂q of the θ point's elastic contact: −(fields' block + dq_extra), the fields'
    // −k m mᵀ − f κ (I − m mᵀ) along its force's direction m
    const double kn = et.active ? et.stiffness : 0.0;
    const double ft = (et.active ? et.force : 0.0) * et.curvature, mx = et.nx, my = et.ny;
    double jf[4] = {-(kn * mx * mx + ft * (1 - mx * mx)), -(kn - ft) * mx * my,
                    -(kn - ft) * mx * my, -(kn * my * my + ft * (1 - my * my))};
    if (et.active) {
      for (int k = 0; k < 4; ++k) jf[k] += et.dq_extra[k];
    }
    const double hq[4] = {-jf[0], -jf[1], -jf[2], -jf[3]};
    const double px = -(pt.y - w.centre_y), py = pt.x - w.centre_x;  // Jq
    const double ax = -(hq[0] * px + hq[1] * py + gy), ay = -(hq[2] * px + hq[3] * py - gx);
    const double hpp = -(ax * px + ay * py);
    const double mqx = f1x - gx - theta * (hq[0] * dx + hq[1] * dy + ax * dpsi);
    const double mqy = f1y - gy - theta * (hq[2] * dx + hq[3] * dy + ay * dpsi);
    const double mpsi = f1psi - gpsi - theta * (ax * dx + ay * dy + hpp * dpsi);
    EXPECT_EQ(s.skew, cc) << sw.where << " " << i << " turn " << turn;
    EXPECT_EQ(s.skew_dx, (mqx - 2.0 * cc * dx) / den) << sw.where << " " << i;
    EXPECT_EQ(s.skew_dy, (mqy - 2.0 * cc * dy) / den) << sw.where << " " << i;
    EXPECT_EQ(s.skew_dpsi, (mpsi - 2.0 * cc * r2 * dpsi) / den) << sw.where << " " << i;
    hessian += et.active && (et.dq_extra[0] != 0.0 || et.dq_extra[3] != 0.0);
    ++checked;
  });
  if (::testing::Test::HasFatalFailure()) return;  // an ASSERT stopped the sweep
  EXPECT_EQ(checked, 70);
  std::printf(
      "pocket discrete gradient's ends at theta = %g: %d steps bit for bit (%d with the "
      "theta point's dq_extra)\n",
      theta, checked, hessian);
  if (theta > 0.0) {
    EXPECT_GT(hessian, 0);
  }
}

TEST(DynamicsPocketDiscreteGradient, EndsAreTheContactsEnergyAndForceBitForBit) {
  check_ends_bit_for_bit(0.0);
}

// At θ = ½ the θ point's ∂F/∂q (its elastic contact's Need::kJacobian: the fields' block and
// dq_extra, the mouth's ramp's and the release's included) enters ∂S through the Hessian's terms
TEST(DynamicsPocketDiscreteGradient, HessianAtThetaHalfIsTheContactsBitForBit) {
  check_ends_bit_for_bit(0.5);
}

// The caller's memo of the step's start (PocketStep::start, kept by the integrator over a step's
// Newton iterations) gives the contact bit for bit as without it: filled by one step and read by
// the next that differs in one of its key's inputs alone — the start, the pocket, the wheel's
// centre (a take-up's), the start's angle ψ₀, the start's wheel centre, the hold (on a release
// wheel) — it is taken afresh (each fails with that key's comparison dropped).
TEST(DynamicsPocketDiscreteGradient, StartsMemoGivesTheSameContact) {
  const double c = kClearance, psi = 0.4, turn = 2e-3;
  const Sprocket w = wheel8(true);
  Sprocket moved = w;  // a take-up's wheel a little along its slide
  moved.centre_x += 3e-5;
  moved.centre_y -= 2e-5;
  Sprocket release = w;
  release.pocket_release = true;
  const Point a0 = near_vertex(w, psi, 3, 0.3 * c, 1.7 * c + 20e-6);
  const Point b0 = near_vertex(w, psi, 3, 0.3 * c, 1.7 * c + 45e-6);  // the same pocket, deeper
  const Point d0 = near_vertex(w, psi, 4, 12.0 * c, 20e-6);           // pocket 4's blend
  const Point a1 = near_vertex(w, psi + turn, 3, 0.1 * c, 1.5 * c + 60e-6);
  const Point d1 = near_vertex(w, psi + turn, 4, 12.4 * c, 30e-6);
  // from a0 to pocket 5's vertex: the θ point (the chord's middle) nearest pocket 4
  const Point e1 = near_vertex(w, psi + turn, 5, 0.0, 1.5 * c + 20e-6);
  // beyond the mouth (2c off vertex 3, 10 → 30 µm above it): in the pocket's law held, free not
  const Point r0 = near_vertex(w, psi, 3, 2.0 * c, -10e-6);
  const Point r1 = near_vertex(w, psi + turn, 3, 2.0 * c, -30e-6);
  struct Call {
    const Sprocket* w;
    Point p0, p1;
    int k;
    double dpsi0 = 0.0, dcx = 0.0;  // ψ₀ and the start's centre (cx0, cy0) moved alone
    int held = kNoPocket;
    bool corrected = true;
  };
  const Call calls[] = {{&w, a0, a1, 3},
                        {&w, a0, a1, 3},
                        {&w, b0, a1, 3},
                        {&w, d0, d1, 4},
                        {&w, a0, a1, 3},
                        {&moved, a0, a1, 3},
                        {&w, a0, a1, 3},
                        {&w, a0, a1, 3, 5e-4},
                        {&w, a0, a1, 3},
                        {&w, a0, a1, 3, 0.0, 2e-5},
                        {&w, a0, a1, 3},
                        {&w, a0, e1, 4},
                        {&release, r0, r1, 3, 0.0, 0.0, kNoPocket, false},
                        {&release, r0, r1, 3, 0.0, 0.0, 3}};
  PocketStart memo;
  int corrected = 0;
  for (const Call& call : calls) {
    const Sprocket& wh = *call.w;
    PocketStep step = step_over(w, call.p0, call.p1, psi + call.dpsi0, psi + turn, 0.5);
    step.cx0 += call.dcx;  // the start's centre moved alone
    step.cy0 -= 0.5 * call.dcx;
    const double qx = 0.5 * (call.p0.x + call.p1.x), qy = 0.5 * (call.p0.y + call.p1.y);
    const SeatContact without =
        pocket_step_contact(wh, qx, qy, 0.1, 0.2, psi + 0.5 * turn, 20.0, call.held, step);
    step.start = &memo;
    const SeatContact with =
        pocket_step_contact(wh, qx, qy, 0.1, 0.2, psi + 0.5 * turn, 20.0, call.held, step);
    EXPECT_TRUE(memo.set);
    EXPECT_EQ(memo.pocket, call.k);
    EXPECT_EQ(with.skew, without.skew) << call.k;
    EXPECT_EQ(with.skew_dx, without.skew_dx) << call.k;
    EXPECT_EQ(with.skew_dy, without.skew_dy) << call.k;
    EXPECT_EQ(with.skew_dpsi, without.skew_dpsi) << call.k;
    EXPECT_EQ(with.force, without.force) << call.k;
    EXPECT_EQ(with.torque, without.torque) << call.k;
    EXPECT_EQ(without.skew != 0.0, call.corrected) << call.k;
    corrected += without.skew != 0.0;
  }
  EXPECT_EQ(corrected, 13);
}

// A call for the step's residual alone (PocketStep::jacobian false: the integrator's line search
// and report) gives the contact bit for bit as the call for the Newton matrix but for the
// correction's derivatives (the θ point's Hessian), left 0, and the same seat friction, over a
// sweep through the pocket, the body's blend and rim, the mouth's ramp and the release (held),
// damped, with friction, the wheel held and turning, with the discrete gradient and without it
// (the θ point's contact alone).
TEST(DynamicsPocketDiscreteGradient, ResidualOnlyCallsGiveTheSameResidual) {
  const double psi = 0.4, th = 0.5;
  int calls = 0, blocks = 0, corrected = 0;
  for (const bool gradient : {true, false}) {
    Sprocket body = wheel8(gradient, 2000.0);
    body.friction = 0.2;
    sweep_pocket_pieces(body, psi, [&](const SweptStep& sw) {
      const Sprocket& w = *sw.w;
      const double turn = sw.turn;
      const Point p0 = sw.p0, p1 = sw.p1;
      const double psi1 = psi + turn, psit = psi + th * turn, h = 1e-4;
      const Point pt{p0.x + th * (p1.x - p0.x), p0.y + th * (p1.y - p0.y)};
      const double vx = (p1.x - p0.x) / h + 0.01, vy = (p1.y - p0.y) / h - 0.02;
      PocketStep step = step_over(w, p0, p1, psi, psi1, th);
      const SeatContact full =
          pocket_step_contact(w, pt.x, pt.y, vx, vy, psit, turn / h, sw.held, step);
      step.jacobian = false;
      const SeatContact r =
          pocket_step_contact(w, pt.x, pt.y, vx, vy, psit, turn / h, sw.held, step);
      ++calls;
      EXPECT_EQ(r.active, full.active) << calls;
      EXPECT_EQ(r.force, full.force) << calls;
      EXPECT_EQ(r.nx, full.nx) << calls;
      EXPECT_EQ(r.ny, full.ny) << calls;
      EXPECT_EQ(r.torque, full.torque) << calls;
      EXPECT_EQ(r.energy, full.energy) << calls;
      EXPECT_EQ(r.depth, full.depth) << calls;
      EXPECT_EQ(r.damping_power, full.damping_power) << calls;
      EXPECT_EQ(r.friction_weight, full.friction_weight) << calls;
      EXPECT_EQ(r.skew, full.skew) << calls;
      EXPECT_EQ(r.skew_x, full.skew_x) << calls;
      EXPECT_EQ(r.skew_y, full.skew_y) << calls;
      const SeatFriction fr = seat_friction(w, r, pt.x, pt.y, vx, vy, turn / h);
      const SeatFriction ff = seat_friction(w, full, pt.x, pt.y, vx, vy, turn / h);
      EXPECT_EQ(fr.fx, ff.fx) << calls;
      EXPECT_EQ(fr.fy, ff.fy) << calls;
      EXPECT_EQ(fr.power, ff.power) << calls;
      EXPECT_EQ(fr.torque, ff.torque) << calls;
      for (int j = 0; j < 4; ++j) {  // the θ point's contact's own blocks are kept
        EXPECT_EQ(r.dq_extra[j], full.dq_extra[j]) << calls;
        EXPECT_EQ(r.dv_extra[j], full.dv_extra[j]) << calls;
        EXPECT_EQ(r.friction_dq[j], full.friction_dq[j]) << calls;
        EXPECT_EQ(r.friction_dv[j], full.friction_dv[j]) << calls;
      }
      blocks += full.skew_dx != 0.0 || full.skew_dy != 0.0 || full.skew_dpsi != 0.0;
      EXPECT_EQ(r.skew_dx, 0.0) << calls;
      EXPECT_EQ(r.skew_dy, 0.0) << calls;
      EXPECT_EQ(r.skew_dpsi, 0.0) << calls;
      corrected += full.skew != 0.0;
    });
  }
  std::printf(
      "pocket residual-only calls: %d calls, %d corrected, %d with the correction's derivatives "
      "in the full call\n",
      calls, corrected, blocks);
  EXPECT_GT(corrected, calls / 4);
  EXPECT_EQ(blocks, corrected);
}

// Across one of E_k's jumps the work is −ΔẼ, Ẽ the energy the step takes (banded_at): the
// mouth's jump spread over its band, the capture's taken over the step as the rest of ΔẼ (a force
// J/|Δz| along it, up to r = |J| / (|Δz| k c) = 1). A joint leaving over the sharp mouth 3c off
// its vertex (E jumps from E₀(g) to 0), and one crossing the body's capture (10c from the vertex)
// 20 µm below the mouth, within its radial band (the pocket's E₀(9c) against the body's blended
// depth, 39 J; the wheel turning 0.03 rad over the step, |Δz| ≈ 7 mm, for r < 1); across the
// capture straight below the vertex, beyond the band (10c) from the mouth (no jump there). With
// the release a joint not held that enters over the mouth 3c off its vertex, from 10 µm above to
// 20 µm below it (the wheel turning 0.03 rad, for r < 1), jumps from 0 to E₀(g) S(u): held
// within the mouth, its Ẽ there is E (J = 0 on the release's law), so the jump is crossed. Over the
// mouth's ramp (w = c) a joint entering 3.5c off its vertex, from 2 µm above the mouth to 2 µm
// below it, meets the ramp's leftover jump E₀(g)(1 − W) (W = 0 from g = 2c on: the whole
// E₀(2.54c), 3.2 J); 1.2c off (g = 0.3c on the mouth, W = 1: no jump). (Before, the steps across a
// jump above k ε²/6 kept the θ point's force: their work missed ΔE by the jump, 1.4 J and more
// here.)
TEST(DynamicsPocketDiscreteGradient, AcrossAJumpTheWorkIsTheEnergysChange) {
  Sprocket release_on = wheel8(true), release_off = wheel8(false);
  release_on.pocket_release = release_off.pocket_release = true;
  const double c = kClearance, psi = 0.4;
  struct Across {
    const char* what;
    double along0, below0, along1, below1;
    bool jump, release;
    double mouth;  // the ramp's width w
    double turn;   // over the step [rad]
  };
  const Across steps[] = {
      {"sharp mouth", 3.0 * c, 2e-6, 3.0 * c, -2e-6, true, false, 0.0, 1e-3},
      {"capture near the mouth", 9.9 * c, 20e-6, 10.1 * c, 20e-6, true, false, 0.0, 0.03},
      {"capture deep", 0.0, 10.4 * c, 0.0, 10.6 * c, false, false, 0.0, 1e-3},
      {"the release's mouth, not held", 3.0 * c, -10e-6, 3.0 * c, 20e-6, true, true, 0.0, 0.03},
      {"the ramp's leftover", 3.5 * c, -2e-6, 3.5 * c, 2e-6, true, false, c, 1e-3},
      {"the ramp's mouth near the vertex", 1.2 * c, -2e-6, 1.2 * c, 2e-6, false, false, c, 1e-3}};
  for (const Across& a : steps) {
    Sprocket on = a.release ? release_on : wheel8(true);
    Sprocket off = a.release ? release_off : wheel8(false);
    on.pocket_mouth = off.pocket_mouth = a.mouth;
    const Point p0 = near_vertex(on, psi, 2, a.along0, a.below0);
    const Point p1 = near_vertex(on, psi + a.turn, 2, a.along1, a.below1);
    const SeatContact with = step_contact(on, p0, p1, psi, psi + a.turn);
    const double change = energy_at(on, p1, psi + a.turn) - energy_at(on, p0, psi);
    const double banded = banded_at(on, p1, psi + a.turn, kNoPocket, a.release ? 2 : kNoPocket) -
                          banded_at(on, p0, psi);
    const double work = step_work(on, p0, p1, psi, psi + a.turn, nullptr);
    const double theta_work = step_work(off, p0, p1, psi, psi + a.turn, nullptr);
    std::printf(
        "pocket discrete gradient across %s: dE %.4g J, dE~ %.4g J, S %.4g N/m, |work + dE~| "
        "%.2e J (the theta point's force: %.3g J off)\n",
        a.what, change, banded, with.skew, std::abs(work + banded), std::abs(theta_work + banded));
    if (a.jump) {
      EXPECT_GT(std::abs(change), 1.0) << a.what;  // the jump
    }
    EXPECT_NE(with.skew, 0.0) << a.what;
    EXPECT_LT(std::abs(work + banded), 1e-8 * std::abs(change)) << a.what;
  }
}

// With the release, a joint not held that enters its pocket 3c off the vertex (10 µm above the
// mouth to 20 µm below it, in the band) is held from there on (update_held: within the mouth, off
// the body), and its next step goes 40 µm deeper, past the band; the wheel turns 0.03 rad a step
// (r < 1: no share left). Over the two steps the work is −(E at the end − 0): the end of the first
// step and the start of the second take the same Ẽ. (With J taken with the hold the step is called
// with, the entry's end took E − (1 − φ) J, the next start E: the two steps' work missed by that,
// 1.4 J here, once per entry.)
TEST(DynamicsPocketDiscreteGradient, TheReleasesEntryOverTwoStepsIsTheEnergysChange) {
  Sprocket on = wheel8(true);
  on.pocket_release = true;
  const double c = kClearance, psi = 0.4, turn = 0.03;
  const Point p0 = near_vertex(on, psi, 2, 3.0 * c, -10e-6);
  const Point p1 = near_vertex(on, psi + turn, 2, 3.0 * c, 20e-6);
  const Point p2 = near_vertex(on, psi + 2.0 * turn, 2, 3.0 * c, 60e-6);
  const double work = step_work(on, p0, p1, psi, psi + turn, nullptr) +
                      step_work(on, p1, p2, psi + turn, psi + 2.0 * turn, nullptr, 2);
  const double change = energy_at(on, p2, psi + 2.0 * turn, 2) - energy_at(on, p0, psi);
  std::printf(
      "pocket discrete gradient, the release's entry over two steps: dE %.4g J, "
      "|work + dE| %.2e J\n",
      change, std::abs(work + change));
  EXPECT_GT(change, 1.0);
  EXPECT_LT(std::abs(work + change), 1e-8 * change);
}

// Within the mouth's band the θ point's force along the step is −∇Ẽ's as the step shrinks,
// whatever its direction, and across it −∇E's (the band's ∇B across the step is not taken, docs):
// steps of |Δq| = L centred on a point 3c off the vertex, 25 µm below the sharp mouth (φ ≈ ½),
// radial and tangential, the wheel held, at θ = ½; L 1 µm and 10 nm. The force on the joint,
// −f n − S Δ, against central differences of banded_at (1 nm) and of pocket_contact's energy.
TEST(DynamicsPocketDiscreteGradient, WithinTheBandTheForceAlongTheStepIsTheBandedEnergys) {
  const Sprocket on = wheel8(true);
  const double c = kClearance, psi = 0.4, h = 1e-9;
  const Point q = near_vertex(on, psi, 2, 3.0 * c, 25e-6);
  auto grad = [&](auto f) {
    return Point{(f(Point{q.x + h, q.y}) - f(Point{q.x - h, q.y})) / (2.0 * h),
                 (f(Point{q.x, q.y + h}) - f(Point{q.x, q.y - h})) / (2.0 * h)};
  };
  const Point gb = grad([&](Point p) { return banded_at(on, p, psi); });
  const Point ge = grad([&](Point p) { return energy_at(on, p, psi); });
  const double rx = q.x - on.centre_x, ry = q.y - on.centre_y, rho = std::hypot(rx, ry);
  const double scale = std::hypot(gb.x, gb.y);
  double worst = 0.0, across = 0.0;
  for (const bool radial : {true, false}) {
    const double ux = radial ? rx / rho : -ry / rho, uy = radial ? ry / rho : rx / rho;
    for (const double len : {1e-6, 1e-8}) {
      const Point p0{q.x - 0.5 * len * ux, q.y - 0.5 * len * uy};
      const Point p1{q.x + 0.5 * len * ux, q.y + 0.5 * len * uy};
      const SeatContact s = step_contact(on, p0, p1, psi, psi);
      ASSERT_TRUE(s.active);
      const double fx = -s.force * s.nx - s.skew * s.skew_x;
      const double fy = -s.force * s.ny - s.skew * s.skew_y;
      const double along = std::abs((fx + gb.x) * ux + (fy + gb.y) * uy) / scale;
      const double off = std::abs((fx + ge.x) * -uy + (fy + ge.y) * ux) / scale;
      worst = std::max(worst, along);
      across = std::max(across, off);
      EXPECT_LT(along, 1e-3) << (radial ? "radial" : "tangential") << " L " << len;
      EXPECT_LT(off, 1e-3) << (radial ? "radial" : "tangential") << " L " << len;
    }
  }
  std::printf(
      "pocket discrete gradient within the band: |grad E~| %.3g N, |grad E~ - grad E| "
      "%.3g N; the force along the step misses -grad E~'s by %.2e of it, across it "
      "-grad E's by %.2e\n",
      scale, std::hypot(gb.x - ge.x, gb.y - ge.y), worst, across);
}

// Ẽ has no jump but the ones crossed_jump takes: tiny steps (0.1 µm, the wheel held) scanned
// radially across the mouth and the band's inner edge, 3c, 6c and 9.9c off the vertex (J 2 J to
// 40 J), and along the band, chords of 0.2c from −12c to 12c off the vertex on the mouth and 25 µm
// below it (across the capture and its shadow), on the sharp mouth, the mouth's ramp (w = c) and
// with the release (a joint not held: its entry is a jump crossed_jump takes). Each step's work is
// −(ΔẼ − s J), s = 1 for any real jump over so short a step (r > 2), so a jump crossed_jump does
// not find shows as work far above the force's scale. Across the band each step's |work| stays
// below 2.5e6 N (the band's force φ′ J, (15/8)/(c/2) · 40 J = 1.5e6 N 9.9c off, J's slope
// included) times its length, 0.25 J; along it, where φ′ J is across the step, below 5e5 N times
// it, 0.05 J: five times the pocket law's force k g at the capture (g < 10c: 1e5 N), the largest
// force met along the band (measured 9e-3 J on the sharp mouth and the ramp, 1.3e-2 J with the
// release). (The chords' ends lie on the mouth to rounding: where the band's side was decided by
// ρ's own rounding and the contact's by ρ²'s, a point the contact put beyond the mouth (E = 0)
// took Ẽ = −J, 0.37–37 J off its neighbours 1.6c–9.8c off the vertex; with the release, the
// ends' sides of the mouth were decided by the path's own radius (hypot), not the contact's ρ²,
// and a step leaving a chord's end at a grazing 1.3e-4 rad stayed within the mouth's rounding a
// span beyond the crossing's bracket, the jump read 0: work up to 37 J. The path's end is still
// taken at q₀ + 1·Δq, not q₁: of 4e6 steps ending on the mouth near the y axis, 180951 have
// q₀ + 1·Δq ≠ q₁ and none a side of its own.)
TEST(DynamicsPocketDiscreteGradient, TheBandedEnergyJumpsOnlyWhereItsJumpsAreTaken) {
  Sprocket release = wheel8(true), ramp = wheel8(true);
  release.pocket_release = true;
  ramp.pocket_mouth = kClearance;
  const double c = kClearance, psi = 0.4, step = 1e-7;
  const double across = 2.5e6 * step, along = 5e5 * step;  // the bounds [J]
  auto scan = [&](const Sprocket& on, const char* what, Point a, Point b, double bound,
                  double& worst) {
    const int n = static_cast<int>(std::hypot(b.x - a.x, b.y - a.y) / step) + 1;
    Point p0 = a;
    for (int i = 1; i <= n; ++i) {
      const double t = static_cast<double>(i) / n;
      const Point p1{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
      const double work = std::abs(step_work(on, p0, p1, psi, psi, nullptr));
      worst = std::max(worst, work);
      if (!(work < bound)) {
        ADD_FAILURE() << what << " at " << i << " of " << n << " from (" << a.x << ", " << a.y
                      << "): work " << work << " J (bound " << bound << " J)";
        return false;
      }
      p0 = p1;
    }
    return true;
  };
  const Sprocket sharp = wheel8(true);
  double worst_across = 0.0;
  for (const double off : {3.0 * c, 6.0 * c, 9.9 * c})
    scan(sharp, "across the band", near_vertex(sharp, psi, 2, off, -5e-6),
         near_vertex(sharp, psi, 2, off, 0.5 * c + 5e-6), across, worst_across);
  struct Chords {
    const Sprocket* on;
    const char* what;
    double worst = 0.0;
  } wheels[] = {{&sharp, "along the band"},
                {&ramp, "along the band, the ramp"},
                {&release, "along the band, the release"}};
  for (Chords& w : wheels) {
    for (const double below : {0.0, 25e-6}) {
      for (int j = -60; j < 60; ++j) {
        if (!scan(*w.on, w.what, near_vertex(*w.on, psi, 2, j * 0.2 * c, below),
                  near_vertex(*w.on, psi, 2, (j + 1) * 0.2 * c, below), along, w.worst))
          break;
      }
    }
  }
  std::printf(
      "pocket discrete gradient, tiny steps across the band: the largest work %.3g J (bound %.3g "
      "J); along it %.3g J on the sharp mouth, %.3g J on the ramp, %.3g J with the release (bound "
      "%.3g J)\n",
      worst_across, across, wheels[0].worst, wheels[1].worst, wheels[2].worst, along);
}

// A point on the mouth that the contact puts within it by its squared radius about the wheel's
// centre (ρ² ≤ (R + c/2)², E the pocket's inner side's) while its radius's own rounding puts it
// beyond (hypot > R + c/2) takes the band's −J too: band_at lets its own radius rule a point out
// only from 1e-9 c beyond the mouth. Such points lie near the axes (19 in 2e6 points on the mouth
// all round the test wheel); one is found by stepping 1 nm at a time along the mouth from 6c off a
// vertex placed 0.035 rad below the y axis (J ≈ 12.6 J there). Steps of 0.1 µm from it radially in
// and out, along the mouth, and back into it do the work of the force's scale (below 0.05 J, as
// along the band above); with the band deciding by its own radius alone, Ẽ there is E's inner
// side, J off its neighbours.
TEST(DynamicsPocketDiscreteGradient, APointOnTheMouthWithinItBySquaredRadiusTakesTheBand) {
  Sprocket sharp = wheel8(true), ramp = wheel8(true);
  ramp.pocket_mouth = kClearance;
  const double c = kClearance, psi = 0.75, step = 1e-7, bound = 5e5 * step;
  const double mouth = sharp.pitch_radius + 0.5 * c, cx = sharp.centre_x, cy = sharp.centre_y;
  double off = 6.0 * c;
  bool found = false;
  for (int i = 0; i < 100000 && !found; ++i) {
    off = 6.0 * c + i * 1e-9;
    const Point p = near_vertex(sharp, psi, 2, off, 0.0);
    const double qx = p.x - cx, qy = p.y - cy;  // as the step's end about the wheel's centre
    const double rx = (qx + cx) - cx, ry = (qy + cy) - cy;  // put back about it (where())
    found = std::hypot(qx, qy) > mouth && rx * rx + ry * ry <= mouth * mouth;
  }
  ASSERT_TRUE(found);
  double worst = 0.0;
  for (const Sprocket* on : {&sharp, &ramp}) {
    const Point p = near_vertex(*on, psi, 2, off, 0.0);
    ASSERT_GT(energy_at(*on, p, psi), 1.0);  // the contact takes the inner side's E there
    const Point to[] = {near_vertex(*on, psi, 2, off, step), near_vertex(*on, psi, 2, off, -step),
                        near_vertex(*on, psi, 2, off + step, 0.0)};
    for (const Point& q : to) {
      for (const auto& [a, b] : {std::pair{p, q}, std::pair{q, p}}) {
        const double work = std::abs(step_work(*on, a, b, psi, psi, nullptr));
        worst = std::max(worst, work);
        EXPECT_LT(work, bound) << (on == &ramp ? "the ramp" : "the sharp mouth") << ", from ("
                               << a.x << ", " << a.y << ") to (" << b.x << ", " << b.y << ")";
      }
    }
  }
  std::printf(
      "pocket discrete gradient, a point on the mouth %.6gc off the vertex within it by rho^2 "
      "and beyond it by hypot: the largest work of a 0.1 um step from or to it %.3g J (bound %.3g "
      "J)\n",
      off / c, worst, bound);
}

// A step across the sharp mouth within about 0.87c of its vertex, where the pocket's E₀(g) is 0 on
// the mouth (g ≤ 0: the energy has no jump there), is corrected like any other: a joint entering
// from 5 µm above the mouth 0.3c off its vertex to 30 µm into its pocket (the θ point still within
// the clearance: the correction acts alone), and one leaving its pocket from 10 µm in to end 3 µm
// above the mouth within its clearance (the step the command's example stopped on at θ = ½), the
// wheel held and turning 1e-3 rad: the work is −ΔE. (The pieces' test, before, kept the θ point's
// force on both, the mouth being crossed between the pocket's law and out of contact.)
TEST(DynamicsPocketDiscreteGradient, AcrossTheMouthWithinTheClearanceIsCorrected) {
  const Sprocket on = wheel8(true), off = wheel8(false);
  const double c = kClearance, psi = 0.4;
  struct Across {
    const char* what;
    double along0, below0, along1, below1;
  };
  const Across steps[] = {{"entering", 0.3 * c, -5e-6, 0.1 * c, 1.5 * c + 30e-6},
                          {"leaving", 0.1 * c, 1.5 * c + 10e-6, 0.2 * c, -3e-6}};
  double worst = 0.0, theta_best = INFINITY;
  for (const double turn : {0.0, 1e-3}) {
    for (const Across& a : steps) {
      const Point p0 = near_vertex(on, psi, 2, a.along0, a.below0);
      const Point p1 = near_vertex(on, psi + turn, 2, a.along1, a.below1);
      const double e0 = energy_at(on, p0, psi), e1 = energy_at(on, p1, psi + turn);
      ASSERT_GT(std::max(e0, e1), 1e-3) << a.what;  // in contact at one end, out at the other
      ASSERT_EQ(std::min(e0, e1), 0.0) << a.what;
      const SeatContact with = step_contact(on, p0, p1, psi, psi + turn);
      EXPECT_NE(with.skew, 0.0) << a.what << " turn " << turn;
      const double work = step_work(on, p0, p1, psi, psi + turn, nullptr);
      const double err = std::abs(work + e1 - e0) / std::abs(e1 - e0);
      EXPECT_LT(err, 1e-9) << a.what << " turn " << turn << ": work " << work << " dE " << e1 - e0;
      worst = std::max(worst, err);
      const double theta_work = step_work(off, p0, p1, psi, psi + turn, nullptr);
      theta_best = std::min(theta_best, std::abs(theta_work + e1 - e0) / std::abs(e1 - e0));
    }
  }
  std::printf(
      "pocket discrete gradient across the mouth within the clearance: |work + dE| / |dE| %.2e; "
      "the theta point's force at best %.3g\n",
      worst, theta_best);
  EXPECT_GT(theta_best, 1e-2);
}

// A slow crossing of the mouth: its jump is spread over the band (Ẽ continuous there), so the
// correction's force does not grow as the step shrinks — at most the band's steepest, 1.875 |J|/ℓ
// (ℓ = c/2), with the capture's share bound 2 k c — and the work is −ΔẼ at every |Δz|. A joint
// entering radially over the mouth's ramp (w = c) where its leftover jump is 0.9 of k ε²/6
// (1.5e-5 J; g found by bisection on the jump measured across the mouth), and one over the sharp
// mouth 3c off its vertex (2.07 J), from |Δz|/2 above the mouth to |Δz|/2 below it, the wheel
// held, for |Δz| from 0.4 mm down to 0.4 nm. (With the threshold at k ε²/6 the ramp's jump was
// corrected in full, J/|Δz| = 3.7e4 N at |Δz| = 0.4 nm; with the jump taken over the step and a
// share of it left from r = |J|/(|Δz| k c) = 1 on, 5151 N, the work missing ΔẼ by up to J.)
TEST(DynamicsPocketDiscreteGradient, ASlowCrossingOfTheMouthsBandIsBoundedAndExact) {
  Sprocket ramp = wheel8(true);
  const Sprocket sharp = wheel8(true);
  const double c = kClearance, psi = 0.4;
  ramp.pocket_mouth = c;
  const double eps = ramp.contact_smoothing, small = kStiffness * eps * eps / 6.0;
  const double spread = 1.875 / (0.5 * c), bound = 2.0 * kStiffness * c;
  // off the vertex so that g = (1 + x) c on the mouth: |e| = (2 + x) c, c/2 below it radially
  auto along_of = [&](double x) { return std::sqrt((2.0 + x) * (2.0 + x) - 0.25) * c; };
  auto jump_at = [&](double x) {
    const double along = along_of(x);
    return energy_at(ramp, near_vertex(ramp, psi, 2, along, 1e-12), psi) -
           energy_at(ramp, near_vertex(ramp, psi, 2, along, -1e-12), psi);
  };
  double lo = 0.0126, hi = 0.03;  // the jump grows with x over [0.0126, 0.03]
  for (int it = 0; it < 60; ++it) {
    const double m = 0.5 * (lo + hi);
    (jump_at(m) < 0.9 * small ? lo : hi) = m;
  }
  struct Across {
    const char* what;
    const Sprocket* w;
    double along;
  };
  const Across cases[] = {{"the ramp's leftover", &ramp, along_of(0.5 * (lo + hi))},
                          {"the sharp mouth", &sharp, 3.0 * c}};
  for (const Across& a : cases) {
    const double jump = std::abs(energy_at(*a.w, near_vertex(*a.w, psi, 2, a.along, 1e-12), psi) -
                                 energy_at(*a.w, near_vertex(*a.w, psi, 2, a.along, -1e-12), psi));
    ASSERT_GT(jump, 0.0) << a.what;
    double largest = 0.0;
    for (double dz = 4e-4; dz > 3e-10; dz *= 0.1) {
      const Point p0 = near_vertex(*a.w, psi, 2, a.along, -0.5 * dz);
      const Point p1 = near_vertex(*a.w, psi, 2, a.along, 0.5 * dz);
      const SeatContact with = step_contact(*a.w, p0, p1, psi, psi);
      const double force = std::abs(with.skew) * dz;
      largest = std::max(largest, force);
      EXPECT_LT(force, spread * jump + bound) << a.what << " |dz| " << dz;
      const double change = banded_at(*a.w, p1, psi) - banded_at(*a.w, p0, psi);
      const double work = step_work(*a.w, p0, p1, psi, psi, nullptr);
      EXPECT_LT(std::abs(work + change), 1e-9 + 1e-9 * std::abs(change))
          << a.what << " |dz| " << dz;
    }
    std::printf(
        "pocket discrete gradient across %s (jump %.3g J) from |dz| 0.4 mm to 0.4 nm: the "
        "correction's force at most %.4g N (bound 1.875 J/l + 2 k c = %.4g N)\n",
        a.what, jump, largest, spread * jump + bound);
  }
}

// The correction's derivatives across a jump where its rule is smooth (r ≤ 1: the jump taken in
// full): ∂S/∂x₁, ∂S/∂ψ₁ against central differences of S over the step's end (the θ point moving
// with it), for a joint leaving over the sharp mouth 3c off its vertex (2 µm in to 30 µm out:
// the θ point beyond the mouth), one crossing the
// capture near the mouth (the wheel turning 1e-3 and 0.03 rad over the step), and one entering
// the sharp mouth 3c off its vertex to end 20 µm below it, in the band where J ≠ 0 (the θ point
// 5 µm above the mouth: J's own Hessian at a θ point in the band is not taken). (Without J's slope,
// −(1 − φ)∇J and ∂J/∂ψ, in the end's gradient, the entering step's slope missed by about a
// quarter.)
TEST(DynamicsPocketDiscreteGradient, AcrossAJumpTheCorrectionsSlopeMatchesTheDifferences) {
  const Sprocket on = wheel8(true);
  const double c = kClearance, psi = 0.4;
  struct Across {
    const char* what;
    double along0, below0, along1, below1, turn;
  };
  const Across steps[] = {{"sharp mouth", 3.0 * c, 2e-6, 3.0 * c, -30e-6, 1e-3},
                          {"capture near the mouth", 9.9 * c, 20e-6, 10.1 * c, 20e-6, 0.03},
                          {"entering the sharp mouth", 3.0 * c, -30e-6, 3.2 * c, 20e-6, 1e-3}};
  for (const Across& a : steps) {
    const Point p0 = near_vertex(on, psi, 2, a.along0, a.below0);
    const Point p1 = near_vertex(on, psi + a.turn, 2, a.along1, a.below1);
    const double psi1 = psi + a.turn;
    const SeatContact with = step_contact(on, p0, p1, psi, psi1);
    ASSERT_NE(with.skew, 0.0) << a.what;
    const double hx = 1e-10, hp = 1e-10 / on.pitch_radius;
    const double fx = (step_contact(on, p0, {p1.x + hx, p1.y}, psi, psi1).skew -
                       step_contact(on, p0, {p1.x - hx, p1.y}, psi, psi1).skew) /
                      (2.0 * hx);
    const double fy = (step_contact(on, p0, {p1.x, p1.y + hx}, psi, psi1).skew -
                       step_contact(on, p0, {p1.x, p1.y - hx}, psi, psi1).skew) /
                      (2.0 * hx);
    const double fp = (step_contact(on, p0, p1, psi, psi1 + hp).skew -
                       step_contact(on, p0, p1, psi, psi1 - hp).skew) /
                      (2.0 * hp);
    const double scale = std::hypot(fx, fy, fp / on.pitch_radius);
    const double miss =
        std::hypot(with.skew_dx - fx, with.skew_dy - fy, (with.skew_dpsi - fp) / on.pitch_radius);
    std::printf(
        "pocket discrete gradient across %s: S %.4g N/m, |dS - FD| / |FD| %.2e (|FD| %.3g)\n",
        a.what, with.skew, miss / scale, scale);
    EXPECT_LT(miss, 1e-5 * scale) << a.what;
  }
}

// The share s(r) J of a jump left to the numerical term between r = |J| / (|Δz| k c) = 1 and 2
// (docs/models/dynamics.md, "The capture"): a joint crossing the body's capture 60 µm below the
// mouth (past the band: no shadow, Ẽ = E) from 9.9c to 10.1c off its vertex, the wheel turning
// by Δψ chosen so that r takes 0.8, 1.2, 1.5, 1.8 and 2.2. J is found here by bisection on
// pocket_contact's energy along the step's straight path in (q, ψ) (the half whose ends differ by
// more than 1 J holds it, to 1e-13 of the path), s(r) = x³(10 − 15x + 6x²), x = r − 1 clamped
// to [0, 1]: the work is −(ΔE − s J) to 1e-7 of J. And the correction's slope along the step,
// ∂S/∂x₁·Δq + ∂S/∂ψ₁ Δψ, against the central difference of S with the end moved by ±1e-5 of the
// step along its own line (the crossing's place, so J, does not move; the share's slope `dleft` is
// then the whole of J's part): within 1e-4 of it (6.5e-7 at r = 2.2, where the code's J,
// bracketed to 1e-9 c of each moved step, enters S whole; 2.7e-8 to 6.3e-8 within (1, 2); dleft
// dropped 1.0–1.5, mis-signed 2.0–3.0). The differences' error is J's rounding over 2h (5.3e-5
// at r = 2.2 with h = 1e-7, 5.5e-4 with h = 1e-8), their truncation, O(h²), below 3e-9 (the
// misses within (1, 2) below 3.8e-8 with h = 4e-5; 8.3e-8 at r = 2.2, J's rounding). (Across the
// line J moves with the crossing's place, which ∂S does not take: quasi-Newton there, not
// tested.)
TEST(DynamicsPocketDiscreteGradient, TheJumpsShareLeftBetweenRatiosOneAndTwo) {
  const Sprocket on = wheel8(true);
  const double c = kClearance, psi = 0.4, below = 60e-6, kc = kStiffness * c;
  auto ends = [&](double turn) {
    return std::pair{near_vertex(on, psi, 2, 9.9 * c, below),
                     near_vertex(on, psi + turn, 2, 10.1 * c, below)};
  };
  // the jump on the path (q₀ + t Δq, ψ₀ + t Δψ)
  auto jump_on_path = [&](Point p0, Point p1, double turn) {
    auto e = [&](double t) {
      return energy_at(on, {p0.x + t * (p1.x - p0.x), p0.y + t * (p1.y - p0.y)}, psi + t * turn);
    };
    double a = 0.0, b = 1.0, ea = e(a), eb = e(b);
    while (b - a > 1e-13) {
      const double m = 0.5 * (a + b), em = e(m);
      if (std::abs(em - ea) > 1.0)
        b = m, eb = em;
      else
        a = m, ea = em;
    }
    return eb - ea;
  };
  double worst_work = 0.0, worst_slope = 0.0;
  for (const double target : {0.8, 1.2, 1.5, 1.8, 2.2}) {
    // Δψ for r = |J| / (|Δz| k c) (the end turns with the wheel: |Δz| grows with Δψ, r falls),
    // by bisection
    auto ratio = [&](double turn, Point& p0, Point& p1, double& jump) {
      std::tie(p0, p1) = ends(turn);
      jump = jump_on_path(p0, p1, turn);
      const double dx = p1.x - p0.x, dy = p1.y - p0.y, rdpsi = on.pitch_radius * turn;
      return std::abs(jump) / (std::sqrt(dx * dx + dy * dy + rdpsi * rdpsi) * kc);
    };
    double lo = 0.0, hi = 0.1, jump = 0.0;
    Point p0, p1;
    for (int it = 0; it < 50; ++it) {
      const double m = 0.5 * (lo + hi);
      (ratio(m, p0, p1, jump) > target ? lo : hi) = m;
    }
    const double turn = 0.5 * (lo + hi), r = ratio(turn, p0, p1, jump);
    const double dx = p1.x - p0.x, dy = p1.y - p0.y;
    ASSERT_NEAR(r, target, 1e-3 * target);
    ASSERT_GT(std::abs(jump), 10.0);  // the capture's jump
    const double x = std::clamp(r - 1.0, 0.0, 1.0),
                 share = x * x * x * (10.0 - 15.0 * x + 6.0 * x * x);
    const double change = energy_at(on, p1, psi + turn) - energy_at(on, p0, psi);
    const double work = step_work(on, p0, p1, psi, psi + turn, nullptr);
    const double miss = std::abs(work + change - share * jump) / std::abs(jump);
    worst_work = std::max(worst_work, miss);
    EXPECT_LT(miss, 1e-7) << "r " << r;
    // S's slope along the step's line
    const SeatContact with = step_contact(on, p0, p1, psi, psi + turn);
    const double along = with.skew_dx * dx + with.skew_dy * dy + with.skew_dpsi * turn;
    const double h = 1e-5;  // of the step
    auto skew_at = [&](double f) {
      return step_contact(on, p0, {p1.x + f * dx, p1.y + f * dy}, psi, psi + turn * (1.0 + f)).skew;
    };
    const double fd = (skew_at(h) - skew_at(-h)) / (2.0 * h);
    const double slope_miss = std::abs(along - fd) / std::abs(fd);
    worst_slope = std::max(worst_slope, slope_miss);
    EXPECT_LT(slope_miss, 1e-4) << "r " << r << ": dS along " << along << ", FD " << fd;
    std::printf(
        "pocket discrete gradient, the jump's share at r %.3g (J %.4g J, turn %.4g rad): s %.4g, "
        "|work + dE - s J| / |J| %.2e; S's slope along the step %.4g against FD %.4g (%.2e)\n",
        r, jump, turn, share, miss, along, fd, slope_miss);
  }
  std::printf(
      "pocket discrete gradient, the jump's share: work misses -(dE - s J) by %.2e of J, S's slope "
      "along the step its differences by %.2e\n",
      worst_work, worst_slope);
}

// Only a step whose two ends lie on opposite sides of one of E_k's jump surfaces has a jump in
// ΔE: a step that dips across the mouth and back out is one branch's change, and is corrected
// like any other, its work −ΔE to rounding and its correction S continuous in how deep it dips.
// On the mouth's ramp (w = c) a held wheel's joint from 0.9c off its vertex, h₀ above the mouth,
// to 2.4c off, 1e-10 m above it: the straight path dips into the mouth by up to 8.5 nm for
// h₀ = 2e-8 to 6e-8 m, and passes above it at 8e-8 m. On the sharp mouth, a joint from 2c to 4c
// off its vertex, 1 nm above the mouth at both ends (E = 0 there) with the θ point inside
// (E > 0), held and turning 1e-3 rad: the work is −ΔE = 0. (Where the path's crossings were
// counted, the dipping steps kept the θ point's force: 0.42 J of work against the ramp's ΔE of
// 0.62 J, and work for no change of E over the sharp mouth.)
TEST(DynamicsPocketDiscreteGradient, ADipAcrossTheMouthAndBackIsCorrected) {
  const double c = kClearance, psi = 0.4;
  Sprocket ramp = wheel8(true);
  ramp.pocket_mouth = c;
  const double mouth = ramp.pitch_radius + 0.5 * c;
  // the straight path's least distance to the centre, less the mouth's radius
  auto dip = [&](Point p0, Point p1) {
    const double ax = p0.x - ramp.centre_x, ay = p0.y - ramp.centre_y;
    const double dx = p1.x - p0.x, dy = p1.y - p0.y;
    const double t = std::clamp(-(ax * dx + ay * dy) / (dx * dx + dy * dy), 0.0, 1.0);
    return std::hypot(ax + t * dx, ay + t * dy) - mouth;
  };
  std::vector<double> skews;
  for (const double h0 : {2e-8, 4e-8, 6e-8, 8e-8}) {
    const Point p0 = near_vertex(ramp, psi, 2, 0.9 * c, -h0);
    const Point p1 = near_vertex(ramp, psi, 2, 2.4 * c, -1e-10);
    const double depth = dip(p0, p1);
    if (h0 < 7e-8)
      ASSERT_LT(depth, 0.0) << h0;  // the path dips into the mouth, its ends above it
    else
      ASSERT_GT(depth, 0.0) << h0;
    const double change = energy_at(ramp, p1, psi) - energy_at(ramp, p0, psi);
    const SeatContact with = step_contact(ramp, p0, p1, psi, psi);
    const double work = step_work(ramp, p0, p1, psi, psi, nullptr);
    std::printf(
        "pocket discrete gradient dipping into the ramp's mouth from %g m: dip %.3g m, dE %.4g J, "
        "S %.5g N/m, work + dE %.3g J\n",
        h0, depth, change, with.skew, work + change);
    EXPECT_NE(with.skew, 0.0) << h0;
    EXPECT_LT(std::abs(work + change), 1e-12 * std::abs(change)) << h0;
    skews.push_back(with.skew);
  }
  for (std::size_t i = 1; i < skews.size(); ++i)
    EXPECT_LT(std::abs(skews[i] - skews[i - 1]), 1e-3 * std::abs(skews[i])) << i;
  const Sprocket sharp = wheel8(true);
  for (const double turn : {0.0, 1e-3}) {
    const Point p0 = near_vertex(sharp, psi, 2, 2.0 * c, -1e-9);
    const Point p1 = near_vertex(sharp, psi + turn, 2, 4.0 * c, -1e-9);
    const Point pt{0.5 * (p0.x + p1.x), 0.5 * (p0.y + p1.y)};
    ASSERT_EQ(energy_at(sharp, p0, psi), 0.0);
    ASSERT_EQ(energy_at(sharp, p1, psi + turn), 0.0);
    const double et = energy_at(sharp, pt, psi + 0.5 * turn);
    ASSERT_GT(et, 0.1) << turn;  // the θ point inside the mouth, 2c and more off its vertex
    const SeatContact with = step_contact(sharp, p0, p1, psi, psi + turn);
    const double work = step_work(sharp, p0, p1, psi, psi + turn, nullptr);
    const double scale = with.force * std::hypot(p1.x - p0.x, p1.y - p0.y);  // the θ point's
    std::printf(
        "pocket discrete gradient dipping into the sharp mouth, turn %g: E at the theta point "
        "%.4g J, its force's work %.4g J, work %.3g J\n",
        turn, et, scale, work);
    EXPECT_NE(with.skew, 0.0) << turn;
    EXPECT_LT(std::abs(work), 1e-14 * scale) << turn;
  }
}

// A crossing with no jump is corrected at any smoothing ε and clearance c: the energy's
// continuous part across the crossing's bracket does not read as a jump (the threshold k ε²/6
// falls as ε², that part, |∇E| times the bracket's 3e-9 c, grows with c). Over the mouth's ramp
// (w = c) near the vertex, where g ≤ c on the mouth (W = 1: the ramp's energy is the pocket's
// there), a joint entering from 2 µm above to 2 µm below the mouth: c = 0.1 mm and ε = 3 nm, 1 nm
// (1.2c off: g = 0.3c); c = 16 mm with ε = 1 µm and no body (1.6c and 1.7c off: g = 0.68c, 0.77c).
// And the capture straight below the vertex (10.4c to 10.6c below the mouth, beyond the body's
// radial band: no jump) with c = 0.1 mm, ε = 10 nm. Each held and turning 1e-3 rad: the work is
// −ΔE. (Where the jump was the two sides' difference alone, all these were skipped: work + ΔE up
// to 4.6e-4 of ΔE.)
TEST(DynamicsPocketDiscreteGradient, ACrossingWithNoJumpIsCorrectedAtAnySmoothingAndClearance) {
  struct Across {
    const char* what;
    double clearance, smoothing, mouth;  // c, ε, the ramp's width w, in c
    bool body;
    double along0, below0, along1, below1;  // in c, below in m
  };
  const double um = 1e-6;
  const Across steps[] = {
      {"ramp, eps 3 nm", 1e-4, 3e-9, 1.0, true, 1.2, -2 * um, 1.2, 2 * um},
      {"ramp, eps 1 nm", 1e-4, 1e-9, 1.0, true, 1.2, -2 * um, 1.2, 2 * um},
      {"ramp, c 16 mm, 1.6c", 16e-3, 1e-6, 1.0, false, 1.6, -2 * um, 1.6, 2 * um},
      {"ramp, c 16 mm, 1.7c", 16e-3, 1e-6, 1.0, false, 1.7, -2 * um, 1.7, 2 * um},
      {"capture deep, eps 10 nm", 1e-4, 1e-8, 0.0, true, 0.0, 10.4e-4, 0.0, 10.6e-4}};
  const double psi = 0.4;
  for (const Across& a : steps) {
    Sprocket w = pocket_wheel(0.064, 0.018, 8, 0.3, -0.2, a.clearance, kStiffness, 0.0);
    w.discrete_gradient = true;
    w.contact_smoothing = a.smoothing;
    w.pocket_mouth = a.mouth * a.clearance;
    w.pocket_body = a.body;
    const double c = a.clearance;
    if (a.mouth > 0.0) {  // W = 1 where the step crosses the mouth: g ≤ c there
      const Point on = near_vertex(w, psi, 2, a.along0 * c, 0.0);
      const Point vertex = near_vertex(w, psi, 2, 0.0, 0.5 * c);
      ASSERT_LT(std::hypot(on.x - vertex.x, on.y - vertex.y) - c, c) << a.what;
    }
    for (const double turn : {0.0, 1e-3}) {
      const Point p0 = near_vertex(w, psi, 2, a.along0 * c, a.below0);
      const Point p1 = near_vertex(w, psi + turn, 2, a.along1 * c, a.below1);
      const double change = energy_at(w, p1, psi + turn) - energy_at(w, p0, psi);
      const SeatContact with = step_contact(w, p0, p1, psi, psi + turn);
      const double work = step_work(w, p0, p1, psi, psi + turn, nullptr);
      std::printf(
          "pocket discrete gradient across no jump, %s, turn %g: dE %.4g J, S %.4g N/m, "
          "|work + dE| / |dE| %.2e\n",
          a.what, turn, change, with.skew, std::abs(work + change) / std::abs(change));
      ASSERT_GT(std::abs(change), 0.0) << a.what;
      EXPECT_NE(with.skew, 0.0) << a.what << " turn " << turn;
      EXPECT_LT(std::abs(work + change), 1e-9 * std::abs(change)) << a.what << " turn " << turn;
    }
  }
}

// The capture is sought only where the θ point's distance to its vertex is within the path's
// reach of `from` (max(θ, 1 − θ) (|Δq| + R |Δψ|)): a held wheel's joint 20 µm below the mouth
// from 9.82c to 10.02c off its vertex, its θ point 0.75 of the reach short of `from` = 10c
// and its end across it, where the pocket's energy jumps to the body's: the θ point's force is
// left out of the correction (r = |J| / (|Δz| k c) ≫ 2 on this 20 µm step: the share left is the
// whole jump, and S |Δz|² is the continuous part's 0.2 J against ΔE = 39 J); with the capture
// sought only within 0.6 of the reach, the jump is not seen and S |Δz|² is all of ΔE.
TEST(DynamicsPocketDiscreteGradient, CaptureIsSoughtWithinThePathsReachOfTheThetaPoint) {
  const Sprocket on = wheel8(true), off = wheel8(false);
  const double c = kClearance, psi = 0.4, from = 10.0 * c;
  const Point p0 = near_vertex(on, psi, 2, 9.82 * c, 20e-6);
  const Point p1 = near_vertex(on, psi, 2, 10.02 * c, 20e-6);
  const Point pt{0.5 * (p0.x + p1.x), 0.5 * (p0.y + p1.y)};
  const Point vertex = near_vertex(on, psi, 2, 0.0, 0.5 * c);
  auto dist = [&](Point q) { return std::hypot(q.x - vertex.x, q.y - vertex.y); };
  const double reach = 0.5 * std::hypot(p1.x - p0.x, p1.y - p0.y);
  ASSERT_LT(dist(p0), from);
  ASSERT_GT(dist(p1), from);
  ASSERT_GT(from - dist(pt), 0.6 * reach);
  ASSERT_LT(from - dist(pt), reach);
  const double change = energy_at(on, p1, psi) - energy_at(on, p0, psi);
  const SeatContact with = step_contact(on, p0, p1, psi, psi);
  const SeatContact without = step_contact(off, p0, p1, psi, psi);
  std::printf(
      "pocket discrete gradient across the capture, the theta point %.3g of the reach short of "
      "it: dE %.4g J, S %.4g N/m\n",
      (from - dist(pt)) / reach, change, with.skew);
  EXPECT_GT(std::abs(change), 1.0);  // the jump
  const double den = (p1.x - p0.x) * (p1.x - p0.x) + (p1.y - p0.y) * (p1.y - p0.y);
  EXPECT_LT(std::abs(with.skew) * den, 0.05 * std::abs(change));
  EXPECT_EQ(with.force, without.force);
}

// A link's two joints falling radially onto a driven pocket wheel at `inward` [m/s], the leading
// one `off` [m] along the pitch circle from vertex 1 and 10 µm above the mouth, both turning with
// the wheel at `spin` [rad/s] and sliding along it at `slip` [m/s]; the links undamped.
testing::PocketSetup fall_onto(double off, double inward, double spin, double slip, double damping,
                               bool gradient) {
  return testing::fall_setup({.off = off,
                              .above = 10e-6,
                              .inward = inward,
                              .spin = spin,
                              .slip = slip,
                              .driven = true,
                              .contact_damping = damping,
                              .discrete_gradient = gradient});
}

// A take-up's pocket wheel (driven, its slide along e = (0.6, 0.8) pushed by 500 N against
// 1e5 N/m, 2 kg): the step's Newton matrix against central differences of its residual, every
// column (the joints', the angle's and the slide's), with the leading joint on the body between
// the pockets — on the blend 1.5 mm off its vertex and on the rim 14 mm off, where the contact's
// whole ∂F/∂q is its dq_extra — with and without the discrete gradient, θ = 0.6, c_c = 2000.
TEST(DynamicsPocketDiscreteGradient, TakeupsNewtonMatrixOnTheBodyMatchesTheDifferences) {
  const double h = 1e-5;
  for (const double off : {1.5e-3, 14e-3}) {
    for (const bool gradient : {false, true}) {
      testing::PocketSetup f = testing::fall_setup({.off = off,
                                                    .above = 10e-6,
                                                    .inward = 2.0,
                                                    .spin = 5.0,
                                                    .driven = true,
                                                    .contact_damping = 2000.0,
                                                    .discrete_gradient = gradient});
      Model& m = f.model;
      State& s = f.state;
      Sprocket& w = m.sprockets[0];
      w.takeup = true;
      w.takeup_dx = 0.6;
      w.takeup_dy = 0.8;
      w.takeup_force = 500.0;
      w.takeup_stiffness = 1e5;
      w.takeup_mass = 2.0;
      Integrator integ(m, {.step = h, .theta = 0.6});
      const std::size_t n = s.nodes(), nu = integ.unknowns();
      ASSERT_EQ(nu, 2 * n + 2);  // the angle, then the slide
      const double r = w.pitch_radius;
      int checked = 0;
      double worst = 0.0;
      for (int step = 0; step < 120 && checked < 3; ++step) {
        ASSERT_TRUE(integ.step(m, s).converged) << step;
        const Sprocket here = at_slide(w, s.slide[0]);
        const SeatContact c =
            pocket_contact(here, s.x[0], s.y[0], s.vx[0] - s.slide_speed[0] * 0.6,
                           s.vy[0] - s.slide_speed[0] * 0.8, s.angle[0], s.speed[0]);
        if (!c.active || c.surface != 3 || !(c.force > 1.0) || step % 3) continue;
        std::vector<double> u(nu);
        for (std::size_t i = 0; i < n; ++i) {
          u[2 * i] = s.x[i] + h * s.vx[i];
          u[2 * i + 1] = s.y[i] + h * s.vy[i];
        }
        u[2 * n] = s.angle[0] + h * s.speed[0];
        u[2 * n + 1] = s.slide[0] + h * s.slide_speed[0];
        std::vector<double> res, jac;
        integ.newton_system(m, s, u, res, &jac);
        const testing::ColumnsAgainstDifferences d = testing::expect_columns_match_differences(
            integ, m, s, u, jac, {},
            [&](std::size_t col) { return col >= 2 * n ? 1e-10 / r : 1e-10; }, 1e-5);
        worst = std::max(worst, d.worst);
        ++checked;
      }
      std::printf(
          "pocket take-up's Newton matrix on the body (%.1f mm off, discrete gradient %d): %d "
          "iterates, worst |J - FD| / column scale %.2e\n",
          off * 1e3, gradient ? 1 : 0, checked, worst);
      EXPECT_GE(checked, 2) << off;
    }
  }
}

// The mouth's ramp (pocket_mouth = c) on a driven wheel: the step's Newton matrix against central
// differences of its residual, every column (the joints' and the wheel's angle), while the leading
// joint is on the ramp (its contact active beyond the mouth R + c/2), falling in at 1 m/s 1.5c
// off its vertex from 60 µm above the mouth, the wheel turning at 5 rad/s, θ = ½ undamped, with
// and without the discrete gradient. The ramp's own ∂F/∂q beyond the fields (dq_extra) turns
// with the wheel as the body's does: without it in the angle's column, row and diagonal the
// columns miss by 1.65e-3 of their scale here (checked; docs/models/dynamics.md, "Pocket wheel:
// the discrete gradient"). The tolerance, 1e-6, is tighter than the file's other matrix tests'
// 1e-5: the differences' noise here is 8.3e-8, and the wheel's own entry alone, left out, misses
// by 4e-5.
TEST(DynamicsPocketDiscreteGradient, RampsNewtonMatrixOnADrivenWheelMatchesTheDifferences) {
  const double h = 1e-5;
  for (const bool gradient : {false, true}) {
    testing::PocketSetup f = testing::fall_setup({.off = 1.5e-4,
                                                  .above = 60e-6,
                                                  .inward = 1.0,
                                                  .spin = 5.0,
                                                  .driven = true,
                                                  .discrete_gradient = gradient});
    Model& m = f.model;
    State& s = f.state;
    Sprocket& w = m.sprockets[0];
    w.pocket_mouth = w.pocket_clearance;
    Integrator integ(m, {.step = h, .theta = 0.5});
    const std::size_t n = s.nodes(), nu = integ.unknowns();
    ASSERT_EQ(nu, 2 * n + 1);
    const double r = w.pitch_radius, mouth = r + 0.5 * w.pocket_clearance;
    int checked = 0;
    double worst = 0.0;
    for (int step = 0; step < 40 && checked < 3; ++step) {
      ASSERT_TRUE(integ.step(m, s).converged) << step;
      const SeatContact c =
          pocket_contact(w, s.x[0], s.y[0], s.vx[0], s.vy[0], s.angle[0], s.speed[0]);
      if (!c.active || !(c.force > 1.0) || !(std::hypot(s.x[0], s.y[0]) > mouth)) continue;
      std::vector<double> u(nu);
      for (std::size_t i = 0; i < n; ++i) {
        u[2 * i] = s.x[i] + h * s.vx[i];
        u[2 * i + 1] = s.y[i] + h * s.vy[i];
      }
      u[2 * n] = s.angle[0] + h * s.speed[0];
      std::vector<double> res, jac;
      integ.newton_system(m, s, u, res, &jac);
      const testing::ColumnsAgainstDifferences d = testing::expect_columns_match_differences(
          integ, m, s, u, jac, {},
          [&](std::size_t col) { return col >= 2 * n ? 1e-10 / r : 1e-10; }, 1e-6);
      worst = std::max(worst, d.worst);
      ++checked;
    }
    std::printf(
        "pocket mouth's ramp on a driven wheel, Newton matrix (discrete gradient %d): %d iterates "
        "on the ramp, worst |J - FD| / column scale %.2e\n",
        gradient ? 1 : 0, checked, worst);
    EXPECT_GE(checked, 2);
  }
}

// (2) The step's Newton matrix with the discrete gradient against central differences of its
// residual, every column (the joints' and the driven wheel's angle), while the leading joint is in
// contact: in its pocket (falling in at 1 m/s), on the body's blend (1.5 mm off the vertex) and on
// its rim (14 mm off), the wheel turning at 5 rad/s, θ = 0.6 damped (c_c = 2000 N·s/m) and θ = ½
// undamped with the joints sliding along the wheel at 0.5 m/s. It is the discrete gradient's
// matrix: it differs from the θ point's at the same iterate (measured, printed), except on the rim
// at θ = ½, whose energy is a function of |q − O| alone (nearly linear over a step: the two agree
// to ~1e-7 of the column there, not asserted). Then where the θ point's force is 0 and the
// correction acts alone (its blocks the matrix's only contact terms): at iterates whose θ point
// is still within the clearance while the step's end is in the pocket (entering), and at iterates
// that pull a joint in contact back out fast enough for the damper to clamp the θ point's force.
TEST(DynamicsPocketDiscreteGradient, NewtonMatrixMatchesTheResidualsDifferences) {
  // the iterates checked: after a step with the joint pressed (force > 1 N), the next step's
  // prediction u = x + h v; the θ point out of contact and the end in; the damper's clamp
  enum class At { kForce, kAlone, kClamp };
  struct Case {
    double off, inward, slip, theta, damping;
    At at;
    double differs;  // the least departure from the θ point's matrix (of the column scale)
  };
  const Case cases[] = {{0.0, 1.0, 0.0, 0.6, 2000.0, At::kForce, 1e-4},
                        {0.0, 1.0, 0.5, 0.5, 0.0, At::kForce, 1e-5},
                        {1.5e-3, 2.0, 0.0, 0.6, 2000.0, At::kForce, 1e-4},
                        {1.5e-3, 2.0, 0.5, 0.5, 0.0, At::kForce, 3e-5},
                        {14e-3, 2.0, 0.0, 0.6, 2000.0, At::kForce, 1e-4},
                        {14e-3, 2.0, 0.5, 0.5, 0.0, At::kForce, 0.0},
                        {0.0, 1.0, 0.0, 0.6, 0.0, At::kAlone, 1e-4},
                        {0.0, 1.0, 0.0, 0.6, 2000.0, At::kClamp, 1e-4}};
  const double h = 1e-5;
  for (const Case& k : cases) {
    testing::PocketSetup f = fall_onto(k.off, k.inward, 5.0, k.slip, k.damping, true);
    const testing::PocketSetup plain = fall_onto(k.off, k.inward, 5.0, k.slip, k.damping, false);
    const Model& m = f.model;
    State& s = f.state;
    const Sprocket& w = m.sprockets[0];
    Integrator integ(m, {.step = h, .theta = k.theta});
    Integrator theta_point(plain.model, {.step = h, .theta = k.theta});
    const std::size_t n = s.nodes(), nu = integ.unknowns();
    ASSERT_EQ(nu, 2 * n + 1);
    const double r = w.pitch_radius;
    // the iterate u = x + a h v (joints and angle)
    const auto iterate = [&](double a) {
      std::vector<double> u(nu);
      for (std::size_t i = 0; i < n; ++i) {
        u[2 * i] = s.x[i] + a * h * s.vx[i];
        u[2 * i + 1] = s.y[i] + a * h * s.vy[i];
      }
      u[2 * n] = s.angle[0] + a * h * s.speed[0];
      return u;
    };
    // whether the leading joint's contact at iterate u is the case's: its θ point's force 0 (out
    // of contact with the end in, or clamped) and the discrete gradient's correction not 0
    const auto alone = [&](const std::vector<double>& u) {
      const double th = k.theta, vx = (u[0] - s.x[0]) / h, vy = (u[1] - s.y[0]) / h;
      const double qx = s.x[0] + th * h * vx, qy = s.y[0] + th * h * vy;
      const double om = (u[2 * n] - s.angle[0]) / h, psi = s.angle[0] + th * h * om;
      const SeatContact at = pocket_contact(w, qx, qy, vx, vy, psi, om);
      const SeatContact end = pocket_contact(w, u[0], u[1], 0.0, 0.0, u[2 * n], 0.0);
      const bool wanted = k.at == At::kAlone ? !at.active && end.active && end.energy > 0.0
                                             : at.active && !(at.force > 0.0);
      if (!wanted) return false;
      const PocketStep e = step_over(w, {s.x[0], s.y[0]}, {u[0], u[1]}, s.angle[0], u[2 * n], th);
      return pocket_step_contact(w, qx, qy, vx, vy, psi, om, kNoPocket, e).skew != 0.0;
    };
    int checked = 0;
    double worst = 0.0, differs = 0.0;
    for (int step = 0; step < 120 && checked < 6; ++step) {
      ASSERT_TRUE(integ.step(m, s).converged) << step;
      std::vector<double> u;
      if (k.at == At::kForce) {
        const SeatContact c =
            pocket_contact(w, s.x[0], s.y[0], s.vx[0], s.vy[0], s.angle[0], s.speed[0]);
        if (!c.active || !(c.force > 1.0) || step % 3) continue;
        u = iterate(1.0);
      } else {  // ahead (entering) or back out (the clamp)
        for (const double a : {1.0, 2.0, -1.0, -2.0}) {
          if (alone(iterate(a))) {
            u = iterate(a);
            break;
          }
        }
        if (u.empty()) continue;
      }
      std::vector<double> res, jac, jac_theta;
      integ.newton_system(m, s, u, res, &jac);
      theta_point.newton_system(plain.model, s, u, res, &jac_theta);
      const testing::ColumnsAgainstDifferences d = testing::expect_columns_match_differences(
          integ, m, s, u, jac, jac_theta,
          [&](std::size_t col) { return col == 2 * n ? 1e-10 / r : 1e-10; }, 1e-5);
      worst = std::max(worst, d.worst);
      differs = std::max(differs, d.differs / d.scale);
      ++checked;
    }
    const char* at = k.at == At::kForce   ? ""
                     : k.at == At::kAlone ? ", the correction alone"
                                          : ", the damper's clamp";
    std::printf(
        "pocket discrete gradient's Newton matrix (%.1f mm off, theta %.1f, c_c %.0f%s): %d "
        "iterates, worst |J - FD| / column scale %.2e, the theta point's matrix off by %.2e\n",
        k.off * 1e3, k.theta, k.damping, at, checked, worst, differs);
    EXPECT_GE(checked, k.at == At::kForce ? 3 : 1);
    if (k.differs > 0.0) {
      EXPECT_GE(differs, k.differs);
    }
  }
}

// (3) A wrap on a driver pocket wheel at θ = ½, undamped and frictionless (links and pockets):
// z = 8, turning clockwise at 5 rad/s, the tight strand (1000 N) level through the top vertex,
// half a turn of joints in their pockets and the slack strand (200 N) leaving at the bottom, the
// strands' ends pulled by constant forces, h = 0.1 ms over `steps` steps. The work balance: the
// driver's work Σ −τ Δψ against the change of the energy (kinetic, links', contacts', the end
// forces' potential). The mouth's ramp `mouth` (0: the sharp mouth, E's jump where a joint leaves
// across it, taken over the step as the rest of ΔE).
struct WrapRun {
  double kinetic0 = 0.0, worst = 0.0;
  double settled = INFINITY;  // the least |balance| over the last 200 steps
  int steps = 0;              // completed
};
WrapRun wrap_run(bool gradient, double mouth, int steps) {
  testing::PocketSetup setup =
      testing::unwinding_setup({.slack = 200.0, .mouth = mouth, .discrete_gradient = gradient});
  const Model& m = setup.model;
  State& s = setup.state;
  Integrator integ(m, {.step = 1e-4, .theta = 0.5});
  WrapRun out;
  const Energy e0 = energy(m, s);
  out.kinetic0 = e0.kinetic;
  double work = 0.0;
  for (int step = 0; step < steps; ++step) {
    const double a0 = s.angle[0];
    if (!integ.step(m, s).converged) break;
    work -= integ.applied_torque()[0] * (s.angle[0] - a0);
    const double balance = energy(m, s).total() - e0.total() - work;
    if (!std::isfinite(balance)) break;
    out.worst = std::max(out.worst, std::abs(balance));
    if (step >= steps - 200) out.settled = std::min(out.settled, std::abs(balance));
    out.steps = step + 1;
  }
  return out;
}

TEST(DynamicsPocketDiscreteGradient, WrapAtThetaHalfKeepsItsWorkBalance) {
  const int steps = 1000;  // 0.1 s
  const double ramp = kClearance;
  const WrapRun kept = wrap_run(true, ramp, steps), theta = wrap_run(false, ramp, steps);
  const WrapRun sharp = wrap_run(true, 0.0, steps), sharp_theta = wrap_run(false, 0.0, steps);
  std::printf(
      "pocket wrap at theta = 1/2 over 0.1 s (kinetic %.4g J), mouth's ramp c: work balance worst "
      "%.2e of the kinetic with the discrete gradient (%d steps), %.3g with the theta point's "
      "force (%d steps); sharp mouth: %.3g (%d steps; %.2e when no joint is in a band), %.3g "
      "(%d steps)\n",
      kept.kinetic0, kept.worst / kept.kinetic0, kept.steps, theta.worst / theta.kinetic0,
      theta.steps, sharp.worst / sharp.kinetic0, sharp.steps, sharp.settled / sharp.kinetic0,
      sharp_theta.worst / sharp.kinetic0, sharp_theta.steps);
  EXPECT_EQ(kept.steps, steps);
  EXPECT_LT(kept.worst, 1e-6 * kept.kinetic0);
  EXPECT_TRUE(theta.steps < steps || theta.worst > 100.0 * kept.worst);
  // the sharp mouth's exits: their jumps spread over the mouth's band, the balance off by the
  // band's share (1 − φ) J of the joints within it at the time (4.8e-3 of the kinetic at worst),
  // back to 8.9e-8 of it when none is (the least over the last 200 steps; 9.8e-3 and growing
  // when the steps across kept the θ point's force, the jumps adding up)
  EXPECT_EQ(sharp.steps, steps);
  EXPECT_LT(sharp.worst, 1e-2 * sharp.kinetic0);
  EXPECT_LT(sharp.settled, 1e-5 * sharp.kinetic0);
}

}  // namespace
}  // namespace catena::dynamics
