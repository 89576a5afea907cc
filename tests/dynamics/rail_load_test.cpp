// A conveyed load on a straight rail (Guide::load_per_metre; docs/models/dynamics.md, "A conveyed
// load"): the ramped weight share sums to the rail's whole load q_L L g over nodes a pitch apart
// wherever they sit, and is 0 beyond the ramp and away from the rail; its Newton block is the
// finite difference of the force; bad values are named; a lead-in carries none; and the work the
// steps report for a chain sliding onto a loaded rail is the load's along its travel. With the
// load's inertia (Guide::load_inertia): the Newton matrix against the residual's differences, a
// loaded chain's start-up and a loaded link's ringing against their spring–mass closed forms,
// and the work balance with the catch and the discharge; with the material arriving at a speed
// of its own (Guide::load_speed) the Newton matrix again, the work balance with the arriving
// material's kinetic energy, and a bad speed named; where loaded pieces with different speeds
// overlap, the Newton matrix, the momentum and energy each piece's material brings, and the
// two pieces' step force against its closed form.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "catena/dynamics/integrator.hpp"
#include "random_guides.hpp"
#include "residual_difference.hpp"

namespace catena::dynamics {
namespace {

constexpr double kPitch = 0.01905;        // [m] 12B
constexpr double kGx = 0.7, kGy = -9.78;  // [m/s²] a gravity not across the rail

Guide loaded_rail(double load) {
  Guide g = testing::inclined_rail(0.2);
  g.load_per_metre = load;
  return g;
}

// Loaded arcs with their carrying sides up (gravity about −y): over an outside arc's top (a convex
// transition) and along an inside arc's bottom (a concave one).
Guide loaded_arc(double load, bool inside) {
  Guide g = loaded_rail(load);
  g.kind = Guide::Kind::kArc;
  g.inside = inside;
  g.centre_x = 0.1;
  g.centre_y = inside ? 0.5 : -0.2;
  g.radius = inside ? 0.4 : 0.3;
  g.start_angle = (inside ? 240.0 : 60.0) * std::numbers::pi / 180.0;
  g.end_angle = (inside ? 300.0 : 120.0) * std::numbers::pi / 180.0;
  return g;
}

// The roller centres' line's radius of an arc.
double line_radius(const Guide& g) {
  return g.inside ? g.radius - g.roller_radius : g.radius + g.roller_radius;
}

// The rail's length along the roller centres' line.
double rail_length(const Guide& g) {
  if (g.kind == Guide::Kind::kStraight) return guide_frame(g).length;
  return line_radius(g) * (g.end_angle - g.start_angle);
}

// The point `along` the rail from its first end and `across` it from the roller centres' line
// (along the free side's normal); on an arc `along` is the arc length on that line.
void at(const Guide& g, double along, double across, double& x, double& y) {
  if (g.kind == Guide::Kind::kArc) {
    const double rho = line_radius(g), phi = g.start_angle + along / rho;
    const double d = g.inside ? rho - across : rho + across;
    x = g.centre_x + d * std::cos(phi);
    y = g.centre_y + d * std::sin(phi);
    return;
  }
  const GuideFrame f = guide_frame(g);
  const double off = g.roller_radius + across;  // along the free side's normal (−u_y, u_x)
  x = g.x0 + along * f.ux - off * f.uy;
  y = g.y0 + along * f.uy + off * f.ux;
}

// A straight rail and both arcs, loaded with `load`.
std::vector<Guide> loaded_rails(double load) {
  return {loaded_rail(load), loaded_arc(load, false), loaded_arc(load, true)};
}

// On a straight rail and on either arc: an arc's nodes a pitch apart along its roller centres'
// line carry q_L L_arc g, L_arc that line's length.
TEST(RailLoad, NodesAPitchApartCarryTheWholeLoadWhereverTheySit) {
  const double q = 7.5;
  for (const Guide& rail : loaded_rails(q)) {
    const GuideFrame f = guide_frame(rail);
    const double len = rail_length(rail);
    for (int k = 0; k < 97; ++k) {  // the nodes' offset along the rail, through a whole pitch
      const double offset = kPitch * k / 97.0;
      double fx = 0.0, fy = 0.0;
      for (double s = -3.0 * kPitch + offset; s < len + 3.0 * kPitch; s += kPitch) {
        double x = 0.0, y = 0.0;
        at(rail, s, 0.0, x, y);
        const RailLoad l = rail_load(rail, f, kPitch, kGx, kGy, x, y);
        fx += l.fx;
        fy += l.fy;
      }
      EXPECT_NEAR(fx, q * len * kGx, 1e-12 * q * len * 10.0) << offset << " inside " << rail.inside;
      EXPECT_NEAR(fy, q * len * kGy, 1e-12 * q * len * 10.0) << offset << " inside " << rail.inside;
    }
  }
  const Guide g = loaded_rail(q);
  const GuideFrame f = guide_frame(g);
  double x = 0.0, y = 0.0;
  at(g, 0.5 * f.length, 0.0, x, y);  // along the rail: one pitch's load
  const RailLoad mid = rail_load(g, f, kPitch, kGx, kGy, x, y);
  EXPECT_TRUE(mid.active);
  EXPECT_DOUBLE_EQ(mid.share, 1.0);
  EXPECT_DOUBLE_EQ(mid.fy, q * kPitch * kGy);
  const double r = g.roller_radius;
  // a roller lifted off by up to a pitch, or pressed in by up to its radius: still carrying
  for (const double d : {0.9 * kPitch, 0.999 * kPitch, -0.9 * r, -0.999 * r}) {
    at(g, 0.5 * f.length, d, x, y);
    EXPECT_TRUE(rail_load(g, f, kPitch, kGx, kGy, x, y).active) << d;
  }
  // beyond the ramp (half a pitch past either end), more than a pitch off the rail, behind it
  // (the centre past the surface: a strand under the rail, up to a pitch or the chain's other
  // run farther down), or no load: nothing
  for (const auto& [s, d] :
       std::vector<std::pair<double, double>>{{-0.5001 * kPitch, 0.0},
                                              {f.length + 0.5001 * kPitch, 0.0},
                                              {0.5 * f.length, 1.001 * kPitch},
                                              {0.5 * f.length, -1.01 * r},
                                              {0.5 * f.length, -0.9 * kPitch},
                                              {0.5 * f.length, -5 * kPitch}}) {
    at(g, s, d, x, y);
    const RailLoad l = rail_load(g, f, kPitch, kGx, kGy, x, y);
    EXPECT_FALSE(l.active) << s << " " << d;
    EXPECT_EQ(l.fx, 0.0);
    EXPECT_EQ(l.fy, 0.0);
  }
  at(g, 0.5 * f.length, 0.0, x, y);
  EXPECT_FALSE(rail_load(loaded_rail(0.0), f, kPitch, kGx, kGy, x, y).active);
  // on the ramp: linear, a quarter of the load a quarter pitch inside the first end's ramp
  at(g, -0.25 * kPitch, 0.0, x, y);
  EXPECT_NEAR(rail_load(g, f, kPitch, kGx, kGy, x, y).share, 0.25, 1e-12);
  at(g, f.length + 0.25 * kPitch, 0.0, x, y);
  EXPECT_NEAR(rail_load(g, f, kPitch, kGx, kGy, x, y).share, 0.25, 1e-12);
}

// On a straight rail and on either arc (there through the arc's parametrisation s = ρ_c φ(q),
// off the roller centres' line too).
TEST(RailLoad, NewtonBlockIsTheForcesDerivative) {
  for (const Guide& g : loaded_rails(12.0)) {
    const GuideFrame f = guide_frame(g);
    const double len = rail_length(g);
    // on each end's ramp and along the rail (where the block is 0)
    for (const double s :
         {-0.3 * kPitch, 0.2 * kPitch, 0.5 * len, len - 0.1 * kPitch, len + 0.35 * kPitch}) {
      double x = 0.0, y = 0.0;
      at(g, s, 0.2 * kPitch, x, y);
      const RailLoad l = rail_load(g, f, kPitch, kGx, kGy, x, y);
      ASSERT_TRUE(l.active) << s;
      const double e = 1e-7;
      for (int c = 0; c < 2; ++c) {
        const double dx = c == 0 ? e : 0.0, dy = c == 1 ? e : 0.0;
        const RailLoad p = rail_load(g, f, kPitch, kGx, kGy, x + dx, y + dy);
        const RailLoad m = rail_load(g, f, kPitch, kGx, kGy, x - dx, y - dy);
        EXPECT_NEAR(l.dq[c], (p.fx - m.fx) / (2 * e), 1e-6) << s << " column " << c;
        EXPECT_NEAR(l.dq[2 + c], (p.fy - m.fy) / (2 * e), 1e-6) << s << " column " << c;
      }
    }
    double x = 0.0, y = 0.0;
    at(g, 0.2 * kPitch, 0.0, x, y);
    EXPECT_GT(std::abs(rail_load(g, f, kPitch, kGx, kGy, x, y).dq[3]), 1.0);  // the ramp's slope
  }
}

// The step's Newton matrix with a loaded rail (−hθ ∂F/∂q on a node's diagonal block, the ramp's
// at the rail's ends): every column against central differences of the step's residual, for a
// two-node chain a half pitch above the rail (no contact) with a node on either end's ramp. The
// load's block is about a tenth of the matrix's scale there: a wrong sign or a missing term shows.
// On a straight rail and on either arc.
TEST(RailLoad, IntegratorNewtonMatrixHasTheRampsBlock) {
  for (const Guide& g : loaded_rails(1e3)) {
    Guide bare_rail = g;
    bare_rail.load_per_metre = 0.0;
    for (const double s0 : {0.2 * kPitch, rail_length(g) - 1.1 * kPitch}) {
      Model m = uniform_chain(2, false, kPitch, 0.024, 1e4, 0.0, false);
      m.gravity_x = kGx;
      m.gravity_y = kGy;
      State st(2, 0);
      for (std::size_t i = 0; i < 2; ++i)
        at(g, s0 + kPitch * static_cast<double>(i), 0.5 * kPitch, st.x[i], st.y[i]);
      std::vector<double> u{st.x[0], st.y[0], st.x[1], st.y[1]};
      const double h = 1e-3;
      std::vector<double> r0, jac, bare;
      m.guides = {bare_rail};
      Integrator plain(m, {.step = h, .theta = 0.6});
      plain.newton_system(m, st, u, r0, &bare);
      m.guides = {g};
      Integrator integ(m, {.step = h, .theta = 0.6});
      ASSERT_EQ(integ.unknowns(), 4u);
      integ.newton_system(m, st, u, r0, &jac);
      double scale = 0.0, load = 0.0;
      for (std::size_t k = 0; k < 16; ++k) {
        scale = std::max(scale, std::abs(jac[k]));
        load = std::max(load, std::abs(jac[k] - bare[k]));
      }
      EXPECT_GT(load, 0.05 * scale) << s0 << ": the load's block is not negligible";
      for (std::size_t c = 0; c < 4; ++c) {
        const std::vector<double> fd = testing::residual_difference(integ, m, st, u, c, 1e-8);
        for (std::size_t r = 0; r < 4; ++r)
          EXPECT_NEAR(jac[r * 4 + c], fd[r], 1e-6 * scale) << s0 << " row " << r << " column " << c;
      }
    }
  }
}

// An arc carries a load only if it presses the chain onto the rail over the whole arc (n·g < 0
// at every angle: the message names the worst) and its roller centres' line's radius is at least
// a pitch; an arc with both problems has both named.
TEST(RailLoad, BadLoadsNamedAndAnArcFacingDownRefused) {
  Model m = uniform_chain(4, false, kPitch, 0.024, 1e7, 0.0, false);
  m.gravity_x = kGx;
  m.gravity_y = kGy;
  Guide arc = loaded_rail(0.0);
  arc.kind = Guide::Kind::kArc;
  arc.radius = 0.2;
  arc.start_angle = 0.0;
  arc.end_angle = 1.0;
  arc.load_per_metre = 5.0;
  // the same rail from its second end to its first: its carrying side faces down, the load
  // would pull the chain off it
  Guide under = loaded_rail(5.0);
  std::swap(under.x0, under.x1);
  std::swap(under.y0, under.y1);
  // an inside arc over 60°–120°: its carrying side (inward) faces down, worst at 94.09°
  Guide hanging = loaded_arc(5.0, true);
  hanging.start_angle = 60.0 * std::numbers::pi / 180.0;
  hanging.end_angle = 120.0 * std::numbers::pi / 180.0;
  Guide tight = loaded_arc(5.0, false);
  tight.radius = 0.01;   // the rollers' line 16 mm round: less than a pitch
  Guide both = hanging;  // facing down and tight: both named
  both.radius = 0.02;    // the rollers' line (inside) 14 mm round, less than a pitch
  m.guides = {loaded_rail(-1.0),
              loaded_rail(NAN),
              loaded_rail(2e4),
              arc,
              loaded_rail(1e4),
              loaded_rail(0.0),
              under,
              loaded_arc(5.0, false),
              loaded_arc(5.0, true),
              hanging,
              tight,
              both};
  const std::vector<Issue> issues = validate(m);
  std::vector<std::string> fields;
  for (const Issue& i : issues) fields.push_back(i.field);
  for (const char* f :
       {"guide[0].load_per_metre", "guide[1].load_per_metre", "guide[2].load_per_metre",
        "guide[3].load_per_metre", "guide[6].load_per_metre", "guide[9].load_per_metre",
        "guide[10].radius", "guide[11].load_per_metre", "guide[11].radius"})
    EXPECT_EQ(std::count(fields.begin(), fields.end(), f), 1) << f;
  EXPECT_EQ(issues.size(), 9u);  // the cap itself, 0 and the two arcs facing up are accepted
  for (const Issue& i : issues) {
    if (i.field == "guide[3].load_per_metre")
      EXPECT_NE(i.expected.find("over the whole arc, and at 0 deg this arc's carrying side "
                                "(outward) faces down (n.g = 0.7 m/s^2"),
                std::string::npos)
          << i.expected;
    else if (i.field == "guide[9].load_per_metre" || i.field == "guide[11].load_per_metre")
      EXPECT_NE(i.expected.find("at 94.0939 deg this arc's carrying side (inward) faces down"),
                std::string::npos)
          << i.expected;
    else if (i.field == "guide[10].radius" || i.field == "guide[11].radius")
      EXPECT_NE(i.expected.find("at least a pitch 0.01905 m"), std::string::npos) << i.expected;
    else if (i.field == "guide[6].load_per_metre")
      EXPECT_NE(i.expected.find("press the chain onto the rail, and this rail's carrying side "
                                "(left going from its first end to its second) faces down"),
                std::string::npos)
          << i.expected;
    else
      EXPECT_NE(i.expected.find("[0, 10000] kg/m"), std::string::npos) << i.expected;
  }
  // without gravity (or with it along the rail) the load presses nothing: refused too
  m.gravity_x = m.gravity_y = 0.0;
  m.guides = {loaded_rail(5.0)};
  const std::vector<Issue> weightless = validate(m);
  ASSERT_EQ(weightless.size(), 1u);
  EXPECT_EQ(weightless[0].field, "guide[0].load_per_metre");
  EXPECT_NE(weightless[0].expected.find("no gravity"), std::string::npos);
  // a loaded rail's lead-ins are arcs: they carry none of its load
  Guide moving = loaded_rail(5.0);
  moving.load_inertia = true;
  for (const Guide& a : lead_in_arcs(moving, LeadIn{.radius = 0.05, .angle = 0.5})) {
    EXPECT_EQ(a.load_per_metre, 0.0);
    EXPECT_FALSE(a.load_inertia);
  }
}

// The load's inertia only with a load: load_inertia on an unloaded rail is named, with the
// other guides' problems, and accepted on a loaded one.
TEST(RailLoad, LoadInertiaWithoutALoadNamed) {
  Model m = uniform_chain(4, false, kPitch, 0.024, 1e7, 0.0, false);
  m.gravity_x = kGx;
  m.gravity_y = kGy;
  Guide bare = loaded_rail(0.0), loaded = loaded_rail(5.0), bad = loaded_rail(-1.0);
  bare.load_inertia = loaded.load_inertia = bad.load_inertia = true;
  m.guides = {bare, loaded, bad};
  const std::vector<Issue> issues = validate(m);
  ASSERT_EQ(issues.size(), 3u);
  EXPECT_EQ(issues[0].field, "guide[0].load_inertia");
  EXPECT_NE(issues[0].expected.find("false without a load (load_per_metre > 0 kg/m)"),
            std::string::npos)
      << issues[0].expected;
  EXPECT_EQ(issues[1].field, "guide[2].load_inertia");
  EXPECT_EQ(issues[2].field, "guide[2].load_per_metre");
}

// ∫ w(s) ds from a to b (a ≤ b), w the ramped share on a rail of length `len`: the trapezoid
// 0 below −p/2, linear to 1 at p/2, 1 to len − p/2, linear to 0 at len + p/2 (len ≥ p), summed
// exactly by the trapezoid rule between its corners.
double share_integral(double a, double b, double len) {
  const double h = 0.5 * kPitch;
  auto w = [&](double s) {
    if (s <= -h || s >= len + h) return 0.0;
    if (s < h) return (s + h) / kPitch;
    if (s > len - h) return (len + h - s) / kPitch;
    return 1.0;
  };
  std::vector<double> cuts{a, b};
  for (const double c : {-h, h, len - h, len + h})
    if (c > a && c < b) cuts.push_back(c);
  std::sort(cuts.begin(), cuts.end());
  double sum = 0.0;
  for (std::size_t k = 1; k < cuts.size(); ++k)
    sum += 0.5 * (w(cuts[k - 1]) + w(cuts[k])) * (cuts[k] - cuts[k - 1]);
  return sum;
}

// A 6-link chain (7 nodes, 24 g each) on two collinear pieces of a 15° rail (μ = 0.1, 1e6 N/m,
// 100 N·s/m), the lower x from −2 m to 0 and the upper 0 to 1 m, the slope down −x, loaded with
// q_L `lower_load` and `upper_load` (kg/m; `inertia`: load_inertia on the loaded ones), the chain
// set on the upper piece at its rest sink (its rollers' mass and the load they carry there).
constexpr double kSlope = 15.0 * std::numbers::pi / 180.0, kG = 9.81, kRollerMass = 0.024;
struct InclinedJoint {
  Model model;
  State state;
};
InclinedJoint inclined_joint(double lower_load, double upper_load, bool inertia,
                             double speed = 0.0) {
  const std::size_t n = 7;
  InclinedJoint out{uniform_chain(n, false, kPitch, kRollerMass, 2e6, 30.0, false), State(n, 0)};
  Model& model = out.model;
  model.gravity_x = -kG * std::sin(kSlope);  // the rail along +x, the slope down −x
  model.gravity_y = -kG * std::cos(kSlope);
  Guide rail;
  rail.roller_radius = 0.006;
  rail.contact_stiffness = 1e6;
  rail.contact_damping = 100.0;
  rail.friction = 0.1;
  Guide lower = rail, upper = rail;
  lower.x0 = -2.0;
  lower.x1 = 0.0;  // its second end, where the chain comes from
  upper.x0 = 0.0;
  upper.x1 = 1.0;
  lower.load_per_metre = lower_load;
  upper.load_per_metre = upper_load;
  lower.load_inertia = inertia && lower_load > 0.0;
  upper.load_inertia = inertia && upper_load > 0.0;
  lower.load_speed = lower.load_inertia ? speed : 0.0;
  upper.load_speed = upper.load_inertia ? speed : 0.0;
  model.guides = {lower, upper};
  const double sink =
      (kRollerMass + upper_load * kPitch) * kG * std::cos(kSlope) / rail.contact_stiffness +
      0.5 * rail.contact_smoothing;
  for (std::size_t i = 0; i < n; ++i) {
    out.state.x[i] = 0.02 + kPitch * static_cast<double>(i);
    out.state.y[i] = rail.roller_radius - sink;
  }
  return out;
}

// A 6-link chain slides down an inclined rail from an unloaded piece onto a loaded one collinear
// with it (15°, μ = 0.1, θ = ½), crossing the loaded piece's first end: the load's work the steps
// report is q_L p g·u Σ ∫ w(s) ds over each node's travel (its weight share along the rail, the
// ramp included) within 1e-3, and the energy balance closes with it.
TEST(RailLoad, WorkOfTheLoadIsItsWeightAlongTheTravel) {
  const double q = 2.5;
  const std::size_t n = 7;
  InclinedJoint joint = inclined_joint(q, 0.0, false);
  const Model& model = joint.model;
  State& s = joint.state;
  const std::vector<double> x0 = s.x;
  const double e0 = energy(model, s).total();
  Integrator integ(model, {.step = 1e-4, .theta = 0.5});
  for (int k = 0; k < 5000; ++k) ASSERT_TRUE(integ.step(model, s).converged) << k;
  const double len = 2.0;
  double expected = 0.0;  // the load's weight along the travel, −x: q p g sin β per metre
  for (std::size_t i = 0; i < n; ++i)  // s along the loaded piece from its first end at x = −2
    expected += q * kPitch * kG * std::sin(kSlope) * share_integral(s.x[i] + 2.0, x0[i] + 2.0, len);
  ASSERT_LT(s.x[n - 1], -0.5 * kPitch) << "every node crossed onto the loaded piece";
  EXPECT_GT(expected, 0.0);
  std::printf("the load's work %.6g J, its weight along the travel %.6g J (%+.2e)\n", s.load_work,
              expected, s.load_work / expected - 1.0);
  EXPECT_NEAR(s.load_work, expected, 1e-3 * expected);
  const double dissipated = s.friction_work + s.damper_work + s.contact_damping_work + s.drag_work;
  const double numerical = energy(model, s).total() - e0 - dissipated - s.load_work;
  std::printf("numerical %.3g J\n", numerical);
  EXPECT_LT(std::abs(numerical), 1e-3 * std::abs(s.load_work))
      << "dE " << energy(model, s).total() - e0 << " dissipated " << dissipated << " load "
      << s.load_work;
}

// A 6-link chain slides down over a loaded convex arc (an outside arc of R = 0.5 m over
// 45°–135°, q_L = 2.5 kg/m, μ = 0.1, θ = ½, 0.15 s) from near its top, every node on the arc and
// off its ramps all along: the load's work the steps report is q_L p g·Σ Δq (its weight along the
// nodes' drop) within 1e-3, and the energy balance closes with it within 1e-3 of it.
TEST(RailLoad, WorkBalanceClosesOnALoadedArc) {
  const double g0 = 9.81, q = 2.5, m = 0.024;
  const std::size_t n = 7;
  Model model = uniform_chain(n, false, kPitch, m, 2e6, 30.0, false);
  model.gravity_y = -g0;
  Guide arc;
  arc.kind = Guide::Kind::kArc;
  arc.radius = 0.5;
  arc.start_angle = 45.0 * std::numbers::pi / 180.0;
  arc.end_angle = 135.0 * std::numbers::pi / 180.0;
  arc.roller_radius = 0.006;
  arc.contact_stiffness = 1e6;
  arc.contact_damping = 100.0;
  arc.friction = 0.1;
  arc.load_per_metre = q;
  model.guides = {arc};
  ASSERT_TRUE(validate(model).empty());
  State s(n, 0);
  const double rho = arc.radius + arc.roller_radius - m * g0 / arc.contact_stiffness;
  for (std::size_t i = 0; i < n; ++i) {
    const double phi = 100.0 * std::numbers::pi / 180.0 + kPitch * static_cast<double>(i) / rho;
    s.x[i] = rho * std::cos(phi);
    s.y[i] = rho * std::sin(phi);
  }
  const std::vector<double> y0 = s.y;
  const double e0 = energy(model, s).total();
  Integrator integ(model, {.step = 1e-4, .theta = 0.5});
  for (int k = 0; k < 1500; ++k) ASSERT_TRUE(integ.step(model, s).converged) << k;
  double drop = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double phi = std::atan2(s.y[i], s.x[i]);
    ASSERT_LT(phi, arc.end_angle - kPitch / rho) << i << ": off the ramp";
    drop += y0[i] - s.y[i];
  }
  const double expected = q * kPitch * g0 * drop;
  EXPECT_GT(drop, 0.05);  // [m] the nodes' drops summed: the chain slid
  std::printf("the arc's load's work %.6g J, its weight along the drop %.6g J (%+.2e)\n",
              s.load_work, expected, s.load_work / expected - 1.0);
  EXPECT_NEAR(s.load_work, expected, 1e-3 * expected);
  const double dissipated = s.friction_work + s.damper_work + s.contact_damping_work + s.drag_work;
  const double numerical = energy(model, s).total() - e0 - dissipated - s.load_work;
  std::printf("numerical %.3g J\n", numerical);
  EXPECT_LT(std::abs(numerical), 1e-3 * expected)
      << "dE " << energy(model, s).total() - e0 << " dissipated " << dissipated << " load "
      << s.load_work;
}

// The load's inertia (Guide::load_inertia): the step's Newton matrix — the load's mass m_L1/hθ on
// the diagonal and its dependence on the iterate through the ramp, (v₁ − v₀ + [Δm_L > 0] v₀)
// (∇m_L)ᵀ — column by column against central differences of the step's residual, for a two-node
// chain a half pitch above the rail moving along it (so one node's load grows and the other's
// shrinks: the catch's branch and the discharge's), one node on either end's ramp, both ways
// along the rail, on a straight rail and either arc. The inertia's blocks are most of the matrix
// there (against the same rail without load_inertia).
// The Newton checks of the load's inertia: a two-node chain a half pitch above guide `g`, node 0
// at `s0` along it, moving along it at 1 m/s (the way of `v`'s sign), the iterate a little off
// x₀ + h v₀ (h = 1 ms, θ = 0.6); the step's Newton matrix with `g` column by column against
// central differences of the step's residual, within 1e-7 of its largest entry. Returns the
// largest |J − J_ref| over that entry, J_ref the matrix with `reference` in place of `g` at the
// same iterate (what the terms `g` adds weigh).
double newton_against_differences(const std::vector<Guide>& gs, const std::vector<Guide>& reference,
                                  double v, double s0) {
  const Guide& g = gs.front();
  Model m = uniform_chain(2, false, kPitch, 0.024, 1e4, 0.0, false);
  m.gravity_x = kGx;
  m.gravity_y = kGy;
  State st(2, 0);
  std::vector<double> u(4);
  const double h = 1e-3;
  for (std::size_t i = 0; i < 2; ++i) {
    const double si = s0 + kPitch * static_cast<double>(i);
    at(g, si, 0.5 * kPitch, st.x[i], st.y[i]);
    // the velocity along the rail (a chord of 1 mm), the iterate a little off x₀ + h v₀
    double xa = 0.0, ya = 0.0;
    at(g, si + 1e-3 * v, 0.5 * kPitch, xa, ya);
    st.vx[i] = (xa - st.x[i]) / 1e-3 * std::abs(v);
    st.vy[i] = (ya - st.y[i]) / 1e-3 * std::abs(v);
    u[2 * i] = st.x[i] + h * st.vx[i] + 2e-5 * (i == 0 ? 1.0 : -0.5);
    u[2 * i + 1] = st.y[i] + h * st.vy[i] + 1e-5;
  }
  std::vector<double> r0, jac, other;
  m.guides = reference;
  Integrator plain(m, {.step = h, .theta = 0.6});
  plain.newton_system(m, st, u, r0, &other);
  m.guides = gs;
  EXPECT_TRUE(validate(m).empty());
  Integrator integ(m, {.step = h, .theta = 0.6});
  integ.newton_system(m, st, u, r0, &jac);
  double scale = 0.0, differs = 0.0;
  for (std::size_t k = 0; k < 16; ++k) {
    scale = std::max(scale, std::abs(jac[k]));
    differs = std::max(differs, std::abs(jac[k] - other[k]));
  }
  for (std::size_t c = 0; c < 4; ++c) {
    const std::vector<double> fd = testing::residual_difference(integ, m, st, u, c, 1e-8);
    for (std::size_t r = 0; r < 4; ++r)
      EXPECT_NEAR(jac[r * 4 + c], fd[r], 1e-7 * scale)
          << s0 << " v " << v << " row " << r << " column " << c;
  }
  return differs / scale;
}
double newton_against_differences(const Guide& g, const Guide& reference, double v, double s0) {
  return newton_against_differences(std::vector<Guide>{g}, std::vector<Guide>{reference}, v, s0);
}

TEST(RailLoad, LoadInertiaNewtonMatrixIsTheResidualsDerivative) {
  for (Guide g : loaded_rails(1e3)) {
    Guide weight_only = g;
    g.load_inertia = true;
    for (const double v : {1.0, -1.0})
      for (const double s0 : {0.2 * kPitch, rail_length(g) - 1.1 * kPitch})
        EXPECT_GT(newton_against_differences(g, weight_only, v, s0), 0.5)
            << s0 << ": the inertia's block is not negligible";
  }
}

// A level, frictionless loaded rail (q_L = 2.5 kg/m) carrying a 6-link chain well inside its
// ramps, with load_inertia: (a) pulled from rest by a constant force F at its front node, its
// centre moves F t²/(2 N (m + q_L p)) in t (the spring–mass chain's start-up with the node mass
// m + q_L p: the load's mass moves with the chain); (b) a single link stretched and let go rings
// at ω = √(2 k/(m + q_L p)), its period measured from the stretch's zero crossings. With the
// load's mass left out both are off by the mass ratio (m + q_L p)/m = 2.98 (its square root).
TEST(RailLoad, LoadInertiaMovesWithTheChain) {
  const double q = 2.5, m = 0.024, k = 1e4, g0 = 9.81, mass = m + q * kPitch;
  Guide rail;
  rail.x0 = -1.0;
  rail.x1 = 1.0;
  rail.roller_radius = 0.006;
  rail.contact_stiffness = 1e6;
  rail.contact_damping = 100.0;
  rail.load_per_metre = q;
  rail.load_inertia = true;
  const double sink = mass * g0 / rail.contact_stiffness + 0.5 * rail.contact_smoothing;
  // (a) the start-up: N = 7 nodes, F = 2 N along +x on the last, 0.2 s at θ = ½
  {
    const std::size_t n = 7;
    Model model = uniform_chain(n, false, kPitch, m, k, 0.5, false);
    model.gravity_y = -g0;
    model.guides = {rail};
    const double f = 2.0;
    model.loads = {NodeLoad{n - 1, f, 0.0}};
    State s(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
      s.x[i] = kPitch * static_cast<double>(i);
      s.y[i] = rail.roller_radius - sink;
    }
    const std::vector<double> x0 = s.x;
    Integrator integ(model, {.step = 1e-4, .theta = 0.5});
    const int steps = 2000;
    for (int j = 0; j < steps; ++j) ASSERT_TRUE(integ.step(model, s).converged) << j;
    const double t = steps * 1e-4;
    double moved = 0.0;
    for (std::size_t i = 0; i < n; ++i) moved += (s.x[i] - x0[i]) / static_cast<double>(n);
    const double expected = f * t * t / (2.0 * static_cast<double>(n) * mass);
    std::printf("start-up: the centre moved %.6g m, F t^2/2 N (m + q_L p) %.6g m (%+.2e)\n", moved,
                expected, moved / expected - 1.0);
    EXPECT_NEAR(moved, expected, 1e-6 * expected);
    ASSERT_LT(s.x[n - 1], rail.x1 - kPitch) << "the chain stayed inside the ramps";
  }
  // (b) one link stretched by 0.1 mm and let go: 8 periods at about 170 steps each
  {
    Model model = uniform_chain(2, false, kPitch, m, k, 0.0, false);
    model.gravity_y = -g0;
    model.guides = {rail};
    State s(2, 0);
    s.x = {-0.5 * kPitch - 5e-5, 0.5 * kPitch + 5e-5};
    s.y = {rail.roller_radius - sink, rail.roller_radius - sink};
    const double omega = std::sqrt(2.0 * k / mass), h = 2.0 * std::numbers::pi / omega / 170.0;
    Integrator integ(model, {.step = h, .theta = 0.5});
    std::vector<double> ups;  // the times the stretch crosses 0 upwards, interpolated
    double last = s.x[1] - s.x[0] - kPitch;
    for (int j = 0; j < 8 * 170 + 20; ++j) {
      ASSERT_TRUE(integ.step(model, s).converged) << j;
      const double now = s.x[1] - s.x[0] - kPitch;
      if (last < 0.0 && now >= 0.0) ups.push_back(s.time - h * now / (now - last));
      last = now;
    }
    ASSERT_GE(ups.size(), 7u);
    const double period = (ups.back() - ups.front()) / static_cast<double>(ups.size() - 1);
    const double expected = 2.0 * std::numbers::pi / omega;
    std::printf("the link's period %.6g ms, 2 pi sqrt((m + q_L p)/2k) %.6g ms (%+.2e)\n",
                1e3 * period, 1e3 * expected, period / expected - 1.0);
    EXPECT_NEAR(period, expected, 1e-3 * expected);
  }
}

// A 6-link chain sliding down a 15° rail (μ = 0.1, θ = ½, 0.7 s) across the joint of two collinear
// pieces, the lower (x from −2 m to 0) and the upper (0 to 1 m), from the upper onto the lower,
// each loaded with load_inertia (q_L = 2.5 kg/m) or not: the run's works and what the work
// balance leaves, E₁ − E₀ (the load's kinetic energy in energy()) less the friction's, dampers',
// load's weight's, catch's and discharge's works.
struct JointSlide {
  State s;
  double numerical = 0.0;  // [J]
};
JointSlide slide_across_joint(bool lower_loaded, bool upper_loaded, double speed = 0.0) {
  const double q = 2.5;
  const std::size_t n = 7;
  InclinedJoint joint = inclined_joint(lower_loaded ? q : 0.0, upper_loaded ? q : 0.0, true, speed);
  const Model& model = joint.model;
  EXPECT_TRUE(validate(model).empty());
  JointSlide out{joint.state};
  State& s = out.s;
  const double e0 = energy(model, s).total();
  Integrator integ(model, {.step = 1e-4, .theta = 0.5});
  for (int j = 0; j < 7000; ++j) {
    if (!integ.step(model, s).converged) {
      ADD_FAILURE() << "step " << j << " did not converge";
      return out;
    }
  }
  EXPECT_LT(s.x[n - 1], -0.5 * kPitch) << "every node crossed onto the lower piece";
  const double dissipated = s.friction_work + s.damper_work + s.contact_damping_work + s.drag_work;
  out.numerical = energy(model, s).total() - e0 - dissipated - s.load_work - s.load_catch_work -
                  s.load_discharge_work;
  std::printf("lower %s, upper %s: catch %.6g J discharge %.6g J load %.6g J numerical %.3g J\n",
              lower_loaded ? "loaded" : "bare", upper_loaded ? "loaded" : "bare", s.load_catch_work,
              s.load_discharge_work, s.load_work, out.numerical);
  return out;
}

// Onto a loaded piece the catch takes work (< 0) and nothing is discharged, off one the reverse;
// the work balance closes within 1e-6 of the catch's (the discharge's) work.
TEST(RailLoad, LoadInertiaWorkBalanceClosesOntoAndOffALoadedPiece) {
  for (const bool onto : {true, false}) {
    const JointSlide r = slide_across_joint(onto, !onto);
    const State& s = r.s;
    const double exchanged = onto ? s.load_catch_work : s.load_discharge_work;
    EXPECT_LT(exchanged, 0.0);
    // (the share inside the ramps is 1 to rounding: a few ulps of the load's mass)
    EXPECT_LT(std::abs(onto ? s.load_discharge_work : s.load_catch_work),
              1e-9 * std::abs(exchanged));
    EXPECT_LT(std::abs(r.numerical), 1e-6 * std::abs(exchanged))
        << "catch " << s.load_catch_work << " discharge " << s.load_discharge_work;
  }
}

// Across the joint of two collinear loaded pieces the load passes from one to the other with its
// node (load_mass sums the pieces' shares, 1 to rounding across the joint): nothing is caught or
// discharged — within 1e-9 of what the same slide catches onto a loaded piece from a bare one.
TEST(RailLoad, LoadInertiaPassesAJointBetweenLoadedPiecesWithoutACatch) {
  const double onto = slide_across_joint(true, false).s.load_catch_work;
  const JointSlide r = slide_across_joint(true, true);
  EXPECT_LT(onto, 0.0);
  EXPECT_LT(std::abs(r.s.load_catch_work), 1e-9 * std::abs(onto));
  EXPECT_LT(std::abs(r.s.load_discharge_work), 1e-9 * std::abs(onto));
  EXPECT_LT(std::abs(r.numerical), 1e-6 * std::abs(onto));
}

// Material arriving with a speed of its own (Guide::load_speed, u along the rail's direction or
// the arc's counter-clockwise sense): the step's Newton matrix against central differences of the
// step's residual, as for the load's inertia above (the same two-node chain, both ways along the
// straight rail and either arc, a node on either end's ramp): the arriving velocity w's terms,
// −[Δm_L > 0] w (∇m_L1)ᵀ and, on an arc, where w turns with the node, −Δm_L ∂w/∂u. Against the
// same rail with the material arriving at rest those terms are far above the check's tolerance.
TEST(RailLoad, LoadSpeedNewtonMatrixIsTheResidualsDerivative) {
  for (Guide g : loaded_rails(1e3)) {
    g.load_inertia = true;
    Guide at_rest = g;
    g.load_speed = 3.0;
    for (const double s0 : {0.2 * kPitch, rail_length(g) - 1.1 * kPitch}) {
      // the node on the ramp gains load one way along the rail and sheds it the other: the
      // arriving velocity's terms act on the way it gains
      double felt = 0.0;
      for (const double v : {1.0, -1.0})
        felt = std::max(felt, newton_against_differences(g, at_rest, v, s0));
      EXPECT_GT(felt, 1e-2) << s0 << ": the arriving velocity's terms are felt";
      std::printf(
          "%s at %.4f m: the arriving velocity's terms %.3g of the matrix\n",
          g.kind == Guide::Kind::kArc ? (g.inside ? "inside arc" : "outside arc") : "straight", s0,
          felt);
    }
  }
}

// The slide onto a loaded piece (above) with the material arriving at u = −0.5 m/s along the rail
// (down the slope, the chain's way): the work balance closes within 1e-6 of the catch's work
// with the catch counting the arriving material's kinetic energy as input; that input,
// load_arrival_work, is ½ u² times the load the chain carries at the end (every node caught on the
// piece once: Σ Δm_L = Σ m_L at the end); and the catch's loss, load_catch_work less it, is a
// loss (< 0; printed beside the same slide's catch with the material arriving at rest).
TEST(RailLoad, LoadSpeedWorkBalanceClosesWithTheArrivingMaterialsEnergy) {
  const double u = -0.5;
  const JointSlide still = slide_across_joint(true, false);
  const JointSlide r = slide_across_joint(true, false, u);
  const State& s = r.s;
  const Model model = inclined_joint(2.5, 0.0, true, u).model;
  const std::vector<GuideFrame> frames{guide_frame(model.guides[0]), guide_frame(model.guides[1])};
  double carried = 0.0;  // [kg] the load the chain carries at the end
  for (std::size_t i = 0; i < s.x.size(); ++i)
    carried += load_mass(model, frames, s.x[i], s.y[i]).mass;
  const double arrival = 0.5 * u * u * carried;
  const double loss = s.load_catch_work - s.load_arrival_work;
  std::printf(
      "arriving at %.2f m/s: catch %.6g J (arrival %.6g J, 1/2 u^2 m_L %.6g J; loss %.6g "
      "J against %.6g J at rest), numerical %.3g J\n",
      u, s.load_catch_work, s.load_arrival_work, arrival, loss, still.s.load_catch_work,
      r.numerical);
  EXPECT_LT(std::abs(r.numerical), 1e-6 * std::abs(loss))
      << "catch " << s.load_catch_work << " discharge " << s.load_discharge_work;
  EXPECT_NEAR(s.load_arrival_work, arrival, 1e-9 * arrival);
  EXPECT_LT(loss, 0.0);
  EXPECT_EQ(still.s.load_arrival_work, 0.0);
}

// A 1-link chain (2 nodes, 24 g each, frictionless) riding round the inside of a circle of
// R = 0.4 m at v = 1 m/s counter-clockwise, near its bottom, from a bare arc (180°–262°) onto a
// loaded one on the same circle (262°–350°, q_L = 2.5 kg/m, load_inertia; θ = ½, 0.15 s: both
// nodes end past the loaded arc's entry ramp). The gravity is a token 0.01 m/s² (a load needs
// one to press it on the rail): over the ride's 6 mm drop its work is 1e-4 of the kinetic energy.
// With the material arriving at rest the catch's loss (load_catch_work less load_arrival_work) is
// the inelastic catch's, −½ v² 2m M_L/(2m + M_L), M_L = 2 q_L p (the angular momentum about the
// centre kept: the contact pushes radially), within 1e-3 (measured +1.7e-4). With load_speed = +v
// (the arc's counter-clockwise sense: the chain's own velocity) nothing is lost, |loss| below
// 1e-6 of that (measured 1.8e-8), the material brings ½ v² M_L (within 1e-9) and the chain keeps
// its speed within 1e-4 (measured +3e-5). With the arc's sign flipped the loss is −0.047 J, three
// times the loss at rest, and the chain nearly stops (the test fails).
TEST(RailLoad, LoadSpeedOnAnArcMatchingTheChainLosesNothing) {
  const double q = 2.5, m = 0.024, v = 1.0;
  const double deg = std::numbers::pi / 180.0;
  Guide bare;
  bare.kind = Guide::Kind::kArc;
  bare.inside = true;
  bare.radius = 0.4;
  bare.roller_radius = 0.006;
  bare.contact_stiffness = 1e6;
  bare.contact_damping = 100.0;
  bare.start_angle = 180.0 * deg;
  bare.end_angle = 262.0 * deg;
  Guide loaded = bare;
  loaded.start_angle = 262.0 * deg;
  loaded.end_angle = 350.0 * deg;
  loaded.load_per_metre = q;
  loaded.load_inertia = true;
  const double rho = line_radius(bare);
  struct Catch {
    double loss = 0.0, arrival = 0.0, speed = 0.0;
  };
  const auto ride = [&](double u) {
    Model model = uniform_chain(2, false, kPitch, m, 2e6, 30.0, false);
    model.gravity_y = -0.01;
    Guide g = loaded;
    g.load_speed = u;
    model.guides = {bare, g};
    State s(2, 0);
    const double lead = 257.0 * deg, gap = 2.0 * std::asin(0.5 * kPitch / rho);
    for (std::size_t i = 0; i < 2; ++i) {
      const double phi = lead - gap * static_cast<double>(1 - i);
      s.x[i] = rho * std::cos(phi);
      s.y[i] = rho * std::sin(phi);
      s.vx[i] = -v * std::sin(phi);
      s.vy[i] = v * std::cos(phi);
    }
    Integrator integ(model, {.step = 1e-4, .theta = 0.5});
    Catch out;
    for (int j = 0; j < 1500; ++j) {
      if (!integ.step(model, s).converged) {
        ADD_FAILURE() << "u " << u << ": step " << j << " did not converge";
        return out;
      }
    }
    for (std::size_t i = 0; i < 2; ++i) {
      const double phi = std::atan2(s.y[i], s.x[i]) + 2.0 * std::numbers::pi;
      EXPECT_GT(phi, loaded.start_angle + 0.5 * kPitch / rho) << i << ": past the entry's ramp";
      EXPECT_LT(phi, loaded.end_angle - 0.5 * kPitch / rho) << i << ": before the exit's ramp";
      out.speed += 0.5 * std::hypot(s.vx[i], s.vy[i]);
    }
    out.arrival = s.load_arrival_work;
    out.loss = s.load_catch_work - s.load_arrival_work;
    return out;
  };
  const double carried = 2.0 * q * kPitch;  // [kg] M_L
  const double expected = -0.5 * v * v * 2.0 * m * carried / (2.0 * m + carried);
  const Catch still = ride(0.0), along = ride(v);
  std::printf(
      "onto a loaded arc: at rest loss %.6g J (-1/2 v^2 2m M_L/(2m + M_L) %.6g J, %+.2e), speed "
      "%.5f m/s; at +v loss %.3g J, arrival %.6g J, speed %.5f m/s\n",
      still.loss, expected, still.loss / expected - 1.0, still.speed, along.loss, along.arrival,
      along.speed);
  EXPECT_NEAR(still.loss, expected, 1e-3 * std::abs(expected));
  EXPECT_LT(std::abs(along.loss), 1e-6 * std::abs(expected));
  EXPECT_NEAR(along.speed, v, 1e-4 * v);
  EXPECT_NEAR(along.arrival, 0.5 * v * v * carried, 1e-9 * carried);
}

// A second loaded piece beside `g` (load_inertia, q_L `load`, arriving at `speed`): from `from` to
// `to` along g's roller centres' line from g's first end (an arc's angles, a straight rail's
// ends), on g's own line.
Guide piece_along(const Guide& g, double from, double to, double load, double speed) {
  Guide out = g;
  out.load_per_metre = load;
  out.load_inertia = true;
  out.load_speed = speed;
  if (g.kind == Guide::Kind::kArc) {
    out.start_angle = g.start_angle + from / line_radius(g);
    out.end_angle = g.start_angle + to / line_radius(g);
    return out;
  }
  const GuideFrame f = guide_frame(g);
  out.x0 = g.x0 + from * f.ux;
  out.y0 = g.y0 + from * f.uy;
  out.x1 = g.x0 + to * f.ux;
  out.y1 = g.y0 + to * f.uy;
  return out;
}

// A loaded straight piece (load_inertia, q_L `load`, arriving at `speed`) across `g` at node 0 of
// newton_against_differences' chain at `s0` along g: its direction turned by the first of ±30°,
// ±65°, ±80° from g's there that keeps the load pressing onto it, node 0 0.3 p off its roller
// centres' line and 0.1 p into its entry ramp (its share grows as node 0 moves along g).
Guide piece_across(const Guide& g, double s0, double load, double speed) {
  double px = 0.0, py = 0.0, ax = 0.0, ay = 0.0;
  at(g, s0, 0.5 * kPitch, px, py);
  at(g, s0 + 1e-4, 0.5 * kPitch, ax, ay);
  const double along = std::atan2(ay - py, ax - px);
  Guide out = g;
  out.kind = Guide::Kind::kStraight;
  out.load_per_metre = load;
  out.load_inertia = true;
  out.load_speed = speed;
  for (const double turn : {30.0, -30.0, 65.0, -65.0, 80.0, -80.0}) {
    const double a = along + turn * std::numbers::pi / 180.0;
    const double ux = std::cos(a), uy = std::sin(a);
    if (!(kGx * -uy + kGy * ux < -1.0)) continue;  // g·n: the load presses onto the rail
    const double off = g.roller_radius + 0.3 * kPitch;
    out.x0 = px - 0.1 * kPitch * ux + off * uy;
    out.y0 = py - 0.1 * kPitch * uy - off * ux;
    out.x1 = out.x0 + 0.2 * ux;
    out.y1 = out.y0 + 0.2 * uy;
    return out;
  }
  ADD_FAILURE() << "no turn keeps the load on the crossing piece";
  return out;
}

// Two loaded pieces with different load_speed overlapping at a node: the step's Newton matrix
// against central differences of the residual (the two-node chain above, both ways along the
// straight rail and either arc) where the material joining the node arrives with the growing
// pieces' increments' velocity w = Σ⁺ Δm_g u_g / Σ⁺ Δm_g: (a) a second piece starting half a
// pitch after the first (their entry ramps overlap: both grow one way, both shrink the other);
// (b) a joint, the second piece starting where the first ends, lighter and heavier (one grows
// while the other shrinks; the node's load grows one way or the other); (c) a straight piece
// crossing the rail at an angle, its entry ramp at node 0 on the rail's (both grow, at rates not in
// proportion to their gradients: the (u_g − w)(∇m_g)ᵀ terms, which cancel where collinear ramps
// grow together). The increments' terms, −[Δm_L > 0] w (∇m_L1)ᵀ − Δm_L ∂w/∂u with ∂w/∂u = Σ⁺ ((u_g
// − w)(∇m_g)ᵀ + Δm_g ∂u_g/∂u)/Σ⁺ Δm_g, against the same pieces arriving at rest, at least 1e-2 of
// the matrix.
TEST(RailLoad, OverlappingLoadSpeedsNewtonMatrixIsTheResidualsDerivative) {
  for (Guide g : loaded_rails(1e3)) {
    g.load_inertia = true;
    g.load_speed = 3.0;
    const double len = rail_length(g);
    struct Case {
      const char* name;
      Guide second;
      double s0;
    };
    const Case cases[] = {
        {"overlapping entries", piece_along(g, 0.5 * kPitch, len, 600.0, -2.0), 0.2 * kPitch},
        {"a joint onto a lighter piece", piece_along(g, len, len + 3.0 * kPitch, 600.0, -2.0),
         len - 0.2 * kPitch},
        {"a joint onto a heavier piece", piece_along(g, len, len + 3.0 * kPitch, 1600.0, -2.0),
         len - 0.2 * kPitch},
        {"a crossing piece", piece_across(g, 0.2 * kPitch, 600.0, -2.0), 0.2 * kPitch},
    };
    for (const Case& c : cases) {
      std::vector<Guide> at_rest{g, c.second};
      at_rest[0].load_speed = at_rest[1].load_speed = 0.0;
      double felt = 0.0;
      for (const double v : {1.0, -1.0}) {
        felt = std::max(
            felt, newton_against_differences(std::vector<Guide>{g, c.second}, at_rest, v, c.s0));
      }
      EXPECT_GT(felt, 1e-2) << c.name << ": the arriving velocity's terms are felt";
      std::printf(
          "%s, %s: the arriving velocity's terms %.3g of the matrix\n",
          g.kind == Guide::Kind::kArc ? (g.inside ? "inside arc" : "outside arc") : "straight",
          c.name, felt);
    }
  }
}

// A level, frictionless rail from x = −0.5 m to `bare_end` (bare) with `loaded` pieces, and a
// chain of n nodes of mass m on it (links 1e5 N/m), at its rest sink, its front node a pitch
// before the bare piece's end, coasting at v0 along +x; `stiffness` the rails' contact.
struct LevelCoast {
  Model model;
  State state;
  std::vector<GuideFrame> frames;
};
Guide level_bare_rail(double stiffness, double end = 0.0) {
  Guide bare;
  bare.x0 = -0.5;
  bare.x1 = end;
  bare.roller_radius = 0.006;
  bare.contact_stiffness = stiffness;
  bare.contact_damping = 100.0;
  return bare;
}
LevelCoast level_coast(std::size_t n, double m, double v0, const std::vector<Guide>& loaded,
                       double bare_end = 0.0) {
  const double g0 = 9.81;
  LevelCoast out{uniform_chain(n, false, kPitch, m, 1e5, 1.0, false), State(n, 0), {}};
  out.model.gravity_y = -g0;
  out.model.guides = loaded;
  out.model.guides.insert(out.model.guides.begin(),
                          level_bare_rail(loaded.front().contact_stiffness, bare_end));
  EXPECT_TRUE(validate(out.model).empty());
  const Guide& bare = out.model.guides.front();
  const double sink = m * g0 / bare.contact_stiffness + 0.5 * bare.contact_smoothing;
  for (std::size_t i = 0; i < n; ++i) {
    out.state.x[i] = -kPitch * static_cast<double>(n - i);
    out.state.y[i] = bare.roller_radius - sink;
    out.state.vx[i] = v0;
  }
  for (const Guide& g : out.model.guides) out.frames.push_back(guide_frame(g));
  return out;
}
// Σ (m + m_L) v_x: the chain's momentum along the rail with its load (m the nodes' own mass).
double carried_momentum(const LevelCoast& c, double m, const State& s) {
  double sum = 0.0;
  for (std::size_t i = 0; i < s.x.size(); ++i)
    sum += (m + load_mass(c.model, c.frames, s.x[i], s.y[i]).mass) * s.vx[i];
  return sum;
}

// A 3-link chain (4 nodes, 24 g each) coasting at 1 m/s along a level frictionless rail from a
// bare piece onto three loaded ones with load_inertia (θ = ½, 0.45 s; a pitch p): A from x = 0 to
// 0.3 m (q_A = 2.5 kg/m, u_A = +0.5 m/s), B from p/2 to 0.6 m (1.5 kg/m, +2 m/s: its entry ramp
// overlaps A's, both growing; 1 mm below the others, so that the rollers carry its load but touch
// only A and C) and C from 0.3 to 0.6 m (3 kg/m, −1 m/s: at the joint with A, A's share shrinks
// while C's grows). No force acts along the rail, so the chain's momentum with its load,
// Σ (m + m_L) v_x, changes only by what the arriving material brings: each node, ending on B and
// C, p (q_A u_A + q_B u_B + (q_C − q_A) u_C) — at the joint A's load passes to C with the node and
// only C's excess q_C − q_A arrives, at u_C; nothing is discharged. The arriving material's
// kinetic energy (load_arrival_work) is ½ p Σ q_g u_g² likewise, and the work balance closes with
// the catch to rounding (within 1e-9 of the catch's loss; measured 1.4e-11).
TEST(RailLoad, OverlappingLoadSpeedsBringEachPiecesMomentum) {
  const double m = 0.024, v0 = 1.0;
  const double qa = 2.5, qb = 1.5, qc = 3.0, ua = 0.5, ub = 2.0, uc = -1.0;
  const std::size_t n = 4;
  const Guide bare = level_bare_rail(1e6);
  const Guide a = piece_along(bare, 0.5, 0.8, qa, ua);
  Guide b = piece_along(bare, 0.5 + 0.5 * kPitch, 1.1, qb, ub);
  b.y0 = b.y1 = -1e-3;  // below the others' surface: its load, not a second contact
  const Guide c = piece_along(bare, 0.8, 1.1, qc, uc);
  LevelCoast coast = level_coast(n, m, v0, {a, b, c});
  const Model& model = coast.model;
  State& s = coast.state;
  const double p0 = carried_momentum(coast, m, s), e0 = energy(model, s).total();
  Integrator integ(model, {.step = 1e-4, .theta = 0.5});
  for (int j = 0; j < 4500; ++j) ASSERT_TRUE(integ.step(model, s).converged) << j;
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_GT(s.x[i], 0.3 + 0.5 * kPitch) << i << ": past the joint's ramps";
    EXPECT_LT(s.x[i], 0.6 - 0.5 * kPitch) << i << ": before the exits' ramps";
  }
  const double nodes = static_cast<double>(n);
  const double brought = nodes * kPitch * (qa * ua + qb * ub + (qc - qa) * uc);
  const double arrival = 0.5 * nodes * kPitch * (qa * ua * ua + qb * ub * ub + (qc - qa) * uc * uc);
  const double gained = carried_momentum(coast, m, s) - p0;
  const double dissipated = s.friction_work + s.damper_work + s.contact_damping_work + s.drag_work;
  const double numerical = energy(model, s).total() - e0 - dissipated - s.load_work -
                           s.load_catch_work - s.load_discharge_work;
  std::printf(
      "momentum gained %.9g kg m/s against %.9g (%+.2e); arrival %.9g J against %.9g J (%+.2e); "
      "catch %.6g J, discharge %.3g J, numerical %.3g J; speed %.5f m/s\n",
      gained, brought, gained / brought - 1.0, s.load_arrival_work, arrival,
      s.load_arrival_work / arrival - 1.0, s.load_catch_work, s.load_discharge_work, numerical,
      s.vx[0]);
  EXPECT_NEAR(gained, brought, 1e-9 * std::abs(brought));
  EXPECT_NEAR(s.load_arrival_work, arrival, 1e-9 * arrival);
  EXPECT_LT(std::abs(s.load_discharge_work), 1e-9 * arrival);
  EXPECT_LT(std::abs(numerical), 1e-9 * std::abs(s.load_catch_work - s.load_arrival_work));
}

