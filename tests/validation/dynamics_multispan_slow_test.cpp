// The slack start of `slack_spans = "all"` over two lower runs laid tangent to their wheels
// (docs/models/dynamics.md, the free layout's start with slack) over ranges too long for the unit
// tier: every count of test 1's range laid tangent with its shares, the start continuous as the
// runs turn, random two-run geometries laid tangent or refused. The unit tier keeps the two counts
// and the limits (tests/dynamics/slack_start_test.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "../dynamics/slack_start_checks.hpp"
#include "catena/dynamics/chain.hpp"
#include "catena/dynamics/integrator.hpp"
#include "catena/dynamics/layout.hpp"

namespace catena::dynamics::testing {
namespace {

// 183 and 215 links (the unit tier lays 180 and 199): each run laid tangent with its share, against
// the tests' own tangent catenary, the joints turning by under 1e-9 rad, every link one pitch, a
// roller on every wheel. Before, they were laid between the tangent points, kinked at the wheels by
// 100.5° and 111.5°.
TEST(DynamicsMultispanSlow, TwoSlackSpansAreEachLaidTangentAcrossTheRange) {
  const TwoRuns t = two_lower_runs();
  ASSERT_EQ(t.spans.size(), 2u);
  const double half = (0.5 * std::numbers::pi - 1.0) * t.chords;
  for (const int links : {183, 215}) {
    const std::string what = std::to_string(links) + " links";
    BeltPath laid;
    const LoopPlacement place =
        place_slack_loop(t.path, t.circles, t.teeth, links, kPitch, laid, t.spans);
    ASSERT_EQ(place.s.size(), static_cast<std::size_t>(links)) << what;
    EXPECT_GT(laid.length - t.path.length, half) << what;
    EXPECT_LT(largest_joint_turn(laid), 1e-9) << what;
    for (const int w : place.wrapped) EXPECT_GT(w, 0) << what;
    expect_both_runs_tangent(t, laid, what);
    expect_every_link_one_pitch(loop_state(laid, t.circles, place, 0.0), links, what,
                                1e-11 * links * kPitch);
  }
}

// The start is continuous as the geometry turns: the high wheels from 0.22 to 0.28 m in steps of
// 5 mm (the runs' slopes from 28.8° to 35.0°), 199 links. Every start is laid tangent (the
// joints turning by under 1e-9 rad), and a, the lowest point of the first run and e change from
// one step to the next by at most 1.5 times the mean step's change.
TEST(DynamicsMultispanSlow, TwoSlackSpansStartContinuouslyAsTheRunsTurn) {
  const int links = 199;
  std::vector<double> as, lows, extras;
  for (int q = 0; q <= 12; ++q) {
    const double high = 0.22 + 0.005 * q;
    const std::string what = "high " + std::to_string(high);
    const TwoRuns t = two_lower_runs(high);
    ASSERT_EQ(t.spans.size(), 2u) << what;
    BeltPath laid;
    const LoopPlacement place =
        place_slack_loop(t.path, t.circles, t.teeth, links, kPitch, laid, t.spans);
    ASSERT_EQ(place.s.size(), static_cast<std::size_t>(links)) << what;
    const PathPiece& run = laid.pieces[t.spans[0]];
    ASSERT_TRUE(run.catenary) << what;
    const double turn = largest_joint_turn(laid);
    EXPECT_LT(turn, 1e-9) << what;
    as.push_back(run.hang_a);
    lows.push_back(catenary_lowest(run));
    extras.push_back(laid.length - t.path.length);
    std::printf("%s: a %.3f mm, lowest point %.3f mm, e %.3f mm, turn %.3g rad\n", what.c_str(),
                run.hang_a * 1e3, lows.back() * 1e3, extras.back() * 1e3, turn);
  }
  const std::pair<const char*, const std::vector<double>&> series[] = {
      {"a", as}, {"lowest point", lows}, {"e", extras}};
  for (const auto& [name, v] : series) {
    const auto [mean, most] = step_changes(v);
    EXPECT_LT(most, 1.5 * mean) << name;
    std::printf("%s: the largest step's change %.4g mm, the mean step's %.4g mm\n", name,
                most * 1e3, mean * 1e3);
  }
}

// Random geometries of the two lower runs (the high wheels at 0.18–0.32 m, the lifting back-side
// wheel at 0.12–0.17 m, the four wheels inside with 13 to 30 teeth each, a count from the first
// past the half circle to 60 beyond it; 30 draws of a fixed seed): no NaN, and every start either
// laid — every link one pitch, every node finite, and where laid tangent (the joints turning by
// under 1e-9 rad) each run tangent to its wheels by plain geometry (tangent_fit) with its own extra
// its share e c_k / Σc (1e-9 of its chord) — or not laid (no path given back); the limit
// (`sag_spans_limit`) finite, between the half circle's and the longest catenary's.
TEST(DynamicsMultispanSlow, RandomTwoRunStartsAreLaidTangentOrRefused) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> high(0.18, 0.32), lift(0.12, 0.17);
  std::uniform_int_distribution<int> teeth(13, 30), more(0, 60);
  int tangent = 0, between = 0, refused = 0;
  for (int trial = 0; trial < 30; ++trial) {
    const double h = high(rng), l = lift(rng);
    std::vector<int> z{17, 17, 17, 17, 17, 17};
    for (const std::size_t w : {0u, 1u, 3u, 4u}) z[w] = teeth(rng);
    const TwoRuns t = two_lower_runs(h, l, z);
    const std::string what = "trial " + std::to_string(trial);
    ASSERT_TRUE(t.path.faults.empty()) << what;
    ASSERT_EQ(t.spans.size(), 2u) << what;
    const double half = (0.5 * std::numbers::pi - 1.0) * t.chords;
    const int links = static_cast<int>(std::ceil((t.path.length + half) / kPitch)) + more(rng);
    std::vector<double> tip;
    for (const Circle& c : t.circles) tip.push_back(c.radius + 0.0066);
    const double most = sag_spans_limit(t.path, t.spans, t.circles, tip, {}, kRoller, kPitch);
    EXPECT_TRUE(std::isfinite(most)) << what;
    EXPECT_GE(most, half) << what;
    EXPECT_LE(most, kCatenaryMostExtra * t.chords) << what;
    BeltPath laid;
    const LoopPlacement place =
        place_slack_loop(t.path, t.circles, t.teeth, links, kPitch, laid, t.spans);
    if (place.s.empty()) {
      EXPECT_TRUE(laid.pieces.empty()) << what;
      ++refused;
      continue;
    }
    ASSERT_EQ(place.s.size(), static_cast<std::size_t>(links)) << what;
    const State st = loop_state(laid, t.circles, place, 0.0);
    for (std::size_t i = 0; i < st.nodes(); ++i)
      ASSERT_TRUE(std::isfinite(st.x[i]) && std::isfinite(st.y[i])) << what << " node " << i;
    expect_every_link_one_pitch(st, links, what, 1e-11 * links * kPitch);
    const double e = laid.length - t.path.length;
    EXPECT_TRUE(std::isfinite(e)) << what;
    if (largest_joint_turn(laid) < 1e-9) {
      ++tangent;
      for (const std::size_t k : t.spans) expect_run_tangent_with_share(t, laid, k, what);
    } else {
      ++between;
    }
    std::printf("%s: %d links, %s, e %.3f mm, limit %.3f mm\n", what.c_str(), links,
                largest_joint_turn(laid) < 1e-9 ? "tangent" : "between the tangent points", e * 1e3,
                most * 1e3);
  }
  std::printf("laid tangent %d, between the tangent points %d, not laid %d\n", tangent, between,
              refused);
  EXPECT_GT(tangent, 0);
}

// The band below the half circle from the spans' kinks (`sag_spans_band`) against the counts that
// close laid tangent below the half circle, measured: on the two lower runs at slopes of 37°, 51°
// and 61° (the high wheels 0.3, 0.5 and 0.72 m up), every count from the first whose N p less the
// path's length lies within a pitch below the band's low end up to the first beyond the half
// circle is laid; each laid tangent (its joints turning by under 1e-9 rad) with its e below the
// half circle must close within the band (the limit checks the tangent lay over the band only).
TEST(DynamicsMultispanSlow, CountsLaidTangentBelowTheHalfCircleCloseWithinTheKinksBand) {
  int below = 0;
  for (const double high : {0.3, 0.5, 0.72}) {
    const TwoRuns t = two_lower_runs(high);
    ASSERT_EQ(t.spans.size(), 2u) << high;
    const double half = (0.5 * std::numbers::pi - 1.0) * t.chords;
    const double band = sag_spans_band(t.path, t.spans, kPitch);
    const int first = static_cast<int>(std::floor((t.path.length + half - band) / kPitch)) - 1;
    const int last = static_cast<int>(std::ceil((t.path.length + half) / kPitch));
    double worst = 0.0;
    for (int links = first; links <= last; ++links) {
      BeltPath laid;
      const LoopPlacement place =
          place_slack_loop(t.path, t.circles, t.teeth, links, kPitch, laid, t.spans);
      if (place.s.empty() || !(largest_joint_turn(laid) < 1e-9)) continue;
      const double e = laid.length - t.path.length;
      if (!(e < half)) continue;
      ++below;
      worst = std::max(worst, half - e);
      EXPECT_LE(half - e, band) << high << " " << links;
    }
    std::printf(
        "high wheels %.2f m: the band %.4f p; counts laid tangent close at most %.4f p "
        "below the half circle\n",
        high, band / kPitch, worst / kPitch);
  }
  EXPECT_GT(below, 0);
}

}  // namespace
}  // namespace catena::dynamics::testing
