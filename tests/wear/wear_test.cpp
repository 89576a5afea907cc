// Hinge wear (docs/models/wear.md): Archard against a hand-integrated case, the sliding of an
// articulation against the hinge kinematics, conservation, block extrapolation, random inputs.
#include "catena/wear/wear.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "catena/engagement/engagement.hpp"
#include "catena/hinge/kinematics.hpp"
#include "catena/hinge/synthesis.hpp"

namespace catena::wear {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kRelTol = 1e-9;  // [1] closed forms against the model: round-off
// [1] the model's 181-point trapezoid against 20 000 midpoints: the creep has a square-root kink
// where the traction saturates (tan ψ1 = f), so the trapezoid's error is O(h^1.5) ≈ 2e-4 there
constexpr double kIntegralTol = 1e-3;
constexpr double kBlockTol = 0.01;  // [1] the issue: halving ΔN changes the life by < 1 %

// The thesis' benches (seed 000 §2.2, concl. 10): t = 125 mm, F = 3.5 kN, v = 0.34 m/s, a
// two-stroke sprocket; z = 8, d = 40 mm, a = 8 mm, R1 = 15 mm, L = 24 mm as the other examples.
Input bench(HingeKind h) {
  Input in;
  in.hinge = h;
  in.pitch = 0.125;
  in.teeth = 8;
  in.strokes = 2;
  in.articulations = 4;
  in.tension = 3500.0;
  in.speed = 0.34;
  in.loop_length = 10.0;
  in.wear_coefficient = 1e-4;
  in.plate_hardness = 4040e6;
  in.roller_hardness = 2962e6;
  in.contact_length = 0.024;
  in.friction = 0.15;
  in.journal_diameter = 0.040;
  in.tooth_diameter = 0.040;
  in.geometry.pin_diameter = 0.040;
  in.geometry.half_thickness = 0.008;
  in.geometry.plate_radius = 0.015;
  return in;
}

TEST(WearArchard, SlidingHingeLifeIsTheHandIntegratedArchardLaw) {
  // The pivot does not turn on this sprocket (engagement finding: z = 8, m = 2, f = 0.15, ψ = 0),
  // so every articulation slides the neck through r·Δφ in link 1's bores under F. Depth of each
  // part: k·F·s/(H·d·L) with s = (d/2)·Δφ, i.e. k·F·Δφ/(2·H·L), independent of the worn d: the
  // elongation is linear in the passes and its integral is the product below.
  const Input in = bench(HingeKind::kSliding);
  const double dphi = kPi / 2.0;  // 360°·2/8
  const double per_articulation =
      1e-4 * 3500.0 * dphi / (2.0 * 0.024) * (1.0 / 4040e6 + 1.0 / 2962e6);
  const double per_pass = 4.0 * per_articulation / 0.125;  // elongation per pass
  const double passes_per_hour = 0.34 * 3600.0 / 10.0;
  const Result r = run(in);
  ASSERT_EQ(r.life_hours.size(), 3u);
  const double limits[] = {0.015, 0.02, 0.03};
  for (int i = 0; i < 3; ++i) {
    ASSERT_TRUE(r.life_hours[i].has_value());
    EXPECT_NEAR(*r.life_hours[i], limits[i] / per_pass / passes_per_hour,
                kRelTol * *r.life_hours[i]);
  }
  // Archard's volume of the pivots over the run: V = k·F·s_total/H = depth·d·L at every point.
  const double passes = r.at_end.hours * passes_per_hour;
  const double s_total = passes * 4.0 * 0.020 * dphi;  // unworn radius: the volume over d·L
  EXPECT_NEAR(archard_volume(1e-4, 3500.0, s_total, 2962e6) / (0.040 * 0.024), r.at_end.roller,
              1e-6 * r.at_end.roller);  // the neck wears: r = 20 mm − depth (< 1e-6 relative)
  EXPECT_EQ(r.first.turned, 0.0);
  EXPECT_NEAR(r.first.slide_link1, 0.020 * dphi, kRelTol * 0.02);
}

TEST(WearArchard, CarterCreepLimits) {
  EXPECT_EQ(carter_creep(0.15, 1e-4, 0.02, 0.0), 0.0);  // no traction: no creep
  EXPECT_NEAR(carter_creep(0.15, 1e-4, 0.02, 1.0), 0.15 * 1e-4 / 0.02, kRelTol);  // full slip
  EXPECT_NEAR(carter_creep(0.15, 1e-4, 0.02, 0.75), 0.15 * 1e-4 / 0.02 * 0.5, kRelTol);
}

TEST(WearKinematics, RolledArcAndPlateTurnAreTheHingeKinematicsMeasuredNumerically) {
  // Independent of the model's own integral: the plate turn measured from two of the pivot's
  // feature points (eq. 11) and the contact's travel summed point by point along M1(φ).
  Input in = bench(HingeKind::kRolling);
  in.limit = RollingLimit::kGuided;
  const Articulation a = articulate(in, {});
  hinge::Hinge h = in.geometry;
  h.teeth = 8;
  h.strokes = 2;
  const double r2 = hinge::r2_eq6(0.040, 0.008, 0.015, hinge::gamma_max(h)).value();
  const auto fp = hinge::feature_points(h, r2);
  const hinge::Pose p0 = hinge::pose(h, r2, 0.0), p1 = hinge::pose(h, r2, a.mutual_turn);
  const auto dir = [&](const hinge::Pose& p) {
    const hinge::Point u = hinge::roller_point(p, fp[0]), v = hinge::roller_point(p, fp[2]);
    return std::atan2(u.y - v.y, u.x - v.x);
  };
  EXPECT_NEAR(std::fabs(dir(p1) - dir(p0)), a.plate_turn, 1e-9);
  double travel = 0.0;
  hinge::Point prev = p0.contact;
  const int n = 20000;
  for (int i = 1; i <= n; ++i) {
    const hinge::Point m = hinge::pose(h, r2, a.mutual_turn * i / n).contact;
    travel += std::hypot(m.x - prev.x, m.y - prev.y);
    prev = m;
  }
  EXPECT_NEAR(a.rolled_arc, travel, 1e-6 * travel);
  // Carter micro-slip integrated independently: ψ1 = θ·R2/(R2 − R1) (rolling without slip,
  // eqs. 1–2), 20 001 points.
  const double rs = 0.015 * r2 / (r2 - 0.015);
  double slip = 0.0;
  const int m = 20000;
  for (int i = 0; i < m; ++i) {
    const double psi = (i + 0.5) / m * a.plate_turn * r2 / (r2 - 0.015);
    const double q = std::min(std::tan(psi) / 0.15, 1.0);
    slip +=
        carter_creep(0.15, a.half_width, rs, q) * 0.015 * (a.plate_turn * r2 / (r2 - 0.015)) / m;
  }
  EXPECT_NEAR(a.micro_slip, slip, kIntegralTol * slip);
}

TEST(WearKinematics, SlidingNeckTurnIsTheLinksRelativeRotationOnTheSprocket) {
  // The sliding hinge's s = r·Δφ against the links' relative rotation measured on the seated
  // chain: vertices of the engagement model's wrap polygon (pitch radius R), the angle between
  // two consecutive links from their chords, for several sprockets.
  for (int z : {6, 8, 11, 17, 25}) {
    for (int m : {1, 2}) {
      Input in = bench(HingeKind::kSliding);
      in.teeth = z;
      in.strokes = m;
      if (!validate(in).empty()) continue;
      const Articulation a = articulate(in, {});
      engagement::SlidingInput si;
      si.tension = in.tension;
      si.teeth = z;
      si.strokes = m;
      si.friction = in.friction;
      si.journal_diameter = in.journal_diameter;
      si.tooth_diameter = in.tooth_diameter;
      const engagement::Wrap w =
          engagement::wrap(engagement::solve_sliding(si), in.tension, in.pitch, kPi);
      // chord t on a circle of radius R: consecutive vertices 2·asin(t/2R) apart
      const double step = 2.0 * std::asin(0.5 * in.pitch / w.pitch_radius);
      double x[3], y[3];
      for (int k = 0; k < 3; ++k) {
        x[k] = w.pitch_radius * std::cos(k * step);
        y[k] = w.pitch_radius * std::sin(k * step);
      }
      const double ux = x[1] - x[0], uy = y[1] - y[0], vx = x[2] - x[1], vy = y[2] - y[1];
      const double turn = std::atan2(ux * vy - uy * vx, ux * vx + uy * vy);
      EXPECT_NEAR((a.slide_link1 + a.slide_link2) / (0.5 * in.journal_diameter), turn, 1e-12)
          << "z = " << z << ", m = " << m;
    }
  }
}

TEST(WearKinematics, SlidingMovesToTheOtherBoresWhereThePivotTurns) {
  // A forward flank and a small tooth diameter make criterion (25) hold late in the engagement:
  // over that range the neck slides in link 2's bores and on the tooth instead of link 1's.
  Input in = bench(HingeKind::kSliding);
  in.flank_angle = 0.5;
  in.tooth_diameter = 0.010;
  const Articulation a = articulate(in, {});
  engagement::SlidingInput si;
  si.tension = 3500.0;
  si.teeth = 8;
  si.strokes = 2;
  si.flank_angle = 0.5;
  si.friction = 0.15;
  si.journal_diameter = 0.040;
  si.tooth_diameter = 0.010;
  si.points = in.samples;
  double turned = 0.0;
  for (const auto& g : engagement::solve_sliding(si).roller_turns) turned += g.to - g.from;
  ASSERT_GT(turned, 0.0);
  EXPECT_NEAR(a.turned, turned, 1e-12);
  EXPECT_NEAR(a.slide_link2, 0.020 * turned, kRelTol);
  EXPECT_NEAR(a.slide_link1 + a.slide_link2, 0.020 * kPi / 2.0, kRelTol);
  EXPECT_NEAR(a.slide_tooth, 0.005 * turned, kRelTol);
  EXPECT_NEAR(a.neck_spread, 1.0 / kPi, kRelTol);  // conclusion 8: the turning neck wears less
  const Articulation fixed = articulate(bench(HingeKind::kSliding), {});
  EXPECT_LT(a.roller_depth, fixed.roller_depth);
  EXPECT_NEAR(a.plate_depth, fixed.plate_depth, kRelTol * fixed.plate_depth);
}

TEST(WearConservation, NoSlidingNoWear) {
  // Rolling throughout (guided) without micro-slip: nothing slides, so nothing wears.
  Input in = bench(HingeKind::kRolling);
  in.limit = RollingLimit::kGuided;
  in.creep = Creep::kNone;
  const Result r = run(in);
  EXPECT_EQ(r.first.slide_pivot_plate, 0.0);
  EXPECT_EQ(r.first.roller_depth, 0.0);
  EXPECT_EQ(r.first.plate_depth, 0.0);
  EXPECT_EQ(r.at_end.elongation, 0.0);
  for (const auto& l : r.life_hours) EXPECT_FALSE(l.has_value());
  ASSERT_FALSE(r.diagnostics.empty());
  EXPECT_EQ(r.diagnostics.back().code, "wear.no_sliding");
  // and the wear of each part is proportional to the sliding: micro-slip alone wears
  in.creep = Creep::kCarter;
  const Articulation a = articulate(in, {});
  EXPECT_GT(a.micro_slip, 0.0);
  EXPECT_NEAR(a.plate_depth / a.roller_depth, 2962e6 / 4040e6, kRelTol);
}

TEST(WearBlocks, HalvingTheBlockChangesTheLifeByLessThanOnePercent) {
  for (HingeKind h : {HingeKind::kSliding, HingeKind::kRolling}) {
    Input in = bench(h);
    const Result coarse = run(in);
    in.block_passes = 0.5 * coarse.block_passes;
    const Result fine = run(in);
    for (std::size_t i = 0; i < coarse.life_hours.size(); ++i) {
      ASSERT_TRUE(coarse.life_hours[i] && fine.life_hours[i]);
      EXPECT_LT(std::fabs(*coarse.life_hours[i] - *fine.life_hours[i]),
                kBlockTol * *fine.life_hours[i]);
    }
  }
}

TEST(WearBlocks, TheWornGeometryIsReSolved) {
  // The rolling hinge's radii change with wear (R1 − plate depth, R2 + pivot depth): the last
  // block's rate differs from the first's, so the block scheme does more than multiply.
  const Input in = bench(HingeKind::kRolling);
  const Result r = run(in);
  const Articulation late = articulate(in, {0.5 * r.at_end.roller, 0.5 * r.at_end.plate});
  EXPECT_NE(late.rolling_limit, r.first.rolling_limit);
  EXPECT_NE(late.plate_depth, r.first.plate_depth);
}

TEST(WearProperties, RandomValidInputsGiveFiniteMonotoneElongation) {
  std::mt19937 rng(20);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int ran = 0;
  for (int k = 0; k < 120; ++k) {
    Input in = bench(u(rng) < 0.5 ? HingeKind::kSliding : HingeKind::kRolling);
    in.teeth = 6 + static_cast<int>(20 * u(rng));
    in.strokes = 1 + (u(rng) < 0.5 ? 1 : 0);
    in.tension = 500.0 + 5e4 * u(rng);
    in.friction = 0.05 + 0.4 * u(rng);
    in.wear_coefficient = std::pow(10.0, -6.0 + 3.0 * u(rng));
    in.contact_length = 0.01 + 0.04 * u(rng);
    in.flank_angle = 0.6 * (u(rng) - 0.3);
    in.tooth_diameter = 0.005 + 0.04 * u(rng);
    in.geometry.pin_diameter = 0.02 + 0.04 * u(rng);
    in.geometry.half_thickness = in.geometry.pin_diameter * (0.1 + 0.2 * u(rng));
    in.geometry.plate_radius =
        (0.25 * in.geometry.pin_diameter - 0.5 * in.geometry.half_thickness) * (1.0 + 0.5 * u(rng));
    in.limit = u(rng) < 0.5 ? RollingLimit::kGuided : RollingLimit::kFriction;
    in.samples = 31;
    if (!validate(in).empty()) continue;
    const Result r = run(in);
    ++ran;
    double prev = -1.0, hours = -1.0;
    for (const Point& p : r.series) {
      ASSERT_TRUE(std::isfinite(p.elongation) && std::isfinite(p.hours));
      EXPECT_GE(p.elongation, prev);
      EXPECT_GT(p.hours, hours);
      prev = p.elongation;
      hours = p.hours;
    }
    for (std::size_t i = 1; i < r.life_hours.size(); ++i) {
      if (r.life_hours[i] && r.life_hours[i - 1]) {
        EXPECT_LE(*r.life_hours[i - 1], *r.life_hours[i]);
      }
    }
    EXPECT_TRUE(std::isfinite(r.at_end.roller) && std::isfinite(r.at_end.plate));
  }
  EXPECT_GT(ran, 60);
}

TEST(WearLoads, EachArticulationWearsUnderItsOwnTension) {
  // Archard is linear in F for the sliding hinge: a pass whose two slack-side articulations
  // carry nothing wears half as fast as one loaded at all four, i.e. lives twice as long.
  Input all = bench(HingeKind::kSliding);
  Input half = all;
  half.tensions = {3500.0, 3500.0, 0.0, 0.0};
  const Result r_all = run(all), r_half = run(half);
  EXPECT_NEAR(*r_half.life_hours[2], 2.0 * *r_all.life_hours[2], kRelTol * *r_half.life_hours[2]);
  EXPECT_NEAR(r_half.pass.slide_pivot_plate, 0.5 * r_all.pass.slide_pivot_plate, 1e-15);
  // the rolling hinge: the micro-slip grows with the Hertz width (b ∝ √F), so a lighter
  // articulation wears less than in proportion to its load, and the pass sums its articulations
  Input roll = bench(HingeKind::kRolling);
  roll.limit = RollingLimit::kGuided;
  roll.tensions = {3500.0, 3500.0, 875.0, 875.0};
  const Result mixed = run(roll);
  Input light = roll;
  light.tensions.clear();
  light.tension = 875.0;
  Input heavy = light;
  heavy.tension = 3500.0;
  const double expected =
      2.0 * articulate(heavy, {}).plate_depth + 2.0 * articulate(light, {}).plate_depth;
  EXPECT_NEAR(mixed.pass.plate_depth, expected, kRelTol * expected);
  EXPECT_LT(articulate(light, {}).plate_depth, 0.25 * articulate(heavy, {}).plate_depth);
  // one value per articulation, or one for all
  Input wrong = all;
  wrong.tensions = {3500.0, 3500.0};
  EXPECT_FALSE(validate(wrong).empty());
}

TEST(WearErrors, ValidateListsEveryProblem) {
  Input in = bench(HingeKind::kSliding);
  in.tension = -1.0;
  in.wear_coefficient = 2.0;
  in.friction = 0.0;
  in.limits = {0.02, 0.9};
  in.journal_diameter = 0.0;
  const auto issues = validate(in);
  std::vector<std::string> fields;
  for (const Issue& i : issues) fields.push_back(i.field);
  for (const char* f : {"tension", "wear_coefficient", "friction", "limits", "journal_diameter"})
    EXPECT_NE(std::find(fields.begin(), fields.end(), f), fields.end()) << f;
  EXPECT_THROW(run(in), InputError);
}

}  // namespace
}  // namespace catena::wear
