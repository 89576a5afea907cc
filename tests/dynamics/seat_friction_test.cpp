// Seat friction (docs/models/dynamics.md, "Seat friction"): the regularised Coulomb force on a
// roller's slip along its seat relative to the wheel, its derivatives for the Newton matrix
// against finite differences (on ISO seats and in a pocket wheel's pockets), its Coulomb value
// outside the band, one-sidedness, and the power identity the work balance rests on.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <random>
#include <string>

#include "catena/dynamics/chain.hpp"
#include "catena/dynamics/pocket_wheel.hpp"

namespace catena::dynamics {
namespace {

constexpr double kPi = std::numbers::pi;

Sprocket wheel(double mu) {
  Sprocket w = iso606_sprocket(0.01905, 0.01207, 0.01168, 17, 0.03, -0.02, 2e8, 800.0);
  w.friction = mu;
  w.friction_band = 1e-3;
  return w;
}

struct Point {
  double x, y, vx, vy;
};

// A roller at angle γ from seat k's inward radial, at distance d from the seat centre, with the
// velocity relative to the wheel's material point: the penetration rate `rate` along the
// contact's normal n and the slip `slip` along t = perp(n); the wheel at angle ψ and speed ω.
Point place(const Sprocket& w, int k, double psi, double omega, double gamma, double d, double rate,
            double slip) {
  const double sigma = psi + 2.0 * kPi * k / w.teeth;
  const double cx = w.centre_x + w.pitch_radius * std::cos(sigma);
  const double cy = w.centre_y + w.pitch_radius * std::sin(sigma);
  // inward radial (−cos σ, −sin σ) turned by γ towards the tangent (−sin σ, cos σ)
  const double ex = -std::cos(sigma) * std::cos(gamma) - std::sin(sigma) * std::sin(gamma);
  const double ey = -std::sin(sigma) * std::cos(gamma) + std::cos(sigma) * std::sin(gamma);
  Point p{cx + d * ex, cy + d * ey, 0.0, 0.0};
  const double rx = p.x - w.centre_x, ry = p.y - w.centre_y;
  // the contact's normal n (on a flank not along e); velocity relative to the wheel
  // rate·n + slip·t, plus the wheel's material velocity ω perp(ρ)
  const SeatContact c = seat_contact(w, p.x, p.y, -omega * ry, omega * rx, psi, omega);
  const double nx = c.active ? c.nx : ex, ny = c.active ? c.ny : ey;
  p.vx = rate * nx - slip * ny - omega * ry;
  p.vy = rate * ny + slip * nx + omega * rx;
  return p;
}

SeatFriction eval(const Sprocket& w, const Point& p, double psi, double omega) {
  const SeatContact c = seat_contact(w, p.x, p.y, p.vx, p.vy, psi, omega);
  return seat_friction(w, c, p.x, p.y, p.vx, p.vy, omega);
}

// The contact of a roller (or joint) at p with the wheel at angle ψ and speed ω.
using ContactAt = std::function<SeatContact(const Point& p, double psi, double omega)>;

// Central differences of F = (fx, fy) and τ against q, v, ψ and ω at p, compared with
// seat_friction's analytic derivatives of the contact `contact` gives, each within 2e-4 of the
// largest analytic entry of its kind. Steps: 1e-11 m (a 1e-5 part of the ramp ε), 1e-8 m/s (1e-5
// of the band), and the same displacement at the pitch radius for ψ and ω.
void expect_derivatives(const Sprocket& w, const ContactAt& contact, const Point& p, double psi,
                        double omega, const std::string& where) {
  auto at = [&](const Point& a, double pa, double wa) {
    return seat_friction(w, contact(a, pa, wa), a.x, a.y, a.vx, a.vy, wa);
  };
  const SeatFriction f = at(p, psi, omega);
  const double hq = 1e-11, hv = 1e-8, hpsi = hq / w.pitch_radius, hw = hv / w.pitch_radius;
  auto diff = [&](Point a, Point b, double pa, double pb, double wa, double wb, double step,
                  double out[3]) {
    const SeatFriction fa = at(a, pa, wa), fb = at(b, pb, wb);
    out[0] = (fb.fx - fa.fx) / (2 * step);
    out[1] = (fb.fy - fa.fy) / (2 * step);
    out[2] = (fb.torque - fa.torque) / (2 * step);
  };
  // scales: the largest analytic entry of each kind
  const double sq =
      std::max({std::abs(f.dq[0]), std::abs(f.dq[1]), std::abs(f.dq[2]), std::abs(f.dq[3]), 1.0});
  const double sv =
      std::max({std::abs(f.dv[0]), std::abs(f.dv[1]), std::abs(f.dv[2]), std::abs(f.dv[3]), 1e-3});
  const double tol = 2e-4, arm = w.pitch_radius * 2;
  // the differences fd of (Fx, Fy, τ) against one argument `of` and its analytic derivatives,
  // within tol of `scale` (the torque's times the arm)
  auto expect = [&](const double fd[3], double fx, double fy, double tau, double scale,
                    const std::string& of) {
    EXPECT_NEAR(fd[0], fx, tol * scale) << "dFx/" << of << " " << where;
    EXPECT_NEAR(fd[1], fy, tol * scale) << "dFy/" << of << " " << where;
    EXPECT_NEAR(fd[2], tau, tol * scale * arm) << "dtau/" << of << " " << where;
  };
  double fd[3];
  for (int j = 0; j < 2; ++j) {
    Point a = p, b = p;
    (j == 0 ? a.x : a.y) -= hq;
    (j == 0 ? b.x : b.y) += hq;
    diff(a, b, psi, psi, omega, omega, hq, fd);
    expect(fd, f.dq[j], f.dq[2 + j], f.torque_dq[j], sq, "dq" + std::to_string(j));
    a = p;
    b = p;
    (j == 0 ? a.vx : a.vy) -= hv;
    (j == 0 ? b.vx : b.vy) += hv;
    diff(a, b, psi, psi, omega, omega, hv, fd);
    expect(fd, f.dv[j], f.dv[2 + j], f.torque_dv[j], sv, "dv" + std::to_string(j));
  }
  diff(p, p, psi - hpsi, psi + hpsi, omega, omega, hpsi, fd);
  expect(fd, f.dpsi[0], f.dpsi[1], f.torque_dpsi, sq * arm, "dpsi");
  diff(p, p, psi, psi, omega - hw, omega + hw, hw, fd);
  expect(fd, f.domega[0], f.domega[1], f.torque_domega, sv * arm, "domega");
}

SeatContact iso_contact(const Sprocket& w, const Point& p, double psi, double omega) {
  return seat_contact(w, p.x, p.y, p.vx, p.vy, psi, omega);
}

// Central differences of F = (fx, fy) and τ against every argument, compared with the analytic
// derivatives, at random contacts on the seating arc and on the flanks, within the C¹ ramp and
// beyond it, sliding inside and outside the friction band.
TEST(DynamicsSeatFriction, DerivativesMatchFiniteDifferences) {
  const Sprocket w = wheel(0.3);
  const double half = 0.5 * w.seating_angle;
  std::mt19937 rng(2111);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int arc = 0, flank = 0, in_band = 0, sliding = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const int k = static_cast<int>(u(rng) * 17) - 8;
    const double psi = 2.0 * kPi * u(rng), omega = 40.0 * (u(rng) - 0.5);
    double gamma = (half + 0.4) * (2.0 * u(rng) - 1.0);
    if (std::abs(std::abs(gamma) - half) < 0.02) continue;   // off the arc–flank joint
    const double g = 3e-6 * u(rng);                          // within and beyond ε = 1e-6
    if (std::abs(g - w.contact_smoothing) < 2e-8) continue;  // off the ramp's end (damping kink)
    const double clearance = w.seat_radius - w.roller_radius;
    // distance giving penetration g: on the arc |e| = ri − r + g, on a flank e·m = ri − r + g
    const double d = std::abs(gamma) <= half ? clearance + g
                                             : (clearance + g) / std::cos(std::abs(gamma) - half);
    const double slip = (u(rng) < 0.5 ? 3e-3 : 0.2) * (2.0 * u(rng) - 1.0);
    const double rate = 0.01 * (u(rng) - 0.3);
    const Point p = place(w, k, psi, omega, gamma, d, rate, slip);
    const SeatContact c = seat_contact(w, p.x, p.y, p.vx, p.vy, psi, omega);
    if (!c.active || !(c.force > 1.0)) continue;
    const SeatFriction f = eval(w, p, psi, omega);
    (c.curvature > 0.0 ? arc : flank)++;
    (std::abs(f.slip) < 3e-3 ? in_band : sliding)++;
    expect_derivatives(
        w, [&](const Point& q, double pa, double wa) { return iso_contact(w, q, pa, wa); }, p, psi,
        omega, "trial " + std::to_string(trial));
  }
  EXPECT_GE(arc, 30);
  EXPECT_GE(flank, 30);
  EXPECT_GE(in_band, 30);
  EXPECT_GE(sliding, 30);
}

// The same derivatives at contacts on the tooth's top (docs/models/dynamics.md, "Tooth tip"),
// with the ISO arc flank (convex: κ < 0) and the straight one: on the flank near its end, at the
// flank/tip corner and on the tip's arc (convex: the normal's turning κ < 0), for the wheels of
// validation (1), z = 9, 12 (a tip arc) and 6 (an apex). Each point is moved along its normal to a
// penetration of 0.2–3 µm, within and beyond the ramp.
TEST(DynamicsSeatFriction, DerivativesMatchFiniteDifferencesOnTheTip) {
  std::mt19937 rng(2112);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int z : {6, 9, 12}) {
    for (const bool straight : {false, true}) {
      Sprocket w = iso606_sprocket(0.01905, 0.01207, 0.01168, z, 0.03, -0.02, 2e8, 800.0);
      if (straight) w.flank_radius = 0.0;
      w.friction = 0.3;
      const double tau = 2.0 * kPi / z;
      int count[4] = {0, 0, 0, 0};
      for (int trial = 0; trial < 3000; ++trial) {
        const double psi = 2.0 * kPi * u(rng), omega = 40.0 * (u(rng) - 0.5);
        // a point round a tooth's top: between the pitch circle and the tip's offset circle
        const double rho =
            w.pitch_radius + (w.tip_radius + w.roller_radius - w.pitch_radius) * u(rng);
        const double a = psi + tau * (0.5 + (u(rng) - 0.5));
        double x = w.centre_x + rho * std::cos(a), y = w.centre_y + rho * std::sin(a);
        SeatContact c = seat_contact(w, x, y, 0.0, 0.0, psi, 0.0);
        if (!c.active || c.surface == 0) continue;
        const double target = 2e-7 + 2.8e-6 * u(rng);
        if (std::abs(target - w.contact_smoothing) < 2e-8) continue;
        x -= (c.penetration - target) * c.nx;
        y -= (c.penetration - target) * c.ny;
        const int surface = c.surface;
        c = seat_contact(w, x, y, 0.0, 0.0, psi, 0.0);
        if (!c.active || c.surface != surface) continue;
        // off the joints between surfaces, where the curvature jumps: the same surface 1e-8 m
        // either way along both axes
        bool interior = true;
        for (const double dx : {-1e-8, 1e-8}) {
          interior = interior &&
                     seat_contact(w, x + dx, y, 0.0, 0.0, psi, 0.0).surface == surface &&
                     seat_contact(w, x, y + dx, 0.0, 0.0, psi, 0.0).surface == surface;
        }
        if (!interior) continue;
        const double rx = x - w.centre_x, ry = y - w.centre_y;
        const double slip = (u(rng) < 0.5 ? 3e-3 : 0.2) * (2.0 * u(rng) - 1.0);
        const double rate = 0.01 * (u(rng) - 0.3);
        const Point p{x, y, rate * c.nx - slip * c.ny - omega * ry,
                      rate * c.ny + slip * c.nx + omega * rx};
        const SeatContact cv = seat_contact(w, p.x, p.y, p.vx, p.vy, psi, omega);
        if (!(cv.force > 1.0)) continue;
        ++count[surface];
        const std::string where = "z " + std::to_string(z) + " surface " + std::to_string(surface);
        expect_derivatives(
            w, [&](const Point& q, double pa, double wa) { return iso_contact(w, q, pa, wa); }, p,
            psi, omega, where);
        const double tol = 2e-4;
        // the normal force's own gradient (the integrator's block: stiffness along n, f κ across)
        const double hn = 1e-11;
        const SeatContact lo = seat_contact(w, p.x - hn, p.y, p.vx, p.vy, psi, omega);
        const SeatContact hi = seat_contact(w, p.x + hn, p.y, p.vx, p.vy, psi, omega);
        const double dfnx = (hi.force * hi.nx - lo.force * lo.nx) / (2 * hn);
        const double tx = -cv.ny, ty = cv.nx;
        const double analytic = cv.stiffness * cv.nx * cv.nx + cv.force * cv.curvature * tx * tx;
        // the damping's q-dependence through ġ adds c (ω + κ v_t) n tᵀ: included for the check
        const double vt = (p.vx + omega * ry) * tx + (p.vy - omega * rx) * ty;
        const double damp = cv.damping * (omega + cv.curvature * vt) * tx * cv.nx;
        EXPECT_NEAR(dfnx, analytic + damp, tol * std::max(std::abs(cv.stiffness), 1.0))
            << "z " << z << " surface " << surface;
      }
      EXPECT_GT(count[1], 20) << "z " << z;
      EXPECT_GT(count[2], 20) << "z " << z;
      if (z >= 9) {
        EXPECT_GT(count[3], 20) << "z " << z;
      }
    }
  }
}

