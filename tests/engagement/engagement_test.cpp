// Engagement forces (seed 000 §1.6): residuals, the frictionless polygon from independent statics,
// limits, monotonicity, and invalid input.
#include "catena/engagement/engagement.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "catena/hinge/kinematics.hpp"
#include "catena/hinge/synthesis.hpp"

namespace catena::engagement {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kResidualTol = 1e-9;   // [1] equilibrium residual, relative to F1
constexpr double kRelForceTol = 1e-9;   // [1] forces compared relative to F1
constexpr double kRelMomentTol = 1e-9;  // [1] moments compared relative to F1 times a length
constexpr double kAngleTol = 1e-9;      // [rad]
constexpr double kTensionTol = 1e-9;    // [N] tensions of ~3e4 N along the wrap: round-off

constexpr double kR2 = 0.0627597756933;  // [m] eq. (6) for the test hinge (hinge CLI)

double deg(double d) { return d * kPi / 180.0; }

hinge::Hinge thesis_hinge() {
  hinge::Hinge h;  // d, a chosen (examples/000_thesis_rolling_hinge.toml); R1, R2 conclusion 7
  h.pin_diameter = 0.040;
  h.half_thickness = 0.008;
  h.plate_radius = 0.015;  // the thesis' R1 = 34 mm, R2 = 35.4 mm exceed R1max for d = 40 mm
  h.roller_radius = 0.0;   // eq. (6): R2 = 62.76 mm
  h.teeth = 8;
  h.strokes = 2;
  return h;
}

RollingInput rolling(double flank = 0.0, double cr = 1e-3) {
  RollingInput in;
  in.hinge = thesis_hinge();
  in.tension = 29.4e3;
  in.flank_angle = flank;
  in.rolling_coefficient = cr;
  return in;
}

SlidingInput sliding(double f = 0.15, double flank = 0.0) {
  SlidingInput in;
  in.tension = 29.4e3;
  in.teeth = 8;
  in.strokes = 2;
  in.friction = f;
  in.flank_angle = flank;
  in.journal_diameter = 0.040;
  in.tooth_diameter = 0.060;
  return in;
}

// Plain statics of the seated roller P0 on the sprocket polygon (independent of the module's
// frame): vertices on the pitch circle R = t/(2 sin(γΣ/2)), link 2 to the engaged roller P−1,
// link 1 turned by γ from the straight extension of link 2 towards P+1, the tooth normal the
// outward radius tilted by ψ towards the motion (P+1 → P0 → P−1). Returns {F2, N}.
struct Polygon {
  double f2, n;
};
Polygon polygon_forces(double f1, int z, int m, double psi, double gamma) {
  const double gs = 2.0 * kPi * m / z;
  const double t = 1.0, r = t / (2.0 * std::sin(0.5 * gs));
  const double p0x = r, p0y = 0.0;
  const double pmx = r * std::cos(gs), pmy = -r * std::sin(gs);
  const double ux = (p0x - pmx) / t, uy = (p0y - pmy) / t;
  const double d1x = ux * std::cos(gamma) - uy * std::sin(gamma);
  const double d1y = ux * std::sin(gamma) + uy * std::cos(gamma);
  const double d2x = -ux, d2y = -uy;
  const double nx = std::cos(psi), ny = -std::sin(psi);
  // F2 d2 + N n = −F1 d1 (Cramer)
  const double det = d2x * ny - nx * d2y;
  return {(-f1 * d1x * ny + nx * f1 * d1y) / det, (d2x * (-f1 * d1y) + f1 * d1x * d2y) / det};
}

TEST(EngagementAngles, ReconstructionOfFigure25) {
  const Angles a = angles(8, 2, deg(10));
  EXPECT_NEAR(a.gamma_sigma, deg(90), kAngleTol);
  EXPECT_NEAR(a.alpha, deg(45), kAngleTol);
  EXPECT_NEAR(a.theta, deg(125), kAngleTol);
  EXPECT_NEAR(a.epsilon, deg(35), kAngleTol);
  EXPECT_NEAR(a.beta1, deg(55), kAngleTol);
  EXPECT_NEAR(epsilon_at(a, 0.0), a.theta, kAngleTol);  // γ = 0: F1, F2 symmetric about N
  EXPECT_NEAR(beta1_at(a, 0.0), deg(-35), kAngleTol);
}

TEST(EngagementSliding, FrictionlessIsThePolygonFromIndependentStatics) {
  for (int z : {6, 8, 12, 21}) {
    for (int m : {1, 2}) {
      if (2 * m >= z) continue;
      for (double psi : {0.0, deg(5), deg(-5), deg(20)}) {
        SlidingInput in = sliding(0.0, psi);
        in.teeth = z, in.strokes = m;
        const Result r = solve_sliding(in);
        for (const Sample& s : r.series) {
          const Polygon p = polygon_forces(in.tension, z, m, psi, s.gamma);
          EXPECT_NEAR(s.f2, p.f2, kRelForceTol * in.tension) << z << " " << m << " " << s.gamma;
          EXPECT_NEAR(s.fn, p.n, kRelForceTol * in.tension) << z << " " << m << " " << s.gamma;
        }
        EXPECT_NEAR(r.series.front().f2, in.tension, kRelForceTol * in.tension);
        EXPECT_NEAR(r.series.front().fn, 0.0, kRelForceTol * in.tension);
      }
    }
  }
}

TEST(EngagementSliding, ResidualsAndFrictionLimit) {
  const Result r = solve_sliding(sliding());
  EXPECT_LE(r.max_residual, kResidualTol);
  // at γ = 0 (ε = θ) friction shifts F2 by −f1·cot θ·F1 and N starts at f1·F1/sin θ
  const Angles& a = r.angles;
  EXPECT_NEAR(r.series.front().f2, 29.4e3 * (1.0 - 0.15 / std::tan(a.theta)),
              kRelForceTol * 29.4e3);
  EXPECT_NEAR(r.series.front().fn, 29.4e3 * 0.15 / std::sin(a.theta), kRelForceTol * 29.4e3);
  // friction → 0: continuous towards the polygon
  constexpr double kForceTol = 1e-6;  // [N] f1 = 1e-12 moves F2 by ~3e-8 N
  const Result small = solve_sliding(sliding(1e-12));
  EXPECT_NEAR(small.series.front().f2, 29.4e3, kForceTol);
}

// F2 falls over the whole engagement when ε(0) = θ ≤ 90°, i.e. ψ ≥ γΣ/2 (z = 12, m = 2: 30°)
TEST(EngagementSliding, ForcesMonotoneOverTheEngagement) {
  for (double psi : {deg(30), deg(35), deg(40)}) {
    SlidingInput in = sliding(0.15, psi);
    in.teeth = 12;
    const Result r = solve_sliding(in);
    for (std::size_t i = 1; i < r.series.size(); ++i) {
      EXPECT_LT(r.series[i].f2, r.series[i - 1].f2);
      EXPECT_GT(r.series[i].fn, r.series[i - 1].fn);
    }
  }
}

TEST(EngagementSliding, RollerTurnsWhereCriterion25Holds) {
  SlidingInput in = sliding();
  const Result r = solve_sliding(in);
  for (const Sample& s : r.series) {
    const double lhs = in.friction * in.tension * in.journal_diameter / 2;  // eq. (25) left
    const double rhs =
        in.friction * s.f2 * in.journal_diameter / 2 + in.friction * s.fn * in.tooth_diameter / 2;
    EXPECT_EQ(s.roller_turns, lhs > rhs);
    bool inside = false;
    for (const Range& g : r.roller_turns) inside = inside || (s.gamma >= g.from && s.gamma <= g.to);
    EXPECT_EQ(inside, s.roller_turns) << s.gamma;
  }
  // a tiny tooth diameter lets the roller turn over the whole engagement
  in.tooth_diameter = 1e-4;
  const Result all = solve_sliding(in);
  // … from where F2 drops below F1 (before that F1 − F2 < 0 cannot beat the braking moments)
  ASSERT_EQ(all.roller_turns.size(), 1u);
  EXPECT_NEAR(all.roller_turns[0].to, all.angles.gamma_sigma, kAngleTol);
  in.tooth_diameter = 0.0;  // not valid input; used only to locate F2 = F1 through the margin
  const double from = all.roller_turns[0].from;
  const Angles& a = all.angles;
  const double f2_at_from = in.tension *
                            (std::sin(epsilon_at(a, from)) - 0.15 * std::cos(epsilon_at(a, from))) /
                            std::sin(a.theta);
  constexpr double kGridRelTol = 0.01;  // [1] relative: `from` is a γ sample, not the crossing
  EXPECT_NEAR(f2_at_from, in.tension, kGridRelTol * in.tension);
}

TEST(EngagementSliding, LargeFrictionIsDiagnosedNotThrown) {
  // f1 = 1 (the largest valid since issue 18) > tan ε(γΣ) = tan(45° − ψ) = 0.70 with ψ = 10°
  const Result r = solve_sliding(sliding(1.0, deg(10)));
  ASSERT_FALSE(r.diagnostics.empty());
  EXPECT_EQ(r.diagnostics[0].code, "engagement.link2_slack");
}

// The residual re-derives the senses of the rolling resistances from the contact positions (not
// from the solver's choice): with the senses Catena used before (both along −t) it is ~4e-3.
TEST(EngagementRolling, ResidualsOfSystem28) {
  for (double psi : {0.0, deg(10), deg(21)}) {
    for (double cr : {0.0, 1e-3, 1e-2}) {
      RollingInput in = rolling(psi, cr);
      in.tooth_arm = cr * 0.02;
      const Result r = solve_rolling(in);
      for (const Sample& s : r.series) ASSERT_FALSE(std::isnan(s.xi)) << s.gamma;
      EXPECT_LE(r.max_residual, kResidualTol) << psi << " " << cr;
    }
  }
}

TEST(EngagementRolling, FrictionlessForcesAreThePolygonAndXiBalancesTheLevers) {
  for (double psi : {0.0, deg(10), deg(21)}) {
    const RollingInput in = rolling(psi, 0.0);
    const Result r = solve_rolling(in);
    for (const Sample& s : r.series) {
      const Polygon p = polygon_forces(in.tension, 8, 2, psi, s.gamma);
      EXPECT_NEAR(s.f2, p.f2, kRelForceTol * in.tension);
      EXPECT_NEAR(s.fn, p.n, kRelForceTol * in.tension);
      // moments straight from the hinge model's pose: F1·e(ξ) = F2·e(γ − ξ)
      auto e = [&](double th) {
        const hinge::Pose q = hinge::pose(in.hinge, kR2, 2.0 * th);
        return q.contact.y - q.centre.y;
      };
      EXPECT_NEAR(in.tension * e(s.xi), s.f2 * e(s.gamma - s.xi),
                  kRelMomentTol * in.tension * 0.008);
      // F2 ≤ F1 ⇒ ξ ≤ γ/2 while the lever e grows with the turn (it peaks near 34° here)
      auto rising = [&](double th) { return e(th + 1e-6) > e(th); };
      if (s.f2 <= in.tension && rising(s.xi) && rising(s.gamma - s.xi)) {
        EXPECT_LE(s.xi, 0.5 * s.gamma + kAngleTol);
      }
    }
    EXPECT_NEAR(r.series.front().xi, 0.0, kAngleTol);
    EXPECT_NEAR(r.series.front().f2, in.tension, kRelForceTol * in.tension);
  }
}

TEST(EngagementRolling, MonotoneWithAForwardFlank) {
  RollingInput in = rolling(deg(35));
  in.hinge.teeth = 12;  // ψ ≥ γΣ/2 = 30°
  const Result r = solve_rolling(in);
  for (std::size_t i = 1; i < r.series.size(); ++i) {
    EXPECT_LT(r.series[i].f2, r.series[i - 1].f2);
    EXPECT_GT(r.series[i].fn, r.series[i - 1].fn);
  }
  // ξ is not claimed monotone: past the peak of the lever e(θ) it turns back (docs)
}

TEST(EngagementRolling, RandomInputsNoNanAndBounded) {
  std::mt19937 rng(6);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int solved = 0;
  for (int k = 0; k < 200; ++k) {
    RollingInput in;
    in.hinge.pin_diameter = 0.02 + 0.04 * u(rng);
    in.hinge.half_thickness = in.hinge.pin_diameter * (0.1 + 0.2 * u(rng));
    in.hinge.teeth = 6 + static_cast<int>(20 * u(rng));
    in.hinge.strokes = 1 + (u(rng) < 0.5 ? 1 : 0);
    in.hinge.plate_radius =
        (0.25 * in.hinge.pin_diameter - 0.5 * in.hinge.half_thickness) * (1.0 + 0.5 * u(rng));
    in.tension = 1e3 + 1e5 * u(rng);
    const double alpha = angles(in.hinge.teeth, in.hinge.strokes, 0).alpha;
    in.flank_angle = (2.0 * u(rng) - 1.0) * 0.5 * alpha;
    in.rolling_coefficient = 5e-3 * u(rng);
    in.points = 11;
    if (!validate(in).empty()) continue;
    const Result r = solve_rolling(in);
    ++solved;
    for (const Sample& s : r.series) {
      ASSERT_FALSE(std::isnan(s.xi));
      EXPECT_LE(s.residual, kResidualTol);
      // triangle inequality of the force balance: |F_N| ≤ F1 + F2 + F1k + F2k
      EXPECT_LE(std::abs(s.fn),
                in.tension + std::abs(s.f2) + s.f1k + std::abs(s.f2k) + kRelForceTol * in.tension);
    }
  }
  EXPECT_GT(solved, 50);
}

// At γ = 0 links 1 and 2 are in line and the tooth normal is at β1(0) = ψ − γΣ/2. With both
// rolling resistances along the faces' tangent t = (−sin ξ, cos ξ) (the senses of (28): against
// the contact's travel), ΣY and ΣX of the roller are, by hand,
//   F_N cos β1 = c_r (F1 + F2) cos ξ,   F2 − F1 + F_N sin β1 − c_r (F1 + F2) sin ξ = 0,
// so F_N(0) = c_r (F1 + F2) cos ξ / cos β1 > 0: the resistances press the roller onto the tooth.
// The senses whose moments oppose the roller's spin (Catena before) put both along −t and gave
// F_N(0) = −c_r (F1 + F2) cos ξ / cos β1 (−64 N on the thesis example): this test fails on them.
TEST(EngagementRolling, ToothReactionAtEntryIsTheClosedFormOfBothResistances) {
  for (double psi : {deg(-20), 0.0, deg(10), deg(21.62), deg(30)}) {
    for (double cr : {1e-3, 1e-2, 5e-2}) {
      RollingInput in = rolling(psi, cr);
      in.points = 2;
      const Sample s = solve_rolling(in).series.front();
      ASSERT_EQ(s.gamma, 0.0);
      const double f1 = in.tension, b1 = psi - deg(45);  // γΣ = 90°
      const double fn = cr * (f1 + s.f2) * std::cos(s.xi) / std::cos(b1);
      const double f2 = f1 - fn * std::sin(b1) + cr * (f1 + s.f2) * std::sin(s.xi);
      EXPECT_NEAR(s.fn, fn, kRelForceTol * f1) << psi << " " << cr;
      EXPECT_NEAR(s.f2, f2, kRelForceTol * f1) << psi << " " << cr;
      EXPECT_GT(s.fn, 0.0) << psi << " " << cr;
      EXPECT_GT(s.f2, f1) << psi << " " << cr;  // tan β1 < 0: F2 starts above F1
      EXPECT_LE(s.residual, kResidualTol);
    }
  }
}

// Over the whole engagement of the thesis' example (and flanks around it), with the default and a
// ten times larger c_r, the tooth only pushes: F_N > 0 at every sample and no lift-off diagnostic.
TEST(EngagementRolling, ToothNeverPullsOverTheThesisEngagement) {
  for (double psi : {0.0, deg(10), deg(21.62), deg(30)}) {
    for (double cr : {1e-3, 1e-2}) {
      const Result r = solve_rolling(rolling(psi, cr));
      for (const Sample& s : r.series) EXPECT_GT(s.fn, 0.0) << psi << " " << cr << " " << s.gamma;
      for (const Diagnostic& d : r.diagnostics) EXPECT_NE(d.code, "engagement.tooth_lift_off");
    }
  }
}

// With F2 < F1 the balance of (28) gives the roller less turn on link 1 than on link 2, so at the
// end of the engagement link 2's turn exceeds γΣ/2 = γmax: faces made by eq. (6) for γmax cannot
// hold it, and a designer gives R2 from eq. (6) for a larger turn. The design-turn warning must
// then compare against that turn, ψ1max·(1 − R1/R2) (eq. 6 solved for γ), not the sprocket's
// γmax; the contact staying on the arc (ψ1 ≤ ψ1max) is the same limit seen from the plate.
TEST(EngagementRolling, DesignTurnOfAGivenR2IsEq6SolvedForTheTurn) {
  RollingInput in = rolling(deg(21.62));
  in.hinge.plate_radius = 0.010;
  const double gmax = hinge::gamma_max(in.hinge);  // 45° (z = 8, m = 2)
  const double psi_max = hinge::psi1_max(0.040, 0.008, 0.010);
  const auto has = [](const Result& r, const std::string& code) {
    return std::any_of(r.diagnostics.begin(), r.diagnostics.end(),
                       [&](const Diagnostic& d) { return d.code == code; });
  };
  const auto worst_turn = [](const Result& r) {
    double w = 0.0;
    for (const Sample& s : r.series) w = std::max({w, std::abs(s.xi), std::abs(s.gamma - s.xi)});
    return w;
  };
  // faces made for 1.5·γmax = 67.5°: the roller turns past γmax but stays on the arc
  in.hinge.roller_radius = *hinge::r2_eq6(0.040, 0.008, 0.010, 1.5 * gmax);
  const Result wide = solve_rolling(in);
  ASSERT_GT(worst_turn(wide), gmax);  // the sprocket's γmax is exceeded ...
  EXPECT_LT(worst_turn(wide), 1.5 * gmax);
  EXPECT_FALSE(has(wide, "engagement.beyond_design_turn"));  // ... but not the faces' turn
  EXPECT_FALSE(has(wide, "engagement.contact_off_arc"));
  // faces made for 0.5·γmax: the warning names that turn as its limit
  in.hinge.roller_radius = *hinge::r2_eq6(0.040, 0.008, 0.010, 0.5 * gmax);
  const Result narrow = solve_rolling(in);
  bool found = false;
  for (const Diagnostic& d : narrow.diagnostics) {
    if (d.code != "engagement.beyond_design_turn") continue;
    found = true;
    EXPECT_NEAR(d.limit, 0.5 * gmax, kAngleTol);
    EXPECT_NEAR(d.limit, psi_max * (1.0 - 0.010 / in.hinge.roller_radius), kAngleTol);
    EXPECT_EQ(d.value, worst_turn(narrow));
  }
  EXPECT_TRUE(found);
  EXPECT_TRUE(has(narrow, "engagement.contact_off_arc"));
  // R2 from eq. (6) (not given): the limit stays the sprocket's γmax
  in.hinge.roller_radius = 0.0;
  for (const Diagnostic& d : solve_rolling(in).diagnostics) {
    if (d.code == "engagement.beyond_design_turn") {
      EXPECT_EQ(d.limit, gmax);
    }
  }
}

// Lift-off remains possible where the balance degenerates: a flank tilted far backwards (ψ = −40°
// against α = 45°) with a rolling coefficient two orders above steel's makes ΣX, ΣY nearly
// singular (det = −[cos(γΣ/2 − ψ) + c_r sin(β1 − ξ)]), F2 turns negative (link 2 would push)
// and so does F_N. It is reported with the least reaction reached.
TEST(EngagementRolling, ToothLiftOffReportsTheLeastReaction) {
  const Result r = solve_rolling(rolling(deg(-40), 0.2));
  double least = 0.0;
  for (const Sample& s : r.series) least = std::min(least, s.fn);
  ASSERT_LT(least, 0.0);
  bool found = false;
  for (const Diagnostic& d : r.diagnostics) {
    if (d.code != "engagement.tooth_lift_off") continue;
    found = true;
    EXPECT_EQ(d.value, least);
    EXPECT_EQ(d.limit, 0.0);
  }
  EXPECT_TRUE(found);
  // without rolling resistance the radial tooth carries nothing at γ = 0 and never pulls
  for (const Diagnostic& d : solve_rolling(rolling(0.0, 0.0)).diagnostics)
    EXPECT_NE(d.code, "engagement.tooth_lift_off");
}

// The whole wrap, frictionless: the sprocket's torque from the tooth loads equals the global
// balance of the engaged chain, (F_in − F_out)·R·cos(γΣ/2) (spans along the polygon's sides).
TEST(EngagementWrap, FrictionlessTorqueIsTheTensionDropTimesTheSideDistance) {
  for (double psi : {0.0, deg(10), deg(21.6)}) {
    const SlidingInput in = sliding(0.0, psi);
    const Result r = solve_sliding(in);
    const double t = 0.125;
    const Wrap w = wrap(r, in.tension, t, kPi);
    ASSERT_EQ(w.rollers, 2);
    ASSERT_EQ(w.tension.size(), 3u);
    const double global = (w.tension.front() - w.tension.back()) * w.pitch_radius *
                          std::cos(0.5 * r.angles.gamma_sigma);
    EXPECT_NEAR(w.torque, global, kRelMomentTol * in.tension * t);
    for (std::size_t k = 1; k < w.tension.size(); ++k)
      EXPECT_LE(w.tension[k], w.tension[k - 1] + kTensionTol);
  }
  EXPECT_THROW(wrap(solve_sliding(sliding()), 29.4e3, -1.0, 0.0), InputError);
}

TEST(EngagementErrors, ValidateListsEveryProblem) {
  SlidingInput s;
  s.tension = -1;
  s.teeth = 2;
  s.friction = -0.1;
  s.points = 1;
  const std::vector<Issue> is = validate(s);
  EXPECT_GE(is.size(), 6u);  // tension, teeth, strokes, friction, d1, d2, points
  EXPECT_THROW(solve_sliding(s), InputError);
  RollingInput r = rolling(deg(80));  // |ψ| ≥ α = 45°
  r.rolling_coefficient = -1;
  r.hinge.face = hinge::Face::kFlat;
  const std::vector<Issue> ir = validate(r);
  EXPECT_GE(ir.size(), 3u);
  EXPECT_THROW(solve_rolling(r), InputError);
}

}  // namespace
}  // namespace catena::engagement
