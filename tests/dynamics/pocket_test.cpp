// The pocket wheel's joint contact (docs/models/dynamics.md, "Pocket wheel"): the O(1) nearest
// pocket against a search over every vertex of the bi-regular polygon, the force against −∇ of
// the contact energy, ∂F/∂q and ∂F/∂v (the integrator's blocks from the contact's fields) against
// finite differences, the torque against −∂E/∂ψ, the mouth, and bad input listed at once.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "catena/dynamics/integrator.hpp"
#include "catena/dynamics/pocket_wheel.hpp"
#include "catena/pocketwheel/geometry.hpp"

namespace catena::dynamics {
namespace {

constexpr double kPi = std::numbers::pi;

// Ø18×64 on z = 8 (seed 003's example), centre off the origin, clearance 0.1 mm
Sprocket wheel(int z = 8, double damping = 0.0) {
  return pocket_wheel(0.064, 0.018, z, 0.3, -0.2, 1e-4, 1e8, damping);
}

TEST(DynamicsPocket, GeometryFromSeed003) {
  const Sprocket w = wheel();
  const pocketwheel::WheelGeometry g = pocketwheel::wheel_geometry({0.064, 0.018, 8});
  EXPECT_TRUE(w.pocket);
  EXPECT_DOUBLE_EQ(w.pitch_radius, g.pitch_radius);
  EXPECT_DOUBLE_EQ(w.pocket_angle, g.delta1);
  EXPECT_NEAR(w.pitch_radius, 0.164283, 1e-6);            // docs/models/pocketwheel.md
  EXPECT_NEAR(w.pocket_angle * 180 / kPi, 28.904, 1e-3);  // δ1
  // the polygon's sides are t + d and t − d
  EXPECT_NEAR(2 * w.pitch_radius * std::sin(0.5 * w.pocket_angle), 0.082, 1e-12);
  EXPECT_NEAR(2 * w.pitch_radius * std::sin(0.5 * (2 * kPi / 8 - w.pocket_angle)), 0.046, 1e-12);
}

TEST(DynamicsPocket, NearestPocketMatchesASearchOverAllVertices) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int z : {5, 8, 13, 30}) {
    const Sprocket w = wheel(z);
    for (int trial = 0; trial < 1000; ++trial) {
      const double psi = 40.0 * (u(rng) - 0.5), polar = 40.0 * (u(rng) - 0.5);
      const PocketVertex v = nearest_pocket(w, polar, psi);
      double best = INFINITY;
      for (int m = 0; m < z; ++m) {
        for (double off : {0.0, w.pocket_angle}) {
          const double a = psi + 2 * kPi * m / z + off;
          best = std::min(best, std::abs(std::remainder(polar - a, 2 * kPi)));
        }
      }
      EXPECT_NEAR(std::abs(std::remainder(polar - v.angle, 2 * kPi)), best, 1e-12);
      // the index names the vertex: even k at ψ + (k/2)τ, odd at ψ + ((k − 1)/2)τ + δ1
      const int k = v.index;
      const double half = std::floor(k / 2.0);
      const double expect = psi + half * 2 * kPi / z + (k % 2 != 0 ? w.pocket_angle : 0.0);
      EXPECT_NEAR(v.angle, expect, 1e-9);
    }
  }
}