// The same derivatives on a pocket wheel's joint contact (docs/models/dynamics.md, "Pocket wheel:
// friction"), z = 8 for seed 003's chain Ø18×64, clearance c = 0.1 mm: within the mouth (the
// force along e = q − C, κ = 1/|e|: the fields seat_friction reads are exact), on the mouth's ramp
// (pocket_mouth = c/2: the force has a radial part) and with the release (pocket_release, a held
// joint beyond the mouth, in and out of its band): there the contact's friction_dq and
// friction_dv carry the rest of the normal force's exact Jacobians. Joints at every angle of e
// round the vertex, 0–3 µm deep (on the ramp also up to 1.5c, where W falls), slipping inside and
// outside the band.
TEST(DynamicsSeatFriction, DerivativesMatchFiniteDifferencesInAPocket) {
  std::mt19937 rng(2113);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  enum Kind { kMouth, kRamp, kRelease };
  for (const Kind kind : {kMouth, kRamp, kRelease}) {
    Sprocket w = pocket_wheel(0.064, 0.018, 8, 0.03, -0.02, 1e-4, 1e8, 2000.0);
    w.friction = 0.3;
    if (kind == kRamp) w.pocket_mouth = 0.5 * w.pocket_clearance;
    if (kind == kRelease) w.pocket_release = true;
    const double c = w.pocket_clearance, mouth = w.pitch_radius + 0.5 * c;
    const double reach = contact_reach(w);
    const ReleaseBand band = release_band(w);
    int count = 0, in_band = 0, sliding = 0, released = 0;
    for (int trial = 0; trial < 4000 && count < 150; ++trial) {
      const double psi = 2 * kPi * u(rng), omega = 40.0 * (u(rng) - 0.5);
      const PocketVertex v = nearest_pocket(w, 2 * kPi * u(rng), psi);
      const int held = kind == kRelease ? v.index : kNoPocket;
      // e at angle β from the outward radial through the vertex, |e| = c + g
      const double beta = kPi * (2 * u(rng) - 1);
      const double g = (kind == kRamp && u(rng) < 0.5 ? 1.5 * c : 3e-6) * u(rng);
      if (std::abs(g - w.contact_smoothing) < 2e-8) continue;  // off the damper's ramp end
      const double dir = v.angle + beta;
      const double x = w.centre_x + w.pitch_radius * std::cos(v.angle) + (c + g) * std::cos(dir);
      const double y = w.centre_y + w.pitch_radius * std::sin(v.angle) + (c + g) * std::sin(dir);
      const double rx = x - w.centre_x, ry = y - w.centre_y, rho = std::hypot(rx, ry);
      if (std::abs(rho - mouth) < 1e-8 || std::abs(rho - reach) < 1e-8) continue;
      if (kind == kMouth && rho > mouth) continue;
      if (kind == kRamp && !(rho > mouth && rho < reach)) continue;
      const SeatContact c0 = pocket_contact(w, x, y, -omega * ry, omega * rx, psi, omega, held);
      if (!c0.active || c0.seat != v.index) continue;
      const double slip = (u(rng) < 0.5 ? 3e-3 : 0.2) * (2.0 * u(rng) - 1.0);
      const double rate = 0.01 * (u(rng) - 0.3);
      const Point p{x, y, rate * c0.nx - slip * c0.ny - omega * ry,
                    rate * c0.ny + slip * c0.nx + omega * rx};
      const ContactAt contact = [&](const Point& q, double pa, double wa) {
        return pocket_contact(w, q.x, q.y, q.vx, q.vy, pa, wa, held);
      };
      const SeatContact cv = contact(p, psi, omega);
      if (!(cv.force > 1.0)) continue;
      ++count;
      const SeatFriction f = seat_friction(w, cv, p.x, p.y, p.vx, p.vy, omega);
      (std::abs(f.slip) < 3e-3 ? in_band : sliding)++;
      // in the release's band: u = e·r̂/|e| between its ends (S between 1 and 0)
      const double cu = std::cos(beta);  // ≈ u (r̂ at q is within 0.04° of the vertex's radial)
      if (kind == kRelease && cu > band.full + 0.01 && cu < band.none - 0.01) ++released;
      expect_derivatives(w, contact, p, psi, omega,
                         "kind " + std::to_string(kind) + " trial " + std::to_string(trial));
    }
    EXPECT_GE(count, 100) << "kind " << kind;
    EXPECT_GE(in_band, 20) << "kind " << kind;
    EXPECT_GE(sliding, 20) << "kind " << kind;
    if (kind == kRelease) {
      EXPECT_GE(released, 10);
    }
  }
}

