// Roller–seat contact on a sprocket: the O(1) nearest seat against a search over every seat, the
// penetration of a displaced roller, and the torque on the wheel against the derivative of the
// contact energy.
#include "catena/drive/sprocket.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "catena/dynamics/chain.hpp"

namespace catena::dynamics {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kLengthTol = 1e-12;  // [m]

// 12B: p = 19.05 mm, d1 = 12.07 mm, b1 = 11.68 mm
Sprocket wheel(int z) { return iso606_sprocket(0.01905, 0.01207, 0.01168, z, 0.3, -0.2, 2e8, 0.0); }

TEST(DynamicsSprocket, PitchAndSeatFromTheIso606Form) {
  const Sprocket w = wheel(17);
  EXPECT_NEAR(w.pitch_radius, 0.5 * 0.01905 / std::sin(kPi / 17), kLengthTol);
  EXPECT_NEAR(w.seat_radius, 0.505 * 0.01207, kLengthTol);  // ri,min = 0.505 d1
  EXPECT_NEAR(w.roller_radius, 0.5 * 0.01207, kLengthTol);
}

TEST(DynamicsSprocket, NearestSeatMatchesASearchOverAllSeats) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int z : {6, 9, 17, 40}) {
    const Sprocket w = wheel(z);
    for (int trial = 0; trial < 500; ++trial) {
      const double psi = 20.0 * (u(rng) - 0.5);
      const double r = w.pitch_radius * (0.6 + 0.4 * u(rng)), a = 2.0 * kPi * u(rng);
      const double x = w.centre_x + r * std::cos(a), y = w.centre_y + r * std::sin(a);
      const SeatContact c = seat_contact(w, x, y, 0.0, 0.0, psi, 0.0);
      double best = INFINITY, bx = 0.0, by = 0.0;
      for (int k = 0; k < z; ++k) {
        const double s = psi + 2.0 * kPi * k / z;
        const double sx = w.centre_x + w.pitch_radius * std::cos(s);
        const double sy = w.centre_y + w.pitch_radius * std::sin(s);
        if (std::hypot(x - sx, y - sy) < best) {
          best = std::hypot(x - sx, y - sy);
          bx = sx;
          by = sy;
        }
      }
      EXPECT_NEAR(c.seat_x, bx, 1e-9) << "z " << z;
      EXPECT_NEAR(c.seat_y, by, 1e-9) << "z " << z;
    }
  }
}

TEST(DynamicsSprocket, RadialPenetrationAndNoTorque) {
  const Sprocket w = wheel(17);
  const double psi = 0.3;
  const double clearance = w.seat_radius - w.roller_radius;
  // a roller on the seat centre's radius, pushed inwards by the clearance + 5 µm
  const double r = w.pitch_radius - clearance - 5e-6;
  const SeatContact c = seat_contact(w, w.centre_x + r * std::cos(psi),
                                     w.centre_y + r * std::sin(psi), 0.0, 0.0, psi, 0.0);
  ASSERT_TRUE(c.active);
  EXPECT_NEAR(c.penetration, 5e-6, 1e-12);
  EXPECT_NEAR(c.force, 2e8 * (5e-6 - 0.5 * w.contact_smoothing), 1e-6);  // past the ramp
  EXPECT_NEAR(c.torque, 0.0, 1e-9);
  // inside the clearance: no contact; outside the pitch circle: the gap is open
  const double r_free = w.pitch_radius - 0.5 * clearance;
  EXPECT_FALSE(seat_contact(w, w.centre_x + r_free * std::cos(psi),
                            w.centre_y + r_free * std::sin(psi), 0.0, 0.0, psi, 0.0)
                   .active);
  const double r_out = w.pitch_radius + 0.5 * w.roller_radius;
  EXPECT_FALSE(seat_contact(w, w.centre_x + r_out * std::cos(psi),
                            w.centre_y + r_out * std::sin(psi), 0.0, 0.0, psi, 0.0)
                   .active);
}