// Contact force on the joint: F = −f n (towards the vertex). Elastic energy E(q, ψ).
TEST(DynamicsPocket, ForceIsMinusTheGradientOfTheEnergyAndTorqueMinusItsAngleDerivative) {
  const Sprocket w = wheel();
  const double psi = 0.4;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int checked = 0;
  for (int trial = 0; trial < 400; ++trial) {
    // a joint near a vertex, displaced by up to 2c (inside and beyond the ramp ε = 1 µm)
    const int m = trial % 16;
    const double a = psi + (m / 2) * 2 * kPi / 8 + (m % 2 ? w.pocket_angle : 0.0);
    const double x = w.centre_x + w.pitch_radius * std::cos(a) + 2e-4 * u(rng);
    const double y = w.centre_y + w.pitch_radius * std::sin(a) + 2e-4 * u(rng);
    const SeatContact c = pocket_contact(w, x, y, 0.0, 0.0, psi, 0.0);
    if (!c.active) continue;
    ++checked;
    const double hq = 1e-10, hp = 1e-10;
    auto energy = [&](double qx, double qy, double ps) {
      const SeatContact e = pocket_contact(w, qx, qy, 0.0, 0.0, ps, 0.0);
      return e.active ? e.energy : 0.0;
    };
    const double fx = -c.force * c.nx, fy = -c.force * c.ny;
    const double gx = -(energy(x + hq, y, psi) - energy(x - hq, y, psi)) / (2 * hq);
    const double gy = -(energy(x, y + hq, psi) - energy(x, y - hq, psi)) / (2 * hq);
    const double scale = std::max(1.0, c.force);
    EXPECT_NEAR(fx, gx, 1e-4 * scale) << trial;
    EXPECT_NEAR(fy, gy, 1e-4 * scale) << trial;
    const double tq = -(energy(x, y, psi + hp) - energy(x, y, psi - hp)) / (2 * hp);
    EXPECT_NEAR(c.torque, tq, 1e-4 * scale * w.pitch_radius) << trial;
  }
  EXPECT_GT(checked, 150);
}

// ∂F/∂q and ∂F/∂v of F = −f n against central differences, moving and with the wheel turning
// (so that the damping and the ramp's rate term are in). f = f(g, ġ), ġ = (v − ω ẑ × r)·n, so
//     ∂f/∂q = (∂f/∂g) nᵀ + c ∂ġ/∂q,  ∂ġ/∂q = ((I − n nᵀ) v_rel)ᵀ/|e| + ω (−n_y, n_x),
//     ∂F/∂q = −[n ⊗ ∂f/∂q + (f/|e|)(I − n nᵀ)],  ∂F/∂v = −c n nᵀ
// with ∂f/∂g the contact's `stiffness` (the ramp's rate term included), c its `damping`, 1/|e|
// its `curvature`. The Newton block of the integrator (as for the sprocket's seats) keeps
// −[(∂f/∂g) n nᵀ + c n nᵀ/(θh) + (f/|e|)(I − n nᵀ)] and drops c n ⊗ ∂ġ/∂q's turning terms (a
// quasi-Newton matrix: the residual is exact); at rest relative to the wheel they vanish, which
// the second half checks.
TEST(DynamicsPocket, ForceDerivativesMatchFiniteDifferences) {
  const Sprocket w = wheel(8, 3000.0);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (bool moving : {true, false}) {
    const double psi = -1.1, omega = moving ? -5.0 : 0.0;
    int checked = 0;
    for (int trial = 0; trial < 400; ++trial) {
      const int m = trial % 16;
      const double a = psi + (m / 2) * 2 * kPi / 8 + (m % 2 ? w.pocket_angle : 0.0);
      const double x = w.centre_x + w.pitch_radius * std::cos(a) + 2e-4 * u(rng);
      const double y = w.centre_y + w.pitch_radius * std::sin(a) + 2e-4 * u(rng);
      const double vx = moving ? 0.05 * u(rng) : 0.0, vy = moving ? 0.05 * u(rng) : 0.0;
      const SeatContact c = pocket_contact(w, x, y, vx, vy, psi, omega);
      if (!c.active || !(c.force > 0.0)) continue;
      // stay clear of the ramp's end, where the derivative jumps
      if (std::abs(c.penetration - w.contact_smoothing) < 1e-8) continue;
      ++checked;
      auto force = [&](double qx, double qy, double ux, double uy, double out[2]) {
        const SeatContact e = pocket_contact(w, qx, qy, ux, uy, psi, omega);
        out[0] = e.active ? -e.force * e.nx : 0.0;
        out[1] = e.active ? -e.force * e.ny : 0.0;
      };
      const double nx = c.nx, ny = c.ny, kt = c.force * c.curvature;
      const double rx = x - w.centre_x, ry = y - w.centre_y;
      const double wx = vx + omega * ry, wy = vy - omega * rx;  // v_rel = v − ω ẑ × r
      const double vn = wx * nx + wy * ny;
      const double dgq[2] = {(wx - vn * nx) * c.curvature - omega * ny,
                             (wy - vn * ny) * c.curvature + omega * nx};
      const double dfq[2] = {c.stiffness * nx + c.damping * dgq[0],
                             c.stiffness * ny + c.damping * dgq[1]};
      const double dq[4] = {-(nx * dfq[0] + kt * (1 - nx * nx)), -(nx * dfq[1] - kt * nx * ny),
                            -(ny * dfq[0] - kt * nx * ny), -(ny * dfq[1] + kt * (1 - ny * ny))};
      if (!moving) {  // the integrator's block (its stiffness part)
        const double kn = c.stiffness;
        EXPECT_NEAR(dq[0], -(kn * nx * nx + kt * (1 - nx * nx)), 1e-6 * kn);
        EXPECT_NEAR(dq[1], -(kn - kt) * nx * ny, 1e-6 * kn);
      }
      const double dv[4] = {-c.damping * nx * nx, -c.damping * nx * ny, -c.damping * nx * ny,
                            -c.damping * ny * ny};
      const double hq = 1e-11, hv = 1e-7;
      const double tol_q = 2e-3 * std::max(1e6, std::abs(c.stiffness));
      double p[2], q[2];
      force(x + hq, y, vx, vy, p), force(x - hq, y, vx, vy, q);
      EXPECT_NEAR(dq[0], (p[0] - q[0]) / (2 * hq), tol_q) << trial;
      EXPECT_NEAR(dq[2], (p[1] - q[1]) / (2 * hq), tol_q) << trial;
      force(x, y + hq, vx, vy, p), force(x, y - hq, vx, vy, q);
      EXPECT_NEAR(dq[1], (p[0] - q[0]) / (2 * hq), tol_q) << trial;
      EXPECT_NEAR(dq[3], (p[1] - q[1]) / (2 * hq), tol_q) << trial;
      force(x, y, vx + hv, vy, p), force(x, y, vx - hv, vy, q);
      EXPECT_NEAR(dv[0], (p[0] - q[0]) / (2 * hv), 1e-3 * 3000.0) << trial;
      EXPECT_NEAR(dv[2], (p[1] - q[1]) / (2 * hv), 1e-3 * 3000.0) << trial;
      force(x, y, vx, vy + hv, p), force(x, y, vx, vy - hv, q);
      EXPECT_NEAR(dv[1], (p[0] - q[0]) / (2 * hv), 1e-3 * 3000.0) << trial;
      EXPECT_NEAR(dv[3], (p[1] - q[1]) / (2 * hv), 1e-3 * 3000.0) << trial;
    }
    EXPECT_GT(checked, 100) << moving;
  }
}