// The same derivatives on a pocket wheel's body between the pockets, in the capture's blend
// (docs/models/dynamics.md, "Pocket wheel: friction"): joints 10c–20c from their vertex within the
// mouth, where the pocket's friction is faded by its share P of the depth (friction_weight, 1 at
// 10c and 0 at 20c) on the blended contact's force and surface: ∇P is in ∂F/∂q and, through the
// turning, in ∂F/∂ψ and the torque's. Without ∇P (friction_weight_dq) the q and ψ derivatives miss
// by μ f_t-sized terms and the test fails.
TEST(DynamicsSeatFriction, DerivativesMatchFiniteDifferencesOverTheBodysBlend) {
  std::mt19937 rng(2117);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Sprocket w = pocket_wheel(0.064, 0.018, 8, 0.03, -0.02, 1e-4, 1e8, 2000.0);
  w.friction = 0.3;
  const double c = w.pocket_clearance, mouth = w.pitch_radius + 0.5 * c;
  int count = 0, in_band = 0, sliding = 0, faded = 0;
  for (int trial = 0; trial < 4000 && count < 150; ++trial) {
    const double psi = 2 * kPi * u(rng), omega = 40.0 * (u(rng) - 0.5);
    const PocketVertex v = nearest_pocket(w, 2 * kPi * u(rng), psi);
    const double dist = c * (10.05 + 9.9 * u(rng)), dir = 2 * kPi * u(rng);
    const double x = w.centre_x + w.pitch_radius * std::cos(v.angle) + dist * std::cos(dir);
    const double y = w.centre_y + w.pitch_radius * std::sin(v.angle) + dist * std::sin(dir);
    const double rx = x - w.centre_x, ry = y - w.centre_y;
    if (!(std::hypot(rx, ry) < mouth - 1e-8)) continue;
    const SeatContact c0 = pocket_contact(w, x, y, -omega * ry, omega * rx, psi, omega);
    if (!c0.active || c0.surface != 3 || c0.seat != v.index) continue;
    const double slip = (u(rng) < 0.5 ? 3e-3 : 0.2) * (2.0 * u(rng) - 1.0);
    const double rate = 0.01 * (u(rng) - 0.3);
    const Point p{x, y, rate * c0.nx - slip * c0.ny - omega * ry,
                  rate * c0.ny + slip * c0.nx + omega * rx};
    const ContactAt contact = [&](const Point& q, double pa, double wa) {
      return pocket_contact(w, q.x, q.y, q.vx, q.vy, pa, wa);
    };
    const SeatContact cv = contact(p, psi, omega);
    if (!(cv.force > 1.0)) continue;
    ++count;
    ASSERT_GT(cv.friction_weight, 0.0);
    ASSERT_LT(cv.friction_weight, 1.0);
    faded += cv.friction_weight > 0.05 && cv.friction_weight < 0.95 ? 1 : 0;
    const SeatFriction f = seat_friction(w, cv, p.x, p.y, p.vx, p.vy, omega);
    EXPECT_NE(f.friction_force, 0.0);
    (std::abs(f.slip) < 3e-3 ? in_band : sliding)++;
    expect_derivatives(w, contact, p, psi, omega, "body trial " + std::to_string(trial));
  }
  std::printf(
      "the body's blend: %d joints, %d in the band, %d sliding, %d with P in (0.05, 0.95)\n", count,
      in_band, sliding, faded);
  EXPECT_GE(count, 100);
  EXPECT_GE(in_band, 20);
  EXPECT_GE(sliding, 20);
  EXPECT_GE(faded, 50);
}

