// Guides (straight and circular-arc rails with Coulomb friction): the contact force against the
// derivative of its energy, the Newton blocks ∂F/∂q and ∂F/∂v against finite differences of the
// force, the regularised friction law, the one-sided reach, and a roller sliding to rest on a rail
// under gravity (stopping distance v₀²/2μg, the friction work equal to the energy lost).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "catena/dynamics/integrator.hpp"
#include "random_guides.hpp"

namespace catena::dynamics {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kRoller = 0.006035;  // [m] 12B roller radius

Guide straight_rail(double mu) { return testing::inclined_rail(mu); }

Guide arc_rail(bool inside, double mu) {
  return testing::arc_rail(straight_rail(mu), 0.1, -0.05, 0.25, -0.5, 2.0, inside);
}

// A roller position pressed `depth` into the rail at a fraction `s` along it.
void touch_point(const Guide& g, double s, double depth, double& x, double& y) {
  if (g.kind == Guide::Kind::kStraight) {
    const double len = std::hypot(g.x1 - g.x0, g.y1 - g.y0);
    const double ux = (g.x1 - g.x0) / len, uy = (g.y1 - g.y0) / len;
    const double off = g.roller_radius - depth;  // along the left normal (−uy, ux)
    x = g.x0 + s * len * ux - off * uy;
    y = g.y0 + s * len * uy + off * ux;
  } else {
    const double a = g.start_angle + s * (g.end_angle - g.start_angle);
    const double d =
        g.inside ? g.radius - g.roller_radius + depth : g.radius + g.roller_radius - depth;
    x = g.centre_x + d * std::cos(a);
    y = g.centre_y + d * std::sin(a);
  }
}

std::vector<Guide> rails(double mu) {
  return {straight_rail(mu), arc_rail(false, mu), arc_rail(true, mu)};
}

TEST(DynamicsGuide, ForceIsMinusTheGradientOfTheContactEnergy) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const Guide& g : rails(0.0)) {
    for (int trial = 0; trial < 100; ++trial) {
      double x = 0.0, y = 0.0;
      // depths both inside the smoothing ramp (ε = 1 µm) and beyond it
      touch_point(g, 0.05 + 0.9 * u(rng), 3e-6 * u(rng) + 1e-8, x, y);
      const GuideContact c = guide_contact(g, x, y, 0.0, 0.0);
      ASSERT_TRUE(c.active);
      const double d = 1e-10;
      auto e = [&](double px, double py) {
        const GuideContact k = guide_contact(g, px, py, 0.0, 0.0);
        return k.active ? k.energy : 0.0;
      };
      const double fx = -(e(x + d, y) - e(x - d, y)) / (2 * d);
      const double fy = -(e(x, y + d) - e(x, y - d)) / (2 * d);
      const double scale = std::max(1e-3, std::hypot(c.fx, c.fy));
      EXPECT_NEAR(c.fx, fx, 1e-4 * scale);
      EXPECT_NEAR(c.fy, fy, 1e-4 * scale);
      EXPECT_NEAR(std::hypot(c.fx, c.fy), c.normal_force, 1e-12 * scale);
    }
  }
}