TEST(DynamicsPocket, MouthAndClearance) {
  const Sprocket w = wheel();
  const double psi = 0.2, c = w.pocket_clearance;
  auto at = [&](double radius, double polar) {
    return pocket_contact(w, w.centre_x + radius * std::cos(polar),
                          w.centre_y + radius * std::sin(polar), 0.0, 0.0, psi, 0.0);
  };
  const double r = w.pitch_radius;
  EXPECT_FALSE(at(r - 0.9 * c, psi).active);  // within the clearance: free
  EXPECT_TRUE(at(r - 1.5 * c, psi).active);   // pressed towards the vertex
  EXPECT_NEAR(at(r - 1.5 * c, psi).penetration, 0.5 * c, 1e-12);
  EXPECT_TRUE(at(r + 0.49 * c, psi + 1.2 * c / r).active);   // in the mouth, off the vertex
  EXPECT_FALSE(at(r + 0.51 * c, psi + 1.2 * c / r).active);  // above the mouth R + c/2
  // a joint entering along the radial tilted by up to 60° is free when it crosses the mouth
  for (double tilt : {0.0, 0.5, 1.0}) {
    const double ex = 0.5 * c * std::tan(tilt);  // tangential offset at height c/2
    const double x = (r + 0.5 * c) * std::cos(psi) - ex * std::sin(psi);
    const double y = (r + 0.5 * c) * std::sin(psi) + ex * std::cos(psi);
    EXPECT_FALSE(
        pocket_contact(w, w.centre_x + x * 0.999999, w.centre_y + y * 0.999999, 0.0, 0.0, psi, 0.0)
            .active)
        << tilt;
  }
}

