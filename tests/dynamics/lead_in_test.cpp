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
#include <optional>
#include <random>
#include <string>
#include <vector>

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

// ∂F/∂q and ∂F/∂v of the guides together (one of them in contact at (x, y)) against central
// differences with the steps dx and 1e-7 m/s
void expect_blocks_match_differences(const std::vector<Guide>& guides, double x, double y,
                                     double vx, double vy, double dx) {
  const Total c = total(guides, x, y, vx, vy);
  ASSERT_EQ(c.active, 1) << x << " " << y;
  const double dv = 1e-7;
  for (int col = 0; col < 2; ++col) {
    double qp[2] = {x, y}, qm[2] = {x, y};
    qp[col] += dx;
    qm[col] -= dx;
    const Total a = total(guides, qp[0], qp[1], vx, vy), b = total(guides, qm[0], qm[1], vx, vy);
    const double scale = 1e-4 * (std::abs(c.dq[col]) + std::abs(c.dq[2 + col])) + 1e-2;
    EXPECT_NEAR(c.dq[col], (a.fx - b.fx) / (2 * dx), scale) << "dq x" << col << " at " << x;
    EXPECT_NEAR(c.dq[2 + col], (a.fy - b.fy) / (2 * dx), scale) << "dq y" << col << " at " << x;
    double vp[2] = {vx, vy}, vm[2] = {vx, vy};
    vp[col] += dv;
    vm[col] -= dv;
    const Total e = total(guides, x, y, vp[0], vp[1]), g = total(guides, x, y, vm[0], vm[1]);
    const double vscale = 1e-5 * (std::abs(c.dv[col]) + std::abs(c.dv[2 + col])) + 1e-6;
    EXPECT_NEAR(c.dv[col], (e.fx - g.fx) / (2 * dv), vscale) << "dv x" << col << " at " << x;
    EXPECT_NEAR(c.dv[2 + col], (e.fy - g.fy) / (2 * dv), vscale) << "dv y" << col << " at " << x;
  }
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
        expect_blocks_match_differences(with, x, y, wx, wy, 1e-3 * std::abs(s));
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
  // none on an arc whose geometry is invalid (radius 0 here), none for a lead-in out of range
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

// Lead-ins on arc rails (docs/models/dynamics.md, "Lead-ins", "On an arc rail"): an arc rail of
// surface radius 0.2 m about (0.1, −0.05) from 0.4 to 2.1 rad, the rollers outside it (convex) or
// inside; its frame at an end: the end point P = C + ρ e, the free side's normal n (e outside, −e
// inside) and the direction past the end (the counter-clockwise tangent t at the end angle, −t at
// the start angle).
Guide arc_rail(bool inside) {
  return testing::arc_rail(inclined_rail(0.3), 0.1, -0.05, 0.2, 0.4, 2.1, inside);
}
struct ArcEnd {
  double px, py, nx, ny, ox, oy;  // the end point, the free side's normal, past the end
};
ArcEnd arc_end(const Guide& rail, bool at_end) {
  const double a = at_end ? rail.end_angle : rail.start_angle;
  const double ex = std::cos(a), ey = std::sin(a), side = rail.inside ? -1.0 : 1.0;
  const double past = at_end ? 1.0 : -1.0;
  return {rail.centre_x + rail.radius * ex,
          rail.centre_y + rail.radius * ey,
          side * ex,
          side * ey,
          -past * ey,
          past * ex};
}
// Either rail's end frame: an arc's as above, a straight rail's at (x0, y0) or (x1, y1) with the
// free side's normal its left (−u_y, u_x) and the direction past it ±u.
ArcEnd rail_end(const Guide& rail, bool at_end) {
  if (rail.kind == Guide::Kind::kArc) return arc_end(rail, at_end);
  const double len = std::hypot(rail.x1 - rail.x0, rail.y1 - rail.y0);
  const double ux = (rail.x1 - rail.x0) / len, uy = (rail.y1 - rail.y0) / len;
  const double past = at_end ? 1.0 : -1.0;
  return {at_end ? rail.x1 : rail.x0, at_end ? rail.y1 : rail.y0, -uy, ux, past * ux, past * uy};
}
double point_x(const Guide& a, double phi) { return a.centre_x + a.radius * std::cos(phi); }
double point_y(const Guide& a, double phi) { return a.centre_y + a.radius * std::sin(phi); }

// Each lead-in joins its end of the arc rail: one of its ends is the rail's end point, with the
// rail's normal on the free side, running on in the rail's direction past the end; every other
// point of it lies on the rail's far side of the rail's extended circle (inside it, |Q − C| < ρ,
// with the rollers outside; outside it with the rollers inside), at the distance from C the
// triangle C, C_L, Q gives (|Q − C|² = d² + R² ± 2 d R cos θ, d = |C_L − C| = ρ ∓ R, θ its angle
// along the lead-in from the joint), and round C beyond the rail's end (off the rail's sweep).
TEST(DynamicsLeadIn, ArcRailLeadInsJoinTheRailAndBendAwayFromItsCircle) {
  int checked = 0;
  for (const bool inside : {false, true}) {
    const Guide rail = arc_rail(inside);
    const double rho = rail.radius;
    const std::vector<double> radii =
        inside ? std::vector<double>{0.01, 0.05, 0.15, 1.0} : std::vector<double>{0.01, 0.05, 0.15};
    for (const double big : radii) {
      for (const double angle : {0.1, 0.5, kPi / 3, kPi / 2}) {
        const LeadIn lead{big, angle, true, true};
        ASSERT_TRUE(validate(lead, rail).empty()) << inside << " " << big << " " << angle;
        const std::vector<Guide> arcs = lead_in_arcs(rail, lead);
        ASSERT_EQ(arcs.size(), 2U);
        for (int k = 0; k < 2; ++k) {
          const bool at_end = k == 1;
          const Guide& a = arcs[static_cast<std::size_t>(k)];
          const ArcEnd e = arc_end(rail, at_end);
          EXPECT_EQ(a.kind, Guide::Kind::kArc);
          EXPECT_FALSE(a.inside);
          EXPECT_EQ(a.radius, big);
          EXPECT_NEAR(a.end_angle - a.start_angle, angle, 1e-14);
          // which of its ends is the joint: the one at the rail's end
          const double tol = 1e-15 * 4.0 * (1.0 + rho + big);
          const bool joint_first =
              std::hypot(point_x(a, a.start_angle) - e.px, point_y(a, a.start_angle) - e.py) < tol;
          const double joint = joint_first ? a.start_angle : a.end_angle;
          EXPECT_NEAR(point_x(a, joint), e.px, tol) << inside << at_end;
          EXPECT_NEAR(point_y(a, joint), e.py, tol) << inside << at_end;
          // the lead-in's free side's normal there (outward: its rollers ride outside) is the
          // rail's
          EXPECT_NEAR(std::cos(joint), e.nx, 1e-14) << inside << at_end;
          EXPECT_NEAR(std::sin(joint), e.ny, 1e-14) << inside << at_end;
          // its direction from the joint into the lead-in: the rail's past its end
          const double into = joint_first ? 1.0 : -1.0;
          EXPECT_NEAR(-into * std::sin(joint), e.ox, 1e-14) << inside << at_end;
          EXPECT_NEAR(into * std::cos(joint), e.oy, 1e-14) << inside << at_end;
          // every other point on the rail's far side of its circle, and off the rail's sweep
          const double d = inside ? rho + big : rho - big;
          for (int j = 1; j <= 16; ++j) {
            const double theta = angle * j / 16.0;
            const double phi = joint + into * theta;
            const double qx = point_x(a, phi) - rail.centre_x, qy = point_y(a, phi) - rail.centre_y;
            const double dist = std::hypot(qx, qy);
            const double expected =
                std::sqrt(d * d + big * big + (inside ? -2.0 : 2.0) * d * big * std::cos(theta));
            EXPECT_NEAR(dist, expected, 1e-14 * (rho + big));
            if (inside)
              EXPECT_GT(dist, rho) << big << " " << angle << " " << theta;
            else
              EXPECT_LT(dist, rho) << big << " " << angle << " " << theta;
            double off = std::atan2(qy, qx) - rail.start_angle;
            off -= 2.0 * kPi * std::floor(off / (2.0 * kPi));
            EXPECT_GT(off, rail.end_angle - rail.start_angle) << big << " " << angle;
            ++checked;
          }
        }
      }
    }
  }
  EXPECT_EQ(checked, (3 + 4) * 4 * 2 * 16);
}

// At each end of the arc rail, outside and inside, a roller 2 µm or 50 µm into the surface at ±δ
// from the joint (along the direction past the end): the rail's contact on one side, the
// lead-in's alone on the other. The gap (penetration) and its gradient (central differences of the
// penetration over δ/10) of the lead-in equal the rail's to the order δ/R of the curvatures'
// difference, both −n; the force is continuous (its change of order (f + k_c δ) δ/R), while the
// bare arc's square end drops it; and the Newton blocks of rail and lead-ins together match central
// differences approaching the joint from both sides.
TEST(DynamicsLeadIn, ArcRailLeadInsCarryTheRailsGapAndForceAcrossTheJoint) {
  int checked = 0;
  for (const bool inside : {false, true}) {
    const Guide rail = arc_rail(inside);
    const double big = 0.05;
    const std::vector<Guide> arcs = lead_in_arcs(rail, {big, kPi / 4, true, true});
    ASSERT_EQ(arcs.size(), 2U);
    std::vector<Guide> with{rail};
    with.insert(with.end(), arcs.begin(), arcs.end());
    const double k = rail.contact_stiffness, r = rail.roller_radius;
    const double curve = 1.0 / big + 1.0 / rail.radius;  // the two curvatures' difference at most
    for (int end = 0; end < 2; ++end) {
      const ArcEnd e = arc_end(rail, end == 1);
      const Guide& lead = arcs[static_cast<std::size_t>(end)];
      for (const double depth : {2e-6, 5e-5}) {
        const auto point = [&](double s, double& x, double& y) {  // s past the end
          x = e.px + (r - depth) * e.nx + s * e.ox;
          y = e.py + (r - depth) * e.ny + s * e.oy;
        };
        const double vx = 0.3 * e.ox + 1e-4 * e.nx, vy = 0.3 * e.oy + 1e-4 * e.ny;
        for (const double delta : {1e-5, 1e-7}) {
          double xa = 0, ya = 0, xb = 0, yb = 0;
          point(-delta, xa, ya);
          point(delta, xb, yb);
          const GuideContact on_rail = guide_contact(rail, xa, ya, vx, vy);
          const GuideContact on_lead = guide_contact(lead, xb, yb, vx, vy);
          ASSERT_TRUE(on_rail.active);
          ASSERT_TRUE(on_lead.active);
          EXPECT_FALSE(guide_contact(lead, xa, ya, vx, vy).active);  // the joint parts them
          EXPECT_FALSE(guide_contact(rail, xb, yb, vx, vy).active);
          // the gap: depth on both sides, to δ²/2 × the curvatures
          EXPECT_NEAR(on_rail.penetration, depth, delta * delta * curve);
          EXPECT_NEAR(on_lead.penetration, on_rail.penetration, delta * delta * curve);
          // its gradient by central differences: −n on both sides, to δ × the curvatures
          const double h = 0.1 * delta;
          auto gradient = [&](const Guide& g, double x, double y, double& gx, double& gy) {
            gx = (guide_contact(g, x + h, y, vx, vy).penetration -
                  guide_contact(g, x - h, y, vx, vy).penetration) /
                 (2 * h);
            gy = (guide_contact(g, x, y + h, vx, vy).penetration -
                  guide_contact(g, x, y - h, vx, vy).penetration) /
                 (2 * h);
          };
          double rgx = 0, rgy = 0, lgx = 0, lgy = 0;
          gradient(rail, xa, ya, rgx, rgy);
          gradient(lead, xb, yb, lgx, lgy);
          const double slope = 2.0 * delta * curve + 1e-6 * (1.0 + 1e-7 / delta);
          EXPECT_NEAR(rgx, -e.nx, slope);
          EXPECT_NEAR(rgy, -e.ny, slope);
          EXPECT_NEAR(lgx, rgx, 2.0 * slope) << inside << end << depth << delta;
          EXPECT_NEAR(lgy, rgy, 2.0 * slope) << inside << end << depth << delta;
          // the force: continuous across the joint; the bare rail's end drops it
          const Total in = total(with, xa, ya, vx, vy), past = total(with, xb, yb, vx, vy);
          ASSERT_EQ(in.active, 1);
          ASSERT_EQ(past.active, 1);
          const double f = std::hypot(in.fx, in.fy);
          EXPECT_GT(f, 0.5 * k * depth);
          EXPECT_LT(std::hypot(past.fx - in.fx, past.fy - in.fy),
                    4.0 * (f + k * delta) * delta * curve)
              << inside << " end " << end << " depth " << depth << " delta " << delta;
          EXPECT_EQ(total({rail}, xb, yb, vx, vy).active, 0);
        }
        for (const double s : {-1e-4, -1e-5, -1e-6, 1e-6, 1e-5, 1e-4}) {
          double x = 0, y = 0;
          point(s, x, y);
          expect_blocks_match_differences(with, x, y, vx, vy, 1e-3 * std::abs(s));
          ++checked;
        }
      }
    }
  }
  EXPECT_EQ(checked, 2 * 2 * 2 * 6);
}

// lead_in_cover against a brute force: roller centres sampled over each lead-in's contact band (its
// sweep within its ends, R − r to R + r from its centre), those guide_contact finds active measured
// round the rail's centre from its end: their farthest is the cover, to the sampling (from below).
// A lead-in that validates shares no contact point with the rail or the other lead-in; on an arc
// whose open part is narrower than the two covers (an inside ring from −170° to 170°) the lead-in
// is refused on lead_in_angle, and the brute force finds points in two contacts at once there.
// Outside an arc the lead-in's radius must be below the arc's: R = ρ is refused on lead_in_radius.
TEST(DynamicsLeadIn, ArcRailLeadInsCoverNoContactOfTheRail) {
  struct Sampled {
    double farthest = 0.0;  // [rad] round C from the end
    int shared = 0;         // points in more than one contact
  };
  const auto sample = [](const Guide& rail, const LeadIn& lead, const std::vector<Guide>& arcs) {
    Sampled out;
    std::vector<Guide> all{rail};
    all.insert(all.end(), arcs.begin(), arcs.end());
    const double r = rail.roller_radius;
    for (std::size_t k = 0; k < arcs.size(); ++k) {
      const Guide& a = arcs[k];
      const bool at_end = k == 1 || !lead.at_start;
      const double end = at_end ? rail.end_angle : rail.start_angle;
      // (off its ends: the joint's line bounds both the rail's contact and the lead-in's, where
      // the rounding of either angle may count a point in both)
      for (int i = 1; i < 400; ++i)
        for (int j = 0; j <= 200; ++j) {
          const double phi = a.start_angle + (a.end_angle - a.start_angle) * i / 400.0;
          const double dist = a.radius - r + 2.0 * r * j / 200.0;
          const double x = a.centre_x + dist * std::cos(phi), y = a.centre_y + dist * std::sin(phi);
          int on = 0;
          for (const Guide& g : all) on += guide_contact(g, x, y, 0.0, 0.0).active ? 1 : 0;
          out.shared += on > 1 ? 1 : 0;
          if (!guide_contact(a, x, y, 0.0, 0.0).active) continue;
          double turn = std::atan2(y - rail.centre_y, x - rail.centre_x) - end;
          turn -= 2.0 * kPi * std::floor(turn / (2.0 * kPi) + 0.5);
          out.farthest = std::max(out.farthest, std::abs(turn));
        }
    }
    return out;
  };
  for (const bool inside : {false, true}) {
    const Guide rail = arc_rail(inside);
    for (const double big : {0.004, 0.05, 0.15}) {
      for (const double angle : {0.2, 1.0, kPi / 2}) {
        const LeadIn lead{big, angle, true, true};
        const double cover = lead_in_cover(rail, lead);
        const Sampled found = sample(rail, lead, lead_in_arcs(rail, lead));
        EXPECT_LE(found.farthest, cover + 1e-12) << inside << " " << big << " " << angle;
        EXPECT_GT(found.farthest, cover * (1.0 - 2e-2)) << inside << " " << big << " " << angle;
        EXPECT_EQ(found.shared, 0) << inside << " " << big << " " << angle;
      }
    }
  }
  // the ring round a wheel, open 20°: a 20 mm, 30° lead-in covers 17.5° round its centre at each
  // end (the tangent's angle from C)
  Guide ring = arc_rail(true);
  ring.radius = 0.0438;
  ring.start_angle = -170.0 * kPi / 180.0;
  ring.end_angle = 170.0 * kPi / 180.0;
  const LeadIn both{0.02, kPi / 6, true, true}, one{0.02, kPi / 6, false, true};
  EXPECT_NEAR(lead_in_cover(ring, both) * 180.0 / kPi, 17.5, 0.05);
  const std::vector<Issue> refused = validate(both, ring);
  ASSERT_EQ(refused.size(), 1U);
  EXPECT_EQ(refused[0].field, "lead_in_angle");
  EXPECT_NE(refused[0].expected.find("open part"), std::string::npos) << refused[0].expected;
  EXPECT_TRUE(lead_in_arcs(ring, both).empty());
  // the same lead-ins laid regardless: contact points shared by the two lead-ins
  Guide open = ring;
  open.end_angle = 100.0 * kPi / 180.0;  // (their geometry is the ends', not the sweep's)
  std::vector<Guide> forced = lead_in_arcs(open, {0.02, kPi / 6, true, false});
  Guide open_end = ring;
  open_end.start_angle = -100.0 * kPi / 180.0;
  for (const Guide& a : lead_in_arcs(open_end, one)) forced.push_back(a);
  ASSERT_EQ(forced.size(), 2U);
  EXPECT_GT(sample(ring, both, forced).shared, 0);
  EXPECT_TRUE(validate(one, ring).empty());  // one end: 17.5° fits
  // a closed ring has no end to lead in from
  Guide closed = ring;
  closed.end_angle = closed.start_angle + 2.0 * kPi;
  EXPECT_TRUE(lead_in_arcs(closed, one).empty());
  EXPECT_EQ(validate(one, closed).size(), 1U);
  // outside an arc: R < ρ
  const Guide convex = arc_rail(false);
  for (const double big : {0.2, 0.5}) {
    const std::vector<Issue> flat = validate(LeadIn{big, 0.5, true, true}, convex);
    ASSERT_EQ(flat.size(), 1U) << big;
    EXPECT_EQ(flat[0].field, "lead_in_radius");
    EXPECT_TRUE(lead_in_arcs(convex, {big, 0.5, true, true}).empty());
  }
  EXPECT_TRUE(validate(LeadIn{0.5, 0.5, true, true}, arc_rail(true)).empty());  // inside: any R
}

// The cover refusal names what fits (docs/models/dynamics.md, "On an arc rail"). The largest
// sweep at a radius, lead_in_angle_limit's closed forms, against lead_in_cover itself: the α found
// covers the β asked to rounding, and a sweep 1e-6 larger covers more; where it gives π/2 every
// sweep fits. The ring opened 20° (−170° to 170°, a 20 mm, 30° lead-in at both ends, 17.5° each):
// the message names the angle and the radius, each of which fits as printed and not one unit of
// its fourth digit beyond, and one end; at one end of a ring opened 10° it names no "one
// lead_in_end"; opened 0.05° nothing fits at all; a closed ring is refused on lead_in_radius.
TEST(DynamicsLeadIn, ArcRailCoverRefusalNamesWhatFits) {
  for (const bool inside : {false, true}) {
    const Guide rail = arc_rail(inside);
    for (const double big : {0.004, 0.05, 0.15}) {
      const double most = lead_in_cover(rail, {big, kPi / 2, true, true});
      for (const double share : {1e-3, 0.1, 0.5, 0.9, 0.999, 1.0, 1.5}) {
        const double beta = share * most;
        const double alpha = lead_in_angle_limit(rail, {big, 0.0, true, true}, beta);
        ASSERT_TRUE(alpha >= 0.0 && alpha <= kPi / 2) << inside << " " << big << " " << share;
        const double got = lead_in_cover(rail, {big, alpha, true, true});
        if (alpha < kPi / 2) {
          EXPECT_NEAR(got, beta, 1e-12 * most) << inside << " " << big << " " << share;
          EXPECT_GT(lead_in_cover(rail, {big, alpha * (1.0 + 1e-6), true, true}), beta)
              << inside << " " << big << " " << share;
        } else {
          EXPECT_LE(got, beta * (1.0 + 1e-12)) << inside << " " << big << " " << share;
        }
      }
    }
  }
  // outside, ρ = 0.2 m, R = 50 mm, r = 6 mm: 5° of cover at α = 18.50°
  Guide convex = arc_rail(false);
  convex.roller_radius = 0.006;
  EXPECT_NEAR(lead_in_angle_limit(convex, {0.05, 0.0, true, true}, 5.0 * kPi / 180.0) * 180.0 / kPi,
              18.50, 0.005);

  const auto after = [](const std::string& text, const std::string& key) {
    const std::size_t at = text.find(key);
    return at == std::string::npos ? NAN : std::stod(text.substr(at + key.size()));
  };
  Guide ring = arc_rail(true);
  ring.radius = 0.0438;
  ring.start_angle = -170.0 * kPi / 180.0;
  ring.end_angle = 170.0 * kPi / 180.0;
  const LeadIn both{0.02, kPi / 6, true, true};
  const std::vector<Issue> refused = validate(both, ring);
  ASSERT_EQ(refused.size(), 1U);
  const std::string& text = refused[0].expected;
  EXPECT_NE(text.find("at each of its 2 ends"), std::string::npos) << text;
  EXPECT_NE(text.find("or one lead_in_end"), std::string::npos) << text;
  const double angle = after(text, "lead_in_angle <= "), radius = after(text, "lead_in_radius <= ");
  EXPECT_NEAR(angle, 15.18, 1e-9) << text;  // the closed form: 10° of cover each
  ASSERT_TRUE(radius > 0.0 && radius < 0.02) << text;
  const double deg = kPi / 180.0;
  EXPECT_TRUE(validate(LeadIn{0.02, angle * deg, true, true}, ring).empty()) << angle;
  EXPECT_FALSE(validate(LeadIn{0.02, (angle + 0.01) * deg, true, true}, ring).empty()) << angle;
  EXPECT_TRUE(validate(LeadIn{radius, kPi / 6, true, true}, ring).empty()) << radius;
  const double unit = std::pow(10.0, std::floor(std::log10(radius)) - 3.0);
  EXPECT_FALSE(validate(LeadIn{radius + unit, kPi / 6, true, true}, ring).empty()) << radius;
  // one end, a ring opened 10°: less than one lead-in's 17.5°
  Guide narrow = ring;
  narrow.start_angle = -175.0 * deg;
  narrow.end_angle = 175.0 * deg;
  const std::vector<Issue> one = validate(LeadIn{0.02, kPi / 6, false, true}, narrow);
  ASSERT_EQ(one.size(), 1U);
  EXPECT_NE(one[0].expected.find("at its end,"), std::string::npos) << one[0].expected;
  EXPECT_EQ(one[0].expected.find("one lead_in_end"), std::string::npos) << one[0].expected;
  EXPECT_FALSE(std::isnan(after(one[0].expected, "lead_in_angle <= "))) << one[0].expected;
  // opened 0.05°: no sweep of 0.1° or more, and no radius (a roller alone covers 4.5°)
  Guide shut = ring;
  shut.start_angle = -179.975 * deg;
  shut.end_angle = 179.975 * deg;
  const std::vector<Issue> none = validate(LeadIn{0.02, kPi / 6, false, true}, shut);
  ASSERT_EQ(none.size(), 1U);
  EXPECT_NE(none[0].expected.find("no lead-in of 0.1 deg or more fits it at any radius"),
            std::string::npos)
      << none[0].expected;
  // closed: no end to lead in from, whatever the lead-in
  Guide closed = ring;
  closed.end_angle = closed.start_angle + 2.0 * kPi;
  const std::vector<Issue> ringed = validate(LeadIn{0.02, kPi / 6, false, true}, closed);
  ASSERT_EQ(ringed.size(), 1U);
  EXPECT_EQ(ringed[0].field, "lead_in_radius");
  EXPECT_NE(ringed[0].expected.find("no lead-in on a closed ring"), std::string::npos)
      << ringed[0].expected;
}

// A roller pressed 0.3 mm into the arc rail's surface (its centre on the circle ρ ± r ∓ 0.3 mm
// about C) passing from 0.3 rad beyond an end onto the rail at 0.5 m/s, sampled every 50 µm of
// its path: with the bare arc the force jumps at the square end from nothing to k_c × 0.3 mm at
// once; with a 50 mm, 30° lead-in its largest step between samples is a few per cent of that jump.
TEST(DynamicsLeadIn, ARollerArrivingBelowAnArcRailsEndIsCaughtGradually) {
  for (const bool inside : {false, true}) {
    const Guide rail = arc_rail(inside);
    std::vector<Guide> with{rail};
    for (const Guide& a : lead_in_arcs(rail, {0.05, kPi / 6, true, true})) with.push_back(a);
    ASSERT_EQ(with.size(), 3U);
    const double depth = 3e-4, r = rail.roller_radius;
    const double line = inside ? rail.radius - r + depth : rail.radius + r - depth;
    for (const bool at_end : {false, true}) {
      const double end = at_end ? rail.end_angle : rail.start_angle;
      const double toward = at_end ? -1.0 : 1.0;  // from past the end onto the rail
      const int samples = static_cast<int>(0.4 * line / 5e-5);
      const auto largest_step = [&](const std::vector<Guide>& guides) {
        double last = 0.0, most = 0.0, peak = 0.0;
        for (int j = 0; j <= samples; ++j) {
          const double phi = end - toward * 0.3 + toward * 0.4 * j / samples;
          const double x = rail.centre_x + line * std::cos(phi);
          const double y = rail.centre_y + line * std::sin(phi);
          const double vx = -toward * 0.5 * std::sin(phi), vy = toward * 0.5 * std::cos(phi);
          const Total t = total(guides, x, y, vx, vy);
          const double f = std::hypot(t.fx, t.fy);
          if (j > 0) most = std::max(most, std::abs(f - last));
          last = f;
          peak = std::max(peak, f);
        }
        EXPECT_GT(peak, 0.9 * rail.contact_stiffness * depth);
        return most;
      };
      const double bare = largest_step({rail}), led = largest_step(with);
      EXPECT_GT(bare, 0.9 * rail.contact_stiffness * depth) << inside << at_end;
      EXPECT_LT(led, 0.05 * bare) << inside << at_end;
      std::printf(
          "arc rail, rollers %s, %s: the force's largest step over the pass %.4g N bare, "
          "%.4g N with the lead-in\n",
          inside ? "inside" : "outside", at_end ? "end" : "start", bare, led);
    }
  }
}

// A roller striking a rail's square end in a step (square_end_strike; docs/models/dynamics.md,
// "Guides against the starting path: the square ends", the run's diagnostic): on the inclined
// straight rail and the arc rail with the rollers outside and inside, at each end, a node moving
// from 0.3 mm past the end onto the rail along it (0.5 mm over the step), g below the roller line
// where it crosses the end's face: struck at g = 2 ε, 1 mm and 2r - 0.1 mm, named with that g
// (to 1e-12 m), its node and its end; an oblique move named with its g interpolated to where it
// crosses the face; not at g = ε/2 (within the contact's ramp), g = 2r + 0.1 mm (behind the
// contact), nor leaving the rail, nor stopping 0.1 mm short of the face. Of three nodes the deepest
// crossing is named; with lead-ins at both ends no end is square and nothing is struck.
TEST(DynamicsSquareEnd, ARollerCrossingABareEndDeeperThanTheRampIsNamed) {
  std::vector<Guide> rails{inclined_rail(0.0), arc_rail(false), arc_rail(true)};
  for (const Guide& rail : rails) {
    const double r = rail.roller_radius, eps = rail.contact_smoothing, h = 1e-3;
    const std::vector<Guide> guides{rail};
    const std::vector<std::size_t> given{0};
    const std::vector<SquareEnd> ends = square_ends(BeltPath{}, guides, given);
    ASSERT_EQ(ends.size(), 2U);
    for (const bool at_end : {false, true}) {
      // the end's point, its free side's normal and the direction past it (out of the rail)
      const ArcEnd e = rail_end(rail, at_end);
      const double px = e.px, py = e.py, nx = e.nx, ny = e.ny, ox = e.ox, oy = e.oy;
      // node i crosses the face g_i below the roller line, from `before` past it at `speed`
      // towards the rail
      const auto strike = [&](std::vector<double> g, double before = 3e-4, double speed = 0.5) {
        std::vector<double> x, y, vx, vy;
        for (const double gi : g) {
          x.push_back(px + (r - gi) * nx + before * ox);
          y.push_back(py + (r - gi) * ny + before * oy);
          vx.push_back(-speed * ox);
          vy.push_back(-speed * oy);
        }
        return square_end_strike(ends, guides, given, x, y, vx, vy, h);
      };
      for (const double g : {2.0 * eps, 1e-3, 2.0 * r - 1e-4}) {
        const std::optional<EndStrike> hit = strike({g});
        ASSERT_TRUE(hit.has_value()) << g << " " << at_end;
        EXPECT_EQ(hit->node, 0U);
        EXPECT_NEAR(hit->depth, g, 1e-12) << at_end;
        EXPECT_EQ(ends[hit->end].at_start, !at_end);
        EXPECT_EQ(ends[hit->end].rail, 0U);
      }
      EXPECT_FALSE(strike({0.5 * eps}).has_value()) << at_end;
      EXPECT_FALSE(strike({2.0 * r + 1e-4}).has_value()) << at_end;
      EXPECT_FALSE(strike({1e-3}, -2e-4, -0.5).has_value()) << "leaving " << at_end;
      EXPECT_FALSE(strike({1e-3}, 6e-4).has_value()) << "short " << at_end;
      // an oblique move, from 0.5 mm below the roller line 0.3 mm before the face to 1.5 mm below
      // it 0.2 mm past: g where it crosses, 0.5 + (1.5 - 0.5) 0.3/0.5 = 1.1 mm, not its start's
      {
        const double x0 = px + (r - 5e-4) * nx + 3e-4 * ox, y0 = py + (r - 5e-4) * ny + 3e-4 * oy;
        const double x1 = px + (r - 1.5e-3) * nx - 2e-4 * ox,
                     y1 = py + (r - 1.5e-3) * ny - 2e-4 * oy;
        const std::vector<double> x{x0}, y{y0}, vx{(x1 - x0) / h}, vy{(y1 - y0) / h};
        const std::optional<EndStrike> hit =
            square_end_strike(ends, guides, given, x, y, vx, vy, h);
        ASSERT_TRUE(hit.has_value()) << at_end;
        EXPECT_NEAR(hit->depth, 1.1e-3, 1e-12) << "oblique " << at_end;
      }
      // the deepest of three crossings
      const std::optional<EndStrike> deepest = strike({1e-3, 3e-3, 2e-3});
      ASSERT_TRUE(deepest.has_value());
      EXPECT_EQ(deepest->node, 1U);
      EXPECT_NEAR(deepest->depth, 3e-3, 1e-12);
    }
    // lead-ins at both ends: no square end, no strike
    std::vector<Guide> led{rail};
    for (const Guide& a : lead_in_arcs(rail, {0.05, kPi / 6, true, true})) led.push_back(a);
    EXPECT_TRUE(square_ends(BeltPath{}, led, given).empty());
  }
}

// A lead-in arc's own far end is square (square_ends of the rail and its lead-in; layout.hpp,
// lead_in_rail_depth): on the inclined straight rail and the arc rail with the rollers outside and
// inside, a lead-in of 2 mm at 30 deg at each end in turn. The far end is built here from the
// rail's end, its normal n and the direction o past it: the arc's centre R behind the end along
// −n, its far face the line from there along cos α n + sin α o. A roller running towards the rail
// parallel to the end's tangent, G below the rail's roller line, meets that face d = (R + r − G)/
// cos α from the centre, g = R + r − d into the arc's contact: named on the arc's far end (not the
// joined near end) with that g (1e-12 m), and lead_in_rail_depth gives G back. The exact clearance:
// at lead_in_clear_radius (at α) and at lead_in_clear_angle (at R) the face is met on the roller
// line (g = 0 to 1e-12 m); 0.1 mm or 0.01 rad less is struck, as much more is not.
TEST(DynamicsSquareEnd, ALeadInsOwnFarEndIsSquareAndItsExactClearanceHolds) {
  for (const Guide& rail : {inclined_rail(0.0), arc_rail(false), arc_rail(true)}) {
    const double r = rail.roller_radius, eps = rail.contact_smoothing, h = 1e-3;
    for (const bool at_end : {false, true}) {
      const ArcEnd e = rail_end(rail, at_end);
      const double px = e.px, py = e.py, nx = e.nx, ny = e.ny, ox = e.ox, oy = e.oy;
      // the lead-in (R, α) at this end; a roller G below the roller line, moving 0.5 mm towards
      // the rail from 0.3 mm before the far face: the strike on the far end, if any
      const auto strike = [&](double R, double a, double G) {
        std::vector<Guide> guides{rail};
        for (const Guide& arc : lead_in_arcs(rail, {R, a, !at_end, at_end})) guides.push_back(arc);
        EXPECT_EQ(guides.size(), 2U);
        const std::vector<std::size_t> all{0, 1};
        const std::vector<SquareEnd> ends = square_ends(BeltPath{}, guides, all);
        // the rail's other end and the arc's far end; below a lead-in smaller than the roller,
        // the rail's own end too (the test below)
        EXPECT_EQ(ends.size(), R < r ? 3U : 2U);
        const double s = (R + r - G) * std::tan(a);  // past the rail's end, the face's
        const std::vector<double> x{px + (r - G) * nx + (s + 3e-4) * ox},
            y{py + (r - G) * ny + (s + 3e-4) * oy}, vx{-0.5 * ox}, vy{-0.5 * oy};
        const std::optional<EndStrike> hit = square_end_strike(ends, guides, all, x, y, vx, vy, h);
        if (hit && G < R + r) {
          EXPECT_EQ(ends[hit->end].rail, 1U);  // the arc's
          // its far end: R (1 - cos α) behind the rail's surface, R sin α past the end
          const double fx = px - R * nx + R * (std::cos(a) * nx + std::sin(a) * ox);
          const double fy = py - R * ny + R * (std::cos(a) * ny + std::sin(a) * oy);
          EXPECT_NEAR(ends[hit->end].x, fx, 1e-12);
          EXPECT_NEAR(ends[hit->end].y, fy, 1e-12);
        }
        return hit;
      };
      const double R = 2e-3, a = kPi / 6.0;
      const double clear = (R + r) * (1.0 - std::cos(a));  // 0.808 mm
      for (const double G : {clear + 1e-4, clear + 1e-3, 2e-3}) {
        const std::optional<EndStrike> hit = strike(R, a, G);
        ASSERT_TRUE(hit.has_value()) << G << " " << at_end;
        EXPECT_NEAR(hit->depth, R + r - (R + r - G) / std::cos(a), 1e-12);
        EXPECT_NEAR(lead_in_rail_depth(R, a, r, hit->depth), G, 1e-12);
      }
      EXPECT_FALSE(strike(R, a, clear - 1e-4).has_value()) << at_end;
      // G = 2 mm: the radius at 30 deg, the angle at 2 mm
      const double G = 2e-3, least = lead_in_clear_radius(a, r, G);
      const double most = lead_in_clear_angle(R, r, G);
      for (const auto& [radius, angle] : {std::pair{least, a}, std::pair{R, most}})
        EXPECT_FALSE(strike(radius, angle, G).has_value()) << at_end;  // g = 0: within ε
      const std::optional<EndStrike> small = strike(least - 1e-4, a, G);
      ASSERT_TRUE(small.has_value()) << at_end;
      EXPECT_GT(small->depth, eps);
      EXPECT_FALSE(strike(least + 1e-4, a, G).has_value()) << at_end;
      const std::optional<EndStrike> narrow = strike(R, most - 0.01, G);
      ASSERT_TRUE(narrow.has_value()) << at_end;
      EXPECT_GT(narrow->depth, eps);
      EXPECT_FALSE(strike(R, most + 0.01, G).has_value()) << at_end;
      // a lead-in smaller than the roller, 0.3 mm: its far face passes the arc's centre R + r
      // below the roller line, past which it lies on the opposite radius, outside the sweep,
      // where the arc's contact (guide_contact) is off. A roller 0.1 mm short of that depth is
      // named on the far end within it; one R + r + 1 mm below the roller line passes under the
      // centre and is not named there (its face point g = R + r + 1 mm / cos α < 2r); this move
      // starts past the rail's own end, which is square there (the test below)
      const double tiny = 3e-4;
      const Guide arc = lead_in_arcs(rail, {tiny, a, !at_end, at_end}).at(0);
      const std::optional<EndStrike> short_of = strike(tiny, a, tiny + r - 1e-4);
      ASSERT_TRUE(short_of.has_value()) << at_end;
      EXPECT_LT(short_of->depth, tiny + r);
      const double deep = tiny + r + 1e-3, w = (tiny + r - deep) * std::tan(a);
      const double qx = px + (r - deep) * nx + w * ox, qy = py + (r - deep) * ny + w * oy;
      EXPECT_FALSE(guide_contact(arc, qx, qy, 0.0, 0.0).active) << at_end;
      EXPECT_FALSE(strike(tiny, a, deep).has_value()) << at_end;  // (starting past the rail's)
    }
  }
  EXPECT_TRUE(std::isnan(lead_in_clear_angle(1e-3, kRoller, 1e-3 + kRoller + 1e-6)));
}

// A rail's own end below a lead-in smaller than the roller (layout.hpp, SquareEnd::from): on the
// inclined straight rail and the arc rail with the rollers outside and inside, at each end, a
// lead-in of 0.3 mm at 30 and 90 deg. The geometry, probed here through the contacts themselves
// (guide_contact) on the end's face line, 1 µm either side of it: short of R + r below the roller
// line the arc's contact holds the face's outer side (no step), past it to 2r the arc's is off
// while the rail's is on (square). square_ends names that end (the rail's, square from R + r,
// under the arc) besides the arc's far end. A roller running parallel to the rail at G = R + r +
// 0.1 mm, 3 mm and 2r - 0.1 mm below the roller line is named on the rail's own end with g = G
// (1e-12 m); rising along the face short of R + r it is not. The remedy: with the lead-in radius
// lead_in_clear_radius names at its sweep (and G - r at 90 deg), laid by lead_in_arcs, a parallel
// roller at G is named on no end; 0.1 mm less is struck. A lead-in of 2r leaves the end unsquare.
TEST(DynamicsSquareEnd, ARailsOwnEndBelowALeadInSmallerThanTheRollerIsSquarePastItsCentre) {
  for (const Guide& rail : {inclined_rail(0.0), arc_rail(false), arc_rail(true)}) {
    const double r = rail.roller_radius, eps = rail.contact_smoothing, h = 1e-3;
    for (const bool at_end : {false, true}) {
      const ArcEnd e = rail_end(rail, at_end);
      const double px = e.px, py = e.py, nx = e.nx, ny = e.ny, ox = e.ox, oy = e.oy;
      for (const double deg : {30.0, 90.0}) {
        const double a = deg * kPi / 180.0;
        const auto laid = [&](double R) {
          std::vector<Guide> guides{rail};
          for (const Guide& arc : lead_in_arcs(rail, {R, a, !at_end, at_end}))
            guides.push_back(arc);
          EXPECT_EQ(guides.size(), 2U);
          return guides;
        };
        // a roller G below the roller line moving 0.5 mm over the step towards the rail from
        // 0.3 mm before the rail's own end
        const auto strike = [&](const std::vector<Guide>& guides, double G, double before = 3e-4) {
          const std::vector<std::size_t> all{0, 1};
          const std::vector<SquareEnd> ends = square_ends(BeltPath{}, guides, all);
          const std::vector<double> x{px + (r - G) * nx + before * ox},
              y{py + (r - G) * ny + before * oy}, vx{-0.5 * ox}, vy{-0.5 * oy};
          const std::optional<EndStrike> hit =
              square_end_strike(ends, guides, all, x, y, vx, vy, h);
          return std::pair{ends, hit};
        };
        const double R = 3e-4;
        const std::vector<Guide> guides = laid(R);
        // the face line probed through the contacts
        for (const double g : {0.5 * (R + r), R + r - 1e-5, R + r + 1e-5, 1.5 * r, 2 * r - 1e-5}) {
          const double fx = px + (r - g) * nx, fy = py + (r - g) * ny;
          const bool out = guide_contact(guides[1], fx + 1e-6 * ox, fy + 1e-6 * oy, 0, 0).active;
          const bool in = guide_contact(rail, fx - 1e-6 * ox, fy - 1e-6 * oy, 0, 0).active;
          EXPECT_TRUE(in) << g;
          EXPECT_EQ(out, g < R + r) << at_end << " " << deg << " " << g;
        }
        const auto [ends, none] = strike(guides, 0.0);
        ASSERT_EQ(ends.size(), 3U) << at_end << deg;
        std::size_t own = ends.size();
        for (std::size_t k = 0; k < ends.size(); ++k)
          if (ends[k].rail == 0U && ends[k].at_start == !at_end) own = k;
        ASSERT_LT(own, ends.size());
        EXPECT_NEAR(ends[own].from, R + r, 1e-15);
        EXPECT_EQ(ends[own].under, 1U);
        EXPECT_NEAR(ends[own].x, px, 1e-15);
        EXPECT_NEAR(ends[own].y, py, 1e-15);
        for (const double G : {R + r + 1e-4, 3e-3 + r, 2.0 * r - 1e-4}) {
          const auto [all_ends, hit] = strike(guides, G);
          ASSERT_TRUE(hit.has_value()) << G << " " << at_end << " " << deg;
          EXPECT_EQ(hit->end, own) << G;
          EXPECT_NEAR(hit->depth, G, 1e-12) << G;
        }
        // rising along the rail's own face, short of the centre: not the rail's end
        {
          const std::vector<std::size_t> all{0, 1};
          const double g0 = R + r - 2e-4;
          const std::vector<double> x{px + (r - g0) * nx + 1e-4 * ox},
              y{py + (r - g0) * ny + 1e-4 * oy}, vx{-0.2 * ox + 0.1 * nx}, vy{-0.2 * oy + 0.1 * ny};
          const std::optional<EndStrike> hit =
              square_end_strike(ends, guides, all, x, y, vx, vy, h);
          EXPECT_TRUE(!hit || hit->end != own) << at_end << deg;
        }
        // the remedy, for G = 3 mm below the rail's surface
        const double G = 3e-3 + r;
        const double least = deg < 90.0 ? lead_in_clear_radius(a, r, G) : G - r;
        EXPECT_NEAR(lead_in_clear_radius(a, r, G), least, 1e-12);
        // from 0.3 mm before the rail's own end, and below 90 deg before the far face (where
        // G meets it, (R + r - G) tan α past the end)
        for (const double radius : {least + 1e-6, least - 1e-4}) {
          const std::vector<Guide> remedy = laid(radius);
          std::vector<double> starts{3e-4};
          if (deg < 90.0) starts.push_back((radius + r - G) * std::tan(a) + 3e-4);
          for (const double before : starts) {
            const auto [remedy_ends, hit] = strike(remedy, G, before);
            EXPECT_EQ(hit.has_value() && hit->depth > eps,
                      radius < least && (deg == 90.0 || before > 3e-4))
                << at_end << " " << deg << " " << radius << " " << before;
          }
        }
      }
      // a lead-in of 2r: the rail's own end is covered to 2r and not square
      const std::vector<std::size_t> all{0, 1};
      std::vector<Guide> wide{rail};
      for (const Guide& arc : lead_in_arcs(rail, {2.0 * r, kPi / 6, !at_end, at_end}))
        wide.push_back(arc);
      EXPECT_EQ(square_ends(BeltPath{}, wide, all).size(), 2U);
    }
  }
}

// When a parallel roller can strike a lead-in's far end (layout.hpp, lead_in_parallel_strike): on
// the inclined rail, a 2 mm lead-in at each end in turn at 30, 60, 89 and 90 deg, the far face
// built here as in the test above. A roller rising along the end's normal through the far face
// 1 mm into the arc's contact is struck at every sweep. A roller running parallel to the rail at
// the depth G that gives (lead_in_rail_depth) is struck there at the same g below a quarter turn,
// and lead_in_parallel_strike says so; at 90 deg the face runs parallel to the rail and it is not
// struck, the clearance's radius and sweep are the lead-in's own, and lead_in_parallel_strike is
// false (the run names no value then).
TEST(DynamicsSquareEnd, ALeadInsFarEndAtAQuarterTurnNamesNoParallelRemedy) {
  const Guide rail = inclined_rail(0.0);
  const double r = rail.roller_radius, R = 2e-3, h = 1e-3;
  const double len = std::hypot(rail.x1 - rail.x0, rail.y1 - rail.y0);
  const double ux = (rail.x1 - rail.x0) / len, uy = (rail.y1 - rail.y0) / len;
  for (const bool at_end : {false, true}) {
    const double px = at_end ? rail.x1 : rail.x0, py = at_end ? rail.y1 : rail.y0;
    const double nx = -uy, ny = ux, ox = at_end ? ux : -ux, oy = at_end ? uy : -uy;
    for (const double deg : {30.0, 60.0, 89.0, 90.0}) {
      const double a = deg * kPi / 180.0;
      std::vector<Guide> guides{rail};
      for (const Guide& arc : lead_in_arcs(rail, {R, a, !at_end, at_end})) guides.push_back(arc);
      ASSERT_EQ(guides.size(), 2U);
      const std::vector<std::size_t> all{0, 1};
      const std::vector<SquareEnd> ends = square_ends(BeltPath{}, guides, all);
      const auto strike = [&](double x, double y, double vx, double vy) {
        return square_end_strike(ends, guides, all, std::vector<double>{x}, std::vector<double>{y},
                                 std::vector<double>{vx}, std::vector<double>{vy}, h);
      };
      // rising along n, from 0.3 mm below the face's point g = 1 mm into the contact
      const double d = R + r - 1e-3;  // from the arc's centre, R behind the end along −n
      const double fx = px - R * nx + d * (std::cos(a) * nx + std::sin(a) * ox);
      const double fy = py - R * ny + d * (std::cos(a) * ny + std::sin(a) * oy);
      const std::optional<EndStrike> rising = strike(fx - 3e-4 * nx, fy - 3e-4 * ny, nx, ny);
      ASSERT_TRUE(rising.has_value()) << at_end << " " << deg;
      EXPECT_EQ(ends[rising->end].rail, 1U);
      EXPECT_NEAR(rising->depth, 1e-3, 1e-12);
      // parallel, towards the rail, G below the roller line, from 0.3 mm before the face
      const double G = lead_in_rail_depth(R, a, r, rising->depth);
      const double w = (R + r - G) * std::tan(a) + 3e-4;
      const std::optional<EndStrike> parallel =
          strike(px + (r - G) * nx + w * ox, py + (r - G) * ny + w * oy, -0.5 * ox, -0.5 * oy);
      // (at 90 deg G = R + r, the depth from which the rail's own end is square: not the far end)
      EXPECT_EQ(parallel.has_value() && ends[parallel->end].rail == 1U, deg < 90.0)
          << at_end << " " << deg;
      if (parallel && deg < 90.0) {
        EXPECT_NEAR(parallel->depth, rising->depth, 1e-9) << deg;
      }
      EXPECT_EQ(lead_in_parallel_strike(R, a, r, rising->depth), deg < 90.0) << at_end << deg;
      if (deg == 90.0) {
        EXPECT_NEAR(lead_in_clear_radius(a, r, G), R, 1e-12);
        EXPECT_NEAR(lead_in_clear_angle(R, r, std::min(G, R + r)), a, 1e-6);
      }
    }
  }
}

// The strike's bound at the contact's far edge, decided by rule (layout.hpp, square_end_strike):
// the contact is off at g >= 2r (guide_contact), so a roller crossing a square end exactly 2r below
// the roller line carries no force and is not struck; the largest double below 2r is. A level rail
// on y = 0 with its free side up: the roller line y = r, the node's level move at y = −r, g = 2r to
// the last bit.
TEST(DynamicsSquareEnd, ACrossingExactlyTwoRollerRadiiDeepIsNoStrike) {
  Guide rail = inclined_rail(0.0);
  rail.x0 = 0.0, rail.y0 = 0.0, rail.x1 = 0.25, rail.y1 = 0.0;
  const double r = rail.roller_radius;
  const std::vector<Guide> guides{rail};
  const std::vector<std::size_t> given{0};
  const std::vector<SquareEnd> ends = square_ends(BeltPath{}, guides, given);
  ASSERT_EQ(ends.size(), 2U);
  const auto strike = [&](double y) {
    // from 0.3 mm before (x0, y0) onto the rail, 0.5 mm over the step
    const std::vector<double> x{-3e-4}, ys{y}, vx{0.5}, vy{0.0};
    return square_end_strike(ends, guides, given, x, ys, vx, vy, 1e-3);
  };
  ASSERT_EQ(r - (-r), 2.0 * r);  // the gap's arithmetic is exact here
  EXPECT_FALSE(guide_contact(rail, 0.01, -r, 0.0, 0.0).active);  // the contact's own cut-off
  EXPECT_FALSE(strike(-r).has_value());
  const double under = std::nextafter(2.0 * r, 0.0);
  ASSERT_EQ(r - (r - under), under);
  EXPECT_TRUE(guide_contact(rail, 0.01, r - under, 0.0, 0.0).active);
  const std::optional<EndStrike> below = strike(r - under);
  ASSERT_TRUE(below.has_value());
  EXPECT_EQ(below->depth, under);
  EXPECT_TRUE(ends[below->end].at_start);
}

}  // namespace
// A rail against the chain's starting path (rail_cut; docs/models/dynamics.md, "Guides against the
// starting path") against a brute force on the lead-in tests' loop (two z = 12 wheels ten pitches
// apart): 400 random rails — straight, 10-150 mm long in any direction, or arcs of 10-120 mm,
// outside or inside, sweeping 10-350° — about the loop. The brute force walks the path every
// 0.02 mm through guide_contact: a rail is cut where a point in its contact lies past its surface,
// g > r. rail_cut (an eighth of a roller radius between its samples) must refuse every rail cut
// over at least 1.5 mm of the path and accept every rail with no point past the surface (those cut
// over less, a crossing at a rail's very end, are left out and counted). The clear part it names
// is cut over less than 1.5 mm of the path and no shorter than the brute force's longest stretch
// of the rail over no cut less two samples' reach; the rail moved by the shift it names is cut
// over less than 1.5 mm and no point past the surface by more than 5 µm (the sagitta between
// samples on the wraps is 2 µm), and the shift is the least: at least the brute force's own least
// (the same intervals on its points) less 5 µm, at most one rail_cut sample's spacing more. The
// move to touching leaves no point of the brute force's deeper than 5 µm in the contact.
TEST(DynamicsRailCut, MatchesABruteForceOnRandomRails) {
  const double p = 0.01905, r = kRoller, step = 2e-5;
  const double radius = 0.5 * p / std::sin(kPi / 12);
  const BeltPath path = belt_path({{0.0, 0.0, radius}, {10 * p, 0.0, radius}}, 0);
  ASSERT_FALSE(path.pieces.empty());
  std::vector<PathPoint> points;
  for (double s = 0.0; s < path.length; s += step) points.push_back(path_point(path, s));
  struct Brute {
    double deepest = 0.0;  // the largest g in the contact
    int past = 0;          // points past the surface
    double shift = 0.0;    // [m] the least move leaving no point past the surface
    double clear = 0.0;    // the longest stretch of the rail over no such point
  };
  // the least s ≥ 0 in none of the open intervals (lo, hi)
  auto least = [](std::vector<std::pair<double, double>> v) {
    std::sort(v.begin(), v.end());
    double s = 0.0;
    for (const auto& [lo, hi] : v)
      if (lo < s) s = std::max(s, hi);
    return s;
  };
  auto brute = [&](const Guide& g) {
    Brute b;
    const GuideFrame frame = guide_frame(g);
    std::vector<std::pair<double, double>> moves;
    std::vector<double> along;
    for (const PathPoint& q : points) {
      // a move s lowers the gap by s: past the surface for s in (g − 2r, g − r)
      const GuideSpot at = guide_spot(g, frame, q.x, q.y);
      if (at.between && at.gap > r) moves.emplace_back(at.gap - 2 * r, at.gap - r);
      const GuideContact c = guide_contact(g, q.x, q.y, 0.0, 0.0);
      if (!c.active) continue;
      b.deepest = std::max(b.deepest, c.penetration);
      if (c.penetration > r) {
        ++b.past;
        along.push_back(at.along);
      }
    }
    b.shift = least(moves);
    std::sort(along.begin(), along.end());
    const double length =
        g.kind == Guide::Kind::kStraight ? frame.length : g.end_angle - g.start_angle;
    for (std::size_t k = 0; k <= along.size(); ++k)
      b.clear = std::max(b.clear,
                         (k == along.size() ? length : along[k]) - (k == 0 ? 0.0 : along[k - 1]));
    return b;
  };
  // the rail with its surface moved `shift` away from the rollers (the sense rail_cut's moves take)
  auto surface_moved = [](const Guide& g, double shift) {
    Guide moved = g;
    if (g.kind == Guide::Kind::kStraight) {
      const double len = std::hypot(g.x1 - g.x0, g.y1 - g.y0);
      const double nx = -(g.y1 - g.y0) / len, ny = (g.x1 - g.x0) / len;
      moved.x0 -= shift * nx;
      moved.y0 -= shift * ny;
      moved.x1 -= shift * nx;
      moved.y1 -= shift * ny;
    } else {
      moved.radius += g.inside ? shift : -shift;
    }
    return moved;
  };
  // one rail_cut sample's spacing, and its reach along the rail
  const double spacing = path.length / std::max(512.0, std::ceil(path.length / (0.125 * r)));
  std::mt19937_64 rng(2111);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  int refused = 0, accepted = 0, left_out = 0, parts = 0, shifts = 0, touchings = 0;
  double most_in_part = 0.0, most_moved = 0.0, deepest_moved = 0.0, most_touching = 0.0;  // [m]
  for (int trial = 0; trial < 400; ++trial) {
    Guide g = inclined_rail(0.0);
    const double x = -0.05 + 0.29 * u01(rng), y = -0.05 + 0.1 * u01(rng);
    if (trial % 2 == 0) {
      const double length = 0.01 + 0.14 * u01(rng), direction = 2 * kPi * u01(rng);
      g.x0 = x;
      g.y0 = y;
      g.x1 = x + length * std::cos(direction);
      g.y1 = y + length * std::sin(direction);
    } else {
      const double start = 2 * kPi * u01(rng) - kPi;
      g = testing::arc_rail(g, x, y, 0.01 + 0.11 * u01(rng), start,
                            start + (10.0 + 340.0 * u01(rng)) * kPi / 180.0, u01(rng) < 0.5);
    }
    const Brute b = brute(g);
    const RailCut cut = rail_cut(path, g);
    if (b.past * step >= 1.5e-3) {
      ++refused;
      EXPECT_FALSE(cut.piece.empty()) << trial << " cut over " << b.past * step << " m";
      EXPECT_GT(cut.depth, r) << trial;
      EXPECT_LE(cut.depth, b.deepest + step) << trial;
    } else if (b.past == 0) {
      ++accepted;
      EXPECT_TRUE(cut.piece.empty()) << trial << " " << cut.piece << " " << cut.depth;
    } else {
      ++left_out;
    }
    if (cut.piece.empty()) continue;
    if (std::isfinite(cut.clear_from)) {
      ++parts;
      Guide part = g;
      if (g.kind == Guide::Kind::kStraight) {
        const double len = std::hypot(g.x1 - g.x0, g.y1 - g.y0);
        const double ux = (g.x1 - g.x0) / len, uy = (g.y1 - g.y0) / len;
        part.x0 = g.x0 + cut.clear_from * ux;
        part.y0 = g.y0 + cut.clear_from * uy;
        part.x1 = g.x0 + cut.clear_to * ux;
        part.y1 = g.y0 + cut.clear_to * uy;
      } else {
        part.start_angle = g.start_angle + cut.clear_from;
        part.end_angle = g.start_angle + cut.clear_to;
      }
      const Brute in_part = brute(part);
      EXPECT_LT(in_part.past * step, 1.5e-3) << trial;
      most_in_part = std::max(most_in_part, in_part.past * step);
      EXPECT_TRUE(rail_cut(path, part).piece.empty()) << trial;
      // the longest: no shorter than the brute force's less two samples' reach each side
      const double reach = g.kind == Guide::Kind::kStraight ? spacing : spacing / (g.radius - r);
      EXPECT_GE(cut.clear_to - cut.clear_from, b.clear - 4 * reach) << trial;
    }
    if (std::isfinite(cut.shift)) {
      ++shifts;
      EXPECT_GT(cut.shift, 0.0) << trial;
      EXPECT_LE(cut.shift, 2 * r) << trial;
      const Guide moved = surface_moved(g, cut.shift);
      const Brute m = brute(moved);
      EXPECT_LT(m.past * step, 1.5e-3) << trial;
      most_moved = std::max(most_moved, m.past * step);
      deepest_moved = std::max(deepest_moved, m.deepest);
      EXPECT_LT(m.deepest, r + 5e-6) << trial;
      EXPECT_TRUE(rail_cut(path, moved).piece.empty()) << trial;
      // the least: not below the brute force's own least, at most a sample's spacing above it
      EXPECT_GE(cut.shift, b.shift - 5e-6) << trial;
      EXPECT_LE(cut.shift, b.shift + spacing) << trial;
    }
    if (std::isfinite(cut.touching)) {
      ++touchings;
      const Guide moved = surface_moved(g, cut.touching);
      const Brute m = brute(moved);
      EXPECT_LT(m.deepest, 5e-6) << trial;
      most_touching = std::max(most_touching, m.deepest);
    }
  }
  std::printf(
      "rail_cut: %d refused, %d accepted, %d left out; %d clear parts (cut over at most %.3g mm), "
      "%d moves (cut over at most %.3g mm, at most %.4g mm in); %d moves to touching (at most "
      "%.3g mm in)\n",
      refused, accepted, left_out, parts, most_in_part * 1e3, shifts, most_moved * 1e3,
      deepest_moved * 1e3, touchings, most_touching * 1e3);
  EXPECT_GT(refused, 40);
  EXPECT_GT(accepted, 40);
  EXPECT_LT(left_out, 40);
}

}  // namespace catena::dynamics