// The torque on the wheel is −∂V/∂ψ of the contact energy V(g) with the roller held, and the
// force is V'(g): both through the smoothed onset and beyond it.
TEST(DynamicsSprocket, TorqueIsTheDerivativeOfTheContactEnergy) {
  const Sprocket w = wheel(13);
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int checked = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const double psi = 3.0 * u(rng);
    const double a = psi + 0.03 * u(rng);
    const double clearance = w.seat_radius - w.roller_radius;
    const double r = w.pitch_radius - clearance - 3e-6 * std::abs(u(rng));
    const double x = w.centre_x + r * std::cos(a), y = w.centre_y + r * std::sin(a);
    const SeatContact c = seat_contact(w, x, y, 0.0, 0.0, psi, 0.0);
    if (!c.active) continue;
    auto energy_at = [&](double angle) {
      const SeatContact e = seat_contact(w, x, y, 0.0, 0.0, angle, 0.0);
      return e.active ? e.energy : 0.0;
    };
    const double d = 1e-7;
    const double numeric = -(energy_at(psi + d) - energy_at(psi - d)) / (2.0 * d);
    EXPECT_NEAR(c.torque, numeric, 1e-4 * std::max(1e-3, std::abs(numeric)));
    // moving the roller by dg along n (away from the seat centre) deepens g by dg
    const double dg = 1e-9;
    const SeatContact deeper = seat_contact(w, x + dg * c.nx, y + dg * c.ny, 0.0, 0.0, psi, 0.0);
    const SeatContact shallower = seat_contact(w, x - dg * c.nx, y - dg * c.ny, 0.0, 0.0, psi, 0.0);
    EXPECT_NEAR(c.force, (deeper.energy - shallower.energy) / (2.0 * dg),
                1e-4 * std::max(1e-3, c.force));
    ++checked;
  }
  EXPECT_GT(checked, 100);
}

// The tooth tip (docs/models/dynamics.md, "Tooth tip"), on the ISO arc flank and on the straight
// one: the penetration is r minus the roller
// centre's signed distance from the tooth, so it is continuous and 1-Lipschitz in the roller's
// position everywhere near the wheel — across the arc, the flanks, the flank/tip corner, the tip's
// arc, the tooth's centre line (where the nearest seat changes) and the reach, where the form
// without a tip jumped. Random pairs of nearby points round the whole wheel out to beyond the tip.
TEST(DynamicsSprocket, TipPenetrationIsContinuousAndLipschitz) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int z : {6, 9, 12, 17, 25}) {
    for (const bool straight : {false, true}) {
      Sprocket w = wheel(z);
      if (straight) w.flank_radius = 0.0;  // the straight flank with the tip
      ASSERT_GT(w.tip_radius, w.pitch_radius) << "z " << z;
      int surfaces[4] = {0, 0, 0, 0};
      for (int trial = 0; trial < 20000; ++trial) {
        const double psi = 6.0 * u(rng);
        const double rho = w.pitch_radius - w.roller_radius +
                           (w.tip_radius - w.pitch_radius + 2.5 * w.roller_radius) * u(rng);
        const double a = 2.0 * kPi * u(rng);
        const double x = w.centre_x + rho * std::cos(a), y = w.centre_y + rho * std::sin(a);
        const double step = 2e-4 * u(rng), dir = 2.0 * kPi * u(rng);
        const double x2 = x + step * std::cos(dir), y2 = y + step * std::sin(dir);
        const SeatContact c1 = seat_contact(w, x, y, 0.0, 0.0, psi, 0.0);
        const SeatContact c2 = seat_contact(w, x2, y2, 0.0, 0.0, psi, 0.0);
        const double g1 = c1.active ? c1.penetration : 0.0, g2 = c2.active ? c2.penetration : 0.0;
        // both clamped at 0 outside contact: |max(0, g)| is 1-Lipschitz as g is
        EXPECT_LE(std::abs(g2 - g1), step * (1.0 + 1e-9) + 1e-15)
            << "z " << z << " surfaces " << c1.surface << " " << c2.surface;
        if (c1.active) ++surfaces[c1.surface];
        // clear of the wheel beyond the tip circle's offset
        if (rho > w.tip_radius + w.roller_radius) {
          EXPECT_FALSE(c1.active);
        }
      }
      EXPECT_GT(surfaces[1], 100) << "z " << z;  // flank
      EXPECT_GT(surfaces[2], 100) << "z " << z;  // corner
      if (z >= 9) {                              // the tip's arc (z = 6: an apex)
        EXPECT_GT(surfaces[3], 100) << "z " << z;
      }
    }
  }
}