// Outside the band the force is Coulomb's μ f against the slip, within 1/(2 (v_t/v_ε)²); it is
// odd in the slip and 0 without slip; F lies along the seat's tangent.
TEST(DynamicsSeatFriction, CoulombOutsideTheBandAgainstTheSlip) {
  const Sprocket w = wheel(0.25);
  const double half = 0.5 * w.seating_angle;
  for (const double gamma : {0.3, -0.5, 1.4, -1.5}) {  // arc and both flanks (α/2 ≈ 1.18 rad)
    for (const double slip : {70e-3, -70e-3, 0.5, -2.0}) {
      const double clr = w.seat_radius - w.roller_radius, g = 4e-6;
      const double d =
          std::abs(gamma) <= half ? clr + g : (clr + g) / std::cos(std::abs(gamma) - half);
      const Point p = place(w, 3, 0.7, 12.0, gamma, d, 0.0, slip);
      const SeatContact c = seat_contact(w, p.x, p.y, p.vx, p.vy, 0.7, 12.0);
      ASSERT_TRUE(c.active && c.force > 0.0);
      const SeatFriction f = eval(w, p, 0.7, 12.0);
      EXPECT_NEAR(f.slip, slip, 1e-12);
      const double r = w.friction_band / slip;
      EXPECT_NEAR(f.friction_force / (-w.friction * c.force * (slip > 0 ? 1 : -1)), 1.0,
                  0.5 * r * r + 1e-12);
      EXPECT_LT(f.friction_force * slip, 0.0);
      EXPECT_NEAR(f.fx * c.nx + f.fy * c.ny, 0.0, 1e-12 * c.force);  // along the tangent
      const Point q = place(w, 3, 0.7, 12.0, gamma, d, 0.0, -slip);
      EXPECT_NEAR(eval(w, q, 0.7, 12.0).friction_force, -f.friction_force, 1e-9 * c.force);
    }
    const double reach = w.seat_radius - w.roller_radius + 4e-6;
    const double d = std::abs(gamma) <= half ? reach : reach / std::cos(std::abs(gamma) - half);
    const Point still = place(w, 3, 0.7, 12.0, gamma, d, 0.0, 0.0);
    EXPECT_NEAR(eval(w, still, 0.7, 12.0).friction_force, 0.0, 1e-9);
  }
}

