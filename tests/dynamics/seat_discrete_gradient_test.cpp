// The ISO seats' discrete gradient (Sprocket::discrete_gradient; docs/models/dynamics.md,
// "Sprockets: the discrete gradient"): the seat's elastic force over a step is
// (E(g₁) − E(g₀))/(g₁ − g₀) between the gaps at the step's ends, each in its own nearest seat (the
// θ point's within its mid-tooth lines). Its work on roller and wheel over one step against the
// change of the contact's energy (the penalty's, written out in penalty_ramp.hpp), also on a step
// across a mid-tooth line; the Newton matrix against central differences of the step's residual,
// and a roller-chain drive at θ = ½ whose work balance closes with it and not without it; the
// force's continuity where the contact switches, and the integrator's reach test for a roller
// entering over a tooth's tip.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

#include "catena/dynamics/integrator.hpp"
#include "penalty_ramp.hpp"
#include "pressed_loop.hpp"
#include "residual_difference.hpp"
#include "two_wheel_loops.hpp"

namespace catena::dynamics {
namespace {

constexpr double kPi = std::numbers::pi;
// 12B (ISO 606): pitch, roller diameter d1, inner width b1
constexpr double kPitch = 0.01905, kRoller = 0.01207, kWidth = 0.01168;
constexpr double kStiffness = 2e8, kSmoothing = 1e-6;  // [N/m], [m] the seats' penalty

// The seats' penalty's energy at the gap g (penalty_ramp.hpp): k_c g³/(6ε) within the ramp,
// k_c (g²/2 − ε g/2 + ε²/6) past it, 0 out of contact.
double penalty_energy(double g) { return testing::penalty_ramp_energy(kStiffness, kSmoothing, g); }

Sprocket wheel17(bool straight_flank) {
  Sprocket w = iso606_sprocket(kPitch, kRoller, kWidth, 17, 0.0, 0.0, kStiffness, 0.0);
  if (straight_flank) w.flank_radius = 0.0;  // the flank the straight line tangent to the arc
  w.discrete_gradient = true;
  return w;
}

struct Point {
  double x = 0.0, y = 0.0;
};
// The roller centre at gap g in seat 0 of wheel w turned to `angle`: on the seating arc at γ from
// the inward radial (|γ| < α/2), or, with `along` ≥ 0, on the straight flank (flank_radius 0) of
// the +t side, `along` [m] from the arc's end J along it. Both from the seat's geometry directly.
Point in_seat(const Sprocket& w, double angle, double g, double gamma, double along = -1.0) {
  const double cs = std::cos(angle), sn = std::sin(angle);
  const double cx = w.pitch_radius * cs, cy = w.pitch_radius * sn;  // the seat centre
  const double r = w.roller_radius, ri = w.seat_radius;
  double a = 0.0, b = 0.0;  // along the inward radial, along t = (−sin σ, cos σ)
  if (along < 0.0) {
    a = (ri - r + g) * std::cos(gamma);
    b = (ri - r + g) * std::sin(gamma);
  } else {
    const double ch = std::cos(0.5 * w.seating_angle), sh = std::sin(0.5 * w.seating_angle);
    // J + along·u + (g − r) m, m = (cos α/2, sin α/2) into the tooth, u = (−sin α/2, cos α/2)
    a = ri * ch - along * sh + (g - r) * ch;
    b = ri * sh + along * ch + (g - r) * sh;
  }
  return {cx - a * cs - b * sn, cy - a * sn + b * cs};
}

// The contact's energy with the roller at q and the wheel at `angle` (its nearest seat)
double energy_at(const Sprocket& w, Point q, double angle) {
  return seat_contact(w, q.x, q.y, 0.0, 0.0, angle, 0.0).energy;
}

// The contact over the step p0 → p1 (wheel ψ₀ → ψ₁, θ = ½) of h [s] (0.1 ms unless given), over
// the step or at the θ point (`gradient` false); the velocity (p1 − p0)/h.
SeatContact step_contact(const Sprocket& w, Point p0, Point p1, double psi0, double psi1,
                         bool gradient, double h = 1e-4) {
  const double theta = 0.5;
  const SeatGeometry t = seat_geometry(w);
  const double qx = p0.x + theta * (p1.x - p0.x), qy = p0.y + theta * (p1.y - p0.y);
  const double psi = psi0 + theta * (psi1 - psi0), omega = (psi1 - psi0) / h;
  const double vx = (p1.x - p0.x) / h, vy = (p1.y - p0.y) / h;
  const double k = nearest_seat(qx, qy, psi, t.tau);
  const SeatStep step{.x0 = p0.x,
                      .y0 = p0.y,
                      .x1 = p1.x,
                      .y1 = p1.y,
                      .angle0 = psi0,
                      .angle1 = psi1,
                      .h = h,
                      .turn = psi1 - psi0,
                      .theta = theta};
  return seat_contact_at(w, t, qx, qy, vx, vy, omega, k, std::cos(psi + k * t.tau),
                         std::sin(psi + k * t.tau), gradient ? &step : nullptr);
}

// The force on the roller over the step: −f n − S Δ
Point roller_force(const SeatContact& c) {
  return {-c.force * c.nx - c.skew * c.skew_x, -c.force * c.ny - c.skew * c.skew_y};
}

// One step's work on roller and wheel, the roller's force times x₁ − x₀ plus the torque times
// ψ₁ − ψ₀, with the force over the step (the discrete gradient) or at the θ point (`gradient`
// false); `surface` gets the θ point's. `direction_only` gets the work of the discrete gradient's
// force without its correction along the step (SeatContact::skew): f_e along the θ point's n.
double step_work(const Sprocket& w, Point p0, Point p1, double psi0, double psi1, bool gradient,
                 int* surface = nullptr, double* direction_only = nullptr) {
  const SeatContact c = step_contact(w, p0, p1, psi0, psi1, gradient);
  if (surface != nullptr) *surface = c.surface;
  const double dx = p1.x - p0.x, dy = p1.y - p0.y, dpsi = psi1 - psi0;
  const double along = -c.force * (c.nx * dx + c.ny * dy);
  const double r2 = w.pitch_radius * w.pitch_radius;
  if (direction_only != nullptr) *direction_only = along + (c.torque + c.skew * r2 * dpsi) * dpsi;
  if (!c.active) return 0.0;
  return along - c.skew * (c.skew_x * dx + c.skew_y * dy) + c.torque * dpsi;
}

// (1) Over one step the discrete gradient's work on roller and wheel is −ΔE of the contact: on
// the straight flank (flank_radius 0) of a held wheel, entering from 2 µm out, pressing, lifting,
// leaving, and over a step of 1e-13 m; on the seating arc (the roller's centre on a circle of
// ri − r ≈ 60 µm about the seat centre), and on a turning wheel, where the gap is not affine and
// the θ point's direction alone misses ΔE (measured), its correction along the step makes it
// exact. The θ point's force misses it by far.
TEST(DynamicsSeatDiscreteGradient, WorkOverAStepIsTheEnergysChange) {
  const Sprocket flat = wheel17(true);
  const double psi = 0.3;
  struct Step {
    double g0, g1;  // [m] the gaps at the ends
  };
  const Step steps[] = {{-2e-6, 3e-6},    {1e-6, 4e-6},  {5e-6, 0.5e-6},
                        {0.2e-6, 0.8e-6}, {2e-6, -1e-6}, {2e-6, 2e-6 + 1e-13}};
  double worst = 0.0, theta_worst = 0.0;
  for (const auto& [g0, g1] : steps) {
    const Point p0 = in_seat(flat, psi, g0, 0.0, 0.8e-3), p1 = in_seat(flat, psi, g1, 0.0, 0.9e-3);
    int surface = -1;
    const double work = step_work(flat, p0, p1, psi, psi, true, &surface);
    EXPECT_EQ(surface, 1) << "the flank";
    const double e0 = energy_at(flat, p0, psi), e1 = energy_at(flat, p1, psi);
    // the reference: the penalty at the gaps the geometry put the roller at
    EXPECT_NEAR(e0, penalty_energy(g0), 1e-6 * penalty_energy(g0) + 1e-18);
    EXPECT_NEAR(e1, penalty_energy(g1), 1e-6 * penalty_energy(g1) + 1e-18);
    const double change = e1 - e0, err = std::abs(work + change);
    // within 1e-9 of ΔE, and of the positions' rounding (~1e-17 m at 5 cm from the centre) times
    // the force, below 1e-16 m × k_c g
    EXPECT_LE(err, 1e-9 * std::abs(change) + 1e-16 * kStiffness * std::max(g0, g1))
        << g0 << " -> " << g1 << ": work " << work << " dE " << change;
    if (std::abs(g1 - g0) > 1e-9) worst = std::max(worst, err / std::abs(change));
    const double theta_work = step_work(flat, p0, p1, psi, psi, false);
    theta_worst = std::max(theta_worst, std::abs(theta_work + change) / std::abs(change));
  }
  EXPECT_GT(theta_worst, 0.1);
  // the seating arc of the ISO wheel, held: pressing 1 → 4 µm while swinging 0.1 → 0.12 rad, and
  // entering from the clearance (−2 µm at −0.5 rad) to 3 µm at +0.4 rad
  const Sprocket iso = wheel17(false);
  struct Swing {
    double g0, gamma0, g1, gamma1;
  };
  double arc_worst = 0.0, arc_direction = 0.0;
  for (const auto& [g0, gamma0, g1, gamma1] :
       {Swing{1e-6, 0.1, 4e-6, 0.12}, Swing{-2e-6, -0.5, 3e-6, 0.4}}) {
    const Point a0 = in_seat(iso, psi, g0, gamma0), a1 = in_seat(iso, psi, g1, gamma1);
    int surface = -1;
    double direction = 0.0;
    const double change = energy_at(iso, a1, psi) - energy_at(iso, a0, psi);
    const double work = step_work(iso, a0, a1, psi, psi, true, &surface, &direction);
    EXPECT_EQ(surface, 0) << "the seating arc";
    arc_worst = std::max(arc_worst, std::abs(work + change) / std::abs(change));
    arc_direction = std::max(arc_direction, std::abs(direction + change) / std::abs(change));
  }
  // a wheel turning at 30 rad/s for the step (3e-3 rad), the roller carried with it while pressing
  // 1 → 4 µm: on the straight flank sliding 0.1 mm along it, on the seating arc swinging 0.1 →
  // 0.12 rad
  double turn_worst = 0.0, turn_direction = 0.0;
  const double turn = 30.0 * 1e-4;
  const Point ends[2][2] = {
      {in_seat(flat, psi, 1e-6, 0.0, 0.8e-3), in_seat(flat, psi + turn, 4e-6, 0.0, 0.9e-3)},
      {in_seat(iso, psi, 1e-6, 0.1), in_seat(iso, psi + turn, 4e-6, 0.12)}};
  for (int j = 0; j < 2; ++j) {
    const Sprocket& w = j == 0 ? flat : iso;
    double direction = 0.0;
    const double change = energy_at(w, ends[j][1], psi + turn) - energy_at(w, ends[j][0], psi);
    const double work =
        step_work(w, ends[j][0], ends[j][1], psi, psi + turn, true, nullptr, &direction);
    turn_worst = std::max(turn_worst, std::abs(work + change) / std::abs(change));
    turn_direction = std::max(turn_direction, std::abs(direction + change) / std::abs(change));
  }
  std::printf(
      "seat discrete gradient: |work + dE| / |dE| worst %.2e on a held straight flank (the theta "
      "point's force: %.3g); seating arc %.2e (the theta point's direction alone: %.2e); turning "
      "wheel %.2e (alone: %.2e)\n",
      worst, theta_worst, arc_worst, arc_direction, turn_worst, turn_direction);
  EXPECT_LT(arc_worst, 1e-9);
  EXPECT_LT(turn_worst, 1e-9);
  EXPECT_GT(arc_direction, 1e-5);  // what the correction puts back
  // a step of 1e-15 … 1e-12 m on the seating arc (held wheel, the roller 2 µm in): the correction
  // would be the gaps' rounding over |Δ|² (S = 1.9e14 N/m at 1e-15 m, 7e7 N/m at 1e-12 m); below
  // |Δz| = 1e-9 R it is skipped, S = 0, and the work still closes within the positions' rounding
  // times the force. Just above (2e-10 m, 1e-9 m) it is bounded by the arc's curvature: S ≤
  // f_e κ = f_e/(ri − r).
  const Point held = in_seat(iso, psi, 2e-6, 0.1);
  double tiny_stiffness = 0.0;
  for (const double d : {1e-15, 1e-13, 1e-12, 2e-10, 1e-9}) {
    const Point moved{held.x + d, held.y + 0.3 * d};
    const SeatContact c = step_contact(iso, held, moved, psi, psi, true);
    ASSERT_TRUE(c.active);
    const double arc_curvature = 1.0 / (iso.seat_radius - iso.roller_radius);
    EXPECT_LE(std::abs(c.skew), c.force * arc_curvature) << "step " << d << " m";
    if (d < 1e-9 * iso.pitch_radius) {  // nor its Newton block
      EXPECT_EQ(c.skew, 0.0) << "step " << d << " m";
      EXPECT_EQ(std::abs(c.skew_dx) + std::abs(c.skew_dy) + std::abs(c.skew_dpsi), 0.0);
    }
    tiny_stiffness = std::max(tiny_stiffness, std::abs(c.skew));
    const double change = energy_at(iso, moved, psi) - energy_at(iso, held, psi);
    const double work = step_work(iso, held, moved, psi, psi, true);
    EXPECT_LE(std::abs(work + change), 1e-16 * kStiffness * 2e-6) << "step " << d << " m";
  }
  std::printf("seat discrete gradient: steps 1e-15 ... 1e-9 m on the arc: |S| at most %.3g N/m\n",
              tiny_stiffness);
}

// The residual's continuity where the discrete gradient switches. (a) A z = 12 wheel's tip (a
// convex surface), seats damped (800 N s/m): a roller moving 1 µm inwards across the mid-tooth
// line, its end gap g₁ crossing 0 while the θ point, on the chord, is about 3 µm inside the tip
// circle: with both ends clear there is no force (the elastic part and the damper are both taken
// over the step), and just past g₁ = 0 hardly any, so the force does not jump as g₁ crosses 0.
// (b) A roller leaving the seating arc (3 → 0.5 µm, swinging 0.1 → 0.3 rad) with the damper
// pulling the total force to 0 at a step h* short enough: the correction along the step S Δ
// (S = f cc, f the clamped total) goes to 0 with it, so the roller's force is continuous across h*.
TEST(DynamicsSeatDiscreteGradient, ForceIsContinuousWhereTheContactSwitches) {
  Sprocket tip = iso606_sprocket(kPitch, kRoller, kWidth, 12, 0.0, 0.0, kStiffness, 800.0);
  tip.discrete_gradient = true;
  const double tau = 2.0 * kPi / 12.0, mid = -0.5 * tau, half = 0.012;
  const double touch = tip.tip_radius + tip.roller_radius;
  double force[2] = {0.0, 0.0};
  for (int j = 0; j < 2; ++j) {
    const double g1 = j == 0 ? -1e-10 : 1e-10, r1 = touch - g1, r0 = r1 + 1e-6;
    const Point p0{r0 * std::cos(mid - half), r0 * std::sin(mid - half)};
    const Point p1{r1 * std::cos(mid + half), r1 * std::sin(mid + half)};
    const SeatContact theta_point = step_contact(tip, p0, p1, 0.0, 0.0, false);
    ASSERT_EQ(theta_point.surface, 3) << "the tip";
    ASSERT_GT(theta_point.penetration, 2e-6);
    const SeatContact c = step_contact(tip, p0, p1, 0.0, 0.0, true);
    force[j] = c.force;
    // with both ends clear it is no contact at all: no force, and no depth for max_penetration
    EXPECT_EQ(c.active, j == 1) << "g1 = " << g1;
  }
  std::printf("seat discrete gradient: the tip's force at g1 = -/+ 1e-10 m: %.6g / %.6g N\n",
              force[0], force[1]);
  EXPECT_EQ(force[0], 0.0);  // both ends clear
  EXPECT_LT(force[1], 1e-3);
  // (b) the held ISO wheel, damped
  Sprocket seat = wheel17(false);
  seat.contact_damping = 800.0;
  const double psi = 0.3;
  const Point a0 = in_seat(seat, psi, 3e-6, 0.1), a1 = in_seat(seat, psi, 0.5e-6, 0.3);
  // f = f_e + D/h (D = C(g₁) − C(g₀) < 0, leaving): f_e and D from two steps, 0 at h* = −D/f_e
  const double h1 = 1e-4, h2 = 2e-4;
  const SeatContact c1 = step_contact(seat, a0, a1, psi, psi, true, h1);
  const SeatContact c2 = step_contact(seat, a0, a1, psi, psi, true, h2);
  ASSERT_GT(c1.force, 0.0);
  const double d = (c1.force - c2.force) / (1.0 / h1 - 1.0 / h2), fe = c1.force - d / h1;
  ASSERT_LT(d, 0.0);
  const double clamp_at = -d / fe;
  ASSERT_LT(clamp_at, h1);
  const SeatContact before = step_contact(seat, a0, a1, psi, psi, true, clamp_at * (1.0 + 1e-9));
  const SeatContact after = step_contact(seat, a0, a1, psi, psi, true, clamp_at * (1.0 - 1e-9));
  EXPECT_GT(before.force, 0.0);
  EXPECT_EQ(after.force, 0.0);
  const Point fb = roller_force(before), fa = roller_force(after);
  const double correction = std::abs(c1.skew) * std::hypot(c1.skew_x, c1.skew_y);
  std::printf(
      "seat discrete gradient: the damper clamps the force at a step of %.4g s; the correction "
      "|S D| %.3g N at 0.1 ms, the force's jump %.3g N across the clamp\n",
      clamp_at, correction, std::hypot(fa.x - fb.x, fa.y - fb.y));
  EXPECT_GT(correction, 0.1);
  EXPECT_LT(std::hypot(fa.x - fb.x, fa.y - fb.y), 1e-6 * correction + 1e-6);
}

// (1c) A step whose ends straddle a mid-tooth line (the roller travelling millimetres relative to
// the wheel in a step: thrown over a tooth, a coarse step, a far Newton iterate): each end's gap
// is taken in its own nearest seat. On a z = 12 wheel (12B, held or turning 3e-3 rad) the roller
// starts touching the corner K of seat 1's tooth from outside (g₀ = 3 µm, 45° between the outward
// radial and the tangent) and ends at the mirror point across the tooth's centre line, touching
// seat 0's corner, turned a little further (2e-5 rad) so that the θ point, on the chord over the
// tip, is seat 0's; the same turned by π − τ/2, so that the tooth's centre line lies on the
// arctangent's cut at ±π and the start's nearest_seat index is 1 − z (seat 1 a turn back). Read
// in seat 0 (the rule until 2026-11-27) the start is on the tip circle continued past K, 1.58 mm
// deep: the elastic force (E(g₁) − E(g₀))/(g₁ − g₀) between the penalty's energies was 1.58e5 N
// (printed below; the roller's whole force, with the correction along the step, 1.59e5 N, the
// old rule put back) and the work −ΔE of an energy the contact does not have. With each end in its
// own seat the work is −ΔE of the contact's energy (seat_contact's, the nearest seat) at the
// ends. The gap is continuous across the line: there both seats' gaps are equal (the tooth is
// symmetric about it), checked on the line from 0.2 R to 2 R for z = 6 … 25 (z ≤ 10 with the
// tip lowered by iso606_sprocket), with the ISO flank arc and the straight flank, each with its
// tip circle and without one (each form set before seat_geometry is taken). An end just inside
// seat k's mid-tooth line (within the sector test's 1e-9 margin) whose nearest_seat index is
// k − z, past the cut, is read with seat k's direction bit for bit (the half-turn reduction).
TEST(DynamicsSeatDiscreteGradient, StepAcrossAMidToothLineTakesEachEndInItsOwnSeat) {
  int lines = 0, touching = 0;
  double worst_line = 0.0;
  for (const int z : {6, 8, 9, 10, 12, 17, 25}) {
    for (const bool straight : {false, true}) {
      for (const bool tip : {true, false}) {
        Sprocket w = iso606_sprocket(kPitch, kRoller, kWidth, z, 0.0, 0.0, kStiffness, 0.0);
        if (straight) w.flank_radius = 0.0;
        if (!tip) w.tip_radius = 0.0;
        const SeatGeometry t = seat_geometry(w);
        EXPECT_EQ(t.has_corner, tip) << "z " << z;  // the form taken
        const double line = 0.5 * t.tau;            // between seats 0 and 1 at ψ = 0
        for (int i = 0; i <= 360; ++i) {
          const double rho = (0.2 + 0.005 * i) * w.pitch_radius;
          const double x = rho * std::cos(line), y = rho * std::sin(line);
          double gap[2] = {0.0, 0.0};
          for (int k = 0; k < 2; ++k) {
            const SeatContact c = seat_contact_at(w, t, x, y, 0.0, 0.0, 0.0, k, std::cos(k * t.tau),
                                                  std::sin(k * t.tau));
            gap[k] = c.active ? c.penetration : 0.0;
          }
          EXPECT_NEAR(gap[0], gap[1], 1e-15)
              << "z " << z << " straight " << straight << " tip " << tip << " rho " << rho;
          worst_line = std::max(worst_line, std::abs(gap[0] - gap[1]));
          ++lines;
          if (gap[0] > 0.0) ++touching;
        }
      }
    }
  }
  std::printf(
      "seat discrete gradient: the two seats' gaps on the mid-tooth line, %d points (%d in "
      "contact): largest difference %.2e m\n",
      lines, touching, worst_line);
  EXPECT_GT(touching, lines / 2);
  Sprocket w12 = iso606_sprocket(kPitch, kRoller, kWidth, 12, 0.0, 0.0, kStiffness, 0.0);
  w12.discrete_gradient = true;
  const SeatGeometry t = seat_geometry(w12);
  ASSERT_TRUE(t.has_corner);
  const double tau = t.tau, r = w12.roller_radius, g0 = 3e-6;
  // K in seat 1's frame: its polar angle from seat 1's radial towards seat 0, and its radius
  const double phi_k = std::atan2(t.kb, w12.pitch_radius - t.ka);
  const double rho_k = std::hypot(w12.pitch_radius - t.ka, t.kb);
  double worst[2] = {0.0, 0.0}, old_depth = 0.0, old_force = 0.0, old_error = 0.0;
  const double cut = kPi - 0.5 * tau;  // the tooth's centre line on the cut at ±π
  for (const double at : {0.0, cut}) {
    for (const double turn : {0.0, 3e-3}) {
      // at ψ₀ = 0: the start touching seat 1's corner from outside, the end its mirror about the
      // tooth's centre line τ/2 turned on by 2e-5 rad, then carried with the wheel by `turn`; all
      // turned by `at` (the wheel at ψ₀ = at)
      const double ak = tau - phi_k;
      const double ux = std::cos(ak) - std::sin(ak), uy = std::sin(ak) + std::cos(ak);
      const Point q0{rho_k * std::cos(ak) + (r - g0) * ux / std::sqrt(2.0),
                     rho_k * std::sin(ak) + (r - g0) * uy / std::sqrt(2.0)};
      const double polar0 = std::atan2(q0.y, q0.x), rho0 = std::hypot(q0.x, q0.y);
      const double polar1 = tau - polar0 - 2e-5 + turn;
      const Point p0{rho0 * std::cos(polar0 + at), rho0 * std::sin(polar0 + at)};
      const Point p1{rho0 * std::cos(polar1 + at), rho0 * std::sin(polar1 + at)};
      const SeatContact start = seat_contact(w12, p0.x, p0.y, 0.0, 0.0, at, 0.0);
      const SeatContact end = seat_contact(w12, p1.x, p1.y, 0.0, 0.0, at + turn, 0.0);
      ASSERT_TRUE(start.active && end.active);
      EXPECT_EQ(start.seat, at == 0.0 ? 1 : 1 - 12) << "past the cut: seat 1 a turn back";
      EXPECT_EQ(end.seat, 0);
      EXPECT_NEAR(start.penetration, g0, 1e-9);  // the corner's gap, as built
      const SeatContact c = step_contact(w12, p0, p1, at, at + turn, true);
      ASSERT_TRUE(c.active);
      EXPECT_EQ((c.seat + 12) % 12, 0) << "the theta point's seat (−12 past the cut)";
      const double change = end.energy - start.energy;
      const double work = step_work(w12, p0, p1, at, at + turn, true);
      const double scale = std::max(start.energy, end.energy);
      worst[at != 0.0] = std::max(worst[at != 0.0], std::abs(work + change) / scale);
      EXPECT_LE(std::abs(work + change), 1e-9 * scale) << "at " << at << " turn " << turn;
      // the force stays of the ends' size (k_c g, 600 N at 3 µm)
      EXPECT_LT(std::hypot(roller_force(c).x, roller_force(c).y), 10.0 * kStiffness * g0);
      // the start read in seat 0 (the θ point's), as the rule until 2026-11-27 took it
      const SeatContact misread =
          seat_contact_at(w12, t, p0.x, p0.y, 0.0, 0.0, 0.0, 0.0, std::cos(at), std::sin(at));
      ASSERT_TRUE(misread.active);
      EXPECT_GT(misread.penetration, 1e-3);
      old_depth = std::max(old_depth, misread.penetration);
      const double old_change =
          penalty_energy(end.penetration) - penalty_energy(misread.penetration);
      old_force =
          std::max(old_force, std::abs(old_change / (end.penetration - misread.penetration)));
      old_error = std::max(old_error, std::abs(old_change - change) / scale);
    }
  }
  std::printf(
      "seat discrete gradient across a mid-tooth line (z = 12): |work + dE| / E worst %.2e "
      "(turned onto the cut: %.2e); the "
      "start read in the theta point's seat: %.3g mm deep, the elastic force %.4g N, the energy's "
      "change off by %.3g times E\n",
      worst[0], worst[1], 1e3 * old_depth, old_force, old_error);
  // The half-turn reduction: seat 6 of the held z = 12 wheel at ψ = −0.2 (its radial at π − 0.2,
  // short of the cut; its mid-tooth line towards seat 7 at π + 0.06, past it), a roller seated
  // 3 µm deep moving onto the tooth towards seat 7 and ending on the tip (2 µm in) just inside
  // seat 6's mid-tooth line: within the sector test's margin (1e-9 of tan(τ/2): 2.5e-10 rad), so
  // the test sends it to nearest_seat, which gives −6 past the cut. k + m is seat 6 whether m is
  // reduced or not; reduced (m = 0) the end is read with seat 6's own (cos σ, sin σ), bit for bit,
  // not those of σ − 2π.
  const double psi = -0.2, k6 = 6.0, sigma6 = psi + k6 * tau;
  const Point seated = in_seat(w12, sigma6, 3e-6, 0.0);
  const double rho_tip = w12.tip_radius + r - 2e-6, polar_end = sigma6 + 0.5 * tau - 1e-11;
  const Point on_tip{rho_tip * std::cos(polar_end), rho_tip * std::sin(polar_end)};
  ASSERT_EQ(nearest_seat(on_tip.x, on_tip.y, psi, tau), k6 - 12.0);
  const SeatContact sliver = step_contact(w12, seated, on_tip, psi, psi, true);
  ASSERT_TRUE(sliver.active);
  ASSERT_EQ(sliver.seat, 6) << "the theta point's seat";
  const SeatContact own = seat_contact_at(w12, t, on_tip.x, on_tip.y, 0.0, 0.0, 0.0, k6,
                                          std::cos(sigma6), std::sin(sigma6));
  ASSERT_TRUE(own.active);
  EXPECT_NEAR(own.penetration, 2e-6, 1e-9);
  EXPECT_EQ(sliver.step_nx, own.nx);
  EXPECT_EQ(sliver.step_ny, own.ny);
  const double sliver_change = energy_at(w12, on_tip, psi) - energy_at(w12, seated, psi);
  const double sliver_work = step_work(w12, seated, on_tip, psi, psi, true);
  EXPECT_LE(std::abs(sliver_work + sliver_change), 1e-9 * std::abs(sliver_change));
}

// (1b) The damper over the step: f_d = (C(g₁) − C(g₀))/h with C(g) = ∫₀^g c(s) ds, c(s) = c_c
// min(1, s/ε), written out in penalty_ramp.hpp. Over one step the contact's work on roller and
// wheel is −ΔE − (C(g₁) − C(g₀)) Δg/h (the damper's −c̄ Δg²/h ≤ 0), and the reported damper's work
// h·damping_power is that share, ≤ 0: on the held straight flank entering from 2 µm out, pressing
// within the ramp and past it, lifting and leaving; on the seating arc swinging, and on a wheel
// turning 3e-3 rad over the step (the correction along the step carries the damper's share too).
// The θ point's damper c(g_θ) ġ_θ differs within the ramp and its work misses Δg on a curved path.
double damper_potential(double g, double c) {
  return testing::penalty_ramp_force(c, kSmoothing, g);
}

TEST(DynamicsSeatDiscreteGradient, DamperWorkOverAStepIsNeverPositive) {
  const double c = 800.0, h = 1e-4, psi = 0.3, turn = 30.0 * 1e-4;
  Sprocket flat = wheel17(true), iso = wheel17(false);
  flat.contact_damping = iso.contact_damping = c;
  struct Case {
    const Sprocket* w;
    Point p0, p1;
    double psi1, g0, g1;
  };
  std::vector<Case> cases;
  for (const auto& [g0, g1] : {std::pair{-2e-6, 3e-6},
                               {0.2e-6, 0.8e-6},
                               {0.3e-6, 2.5e-6},
                               {1e-6, 4e-6},
                               {5e-6, 0.5e-6},
                               {2e-6, -1e-6},
                               {0.9e-6, -3e-6}}) {
    cases.push_back({&flat, in_seat(flat, psi, g0, 0.0, 0.8e-3),
                     in_seat(flat, psi, g1, 0.0, 0.9e-3), psi, g0, g1});
  }
  cases.push_back(
      {&iso, in_seat(iso, psi, 0.4e-6, 0.1), in_seat(iso, psi, 4e-6, 0.12), psi, 0.4e-6, 4e-6});
  cases.push_back({&iso, in_seat(iso, psi, 3e-6, 0.1), in_seat(iso, psi + turn, 0.5e-6, 0.3),
                   psi + turn, 3e-6, 0.5e-6});
  cases.push_back({&iso, in_seat(iso, psi, -2e-6, -0.5), in_seat(iso, psi + turn, 0.7e-6, 0.4),
                   psi + turn, -2e-6, 0.7e-6});
  double worst = 0.0, worst_damper = 0.0;
  for (const Case& k : cases) {
    const Sprocket& w = *k.w;
    const SeatContact sc = step_contact(w, k.p0, k.p1, psi, k.psi1, true, h);
    ASSERT_TRUE(sc.active);
    const double dx = k.p1.x - k.p0.x, dy = k.p1.y - k.p0.y, dpsi = k.psi1 - psi;
    const double work = -sc.force * (sc.nx * dx + sc.ny * dy) -
                        sc.skew * (sc.skew_x * dx + sc.skew_y * dy) + sc.torque * dpsi;
    const double change = energy_at(w, k.p1, k.psi1) - energy_at(w, k.p0, psi);
    const double dg = k.g1 - k.g0;
    const double damper = (damper_potential(k.g1, c) - damper_potential(k.g0, c)) / h;
    const double fe = (penalty_energy(k.g1) - penalty_energy(k.g0)) / dg;
    ASSERT_GT(fe + damper, 0.0) << k.g0 << " -> " << k.g1 << ": not clamped";
    const double dissipated = -damper * dg;  // the damper's work, −c̄ Δg²/h
    EXPECT_LE(h * sc.damping_power, 0.0) << k.g0 << " -> " << k.g1;
    const double err = std::abs(work - (-change + dissipated));
    const double scale = std::abs(change) + std::abs(dissipated);
    EXPECT_LE(err, 1e-8 * scale) << k.g0 << " -> " << k.g1 << ": work " << work << ", -dE "
                                 << -change << ", damper " << dissipated;
    EXPECT_NEAR(h * sc.damping_power, dissipated, 1e-8 * scale) << k.g0 << " -> " << k.g1;
    worst = std::max(worst, err / scale);
    worst_damper = std::max(worst_damper, std::abs(h * sc.damping_power - dissipated) / scale);
  }
  std::printf(
      "seat discrete gradient, damped (800 N s/m): |work - (-dE + damper's)| worst %.2e of the "
      "step's |dE| + |damper's|; the reported damper's work %.2e\n",
      worst, worst_damper);
  // The clamp: a fast exit (3 → 0.5 µm in a step) against a heavy damper (2e5 N s/m) pulls
  // f_e + f_d below 0. No force, no correction along the step, and the damper's reported work is
  // f_e Δg < 0: the contact does no work, so the damper took all of the elastic energy released.
  const double heavy_c = 2e5, g0 = 3e-6, g1 = 0.5e-6;
  Sprocket heavy = wheel17(true);
  heavy.contact_damping = heavy_c;
  const SeatContact clamped = step_contact(heavy, in_seat(heavy, psi, g0, 0.0, 0.8e-3),
                                           in_seat(heavy, psi, g1, 0.0, 0.9e-3), psi, psi, true, h);
  const double fe = (penalty_energy(g1) - penalty_energy(g0)) / (g1 - g0);
  ASSERT_LT(fe + (damper_potential(g1, heavy_c) - damper_potential(g0, heavy_c)) / h, 0.0)
      << "the case must clamp";
  EXPECT_EQ(clamped.force, 0.0);
  EXPECT_EQ(clamped.skew, 0.0);
  EXPECT_LT(h * clamped.damping_power, 0.0);
  EXPECT_NEAR(h * clamped.damping_power, fe * (g1 - g0), 1e-8 * std::abs(fe * (g1 - g0)));
}

// The caller's memo of the step's start (SeatStep::start, kept by the integrator over a step's
// Newton iterations) gives the contact bit for bit as without it: filled by one call and read by
// the next that differs in one of its key's inputs alone — the start x₀, the start's angle ψ₀,
// the start's wheel centre (a take-up's), the θ point's seat index (seat 0 as k = −z, as
// nearest_seat gives it past the cut at ±π: the same seat, its direction rounded otherwise) — it
// is taken afresh (each fails with that key's comparison dropped), and a call with the key it
// holds reads it (a memo whose gap is altered under the same key moves the force). A call for the
// residual alone (SeatStep::jacobian false, the integrator's line search and report) gives the
// same contact bit for bit but for the derivatives, left 0, and the same seat friction (μ = 0.2:
// seat_friction's force, power and torque, the residual's).
TEST(DynamicsSeatDiscreteGradient, StartsMemoGivesTheSameContact) {
  Sprocket w = wheel17(false);
  w.contact_damping = 800.0;  // [N·s/m] the damper's integral C(g₀) kept too
  w.friction = 0.2;
  const SeatGeometry t = seat_geometry(w);
  const double psi = 0.3, turn = 2e-3, h = 1e-4, z = 17.0;
  const Point a0 = in_seat(w, psi, 2e-6, 0.10), a1 = in_seat(w, psi + turn, 3.5e-6, 0.16);
  const Point b0 = in_seat(w, psi, 5e-6, 0.12);  // another start, deeper
  struct Call {
    Point p0;
    double k = 0.0;                 // the θ point's seat index
    double dpsi0 = 0.0, dcx = 0.0;  // ψ₀ and the start's centre (cx0, cy0) moved alone
  };
  const Call calls[] = {{a0}, {a0},     {b0}, {a0}, {a0, 0.0, 4e-4}, {a0}, {a0, 0.0, 0.0, 2e-5},
                        {a0}, {a0, -z}, {a0}};
  auto contact = [&](const Call& call, SeatStart* memo, bool jacobian = true) {
    const double psi0 = psi + call.dpsi0, psi1 = psi + turn, th = 0.5;
    const SeatStep step{.x0 = call.p0.x,
                        .y0 = call.p0.y,
                        .x1 = a1.x,
                        .y1 = a1.y,
                        .angle0 = psi0,
                        .angle1 = psi1,
                        .cx0 = call.dcx,
                        .cy0 = -0.5 * call.dcx,
                        .h = h,
                        .turn = psi1 - psi0,
                        .theta = th,
                        .start = memo,
                        .jacobian = jacobian};
    const double qx = call.p0.x + th * (a1.x - call.p0.x), qy = call.p0.y + th * (a1.y - call.p0.y);
    const double psit = psi0 + th * (psi1 - psi0), sigma = psit + call.k * t.tau;
    return seat_contact_at(w, t, qx, qy, (a1.x - call.p0.x) / h, (a1.y - call.p0.y) / h,
                           (psi1 - psi0) / h, call.k, std::cos(sigma), std::sin(sigma), &step);
  };
  SeatStart memo;
  double force[std::size(calls)];
  for (std::size_t i = 0; i < std::size(calls); ++i) {
    const Call& call = calls[i];
    const SeatContact without = contact(call, nullptr);
    const SeatContact with = contact(call, &memo);
    ASSERT_TRUE(without.active) << i;
    EXPECT_NE(without.skew, 0.0) << i;  // a turning wheel on the seating arc: corrected
    EXPECT_TRUE(memo.set);
    EXPECT_EQ(memo.seat, call.k) << i;
    EXPECT_EQ(with.force, without.force) << i;
    EXPECT_EQ(with.torque, without.torque) << i;
    EXPECT_EQ(with.damping_power, without.damping_power) << i;
    EXPECT_EQ(with.skew, without.skew) << i;
    EXPECT_EQ(with.skew_dx, without.skew_dx) << i;
    EXPECT_EQ(with.skew_dy, without.skew_dy) << i;
    EXPECT_EQ(with.skew_dpsi, without.skew_dpsi) << i;
    EXPECT_EQ(with.gap_slope, without.gap_slope) << i;
    force[i] = without.force;
    const SeatContact residual = contact(call, &memo, false);
    EXPECT_EQ(residual.force, without.force) << i;
    EXPECT_EQ(residual.nx, without.nx) << i;
    EXPECT_EQ(residual.ny, without.ny) << i;
    EXPECT_EQ(residual.torque, without.torque) << i;
    EXPECT_EQ(residual.damping_power, without.damping_power) << i;
    EXPECT_EQ(residual.depth, without.depth) << i;
    EXPECT_EQ(residual.skew, without.skew) << i;
    EXPECT_EQ(residual.skew_x, without.skew_x) << i;
    EXPECT_EQ(residual.skew_y, without.skew_y) << i;
    EXPECT_NE(without.skew_dx, 0.0) << i;
    EXPECT_EQ(residual.skew_dx, 0.0) << i;
    EXPECT_EQ(residual.skew_dy, 0.0) << i;
    EXPECT_EQ(residual.skew_dpsi, 0.0) << i;
    EXPECT_EQ(residual.friction_dv[0], 0.0) << i;
    // the θ point and its velocities, as `contact` takes them
    const double psi0 = psi + call.dpsi0, speed = (psi + turn - psi0) / h;
    const double qx = call.p0.x + 0.5 * (a1.x - call.p0.x),
                 qy = call.p0.y + 0.5 * (a1.y - call.p0.y);
    const double vx = (a1.x - call.p0.x) / h, vy = (a1.y - call.p0.y) / h;
    const SeatFriction fr = seat_friction(w, residual, qx, qy, vx, vy, speed);
    const SeatFriction ff = seat_friction(w, without, qx, qy, vx, vy, speed);
    EXPECT_NE(std::hypot(ff.fx, ff.fy), 0.0) << i;
    EXPECT_EQ(fr.fx, ff.fx) << i;
    EXPECT_EQ(fr.fy, ff.fy) << i;
    EXPECT_EQ(fr.power, ff.power) << i;
    EXPECT_EQ(fr.torque, ff.torque) << i;
  }
  // each key's change moves the contact (else its case would not test its comparison)
  for (const std::size_t i : {2, 4, 6, 8}) EXPECT_NE(force[i], force[0]) << i;
  // the memo is read: the start's gap, its damper's integral and (the quotient took it) energy
  // as taken, and an altered gap under the same key moves the force
  EXPECT_NEAR(memo.gap, seat_contact(w, a0.x, a0.y, 0.0, 0.0, psi, 0.0).penetration, 1e-15);
  EXPECT_TRUE(memo.energy_set);
  EXPECT_DOUBLE_EQ(memo.energy, penalty_energy(memo.gap));
  EXPECT_DOUBLE_EQ(memo.damper, damper_potential(memo.gap, w.contact_damping));
  SeatStart altered = memo;
  altered.gap += 1e-7;
  altered.energy_set = false;
  EXPECT_NE(contact(calls[0], &altered).force, force[0]);
}

// (2) The Newton matrix with the discrete gradient against central differences of the step's
// residual, every column: θ = 0.6 with the seats' damper and frictionless, the driven wheel's
// angle an unknown, the iterate jittered by ±1 µm so that rollers enter and leave their seats
// over the step (g₀ and g₁ of opposite signs); then θ = ½ with seat friction μ = 0.2 (where the
// friction's turning columns are exact, docs). It is the discrete gradient's matrix: different from
// the θ point's at the same iterate. The wheel angle's difference step is 1e-9 rad: the
// differences' truncation there goes as its square (6.7e-4 of the column at 1e-7, 6.7e-6 at
// 1e-8, measured; 3e-7 at 1e-9, where their rounding takes over).
TEST(DynamicsSeatDiscreteGradient, NewtonMatrixMatchesTheResidualsDifferences) {
  const double h = 1e-4;
  struct Case {
    double theta, damping, friction;
  };
  for (const Case& k : {Case{0.6, 800.0, 0.0}, Case{0.5, 800.0, 0.2}}) {
    std::vector<double> jac_theta;
    for (const bool gradient : {false, true}) {
      testing::Loop l = testing::pressed_loop(
          {.contact_damping = k.damping, .friction = k.friction, .discrete_gradient = gradient});
      Integrator integ(l.model, {.step = h, .theta = k.theta});
      const std::size_t n = l.model.nodes(), size = integ.unknowns();
      ASSERT_EQ(size, 2 * n + 1);
      const std::vector<double> u = testing::pressed_iterate(l, size, h, 2e-5);
      std::vector<double> r0, jac;
      integ.newton_system(l.model, l.state, u, r0, &jac);
      if (!gradient) {
        jac_theta = jac;
        continue;
      }
      const testing::ColumnsAgainstDifferences d = testing::expect_columns_match_differences(
          integ, l.model, l.state, u, jac, jac_theta,
          [n](std::size_t c) { return c == 2 * n ? 1e-9 : 1e-10; }, 1e-5);
      std::printf(
          "seat discrete gradient's Newton matrix (theta %.1f, mu %.1f): worst |J - FD| / column "
          "scale %.2e\n",
          k.theta, k.friction, d.worst);
      EXPECT_GT(d.differs, 1e-3 * d.scale);
    }
  }
}

// (3) The drive at θ = ½: the loop above unpressed (every roller on its pitch circle, the links
// 0.1 % short), the driver at 13 rad/s, the driven wheel's inertia 0.01 kg·m² under a load of
// 5 N·m, seats undamped (c_c = 0) and frictionless, links undamped, over 0.2 s of 0.1 ms steps
// (ω h ≈ 9 on the seats). The work balance: the driver's work Σ −τ₀ Δψ₀ and the load's −T_L Σ Δψ₁
// against the change of the energy (kinetic, links', contacts'). With the discrete gradient it
// closes to Newton's tolerance (the rollers rattle in their seats unresolved; without the
// correction along the step it wandered by 5e-2 of the kinetic energy, docs); with the θ point's
// force the contacts gain energy until the run diverges.
struct DriveRun {
  double kinetic0 = 0.0, worst = 0.0, end = 0.0;
  double damper = 0.0;  // [J] the seats' dampers' work
  int steps = 0;        // completed
};
DriveRun drive_run(bool gradient, double damping = 0.0, int steps = 2000) {
  const int z = 12, m = 10;
  const auto n = static_cast<std::size_t>(z + 2 * m);
  Model model = uniform_chain(n, true, kPitch * (1 - 1e-3), 0.0238, 5e7, 0.0, false);
  model.sprockets = testing::equal_wheels({.teeth = z,
                                           .span = m,
                                           .omega = 13.0,
                                           .inertia = 0.01,
                                           .load = 5.0,
                                           .contact_damping = damping});
  for (Sprocket& w : model.sprockets) w.discrete_gradient = gradient;
  State s = two_sprocket_loop(z, m, kPitch, model.sprockets[0].pitch_radius, 13.0);
  const double h = 1e-4;
  Integrator integ(model, {.step = h, .theta = 0.5});
  DriveRun out;
  const Energy e0 = energy(model, s);
  out.kinetic0 = e0.kinetic;
  double work = 0.0;
  for (int k = 0; k < steps; ++k) {
    const double a0 = s.angle[0], b0 = s.angle[1];
    const StepReport rep = integ.step(model, s);
    if (!rep.converged) break;
    work += -integ.applied_torque()[0] * (s.angle[0] - a0) -
            model.sprockets[1].load_torque * (s.angle[1] - b0);
    // the seats' dampers' work (0 undamped)
    const double balance = energy(model, s).total() - e0.total() - work - s.contact_damping_work;
    if (!std::isfinite(balance)) break;
    out.worst = std::max(out.worst, std::abs(balance));
    out.end = balance;
    out.steps = k + 1;
    out.damper = s.contact_damping_work;
  }
  return out;
}

TEST(DynamicsSeatDiscreteGradient, DriveAtThetaHalfKeepsItsWorkBalance) {
  const DriveRun kept = drive_run(true), theta = drive_run(false);
  std::printf(
      "drive at theta = 1/2 over 0.2 s (kinetic %.4g J): work balance worst %.2e of the kinetic "
      "with the discrete gradient (%d steps), %.3g with the theta point's force (%d steps, end "
      "%.3g J)\n",
      kept.kinetic0, kept.worst / kept.kinetic0, kept.steps, theta.worst / theta.kinetic0,
      theta.steps, theta.end);
  EXPECT_EQ(kept.steps, 2000);
  EXPECT_LT(kept.worst, 1e-6 * kept.kinetic0);
  // the θ point's force: diverges, or gains far more than the discrete gradient's error
  EXPECT_TRUE(theta.steps < 2000 || theta.worst > 100.0 * kept.worst);
}

// (3b) The same drive with the seats damped as the example's (800 N·s/m), θ = ½, over 0.1 s: with
// the damper over the step (f_d = (C(g₁) − C(g₀))/h, ∂f_d/∂g₁ ≥ 0) every step converges and the
// work balance, with the dampers' work (≤ 0), closes. With the θ point's c(g_θ) ġ_θ the residual's
// slope along n turned negative within the ramp (hθ c_c |ġ|/ε past m/(hθ) + c_c + h ∂f_e/∂g₁ for
// rollers rattling across their seats at θ = ½) and Newton stalled within a few steps (docs).
TEST(DynamicsSeatDiscreteGradient, DampedDriveAtThetaHalfConvergesAndKeepsItsWorkBalance) {
  const DriveRun damped = drive_run(true, 800.0, 1000);
  std::printf(
      "damped drive (800 N s/m) at theta = 1/2 over 0.1 s: %d steps, work balance worst %.2e of "
      "the kinetic %.4g J (end %.3g J), the seats' dampers' work %.4g J\n",
      damped.steps, damped.worst / damped.kinetic0, damped.kinetic0, damped.end, damped.damper);
  EXPECT_EQ(damped.steps, 1000);
  EXPECT_LT(damped.damper, 0.0);
  EXPECT_LT(damped.worst, 1e-6 * damped.kinetic0);
}

// (4) The integrator's reach test with the discrete gradient: a roller entering over a tooth's
// tip whose θ point is beyond the wheel's reach (tip + roller radius) while its iterate x₁ is
// inside, in contact. Two linked rollers (the second a pitch above the first, clear) fall
// radially onto the tip of a held z = 17 wheel, θ = ½, one step, undamped: its work is −ΔE, so
// the energy (kinetic, link's, contact's) is kept while the roller ends in contact. (a) 1.5 µm
// over a 0.1 ms step from 1 µm outside the reach: the θ point 0.25 µm beyond it, the node on the
// wheel's candidate list; the node is tried because x₁ is within reach. (b) 15 mm over a 1 ms
// step from 1.21 reach to 5 µm inside: the θ point beyond the list's 1.1 reach, off the list; every
// node is tried because the step's travel is past the list's margin. Without either, the step
// flies into the tooth and gains the contact's energy E(g₁).
struct Entry {
  double before = 0.0, after = 0.0, contact = 0.0;
  bool converged = false;
};
Entry enter_over_the_tip(double start, double travel, double h) {
  Sprocket w = iso606_sprocket(kPitch, kRoller, kWidth, 17, 0.0, 0.0, kStiffness, 0.0);
  w.discrete_gradient = true;
  w.driver = true;  // held: speed 0
  w.speed = 0.0;
  const double tau = 2.0 * kPi / w.teeth, top = 0.5 * kPi + 0.01;  // just off the tooth's centre
  State s(2, 1);
  s.angle = {0.5 * kPi - 0.5 * tau};  // a tooth's centre line at 90°
  s.speed = {0.0};
  const double ex = std::cos(top), ey = std::sin(top), v = travel / h;
  s.x = {start * ex, start * ex};
  s.y = {start * ey, start * ey + kPitch};
  s.vx = {-v * ex, -v * ex};
  s.vy = {-v * ey, -v * ey};
  Model model = uniform_chain(2, false, kPitch, 0.0238, 5e7, 0.0, false);
  model.sprockets = {w};
  Entry out;
  out.before = energy(model, s).total();
  Integrator integ(model, {.step = h, .theta = 0.5});
  out.converged = integ.step(model, s).converged;
  out.after = energy(model, s).total();
  out.contact = seat_contact(w, s.x[0], s.y[0], 0.0, 0.0, s.angle[0], 0.0).energy;
  return out;
}

TEST(DynamicsSeatDiscreteGradient, RollerEnteringOverTheTipIsTriedByItsEnds) {
  const double reach = contact_reach(wheel17(false));
  const Entry near = enter_over_the_tip(reach + 1e-6, 1.5e-6, 1e-4);
  const Entry far = enter_over_the_tip(1.21 * reach, 0.21 * reach + 5e-6, 1e-3);
  std::printf(
      "seat discrete gradient, entering over the tip: |dE| %.3g of the contact's energy %.3g J "
      "(near), %.3g of %.3g J (far)\n",
      std::abs(near.after - near.before) / near.contact, near.contact,
      std::abs(far.after - far.before) / far.contact, far.contact);
  for (const Entry& e : {near, far}) {
    EXPECT_TRUE(e.converged);
    EXPECT_GT(e.contact, 0.0);  // the roller ends in contact
    EXPECT_LT(std::abs(e.after - e.before), 1e-6 * e.contact);
  }
}

}  // namespace
}  // namespace catena::dynamics
