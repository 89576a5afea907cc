// Loop tensions by the contour method (seed 000 §1.5, fig. 19): hand-derived loops, the exact
// affine take-up solution against a brute-force search over the loop, property tests over random
// loops, diagnostics and error cases.
#include "catena/strength/loop.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace {

using namespace catena::strength;
using catena::Diagnostic;
using catena::InputError;

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;
constexpr double kHandTol = 1e-9;   // [N] hand sums of numbers of order 1e3 (round-off only)
constexpr double kPowerTol = 1e-9;  // [W] hand-derived powers of order 1e3 (round-off only)
constexpr double kRelTol = 1e-12;   // [1] relative, round-off of a few dozen operations
// [1] relative to the loop's tensions (up to ~1e6 N): round-off of sums and products along a
// random loop of up to 21 segments
constexpr double kSumRelTol = 1e-9;
// [1] relative to the loop's tensions, when the two sides come from different walks of the loop
// (a bisection stopped at 1e-10 of a ±1e9 N bracket, a take-up moved elsewhere)
constexpr double kWalkRelTol = 1e-8;
constexpr double kShiftTol = 1e-8;  // [N] a tension shift of ~1e2 N taken between ~1e6 N tensions

Segment straight(double L, double q0, double q, double w, double beta = 0.0) {
  Segment s;
  s.kind = SegmentKind::kStraight;
  s.length = L;
  s.chain_weight = q0;
  s.load_weight = q;
  s.resistance = w;
  s.incline = beta;
  return s;
}
Segment turn(double k) {
  Segment s;
  s.kind = SegmentKind::kTurn;
  s.factor = k;
  return s;
}
Segment guide(double f, double alpha) {
  Segment s;
  s.kind = SegmentKind::kTurn;
  s.friction = f;
  s.wrap = alpha;
  return s;
}
Segment takeup(double s0) {
  Segment s;
  s.kind = SegmentKind::kTakeup;
  s.pretension = s0;
  return s;
}
Segment drive(double loss = 0.0) {
  Segment s;
  s.kind = SegmentKind::kDrive;
  s.loss = loss;
  return s;
}

// A horizontal conveyor: take-up just after the drive, return run, tail sprocket, carrying run,
// head guide, drive.
Loop horizontal() {
  Loop l;
  l.segments = {takeup(1000.0), straight(20.0, 100.0, 0.0, 0.1),
                turn(1.05),     straight(20.0, 100.0, 400.0, 0.1),
                turn(1.02),     drive(0.03)};
  l.speed = 0.5;
  l.efficiency = 0.8;
  return l;
}

TEST(Loop, HorizontalLoopByHand) {
  // S0 = 1000 N at the take-up, which sits at the drive's slack side: S_slack = 1000.
  // return run:  ΔS = (q0 + q)·L·w = 100·20·0.1 = 200            → 1200
  // tail turn:   ×1.05                                           → 1260
  // carrying:    ΔS = (100 + 400)·20·0.1 = 1000                  → 2260
  // head guide:  ×1.02                                           → 2305.2 = S_tight
  // drive:       F = 2305.2 − 1000 + 0.03·(2305.2 + 1000) = 1305.2 + 99.156 = 1404.356 N
  // power:       P = F·v/η = 1404.356·0.5/0.8 = 877.7225 W
  const LoopResult r = solve(horizontal());
  ASSERT_EQ(r.segments.size(), 6u);
  const double expected_in[6] = {1000.0, 1000.0, 1200.0, 1260.0, 2260.0, 2305.2};
  const double expected_out[6] = {1000.0, 1200.0, 1260.0, 2260.0, 2305.2, 1000.0};
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_NEAR(r.segments[i].tension_in, expected_in[i], kHandTol) << i;
    EXPECT_NEAR(r.segments[i].tension_out, expected_out[i], kHandTol) << i;
  }
  EXPECT_NEAR(r.slack_tension, 1000.0, kHandTol);
  EXPECT_NEAR(r.tight_tension, 2305.2, kHandTol);
  EXPECT_NEAR(r.drive_force, 1404.356, kHandTol);
  EXPECT_NEAR(r.power, 877.7225, kPowerTol);
  EXPECT_DOUBLE_EQ(r.length, 40.0);
  EXPECT_DOUBLE_EQ(r.segments[3].s_start, 20.0);
  EXPECT_DOUBLE_EQ(r.segments[3].s_end, 40.0);
  // fig. 19 qualitatively: greatest on the branch running onto the drive sprocket (its tight
  // side, the end of the walk), falling over the sprocket to the least where the links leave it
  EXPECT_NEAR(r.max.tension, 2305.2, kHandTol);
  EXPECT_EQ(r.max.segment, 4u);
  EXPECT_TRUE(r.max.at_end);
  EXPECT_DOUBLE_EQ(r.max.s, 40.0);
  EXPECT_NEAR(r.min.tension, 1000.0, kHandTol);
  EXPECT_EQ(r.min.segment, 0u);
  EXPECT_FALSE(r.min.at_end);
  EXPECT_TRUE(r.diagnostics.empty());
}

