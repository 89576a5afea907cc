// The thesis' wear experiments (seed 000 §2.3, conclusions 10–11) against the wear model:
// docs/models/wear.md, "Reproduction table". The thesis gives ratios only. One coefficient is
// fitted — the rolling pair's Archard k, from bench 1's pitch-extension ratio 4.4 — and every
// other ratio is the model's prediction, asserted here as the model gives it (not as the thesis
// states it where the two differ; the doc shows why).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "catena/hinge/hinge.hpp"
#include "catena/hinge/synthesis.hpp"
#include "catena/wear/wear.hpp"

namespace catena::wear {
namespace {

constexpr double kRelTol = 1e-9;     // [1] ratios that are identities of the model: round-off
constexpr double kPrintTol = 0.005;  // [1] numbers the doc prints to 2–3 digits

// Bench 1 (§2.2, concl. 10): F ≈ 3.5 kN, v = 0.34 m/s, the 125 mm chain, a two-stroke sprocket
// (z = 8 as the other examples); d = 40 mm, a = 8 mm, R1 = 15 mm (R2 from eq. 6), L = 24 mm;
// plates 42 HRC, pivots 30 HRC for both chains (the serial chain's hardness is not given).
Input bench1(HingeKind h, RollingLimit limit = RollingLimit::kFriction) {
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
  in.limit = limit;
  return in;
}

struct Ratios {
  double pitch, roller, plate;
};

// Sliding over rolling: pitch extension, pivot wear, plate wear per pass of the new chains.
Ratios ratios(const Input& sliding, const Input& rolling) {
  const Articulation s = articulate(sliding, {}), r = articulate(rolling, {});
  return {(s.roller_depth + s.plate_depth) / (r.roller_depth + r.plate_depth),
          s.roller_depth / r.roller_depth, s.plate_depth / r.plate_depth};
}

// The rolling pair's k that makes bench 1's pitch ratio 4.4 (Archard is linear in k).
double fitted_k(RollingLimit limit) {
  return 1e-4 * ratios(bench1(HingeKind::kSliding), bench1(HingeKind::kRolling, limit)).pitch / 4.4;
}

TEST(WearPaper, EqualCoefficientsCannotGiveBenchOnesRatioUnderEitherReading) {
  // The same k on both chains: with eq. (21)'s friction limit the rolling hinge slides most of
  // its 45° plate turn (the limit is 6.5°) over a narrow band and wears MORE than the sliding
  // hinge; rolling throughout (guided) it wears only by micro-slip, hundreds of times less.
  const Ratios friction = ratios(bench1(HingeKind::kSliding), bench1(HingeKind::kRolling));
  const Ratios guided =
      ratios(bench1(HingeKind::kSliding), bench1(HingeKind::kRolling, RollingLimit::kGuided));
  std::printf("equal k: pitch ratio friction %.4g, guided %.4g\n", friction.pitch, guided.pitch);
  EXPECT_LT(friction.pitch, 1.0);
  EXPECT_GT(guided.pitch, 100.0);
  EXPECT_NEAR(friction.pitch, 0.1009, kPrintTol * 0.1009);
  EXPECT_NEAR(guided.pitch, 328.0, kPrintTol * 328.0);
}

TEST(WearPaper, FittedOnBenchOnePitchRatioPredictsRollerEqualsPlateRatio) {
  // The fit (4.4) does not use the part ratios: with one k per material pair each pair's two
  // parts wear in inverse proportion to their hardness, so the sliding/rolling ratio is the same
  // for pivots and plates — 4.4, not 9.4 and 1.9 — for any k, either reading, a pivot that does
  // not turn, and equal hardness ratios in the two chains.
  for (RollingLimit limit : {RollingLimit::kFriction, RollingLimit::kGuided}) {
    Input rolling = bench1(HingeKind::kRolling, limit);
    rolling.wear_coefficient = fitted_k(limit);
    const Ratios r = ratios(bench1(HingeKind::kSliding), rolling);
    EXPECT_NEAR(r.pitch, 4.4, kRelTol * 4.4);  // the fit itself
    EXPECT_NEAR(r.roller, r.plate, kRelTol * r.plate);
    EXPECT_NEAR(r.roller, 4.4, kRelTol * 4.4);
  }
  std::printf("fitted k_rolling: friction %.4g, guided %.4g\n", fitted_k(RollingLimit::kFriction),
              fitted_k(RollingLimit::kGuided));
}

TEST(WearPaper, ThePartSplitNeedsAHardnessRatioNoSteelPairHas) {
  // 9.4 / 1.9 = 4.95: the serial chain's plate/pivot hardness ratio must be 4.95 times the
  // rolling chain's (4040/2962 = 1.36), i.e. 6.75 — checked on the model by giving the sliding
  // chain that ratio (pivots 4040/6.75 = 599 MPa ≈ 61 HV, softer than any chain steel).
  Input sliding = bench1(HingeKind::kSliding);
  sliding.roller_hardness = 4040e6 / (4040.0 / 2962.0 * 9.4 / 1.9);
  Input rolling = bench1(HingeKind::kRolling, RollingLimit::kGuided);
  rolling.wear_coefficient = 1e-4;
  const Ratios r = ratios(sliding, rolling);
  EXPECT_NEAR(r.roller / r.plate, 9.4 / 1.9, kRelTol * 5.0);
  EXPECT_LT(sliding.roller_hardness, 1e9);
}

TEST(WearPaper, BenchTwoLoadDoesNotReachThreePointFour) {
  // Bench 2 loads 1600–3200 N (§2.1.2), mean 2400 N, held constant here. Archard is linear in F;
  // the load enters the ratio only through the rolling contact's Hertz half-width b ∝ √F: in the
  // micro-slip (creep ∝ b) and in the band R1·ψ1 + 2b that the rolling hinge's wear covers.
  // With the friction limit the gross slide dominates and a narrower band at the lower load
  // lowers the ratio to 4.30; rolling throughout, the micro-slip falls with b and the ratio rises
  // to 5.29. The thesis' 3.4 is below both.
  const double expected[] = {4.296, 5.293};  // friction, guided
  int i = 0;
  for (RollingLimit limit : {RollingLimit::kFriction, RollingLimit::kGuided}) {
    Input sliding = bench1(HingeKind::kSliding);
    Input rolling = bench1(HingeKind::kRolling, limit);
    rolling.wear_coefficient = fitted_k(limit);
    sliding.tension = rolling.tension = 2400.0;
    const Ratios r = ratios(sliding, rolling);
    std::printf("bench 2 (2400 N) pitch ratio %s: %.4g\n",
                limit == RollingLimit::kGuided ? "guided" : "friction", r.pitch);
    EXPECT_NEAR(r.pitch, expected[i], kPrintTol * expected[i]);
    EXPECT_GT(r.pitch, 3.4 * 1.2);                      // the thesis' 3.4 is not reached
    EXPECT_NEAR(r.roller, r.plate, kRelTol * r.plate);  // and 6.8 vs 1.7 cannot split
    ++i;
  }
}

TEST(WearPaper, BenchTwoLoadCycledOverThePass) {
  // The bench-2 load varies smoothly 1600–3200 N: one pass of four articulations at 1600, 2400,
  // 3200 and 2400 N instead of the constant mean. The ratios barely move from the mean-load ones.
  const double expected[] = {4.306, 5.187};  // friction, guided
  int i = 0;
  for (RollingLimit limit : {RollingLimit::kFriction, RollingLimit::kGuided}) {
    Input sliding = bench1(HingeKind::kSliding);
    Input rolling = bench1(HingeKind::kRolling, limit);
    rolling.wear_coefficient = fitted_k(limit);
    sliding.tensions = rolling.tensions = {1600.0, 2400.0, 3200.0, 2400.0};
    const Result s = run(sliding), r = run(rolling);
    const double ratio =
        (s.pass.roller_depth + s.pass.plate_depth) / (r.pass.roller_depth + r.pass.plate_depth);
    std::printf("bench 2 (cycled) pitch ratio %s: %.4g\n",
                limit == RollingLimit::kGuided ? "guided" : "friction", ratio);
    EXPECT_NEAR(ratio, expected[i], kPrintTol * expected[i]);
    EXPECT_GT(ratio, 3.4 * 1.2);
    ++i;
  }
}

TEST(WearPaper, AccelerationFactorIsNotPredictedOnlyWhatItImplies) {
  // 1 h of bench 2 ≈ 5.6 h of bench 1: the summary gives neither bench 2's cycle rate nor its
  // amplitude, nor bench 1's loop length. The model's wear rate is k·F·(sliding per hour)/H, so
  // 5.6 at 2400 N means 5.6·3500/2400 = 8.17 times bench 1's sliding per hour — checked here on
  // the sliding chain: 8.17 times the passes per hour at 2400 N wears 5.6 times as fast.
  const Input b1 = bench1(HingeKind::kSliding);
  Input b2 = b1;
  b2.tension = 2400.0;
  b2.loop_length = b1.loop_length / (5.6 * 3500.0 / 2400.0);
  const Result r1 = run(b1), r2 = run(b2);
  EXPECT_NEAR(*r1.life_hours[2] / *r2.life_hours[2], 5.6, 5.6 * 1e-6);
}

// Bench 2's motion (§2.1.2): "continuous oscillating (back-and-forth) or rotary (also reversing)
// motion of the axles under a smoothly varying load (from 1600 N to 3200 N)". The summary gives
// neither the oscillation's angle nor its rate (nor the crank-rocker's dimensions, the worm
// reducer's ratio or the motor's speed), so the stroke is the unknown here. One oscillation of the
// links' mutual angle from 0 to Δφ and back is two articulations of Δφ — what a sprocket does to
// a hinge entering and leaving it — on the bench-1 chain's own hinge (R2 of bench 1's sprocket,
// fixed; no tooth: the sliding pivot never turns). With the k fitted on bench 1, the predicted
// sliding/rolling pitch ratio as a function of the stroke Δφ ≤ 90° (the aperture of bench 1's
// hinge; a rolling hinge cannot turn further, so "rotary" motion can only be of the sliding
// chain's pivots or of the whole specimen): friction alone never comes down to 3.4 (its least is
// at the largest stroke); guided, the ratio passes 3.4 at one stroke (≈ 54°) — a stroke the
// thesis would have to state for this to be a prediction.
struct Stroke {
  double degrees, friction, guided;
};

std::vector<Stroke> bench_two_ratios(const std::vector<double>& tensions) {
  hinge::Hinge h1;
  h1.pin_diameter = 0.040;
  h1.half_thickness = 0.008;
  h1.plate_radius = 0.015;
  h1.teeth = 8;
  h1.strokes = 2;
  const double r2 = *hinge::r2_eq6(0.040, 0.008, 0.015, hinge::gamma_max(h1));
  std::vector<Stroke> out;
  for (int deg = 10; deg <= 90; deg += 5) {
    Stroke st{static_cast<double>(deg), 0.0, 0.0};
    for (RollingLimit limit : {RollingLimit::kFriction, RollingLimit::kGuided}) {
      Input sliding = bench1(HingeKind::kSliding);
      Input rolling = bench1(HingeKind::kRolling, limit);
      rolling.wear_coefficient = fitted_k(limit);
      for (Input* in : {&sliding, &rolling}) {
        in->teeth = 360;  // mutual turn 360°·m/z = m degrees
        in->strokes = deg;
        in->articulations = static_cast<int>(tensions.size());
        in->tensions = tensions;
        in->geometry.roller_radius = r2;
      }
      const Result s = run(sliding), r = run(rolling);
      EXPECT_EQ(s.first.turned, 0.0) << deg;  // no tooth: the neck slides in one pair of bores
      const double ratio =
          (s.pass.roller_depth + s.pass.plate_depth) / (r.pass.roller_depth + r.pass.plate_depth);
      (limit == RollingLimit::kGuided ? st.guided : st.friction) = ratio;
    }
    out.push_back(st);
  }
  return out;
}

TEST(WearPaper, BenchTwoStrokeIsNotGivenRatioOverTheUnknownStroke) {
  // the load cycled smoothly 1600–3200 N over each pair of oscillations
  const std::vector<Stroke> ratios = bench_two_ratios({1600.0, 2400.0, 3200.0, 2400.0});
  double least_friction = 1e300, at_34 = 0.0;
  int crossings = 0;
  for (std::size_t i = 0; i < ratios.size(); ++i) {
    const Stroke& s = ratios[i];
    std::printf("bench 2 stroke %4.0f deg: pitch ratio friction %.4g, guided %.4g\n", s.degrees,
                s.friction, s.guided);
    least_friction = std::min(least_friction, s.friction);
    if (i > 0 && (ratios[i - 1].guided - 3.4) * (s.guided - 3.4) <= 0.0) {
      const Stroke& a = ratios[i - 1];
      at_34 = a.degrees + (3.4 - a.guided) / (s.guided - a.guided) * (s.degrees - a.degrees);
      ++crossings;
    }
  }
  std::printf("friction: least ratio %.4g; guided: 3.4 at a stroke of %.3g deg\n", least_friction,
              at_34);
  // friction alone: 3.4 is out of reach for every stroke from 10° to the hinge's 90°; its least
  // is at the largest stroke (a small stroke rolls within eq. (21)'s limit and hardly wears)
  EXPECT_GT(least_friction, 3.4 * 1.2);
  EXPECT_EQ(least_friction, ratios.back().friction);
  // guided: 3.4 is reached at exactly one stroke of the sweep, near 54°
  EXPECT_EQ(crossings, 1);
  EXPECT_NEAR(at_34, 54.1, 0.5);
  // at 90° the stroke is bench 1's articulation: the earlier cycled-load numbers
  EXPECT_NEAR(ratios.back().friction, 4.306, kPrintTol * 4.306);
  EXPECT_NEAR(ratios.back().guided, 5.187, kPrintTol * 5.187);
}

}  // namespace
}  // namespace catena::wear
