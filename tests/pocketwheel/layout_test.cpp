#include "catena/pocketwheel/layout.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace catena::pocketwheel {
namespace {

const PocketWheel kWheel{0.064, 0.018, 8};  // the paper's chain 18 × 64, z = 8

constexpr double kLengthTol = 1e-12;       // [m] joint radii and link lengths of ~0.1 m
constexpr double kExactLengthTol = 1e-15;  // [m] the guide end, placed from the inputs
constexpr double kInsideTol = 1e-9;        // [m] "not inside the pitch circle", up to round-off

double norm(std::pair<double, double> p) { return std::hypot(p.first, p.second); }
double dist(std::pair<double, double> a, std::pair<double, double> b) {
  return std::hypot(a.first - b.first, a.second - b.second);
}

void check(const Guide& guide) {
  const RunOnPlan plan = plan_run_on(kWheel, guide);
  const ChainLayout layout = chain_layout(kWheel, plan);
  const double r = plan.geometry.pitch_radius, t = kWheel.pitch, d = kWheel.wire;
  ASSERT_GE(layout.seated.size(), 8u);  // half a turn of a 16-joint polygon
  for (const auto& p : layout.seated) EXPECT_NEAR(norm(p), r, kLengthTol);
  // the seated links alternate t + d and t − d, starting with the kind the next one is not
  const bool next_long = plan.first_link > t;
  for (std::size_t i = 0; i + 1 < layout.seated.size(); ++i) {
    const bool long_link = (i % 2 == 0) != next_long;
    EXPECT_NEAR(dist(layout.seated[i], layout.seated[i + 1]), long_link ? t + d : t - d, kLengthTol)
        << i;
  }
  // the next joint up the strand (first_link from the crank, on the straight span) is not yet
  // inside the pitch circle: the crank is the last seated joint at φ = 0
  const auto c = layout.seated.front();
  const auto s = layout.strand[1];
  const double len = dist(c, s);
  ASSERT_GT(len, plan.first_link);
  const std::pair<double, double> next{c.first + (s.first - c.first) * plan.first_link / len,
                                       c.second + (s.second - c.second) * plan.first_link / len};
  EXPECT_GE(norm(next), r - kInsideTol);
  EXPECT_EQ(layout.strand.front(), c);
}

TEST(ChainLayout, SeatedJointsAndStrandAreConsistentWithThePlan) {
  check(Guide{GuideKind::kNone});
  check(Guide{GuideKind::kChordal, 0.0, 0.256});
  check(Guide{GuideKind::kTangential, 0.0, 0.256});
  check(Guide{GuideKind::kTangential, 0.0, 0.256, SpanModel::kPivot});
  const RunOnPlan plan = plan_run_on(kWheel, Guide{GuideKind::kTangential, 0.0, 0.256});
  const ChainLayout guided = chain_layout(kWheel, plan);
  ASSERT_EQ(guided.strand.size(), 3u);
  EXPECT_NEAR(guided.strand[1].first, -0.256, kExactLengthTol);  // the guide end E = (−l, H)
  EXPECT_NEAR(guided.strand[1].second, plan.guide_height, kExactLengthTol);
}

}  // namespace
}  // namespace catena::pocketwheel