// Where the contact is on the tip: its normal points from the roller to the wheel's centre side
// (the force −f n pushes the roller out), the corner K = q + (r − g) n lies on the tip circle
// (or on the tooth's centre line at an apex) and on the flank's line, and the depth along n is
// the penetration's gradient (g(q + s n) = g + s).
TEST(DynamicsSprocket, TipCornerAndArcGeometry) {
  std::mt19937 rng(22);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int z : {6, 9, 12, 17, 25}) {
    for (const bool straight : {false, true}) {
      Sprocket w = wheel(z);
      if (straight) w.flank_radius = 0.0;  // the straight flank with the tip
      const double tau = 2.0 * kPi / z;
      int corners = 0, tips = 0;
      for (int trial = 0; trial < 4000; ++trial) {
        const double psi = 6.0 * u(rng);
        const double rho =
            w.pitch_radius + (w.tip_radius - w.pitch_radius + w.roller_radius) * u(rng);
        const double a = 2.0 * kPi * u(rng);
        const double x = w.centre_x + rho * std::cos(a), y = w.centre_y + rho * std::sin(a);
        const SeatContact c = seat_contact(w, x, y, 0.0, 0.0, psi, 0.0);
        if (!c.active || c.surface < 2) continue;
        const double kx = x + (w.roller_radius - c.penetration) * c.nx;
        const double ky = y + (w.roller_radius - c.penetration) * c.ny;
        const double ox = kx - w.centre_x, oy = ky - w.centre_y;
        const double off = std::remainder(std::atan2(oy, ox) - psi, tau);  // from the seat radial
        if (c.surface == 3) {
          ++tips;
          EXPECT_NEAR(std::hypot(ox, oy), w.tip_radius, 1e-12);
          EXPECT_NEAR(c.curvature, -1.0 / std::hypot(x - w.centre_x, y - w.centre_y), 1e-9);
        } else {
          ++corners;
          const bool on_tip = std::abs(std::hypot(ox, oy) - w.tip_radius) < 1e-12;
          const bool on_centre_line = std::abs(std::abs(off) - 0.5 * tau) < 1e-9;
          EXPECT_TRUE(on_tip || on_centre_line) << "z " << z << " off " << off;
          // K is the flank's end: on the flank (m the normal at the seating arc's end)
          const double sigma = psi + c.seat * tau;
          const double cx = w.centre_x + w.pitch_radius * std::cos(sigma);
          const double cy = w.centre_y + w.pitch_radius * std::sin(sigma);
          const double side = off > 0.0 ? 1.0 : -1.0, half = 0.5 * w.seating_angle;
          const double mx =
              -std::cos(sigma) * std::cos(half) - std::sin(sigma) * side * std::sin(half);
          const double my =
              -std::sin(sigma) * std::cos(half) + std::cos(sigma) * side * std::sin(half);
          if (w.flank_radius > 0.0) {  // on the ISO flank's circle about F = C + (ri + re) m
            const double fx = cx + (w.seat_radius + w.flank_radius) * mx;
            const double fy = cy + (w.seat_radius + w.flank_radius) * my;
            EXPECT_NEAR(std::hypot(kx - fx, ky - fy), w.flank_radius, 1e-12) << "z " << z;
          } else {  // on the straight flank
            EXPECT_NEAR((kx - cx) * mx + (ky - cy) * my, w.seat_radius, 1e-12) << "z " << z;
          }
        }
        for (const double s : {-3e-7, 2e-7}) {
          const SeatContact d = seat_contact(w, x + s * c.nx, y + s * c.ny, 0.0, 0.0, psi, 0.0);
          if (d.active && d.surface == c.surface) {
            EXPECT_NEAR(d.penetration, c.penetration + s, 1e-12);
          }
        }
      }
      EXPECT_GT(corners, 20) << "z " << z;
      if (z >= 9) {
        EXPECT_GT(tips, 20) << "z " << z;
      }
    }
  }
}