TEST(Loop, TakeUpElsewhereSolvesBackwards) {
  // The same loop with the take-up moved to the tail (after the return run, before the tail
  // turn), S0 = 1200 N: then S_slack + 200 = 1200 → S_slack = 1000, and every tension is the
  // hand-derived one above.
  Loop l = horizontal();
  l.segments = {straight(20.0, 100.0, 0.0, 0.1),   takeup(1200.0), turn(1.05),
                straight(20.0, 100.0, 400.0, 0.1), turn(1.02),     drive(0.03)};
  const LoopResult r = solve(l);
  EXPECT_NEAR(r.slack_tension, 1000.0, kHandTol);
  EXPECT_NEAR(r.tight_tension, 2305.2, kHandTol);
  EXPECT_NEAR(r.drive_force, 1404.356, kHandTol);
  // and after the tail turn: S_slack = (1260 − 200)/1.05 ... with S0 = 1260 at that point
  l.segments = {straight(20.0, 100.0, 0.0, 0.1),   turn(1.05), takeup(1260.0),
                straight(20.0, 100.0, 400.0, 0.1), turn(1.02), drive(0.03)};
  EXPECT_NEAR(solve(l).slack_tension, 1000.0, kHandTol);
}

TEST(Loop, DescendingRunLowersTheTension) {
  // β = −10°, L = 10 m, q0 = 100 N/m, w = 0.1: ΔS = 100·10·(0.1·cos10° − sin10°)
  //   = 1000·(0.0984808 − 0.1736482) = −75.167 N: gravity pulls harder than friction resists
  Loop l;
  l.segments = {takeup(500.0), straight(10.0, 100.0, 0.0, 0.1, -10.0 * kDeg), turn(1.0),
                straight(10.0, 100.0, 0.0, 0.1, 10.0 * kDeg), drive()};
  l.speed = 1.0;
  constexpr double kPrintedTol = 1e-4;  // [N] the hand value −75.1674 has 4 decimals
  const LoopResult r = solve(l);
  const double down = 1000.0 * (0.1 * std::cos(10.0 * kDeg) - std::sin(10.0 * kDeg));
  EXPECT_NEAR(down, -75.1674, kPrintedTol);
  EXPECT_NEAR(r.segments[1].tension_out, 500.0 + down, kHandTol);
  EXPECT_LT(r.segments[1].tension_out, r.segments[1].tension_in);
  // rising back by the same height: the heights cancel and only friction is left,
  // F = 2·100·10·0.1·cos10° = 196.96 N
  EXPECT_NEAR(r.drive_force, 200.0 * std::cos(10.0 * kDeg), kHandTol);
  EXPECT_NEAR(r.min.tension, 500.0 + down, kHandTol);
  EXPECT_EQ(r.min.segment, 1u);
}

TEST(Loop, EulerFormAgreesWithItsFactor) {
  // exp(f·α) with f = 0.2, α = 90° is the factor k = exp(0.1·π) = 1.369107…
  constexpr double kPrintedTol = 1e-4;  // [1] the factor is written 1.3691, with 4 decimals
  Loop a = horizontal(), b = horizontal();
  a.segments[2] = guide(0.2, kPi / 2);
  b.segments[2] = turn(std::exp(0.2 * kPi / 2));
  EXPECT_NEAR(std::exp(0.1 * kPi), 1.3691, kPrintedTol);
  const LoopResult ra = solve(a), rb = solve(b);
  for (std::size_t i = 0; i < ra.segments.size(); ++i)
    EXPECT_NEAR(ra.segments[i].tension_out, rb.segments[i].tension_out,
                kRelTol * rb.segments[i].tension_out);
  EXPECT_NEAR(ra.segments[2].tension_out, 1200.0 * std::exp(0.1 * kPi), kHandTol);
}