// No normal force, no friction: a roller clear of its seat, or leaving it fast enough that the
// damper would pull (the force clamped at 0), feels none; nor does any roller with μ = 0.
TEST(DynamicsSeatFriction, OnlyWithANormalForce) {
  const Sprocket w = wheel(0.3);
  const double clr = w.seat_radius - w.roller_radius;
  // clear of the seat: inside the clearance
  const Point clear = place(w, 0, 0.2, 5.0, 0.1, 0.5 * clr, 0.0, 0.3);
  EXPECT_FALSE(seat_contact(w, clear.x, clear.y, clear.vx, clear.vy, 0.2, 5.0).active);
  EXPECT_EQ(eval(w, clear, 0.2, 5.0).friction_force, 0.0);
  // in contact but separating: 1 µm deep, leaving at 1 m/s (the damper outweighs k_c g)
  const Point leaving = place(w, 0, 0.2, 5.0, 0.1, clr + 1e-6, -1.0, 0.3);
  const SeatContact c = seat_contact(w, leaving.x, leaving.y, leaving.vx, leaving.vy, 0.2, 5.0);
  EXPECT_TRUE(c.active);
  EXPECT_EQ(c.force, 0.0);
  const SeatFriction f = eval(w, leaving, 0.2, 5.0);
  EXPECT_EQ(f.friction_force, 0.0);
  EXPECT_EQ(f.dq[0], 0.0);
  EXPECT_EQ(f.torque, 0.0);
  // pressed in but frictionless
  const Point pressed = place(w, 0, 0.2, 5.0, 0.1, clr + 3e-6, 0.0, 0.3);
  EXPECT_EQ(eval(wheel(0.0), pressed, 0.2, 5.0).friction_force, 0.0);
  EXPECT_NE(eval(wheel(0.3), pressed, 0.2, 5.0).friction_force, 0.0);
}