// The step force of two pieces on a run at v, the second starting on the first's stretch (their
// entry ramps apart): q₁ v (v − u₁) + q₂ v (v − u₂), each piece catching its own material. A
// 1-link chain of two 2 t nodes (its speed changes by 1.2e-5 over the run: steady) coasts at
// v = 1 m/s (θ = ½, 0.3 s, rails of 1e9 N/m) onto A (0 to 0.4 m, q₁ = 2.5 kg/m, u₁ = +0.5 m/s)
// and B (0.1 to 0.4 m, q₂ = 1.5 kg/m, u₂ = +2 m/s), both 1 mm below the bare rail, which
// carries the chain on to 1 m (no joint to cross). The catches' impulse on the
// chain, Σ over the steps and nodes of (m + m_L1)(v₁ − v₀) (nothing else acts along the rail), is
// that force over the time the two nodes take to pass, 2 p/v: 2 p (q₁ (u₁ − v) + q₂ (u₂ − v)),
// within 1e-3 (measured +9.1e-5: the speed's drift, with each catch's impulse five times the
// net). The whole load's velocity gave B's catch w̄ = u₂ + (u₁ − u₂)(q₁/q₂) ln(1 + q₂/q₁)
// = 0.825 m/s in place of u₂: 2 p (q₁ (u₁ − v) + q₂ (w̄ − v)), of the other sign.
TEST(RailLoad, OverlappingLoadSpeedsStepForceIsEachPiecesCatch) {
  const double m = 2e3, v = 1.0, q1 = 2.5, q2 = 1.5, u1 = 0.5, u2 = 2.0;
  const Guide bare = level_bare_rail(1e9);
  Guide a = piece_along(bare, 0.5, 0.9, q1, u1);
  Guide b = piece_along(bare, 0.6, 0.9, q2, u2);
  a.y0 = a.y1 = b.y0 = b.y1 = -1e-3;  // the loads only: the chain rides on the bare rail
  LevelCoast coast = level_coast(2, m, v, {a, b}, 1.0);
  const Model& model = coast.model;
  State& s = coast.state;
  Integrator integ(model, {.step = 1e-4, .theta = 0.5});
  double impulse = 0.0;
  for (int j = 0; j < 3000; ++j) {
    const std::vector<double> before = s.vx;
    ASSERT_TRUE(integ.step(model, s).converged) << j;
    for (std::size_t i = 0; i < 2; ++i)
      impulse += (m + load_mass(model, coast.frames, s.x[i], s.y[i]).mass) * (s.vx[i] - before[i]);
  }
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_GT(s.x[i], 0.1 + 0.5 * kPitch) << i << ": past B's entry ramp";
    EXPECT_LT(s.x[i], 0.4 - 0.5 * kPitch) << i << ": before the exits' ramps";
  }
  const double expected = 2.0 * kPitch * (q1 * (u1 - v) + q2 * (u2 - v));
  const double mixed = u2 + (u1 - u2) * (q1 / q2) * std::log(1.0 + q2 / q1);
  const double whole_load = 2.0 * kPitch * (q1 * (u1 - v) + q2 * (mixed - v));
  std::printf(
      "the catches' impulse %.6g N s against 2 p (q1 (u1 - v) + q2 (u2 - v)) %.6g N s (%+.2e); "
      "the whole load's velocity's closed form %.6g N s; speed %.6f m/s\n",
      impulse, expected, impulse / expected - 1.0, whole_load, s.vx[0]);
  EXPECT_NEAR(impulse, expected, 1e-3 * std::abs(expected));
}