TEST(DynamicsGuide, NewtonBlocksMatchFiniteDifferencesOfTheForce) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0), s(-1.0, 1.0);
  int checked = 0;
  for (const Guide& g : rails(0.3)) {
    for (int trial = 0; trial < 200; ++trial) {
      double x = 0.0, y = 0.0;
      touch_point(g, 0.05 + 0.9 * u(rng), 4e-6 * u(rng) + 2e-7, x, y);
      // sliding speeds from inside the friction band (1 mm/s) to 2 m/s; normal speeds small
      // enough for the damper not to lift the roller off
      const double vx = (trial % 3 == 0 ? 2e-3 : 2.0) * s(rng);
      const double vy = (trial % 3 == 0 ? 2e-3 : 2.0) * s(rng);
      const GuideContact c = guide_contact(g, x, y, vx, vy);
      if (!(c.normal_force > 0.0)) continue;
      const double dx = 1e-9, dv = 1e-9 * std::max(1e-3, std::hypot(vx, vy));
      const double q[2] = {x, y}, v[2] = {vx, vy};
      for (int col = 0; col < 2; ++col) {
        double qp[2] = {q[0], q[1]}, qm[2] = {q[0], q[1]};
        qp[col] += dx;
        qm[col] -= dx;
        const GuideContact a = guide_contact(g, qp[0], qp[1], vx, vy);
        const GuideContact b = guide_contact(g, qm[0], qm[1], vx, vy);
        const double scale = 1e-5 * (std::abs(c.dq[col]) + std::abs(c.dq[2 + col])) + 1e-2;
        EXPECT_NEAR(c.dq[col], (a.fx - b.fx) / (2 * dx), scale) << "dq x" << col;
        EXPECT_NEAR(c.dq[2 + col], (a.fy - b.fy) / (2 * dx), scale) << "dq y" << col;
        double vp[2] = {v[0], v[1]}, vm[2] = {v[0], v[1]};
        vp[col] += dv;
        vm[col] -= dv;
        const GuideContact e = guide_contact(g, x, y, vp[0], vp[1]);
        const GuideContact f = guide_contact(g, x, y, vm[0], vm[1]);
        const double vscale = 1e-5 * (std::abs(c.dv[col]) + std::abs(c.dv[2 + col])) + 1e-6;
        EXPECT_NEAR(c.dv[col], (e.fx - f.fx) / (2 * dv), vscale) << "dv x" << col;
        EXPECT_NEAR(c.dv[2 + col], (e.fy - f.fy) / (2 * dv), vscale) << "dv y" << col;
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 400);
}

TEST(DynamicsGuide, SlidingFrictionIsCoulombOutsideTheBand) {
  for (const Guide& g : rails(0.25)) {
    double x = 0.0, y = 0.0;
    touch_point(g, 0.5, 5e-6, x, y);
    const GuideContact rest = guide_contact(g, x, y, 0.0, 0.0);
    const double tx = -rest.ny, ty = rest.nx;
    for (double speed : {-3.0, -0.1, 0.1, 3.0}) {
      const GuideContact c = guide_contact(g, x, y, speed * tx, speed * ty);
      // opposes the sliding, μ f within 1/(2 (v/v_ε)²) = 5e-5 at 0.1 m/s
      EXPECT_LT(c.friction_force * speed, 0.0);
      EXPECT_NEAR(std::abs(c.friction_force), 0.25 * c.normal_force, 6e-5 * c.normal_force);
      EXPECT_DOUBLE_EQ(c.slip, speed);
    }
    const GuideContact still = guide_contact(g, x, y, 0.0, 0.0);
    EXPECT_EQ(still.friction_force, 0.0);
  }
}

TEST(DynamicsGuide, OneSidedAndOnlyBetweenItsEnds) {
  for (const Guide& g : rails(0.2)) {
    double x = 0.0, y = 0.0;
    touch_point(g, 0.5, -1e-4, x, y);  // clear of the rail on the free side
    EXPECT_FALSE(guide_contact(g, x, y, 0.0, 0.0).active);
    touch_point(g, 0.5, 2.5 * kRoller, x, y);  // centre past the surface: the far side
    EXPECT_FALSE(guide_contact(g, x, y, 0.0, 0.0).active);
    touch_point(g, -0.02, 1e-6, x, y);  // beyond the first end
    EXPECT_FALSE(guide_contact(g, x, y, 0.0, 0.0).active);
    touch_point(g, 1.02, 1e-6, x, y);  // beyond the second end
    EXPECT_FALSE(guide_contact(g, x, y, 0.0, 0.0).active);
    touch_point(g, 0.99, 1e-6, x, y);
    EXPECT_TRUE(guide_contact(g, x, y, 0.0, 0.0).active);
  }
}

TEST(DynamicsGuide, InvalidGuidesListEveryProblem) {
  Model m = uniform_chain(4, false, 0.01905, 0.024, 1e7, 0.0, false);
  Guide a = straight_rail(-0.1);
  a.x1 = a.x0;
  a.y1 = a.y0;
  a.friction_band = 0.0;
  Guide b = arc_rail(true, 1.5);
  b.radius = 0.001;  // inside, smaller than the roller
  b.end_angle = b.start_angle;
  b.contact_stiffness = -1.0;
  m.guides = {a, b};
  const std::vector<Issue> issues = validate(m);
  std::vector<std::string> fields;
  for (const Issue& i : issues) fields.push_back(i.field);
  for (const char* f :
       {"guide[0].end", "guide[0].friction", "guide[0].friction_band", "guide[1].radius",
        "guide[1].end_angle", "guide[1].contact_stiffness", "guide[1].friction"}) {
    EXPECT_NE(std::find(fields.begin(), fields.end(), f), fields.end()) << f;
  }
}

// Two rollers joined by one link slide along a level rail under gravity from v₀: Coulomb friction
// stops them after v₀²/(2 μ g), at t = v₀/(μ g), and the friction work the steps report is the
// kinetic energy lost.
TEST(DynamicsGuide, RollersSlideToRestOnALevelRail) {
  const double p = 0.01905, m = 0.024, mu = 0.3, g0 = 9.81, v0 = 0.5;
  Model model = uniform_chain(2, false, p, m, 1e6, 5.0, false);
  model.gravity_y = -g0;
  Guide rail;
  rail.x0 = -1.0;
  rail.x1 = 1.0;
  rail.roller_radius = kRoller;
  rail.contact_stiffness = 1e6;
  rail.contact_damping = 50.0;
  rail.friction = mu;
  rail.friction_band = 1e-4;
  model.guides = {rail};
  State s(2, 0);
  const double sink = m * g0 / rail.contact_stiffness + 0.5 * rail.contact_smoothing;
  for (std::size_t i = 0; i < 2; ++i) {
    s.x[i] = p * static_cast<double>(i);
    s.y[i] = kRoller - sink;
    s.vx[i] = v0;
  }
  const Energy e0 = energy(model, s);
  Integrator integrator(model, {.step = 2e-4, .theta = 0.5});
  const double t_stop = v0 / (mu * g0);
  while (s.time < 1.5 * t_stop) {
    const StepReport r = integrator.step(model, s);
    ASSERT_TRUE(r.converged) << s.time;
  }
  const double distance = s.x[0];
  EXPECT_NEAR(distance, v0 * v0 / (2 * mu * g0), 2e-3 * distance);
  EXPECT_LT(std::abs(s.vx[0]), 1e-3 * v0);  // crept to rest within the band's scale
  const Energy e1 = energy(model, s);
  // everything the friction took: ½ (2m) v₀² (the rest of the energy is back where it was)
  EXPECT_NEAR(s.friction_work, -(e0.total() - e1.total()), 2e-3 * m * v0 * v0);
  EXPECT_NEAR(s.friction_work, -m * v0 * v0, 1e-2 * m * v0 * v0);
}

// The integrator culls node–guide pairs by guide_bounds before guide_contact: the cull must be
// exact. Random straight rails and arcs (inside and outside, any orientation and span), random
// roller centres concentrated where contact is possible (on and around the contact band, near
// the ends): every centre the brute-force guide_contact finds active lies in the bounds. The
// points are drawn so that both outcomes, and centres just outside the band, occur many times.
TEST(Guide, BoundsNeverCullAPossibleContact) {
  std::mt19937_64 rng(20261126);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  auto uni = [&](double a, double b) { return a + (b - a) * u01(rng); };
  long active = 0, culled = 0, near_edge = 0;
  for (int trial = 0; trial < 400; ++trial) {
    // rollers of 1–20 mm, within ±5 m of the origin, rails up to 2 m, arcs from just over the
    // roller's radius to 1 m spanning 1 mrad to a whole turn
    const Guide g = testing::random_guide(rng, trial, testing::GuideRanges{});
    const double r = g.roller_radius;
    const GuideBounds b = guide_bounds(g);
    for (int k = 0; k < 2000; ++k) {
      double x = 0.0, y = 0.0;
      // a point at a random place along the surface (a little past its ends too), at a normal
      // offset within ±1.5 r of the contact band's middle
      const double off = uni(-1.5, 1.5) * r;
      const double along = uni(-0.1, 1.1);
      testing::point_near(g, along, off, x, y);
      const GuideContact c = guide_contact(g, x, y, uni(-2.0, 2.0), uni(-2.0, 2.0));
      const bool possible = guide_touch_possible(b, x, y);
      if (c.active) {
        ++active;
        ASSERT_TRUE(possible) << "trial " << trial << " point (" << x << ", " << y << ")";
        // the bounds are tight: within the roller radius (and the padding) of the surface
        if (std::abs(std::abs(off) - r) < 0.05 * r) ++near_edge;
      }
      if (!possible) ++culled;
    }
  }
  EXPECT_GT(active, 100000);
  EXPECT_GT(culled, 10000);
  EXPECT_GT(near_edge, 1000);
}

// The bounds of a rail with a non-finite coordinate cull nothing (guide_contact decides).
TEST(Guide, BoundsOfANonFiniteRailCoverThePlane) {
  Guide g = straight_rail(0.0);
  g.x1 = NAN;
  const GuideBounds b = guide_bounds(g);
  EXPECT_TRUE(guide_touch_possible(b, 1e6, -1e6));
}

}  // namespace
}  // namespace catena::dynamics