// The friction's power on roller and wheel together is f_t v_t ≤ 0: F·v + τ ω, the identity the
// integrator's seat friction work (h f_t v_t a step) rests on.
TEST(DynamicsSeatFriction, PowerOnRollerAndWheelIsForceTimesSlip) {
  const Sprocket w = wheel(0.3);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int checked = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const double psi = 3.0 * u(rng), omega = 30.0 * u(rng);
    const double d = w.seat_radius - w.roller_radius + 2e-6 * (1.0 + u(rng));
    const Point p = place(w, 2, psi, omega, 1.5 * u(rng), d, 0.0, 0.5 * u(rng));
    const SeatFriction f = eval(w, p, psi, omega);
    if (f.friction_force == 0.0) continue;
    ++checked;
    EXPECT_LE(f.power, 0.0);
    EXPECT_NEAR(f.power, f.fx * p.vx + f.fy * p.vy + f.torque * omega,
                1e-9 * std::abs(f.friction_force) * (std::abs(f.slip) + 1.0));
  }
  EXPECT_GE(checked, 100);
}

TEST(DynamicsSeatFriction, ValidationNamesTheFields) {
  Model m = uniform_chain(4, false, 0.01905, 0.024, 1e6, 0.0, false);
  Sprocket w = wheel(-0.1);
  w.driver = true;
  w.friction_band = 0.0;
  m.sprockets = {w, wheel(NAN)};
  m.sprockets[1].driver = true;
  m.sprockets[1].friction_band = 2.0;
  const std::vector<Issue> issues = validate(m);
  int found = 0;
  for (const Issue& i : issues) {
    if (i.field == "sprocket[0].friction" || i.field == "sprocket[0].friction_band" ||
        i.field == "sprocket[1].friction" || i.field == "sprocket[1].friction_band") {
      ++found;
    }
  }
  EXPECT_EQ(found, 4);
  Sprocket ok = wheel(1.0);
  ok.driver = true;
  m.sprockets = {ok};
  EXPECT_TRUE(validate(m).empty());
}

}  // namespace
}  // namespace catena::dynamics
