// Sticking on a guide (Guide::stick_stiffness, issue 21; docs/models/dynamics.md, "Guides:
// sticking"): the stick law's Newton blocks against central differences of the force and of the
// step's residual; a short piece of chain resting on an incline with tan β < μ holds (the
// regularised law creeps); with tan β > μ it slides at g (sin β − μ cos β) under either law; an
// incline tilted slowly through μ lets go at tan β = μ; the work balance closes with the stick
// springs' energy and the slip's dissipation, also where a lifted roller's spring is released
// (and where a held roller is moved far off the rail between two steps); the springs stay within
// their reach μ f/k_t and every step's friction work is ≤ 0; on arcs ("On an arc": s = ±ρ_c φ)
// the Newton blocks, a piece held on a convex arc's slope, and a piece crossing a closed inside
// arc's seam, stopping and held with the balance closing; the balance with the hinges' stick law
// on the same run (both kinds of spring); and the stick stiffness's bad values are named (also on
// a frictionless rail; an arc's accepted).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "catena/dynamics/integrator.hpp"
#include "random_guides.hpp"
#include "residual_difference.hpp"

namespace catena::dynamics {
namespace {

constexpr double kPitch = 0.01905, kMass = 0.024, kG = 9.81, kRoller = 0.006035;
constexpr double kContact = 1e6;  // [N/m] the rail's penalty

// A level rail from x = −1 to 1 m, rollers on top; the incline is the gravity's tilt β (the
// downhill direction −x), the same problem turned by β.
Guide level_rail(double mu, double stick) {
  Guide g;
  g.x0 = -1.0;
  g.x1 = 1.0;
  g.roller_radius = kRoller;
  g.contact_stiffness = kContact;
  g.contact_damping = 20.0;
  g.friction = mu;
  g.stick_stiffness = stick;
  return g;
}

void tilt(Model& m, double beta) {
  m.gravity_x = -kG * std::sin(beta);
  m.gravity_y = -kG * std::cos(beta);
}

// The penetration where a rail's contact (kContact, smoothing ε) carries the normal force w:
// k g²/2ε = w within the ramp (g < ε), k (g − ε/2) = w beyond.
double resting_sink(double w, double eps) {
  return w / kContact >= 0.5 * eps ? w / kContact + 0.5 * eps : std::sqrt(2.0 * eps * w / kContact);
}

// Two rollers one link apart resting on the rail (their normal contact in equilibrium), at rest.
struct Piece {
  Model model;
  State state{2, 0};
};
// With `load` [kg/m] conveyed on the rail (Guide::load_per_metre): each roller carries its
// pitch's share q_L p too.
Piece resting_piece(double mu, double stick, double beta, double load = 0.0) {
  Piece p;
  p.model = uniform_chain(2, false, kPitch, kMass, 1e6, 5.0, false);
  tilt(p.model, beta);
  p.model.guides = {level_rail(mu, stick)};
  p.model.guides[0].load_per_metre = load;
  const double sink = resting_sink((kMass + load * kPitch) * kG * std::cos(beta),
                                   p.model.guides[0].contact_smoothing);
  for (std::size_t i = 0; i < 2; ++i) {
    p.state.x[i] = kPitch * static_cast<double>(i);
    p.state.y[i] = kRoller - sink;
  }
  return p;
}

// The contact's ∂F/∂q and ∂F/∂v at q = (x, y), v = (vx, vy) about the anchor `anchor`, column by
// column against central differences of guide_contact about the same anchor (`k` names the
// contact in a failure).
void expect_blocks_match_differences(const Guide& g, const GuideFrame& f, double x, double y,
                                     double vx, double vy, double anchor, int k) {
  const GuideContact c = guide_contact(g, f, x, y, vx, vy, anchor);
  const double dx = 1e-10, dv = 1e-8;
  const double q[2] = {x, y}, v[2] = {vx, vy};
  for (int col = 0; col < 2; ++col) {
    double qp[2] = {q[0], q[1]}, qm[2] = {q[0], q[1]};
    qp[col] += dx;
    qm[col] -= dx;
    const GuideContact a = guide_contact(g, f, qp[0], qp[1], vx, vy, anchor);
    const GuideContact b = guide_contact(g, f, qm[0], qm[1], vx, vy, anchor);
    const double tol = 1e-5 * (std::abs(c.dq[col]) + std::abs(c.dq[2 + col])) + 1e-2;
    EXPECT_NEAR(c.dq[col], (a.fx - b.fx) / (2 * dx), tol) << k << " dq x" << col;
    EXPECT_NEAR(c.dq[2 + col], (a.fy - b.fy) / (2 * dx), tol) << k << " dq y" << col;
    double vp[2] = {v[0], v[1]}, vm[2] = {v[0], v[1]};
    vp[col] += dv;
    vm[col] -= dv;
    const GuideContact e = guide_contact(g, f, x, y, vp[0], vp[1], anchor);
    const GuideContact h = guide_contact(g, f, x, y, vm[0], vm[1], anchor);
    const double vtol = 1e-5 * (std::abs(c.dv[col]) + std::abs(c.dv[2 + col])) + 1e-6;
    EXPECT_NEAR(c.dv[col], (e.fx - h.fx) / (2 * dv), vtol) << k << " dv x" << col;
    EXPECT_NEAR(c.dv[2 + col], (e.fy - h.fy) / (2 * dv), vtol) << k << " dv y" << col;
  }
  // the stick law: the spring (and its damper, −c_t ṡ, ṡ by differences of s along v) within
  // the reach, μ f beyond (never the regularised φ); along t times σ, ∂s/∂q = σ t (1 on a
  // straight rail, ρ_c/|q − C| on an arc, from the geometry here)
  const bool arc = g.kind == Guide::Kind::kArc;
  const double sigma = arc ? (g.inside ? g.radius - g.roller_radius : g.radius + g.roller_radius) /
                                 std::hypot(x - g.centre_x, y - g.centre_y)
                           : 1.0;
  double spring = -g.stick_stiffness * (c.position - anchor);
  if (g.stick_damping > 0.0) {
    const double e = 1e-5;  // [s]
    const double sdot = (guide_position(g, f, x + e * vx, y + e * vy) -
                         guide_position(g, f, x - e * vx, y - e * vy)) /
                        (2 * e);
    spring -= g.stick_damping * sdot;
  }
  spring *= sigma;
  if (c.sticking) {
    if (g.stick_damping > 0.0)
      EXPECT_NEAR(c.friction_force, spring, 1e-7 * std::abs(spring)) << k;
    else if (arc)
      EXPECT_NEAR(c.friction_force, spring, 1e-13 * std::abs(spring)) << k;
    else
      EXPECT_DOUBLE_EQ(c.friction_force, spring) << k;
  }
  if (!c.sticking) {
    EXPECT_DOUBLE_EQ(std::abs(c.friction_force), g.friction * c.normal_force) << k;
    EXPECT_GT(c.friction_force * spring, 0.0) << k;
  }
}

// Sticking and sliding contacts on the inclined rail of the guides' tests: ∂F/∂q and ∂F/∂v
// column by column against central differences of guide_contact about the same anchor, on both
// sides of the spring's reach μ f/k_t.
TEST(GuideStick, ContactBlocksMatchFiniteDifferencesOfTheForce) {
  for (const double damper : {0.0, 300.0}) {
    Guide g = testing::inclined_rail(0.3);
    g.stick_stiffness = 2e5;
    g.stick_damping = damper;
    const GuideFrame f = guide_frame(g);
    int sticking = 0, sliding = 0;
    for (int k = 0; k < 40; ++k) {
      const double along = 0.1 + 0.015 * k, depth = 1.2e-6 + 1e-7 * k;  // beyond the ramp
      const double x = g.x0 + along * f.ux + (g.roller_radius - depth) * -f.uy;
      const double y = g.y0 + along * f.uy + (g.roller_radius - depth) * f.ux;
      const double vx = 0.01 * std::sin(k), vy = 0.01 * std::cos(3.0 * k);
      // deflections from well within the reach μ f/k_t (10 … 70 µm here) to beyond it, either way
      const double s = guide_position(g, f, x, y);
      const double anchor = s - (k % 2 == 0 ? 1.0 : -1.0) * 2e-6 * (1 + k);
      const GuideContact c = guide_contact(g, f, x, y, vx, vy, anchor);
      ASSERT_TRUE(c.normal_force > 0.0) << k;
      (c.sticking ? sticking : sliding)++;
      expect_blocks_match_differences(g, f, x, y, vx, vy, anchor, k);
    }
    EXPECT_GT(sticking, 5) << damper;
    EXPECT_GT(sliding, 5) << damper;
  }
  Guide g = testing::inclined_rail(0.3);
  g.stick_stiffness = 2e5;
  const GuideFrame f = guide_frame(g);
  // a NaN anchor or k_t = 0: the regularised contact, bit for bit
  double x = 0.0, y = 0.0;
  x = g.x0 + 0.3 * f.ux - (g.roller_radius - 2e-6) * f.uy;
  y = g.y0 + 0.3 * f.uy + (g.roller_radius - 2e-6) * f.ux;
  const GuideContact plain = guide_contact(g, f, x, y, 0.01, 0.0);
  const GuideContact none = guide_contact(g, f, x, y, 0.01, 0.0, NAN);
  EXPECT_EQ(plain.fx, none.fx);
  EXPECT_EQ(plain.fy, none.fy);
  Guide off = g;
  off.stick_stiffness = 0.0;
  EXPECT_EQ(guide_contact(off, f, x, y, 0.01, 0.0, 0.0).fx, plain.fx);
}

// (9) An arc guide (R = 30 mm about (0.1, −0.2) m from 0.3 to 4 rad, the rollers outside it and
// inside it; a soft penalty 1e4 N/m so that rollers sunk up to 1.4 r stay at sane forces, where
// the roller centres' line's radius ρ_c is up to 1.3 times the roller's distance from the centre):
// the position along t is ρ_c φ outside and −ρ_c φ inside (φ from the start angle, as the conveyed
// load's), and ∂F/∂q and ∂F/∂v match central differences sticking and sliding (anchors from 0.3 to
// 2.5 times the spring's reach μ f/k_t either way) — with ∂s/∂q = ρ_c t/|q − C| and t turning with
// the roller.
TEST(GuideStick, ArcContactBlocksMatchFiniteDifferencesOfTheForce) {
  for (const double damper : {0.0, 30.0})
    for (const bool inside : {false, true}) {
      Guide g;
      g.kind = Guide::Kind::kArc;
      g.centre_x = 0.1;
      g.centre_y = -0.2;
      g.radius = 0.03;
      g.start_angle = 0.3;
      g.end_angle = 4.0;
      g.inside = inside;
      g.roller_radius = kRoller;
      g.contact_stiffness = 1e4;
      g.contact_damping = 20.0;
      g.friction = 0.3;
      g.stick_stiffness = 2e5;
      g.stick_damping = damper;
      Model m = uniform_chain(2, false, kPitch, kMass, 1e6, 5.0, false);
      m.guides = {g};
      ASSERT_TRUE(validate(m).empty()) << inside;
      const GuideFrame f = guide_frame(g);
      const double line = inside ? g.radius - kRoller : g.radius + kRoller, sgn = inside ? -1 : 1;
      int sticking = 0, sliding = 0;
      double widest = 0.0;    // the largest |ρ_c/|q − C| − 1| met
      double gradient = 0.0;  // the largest |F_t + ∇E|/|F_t| sticking, without the damper
      double switched = 0.0;  // the largest ||F_t|/μ f − 1| at an anchor moved by the update
      for (int k = 0; k < 48; ++k) {
        const double phi = 0.2 + 0.07 * k, depth = 5e-5 + 1.8e-4 * k;  // up to 1.4 r
        const double d = line - sgn * depth;
        widest = std::max(widest, std::abs(line / d - 1.0));
        const double x = g.centre_x + d * std::cos(g.start_angle + phi);
        const double y = g.centre_y + d * std::sin(g.start_angle + phi);
        const double vx = 0.02 * std::sin(k), vy = 0.02 * std::cos(3.0 * k);
        const GuideContact plain = guide_contact(g, f, x, y, vx, vy);
        ASSERT_TRUE(plain.normal_force > 0.0) << k;
        const double s = guide_position(g, f, x, y);
        EXPECT_NEAR(s, sgn * line * phi, 1e-14) << k;
        const double reach = g.friction * plain.normal_force / g.stick_stiffness;
        const double frac[4] = {0.3, 0.7, 1.4, 2.5};
        const double anchor =
            s - (k % 2 == 0 ? 1.0 : -1.0) * frac[k % 4 / 2 + 2 * (k % 8 / 4)] * reach;
        const GuideContact c = guide_contact(g, f, x, y, vx, vy, anchor);
        EXPECT_EQ(c.normal_force, plain.normal_force) << k;
        (c.sticking ? sticking : sliding)++;
        expect_blocks_match_differences(g, f, x, y, vx, vy, anchor, k);
        // sticking without the damper, the spring's force is minus the gradient of its energy
        // ½ k_t (s − a)² (central differences of the position), not −k_t (s − a) t
        if (damper == 0.0 && c.sticking) {
          auto spring_energy = [&](double px, double py) {
            const double st = stick_stretch(g, guide_position(g, f, px, py), anchor);
            return 0.5 * g.stick_stiffness * st * st;
          };
          const double e = 1e-8;
          const double gx = (spring_energy(x + e, y) - spring_energy(x - e, y)) / (2 * e);
          const double gy = (spring_energy(x, y + e) - spring_energy(x, y - e)) / (2 * e);
          const double ft = std::abs(c.friction_force);
          EXPECT_NEAR(-c.ny * c.friction_force, -gx, 1e-7 * ft) << k;
          EXPECT_NEAR(c.nx * c.friction_force, -gy, 1e-7 * ft) << k;
          gradient = std::max(
              gradient,
              std::hypot(-c.ny * c.friction_force + gx, c.nx * c.friction_force + gy) / ft);
        }
        // the anchor's update agrees with the switch: a sticking spring's anchor is kept, and a
        // sliding one's, moved with the roller staying where it is, leaves the spring exactly at
        // μ f (its force along t σ k_t (s − a): the reach μ f/(k_t σ))
        if (damper == 0.0) {
          const double next = stick_anchor_after(g, c, anchor, c.position);
          if (c.sticking) {
            EXPECT_EQ(next, anchor) << k;
          } else {
            const GuideContact moved = guide_contact(g, f, x, y, vx, vy, next);
            const double limit = g.friction * moved.normal_force;
            EXPECT_NEAR(std::abs(moved.friction_force), limit, 1e-9 * limit) << k;
            switched = std::max(switched, std::abs(std::abs(moved.friction_force) / limit - 1.0));
          }
        }
        // a NaN anchor: the regularised contact, bit for bit
        const GuideContact none = guide_contact(g, f, x, y, vx, vy, NAN);
        EXPECT_EQ(none.fx, plain.fx);
        EXPECT_EQ(none.fy, plain.fy);
      }
      EXPECT_GT(sticking, 10) << inside;
      EXPECT_GT(sliding, 10) << inside;
      EXPECT_GT(widest, 0.2) << inside;
      if (damper == 0.0)
        std::printf(
            "arc stick spring (%s): largest |F_t + grad E|/|F_t| %.2e, sigma - 1 up to %.3f, "
            "|F_t|/mu f - 1 after the anchor's update %.2e\n",
            inside ? "inside" : "outside", gradient, widest, switched);
    }
}

// The step's Newton matrix with the stick law: every column against central differences of the
// step's residual, node 0 sticking and node 1 sliding (their anchors `offset` from where they
// start in the state), moved to `u`; the stick spring's share of the matrix is not negligible.
void expect_newton_matrix_has_the_stick_blocks(Piece p, const double (&offset)[2],
                                               const std::vector<double>& u, std::size_t rail) {
  const Guide& g = p.model.guides[rail];
  const GuideFrame f = guide_frame(g);
  p.state.stick_anchor = {guide_position(g, f, p.state.x[0], p.state.y[0]) + offset[0],
                          guide_position(g, f, p.state.x[1], p.state.y[1]) + offset[1]};
  const double h = 1e-3;
  Integrator integ(p.model, {.step = h, .theta = 0.6});
  std::vector<double> r, jac, bare;
  integ.newton_system(p.model, p.state, u, r, &jac);
  Model plain = p.model;
  plain.guides[rail].stick_stiffness = 0.0;
  plain.guides[rail].stick_damping = 0.0;
  Integrator base(plain, {.step = h, .theta = 0.6});
  base.newton_system(plain, p.state, u, r, &bare);
  double scale = 0.0, stick = 0.0;
  for (std::size_t k = 0; k < 16; ++k) {
    scale = std::max(scale, std::abs(jac[k]));
    stick = std::max(stick, std::abs(jac[k] - bare[k]));
  }
  EXPECT_GT(stick, 1e-3 * scale) << "the stick spring's block is not negligible";
  for (std::size_t c = 0; c < 4; ++c) {
    const std::vector<double> fd =
        testing::residual_difference(integ, p.model, p.state, u, c, 1e-9);
    for (std::size_t row = 0; row < 4; ++row)
      EXPECT_NEAR(jac[row * 4 + c], fd[row], 1e-6 * scale) << "row " << row << " column " << c;
  }
}

TEST(GuideStick, IntegratorNewtonMatrixHasTheStickBlocks) {
  const Piece p = resting_piece(0.3, 1e5, 0.0);
  const std::vector<double> u{p.state.x[0] - 1e-7, p.state.y[0], p.state.x[1] + 3e-7, p.state.y[1]};
  expect_newton_matrix_has_the_stick_blocks(p, {2e-7, -2e-4}, u, 0);
}

// Runs the piece for `seconds`; returns the largest downhill displacement of node 0 from its start.
double run(Piece& p, double seconds, double h, double theta) {
  Integrator integ(p.model, {.step = h, .theta = theta});
  const double x0 = p.state.x[0];
  double most = 0.0;
  while (p.state.time < seconds - 0.5 * h) {
    const StepReport r = integ.step(p.model, p.state);
    EXPECT_TRUE(r.converged) << p.state.time;
    if (!r.converged) break;
    most = std::max(most, x0 - p.state.x[0]);
  }
  EXPECT_NEAR(p.state.time, seconds, h);
  return most;
}

// (1) tan β = μ/2: with the stick law the piece holds — over 1 s its displacement stays within
// twice the spring's static deflection m g sin β/k_t (a load applied at once overshoots to twice
// it) and settles to it within 1 %; the regularised law creeps at about the band's speed.
TEST(GuideStick, APieceHoldsOnAnInclineBelowTheFrictionAngle) {
  const double mu = 0.3, kt = 1e5, beta = std::atan(0.5 * mu);
  const double deflection = kMass * kG * std::sin(beta) / kt;
  Piece held = resting_piece(mu, kt, beta);
  const double most = run(held, 1.0, 2e-4, 0.6);
  EXPECT_LE(most, 2.0 * deflection * (1 + 1e-3));
  EXPECT_NEAR(-held.state.x[0], deflection, 0.01 * deflection);
  EXPECT_NEAR(kPitch - held.state.x[1], deflection, 0.01 * deflection);
  Piece creeps = resting_piece(mu, 0.0, beta);
  const double crept = run(creeps, 1.0, 2e-4, 0.6);
  // φ(v) = tan β/μ = ½: v = v_ε/√3 ≈ 0.58 mm/s
  EXPECT_GT(crept, 1e-4);
  EXPECT_NEAR(-creeps.state.vx[0], 1e-3 / std::sqrt(3.0), 0.05e-3);
}

// (2) tan β = 2μ: either law slides at a = g (sin β − μ cos β), measured over 0.1 … 0.3 s.
TEST(GuideStick, APieceSlidesAtTheAnalyticAccelerationAboveIt) {
  const double mu = 0.25, beta = std::atan(2.0 * mu);
  const double a = kG * (std::sin(beta) - mu * std::cos(beta));
  for (const double kt : {0.0, 1e5}) {
    Piece p = resting_piece(mu, kt, beta);
    run(p, 0.1, 2e-4, 0.5);
    const double v1 = -p.state.vx[0], t1 = p.state.time;
    run(p, 0.3, 2e-4, 0.5);
    const double v2 = -p.state.vx[0], t2 = p.state.time;
    EXPECT_NEAR((v2 - v1) / (t2 - t1), a, 0.01 * a) << "k_t " << kt;
  }
}

// (3) The incline tilted slowly (tan β from 0.8 μ to 1.2 μ over 4 s): with the stick law the piece
// lets go at tan β = μ within 0.5 % (it has slid 2 µm by then, 30 times the static deflection); the
// regularised law creeps from the start.
double tan_at_slip(double kt) {
  const double mu = 0.3, lo = 0.8 * mu, hi = 1.2 * mu, span = 4.0, h = 2e-4;
  Piece p = resting_piece(mu, kt, std::atan(lo));
  Integrator integ(p.model, {.step = h, .theta = 0.6});
  const double x0 = p.state.x[0];
  while (p.state.time < span) {
    const double t = lo + (hi - lo) * p.state.time / span;
    tilt(p.model, std::atan(t));
    if (!integ.step(p.model, p.state).converged) return NAN;
    if (x0 - p.state.x[0] > 2e-6) return t;
  }
  return INFINITY;
}
TEST(GuideStick, AnInclineTiltedThroughTheFrictionAngleLetsGoThere) {
  EXPECT_NEAR(tan_at_slip(1e6), 0.3, 0.0015);
  EXPECT_LT(tan_at_slip(0.0), 0.25);
}

// (4) Two rollers sliding along a level rail from v₀ stop after v₀²/2μg and stay (no creep); the
// work balance closes: the energy lost (the stick springs' energy counted) is the slip's
// dissipation −Σ μ f |Δa| the steps report (with the contact and link dampers' work), ½ (2m) v₀².
TEST(GuideStick, WorkBalanceClosesWithTheSpringsEnergyAndTheSlip) {
  const double mu = 0.3, v0 = 0.5;
  Piece p = resting_piece(mu, 1e5, 0.0);
  p.state.vx = {v0, v0};
  const Energy e0 = energy(p.model, p.state);
  const double t_stop = v0 / (mu * kG);
  run(p, 1.5 * t_stop, 2e-4, 0.5);
  const double distance = p.state.x[0];
  EXPECT_NEAR(distance, v0 * v0 / (2 * mu * kG), 2e-3 * distance);
  const double stopped = p.state.x[0];
  run(p, 1.5 * t_stop + 0.5, 2e-4, 0.5);
  const double spring_reach = mu * kMass * kG / 1e5;
  EXPECT_LT(std::abs(p.state.x[0] - stopped), 2.0 * spring_reach);  // held, not creeping
  const Energy e1 = energy(p.model, p.state);
  const double dissipated =
      p.state.friction_work + p.state.contact_damping_work + p.state.damper_work;
  EXPECT_NEAR(dissipated, e1.total() - e0.total(), 1e-4 * kMass * v0 * v0);
  EXPECT_NEAR(p.state.friction_work, -kMass * v0 * v0, 1e-3 * kMass * v0 * v0);
}

// (5) A piece held on an incline (tan β = μ/2, a soft k_t = 1e3 N/m: its springs deflected by
// m g sin β/k_t = 35 µm) lifted off the rail (the gravity turned away from it): the anchors are
// released and the springs' energy let go is counted as dissipated, so that the balance over the
// lift-off still closes.
TEST(GuideStick, ReleasedSpringsEnergyIsCountedWhenLiftedOff) {
  const double mu = 0.3, kt = 1e3, beta = std::atan(0.5 * mu);
  Piece p = resting_piece(mu, kt, beta);
  run(p, 0.05, 2e-4, 0.5);
  ASSERT_EQ(p.state.stick_anchor.size(), 2u);
  ASSERT_TRUE(std::isfinite(p.state.stick_anchor[0]));
  p.model.gravity_y = kG;  // away from the rail
  const Energy e0 = energy(p.model, p.state);
  const Guide& g = p.model.guides[0];
  double stored = 0.0;
  for (std::size_t i = 0; i < 2; ++i) {
    const double d =
        guide_position(g, guide_frame(g), p.state.x[i], p.state.y[i]) - p.state.stick_anchor[i];
    stored += 0.5 * kt * d * d;
  }
  const double w0 = p.state.friction_work + p.state.contact_damping_work + p.state.damper_work;
  run(p, 0.07, 2e-4, 0.5);
  EXPECT_GT(p.state.y[0], kRoller + 1e-4);  // off the rail
  EXPECT_TRUE(std::isnan(p.state.stick_anchor[0]));
  EXPECT_TRUE(std::isnan(p.state.stick_anchor[1]));
  const double w1 = p.state.friction_work + p.state.contact_damping_work + p.state.damper_work;
  EXPECT_GT(stored, 1e-7);
  EXPECT_NEAR(w1 - w0, energy(p.model, p.state).total() - e0.total(), 1e-2 * stored);
}

// (14) The held piece of (5) moved 1 m off the rail between two steps (its rollers far outside the
// rail's box and the guides' hint's lists, which the anchors' update visits with the anchored
// nodes): the next step releases both anchors all the same and counts their springs' energy as
// dissipated.
TEST(GuideStick, AnAnchorFarOffTheRailIsReleased) {
  const double mu = 0.3, kt = 1e3, beta = std::atan(0.5 * mu);
  Piece p = resting_piece(mu, kt, beta);
  run(p, 0.05, 2e-4, 0.5);
  ASSERT_EQ(p.state.stick_anchor.size(), 2u);
  const Guide& g = p.model.guides[0];
  double stored = 0.0;
  for (std::size_t i = 0; i < 2; ++i) {
    ASSERT_TRUE(std::isfinite(p.state.stick_anchor[i])) << i;
    const double d =
        guide_position(g, guide_frame(g), p.state.x[i], p.state.y[i]) - p.state.stick_anchor[i];
    stored += 0.5 * kt * d * d;
    p.state.y[i] += 1.0;
  }
  EXPECT_GT(stored, 1e-7);
  const double w0 = p.state.friction_work;
  Integrator integ(p.model, {.step = 2e-4, .theta = 0.5});
  ASSERT_TRUE(integ.step(p.model, p.state).converged);
  EXPECT_TRUE(std::isnan(p.state.stick_anchor[0]));
  EXPECT_TRUE(std::isnan(p.state.stick_anchor[1]));
  EXPECT_NEAR(p.state.friction_work - w0, -stored, 1e-9 * stored);
}

// (6) The holdback question with a conveyed load: the piece carrying 2.5 kg/m on the same rail
// (q_L p = 48 g a roller, twice its own mass) at tan β = μ/2 holds with the stick law — within
// twice the springs' static deflection under the whole weight, (m + q_L p) g sin β/k_t (a load
// applied at once overshoots to twice it; θ = ½ does not damp the ringing) — and creeps with the
// regularised law at v_ε/√3 (the load leaves tan β/μ as it is); the work balance closes with the
// load's work in either.
TEST(GuideStick, ALoadedPieceHoldsAndTheBalanceClosesWithTheLoadsWork) {
  const double mu = 0.3, kt = 1e5, beta = std::atan(0.5 * mu), load = 2.5;
  const double weight = kMass + load * kPitch;  // [kg] a roller's share
  const double deflection = weight * kG * std::sin(beta) / kt;
  for (const double k : {kt, 0.0}) {
    Piece p = resting_piece(mu, k, beta, load);
    ASSERT_TRUE(validate(p.model).empty());
    const Energy e0 = energy(p.model, p.state);
    const double most = run(p, 1.0, 2e-4, 0.5);
    const double lost = energy(p.model, p.state).total() - e0.total();
    const double works = p.state.friction_work + p.state.contact_damping_work +
                         p.state.damper_work + p.state.load_work;
    // the load works on the chain: it moves down (holding: the springs' deflection; creeping:
    // 0.58 mm)
    EXPECT_GT(p.state.load_work, 0.0) << "k_t " << k;
    EXPECT_NEAR(lost, works, 1e-3 * p.state.load_work) << "k_t " << k;
    if (k > 0.0) {
      EXPECT_LE(most, 2.0 * deflection * (1 + 1e-3));
      EXPECT_GT(most, 1.5 * deflection);  // the load's weight is carried by the springs
      std::printf(
          "loaded, held: largest displacement %.4g static deflections, balance %.3g of "
          "the load's work %.4g J\n",
          most / deflection, (lost - works) / p.state.load_work, p.state.load_work);
    } else {
      EXPECT_GT(most, 1e-4);
      EXPECT_NEAR(-p.state.vx[0], 1e-3 / std::sqrt(3.0), 0.05e-3);
      std::printf("loaded, regularised: crept %.4g mm, balance %.3g of the load's work %.4g J\n",
                  most * 1e3, (lost - works) / p.state.load_work, p.state.load_work);
    }
  }
}

// (7) The springs are left at most at their reach: two rollers sliding from 0.5 m/s on a level
// rail at θ = 0.6 (a step moves them 100 µm, 140 times the reach μ m g/k_t = 0.7 µm): after every
// step each spring's energy ½ k_t (s − a)² stays within (μ f)²/2k_t (f within 2 % of m g), and
// every step's friction work is ≤ 0 — sliding, stopping and held; where both hold it is
// −k_t (θ − ½) Σ Δs², the θ-method's damping of the springs.
TEST(GuideStick, SpringsStayWithinTheirReachAndEveryStepDissipates) {
  const double mu = 0.3, kt = 1e5, v0 = 0.5, h = 2e-4, theta = 0.6;
  Piece p = resting_piece(mu, kt, 0.0);
  p.state.vx = {v0, v0};
  const Guide& g = p.model.guides[0];
  const GuideFrame f = guide_frame(g);
  const double bound = 0.5 * std::pow(mu * 1.02 * kMass * kG, 2) / kt;
  Integrator integ(p.model, {.step = h, .theta = theta});
  double most = 0.0, worst = -INFINITY, held_work = 0.0;
  int sliding = 0, held = 0;
  while (p.state.time < 0.3) {
    const std::vector<double> a0 = p.state.stick_anchor;
    double s0[2];
    for (std::size_t i = 0; i < 2; ++i) s0[i] = guide_position(g, f, p.state.x[i], p.state.y[i]);
    const StepReport r = integ.step(p.model, p.state);
    ASSERT_TRUE(r.converged) << p.state.time;
    worst = std::max(worst, r.friction_work);
    EXPECT_LE(r.friction_work, 1e-15) << p.state.time;
    if (p.state.vx[0] > 0.01) ++sliding;
    double sticking = 0.0;  // −k_t (θ − ½) Σ Δs², what the θ-method takes from held springs
    for (std::size_t i = 0; i < 2; ++i) {
      const double s1 = guide_position(g, f, p.state.x[i], p.state.y[i]);
      const double d = s1 - p.state.stick_anchor[i];
      most = std::max(most, 0.5 * kt * d * d);
      EXPECT_LE(0.5 * kt * d * d, bound) << p.state.time << " node " << i;
      sticking -= kt * (theta - 0.5) * (s1 - s0[i]) * (s1 - s0[i]);
    }
    if (a0.size() == 2 && a0 == p.state.stick_anchor && std::isfinite(a0[0] + a0[1])) {
      // both held (their anchors kept): the step's friction work is exactly that
      ++held;
      held_work += r.friction_work;
      // (within 1e-5 of it: the θ point rounded in the last bits of positions ~0.1 m)
      // term) J)
      EXPECT_NEAR(r.friction_work, sticking, 1e-5 * std::abs(sticking) + 1e-17) << p.state.time;
    }
  }
  EXPECT_GT(sliding, 100);  // it slid for 0.17 s and stopped
  EXPECT_GT(held, 100);
  EXPECT_LT(p.state.vx[0], 1e-3);
  EXPECT_GT(most, 0.5 * bound);  // the springs did reach their reach
  EXPECT_LT(held_work, 0.0);
  std::printf(
      "largest spring energy %.4g of (mu m g)^2/2k_t; largest step friction work %.3g J; "
      "%d held steps' friction work %.4g J\n",
      most / bound * 1.02 * 1.02, worst, held, held_work);
}

// (8) A piece passing from a lead-in arc (regularised law, R = 0.2 m, 0.2 rad) onto the sticking
// rail at 0.8 m/s: each roller is anchored on arrival, within its spring's reach of where it ends
// that step, and never anchored on the arc; sliding at μ f either way, the piece's speed follows
// the regularised rail's within 1e-3 of v₀ until it has nearly stopped (no jump in the force
// beyond the contact's own), it stops and is held (within twice the spring's reach over its last
// 0.1 s), and the work balance over the passage closes.
TEST(GuideStick, ARollerComingOffALeadInIsAnchoredOnArrival) {
  const double mu = 0.3, kt = 1e5, v0 = 0.8, h = 2e-4, radius = 0.2, sweep = 0.2;
  auto entering = [&](double k) {
    Piece p;
    p.model = uniform_chain(2, false, kPitch, kMass, 1e6, 5.0, false);
    tilt(p.model, 0.0);
    // the arc first: the rail is guide 1, the only sticking one (its anchors State::stick_anchor's
    // first N)
    const Guide rail = level_rail(mu, k);
    p.model.guides = lead_in_arcs(rail, {.radius = radius, .angle = sweep, .at_end = false});
    p.model.guides.push_back(rail);
    const Guide& arc = p.model.guides.at(0);
    // the rollers on the arc short of the joint at φ = π/2 (the leading one 6 mm before it),
    // resting on it, moving along it toward the rail
    const double rho = radius + kRoller -
                       std::sqrt(2.0 * arc.contact_smoothing * kMass * kG /
                                 kContact);  // the sink under the weight
    const double phi0 = 0.5 * std::numbers::pi + 0.03;
    const double phi[2] = {phi0, phi0 + 2.0 * std::asin(0.5 * kPitch / rho)};
    for (std::size_t i = 0; i < 2; ++i) {
      p.state.x[i] = arc.centre_x + rho * std::cos(phi[i]);
      p.state.y[i] = arc.centre_y + rho * std::sin(phi[i]);
      p.state.vx[i] = v0 * std::sin(phi[i]);
      p.state.vy[i] = -v0 * std::cos(phi[i]);
    }
    return p;
  };
  Piece p = entering(kt), q = entering(0.0);
  ASSERT_TRUE(validate(p.model).empty());
  const Guide& rail = p.model.guides[1];
  const GuideFrame f = guide_frame(rail);
  const double x0 = rail.x0;
  const double reach = mu * 1.5 * kMass * kG / kt;  // the normal force within 1.5 m g
  const Energy e0 = energy(p.model, p.state);
  Integrator integ(p.model, {.step = h, .theta = 0.5}), plain(q.model, {.step = h, .theta = 0.5});
  bool arrived[2] = {false, false};
  double worst = 0.0, lo = INFINITY, hi = -INFINITY;
  while (p.state.time < 0.4) {
    ASSERT_TRUE(integ.step(p.model, p.state).converged) << p.state.time;
    ASSERT_TRUE(plain.step(q.model, q.state).converged) << q.state.time;
    for (std::size_t i = 0; i < 2; ++i) {
      ASSERT_EQ(p.state.stick_anchor.size(), 2u);  // the sticking rail's only
      const double a = p.state.stick_anchor[i];
      const double s1 = guide_position(rail, f, p.state.x[i], p.state.y[i]);
      if (p.state.x[i] < x0 - 1e-4) {
        EXPECT_TRUE(std::isnan(a)) << p.state.time << " node " << i;
      }
      if (p.state.x[i] > x0 + 1e-4) {
        EXPECT_TRUE(std::isfinite(a)) << p.state.time << " node " << i;
        arrived[i] = true;
      }
      if (std::isfinite(a)) {
        EXPECT_LE(std::abs(s1 - a), reach) << p.state.time << " node " << i;
      }
    }
    if (q.state.vx[0] > 0.05) worst = std::max(worst, std::abs(p.state.vx[0] - q.state.vx[0]));
    if (p.state.time > 0.3) {  // stopped (after about 0.28 s): held, ringing within the reach
      lo = std::min(lo, p.state.x[0]);
      hi = std::max(hi, p.state.x[0]);
    }
  }
  EXPECT_TRUE(arrived[0] && arrived[1]);
  EXPECT_LT(worst, 1e-3 * v0);
  EXPECT_LT(hi - lo, 2.0 * reach);  // stopped on the rail
  EXPECT_GT(p.state.x[1], x0 + 0.01);
  const double dissipated =
      p.state.friction_work + p.state.contact_damping_work + p.state.damper_work;
  EXPECT_NEAR(energy(p.model, p.state).total() - e0.total(), dissipated, 1e-4 * kMass * v0 * v0);
  std::printf("lead-in: speed difference %.3g of v0, balance %.3g of m v0^2, stopped at %.4g m\n",
              worst / v0,
              (energy(p.model, p.state).total() - e0.total() - dissipated) / (kMass * v0 * v0),
              p.state.x[1]);
}

// An arc guide of radius R about the origin from `start` to `end` [rad], the rollers outside it
// or `inside`, otherwise the level rail's (μ, k_t, its penalty and damper).
Guide arc_rail(double radius, double start, double end, bool inside, double mu, double stick) {
  return testing::arc_rail(level_rail(mu, stick), 0.0, 0.0, radius, start, end, inside);
}

// Two rollers one link apart on the arc `g` under the gravity −y, node 0 at the angle `at` and
// node 1 a chord on counter-clockwise, both at the roller centres' line sunk by the penetration
// that carries node 0's weight's normal part, moving at `speed` counter-clockwise.
Piece piece_on_arc(const Guide& g, double at, double speed = 0.0) {
  Piece p;
  p.model = uniform_chain(2, false, kPitch, kMass, 1e6, 5.0, false);
  tilt(p.model, 0.0);
  p.model.guides = {g};
  const double sgn = g.inside ? -1.0 : 1.0, line = g.radius + sgn * g.roller_radius;
  const double rho =
      line - sgn * resting_sink(kMass * kG * sgn * std::sin(at), g.contact_smoothing);
  const double phi[2] = {at, at + 2.0 * std::asin(0.5 * kPitch / rho)};
  for (std::size_t i = 0; i < 2; ++i) {
    p.state.x[i] = rho * std::cos(phi[i]);
    p.state.y[i] = rho * std::sin(phi[i]);
    p.state.vx[i] = -speed * std::sin(phi[i]);
    p.state.vy[i] = speed * std::cos(phi[i]);
  }
  return p;
}

// (10) The step's Newton matrix on arcs (a convex one, R = 0.5 m, the piece 0.15 rad down its
// slope; a closed inside one, the piece at its bottom): node 0 sticking, node 1 sliding, against
// central differences of the step's residual.
TEST(GuideStick, IntegratorNewtonMatrixHasTheStickBlocksOnAnArc) {
  constexpr double kPi = std::numbers::pi;
  for (const double damper : {0.0, 30.0})
    for (const bool inside : {false, true}) {
      Guide g = inside ? arc_rail(0.5, -0.5 * kPi, 1.5 * kPi, true, 0.3, 1e5)
                       : arc_rail(0.5, 0.3, kPi - 0.3, false, 0.3, 1e5);
      g.stick_damping = damper;
      const Piece p = piece_on_arc(g, inside ? -0.5 * kPi + 0.01 : 0.5 * kPi + 0.15);
      ASSERT_TRUE(validate(p.model).empty());
      const std::vector<double> u{p.state.x[0] - 1e-7, p.state.y[0] + 2e-8, p.state.x[1] + 3e-7,
                                  p.state.y[1] - 1e-8};
      expect_newton_matrix_has_the_stick_blocks(p, {2e-7, -2e-4}, u, 0);
    }
}

// Each node's displacement along its guide's tangent (guide_position) since `from`: the largest
// over a run, and the last.
struct Travel {
  double most[2] = {0.0, 0.0}, last[2] = {0.0, 0.0};
};
Travel run_along(Piece& p, double seconds, double h, double theta) {
  const Guide& g = p.model.guides[0];
  const GuideFrame f = guide_frame(g);
  double s0[2];
  for (std::size_t i = 0; i < 2; ++i) s0[i] = guide_position(g, f, p.state.x[i], p.state.y[i]);
  Integrator integ(p.model, {.step = h, .theta = theta});
  Travel t;
  while (p.state.time < seconds - 0.5 * h) {
    const StepReport r = integ.step(p.model, p.state);
    EXPECT_TRUE(r.converged) << p.state.time;
    if (!r.converged) break;
    for (std::size_t i = 0; i < 2; ++i) {
      t.last[i] = guide_position(g, f, p.state.x[i], p.state.y[i]) - s0[i];
      t.most[i] = std::max(t.most[i], std::abs(t.last[i]));
    }
  }
  return t;
}

// (11) A piece resting on a convex arc's slope (R = 0.5 m, its two rollers 5.1° and 7.3° from the
// top, tan β = 0.09 and 0.13 < μ = 0.3): with the stick law it holds — over 1 s each roller moves
// along the arc at most twice the springs' static deflection m g sin β₁/k_t under the steeper
// roller's load (a load applied at once overshoots to twice it, here within the reach μ f/k_t),
// and settles within 2 % of m g (sin β₀ + sin β₁)/2k_t (the link shares the load) — while the
// regularised law creeps down it.
TEST(GuideStick, APieceHoldsOnAConvexArcsSlopeBelowTheFrictionAngle) {
  constexpr double kPi = std::numbers::pi;
  const double mu = 0.3, kt = 1e5, radius = 0.5, at = 0.5 * kPi + std::atan(0.3 * mu);
  Piece held = piece_on_arc(arc_rail(radius, 0.3, kPi - 0.3, false, mu, kt), at);
  ASSERT_TRUE(validate(held.model).empty());
  const double beta[2] = {std::atan2(-held.state.x[0], held.state.y[0]),
                          std::atan2(-held.state.x[1], held.state.y[1])};
  ASSERT_LT(std::tan(beta[1]), 0.5 * mu);
  const double steeper = kMass * kG * std::sin(beta[1]) / kt;
  const double shared = kMass * kG * (std::sin(beta[0]) + std::sin(beta[1])) / (2.0 * kt);
  const Travel t = run_along(held, 1.0, 2e-4, 0.6);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_LE(t.most[i], 2.0 * steeper) << i;
    EXPECT_NEAR(t.last[i], shared, 0.02 * shared) << i;
  }
  std::printf(
      "convex arc, held: largest %.4g and %.4g of the steeper static deflection %.3g m, "
      "final %.5g and %.5g of the shared one\n",
      t.most[0] / steeper, t.most[1] / steeper, steeper, t.last[0] / shared, t.last[1] / shared);
  Piece creeps = piece_on_arc(arc_rail(radius, 0.3, kPi - 0.3, false, mu, 0.0), at);
  const Travel c = run_along(creeps, 1.0, 2e-4, 0.6);
  EXPECT_GT(c.last[0], 1e-4);
  EXPECT_GT(c.last[1], 1e-4);
  std::printf("convex arc, regularised: crept %.4g mm\n", c.last[0] * 1e3);
}

// (12) A piece sliding at 0.5 m/s along the bottom of a closed inside arc (R = 0.5 m, its seam at
// the bottom, where φ and s jump by the circumference) climbs it, stops and is held: every spring
// stays within its reach μ f/k_t after every step (the stretch taken across the seam), every
// step's friction work is ≤ 0 (a roller crossing the seam is not taken as a jump back of one
// circumference; positive at most by the midpoint rule's error on a held roller's ringing), both
// rollers cross the seam, are held over the last 0.2 s within twice their reach, and the work
// balance closes: the energy lost (the springs' energy counted) is the friction's and the dampers'
// work.
TEST(GuideStick, OnAClosedInsideArcThePieceCrossesTheSeamStopsAndTheBalanceCloses) {
  constexpr double kPi = std::numbers::pi;
  const double mu = 0.3, kt = 1e5, v0 = 0.5, h = 2e-4;
  Piece p = piece_on_arc(arc_rail(0.5, -0.5 * kPi, 1.5 * kPi, true, mu, kt), -0.5 * kPi - 0.05, v0);
  ASSERT_TRUE(validate(p.model).empty());
  const Guide& g = p.model.guides[0];
  const GuideFrame f = guide_frame(g);
  const double reach = mu * 1.5 * kMass * kG / kt;  // the normal force within 1.5 m g
  // a held spring's ringing exchanges energy with the roller: the force is minus the gradient of
  // the spring's energy E = ½ k_t (s − a)² at the θ point (θ = ½), so a held step books as
  // friction work only the midpoint rule's error over the step, (1/24) E‴ Δq³ with E‴ ≈ 3 k_t/ρ_c
  // through s's curvature: k_t Δq³/8ρ_c, Δq at most h ω times the reach (ω = √(k_t/m), a roller
  // ringing within its reach). The force −k_t (s − a) t (not σ times it, σ = ρ_c/|q − C|) booked
  // 13.5 times that (the penetration's g/ρ_c share of the energy exchanged).
  const double rho = g.radius - g.roller_radius, swing = h * std::sqrt(kt / kMass) * reach;
  const double ringing = kt * swing * swing * swing / (8.0 * rho);
  const Energy e0 = energy(p.model, p.state);
  Integrator integ(p.model, {.step = h, .theta = 0.5});
  double worst = -INFINITY, lo = INFINITY, hi = -INFINITY;
  bool crossed[2] = {false, false};
  while (p.state.time < 0.6) {
    const StepReport r = integ.step(p.model, p.state);
    ASSERT_TRUE(r.converged) << p.state.time;
    worst = std::max(worst, r.friction_work);
    EXPECT_LE(r.friction_work, ringing) << p.state.time;
    for (std::size_t i = 0; i < 2; ++i) {
      const double a = p.state.stick_anchor.at(i);
      ASSERT_TRUE(std::isfinite(a)) << p.state.time << " node " << i;
      const double s = guide_position(g, f, p.state.x[i], p.state.y[i]);
      EXPECT_LE(std::abs(stick_stretch(g, s, a)), reach) << p.state.time << " node " << i;
      if (p.state.x[i] > 0.0) crossed[i] = true;
    }
    if (p.state.time > 0.4) {
      lo = std::min(lo, p.state.x[0]);
      hi = std::max(hi, p.state.x[0]);
    }
  }
  EXPECT_TRUE(crossed[0] && crossed[1]);
  EXPECT_LT(hi - lo, 2.0 * reach);
  const double dissipated =
      p.state.friction_work + p.state.contact_damping_work + p.state.damper_work;
  const double lost = energy(p.model, p.state).total() - e0.total();
  EXPECT_NEAR(lost, dissipated, 1e-4 * kMass * v0 * v0);
  std::printf(
      "closed inside arc: stopped at %.4g m, largest step friction work %.3g J (%.3g of a "
      "spring's energy at its reach, %.3g of the bound %.3g J), balance %.3g of m v0^2, friction "
      "work %.4g of m v0^2\n",
      p.state.x[0], worst, worst / (0.5 * kt * reach * reach), worst / ringing, ringing,
      (lost - dissipated) / (kMass * v0 * v0), p.state.friction_work / (kMass * v0 * v0));
}

// (13) The stick law's damper (Guide::stick_damping c_t = 50 N·s/m, half the critical 2 √(k_t m))
// on a piece held on the incline at tan β = 0.3 μ at θ = ½ (which does not damp): the springs'
// ringing, which without it keeps swinging through about twice the static deflection
// m g sin β/k_t, dies out — over the last 0.2 s of 1 s the piece moves less than 1e-3 of the
// deflection and rests at it within 1e-3 — every step's friction work is ≤ 0 (the damper's
// −c_t ṡ v_t h; the spring's share is 0 at θ = ½), and the work balance closes: the energy lost
// (the springs' energy counted) is the friction's and the dampers' work within 1e-6 of the
// friction work.
TEST(GuideStick, TheStickDamperDampsAHeldPiecesRinging) {
  const double mu = 0.3, kt = 1e5, beta = std::atan(0.3 * mu), h = 2e-4;
  const double deflection = kMass * kG * std::sin(beta) / kt;
  for (const double damper : {50.0, 0.0}) {
    Piece p = resting_piece(mu, kt, beta);
    p.model.guides[0].stick_damping = damper;
    ASSERT_TRUE(validate(p.model).empty());
    const Energy e0 = energy(p.model, p.state);
    Integrator integ(p.model, {.step = h, .theta = 0.5});
    double lo = INFINITY, hi = -INFINITY, worst = -INFINITY;
    while (p.state.time < 1.0 - 0.5 * h) {
      const StepReport r = integ.step(p.model, p.state);
      ASSERT_TRUE(r.converged) << p.state.time;
      worst = std::max(worst, r.friction_work);
      if (p.state.time > 0.8) {
        lo = std::min(lo, -p.state.x[0]);
        hi = std::max(hi, -p.state.x[0]);
      }
    }
    const double lost = energy(p.model, p.state).total() - e0.total();
    const double works = p.state.friction_work + p.state.contact_damping_work + p.state.damper_work;
    std::printf(
        "stick damper %g N s/m: swing over the last 0.2 s %.3g of the static deflection, "
        "rests at %.6g of it, friction work %.4g J, largest a step %.3g J, balance %.3g of "
        "the friction work\n",
        damper, (hi - lo) / deflection, p.state.x[0] / -deflection, p.state.friction_work, worst,
        (lost - works) / p.state.friction_work);
    if (damper > 0.0) {
      EXPECT_LT(hi - lo, 1e-3 * deflection);
      EXPECT_NEAR(-p.state.x[0], deflection, 1e-3 * deflection);
      EXPECT_LE(worst, 1e-15);
      EXPECT_LT(p.state.friction_work, 0.0);
      EXPECT_NEAR(lost, works, 1e-6 * std::abs(p.state.friction_work));
    } else {
      EXPECT_GT(hi - lo, 0.5 * deflection);
    }
  }
}

// (15) Both stick laws in one run: an open 12-node chain with hinge friction (μ 0.1 on the 12B
// pin, e = 0.286 mm) and the hinges' stick law (k_t = 1 N·m/rad) lies with eight rollers on a
// sticking rail (k_t = 1e4 N/m, μ = 0.3; the penalty on its discrete gradient, so that the
// contact's work is exactly its energy's change) and four hanging over the rail's end, swinging
// under a 10 N load at the end node. Each lying roller is pressed on the rail by 10 N and pushed
// back by 0.5 N, so that the rail's springs hold their share of the swinging end's pull; the
// lying part starts sliding away from the end at 0.3 m/s and stops on its springs. At θ = ½
// the balance ΔE = W_friction + W_hinge + W_dampers closes to Newton's tolerance; both kinds of
// spring hold energy at the end, each far beyond that bound, so that the balance fails without
// either's ½ k_t d² in energy().
TEST(GuideStick, HingeAndRailStickLawsTogetherCloseTheWorkBalance) {
  constexpr std::size_t kLying = 8, kNodes = 12;
  const double press = 10.0, push = 0.5, end_load = 10.0, rail_kt = 1e4, hinge_kt = 1.0;
  Model m = uniform_chain(kNodes, false, kPitch, kMass, 5e7, 5.0, false);
  m.gravity_y = -kG;
  m.hinge = HingeFriction{.arm = 2.86e-4, .rate_band = 5.0};
  m.hinge.stick_stiffness = hinge_kt;
  Guide rail = level_rail(0.3, rail_kt);
  rail.x1 = 0.0;  // the rail ends at x = 0
  rail.discrete_gradient = true;
  m.guides = {rail};
  const double level = kRoller - resting_sink(kMass * kG + press, rail.contact_smoothing);
  State s(kNodes, 0);
  const double edge = -5e-3;  // the last lying roller, 5 mm before the rail's end
  for (std::size_t i = 0; i < kNodes; ++i) {
    if (i < kLying) {
      s.x[i] = edge - kPitch * static_cast<double>(kLying - 1 - i);
      s.y[i] = level;
      s.vx[i] = -0.3;  // sliding away from the end, to stop within 0.4 mm
      m.loads.push_back({.node = i, .fx = -push, .fy = -press});
    } else {
      // hanging straight down from the last lying roller, swinging outwards at 30 rad/s
      const double depth = kPitch * static_cast<double>(i + 1 - kLying);
      s.x[i] = edge;
      s.y[i] = level - depth;
      s.vx[i] = 30.0 * depth;
    }
  }
  m.loads.push_back({.node = kNodes - 1, .fx = 0.0, .fy = -end_load});
  Integrator integ(m, {.step = 1e-4, .tolerance = 1e-12, .theta = 0.5});
  const double e0 = energy(m, s).total();
  double largest_kinetic = 0.0;
  int sticking_steps = 0;
  for (int k = 0; k < 1000; ++k) {
    const StepReport r = integ.step(m, s);
    ASSERT_TRUE(r.converged) << k;
    largest_kinetic = std::max(largest_kinetic, energy(m, s).kinetic);
    bool held = true;
    for (std::size_t i = 0; i < kLying; ++i) held = held && std::isfinite(s.stick_anchor[i]);
    sticking_steps += held ? 1 : 0;
  }
  // every lying roller anchored on the rail throughout, none of the hanging ones
  EXPECT_EQ(sticking_steps, 1000);
  for (std::size_t i = kLying; i < kNodes; ++i) EXPECT_TRUE(std::isnan(s.stick_anchor[i])) << i;
  // the springs' energies at the end, from the state
  const GuideFrame frame = guide_frame(m.guides[0]);
  double rail_springs = 0.0, hinge_springs = 0.0;
  for (std::size_t i = 0; i < kLying; ++i) {
    const double d = guide_position(m.guides[0], frame, s.x[i], s.y[i]) - s.stick_anchor[i];
    rail_springs += 0.5 * rail_kt * d * d;
  }
  for (const double d : s.hinge_deflection) hinge_springs += 0.5 * hinge_kt * d * d;
  const double dissipated =
      s.friction_work + s.hinge_work + s.damper_work + s.contact_damping_work + s.drag_work;
  const double balance = energy(m, s).total() - e0 - dissipated;
  std::printf(
      "both stick laws: friction work %.6e J, hinge work %.6e J, dampers %.6e J; springs at the "
      "end: rail %.6e J, hinges %.6e J; largest kinetic %.6e J; balance %.3e J\n",
      s.friction_work, s.hinge_work, s.damper_work + s.contact_damping_work, rail_springs,
      hinge_springs, largest_kinetic, balance);
  // the bound: 1e-9 of the swing's kinetic energy (Newton's tolerance, 1e-12 p, on forces of
  // tens of N over 1000 steps)
  const double bound = 1e-9 * largest_kinetic;
  EXPECT_LT(std::abs(balance), bound);
  EXPECT_GT(rail_springs, 100.0 * bound);
  EXPECT_GT(hinge_springs, 100.0 * bound);
  // both frictions did work: the hinges slid as the end swung, the rail's rollers slid and stopped
  EXPECT_LT(s.hinge_work, -1e3 * bound);
  EXPECT_LT(s.friction_work, -1e3 * bound);
}

TEST(GuideStick, BadStickStiffnessNamed) {
  Model m = uniform_chain(4, false, kPitch, kMass, 1e7, 0.0, false);
  // a frictionless rail (μ = 0) has nothing to stick with: its spring's reach μ f/k_t is 0; an
  // arc sticks as a straight rail does, and is refused as one
  m.guides = {level_rail(0.3, -1.0),
              level_rail(0.3, NAN),
              arc_rail(0.2, 0.0, 1.0, false, 0.3, 1e5),
              level_rail(0.3, 1e5),
              level_rail(0.3, 0.0),
              level_rail(0.0, 1e5),
              level_rail(0.0, 0.0),
              arc_rail(0.2, 0.0, 1.0, true, 0.0, 1e5),
              arc_rail(0.2, 0.0, 1.0, true, 0.3, -1.0),
              level_rail(0.3, 1e5),
              level_rail(0.3, 1e5),
              level_rail(0.3, 0.0),
              arc_rail(0.2, 0.0, 1.0, false, 0.3, 1e5)};
  // the stick law's damper: finite, ≥ 0, and only beside a spring
  m.guides[9].stick_damping = -1.0;
  m.guides[10].stick_damping = NAN;
  m.guides[11].stick_damping = 10.0;
  m.guides[12].stick_damping = 10.0;
  std::vector<std::string> fields;
  for (const Issue& i : validate(m)) fields.push_back(i.field);
  const std::vector<std::string> want{"guide[0].stick_stiffness", "guide[1].stick_stiffness",
                                      "guide[5].stick_stiffness", "guide[7].stick_stiffness",
                                      "guide[8].stick_stiffness", "guide[9].stick_damping",
                                      "guide[10].stick_damping",  "guide[11].stick_damping"};
  EXPECT_EQ(fields, want);
  // a lead-in's arcs slide with the regularised law: they do not inherit the rail's k_t
  Guide damped = level_rail(0.3, 1e5);
  damped.stick_damping = 10.0;
  for (const Guide& a : lead_in_arcs(damped, {.radius = 0.05, .angle = 0.3})) {
    EXPECT_EQ(a.stick_stiffness, 0.0);
    EXPECT_EQ(a.stick_damping, 0.0);
  }
}

}  // namespace
}  // namespace catena::dynamics
