// Closed forms of the pocket-wheel run-on against the independent numerical solver, against
// finite differences of their own positions, and over wide random inputs.
#include "catena/pocketwheel/run_on.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "catena/pocketwheel/run_on_numeric.hpp"

namespace catena::pocketwheel {
namespace {

constexpr double kSeatingTol = 1e-10;   // [rad] event angles, closed form vs numerical
constexpr double kPositionTol = 1e-11;  // [m]
constexpr double kVelocityTol = 1e-9;   // [m/s] the bound
constexpr double kAccelTol = 1e-6;      // [m/s²] the bound
constexpr double kEventGap = 1e-7;      // [rad] samples this close to an event are skipped

const PocketWheel kPaperWheel{0.064, 0.018, 8};  // 003: chain Ø18×64, z = 8
constexpr double kPaperOmega = 5.0;              // [1/s]
constexpr double kPaperGuideEnd = 0.256;         // [m]

struct Case {
  const char* name;
  PocketWheel wheel;
  Guide guide;
  double omega;
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

std::vector<Case> cases() {
  const WheelGeometry g = wheel_geometry(kPaperWheel);
  const double mid = 0.5 * (g.chordal_height + g.pitch_radius);
  std::vector<Case> out;
  for (SpanModel span : {SpanModel::kSlider, SpanModel::kPivot}) {
    const bool slider = span == SpanModel::kSlider;
    out.push_back(
        {slider ? "free" : "free_again", kPaperWheel, {GuideKind::kNone, 0, 0, span}, kPaperOmega});
    out.push_back({slider ? "chordal_slider" : "chordal_pivot",
                   kPaperWheel,
                   {GuideKind::kChordal, 0, kPaperGuideEnd, span},
                   kPaperOmega});
    out.push_back({slider ? "tangential_slider" : "tangential_pivot",
                   kPaperWheel,
                   {GuideKind::kTangential, 0, kPaperGuideEnd, span},
                   kPaperOmega});
    out.push_back({slider ? "mid_slider" : "mid_pivot",
                   kPaperWheel,
                   {GuideKind::kHeight, mid, kPaperGuideEnd, span},
                   kPaperOmega});
    out.push_back({slider ? "high_slider" : "high_pivot",
                   kPaperWheel,
                   {GuideKind::kHeight,
                    g.chordal_height + 0.9 * (g.pitch_radius - g.chordal_height), 0.4, span},
                   kPaperOmega});
    out.push_back({slider ? "z5_slider" : "z5_pivot",
                   PocketWheel{0.042, 0.014, 5},
                   {GuideKind::kTangential, 0, 0.3, span},
                   12.0});
    out.push_back({slider ? "z12_chordal" : "z12_chordal_pivot",
                   PocketWheel{0.092, 0.026, 12},
                   {GuideKind::kChordal, 0, 0.9, span},
                   2.0});
  }
  return out;
}

bool near_event(const RunOnPlan& plan, double phi) {
  for (const Phase& p : plan.phases) {
    if (std::abs(phi - p.begin) < kEventGap || std::abs(phi - p.end) < kEventGap) return true;
  }
  return false;
}

class RunOnCase : public ::testing::TestWithParam<Case> {};

TEST_P(RunOnCase, ClosedFormsAgreeWithTheNumericalSolver) {
  const Case& c = GetParam();
  const RunOnPlan plan = plan_run_on(c.wheel, c.guide);
  const numeric::NumericPlan num = numeric::plan(c.wheel, c.guide);
  ASSERT_EQ(plan.phases.size(), num.phases.size());
  ASSERT_EQ(plan.seating_angles.size(), num.seating_angles.size());
  for (std::size_t i = 0; i < plan.phases.size(); ++i) {
    EXPECT_NEAR(plan.phases[i].end, num.phases[i].end, kSeatingTol) << "phase " << i;
  }
  for (std::size_t i = 0; i < plan.seating_angles.size(); ++i) {
    EXPECT_NEAR(plan.seating_angles[i], num.seating_angles[i], kSeatingTol);
  }
  const int n = 2001;
  int compared = 0;
  for (int i = 0; i < n; ++i) {
    const double phi = plan.geometry.tooth_angle * i / (n - 1);
    if (near_event(plan, phi)) continue;
    const PointKinematics a = evaluate(plan, phi);
    const PointKinematics b = numeric::evaluate(num, phi);
    EXPECT_NEAR(a.x, b.x, kPositionTol) << "phi = " << phi;
    EXPECT_NEAR(c.omega * a.dx, c.omega * b.dx, kVelocityTol) << "phi = " << phi;
    EXPECT_NEAR(c.omega * c.omega * a.d2x, c.omega * c.omega * b.d2x, kAccelTol) << "phi = " << phi;
    if (c.guide.kind == GuideKind::kNone) {
      EXPECT_NEAR(c.omega * a.dy, c.omega * b.dy, kVelocityTol);
      EXPECT_NEAR(c.omega * c.omega * a.d2y, c.omega * c.omega * b.d2y, kAccelTol);
    }
    ++compared;
  }
  EXPECT_GT(compared, n - 20);
}

TEST_P(RunOnCase, DerivativesMatchFiniteDifferencesOfTheirOwnPositions) {
  const Case& c = GetParam();
  const RunOnPlan plan = plan_run_on(c.wheel, c.guide);
  constexpr double h = 1e-5;               // [rad]
  constexpr double kFdTol = 50.0 * h * h;  // [1] relative to the scale R, central differences O(h²)
  // [1] relative to R: the second difference loses ε·R/h² ≈ 2e-6 R to round-off
  constexpr double kSecondDifferenceTol = 1e-4;
  const double scale = plan.geometry.pitch_radius;
  for (std::size_t index = 0; index < plan.phases.size(); ++index) {
    const Phase& p = plan.phases[index];
    for (int i = 1; i < 50; ++i) {
      const double phi = p.begin + (p.end - p.begin) * i / 50.0;
      const PointKinematics m = evaluate_phase(plan, index, phi - h);
      const PointKinematics k = evaluate_phase(plan, index, phi);
      const PointKinematics q = evaluate_phase(plan, index, phi + h);
      EXPECT_NEAR(k.dx, (q.x - m.x) / (2 * h), kFdTol * scale) << "phase " << index;
      EXPECT_NEAR(k.d2x, (q.dx - m.dx) / (2 * h), kFdTol * scale) << "phase " << index;
      EXPECT_NEAR(k.d2x, (q.x - 2 * k.x + m.x) / (h * h), kSecondDifferenceTol * scale)
          << "phase " << index;
      EXPECT_NEAR(k.dy, (q.y - m.y) / (2 * h), kFdTol * scale);
      EXPECT_NEAR(k.d2y, (q.dy - m.dy) / (2 * h), kFdTol * scale);
    }
  }
}

TEST_P(RunOnCase, PositionIsContinuousAndAdvancesTwoPitchesPerPeriod) {
  const Case& c = GetParam();
  const RunOnPlan plan = plan_run_on(c.wheel, c.guide);
  EXPECT_NEAR(evaluate(plan, 0.0).x, 0.0, kPositionTol);
  for (std::size_t i = 0; i + 1 < plan.phases.size(); ++i) {
    const double at = plan.phases[i].end;
    EXPECT_NEAR(evaluate_phase(plan, i, at).x, evaluate_phase(plan, i + 1, at).x, kPositionTol)
        << "x jumps at the seating at phi = " << at;
  }
  const double period = plan.geometry.tooth_angle;
  EXPECT_NEAR(evaluate_phase(plan, plan.phases.size() - 1, period).x, 2.0 * c.wheel.pitch,
              kPositionTol);
  EXPECT_NEAR(evaluate(plan, period).x, 2.0 * c.wheel.pitch, kPositionTol);
}

INSTANTIATE_TEST_SUITE_P(Guides, RunOnCase, ::testing::ValuesIn(cases()),
                         [](const auto& param_info) { return std::string(param_info.param.name); });

TEST(RunOn, SeatingOrderFollowsThePaper) {
  // Chordal: at φ = 0 a t + d link has just seated along the guide; the t − d link is next
  // (the only consistent order). Tangential: the t + d link seats first (003 eq. 29 uses δ1).
  const Guide chordal{GuideKind::kChordal, 0, kPaperGuideEnd, SpanModel::kSlider};
  const Guide tangential{GuideKind::kTangential, 0, kPaperGuideEnd, SpanModel::kSlider};
  EXPECT_DOUBLE_EQ(plan_run_on(kPaperWheel, chordal).first_link, 0.064 - 0.018);
  EXPECT_DOUBLE_EQ(plan_run_on(kPaperWheel, tangential).first_link, 0.064 + 0.018);
  // the chordal period ends exactly with the next t + d link lying on the guide line
  const RunOnPlan plan = plan_run_on(kPaperWheel, chordal);
  EXPECT_EQ(plan.phases.size(), 2u);
  EXPECT_EQ(plan.seating_angles.front(), 0.0);
}

TEST(RunOn, FarGuideTendsToFreeRunOn) {
  // l → ∞: the span stays parallel to the guide; a chordal guide then moves the strand as free
  // run-on does, with an error of order R/l.
  const double l = 2000.0;                // [m]
  constexpr double kFarGuideFactor = 10;  // [1] on R²/l [m]: the error is of order R/l
  const RunOnPlan free = plan_run_on(kPaperWheel, Guide{});
  const RunOnPlan far =
      plan_run_on(kPaperWheel, Guide{GuideKind::kChordal, 0, l, SpanModel::kSlider});
  const double r = free.geometry.pitch_radius;
  for (int i = 0; i < 200; ++i) {
    const double phi = free.geometry.tooth_angle * (i + 0.5) / 200;
    if (std::abs(phi - free.geometry.tooth_angle / 2) < 1e-3) continue;
    EXPECT_NEAR(evaluate(far, phi).dx, evaluate(free, phi).dx, kFarGuideFactor * r * r / l);
    EXPECT_NEAR(evaluate(far, phi).x, evaluate(free, phi).x, kFarGuideFactor * r * r / l);
  }
}

TEST(RunOn, InfeasibleGuidesAreErrorsThatStateTheLimit) {
  const WheelGeometry g = wheel_geometry(kPaperWheel);
  try {
    plan_run_on(kPaperWheel, Guide{GuideKind::kTangential, 0, 0.1, SpanModel::kSlider});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("l > R = 0.164283 m"), std::string::npos) << e.what();
  }
  try {
    plan_run_on(kPaperWheel, Guide{GuideKind::kChordal, 0, 0.165, SpanModel::kSlider});
    FAIL();
  } catch (const InputError& e) {
    const std::string text = e.what();
    EXPECT_NE(text.find("l ≥ "), std::string::npos) << text;
    // the stated limit is the boundary: just above it the plan exists
    const double limit = std::stod(text.substr(text.find("l ≥ ") + std::string("l ≥ ").size()));
    EXPECT_NO_THROW(plan_run_on(kPaperWheel,
                                Guide{GuideKind::kChordal, 0, limit * 1.0001, SpanModel::kSlider}));
    EXPECT_THROW(
        plan_run_on(kPaperWheel, Guide{GuideKind::kChordal, 0, limit * 0.999, SpanModel::kSlider}),
        InputError);
  }
  try {
    plan_run_on(kPaperWheel, Guide{GuideKind::kHeight, 0.1, 0.256, SpanModel::kSlider});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("between the chordal height"), std::string::npos);
  }
  EXPECT_LT(g.chordal_height, g.pitch_radius);
}

TEST(RunOn, RandomDesignsGiveFiniteMonotoneMotion) {
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> pitch(0.01, 0.2);
  std::uniform_real_distribution<double> ratio(0.1, 0.45);
  std::uniform_int_distribution<int> teeth(3, 24);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  constexpr double kEndTol = 1e-12;  // [m] two pitches (≤ 0.4 m) at the end of the sampled period
  int checked = 0;
  for (int i = 0; i < 300; ++i) {
    PocketWheel wheel{pitch(rng), 0.0, teeth(rng)};
    wheel.wire = ratio(rng) * wheel.pitch;
    const WheelGeometry g = wheel_geometry(wheel);
    Guide guide;
    guide.kind = static_cast<GuideKind>(i % 4);
    guide.span_model = unit(rng) < 0.5 ? SpanModel::kSlider : SpanModel::kPivot;
    guide.height = g.chordal_height + unit(rng) * (g.pitch_radius - g.chordal_height);
    guide.end_distance = g.pitch_radius + (1.0 + 20.0 * unit(rng)) * 2.0 * wheel.pitch;
    RunOnPlan plan;
    try {
      plan = plan_run_on(wheel, guide);
    } catch (const InputError& e) {
      // only the "too close" diagnosis is acceptable for valid input, and it must state a limit
      EXPECT_NE(std::string(e.what()).find("l ≥ "), std::string::npos) << e.what();
      continue;
    }
    const RunOnResult res = sample_run_on(plan, Sampling{3.0, 301, 10.0},
                                          [&plan](double phi) { return evaluate(plan, phi); });
    for (std::size_t k = 0; k < res.series.x.size(); ++k) {
      ASSERT_TRUE(std::isfinite(res.series.x[k]) && std::isfinite(res.series.vx[k]) &&
                  std::isfinite(res.series.ax[k]) && std::isfinite(res.series.inertial_force[k]));
      EXPECT_GT(res.series.vx[k], 0.0) << "the strand moves towards the wheel";
      if (k) {
        EXPECT_GT(res.series.x[k], res.series.x[k - 1]);
      }
    }
    EXPECT_NEAR(res.series.x.back(), 2.0 * wheel.pitch, kEndTol);
    EXPECT_LE(res.extremes.vx_min, res.extremes.vx_max);
    ++checked;
  }
  EXPECT_GT(checked, 200);
}

}  // namespace
}  // namespace catena::pocketwheel