TEST(DynamicsPocket, BadFieldsAreListedAtOnce) {
  Model m = uniform_chain(5, true, 0.064, 0.4, 1e8, 0.0, false);
  m.alternation = 0.018;  // a closed loop of 5 links cannot alternate
  Sprocket w = wheel();
  w.pocket_angle = 1.2;  // > 2π/8
  w.pocket_clearance = -1e-4;
  w.contact_stiffness = 0.0;
  w.inertia = 1.0;
  w.friction = 0.2;  // friction in the pockets is not built
  m.sprockets = {w};
  const std::vector<Issue> issues = validate(m);
  std::string fields;
  for (const Issue& i : issues) fields += i.field + " ";
  for (const char* f :
       {"alternation", "sprocket[0].pocket_angle", "sprocket[0].pocket_clearance",
        "sprocket[0].contact_stiffness", "sprocket[0].contact_smoothing", "sprocket[0].friction"}) {
    EXPECT_NE(fields.find(f), std::string::npos) << f << " in " << fields;
  }
  Model a = uniform_chain(4, false, 0.064, 0.4, 1e8, 0.0, false);
  a.alternation = 0.07;  // ≥ the pitch
  EXPECT_EQ(validate(a).size(), 1u);
  a.alternation = 0.018;
  EXPECT_TRUE(validate(a).empty());
  EXPECT_DOUBLE_EQ(a.rest_length(0), 0.082);
  EXPECT_DOUBLE_EQ(a.rest_length(1), 0.046);
  // a pocket wheel needs the chain's alternating links: its polygon's sides are t + d and t − d
  Sprocket driver = wheel();
  driver.driver = true;
  driver.speed = 1.0;
  a.sprockets = {driver};
  EXPECT_TRUE(validate(a).empty());
  a.alternation = 0.0;  // equal links on the bi-regular polygon
  const std::vector<Issue> equal = validate(a);
  ASSERT_EQ(equal.size(), 1u);
  EXPECT_EQ(equal[0].field, "sprocket[0].pocket_angle");
  a.alternation = 0.016;  // a thinner wire than the wheel's 18 mm
  EXPECT_EQ(validate(a).size(), 1u);
  // the wheel's constructor: the chain's problems at once (t ≤ d, z < 3)
  try {
    (void)pocket_wheel(0.01, 0.02, 2, 0.0, 0.0, 1e-4, 1e8, 0.0);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("pitch"), std::string::npos) << what;
    EXPECT_NE(what.find("teeth"), std::string::npos) << what;
  }
}

// In the integrator: a lying link's two joints in their pockets over the top of a driver wheel,
// pressed in by gravity (inward at the top), are carried round with it (the contact's blocks in
// the Newton matrix converge). A joint pulled outward along its radial is not held — the pocket is
// open outward (docs/models/dynamics.md) — so the wheel turns only 0.2 rad here.
TEST(DynamicsPocket, JointsInTheirPocketsTurnWithADriverWheel) {
  Model m = uniform_chain(2, false, 0.064, 0.4, 1e8, 100.0, false);
  m.alternation = 0.018;
  m.gravity_y = -9.81;
  Sprocket w = pocket_wheel(0.064, 0.018, 8, 0.0, 0.0, 1e-4, 1e8, 500.0);
  w.driver = true;
  w.speed = 1.0;
  m.sprockets = {w};
  State s(2, 1);
  const double r = w.pitch_radius, d1 = w.pocket_angle;
  s.angle = {0.5 * kPi - 0.5 * d1};
  s.speed = {1.0};
  const double a[2] = {s.angle[0], s.angle[0] + d1};  // the two vertices of a t + d side
  for (int i = 0; i < 2; ++i) {
    s.x[i] = r * std::cos(a[i]);
    s.y[i] = r * std::sin(a[i]);
    s.vx[i] = -r * std::sin(a[i]);
    s.vy[i] = r * std::cos(a[i]);
  }
  Integrator integ(m, {.step = 1e-4, .theta = 0.6});
  for (int k = 0; k < 2000; ++k) ASSERT_TRUE(integ.step(m, s).converged) << k;
  EXPECT_NEAR(s.angle[0] - a[0], 0.2, 1e-9);
  for (int i = 0; i < 2; ++i) {  // within the clearance (+ the contact's give) of its vertex
    const double b = a[i] + 0.2;
    EXPECT_LT(std::hypot(s.x[i] - r * std::cos(b), s.y[i] - r * std::sin(b)), 1.1e-4) << i;
  }
}

}  // namespace
}  // namespace catena::dynamics
