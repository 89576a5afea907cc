// Roller–seat contact on a sprocket: the O(1) nearest seat against a search over every seat, the
// penetration of a displaced roller, and the torque on the wheel against the derivative of the
// contact energy.
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

}  // namespace
}  // namespace catena::dynamics