// The form without a tip (tip_radius 0) keeps its reach R + r and flanks that run on to it.
TEST(DynamicsSprocket, WithoutATipTheFlanksRunToTheReach) {
  Sprocket w = wheel(12);
  w.tip_radius = 0.0;
  EXPECT_DOUBLE_EQ(contact_reach(w), w.pitch_radius + w.roller_radius);
  Sprocket t = wheel(12);
  EXPECT_DOUBLE_EQ(contact_reach(t), t.tip_radius + t.roller_radius);
  // just inside the reach, a tooth's width off the seat: the flank's finite penetration at once
  const double rho = w.pitch_radius + w.roller_radius - 1e-9, a = 0.3 + 0.45 * 2.0 * kPi / 12;
  const SeatContact c = seat_contact(w, w.centre_x + rho * std::cos(a),
                                     w.centre_y + rho * std::sin(a), 0.0, 0.0, 0.3, 0.0);
  ASSERT_TRUE(c.active);
  EXPECT_GT(c.penetration, 1e-3);
  EXPECT_EQ(c.surface, 1);
  // with the tip the same roller meets the tooth's top continuously
  const SeatContact d = seat_contact(t, t.centre_x + rho * std::cos(a),
                                     t.centre_y + rho * std::sin(a), 0.0, 0.0, 0.3, 0.0);
  const double rho2 = rho + 1e-6;
  const SeatContact e = seat_contact(t, t.centre_x + rho2 * std::cos(a),
                                     t.centre_y + rho2 * std::sin(a), 0.0, 0.0, 0.3, 0.0);
  EXPECT_LE(std::abs((d.active ? d.penetration : 0.0) - (e.active ? e.penetration : 0.0)),
            1.0000001e-6);
}

TEST(DynamicsSprocket, TipRadiusIsValidated) {
  Model m = uniform_chain(4, false, 0.01905, 0.02, 1e7, 0.0, true);
  m.sprockets.push_back(wheel(12));
  const std::size_t base = validate(m).size();  // whatever else the bare model lacks
  auto names_tip = [&] {
    for (const Issue& i : validate(m)) {
      if (i.field == "sprocket[0].tip_radius") return true;
    }
    return false;
  };
  EXPECT_FALSE(names_tip());
  for (const double bad :
       {0.5 * m.sprockets[0].pitch_radius, -1e-3, double(NAN), double(INFINITY)}) {
    m.sprockets[0].tip_radius = bad;
    EXPECT_TRUE(names_tip()) << bad;
    EXPECT_EQ(validate(m).size(), base + 1) << bad;
  }
  m.sprockets[0].tip_radius = 0.0;
  EXPECT_FALSE(names_tip());
}

