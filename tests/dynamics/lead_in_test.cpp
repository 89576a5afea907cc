// Lead-ins on straight guides (docs/models/dynamics.md, "Lead-ins"): the arcs lead_in_arcs lays
// are tangent to the rail at its ends (the surface point and its direction continuous), the
// contact's force is continuous across the joint and its Newton blocks match central differences
// on both sides of it up to the joint (where the bare rail's square end makes the force jump by
// the whole contact force), the lead-in's values are checked, and on a conveyor whose rails stand
// a little above the rollers' line the entering rollers' peak rail force falls with lead-ins.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>

#include "catena/dynamics/guide_hint.hpp"
#include "catena/dynamics/integrator.hpp"
#include "catena/dynamics/layout.hpp"
#include "random_guides.hpp"
#include "two_wheel_loops.hpp"

namespace catena::dynamics {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kRoller = 0.006035;  // [m] 12B roller radius

using testing::inclined_rail;  // tests/dynamics/random_guides.hpp

// the force of the rail and its lead-in arcs together, and their Newton blocks summed
struct Total {
  double fx = 0.0, fy = 0.0;
  double dq[4] = {0, 0, 0, 0}, dv[4] = {0, 0, 0, 0};
  int active = 0;
};
Total total(const std::vector<Guide>& guides, double x, double y, double vx, double vy) {
  Total t;
  for (const Guide& g : guides) {
    const GuideContact c = guide_contact(g, x, y, vx, vy);
    if (!c.active) continue;
    ++t.active;
    t.fx += c.fx;
    t.fy += c.fy;
    for (int k = 0; k < 4; ++k) {
      t.dq[k] += c.dq[k];
      t.dv[k] += c.dv[k];
    }
  }
  return t;
}

TEST(DynamicsLeadIn, ArcsAreTangentToTheRailAtItsEnds) {
  for (const double angle : {0.1, 0.5, kPi / 3, kPi / 2}) {
    for (const double radius : {0.01, 0.05, 2.0}) {
      const Guide rail = inclined_rail(0.0);
      const std::vector<Guide> arcs = lead_in_arcs(rail, {radius, angle, true, true});
      ASSERT_EQ(arcs.size(), 2U);
      const double len = std::hypot(rail.x1 - rail.x0, rail.y1 - rail.y0);
      const double ux = (rail.x1 - rail.x0) / len, uy = (rail.y1 - rail.y0) / len;
      const double nx = -uy, ny = ux;
      for (int end = 0; end < 2; ++end) {
        const Guide& a = arcs[static_cast<std::size_t>(end)];
        EXPECT_EQ(a.kind, Guide::Kind::kArc);
        EXPECT_FALSE(a.inside);
        EXPECT_EQ(a.radius, radius);
        EXPECT_NEAR(a.end_angle - a.start_angle, angle, 1e-15);
        // the arc's end at the joint: the rail's end, with the rail's normal, and going on along
        // the rail's direction (away from the rail: −u at the first end, +u at the second)
        const double at = end == 0 ? a.start_angle : a.end_angle;
        const double px = a.centre_x + radius * std::cos(at),
                     py = a.centre_y + radius * std::sin(at);
        const double ex = end == 0 ? rail.x0 : rail.x1, ey = end == 0 ? rail.y0 : rail.y1;
        EXPECT_NEAR(px, ex, 1e-15 * (1.0 + radius)) << end;
        EXPECT_NEAR(py, ey, 1e-15 * (1.0 + radius)) << end;
        EXPECT_NEAR(std::cos(at), nx, 1e-15);
        EXPECT_NEAR(std::sin(at), ny, 1e-15);
        // the tangent d/dφ of the surface point, pointing away from the rail
        const double sgn = end == 0 ? 1.0 : -1.0;  // the first end's arc grows counter-clockwise
        const double tx = -sgn * std::sin(at), ty = sgn * std::cos(at);
        const double along = end == 0 ? -1.0 : 1.0;
        EXPECT_NEAR(tx, along * ux, 1e-15);
        EXPECT_NEAR(ty, along * uy, 1e-15);
        // the other end of the arc: R sin α past the rail's end, R (1 − cos α) below the surface
        const double other = end == 0 ? a.end_angle : a.start_angle;
        const double qx = a.centre_x + radius * std::cos(other) - ex;
        const double qy = a.centre_y + radius * std::sin(other) - ey;
        EXPECT_NEAR(qx * ux + qy * uy, along * radius * std::sin(angle), 1e-12 * (1.0 + radius));
        EXPECT_NEAR(qx * nx + qy * ny, -radius * (1.0 - std::cos(angle)), 1e-12 * (1.0 + radius));
      }
      EXPECT_EQ(lead_in_arcs(rail, {radius, angle, true, false}).size(), 1U);
      EXPECT_EQ(lead_in_arcs(rail, {radius, angle, false, true})[0].start_angle,
                arcs[1].start_angle);
    }
  }
}

// A roller pressed 2 µm into the rail slides across the joint at its second end: with the lead-in
// the force is continuous (its change over ±δ of order the force's slope times δ), and at points
// approaching the joint from both sides ∂F/∂q and ∂F/∂v match central differences; without it the
// force drops to nothing past the square end.
TEST(DynamicsLeadIn, ForceContinuousAndNewtonBlocksMatchCentralDifferencesAcrossTheJoint) {
  const Guide rail = inclined_rail(0.3);
  std::vector<Guide> with{rail};
  for (const Guide& a : lead_in_arcs(rail, {0.05, kPi / 4, true, true})) with.push_back(a);
  const std::vector<Guide> bare{rail};
  const double len = std::hypot(rail.x1 - rail.x0, rail.y1 - rail.y0);
  const double ux = (rail.x1 - rail.x0) / len, uy = (rail.y1 - rail.y0) / len;
  const double nx = -uy, ny = ux;
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int checked = 0;
  for (int end = 0; end < 2; ++end) {
    const double ex = end == 0 ? rail.x0 : rail.x1, ey = end == 0 ? rail.y0 : rail.y1;
    const double out = end == 0 ? -1.0 : 1.0;  // along u, away from the rail
    for (const double depth : {2e-6, 5e-5}) {
      const double off = kRoller - depth;
      const auto point = [&](double s, double& x, double& y) {  // s: past the end, along u·out
        x = ex + out * s * ux + off * nx;
        y = ey + out * s * uy + off * ny;
      };
      const double vx = 0.3 * out * ux + 1e-4 * nx, vy = 0.3 * out * uy + 1e-4 * ny;
      for (const double delta : {1e-5, 1e-7}) {
        double xa = 0, ya = 0, xb = 0, yb = 0;
        point(-delta, xa, ya);
        point(delta, xb, yb);
        const Total in = total(with, xa, ya, vx, vy), past = total(with, xb, yb, vx, vy);
        ASSERT_EQ(in.active, 1);
        ASSERT_EQ(past.active, 1);
        const double f = std::hypot(in.fx, in.fy);
        EXPECT_GT(f, 0.5 * 1e7 * depth);
        // across 2δ the force changes by its slope (k_c |∂g/∂s| ≤ k_c δ/R on the arc, and the
        // normal's turn f δ/R): nothing like f
        EXPECT_LT(std::hypot(past.fx - in.fx, past.fy - in.fy),
                  4.0 * (f + 1e7 * delta) * delta / 0.05)
            << "end " << end << " depth " << depth << " delta " << delta;
        const Total bare_past = total(bare, xb, yb, vx, vy);
        EXPECT_EQ(bare_past.active, 0);  // the square end: the whole force lost past it
      }
      // ∂F/∂q and ∂F/∂v against central differences at points approaching the joint from both
      // sides (the difference step well inside the distance to the joint: the stiffness jumps by
      // the arc's curvature term there)
      for (const double s : {-1e-4, -1e-5, -1e-6, 1e-6, 1e-5, 1e-4}) {
        double x = 0, y = 0;
        point(s, x, y);
        // sliding speeds along the rail from −0.4 to 0.4 m/s (the damper's share kept below the
        // elastic force's: no clamp at f = 0 within the differences)
        const double slide = 0.1 * u(rng);
        const double wx = vx + slide * ux, wy = vy + slide * uy;
        const Total c = total(with, x, y, wx, wy);
        ASSERT_EQ(c.active, 1) << s;
        const double dx = 1e-3 * std::abs(s), dv = 1e-7;
        for (int col = 0; col < 2; ++col) {
          double qp[2] = {x, y}, qm[2] = {x, y};
          qp[col] += dx;
          qm[col] -= dx;
          const Total a = total(with, qp[0], qp[1], wx, wy), b = total(with, qm[0], qm[1], wx, wy);
          const double scale = 1e-4 * (std::abs(c.dq[col]) + std::abs(c.dq[2 + col])) + 1e-2;
          EXPECT_NEAR(c.dq[col], (a.fx - b.fx) / (2 * dx), scale) << "dq x" << col << " s " << s;
          EXPECT_NEAR(c.dq[2 + col], (a.fy - b.fy) / (2 * dx), scale)
              << "dq y" << col << " s " << s;
          double vp[2] = {wx, wy}, vm[2] = {wx, wy};
          vp[col] += dv;
          vm[col] -= dv;
          const Total e = total(with, x, y, vp[0], vp[1]), g = total(with, x, y, vm[0], vm[1]);
          const double vscale = 1e-5 * (std::abs(c.dv[col]) + std::abs(c.dv[2 + col])) + 1e-6;
          EXPECT_NEAR(c.dv[col], (e.fx - g.fx) / (2 * dv), vscale) << "dv x" << col << " s " << s;
          EXPECT_NEAR(c.dv[2 + col], (e.fy - g.fy) / (2 * dv), vscale)
              << "dv y" << col << " s " << s;
        }
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked, 24);
}

TEST(DynamicsLeadIn, ValuesOutOfRangeAreNamed) {
  EXPECT_TRUE(validate(LeadIn{0.05, kPi / 6, true, true}).empty());
  EXPECT_TRUE(validate(LeadIn{0.05, kPi / 2, true, false}).empty());
  for (const LeadIn& bad :
       {LeadIn{0.0, 0.0}, LeadIn{-1.0, kPi}, LeadIn{NAN, NAN}, LeadIn{INFINITY, -0.1}}) {
    const std::vector<Issue> issues = validate(bad);
    ASSERT_EQ(issues.size(), 2U);
    EXPECT_EQ(issues[0].field, "lead_in_radius");
    EXPECT_EQ(issues[1].field, "lead_in_angle");
    EXPECT_NE(issues[1].expected.find("[0.1, 90] deg"), std::string::npos);
  }
  // a sweep below 0.1 deg is refused by name (1e-15 deg reached the inner arc guide's end_angle
  // check, a field the user never wrote); 0.1 deg itself is accepted
  const std::vector<Issue> tiny = validate(LeadIn{0.05, 1e-17, true, true});
  ASSERT_EQ(tiny.size(), 1U);
  EXPECT_EQ(tiny[0].field, "lead_in_angle");
  EXPECT_TRUE(validate(LeadIn{0.05, 0.1 * kPi / 180.0, true, true}).empty());
  // none on an arc, none for a lead-in out of range
  Guide arc = inclined_rail(0.0);
  arc.kind = Guide::Kind::kArc;
  EXPECT_TRUE(lead_in_arcs(arc, {0.05, 0.5, true, true}).empty());
  EXPECT_TRUE(lead_in_arcs(inclined_rail(0.0), {0.05, 2.0, true, true}).empty());
}

// A 12B conveyor (z = 16 at 5 rad/s, 60 pitches, gravity) whose two level rails stand 0, 0.1 and
// 0.3 mm above the mean height of the polygon's tangent point (the runs start straight at the
// pitch radius and sag under gravity): the rollers entering a rail meet its end a little below
// its surface. With the bare rails' square ends the impact is more than Newton can take: a step
// fails at about 0.079 s, whatever the rise (its peak counted infinite; so it was in the
// conveyor of validation (6b) before its hand-laid lead-ins). With a 50 mm, 30° lead-in at each
// end every step of the 0.25 s converges and the entering rollers' peak rail force, after the
// start, stays finite (44-62 N here). There is no finite bare peak to compare with: the test
// asserts that the bare ends' run fails and the lead-ins' runs converge with a finite peak.
TEST(DynamicsLeadIn, EnteringRollersRunOnLeadInsWhereTheBareEndsFail) {
  // validation (6b)'s conveyor without its guides (tests/dynamics/two_wheel_loops.hpp: these
  // defaults), started from the two-wheel loop itself (its runs straight at the pitch radius)
  // rather than from conveyor_loop's start lifted onto the rails' level
  testing::Conveyor d;
  d.pieces = 0;
  const testing::Loop loop = testing::conveyor_loop(d);
  const Model& m = loop.model;
  const std::size_t n = m.nodes();
  const double r = 0.5 * d.roller, level = loop.level;
  const double x_lo = d.guide_gap * d.pitch, x_hi = (d.span_links - d.guide_gap) * d.pitch;
  const State start =
      two_sprocket_loop(d.teeth, d.span_links, d.pitch, m.sprockets[0].pitch_radius, d.omega);
  // the peak over the run, or infinity when a step does not converge (Newton fails on the square
  // end's impact)
  const auto peak_entry_force = [&](const std::vector<Guide>& guides) -> double {
    Model mg = m;
    mg.guides = guides;
    State s = start;
    lift_onto_guides(mg.guides, s.x, s.y);
    Integrator integ(mg, {.step = 1e-4, .theta = 0.6});
    double peak = 0.0;
    for (int step = 0; step < 2500; ++step) {
      if (!integ.step(mg, s).converged) return INFINITY;
      if (step < 500) continue;  // the start's settling
      for (std::size_t i = 0; i < n; ++i) {
        // the entering rollers: within 4 pitches of a rail's entry end (the upper run comes from
        // +x, the lower from −x)
        const bool upper = s.y[i] > 0.0;
        const double from_entry = upper ? x_hi - s.x[i] : s.x[i] - x_lo;
        if (from_entry > 4.0 * d.pitch || from_entry < -4.0 * d.pitch) continue;
        for (const Guide& g : mg.guides)
          peak = std::max(peak, guide_contact(g, s.x[i], s.y[i], s.vx[i], s.vy[i]).normal_force);
      }
    }
    return peak;
  };
  for (const double rise : {0.0, 1e-4, 3e-4}) {
    std::vector<Guide> rails;
    for (const double yl : {level, -level}) {
      Guide g;
      g.x0 = x_lo;
      g.x1 = x_hi;
      g.y0 = g.y1 = yl - r + rise;  // left to right: the rollers on top, on both runs
      g.roller_radius = r;
      g.contact_stiffness = 1e7;
      g.contact_damping = 100.0;
      g.friction = 0.3;
      rails.push_back(g);
    }
    const double bare = peak_entry_force(rails);
    std::vector<Guide> led = rails;
    for (const Guide& g : rails)
      for (const Guide& arc : lead_in_arcs(g, {0.05, kPi / 6, true, true})) led.push_back(arc);
    const double smooth = peak_entry_force(led);
    EXPECT_FALSE(std::isfinite(bare)) << rise;   // the bare ends' run fails (above)
    EXPECT_TRUE(std::isfinite(smooth)) << rise;  // every step converged with the lead-ins
    EXPECT_GT(smooth, 0.0) << rise;
    EXPECT_LT(smooth, 100.0) << "rise " << rise << " m: with lead-ins " << smooth << " N";
    std::printf(
        "rails %.2g mm high: entering rollers' peak rail force bare %.4g N, with lead-ins "
        "%.4g N\n",
        rise * 1e3, bare, smooth);
  }
}

// The lead-in's clearance (lead_in_obstacle, lead_in_limit) against an independent brute force on
// the 32-link 12B loop of the CLI's lead-in tests (two z = 12 wheels ten pitches apart): random
// lead-ins (radius 2 mm to 0.15 m, sweep 0.1-90°, start, end or both) on a random level rail under
// the upper run, with a random post (a straight guide 5-40 mm long, any direction) below it. The
// check samples the arc and measures to the path's pieces; the brute force turns it round: it
// samples the path (path_point, every 0.1 mm) and the post (every 0.1 mm) and measures to the arcs.
// A lead-in is refused exactly when some arc comes closer than a roller radius to a point of the
// path off the spans the rail carries (those with a point within a roller's diameter of it) or to
// the post (draws within 2 % of a roller radius of the threshold are left out: the sampling's own
// error). The limits it names (the radius at the sweep, the sweep at the radius) clear, by the
// brute force too.
TEST(DynamicsLeadIn, ClearanceMatchesABruteForceOnRandomLeadIns) {
  const double p = 0.01905, roller = 0.01207, r = 0.5 * roller, step = 1e-4;
  const double radius = 0.5 * p / std::sin(kPi / 12);
  const BeltPath path = belt_path({{0.0, 0.0, radius}, {10 * p, 0.0, radius}}, 0);
  ASSERT_FALSE(path.pieces.empty());
  struct Point {
    double x, y;
    std::size_t piece;
  };
  std::vector<Point> points;  // the path's
  for (double s = 0.0; s < path.length; s += step) {
    const PathPoint q = path_point(path, s);
    points.push_back({q.x, q.y, q.piece});
  }
  auto to_segment = [](double x, double y, const Guide& g) {
    const double ux = g.x1 - g.x0, uy = g.y1 - g.y0;
    const double t =
        std::clamp(((x - g.x0) * ux + (y - g.y0) * uy) / (ux * ux + uy * uy), 0.0, 1.0);
    return std::hypot(x - g.x0 - t * ux, y - g.y0 - t * uy);
  };
  // to an arc: to its circle within its sweep, else to the nearer end
  auto to_arc = [](double x, double y, const Guide& g) {
    const double a = std::atan2(y - g.centre_y, x - g.centre_x);
    for (const double turn : {-2 * kPi, 0.0, 2 * kPi})
      if (a + turn >= g.start_angle && a + turn <= g.end_angle)
        return std::abs(std::hypot(x - g.centre_x, y - g.centre_y) - g.radius);
    return std::min(std::hypot(x - g.centre_x - g.radius * std::cos(g.start_angle),
                               y - g.centre_y - g.radius * std::sin(g.start_angle)),
                    std::hypot(x - g.centre_x - g.radius * std::cos(g.end_angle),
                               y - g.centre_y - g.radius * std::sin(g.end_angle)));
  };
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  int accepted = 0, by_path = 0, by_post = 0, end_near = 0;
  for (int trial = 0; trial < 250; ++trial) {
    Guide upper = inclined_rail(0.0);
    upper.y0 = upper.y1 = radius - r - 1e-3 * u01(rng);  // the rollers 0-1 mm above it
    upper.x0 = 0.12 * u01(rng) - 0.01;
    upper.x1 = upper.x0 + 0.02 + (0.2 - upper.x0) * u01(rng);
    Guide post = inclined_rail(0.0);
    post.x0 = -0.06 + 0.32 * u01(rng);
    post.y0 = -0.04 + 0.07 * u01(rng);
    const double length = 0.005 + 0.035 * u01(rng), direction = 2 * kPi * u01(rng);
    post.x1 = post.x0 + length * std::cos(direction);
    post.y1 = post.y0 + length * std::sin(direction);
    LeadIn lead;
    lead.radius = 0.002 * std::pow(0.15 / 0.002, u01(rng));
    lead.angle = (0.1 + 89.9 * u01(rng)) * kPi / 180.0;
    const int ends = static_cast<int>(3 * u01(rng));
    lead.at_start = ends != 1;
    lead.at_end = ends != 0;
    const std::vector<Guide> arcs = lead_in_arcs(upper, lead);
    ASSERT_FALSE(arcs.empty());
    std::vector<Guide> guides{upper, post};
    guides.insert(guides.end(), arcs.begin(), arcs.end());
    std::vector<std::size_t> skip{0};
    for (std::size_t k = 0; k < arcs.size(); ++k) skip.push_back(2 + k);
    bool blocked = false;
    std::string names;
    for (const Guide& arc : arcs) {
      const std::string what = lead_in_obstacle(path, upper, arc, guides, skip, roller);
      blocked = blocked || !what.empty();
      names += what + " ";
    }
    // the brute force: the pieces the rail carries, then the nearest approach of the path's
    // points (off those) and of the post's to the arcs
    std::vector<bool> carried(path.pieces.size(), false);
    for (const Point& q : points)
      if (!path.pieces[q.piece].arc && to_segment(q.x, q.y, upper) < roller)
        carried[q.piece] = true;
    // path: the least margin of the path's points to the arcs over what each piece allows, a roller
    // radius or, nearer, the rail's end's own distance from the piece (the arc may not close in
    // beyond it); post: the post's nearest approach
    struct Nearest {
      double path = INFINITY, post = INFINITY;
      bool end_near = false;  // the rail's end within a roller radius of a piece off the rail
    };
    auto nearest = [&](const std::vector<Guide>& laid) {
      Nearest n;
      for (std::size_t k = 0; k < laid.size(); ++k) {
        const Guide& arc = laid[k];
        const bool first = k == 0 && lead.at_start;  // lead_in_arcs lays the start's first
        const double ex = first ? upper.x0 : upper.x1, ey = first ? upper.y0 : upper.y1;
        std::vector<double> end(path.pieces.size(), INFINITY);
        for (const Point& q : points)
          end[q.piece] = std::min(end[q.piece], std::hypot(q.x - ex, q.y - ey));
        for (const Point& q : points) {
          if (carried[q.piece]) continue;
          n.end_near = n.end_near || end[q.piece] < r;
          n.path = std::min(n.path, to_arc(q.x, q.y, arc) - std::min(r, end[q.piece]));
        }
        for (double t = 0.0; t <= 1.0; t += step / length)
          n.post = std::min(n.post, to_arc(post.x0 + t * (post.x1 - post.x0),
                                           post.y0 + t * (post.y1 - post.y0), arc));
      }
      return n;
    };
    const Nearest n = nearest(arcs);
    if (std::abs(n.path) < 0.02 * r || std::abs(n.post - r) < 0.02 * r) continue;
    EXPECT_EQ(blocked, n.path < 0.0 || n.post < r)
        << "trial " << trial << ": R = " << lead.radius << " m, " << lead.angle * 180 / kPi
        << " deg, margin " << n.path * 1e3 << " mm (path), nearest " << n.post * 1e3
        << " mm (post), " << names;
    if (!blocked) {
      ++accepted;
      continue;
    }
    by_path += n.path < 0.0;
    by_post += n.post < r;
    end_near += n.end_near && n.path < 0.0;
    // the limits named clear (by the brute force too)
    const LeadInLimit most = lead_in_limit(path, upper, lead, guides, skip, roller);
    EXPECT_LT(most.radius, lead.radius) << trial;
    EXPECT_LT(most.angle, lead.angle) << trial;
    LeadIn smaller = lead, shorter = lead;
    smaller.radius = most.radius;
    shorter.angle = most.angle;
    for (const LeadIn& at : {smaller, shorter}) {
      if (!validate(at).empty()) continue;  // none clears
      const Nearest clear = nearest(lead_in_arcs(upper, at));
      EXPECT_GT(clear.path, -0.02 * r) << "trial " << trial;
      EXPECT_GT(clear.post, 0.98 * r) << "trial " << trial;
    }
  }
  std::printf(
      "lead-ins: %d accepted; refused: %d by the chain's path (%d of them from a rail's end within "
      "a roller radius of the path), %d by the post\n",
      accepted, by_path, end_near, by_post);
  EXPECT_GE(accepted, 50);
  EXPECT_GE(by_path, 30);
  EXPECT_GE(by_post, 8);
}

}  // namespace
}  // namespace catena::dynamics
