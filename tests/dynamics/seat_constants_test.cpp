// The seat contacts' shortcuts (docs/models/dynamics.md, "Solver"): the seat index without the
// arctangent, the wheel's tooth constants and seat directions taken once, and the wheels'
// candidate lists. Each must give exactly what the plain computation gives, bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "catena/drive/sprocket.hpp"
#include "catena/dynamics/chain.hpp"
#include "catena/dynamics/integrator.hpp"

namespace catena::dynamics {
namespace {

constexpr double kPi = std::numbers::pi;

double plain_seat(double rx, double ry, double angle, double tau) {
  return std::nearbyint((std::atan2(ry, rx) - angle) / tau);
}

// equal, or both NaN
bool same(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

TEST(DynamicsSeatConstants, NearestSeatIsTheArctangentFormulaOverRandomRollers) {
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  long mismatches = 0, trials = 0;
  for (const int z : {3, 6, 9, 17, 20, 40, 120}) {
    const double tau = 2.0 * kPi / z;
    for (int trial = 0; trial < 200000; ++trial) {
      const double scale = std::pow(10.0, -6.0 + 7.0 * u(rng));  // 1 µm .. 10 m
      const double a = 2.0 * kPi * u(rng);
      const double rx = scale * std::cos(a), ry = scale * std::sin(a);
      // angles near zero and far out (a wheel that has turned for hours)
      const double angle = (trial % 3 == 0   ? 10.0
                            : trial % 3 == 1 ? 1e4
                                             : 1e6) *
                           (2.0 * u(rng) - 1.0);
      ++trials;
      if (!same(nearest_seat(rx, ry, angle, tau), plain_seat(rx, ry, angle, tau))) ++mismatches;
    }
  }
  EXPECT_EQ(mismatches, 0) << "of " << trials;
}

TEST(DynamicsSeatConstants, NearestSeatIsTheArctangentFormulaHalfWayBetweenSeats) {
  // rollers at x = (φ − angle)/τ = k + ½ + δ: where the two ways could round apart
  std::mt19937_64 rng(22);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  long mismatches = 0, trials = 0;
  for (const int z : {3, 6, 17, 20, 40}) {
    const double tau = 2.0 * kPi / z;
    for (const double delta : {0.0, 1e-16, -1e-16, 1e-13, -1e-13, 1e-10, -1e-10, 1e-8, -1e-8, 1e-7,
                               -1e-7, 1e-6, -1e-6, 1e-5, -1e-5, 1e-3, -1e-3}) {
      for (int trial = 0; trial < 4000; ++trial) {
        const double angle = (trial % 2 == 0 ? 5.0 : 5e5) * (2.0 * u(rng) - 1.0);
        const double k = std::floor(z * u(rng));
        const double phi = angle + (k + 0.5 + delta) * tau;
        const double scale = 0.01 + u(rng);
        const double rx = scale * std::cos(phi), ry = scale * std::sin(phi);
        ++trials;
        if (!same(nearest_seat(rx, ry, angle, tau), plain_seat(rx, ry, angle, tau))) ++mismatches;
      }
    }
  }
  EXPECT_EQ(mismatches, 0) << "of " << trials;
}

TEST(DynamicsSeatConstants, NearestSeatIsTheArctangentFormulaOnTheAxesAndAtOddInputs) {
  const double tau = 2.0 * kPi / 20;
  const double values[] = {0.0,   -0.0,   1.0,      -1.0,      1e-300, -1e-300,
                           1e300, -1e300, INFINITY, -INFINITY, NAN};
  for (const double rx : values) {
    for (const double ry : values) {
      for (const double angle : {0.0, -0.0, kPi, -kPi, 0.5 * tau, -0.5 * tau, 1e7, double{NAN}}) {
        EXPECT_TRUE(same(nearest_seat(rx, ry, angle, tau), plain_seat(rx, ry, angle, tau)))
            << rx << " " << ry << " " << angle;
      }
    }
  }
}

TEST(DynamicsSeatConstants, SeatContactWithTheWheelsConstantsIsSeatContact) {
  // every surface of the gap (arc, flank, corner, tip): rollers all round a wheel, near the
  // pitch circle, on wheels with and without a tip circle and a flank arc
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const int z : {9, 20, 40}) {
    Sprocket w = iso606_sprocket(0.01905, 0.01207, 0.01168, z, 0.3, -0.2, 2e8, 800.0);
    for (const bool straight : {false, true}) {
      if (straight) w.flank_radius = 0.0;
      const SeatGeometry t = seat_geometry(w);
      for (int trial = 0; trial < 3000; ++trial) {
        const double r = w.pitch_radius + 0.02 * (u(rng) - 0.5), a = 2.0 * kPi * u(rng);
        const double x = w.centre_x + r * std::cos(a), y = w.centre_y + r * std::sin(a);
        const double vx = u(rng) - 0.5, vy = u(rng) - 0.5, psi = 10.0 * u(rng), omega = 30.0;
        const SeatContact c = seat_contact(w, x, y, vx, vy, psi, omega);
        const SeatContact d = seat_contact(w, t, x, y, vx, vy, psi, omega);
        const double k = nearest_seat(x - w.centre_x, y - w.centre_y, psi, t.tau);
        const double sigma = psi + k * t.tau;
        const SeatContact e =
            std::hypot(x - w.centre_x, y - w.centre_y) > t.reach
                ? SeatContact{}
                : seat_contact_at(w, t, x, y, vx, vy, omega, k, std::cos(sigma), std::sin(sigma));
        for (const SeatContact* o : {&d, &e}) {
          EXPECT_EQ(o->active, c.active);
          EXPECT_EQ(o->seat, c.seat);
          EXPECT_EQ(o->surface, c.surface);
          EXPECT_EQ(o->force, c.force);
          EXPECT_EQ(o->penetration, c.penetration);
          EXPECT_EQ(o->nx, c.nx);
          EXPECT_EQ(o->ny, c.ny);
          EXPECT_EQ(o->torque, c.torque);
          EXPECT_EQ(o->curvature, c.curvature);
        }
      }
    }
  }
}

// The benchmark's drive (200 links of 12B over two z = 20 wheels, the driven one J = 0.05 kg·m²)
struct Drive {
  Model model;
  State state;
};
Drive drive() {
  constexpr double kPitch = 0.01905;
  const auto n = static_cast<std::size_t>(20 + 2 * 90);
  Drive d;
  d.model = uniform_chain(n, true, kPitch * (1.0 - 1e-3), 0.0238, 5e7, 100.0, false);
  d.model.gravity_y = -9.81;
  Sprocket a = iso606_sprocket(kPitch, 0.01207, 0.01168, 20, 0.0, 0.0, 2e8, 800.0);
  a.driver = true;
  a.speed = 30.0;
  Sprocket b = iso606_sprocket(kPitch, 0.01207, 0.01168, 20, 90 * kPitch, 0.0, 2e8, 800.0);
  b.inertia = 0.05;
  b.load_torque = 20.0;
  d.model.sprockets = {a, b};
  d.state = two_sprocket_loop(20, 90, kPitch, a.pitch_radius, 30.0);
  return d;
}

// Unknowns with every node moved `shift` places along the loop (and a small jitter): nodes that
// were far from a wheel are on it now.
std::vector<double> shifted(const Drive& d, std::size_t shift, double jitter, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-jitter, jitter);
  const std::size_t n = d.model.nodes();
  std::vector<double> v(2 * n + 1);
  for (std::size_t i = 0; i < n; ++i) {
    v[2 * i] = d.state.x[(i + shift) % n] + u(rng);
    v[2 * i + 1] = d.state.y[(i + shift) % n] + u(rng);
  }
  v[2 * n] = d.state.angle[1] + 1e-4 * d.state.speed[1];
  return v;
}

TEST(DynamicsSeatConstants, CandidateListsGiveTheResidualOfAFreshIntegrator) {
  // One integrator evaluated at iterates far apart (its lists out of date: remade) and close
  // together (kept), against a fresh integrator at each: the same residual and Jacobian, bit for
  // bit, and a non-finite iterate in between changes nothing after it.
  const Drive d = drive();
  std::mt19937 rng(24);
  Integrator kept(d.model, {.step = 1e-4, .theta = 0.6});
  const std::size_t shifts[] = {0, 0, 1, 1, 5, 37, 37, 100, 3};
  const double jitters[] = {0.0, 1e-4, 1e-3, 2e-3, 1e-5, 0.0, 5e-3, 1e-6, 1e-4};
  for (int pass = 0; pass < 9; ++pass) {
    std::vector<double> v = shifted(d, shifts[pass], jitters[pass], rng);
    if (pass == 6) {  // a non-finite iterate first: no lists, every node tested
      std::vector<double> bad = v;
      bad[10] = NAN;
      std::vector<double> rb;
      kept.newton_system(d.model, d.state, bad, rb, nullptr);
      EXPECT_TRUE(std::isnan(rb[10]));
    }
    std::vector<double> r1, r2, j1, j2;
    kept.newton_system(d.model, d.state, v, r1, &j1);
    Integrator fresh(d.model, {.step = 1e-4, .theta = 0.6});
    fresh.newton_system(d.model, d.state, v, r2, &j2);
    ASSERT_EQ(r1.size(), r2.size());
    long differ = 0;
    for (std::size_t i = 0; i < r1.size(); ++i) differ += r1[i] != r2[i];
    for (std::size_t i = 0; i < j1.size(); ++i) differ += j1[i] != j2[i];
    EXPECT_EQ(differ, 0) << "pass " << pass;
  }
}

TEST(DynamicsSeatConstants, StepsWithOneIntegratorMatchStepsWithAFreshOneEachStep) {
  // A fresh integrator has no lists, no seat directions and no predictor history: give it the
  // kept one's history by stepping both from the same states; the kept one's lists and tables
  // carry over steps. Constant-velocity predictor in both (a fresh integrator has no history):
  // compared on the first step from each state.
  Drive d = drive();
  Integrator kept(d.model, {.step = 1e-4, .theta = 0.6});
  for (int step = 0; step < 300; ++step) {
    State a = d.state, b = d.state;
    a.time = b.time = -1.0 - step;  // no history in either
    Integrator fresh(d.model, {.step = 1e-4, .theta = 0.6});
    const StepReport ra = kept.step(d.model, a);
    const StepReport rb = fresh.step(d.model, b);
    ASSERT_TRUE(ra.converged && rb.converged);
    EXPECT_EQ(ra.iterations, rb.iterations);
    EXPECT_EQ(ra.max_penetration, rb.max_penetration);
    EXPECT_EQ(kept.applied_torque()[1], fresh.applied_torque()[1]);
    long differ = 0;
    for (std::size_t i = 0; i < a.x.size(); ++i) differ += a.x[i] != b.x[i] || a.vy[i] != b.vy[i];
    EXPECT_EQ(differ, 0) << "step " << step;
    Integrator advance(d.model, {.step = 1e-4, .theta = 0.6});
    ASSERT_TRUE(advance.step(d.model, d.state).converged);  // the next state: 0.1 ms on
  }
}

}  // namespace
}  // namespace catena::dynamics