// A bad load_speed named with the other guides' problems: not finite, beyond ±100 m/s, and a
// speed on a guide whose load is weight only (it would do nothing); accepted on a loaded guide
// with the inertia, either way along it.
TEST(RailLoad, BadLoadSpeedNamed) {
  Model m = uniform_chain(4, false, kPitch, 0.024, 1e7, 0.0, false);
  m.gravity_x = kGx;
  m.gravity_y = kGy;
  Guide fast = loaded_rail(5.0), nan = loaded_rail(5.0), weight = loaded_rail(5.0),
        good = loaded_rail(5.0), back = loaded_rail(5.0);
  fast.load_inertia = nan.load_inertia = good.load_inertia = back.load_inertia = true;
  fast.load_speed = 100.5;
  nan.load_speed = NAN;
  weight.load_speed = 1.0;
  good.load_speed = 100.0;
  back.load_speed = -2.0;
  m.guides = {good, fast, nan, back, weight};
  const std::vector<Issue> issues = validate(m);
  ASSERT_EQ(issues.size(), 3u);
  EXPECT_EQ(issues[0].field, "guide[1].load_speed");
  EXPECT_NE(issues[0].expected.find("a speed in [-100, 100] m/s"), std::string::npos)
      << issues[0].expected;
  EXPECT_EQ(issues[1].field, "guide[2].load_speed");
  EXPECT_EQ(issues[2].field, "guide[4].load_speed");
  EXPECT_NE(issues[2].expected.find("0 without load_inertia = true"), std::string::npos)
      << issues[2].expected;
  // a lead-in arc carries none of its rail's load, nor its speed
  for (const Guide& a : lead_in_arcs(good, LeadIn{.radius = 0.05, .angle = 0.5}))
    EXPECT_EQ(a.load_speed, 0.0);
}

}  // namespace
}  // namespace catena::dynamics