// Tensions by a second method: march the loop segment by segment with the textbook formulas
// (written again here, not through affine()) and find S_slack by bisection on the take-up
// condition S(take-up) = S0.
double march_to_takeup(const Loop& l, double slack) {
  double S = slack;
  for (const Segment& s : l.segments) {
    if (s.kind == SegmentKind::kTakeup) return S;
    if (s.kind == SegmentKind::kStraight)
      S += (s.chain_weight + s.load_weight) * s.length *
           (s.resistance * std::cos(s.incline) + std::sin(s.incline));
    if (s.kind == SegmentKind::kTurn)
      S = s.factor ? S * *s.factor : S * std::exp(*s.friction * *s.wrap);
  }
  return S;
}

double bisect_slack(const Loop& l) {
  double S0 = 0.0;
  for (const Segment& s : l.segments)
    if (s.kind == SegmentKind::kTakeup) S0 = s.pretension;
  double lo = -1e9, hi = 1e9;  // march_to_takeup is increasing in the slack tension
  for (int i = 0; i < 200 && hi - lo > 1e-10 * (1.0 + std::abs(hi)); ++i) {
    const double mid = 0.5 * (lo + hi);
    (march_to_takeup(l, mid) < S0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

Loop random_loop(std::mt19937& rng, bool with_turns = true) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::uniform_int_distribution<int> count(2, 19);
  Loop l;
  const int n = count(rng);
  for (int i = 0; i < n; ++i) {
    if (with_turns && u(rng) < 0.35) {
      l.segments.push_back(u(rng) < 0.5 ? turn(1.0 + 0.15 * u(rng))
                                        : guide(0.4 * u(rng), kPi * u(rng)));
    } else {
      l.segments.push_back(straight(0.5 + 100.0 * u(rng), 10.0 + 500.0 * u(rng),
                                    u(rng) < 0.5 ? 0.0 : 2000.0 * u(rng), 0.3 * u(rng),
                                    (u(rng) - 0.5) * 60.0 * kDeg));
    }
  }
  std::uniform_int_distribution<std::size_t> where(0, l.segments.size());
  l.segments.insert(l.segments.begin() + static_cast<std::ptrdiff_t>(where(rng)),
                    takeup(20000.0 * u(rng)));
  l.segments.push_back(drive(0.05 * u(rng)));
  l.speed = 0.05 + 2.0 * u(rng);
  l.efficiency = 0.5 + 0.5 * u(rng);
  return l;
}

TEST(Loop, AffineSolutionMatchesBruteForceSearch) {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 200; ++trial) {
    const Loop l = random_loop(rng);
    const LoopResult r = solve(l);
    const double scale = 1.0 + r.max.tension - r.min.tension + std::abs(r.slack_tension);
    EXPECT_NEAR(r.slack_tension, bisect_slack(l), kWalkRelTol * scale) << trial;
  }
}

TEST(Loop, RandomLoopsHoldTheContourInvariants) {
  std::mt19937 rng(17);
  for (int trial = 0; trial < 500; ++trial) {
    const Loop l = random_loop(rng);
    const LoopResult r = solve(l);
    const std::size_t n = l.segments.size();
    double sum = 0.0, magnitude = 1.0;
    for (std::size_t i = 0; i < n; ++i) {
      const SegmentTension& t = r.segments[i];
      ASSERT_TRUE(std::isfinite(t.tension_in) && std::isfinite(t.tension_out)) << trial;
      magnitude += std::abs(t.tension_in);
      if (i + 1 < n) {
        EXPECT_DOUBLE_EQ(t.tension_in, i == 0 ? r.slack_tension : r.segments[i - 1].tension_out);
        // each resistance in its own right: run by its formula, turn (k − 1)·S_in
        const Segment& s = l.segments[i];
        double expected = 0.0;
        if (s.kind == SegmentKind::kStraight)
          expected = (s.chain_weight + s.load_weight) * s.length *
                     (s.resistance * std::cos(s.incline) + std::sin(s.incline));
        if (s.kind == SegmentKind::kTurn)
          expected =
              ((s.factor ? *s.factor : std::exp(*s.friction * *s.wrap)) - 1.0) * t.tension_in;
        EXPECT_NEAR(t.tension_out - t.tension_in, expected, kSumRelTol * magnitude)
            << trial << " " << i;
        sum += expected;
        if (s.kind == SegmentKind::kTakeup) {
          EXPECT_NEAR(t.tension_in, s.pretension, kSumRelTol * magnitude);
        }
      }
    }
    // the drive supplies what the loop resists, plus its own loss
    const double xi = l.segments.back().loss;
    EXPECT_NEAR(r.drive_force, sum + xi * (r.tight_tension + r.slack_tension),
                kSumRelTol * magnitude)
        << trial;
    EXPECT_NEAR(r.power * (r.drive_force >= 0 ? l.efficiency : 1.0 / l.efficiency),
                r.drive_force * l.speed, kSumRelTol * magnitude * l.speed);
    EXPECT_LE(r.min.tension, r.max.tension);
    EXPECT_EQ(r.segments.back().tension_out, r.slack_tension);  // the loop closes
  }
}

TEST(Loop, TensionsAreAffineInTheWeights) {
  // S_i = A_i·S_slack + B_i with B linear in the weights: S(λ) − S(0) = λ·(S(1) − S(0))
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> lambda(0.0, 5.0);
  for (int trial = 0; trial < 200; ++trial) {
    const Loop l1 = random_loop(rng);
    Loop l0 = l1, ll = l1;
    const double k = lambda(rng);
    for (Segment& s : l0.segments) s.chain_weight = s.load_weight = 0.0;
    for (Segment& s : ll.segments) {
      s.chain_weight *= k;
      s.load_weight *= k;
    }
    const LoopResult r0 = solve(l0), r1 = solve(l1), rl = solve(ll);
    for (std::size_t i = 0; i < l1.segments.size(); ++i) {
      const double d1 = r1.segments[i].tension_out - r0.segments[i].tension_out;
      const double dl = rl.segments[i].tension_out - r0.segments[i].tension_out;
      EXPECT_NEAR(dl, k * d1, kSumRelTol * (1.0 + std::abs(k * d1) + r0.segments[i].tension_out))
          << trial << " " << i;
    }
  }
}

TEST(Loop, MovingTheTakeUpOrItsPretensionShiftsTheTensions) {
  std::mt19937 rng(29);
  for (int trial = 0; trial < 200; ++trial) {
    // without turns every tension shifts by the same ΔS0, wherever the take-up sits, and the
    // tension differences (the runs' resistances) do not change
    Loop l = random_loop(rng, false);
    const LoopResult a = solve(l);
    Loop raised = l;
    for (Segment& s : raised.segments)
      if (s.kind == SegmentKind::kTakeup) s.pretension += 750.0;
    const LoopResult b = solve(raised);
    for (std::size_t i = 0; i < l.segments.size(); ++i)
      EXPECT_NEAR(b.segments[i].tension_out - a.segments[i].tension_out, 750.0, kShiftTol);
    // moved elsewhere with the tension it had found there: the same loop
    std::size_t from = 0;
    for (std::size_t i = 0; i < l.segments.size(); ++i)
      if (l.segments[i].kind == SegmentKind::kTakeup) from = i;
    Segment moved = l.segments[from];
    l.segments.erase(l.segments.begin() + static_cast<std::ptrdiff_t>(from));
    const std::size_t to = static_cast<std::size_t>(trial) % l.segments.size();  // before drive
    moved.pretension = a.segments[to < from ? to : to + 1].tension_in;
    if (moved.pretension < 0.0) continue;  // a take-up cannot push: not a valid input
    l.segments.insert(l.segments.begin() + static_cast<std::ptrdiff_t>(to), moved);
    const LoopResult c = solve(l);
    EXPECT_NEAR(c.slack_tension, a.slack_tension, kWalkRelTol * (1.0 + a.max.tension)) << trial;
    EXPECT_NEAR(c.drive_force, a.drive_force, kWalkRelTol * (1.0 + a.max.tension)) << trial;
  }
  // with turns, ΔS_i = ΔS0·A_i/A_takeup (A_i the product of the factors k up to point i): every
  // tension rises, by exactly ΔS0 at the take-up, less before it and more after it
  for (int trial = 0; trial < 100; ++trial) {
    const Loop l = random_loop(rng);
    Loop raised = l;
    for (Segment& s : raised.segments)
      if (s.kind == SegmentKind::kTakeup) s.pretension += 100.0;
    const LoopResult a = solve(l), b = solve(raised);
    double previous = b.slack_tension - a.slack_tension;
    EXPECT_GT(previous, 0.0);
    for (std::size_t i = 0; i + 1 < l.segments.size(); ++i) {
      const double shift = b.segments[i].tension_out - a.segments[i].tension_out;
      EXPECT_GE(shift, previous * (1 - kSumRelTol)) << trial << " " << i;
      if (l.segments[i].kind == SegmentKind::kTakeup) {
        EXPECT_NEAR(shift, 100.0, kShiftTol);
      }
      previous = shift;
    }
  }
}

TEST(Loop, HorizontalLoopsPeakAtTheDriveTightSide) {
  // fig. 19: on a loop without descents the tension only grows along the walk, so the greatest
  // is where the chain runs onto the drive sprocket and the least where it leaves it (take-up at
  // the slack side)
  std::mt19937 rng(31);
  for (int trial = 0; trial < 100; ++trial) {
    // horizontal runs, the take-up at the drive's slack side (S ≥ S0 ≥ 0 everywhere)
    Loop l = random_loop(rng);
    for (Segment& s : l.segments) s.incline = 0.0;
    const auto t = std::find_if(l.segments.begin(), l.segments.end(),
                                [](const Segment& s) { return s.kind == SegmentKind::kTakeup; });
    std::rotate(l.segments.begin(), t, t + 1);
    const LoopResult r = solve(l);
    EXPECT_NEAR(r.max.tension, r.tight_tension, kSumRelTol * r.tight_tension);
    EXPECT_NEAR(r.min.tension, r.slack_tension, kSumRelTol * (1.0 + r.tight_tension));
    EXPECT_DOUBLE_EQ(r.max.s, r.length);
    EXPECT_EQ(r.min.s, 0.0);
    for (std::size_t i = 0; i + 1 < l.segments.size(); ++i)
      EXPECT_GE(r.segments[i].tension_out, r.segments[i].tension_in);
  }
}

bool has(const LoopResult& r, const std::string& code, Diagnostic* out = nullptr) {
  for (const Diagnostic& d : r.diagnostics)
    if (d.code == code) {
      if (out) *out = d;
      return true;
    }
  return false;
}

TEST(Loop, SlackChainIsADiagnosticWithTheShortfall) {
  // a long descent after a weak take-up: 200 + 100·50·(0.05·cos20° − sin20°) = −1275.1 N
  Loop l;
  l.segments = {takeup(200.0), straight(50.0, 100.0, 0.0, 0.05, -20.0 * kDeg),
                straight(50.0, 100.0, 300.0, 0.1, 20.0 * kDeg), turn(1.05), drive()};
  l.speed = 0.3;
  Diagnostic d;
  const LoopResult r = solve(l);
  ASSERT_TRUE(has(r, "loop.chain_slack", &d));
  EXPECT_EQ(d.severity, Diagnostic::Severity::kInfeasible);
  EXPECT_NEAR(d.value, 200.0 + 5000.0 * (0.05 * std::cos(20 * kDeg) - std::sin(20 * kDeg)),
              kHandTol);
  EXPECT_EQ(d.limit, 0.0);
  EXPECT_NE(d.message.find("segment 1"), std::string::npos) << d.message;
}

TEST(Loop, MinimumAndAllowableTensionsAreChecked) {
  Loop l = horizontal();
  l.min_tension = 1100.0;
  l.allowable_tension = 2000.0;
  Diagnostic d;
  const LoopResult r = solve(l);
  ASSERT_TRUE(has(r, "loop.below_min_tension", &d));
  EXPECT_NEAR(d.value, 1000.0, kHandTol);
  EXPECT_EQ(d.limit, 1100.0);
  ASSERT_TRUE(has(r, "loop.over_allowable_tension", &d));
  EXPECT_NEAR(d.value, 2305.2, kHandTol);
  EXPECT_EQ(d.limit, 2000.0);
  l.min_tension = 900.0;
  l.allowable_tension = 2400.0;
  EXPECT_TRUE(solve(l).diagnostics.empty());
}

TEST(Loop, DownhillLoopBrakesWithItsPowerReturned) {
  Loop l;
  l.segments = {takeup(8000.0), straight(30.0, 100.0, 0.0, 0.05, 15.0 * kDeg), turn(1.02),
                straight(30.0, 100.0, 1000.0, 0.05, -15.0 * kDeg), drive()};
  l.speed = 0.5;
  l.efficiency = 0.8;
  const LoopResult r = solve(l);
  ASSERT_LT(r.drive_force, 0.0);
  EXPECT_TRUE(has(r, "loop.drive_brakes"));
  EXPECT_NEAR(r.power, r.drive_force * 0.5 * 0.8, kPowerTol);
}

std::vector<catena::Issue> issues_of(const Loop& l) {
  try {
    solve(l);
  } catch (const InputError& e) {
    return e.issues();
  }
  return {};
}

bool names(const std::vector<catena::Issue>& issues, const std::string& field) {
  for (const auto& i : issues)
    if (i.field == field) return true;
  return false;
}

TEST(Loop, EveryProblemIsReportedAtOnce) {
  Loop l;
  l.segments = {takeup(-5.0), straight(-1.0, 100.0, 0.0, 0.1), turn(0.95), drive(0.03),
                straight(10.0, -1.0, 0.0, 1.5, 100.0 * kDeg)};
  l.speed = 0.0;
  l.efficiency = 1.5;
  const auto issues = issues_of(l);
  for (const char* f : {"segment[0].pretension", "segment[1].length", "segment[2].factor",
                        "segment[3].kind", "segment[4].chain_weight", "segment[4].resistance",
                        "segment[4].incline", "speed", "efficiency"})
    EXPECT_TRUE(names(issues, f)) << f;
  for (const auto& i : issues)
    if (i.field == "segment[2].factor") {
      EXPECT_NE(i.expected.find("k ≥ 1"), std::string::npos) << i.expected;
    }
}

TEST(Loop, DriveAndTakeUpCountsAreChecked) {
  Loop l;
  l.speed = 1.0;
  l.segments = {takeup(100.0), straight(10.0, 100.0, 0.0, 0.1)};  // no drive
  EXPECT_TRUE(names(issues_of(l), "segments"));
  l.segments = {takeup(100.0), drive(), straight(10.0, 100.0, 0.0, 0.1), drive()};  // two
  const auto two = issues_of(l);
  EXPECT_TRUE(names(two, "segments"));
  EXPECT_TRUE(names(two, "segment[1].kind"));               // and the first is not last
  l.segments = {straight(10.0, 100.0, 0.0, 0.1), drive()};  // no take-up
  EXPECT_TRUE(names(issues_of(l), "segments"));
  l.segments = {};
  EXPECT_TRUE(names(issues_of(l), "segments"));
}

TEST(Loop, TurnTakesExactlyOneForm) {
  Loop l = horizontal();
  l.segments[2].wrap = kPi;  // k and α both
  EXPECT_TRUE(names(issues_of(l), "segment[2].factor"));
  l.segments[2] = turn(1.0);
  l.segments[2].factor.reset();  // neither
  EXPECT_TRUE(names(issues_of(l), "segment[2].factor"));
  l.segments[2].wrap = kPi;  // α without f
  EXPECT_TRUE(names(issues_of(l), "segment[2].friction"));
  l.segments[2].friction = 2.0;  // f out of range
  EXPECT_TRUE(names(issues_of(l), "segment[2].friction"));
  l.segments[2].friction = 0.1;
  l.segments[2].wrap = 7.0;  // α > 2π
  EXPECT_TRUE(names(issues_of(l), "segment[2].wrap"));
  l.segments[2].wrap = std::nan("");
  EXPECT_TRUE(names(issues_of(l), "segment[2].wrap"));
}

}  // namespace
