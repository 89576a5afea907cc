// The guides' rails under the line law (contact_law = "line"; docs/models/dynamics.md, "Guides:
// the line law"): a roller on a rail is a line contact of the roller on a flat (ρ = r), on a
// convex arc (1/ρ = 1/r + 1/R) or in a concave one (1/ρ = 1/r − 1/R), its force Q(g) the inverse of
// Johnson's plane-strain approach δ(Q), written out here from its formula (not through the
// library), as the seats' (seat_line_law_test.cpp); its tangent and energy; the Newton matrix with
// the law (also with the stick law on an arc); a chain piece settling on a straight rail under
// gravity at the law's approach, on steel and on a polymer rail; and the energy of a damped drop
// onto the rail, balanced by the work of its damper.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "catena/dynamics/integrator.hpp"
#include "log_simpson.hpp"
#include "penalty_ramp.hpp"
#include "residual_difference.hpp"

namespace catena::dynamics {
namespace {

constexpr double kPi = std::numbers::pi;
// 12B (ISO 606): pitch, roller radius d1/2, inner width b1, a link's mass; steel rollers
constexpr double kPitch = 0.01905, kRoller = 0.006035, kWidth = 0.01168, kMass = 0.0238;
constexpr double kSteel = 210e9, kSteelNu = 0.3;
constexpr double kPolymer = 0.7e9, kPolymerNu = 0.4;  // UHMW-PE
constexpr double kArcRadius = 0.25;

// The rails of the tests: straight, level, rollers on top (free side +y), the surface at y = 0;
// an arc of R = 0.25 m about the origin with the rollers outside or inside it
Guide rail(Guide::Kind kind, bool inside, double modulus = kSteel, double nu = kSteelNu) {
  Guide g;
  g.kind = kind;
  if (kind == Guide::Kind::kStraight) {
    g.x0 = -0.5;
    g.x1 = 0.5;
  } else {
    g.radius = kArcRadius;
    g.start_angle = 0.2;
    g.end_angle = 2.9;
    g.inside = inside;
  }
  g.roller_radius = kRoller;
  g.contact_stiffness = 1e7;  // the penalty the law replaces (used if the law were off)
  g.rail = {modulus, nu};
  use_line_law(g, kWidth);
  return g;
}

// Johnson's line contact of the roller on the rail written out: the reduced radius, the
// compliance Σ(1 − ν²)/E and E*
struct Johnson {
  double rho = 0.0, compliance = 0.0, e_star = 0.0;
};
Johnson johnson(const Guide& g) {
  Johnson j;
  const double curvature = g.kind == Guide::Kind::kStraight ? 0.0
                           : g.inside                       ? -1.0 / g.radius
                                                            : 1.0 / g.radius;
  j.rho = 1.0 / (1.0 / kRoller + curvature);
  j.compliance =
      (1 - kSteelNu * kSteelNu) / kSteel + (1 - g.rail.poisson * g.rail.poisson) / g.rail.modulus;
  j.e_star = 1.0 / j.compliance;
  return j;
}
// [m] δ(Q) = (q/π) Σ(1 − ν²)/E (2 ln(4 r/b) − 1), b = √(4qρ/(πE*)), q = Q/b1
double johnson_approach(const Guide& g, double load) {
  const Johnson j = johnson(g);
  const double q = load / kWidth;
  const double b = std::sqrt(4 * q * j.rho / (kPi * j.e_star));
  return q / kPi * j.compliance * (2 * std::log(4 * kRoller / b) - 1);
}
// [J] ∫ Q dδ = b1 ∫ q dδ: with δ = A q (C − ln q) (A = compliance/π, C from the formula above),
// b1 A q² ((C − ln q)/2 − 1/4)
double johnson_energy(const Guide& g, double load) {
  const Johnson j = johnson(g);
  const double q = load / kWidth, a = j.compliance / kPi;
  const double c = 2 * std::log(4 * kRoller) - std::log(4 * j.rho / (kPi * j.e_star)) - 1;
  return kWidth * a * q * q * (0.5 * (c - std::log(q)) - 0.25);
}

// The roller's centre pressed `depth` into the rail at the rail's middle, and the normal n there
struct Touch {
  double x = 0.0, y = 0.0, nx = 0.0, ny = 0.0;
};
Touch touch(const Guide& g, double depth, double along = 0.5) {
  Touch t;
  if (g.kind == Guide::Kind::kStraight) {
    t.x = g.x0 + along * (g.x1 - g.x0);
    t.y = kRoller - depth;
    t.ny = 1.0;
    return t;
  }
  const double a = g.start_angle + along * (g.end_angle - g.start_angle);
  const double d = g.inside ? g.radius - kRoller + depth : g.radius + kRoller - depth;
  const double sgn = g.inside ? -1.0 : 1.0;
  t.x = d * std::cos(a);
  t.y = d * std::sin(a);
  t.nx = sgn * std::cos(a);
  t.ny = sgn * std::sin(a);
  return t;
}
GuideContact at_depth(const Guide& g, double depth) {
  const Touch t = touch(g, depth);
  return guide_contact(g, t.x, t.y, 0.0, 0.0);
}
// −nᵀ (∂F/∂q) n: the normal force's stiffness ∂f/∂g (the arc's f κ t tᵀ has no n n part)
double normal_stiffness(const GuideContact& c) {
  return -(c.nx * (c.dq[0] * c.nx + c.dq[1] * c.ny) + c.ny * (c.dq[2] * c.nx + c.dq[3] * c.ny));
}
// ∫ f dg' over [from, to] by Simpson's rule in s = ln g'
double quadrature(const Guide& g, double from, double to) {
  return testing::simpson_in_log(from, to, [&g](double d) { return at_depth(g, d).normal_force; });
}

// (1) The law against independent numerics on a flat steel rail, outside and inside a steel arc
// and on a flat polymer rail: at 100 random loads over 1 N … the cap, the rail contact's normal
// force at δ(Q) is Q, its stiffness the central difference of the force, its energy the
// quadrature of the force over g and the closed form; past the cap the tangent (C¹).
TEST(DynamicsRailLineLaw, ForceStiffnessAndEnergyAgainstJohnsonsApproach) {
  const std::vector<Guide> rails = {rail(Guide::Kind::kStraight, false),
                                    rail(Guide::Kind::kArc, false), rail(Guide::Kind::kArc, true),
                                    rail(Guide::Kind::kStraight, false, kPolymer, kPolymerNu)};
  const char* names[] = {"flat", "outside arc", "inside arc", "flat polymer"};
  for (std::size_t k = 0; k < rails.size(); ++k) {
    const Guide& g = rails[k];
    EXPECT_NEAR(g.line.law.rho / johnson(g).rho, 1.0, 1e-14) << names[k];
    const double cap = g.line.cap_force;
    std::mt19937 rng(21);
    std::uniform_real_distribution<double> decade(0.0, std::log10(cap));
    double worst = 0.0;
    for (int i = 0; i < 100; ++i) {
      const double load = std::pow(10.0, decade(rng));
      const double d = johnson_approach(g, load);
      const GuideContact c = at_depth(g, d);
      ASSERT_TRUE(c.active) << names[k];
      // at the penetration guide_contact finds (on the arcs the roller's centre, 0.25 m from
      // theirs, rounds it by 1e-17 m, 1e-8 of the lightest loads' approach), the force's approach
      // by the formula is that penetration
      const double back = johnson_approach(g, c.normal_force) / c.penetration;
      worst = std::max(worst, std::abs(back - 1.0));
      EXPECT_NEAR(back, 1.0, 1e-12) << names[k] << " " << load;
      EXPECT_NEAR(c.normal_force / load, 1.0, 1e-7) << names[k] << " " << load;
      // over the penetrations guide_contact itself finds (the arcs' centres at 0.25 m round the
      // roller's position at 1e-17 m, against steps of 1e-14 m at the lightest loads)
      const GuideContact up = at_depth(g, 1.0001 * d), down = at_depth(g, 0.9999 * d);
      const double slope =
          (up.normal_force - down.normal_force) / (up.penetration - down.penetration);
      EXPECT_NEAR(normal_stiffness(c) / slope, 1.0, 1e-7) << names[k] << " " << load;
      EXPECT_NEAR(c.energy / johnson_energy(g, c.normal_force), 1.0, 1e-12)
          << names[k] << " " << load;
      if (i % 10 == 0) {
        EXPECT_NEAR(c.energy / quadrature(g, 1e-14 * d, d), 1.0, 1e-9) << names[k] << " " << load;
      }
    }
    const double g_cap = g.line.cap_depth;
    const GuideContact below = at_depth(g, g_cap * (1 - 1e-9)),
                       above = at_depth(g, g_cap * (1 + 1e-9));
    EXPECT_NEAR(above.normal_force / below.normal_force, 1.0, 1e-8) << names[k];
    EXPECT_NEAR(normal_stiffness(above) / normal_stiffness(below), 1.0, 1e-6) << names[k];
    const GuideContact deep = at_depth(g, 1.5 * g_cap);
    EXPECT_NEAR(deep.normal_force, cap + g.line.cap_stiffness * 0.5 * g_cap, 1e-9 * cap);
    std::printf(
        "%s rail: cap %.4g N at %.4g um, worst |delta(Q(g))/g - 1| %.2e, at 100 N: %.4g um\n",
        names[k], cap, g_cap * 1e6, worst, johnson_approach(g, 100.0) * 1e6);
  }
}

// Lead-ins take their own arc's curvature: a straight rail's lead-in arcs under the line law carry
// the law of a roller on a convex arc of the lead-in's radius and the rail's material.
TEST(DynamicsRailLineLaw, LeadInArcsUseTheirCurvature) {
  const Guide flat = rail(Guide::Kind::kStraight, false, kPolymer, kPolymerNu);
  const std::vector<Guide> arcs = lead_in_arcs(flat, {.radius = 0.05, .angle = 0.5});
  ASSERT_EQ(arcs.size(), 2u);
  for (const Guide& a : arcs) {
    EXPECT_TRUE(a.line_law);
    EXPECT_NEAR(a.line.law.rho, 1.0 / (1.0 / kRoller + 1.0 / 0.05), 1e-15);
    EXPECT_NEAR(a.line.law.e_star / johnson(flat).e_star, 1.0, 1e-14);
    EXPECT_EQ(a.line.width, kWidth);
  }
}

// The model's check names a rail's bad material and a law left unset, each by field.
TEST(DynamicsRailLineLaw, ModelCheckNamesTheRailsFields) {
  Model m = uniform_chain(2, false, kPitch, kMass, 5e7, 0.0, false);
  m.guides = {rail(Guide::Kind::kStraight, false)};
  EXPECT_TRUE(validate(m).empty());
  m.guides[0].rail = {1e6, 0.5};
  m.guides[0].line.cap_depth = 0.0;
  std::vector<std::string> fields;
  for (const Issue& i : validate(m)) fields.push_back(i.field);
  for (const char* f :
       {"guide[0].rail_modulus", "guide[0].rail_poisson", "guide[0].line_cap_depth"})
    EXPECT_NE(std::find(fields.begin(), fields.end(), f), fields.end()) << f;
}

// The Newton matrix tests' set-up ((2), (7)): two linked 12B rollers (5e7 N/m, 100 N s/m) under
// gravity on the rail rail(kind, inside) with its damper 200 N s/m and friction 0.3, then
// tune(guide); roller i placed by place(guide, i, along, start, u) at the step's start and in the
// iterate u, `along` 0.5 + 0.02 i of the straight rail (0.5 + 0.07 i of an arc).
struct RailPair {
  Model model;
  State start;
  std::vector<double> u;
};
template <class Tune, class Place>
RailPair rail_pair(Guide::Kind kind, bool inside, Tune tune, Place place) {
  Guide g = rail(kind, inside);
  g.contact_damping = 200.0;
  g.friction = 0.3;
  tune(g);
  RailPair p{uniform_chain(2, false, kPitch, kMass, 5e7, 100.0, false), State(2, 0),
             std::vector<double>(4)};
  p.model.gravity_y = -9.81;
  p.model.guides = {g};
  for (std::size_t i = 0; i < 2; ++i) {
    const double along =
        0.5 + (kind == Guide::Kind::kStraight ? 0.02 : 0.07) * static_cast<double>(i);
    place(g, i, along, p.start, p.u);
  }
  return p;
}

// (2) The step's Newton matrix with rails in the line law, against central differences of the
// step's residual, every column: two linked rollers pressed 1–3 µm into a straight rail, an arc
// from outside and one from inside, moving along and into it, with the rails' damping and
// friction; and it is the law's matrix: it differs from the penalty's (1e7 N/m) at the same
// iterate. The arc from outside once more with the stick law (k_t = 1e6 N/m, "Guides: sticking"):
// node 0 anchored within its spring's reach (sticking), node 1 beyond it (sliding at μ f of the
// line law's force).
TEST(DynamicsRailLineLaw, NewtonMatrixMatchesTheResidualsDifferences) {
  const double h = 1e-4;
  struct Case {
    Guide::Kind kind;
    bool inside;
    double stick;  // [N/m] k_t (0: the regularised friction)
  };
  const Case rails[] = {{Guide::Kind::kStraight, false, 0.0},
                        {Guide::Kind::kArc, false, 0.0},
                        {Guide::Kind::kArc, true, 0.0},
                        {Guide::Kind::kArc, false, 1e6}};
  for (const auto& [kind, inside, stick] : rails) {
    std::vector<double> jac_linear;
    for (const bool line : {false, true}) {
      std::mt19937 rng(3);
      std::uniform_real_distribution<double> jitter(-1e-8, 1e-8);
      RailPair pair = rail_pair(
          kind, inside,
          [&](Guide& g) {
            g.stick_stiffness = stick;
            g.line_law = line;
            g.discrete_gradient = line;  // the penalty at the θ point, the law's discrete gradient
          },
          [&](const Guide& g, std::size_t i, double along, State& s, std::vector<double>& u) {
            // pressed 1 and 3 µm in, moving along the rail and into it; u a step on, jittered
            const Touch t = touch(g, 1e-6 + 2e-6 * static_cast<double>(i), along);
            s.x[i] = t.x;
            s.y[i] = t.y;
            s.vx[i] = -0.2 * t.ny - 1e-3 * t.nx;
            s.vy[i] = 0.2 * t.nx - 1e-3 * t.ny;
            u[2 * i] = s.x[i] + h * s.vx[i] + jitter(rng);
            u[2 * i + 1] = s.y[i] + h * s.vy[i] + jitter(rng);
          });
      const Model& m = pair.model;
      const Guide& g = m.guides[0];
      State& s = pair.start;
      const std::vector<double>& u = pair.u;
      Integrator integ(m, {.step = h, .theta = 0.6});
      ASSERT_EQ(integ.unknowns(), 4u);
      if (stick > 0.0) {
        // the anchors 0.5 and 3 reaches μ f/k_t behind the θ point, f its normal force
        const GuideFrame f = guide_frame(g);
        s.stick_anchor.assign(2, NAN);
        for (std::size_t i = 0; i < 2; ++i) {
          const double qx = s.x[i] + 0.6 * (u[2 * i] - s.x[i]);
          const double qy = s.y[i] + 0.6 * (u[2 * i + 1] - s.y[i]);
          const double vx = (u[2 * i] - s.x[i]) / h, vy = (u[2 * i + 1] - s.y[i]) / h;
          const GuideContact c = guide_contact(g, f, qx, qy, vx, vy);
          ASSERT_GT(c.normal_force, 0.0) << i;
          const double reach = g.friction * c.normal_force / stick;
          s.stick_anchor[i] = guide_position(g, f, qx, qy) - (i == 0 ? 0.5 : 3.0) * reach;
          EXPECT_EQ(guide_contact(g, f, qx, qy, vx, vy, s.stick_anchor[i]).sticking, i == 0) << i;
        }
      }
      std::vector<double> r0, jac;
      integ.newton_system(m, s, u, r0, &jac);
      if (stick > 0.0) {
        // the stick law's share of the matrix is not negligible
        Model bare = m;
        bare.guides[0].stick_stiffness = 0.0;
        Integrator plain(bare, {.step = h, .theta = 0.6});
        std::vector<double> r1, without;
        plain.newton_system(bare, s, u, r1, &without);
        double scale = 0.0, share = 0.0;
        for (std::size_t k = 0; k < jac.size(); ++k) {
          scale = std::max(scale, std::abs(jac[k]));
          share = std::max(share, std::abs(jac[k] - without[k]));
        }
        EXPECT_GT(share, 1e-3 * scale);
      }
      if (!line) {
        jac_linear = jac;
        continue;
      }
      const testing::ColumnsAgainstDifferences d = testing::expect_columns_match_differences(
          integ, m, s, u, jac, jac_linear, [](std::size_t) { return 1e-9; }, 1e-5);
      std::printf("rail line law's Newton matrix (%s%s): worst |J - FD| / column scale %.2e\n",
                  kind == Guide::Kind::kStraight ? "straight" : (inside ? "inside arc" : "arc"),
                  stick > 0.0 ? ", sticking" : "", d.worst);
      EXPECT_GT(d.differs, 0.1 * d.scale);
    }
  }
}

// (3) A chain piece of five links resting on a level straight rail under gravity, frictionless,
// settles (θ = 1: its fixed point is the static equilibrium) with each roller at the approach
// δ(m g/b1) of the closed form, and the contacts' energy at rest is the closed form's; on a
// polymer rail (UHMW-PE, E = 0.7 GPa, ν = 0.4) the rollers sink deeper by the law's ratio of the
// two approaches, not by the moduli's.
struct Settled {
  std::vector<double> depth;
  double elastic = 0.0;
};
Settled settle(const Guide& g) {
  constexpr double kG = 9.81;
  const std::size_t n = 5;
  Model m = uniform_chain(n, false, kPitch, kMass, 5e7, 100.0, false);
  m.gravity_y = -kG;
  Guide r = g;
  r.contact_damping = 2000.0;
  m.guides = {r};
  State s(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    s.x[i] = kPitch * static_cast<double>(i);
    s.y[i] = kRoller;  // touching
  }
  Integrator integ(m, {.step = 1e-4, .theta = 1.0});
  for (int k = 0; k < 400; ++k) {
    const StepReport rep = integ.step(m, s);
    if (!rep.converged) {
      ADD_FAILURE() << "step " << k << " did not converge";
      break;
    }
  }
  Settled out;
  for (std::size_t i = 0; i < n; ++i) out.depth.push_back(kRoller - s.y[i]);
  out.elastic = energy(m, s).elastic;
  return out;
}

TEST(DynamicsRailLineLaw, ChainPieceSettlesAtTheLawsApproach) {
  const double weight = kMass * 9.81;
  const Guide steel = rail(Guide::Kind::kStraight, false);
  const Guide polymer = rail(Guide::Kind::kStraight, false, kPolymer, kPolymerNu);
  const Settled on_steel = settle(steel), on_polymer = settle(polymer);
  const double d_steel = johnson_approach(steel, weight);
  const double d_polymer = johnson_approach(polymer, weight);
  for (std::size_t i = 0; i < on_steel.depth.size(); ++i) {
    EXPECT_NEAR(on_steel.depth[i] / d_steel, 1.0, 1e-6) << i;
    EXPECT_NEAR(on_polymer.depth[i] / d_polymer, 1.0, 1e-6) << i;
  }
  const double n = static_cast<double>(on_steel.depth.size());
  EXPECT_NEAR(on_steel.elastic / (n * johnson_energy(steel, weight)), 1.0, 1e-5);
  EXPECT_NEAR(on_polymer.elastic / (n * johnson_energy(polymer, weight)), 1.0, 1e-5);
  const double ratio = on_polymer.depth[2] / on_steel.depth[2];
  const double moduli = johnson(steel).compliance / johnson(polymer).compliance;
  std::printf(
      "at rest under %.4g N a roller: steel %.5g nm, polymer %.5g nm (x %.2f; the "
      "compliances' ratio %.2f)\n",
      weight, on_steel.depth[2] * 1e9, on_polymer.depth[2] * 1e9, ratio, 1.0 / moduli);
  EXPECT_NEAR(ratio, d_polymer / d_steel, 1e-5 * ratio);
  EXPECT_LT(ratio, 1.0 / moduli);  // the log term grows less on the softer rail (b wider)
}

// (4) Energy: two linked rollers dropped at 0.3 m/s onto the polymer rail from 0.1 µm above it,
// frictionless, at θ = ½ over 2 ms of 0.5 µs steps. Undamped, the energy is conserved and the
// deepest approach is the closed form's: the contact's energy E(Q) at δ(Q) equals the kinetic
// energy and the fall, ½ m v₀² + m g (δ + 0.1 µm), per roller. With the rail's damper the energy
// lost is the damper's work (the work balance closes).
struct RailDrop {
  double deepest = 0.0, lost = 0.0, damper = 0.0, kinetic0 = 0.0, drift = 0.0, gained = 0.0;
  double friction = 0.0;  // [J] the rail's friction work booked
};
// the drop's speed [m/s] and height [m] above the rail, its steps [s] and their number; its speed
// along the rail [m/s]
struct DropRun {
  double speed = 0.3, above = 1e-7, step = 5e-7;
  int steps = 4000;
  double along = 0.0;
};
RailDrop rail_drop(const Guide& g, double damping, const DropRun& run = {}) {
  constexpr double kG = 9.81;
  const double kV = run.speed, kAbove = run.above;
  Guide r = g;
  r.contact_damping = damping;
  Model m = uniform_chain(2, false, kPitch, kMass, 5e7, 0.0, false);
  m.gravity_y = -kG;
  m.guides = {r};
  State s(2, 0);
  for (std::size_t i = 0; i < 2; ++i) {
    s.x[i] = kPitch * static_cast<double>(i);
    s.y[i] = kRoller + kAbove;
    s.vx[i] = run.along;
    s.vy[i] = -kV;
  }
  const Energy e0 = energy(m, s);
  Integrator integ(m, {.step = run.step, .theta = 0.5});
  RailDrop d;
  d.kinetic0 = e0.kinetic;
  double lowest = INFINITY;
  for (int k = 0; k < run.steps; ++k) {
    if (!integ.step(m, s).converged) {
      ADD_FAILURE() << "step " << k << " did not converge";
      break;
    }
    lowest = std::min(lowest, s.y[0]);
    const double change = energy(m, s).total() - e0.total();
    d.drift = std::max(d.drift, std::abs(change));
    d.gained = std::max(d.gained, change);
  }
  d.deepest = kRoller - lowest;
  d.lost = e0.total() - energy(m, s).total();
  d.damper = s.contact_damping_work;
  d.friction = s.friction_work;
  return d;
}

TEST(DynamicsRailLineLaw, DropsEnergyAndWorkBalance) {
  constexpr double kG = 9.81, kV = 0.3, kAbove = 1e-7;
  const Guide g = rail(Guide::Kind::kStraight, false, kPolymer, kPolymerNu);
  const RailDrop free = rail_drop(g, 0.0), damped = rail_drop(g, 20.0);
  // the closed form's deepest approach: E(Q) − m g δ(Q) = ½ m v₀² + m g · 0.1 µm, by bisection
  // in Q (the left side increases with Q: dE = Q dδ > m g dδ past the roller's weight)
  const double target = 0.5 * kMass * kV * kV + kMass * kG * kAbove;
  double lo = kMass * kG, hi = 1e5;
  for (int i = 0; i < 200; ++i) {
    const double mid = std::sqrt(lo * hi);
    const double left = johnson_energy(g, mid) - kMass * kG * johnson_approach(g, mid);
    (left < target ? lo : hi) = mid;
  }
  const double deepest = johnson_approach(g, lo);
  std::printf(
      "drop on polymer: deepest %.5g um (closed form %.5g um) at %.4g N, |E - E0| "
      "%.2e of the kinetic; damped: lost %.6g J, the damper's work %.6g J\n",
      free.deepest * 1e6, deepest * 1e6, lo, free.drift / free.kinetic0, damped.lost,
      damped.damper);
  EXPECT_NEAR(free.deepest / deepest, 1.0, 1e-3);
  EXPECT_LT(free.drift, 1e-3 * free.kinetic0);
  EXPECT_EQ(free.damper, 0.0);
  EXPECT_GT(damped.lost, 0.1 * damped.kinetic0);
  EXPECT_NEAR(damped.lost, -damped.damper, 1e-3 * damped.lost);
}

// (5) The discrete gradient (Guide::discrete_gradient, the law's default; docs "Guides: the
// discrete gradient"). Over a step from x₀ to x₁ on a straight rail the gap is affine in q, so
// the elastic force's work F·(x₁ − x₀) is exactly −(E(x₁) − E(x₀)), E the contact's energy where
// the roller stands: entering from above the rail, pressing in, lifting, leaving, past the cap and
// over a step of 1e-13 m. The θ point's force misses it (by far on the entry). On an arc the gap
// is not affine, and the force acts along ν ((10)): the same identity to the gaps' rounding
// (~1e-16 ρ each: 6e-12 of ΔE on this step; along the θ point's n it missed by 1.9e-8).
TEST(DynamicsRailLineLaw, DiscreteGradientsWorkIsTheEnergysChange) {
  const Guide straight = rail(Guide::Kind::kStraight, false);
  const GuideFrame f = guide_frame(straight);
  struct Step {
    double g0, g1;  // [m] the gaps at the step's ends
  };
  const double cap = straight.line.cap_depth;
  const Step steps[] = {
      {-2e-6, 3e-6},       {1e-6, 4e-6}, {5e-6, 0.5e-6}, {2e-6, -1e-6}, {cap - 1e-4, cap + 1e-4},
      {2e-6, 2e-6 + 1e-13}};
  auto energy_at = [&](const Guide& g, double x, double y) {
    return guide_contact(g, x, y, 0.0, 0.0).energy;
  };
  double worst = 0.0, theta_worst = 0.0;
  for (const auto& [g0, g1] : steps) {
    const Touch a = touch(straight, g0, 0.5), b = touch(straight, g1, 0.5 + 1e-4);
    const double dx = b.x - a.x, dy = b.y - a.y, h = 1e-4;
    const double qx = a.x + 0.5 * dx, qy = a.y + 0.5 * dy;
    const GuideStep step{a.x, a.y, b.x, b.y, h};
    const GuideContact c = guide_contact(straight, f, qx, qy, dx / h, dy / h, NAN, &step);
    ASSERT_TRUE(c.active) << g0 << " " << g1;
    const double e0 = energy_at(straight, a.x, a.y), e1 = energy_at(straight, b.x, b.y);
    const double change = e1 - e0, work = c.fx * dx + c.fy * dy;
    // within 1e-9 of ΔE, and of the reference ΔE's own rounding, ~1e-16 of the energies (6e-9
    // of ΔE over the 1e-13 m step)
    const double err = std::abs(work + change);
    EXPECT_LE(err, 1e-9 * std::abs(change) + 1e-14 * std::max(e0, e1))
        << g0 << " -> " << g1 << ": work " << work << " dE " << change;
    if (std::abs(g1 - g0) > 1e-9) worst = std::max(worst, err / std::abs(change));
    // the θ point's force (no step) over the same displacement; inactive at the entry's θ point
    // (the gap there ≤ 0)
    const GuideContact t = guide_contact(straight, f, qx, qy, dx / h, dy / h);
    const double theta_work = t.fx * dx + t.fy * dy;
    theta_worst = std::max(theta_worst, std::abs(theta_work + change) / std::abs(change));
  }
  EXPECT_GT(theta_worst, 0.1);
  // an arc (outside, R = 0.25 m): a step of 0.1 mm along it while pressing 1 → 4 µm in
  const Guide arc = rail(Guide::Kind::kArc, false);
  const GuideFrame fa = guide_frame(arc);
  const double phi = 1.0, d0 = kArcRadius + kRoller - 1e-6, d1 = kArcRadius + kRoller - 4e-6;
  const double turn = 1e-4 / d0;
  const double x0 = d0 * std::cos(phi), y0 = d0 * std::sin(phi);
  const double x1 = d1 * std::cos(phi + turn), y1 = d1 * std::sin(phi + turn);
  const double h = 1e-4, dx = x1 - x0, dy = y1 - y0;
  const GuideStep step{x0, y0, x1, y1, h};
  const GuideContact c =
      guide_contact(arc, fa, x0 + 0.5 * dx, y0 + 0.5 * dy, dx / h, dy / h, NAN, &step);
  const double change = energy_at(arc, x1, y1) - energy_at(arc, x0, y0);
  const double arc_err = std::abs(c.fx * dx + c.fy * dy + change) / std::abs(change);
  std::printf(
      "discrete gradient: |work + dE| / |dE| worst %.2e on a straight rail (the theta point's "
      "force: %.3g); on an arc of 0.25 m, 0.1 mm along and 1 -> 4 um in: %.2e\n",
      worst, theta_worst, arc_err);
  EXPECT_LT(arc_err, 1e-10);
}

// (5b) The discrete gradient of the penalty (contact_law "penalty" with discrete_gradient set:
// through the API only, the case file sets it with the line law): over steps on a straight rail
// across the ramp's ε, past it and out of contact, the elastic force's work is −ΔE of the
// penalty's energy (penalty_ramp.hpp), kc g³/(6ε) within the ramp, kc (g²/2 − ε g/2 + ε²/6) past
// it.
TEST(DynamicsRailLineLaw, PenaltysDiscreteGradientsWorkIsTheEnergysChange) {
  Guide g = rail(Guide::Kind::kStraight, false);
  g.line_law = false;
  g.discrete_gradient = true;
  g.contact_smoothing = 1e-6;
  const double kc = g.contact_stiffness, eps = g.contact_smoothing;
  const GuideFrame f = guide_frame(g);
  auto penalty_energy = [&](double gap) { return testing::penalty_ramp_energy(kc, eps, gap); };
  struct Step {
    double g0, g1;  // [m] the gaps at the step's ends
  };
  const Step steps[] = {{-2e-6, 0.5e-6}, {0.2e-6, 0.8e-6}, {0.5e-6, 3e-6},
                        {4e-6, 1e-6},    {3e-6, -1e-6},    {2e-6, 2e-6 + 1e-13}};
  double worst = 0.0;
  for (const auto& [g0, g1] : steps) {
    const Touch a = touch(g, g0, 0.5), b = touch(g, g1, 0.5 + 1e-4);
    const double dx = b.x - a.x, dy = b.y - a.y, h = 1e-4;
    const GuideStep step{a.x, a.y, b.x, b.y, h};
    const GuideContact c =
        guide_contact(g, f, a.x + 0.5 * dx, a.y + 0.5 * dy, dx / h, dy / h, NAN, &step);
    ASSERT_TRUE(c.active) << g0 << " " << g1;
    // the gaps as the rail takes them, r − y (exact: y is within a factor 2 of r)
    const double e0 = penalty_energy(kRoller - a.y), e1 = penalty_energy(kRoller - b.y);
    const double change = e1 - e0;
    const double err = std::abs(c.fx * dx + c.fy * dy + change);
    // within 1e-9 of ΔE, and of the reference ΔE's own rounding, ~1e-16 of the energies
    EXPECT_LE(err, 1e-9 * std::abs(change) + 1e-14 * std::max(e0, e1))
        << g0 << " -> " << g1 << ": work " << c.fx * dx + c.fy * dy << " dE " << change;
    if (std::abs(g1 - g0) > 1e-9) worst = std::max(worst, err / std::abs(change));
  }
  std::printf("penalty's discrete gradient: |work + dE| / |dE| worst %.2e on a straight rail\n",
              worst);
}

// (6) A pair of undamped rollers dropped at θ = ½ onto a stiff steel rail in steps of 0.1 ms
// (the conveyor's; ω h ≈ 10 at the law's stiffness under a roller's weight): with the discrete
// gradient the energy is kept to Newton's tolerance; with the θ point's force (the law without it)
// the entry steps create energy, many times the drop's.
TEST(DynamicsRailLineLaw, DiscreteGradientKeepsADropsEnergy) {
  Guide g = rail(Guide::Kind::kStraight, false);
  ASSERT_TRUE(g.discrete_gradient);  // the law's default
  const DropRun run{.speed = 0.05, .above = 1e-5, .step = 1e-4, .steps = 400};
  const RailDrop kept = rail_drop(g, 0.0, run);
  g.discrete_gradient = false;
  const RailDrop theta = rail_drop(g, 0.0, run);
  std::printf(
      "drop on steel at 0.1 ms steps (kinetic %.3g J): |E - E0| worst %.2e of the kinetic with "
      "the discrete gradient, %.3g gained with the theta point's force\n",
      kept.kinetic0, kept.drift / kept.kinetic0, theta.gained / theta.kinetic0);
  EXPECT_LT(kept.drift, 1e-6 * kept.kinetic0);
  EXPECT_GT(theta.gained, 1.0 * theta.kinetic0);
}

// (6b) The stick law on a line-law rail (k_t = 1e6 N/m, μ = 0.3; docs "Guides: sticking"): the
// pair dropped at θ = ½ in steps of 0.1 ms from 10 µm above the rail at 0.05 m/s while sliding
// along it at 0.2 m/s, undamped: it bounces, a contact acting on the entry's and the bounces'
// steps while its θ point is above the rail (the discrete gradient's, over the step). The anchors
// are taken and the friction work booked on those steps as the force acted: the work balance
// closes, the energy lost the friction's work.
TEST(DynamicsRailLineLaw, StickLawsWorkBalanceClosesOnABouncingDrop) {
  Guide g = rail(Guide::Kind::kStraight, false);
  ASSERT_TRUE(g.discrete_gradient);
  g.friction = 0.3;
  g.stick_stiffness = 1e6;
  const DropRun run{.speed = 0.05, .above = 1e-5, .step = 1e-4, .steps = 400, .along = 0.2};
  const RailDrop d = rail_drop(g, 0.0, run);
  const double balance = -d.lost - (d.friction + d.damper);
  std::printf(
      "stick law on a line-law rail, bouncing drop at 0.1 ms steps: lost %.6g J, friction work "
      "%.6g J, balance %.2e J\n",
      d.lost, d.friction, balance);
  EXPECT_LT(d.friction, -0.1 * d.kinetic0);  // it slid and was slowed
  EXPECT_EQ(d.damper, 0.0);
  EXPECT_LT(std::abs(balance), 1e-6 * d.kinetic0);
}

// (7) The discrete gradient's Newton matrix (θ = 0.6, damping and friction) on a step where one
// roller drops in from above the rail (g₀ = −0.08 µm, g₁ = 0.02 µm: its θ point still above it,
// the force the discrete gradient's alone) and one lifts off (0.05 → −0.05 µm), on the straight
// rail and outside an arc: every column against central differences of the residual, and
// different from the θ point's matrix (which has no force at these θ points for the entering one).
TEST(DynamicsRailLineLaw, DiscreteGradientsNewtonMatrixOnEntryAndExit) {
  const double h = 1e-4;
  for (const auto& [kind, inside] :
       {std::pair{Guide::Kind::kStraight, false}, std::pair{Guide::Kind::kArc, false}}) {
    std::vector<double> jac_theta;
    for (const bool gradient : {false, true}) {
      const double g0[2] = {-0.08e-6, 0.05e-6}, g1[2] = {0.02e-6, -0.05e-6};
      RailPair pair = rail_pair(
          kind, inside, [&](Guide& g) { g.discrete_gradient = gradient; },
          [&](const Guide& g, std::size_t i, double along, State& s, std::vector<double>& u) {
            const Touch a = touch(g, g0[i], along), b = touch(g, g1[i], along);
            // sliding along the rail at 0.2 m/s besides
            s.x[i] = a.x;
            s.y[i] = a.y;
            u[2 * i] = b.x - 0.2 * h * a.ny;
            u[2 * i + 1] = b.y + 0.2 * h * a.nx;
            s.vx[i] = (u[2 * i] - s.x[i]) / h;
            s.vy[i] = (u[2 * i + 1] - s.y[i]) / h;
          });
      const Model& m = pair.model;
      const State& s = pair.start;
      const std::vector<double>& u = pair.u;
      Integrator integ(m, {.step = h, .theta = 0.6});
      ASSERT_EQ(integ.unknowns(), 4u);
      std::vector<double> r0, jac;
      integ.newton_system(m, s, u, r0, &jac);
      if (!gradient) {
        jac_theta = jac;
        continue;
      }
      const testing::ColumnsAgainstDifferences d = testing::expect_columns_match_differences(
          integ, m, s, u, jac, jac_theta, [](std::size_t) { return 1e-10; }, 1e-5);
      std::printf(
          "discrete gradient's Newton matrix on entry and exit (%s): worst |J - FD| / column "
          "scale %.2e\n",
          kind == Guide::Kind::kStraight ? "straight" : "arc", d.worst);
      EXPECT_GT(d.differs, 0.1 * d.scale);
    }
  }
}

// (8) The damper over the step (Guide::discrete_gradient; docs "Guides: the discrete gradient",
// the seats' "The damper over the step"): f_d = (C(g₁) − C(g₀))/h, C(g) = ∫₀^g c_c min(1, s/ε) ds
// (penalty_ramp.hpp). On a penalty rail (1e7 N/m, ε = 1 µm, c_c = 200 N s/m, h = 0.1 ms) over
// steps entering from 2 µm above, pressing within the ramp and past it, lifting, leaving within
// the ramp and out of contact: the contact's work on the roller is −ΔE − (C(g₁) − C(g₀)) Δg/h, the
// damper's share is never positive and `damping_power` h books it. Straight (exact to rounding)
// and outside an arc (R = 0.25 m, 0.1 mm along it: the force along ν, (10); the gaps here written
// out with hypot, within an ulp of ρ of the rail's, 2.6e-10 of the step's work at 0.6 µm of Δg;
// along the θ point's n 1.5e-9). A step leaving fast clamps the force at 0: no work, the damper's
// share f_e Δg ≤ 0. The θ point's damper (c(g_θ) ġ_θ) misses the identity.
TEST(DynamicsRailLineLaw, DamperOverTheStepWorkIsNeverPositive) {
  constexpr double kDamper = 200.0, kH = 1e-4;
  struct Step {
    double g0, g1;  // [m] the gaps at the step's ends
  };
  const Step steps[] = {{-2e-6, 0.5e-6}, {0.2e-6, 0.8e-6}, {0.3e-6, 2.5e-6}, {1e-6, 4e-6},
                        {4e-6, 1.5e-6},  {0.8e-6, 0.2e-6}, {2e-6, 0.6e-6},   {3e-6, -1e-6}};
  for (const auto& [kind, tolerance] :
       {std::pair{Guide::Kind::kStraight, 1e-9}, std::pair{Guide::Kind::kArc, 1e-9}}) {
    Guide g = rail(kind, false);
    g.line_law = false;
    g.discrete_gradient = true;
    g.contact_smoothing = 1e-6;
    g.contact_damping = kDamper;
    const double kc = g.contact_stiffness, eps = g.contact_smoothing;
    const GuideFrame f = guide_frame(g);
    auto penalty_energy = [&](double gap) { return testing::penalty_ramp_energy(kc, eps, gap); };
    auto damper_potential = [&](double gap) {  // C(g)
      return testing::penalty_ramp_force(kDamper, eps, gap);
    };
    // the gap as the rail takes it: r − y on the straight rail, R + r − |q| outside the arc
    auto gap_at = [&](const Touch& t) {
      return kind == Guide::Kind::kStraight ? kRoller - t.y
                                            : kArcRadius + kRoller - std::hypot(t.x, t.y);
    };
    double worst = 0.0, theta_worst = 0.0;
    for (const auto& [g0, g1] : steps) {
      const double along = kind == Guide::Kind::kStraight ? 1e-4 : 1e-4 / (g.end_angle - 0.2);
      const Touch a = touch(g, g0, 0.5), b = touch(g, g1, 0.5 + along);
      const double dx = b.x - a.x, dy = b.y - a.y;
      const double qx = a.x + 0.5 * dx, qy = a.y + 0.5 * dy;
      const GuideStep step{a.x, a.y, b.x, b.y, kH};
      const GuideContact c = guide_contact(g, f, qx, qy, dx / kH, dy / kH, NAN, &step);
      ASSERT_TRUE(c.active) << g0 << " -> " << g1;
      const double e0 = penalty_energy(gap_at(a)), e1 = penalty_energy(gap_at(b));
      const double dg = gap_at(b) - gap_at(a);
      const double share = -(damper_potential(gap_at(b)) - damper_potential(gap_at(a))) * dg / kH;
      const double work = c.fx * dx + c.fy * dy, expected = -(e1 - e0) + share;
      const double scale = std::abs(e1 - e0) + std::abs(share);
      EXPECT_LE(share, 0.0) << g0 << " -> " << g1;
      EXPECT_NEAR(work, expected, tolerance * scale) << g0 << " -> " << g1;
      EXPECT_NEAR(c.damping_power * kH, share, 1e-9 * scale) << g0 << " -> " << g1;
      worst = std::max(worst, std::abs(work - expected) / scale);
      // the θ point's force and damper (the rail without the key) over the same displacement
      Guide theta = g;
      theta.discrete_gradient = false;
      const GuideContact t = guide_contact(theta, f, qx, qy, dx / kH, dy / kH, NAN, &step);
      theta_worst = std::max(theta_worst, std::abs(t.fx * dx + t.fy * dy - expected) / scale);
    }
    std::printf(
        "rail damper over the step (%s): |work - (-dE + damper's)| / scale worst %.2e (the theta "
        "point's damper: %.3g)\n",
        kind == Guide::Kind::kStraight ? "straight" : "arc", worst, theta_worst);
    EXPECT_GT(theta_worst, 0.1);
    if (kind != Guide::Kind::kStraight) continue;
    // leaving fast within the ramp: f_e + f_d < 0, clamped; no force, the damper's share f_e Δg
    const Touch a = touch(g, 0.5e-6, 0.5), b = touch(g, -1e-6, 0.5);
    const double dx = b.x - a.x, dy = b.y - a.y;
    const GuideStep step{a.x, a.y, b.x, b.y, kH};
    const GuideContact c =
        guide_contact(g, f, a.x + 0.5 * dx, a.y + 0.5 * dy, dx / kH, dy / kH, NAN, &step);
    ASSERT_TRUE(c.active);
    EXPECT_EQ(c.normal_force, 0.0);
    EXPECT_EQ(c.fx * dx + c.fy * dy, 0.0);
    const double fe = penalty_energy(gap_at(a)) / (gap_at(a) - gap_at(b));
    EXPECT_LT(c.damping_power, 0.0);
    EXPECT_NEAR(c.damping_power * kH, fe * (gap_at(b) - gap_at(a)),
                1e-9 * penalty_energy(gap_at(a)));
  }
}

// (9) A damped rail at θ = ½ with the discrete gradient (the damper over the step): two linked
// rollers rattling between two parallel rails 20 µm apart (a lower one under them, an upper one
// facing down), sliding along at 0.2 m/s with μ = 0.3, thrown across at ±0.3 m/s under gravity,
// c_c = 800 N s/m on both, 0.1 ms steps over 40 ms, on the penalty (1e7 N/m) and on the line law:
// every step converges and the work balance closes, ΔE = the dampers' + the friction's work, to
// 1e-6 of the kinetic energy; the dampers take most of the energy. On the line law a bounce lasts
// less than a step, its θ point mostly above the rail: the θ point's damper, ramped by the θ
// point's gap, let most of it through (−2.0e-4 J of the 3.1e-3 J kinetic, measured).
TEST(DynamicsRailLineLaw, DampedRailsAtThetaHalfConvergeAndKeepTheirWorkBalance) {
  for (const bool line : {false, true}) {
    Guide lower = rail(Guide::Kind::kStraight, false);
    lower.line_law = line;
    lower.discrete_gradient = true;
    lower.friction = 0.3;
    lower.contact_damping = 800.0;
    Guide upper = lower;  // its free side down (the left normal of x0 → x1 = −x)
    upper.x0 = 0.5;
    upper.x1 = -0.5;
    upper.y0 = upper.y1 = 2.0 * kRoller + 20e-6;
    Model m = uniform_chain(2, false, kPitch, kMass, 5e7, 0.0, false);
    m.gravity_y = -9.81;
    m.guides = {lower, upper};
    State s(2, 0);
    for (std::size_t i = 0; i < 2; ++i) {
      s.x[i] = kPitch * static_cast<double>(i);
      s.y[i] = kRoller + 10e-6;
      s.vx[i] = 0.2;
      s.vy[i] = i == 0 ? 0.3 : -0.3;
    }
    const Energy e0 = energy(m, s);
    Integrator integ(m, {.step = 1e-4, .theta = 0.5});
    int iterations = 0, halvings = 0;
    for (int k = 0; k < 400; ++k) {
      const StepReport r = integ.step(m, s);
      ASSERT_TRUE(r.converged) << (line ? "line law" : "penalty") << ": step " << k;
      iterations += r.iterations;
      halvings += r.backtracks;
    }
    const double change = energy(m, s).total() - e0.total();
    const double balance = change - s.contact_damping_work - s.friction_work;
    std::printf(
        "damped rails at theta = 1/2 (%s): dE %.6g J, dampers %.6g J, friction %.6g J, balance "
        "%.2e J (kinetic %.3g J); %d Newton iterations, %d halvings\n",
        line ? "line law" : "penalty", change, s.contact_damping_work, s.friction_work, balance,
        e0.kinetic, iterations, halvings);
    EXPECT_LT(std::abs(balance), 1e-6 * e0.kinetic);
    EXPECT_LT(s.contact_damping_work, -0.3 * e0.kinetic);
    EXPECT_LT(s.friction_work, 0.0);
  }
}

// (10) On an arc the gap is a function of ρ = |q − C| alone and the discrete gradient's normal
// force f acts along ν = s (q_θ − C)/ρ̄, ρ̄ = (ρ₀ + ρ₁)/2 (docs "Guides: the discrete gradient",
// "On an arc"): at θ = ½ ν·(x₁ − x₀) = s (ρ₁² − ρ₀²)/(ρ₀ + ρ₁) = −Δg, so its work over the step is
// −ΔE plus the damper's share −f_d Δg, to rounding: outside and inside an arc of 0.25 m, on the
// line law and on the penalty with its ramp (ε = 1 µm) and damper (200 N s/m), over steps entering
// from 2 µm above, across the ramp, pressing, lifting and leaving, 0.1 mm and 5 mm along the arc.
// ΔE is the contact's energy as the library reports it at the ends (what the integrator's energy
// sums; the gaps' own rounding, ~1e-17 m at 0.25 m, is not the identity's); the damper's share
// `damping_power` h, checked against C written out here. Along the θ point's n (the force before)
// the work misses by about (Δφ)²/8 of it, Δφ the step's turn. At θ = 0.6 the miss is
// s f (θ − ½)|Δx|²/ρ̄ (q_θ − C = (r₀ + r₁)/2 + (θ − ½) Δx), checked to rounding.
TEST(DynamicsRailLineLaw, ArcDiscreteGradientsWorkIsTheEnergysChange) {
  constexpr double kH = 1e-4, kDamper = 200.0;
  struct Step {
    double g0, g1;  // [m] the gaps at the step's ends
  };
  const Step steps[] = {{-2e-6, 0.5e-6}, {0.2e-6, 0.8e-6}, {0.3e-6, 2.5e-6}, {1e-6, 4e-6},
                        {4e-6, 1.5e-6},  {0.8e-6, 0.2e-6}, {2e-6, 0.6e-6},   {3e-6, -1e-6}};
  constexpr double kEps = std::numeric_limits<double>::epsilon();
  double worst = 0.0, worst_ulps = 0.0, worst_theta = 0.0;
  double theta_point_slow = 0.0, theta_point_fast = 0.0;
  for (const bool inside : {false, true}) {
    for (const bool line : {true, false}) {
      Guide g = rail(Guide::Kind::kArc, inside);
      if (!line) {
        g.line_law = false;
        g.contact_smoothing = 1e-6;
        g.contact_damping = kDamper;
      }
      ASSERT_TRUE(g.discrete_gradient);
      const GuideFrame f = guide_frame(g);
      const double sgn = inside ? -1.0 : 1.0;
      auto radius = [](const Touch& t) { return std::sqrt(t.x * t.x + t.y * t.y); };
      auto gap = [&](const Touch& t) {  // written out: R + r − ρ outside, ρ − (R − r) inside
        return inside ? radius(t) - (kArcRadius - kRoller) : kArcRadius + kRoller - radius(t);
      };
      for (const double along : {1e-4, 5e-3}) {
        for (const auto& [g0, g1] : steps) {
          const Touch a = touch(g, g0, 0.5);
          const Touch b = touch(g, g1, 0.5 + along / (kArcRadius * (g.end_angle - g.start_angle)));
          const double dx = b.x - a.x, dy = b.y - a.y;
          const GuideStep step{a.x, a.y, b.x, b.y, kH};
          const double e0 = guide_contact(g, a.x, a.y, 0.0, 0.0).energy;
          const double e1 = guide_contact(g, b.x, b.y, 0.0, 0.0).energy;
          for (const double theta : {0.5, 0.6}) {
            const double qx = a.x + theta * dx, qy = a.y + theta * dy;
            const GuideContact c = guide_contact(g, f, qx, qy, dx / kH, dy / kH, NAN, &step);
            ASSERT_TRUE(c.active) << g0 << " -> " << g1;
            const double share = c.damping_power * kH;
            const double scale = std::abs(e1 - e0) + std::abs(share);
            // the damper's share against C written out (the gaps' rounding: 1e-9)
            const double written =
                line ? 0.0
                     : -(testing::penalty_ramp_force(kDamper, g.contact_smoothing, gap(b)) -
                         testing::penalty_ramp_force(kDamper, g.contact_smoothing, gap(a))) *
                           (gap(b) - gap(a)) / kH;
            // (where f is clamped at 0 the share is f_e Δg, also ≤ 0)
            if (c.normal_force > 0.0) {
              EXPECT_NEAR(share, written, 1e-9 * scale);
            }
            EXPECT_LE(share, 0.0);
            const double work = c.fx * dx + c.fy * dy, expected = -(e1 - e0) + share;
            // the gaps' rounding: each within a few ulps of ρ (f ε ρ of work), the rest 1e-14
            const double floor = c.normal_force * kEps * radius(a);
            const double tolerance = 1e-14 * scale + 8.0 * floor;
            if (theta == 0.5) {
              EXPECT_NEAR(work, expected, tolerance)
                  << (inside ? "inside " : "outside ") << (line ? "line law " : "penalty ") << g0
                  << " -> " << g1 << " along " << along;
              worst = std::max(worst, std::abs(work - expected) / scale);
              if (floor > 0.0) worst_ulps = std::max(worst_ulps, std::abs(work - expected) / floor);
              const double before = c.normal_force * (c.nx * dx + c.ny * dy);
              double& miss = along < 1e-3 ? theta_point_slow : theta_point_fast;
              miss = std::max(miss, std::abs(before - expected) / scale);
              continue;
            }
            const double mean = 0.5 * (radius(a) + radius(b));
            const double off = sgn * c.normal_force * (theta - 0.5) * (dx * dx + dy * dy) / mean;
            EXPECT_NEAR(work - expected, off, tolerance) << g0 << " -> " << g1;
            worst_theta = std::max(worst_theta, std::abs(work - expected - off) / scale);
          }
        }
      }
    }
  }
  std::printf(
      "arc's discrete gradient at theta = 1/2: |work - (-dE + damper's)| / scale worst %.2e, "
      "%.2f f eps rho (along the theta point's n: %.2e at 0.1 mm, %.2e at 5 mm); at theta = 0.6 "
      "the miss is s f (theta - 1/2)|dx|^2/rho to %.2e\n",
      worst, worst_ulps, theta_point_slow, theta_point_fast, worst_theta);
  EXPECT_GT(theta_point_slow, 1e-10);
  EXPECT_GT(theta_point_fast, 1e-6);
}

// The soft penalty arc of (11) and (12): 5 cm, the penalty with the discrete gradient (1e4 N/m,
// ε = 0.5 mm, 5 N s/m, μ = 0.3), the rollers outside or inside it
Guide soft_arc(bool inside) {
  Guide g = rail(Guide::Kind::kArc, inside);
  g.radius = 0.05;
  g.line_law = false;
  g.discrete_gradient = true;
  g.contact_stiffness = 1e4;
  g.contact_smoothing = 0.5e-3;
  g.contact_damping = 5.0;
  g.friction = 0.3;
  return g;
}

// (11) The arc's discrete gradient's blocks at the contact: dq = ∂F/∂q_θ (ν's turn, bend I with
// bend = s/ρ̄, besides the friction's t turning) and dv = ∂F/∂v with x₁ = x₀ + h v (f through g₁,
// ν through ρ₁ in ρ̄, the friction), against central differences of the contact's force, outside
// and inside a 5 cm arc, θ = ½ and 0.6. A soft penalty (1e4 N/m, ε = 0.5 mm, 5 N s/m, μ = 0.3,
// pressed 1 → 2 mm in over 2 mm along in 1 ms) makes f/ρ̄ a large part of the blocks: the θ point's
// f κ t tᵀ in place of f bend I misses dq's n n entry by all of it, and dv without ν's −(bend/2)
// ν ⊗ n₁ misses by ~1 % of its column.
TEST(DynamicsRailLineLaw, ArcDiscreteGradientsBlocksMatchDifferences) {
  constexpr double kH = 1e-3;
  double worst = 0.0;
  for (const bool inside : {false, true}) {
    const Guide g = soft_arc(inside);
    const GuideFrame f = guide_frame(g);
    const Touch a = touch(g, 1e-3, 0.5);
    const Touch b = touch(g, 2e-3, 0.5 + 2e-3 / (g.radius * (g.end_angle - g.start_angle)));
    const double vx = (b.x - a.x) / kH, vy = (b.y - a.y) / kH;
    for (const double theta : {0.5, 0.6}) {
      // the force at the θ point (qx, qy), velocity (wx, wy), the step's end x₀ + h w
      auto force = [&](double qx, double qy, double wx, double wy) {
        const GuideStep step{a.x, a.y, a.x + kH * wx, a.y + kH * wy, kH};
        const GuideContact c = guide_contact(g, f, qx, qy, wx, wy, NAN, &step);
        EXPECT_GT(c.normal_force, 0.0);
        return std::pair{c.fx, c.fy};
      };
      const double qx = a.x + theta * (b.x - a.x), qy = a.y + theta * (b.y - a.y);
      const GuideStep step{a.x, a.y, a.x + kH * vx, a.y + kH * vy, kH};
      const GuideContact c = guide_contact(g, f, qx, qy, vx, vy, NAN, &step);
      for (const bool velocity : {false, true}) {
        const double e = velocity ? 1e-6 : 1e-9;  // [m/s], [m]: x₁ or q_θ moved by 1e-9 m
        const double* block = velocity ? c.dv : c.dq;
        for (int col = 0; col < 2; ++col) {
          const double ex = col == 0 ? e : 0.0, ey = col == 0 ? 0.0 : e;
          const auto [px, py] =
              velocity ? force(qx, qy, vx + ex, vy + ey) : force(qx + ex, qy + ey, vx, vy);
          const auto [mx, my] =
              velocity ? force(qx, qy, vx - ex, vy - ey) : force(qx - ex, qy - ey, vx, vy);
          const double fd[2] = {(px - mx) / (2 * e), (py - my) / (2 * e)};
          const double scale = std::max(std::abs(fd[0]), std::abs(fd[1]));
          for (int row = 0; row < 2; ++row) {
            EXPECT_NEAR(block[2 * row + col], fd[row], 1e-6 * scale)
                << (inside ? "inside" : "outside") << " theta " << theta
                << (velocity ? " dv" : " dq") << " row " << row << " column " << col;
            worst = std::max(worst, std::abs(block[2 * row + col] - fd[row]) / scale);
          }
        }
      }
    }
  }
  std::printf("arc's discrete gradient's blocks: worst |block - FD| / column scale %.2e\n", worst);
}

// (12) The arc's blocks in the step's Newton matrix (residual_difference.hpp): two softly linked
// rollers (1e3 N/m) pressed 1 and 2 mm into the soft penalty arc of (11) (5 cm, outside and
// inside) moving along it at 1 m/s and into it, 1 ms steps at θ = ½ and 0.6: every column against
// central differences of the step's residual. The blocks f bend I and −(bend/2) ν ⊗ n₁ of (11) are
// checked through the integrator's assembly.
TEST(DynamicsRailLineLaw, ArcDiscreteGradientsNewtonMatrix) {
  constexpr double kH = 1e-3;
  for (const bool inside : {false, true}) {
    for (const double theta : {0.5, 0.6}) {
      const Guide g = soft_arc(inside);
      Model m = uniform_chain(2, false, kPitch, kMass, 1e3, 0.0, false);
      m.guides = {g};
      State s(2, 0);
      std::vector<double> u(4);
      for (std::size_t i = 0; i < 2; ++i) {
        const double along = 0.5 + 0.15 * static_cast<double>(i);
        const Touch t = touch(g, 1e-3 * static_cast<double>(i + 1), along);
        s.x[i] = t.x;
        s.y[i] = t.y;
        s.vx[i] = -1.0 * t.ny - 0.5 * t.nx;  // along t and into the rail (−n)
        s.vy[i] = 1.0 * t.nx - 0.5 * t.ny;
        u[2 * i] = s.x[i] + kH * s.vx[i];
        u[2 * i + 1] = s.y[i] + kH * s.vy[i];
      }
      Integrator integ(m, {.step = kH, .theta = theta});
      ASSERT_EQ(integ.unknowns(), 4u);
      std::vector<double> r0, jac;
      integ.newton_system(m, s, u, r0, &jac);
      const testing::ColumnsAgainstDifferences d = testing::expect_columns_match_differences(
          integ, m, s, u, jac, {}, [](std::size_t) { return 1e-9; }, 1e-7);
      std::printf(
          "arc's discrete gradient in the Newton matrix (%s, theta %.1f): worst |J - FD| / column "
          "scale %.2e\n",
          inside ? "inside" : "outside", theta, d.worst);
    }
  }
}

// (13) A run on arcs at θ = ½: two linked 12B rollers going round at 3 m/s in a channel between
// two concentric arcs 20 µm wider than the roller (an outside arc of 5 cm under them, an inside
// one over them), thrown across it at ±0.3 m/s, damped (800 N s/m) with friction μ = 0.3, in
// 0.2 ms steps over 40 ms (a turn of Δφ ≈ 0.01 a step), on the penalty (1e7 N/m) and the line
// law: the work balance, ΔE = the dampers' + the friction's work, closes to the Newton tolerance's
// level (held at 1e-11 of the kinetic energy). Along the θ point's n (before) each contact step
// missed (Δφ)²/8 of its |ΔE| + |damper's|.
TEST(DynamicsRailLineLaw, ArcRailsAtThetaHalfKeepTheirWorkBalance) {
  constexpr double kR = 0.05, kSpeed = 3.0;
  for (const bool line : {false, true}) {
    Guide under = rail(Guide::Kind::kArc, false);
    under.radius = kR;
    under.start_angle = 0.0;
    under.end_angle = 2.0 * kPi;
    if (line) {
      use_line_law(under, kWidth);
    } else {
      under.line_law = false;
      under.discrete_gradient = true;
    }
    under.friction = 0.3;
    under.contact_damping = 800.0;
    Guide over = under;  // the rollers inside it
    over.inside = true;
    over.radius = kR + 2.0 * kRoller + 20e-6;
    if (line) use_line_law(over, kWidth);
    Model m = uniform_chain(2, false, kPitch, kMass, 5e7, 0.0, false);
    m.guides = {under, over};
    State s(2, 0);
    const double rho = kR + kRoller + 10e-6;
    for (std::size_t i = 0; i < 2; ++i) {
      const double phi = 0.3 + 2.0 * std::asin(0.5 * kPitch / rho) * static_cast<double>(i);
      const double across = i == 0 ? 0.3 : -0.3;
      s.x[i] = rho * std::cos(phi);
      s.y[i] = rho * std::sin(phi);
      s.vx[i] = -kSpeed * std::sin(phi) + across * std::cos(phi);
      s.vy[i] = kSpeed * std::cos(phi) + across * std::sin(phi);
    }
    const Energy e0 = energy(m, s);
    Integrator integ(m, {.step = 2e-4, .tolerance = 1e-13, .theta = 0.5});
    for (int k = 0; k < 200; ++k) {
      const StepReport r = integ.step(m, s);
      ASSERT_TRUE(r.converged) << (line ? "line law" : "penalty") << ": step " << k;
    }
    const double change = energy(m, s).total() - e0.total();
    const double balance = change - s.contact_damping_work - s.friction_work;
    std::printf(
        "arc channel at theta = 1/2 (%s): dE %.6g J, dampers %.6g J, friction %.6g J, balance "
        "%.2e J (kinetic %.3g J)\n",
        line ? "line law" : "penalty", change, s.contact_damping_work, s.friction_work, balance,
        e0.kinetic);
    EXPECT_LT(std::abs(balance), 1e-11 * e0.kinetic);
    EXPECT_LT(s.contact_damping_work, -1e-3 * e0.kinetic);
    EXPECT_LT(s.friction_work, -1e-3 * e0.kinetic);
  }
}

// (14) A step whose ends are both at the arc's centre (ρ₀ + ρ₁ = 0, ρ̄ = 0: ν = s (q_θ − C)/ρ̄ has
// no direction) with the θ point off it, as a caller other than the integrator may pass (its θ
// point lies on the segment x₀x₁): the force keeps the θ point's n, finite, on the penalty (the
// gaps at the centre R + r) and with the line law.
TEST(DynamicsRailLineLaw, ArcStepWithBothEndsAtTheCentreKeepsTheNormal) {
  for (const bool line : {false, true}) {
    Guide g = rail(Guide::Kind::kArc, false);
    if (!line) {
      g.line_law = false;
      g.discrete_gradient = true;
    }
    const GuideStep step{0.0, 0.0, 0.0, 0.0, 1e-4};  // the arc's centre is the origin
    const double rho = kArcRadius + kRoller - 1e-6, phi = 1.0;
    const double qx = rho * std::cos(phi), qy = rho * std::sin(phi);
    const GuideContact c = guide_contact(g, guide_frame(g), qx, qy, 0.0, 0.0, NAN, &step);
    const char* law = line ? "line law" : "penalty";
    ASSERT_TRUE(c.active) << law;
    ASSERT_TRUE(std::isfinite(c.fx) && std::isfinite(c.fy)) << law << ": " << c.fx << ", " << c.fy;
    EXPECT_GT(c.normal_force, 0.0) << law;
    EXPECT_DOUBLE_EQ(c.fx, c.normal_force * c.nx) << law;
    EXPECT_DOUBLE_EQ(c.fy, c.normal_force * c.ny) << law;
    EXPECT_NEAR(c.nx, std::cos(phi), 1e-12) << law;
    EXPECT_NEAR(c.ny, std::sin(phi), 1e-12) << law;
    for (int i = 0; i < 4; ++i) {
      EXPECT_TRUE(std::isfinite(c.dq[i]) && std::isfinite(c.dv[i])) << law << " " << i;
    }
  }
}

}  // namespace
}  // namespace catena::dynamics