// The tip against the chain's articulation (docs/models/dynamics.md, "Tooth tip"): a roller
// winding on swings about its seated neighbour's seat centre at the chord 2R sin(π/z). Checked
// here by its own sampling — random points of that quarter turn with the wheel at random angles
// (the whole figure turned) — not by articulation_interference: with iso606_sprocket's tip no
// point of the path is inside a tooth. Where ISO's da,max already clears (z ≥ 11 for 08B, 12B,
// 16B) the tip is da,max/2 exactly; where it does not (z = 7…10) the tip is lowered, and only as
// far as needed (2 µm higher cuts the path: the limit less its 1 µm margin), and for z ≥ 8 stays
// within ISO's range [da,min/2, da,max/2]. At z = 6 even a tip at the pitch circle does not clear
// (the flanks themselves cut the path): the tip is left at da,max/2 and the case stays as it was.
TEST(DynamicsSprocket, TipClearsTheRollerArticulation) {
  struct Chain {
    const char* name;
    double p, d1, b1;
  };
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const Chain c :
       {Chain{"08B", 0.0127, 0.00851, 0.00775}, Chain{"12B", 0.01905, 0.01207, 0.01168},
        Chain{"16B", 0.0254, 0.01588, 0.01702}}) {
    for (int z = 6; z <= 40; ++z) {
      const Sprocket w = iso606_sprocket(c.p, c.d1, c.b1, z, 0.1, -0.2, 2e8, 0.0);
      const drive::Sprocket iso =
          drive::sprocket({.pitch = c.p, .roller_diameter = c.d1, .inner_width = c.b1, .teeth = z});
      const double da_max = 0.5 * iso.tip_diameter_max, da_min = 0.5 * iso.tip_diameter_min;
      Sprocket full = w;
      full.tip_radius = da_max;
      const bool cut = articulation_interference(full) > 0.0;
      EXPECT_EQ(cut, z <= 10) << c.name << " z " << z;
      if (z == 6) {
        EXPECT_EQ(w.tip_radius, da_max) << c.name;  // no cure: left as it was
        continue;
      }
      if (!cut) {
        EXPECT_EQ(w.tip_radius, da_max) << c.name << " z " << z;
      } else {
        EXPECT_LT(w.tip_radius, da_max) << c.name << " z " << z;
        Sprocket higher = w;
        higher.tip_radius += 2e-6;
        EXPECT_GT(articulation_interference(higher), 0.0) << c.name << " z " << z;
        if (z >= 8) {
          EXPECT_GE(w.tip_radius, da_min) << c.name << " z " << z;
        }
      }
      const double R = w.pitch_radius, step = kPi / z, chord = 2 * R * std::sin(step);
      double worst = 0.0;
      for (int k = 0; k < 4000; ++k) {
        const double psi = 2 * kPi * u(rng), beta = -step + 0.5 * kPi * u(rng);
        // seat 0 at angle ψ: its centre C0, the roller at the chord from it, turned with ψ
        const double c0x = w.centre_x + R * std::cos(psi), c0y = w.centre_y + R * std::sin(psi);
        const double turn = psi - 0.5 * kPi;
        const double qx = c0x + chord * std::cos(beta + turn);
        const double qy = c0y + chord * std::sin(beta + turn);
        const SeatContact sc = seat_contact(w, qx, qy, 0.0, 0.0, psi, 0.0);
        if (sc.active) worst = std::max(worst, sc.penetration);
      }
      EXPECT_LE(worst, 1e-9) << c.name << " z " << z;
    }
  }
  // 12B, the validation's wheels (DynamicsChordal): da,max/2 = 33.720 mm cuts the path by
  // 0.225 mm at z = 9 (0.037 mm at z = 10); the tips become 32.449 and 36.499 mm
  const Sprocket w9 = wheel(9), w10 = wheel(10);
  EXPECT_NEAR(w9.tip_radius, 0.032449, 2e-6);
  EXPECT_NEAR(w10.tip_radius, 0.036499, 2e-6);
  Sprocket full9 = w9;
  full9.tip_radius = 0.5 * (w9.pitch_radius * 2 + 1.25 * 0.01905 - 0.01207);
  EXPECT_NEAR(articulation_interference(full9), 0.000225, 1e-6);
}

}  // namespace
}  // namespace catena::dynamics
