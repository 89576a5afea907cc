#include "catena/pocketwheel/geometry.hpp"

#include <gtest/gtest.h>

#include <numbers>
#include <random>

#include "catena/pocketwheel/run_on_numeric.hpp"

namespace catena::pocketwheel {
namespace {

constexpr double kLengthTol = 1e-12;  // [m]
constexpr double kAngleTol = 1e-12;   // [rad]

TEST(WheelGeometry, PitchRadiusEq6IsTheRootOfThePolygonClosure) {
  std::mt19937 rng(6);
  std::uniform_real_distribution<double> pitch(0.01, 0.3);
  std::uniform_real_distribution<double> ratio(0.05, 0.5);
  std::uniform_int_distribution<int> teeth(3, 40);
  for (int i = 0; i < 500; ++i) {
    PocketWheel wheel{pitch(rng), 0.0, teeth(rng)};
    wheel.wire = ratio(rng) * wheel.pitch;
    const WheelGeometry g = wheel_geometry(wheel);
    EXPECT_NEAR(g.pitch_radius, numeric::pitch_radius(wheel), kLengthTol);
    EXPECT_NEAR(g.delta1 + g.delta2, g.tooth_angle, kAngleTol);  // eq. (9)
    EXPECT_NEAR(2.0 * g.pitch_radius * std::sin(g.delta1 / 2), wheel.pitch + wheel.wire,
                kLengthTol);
    EXPECT_NEAR(2.0 * g.pitch_radius * std::sin(g.delta2 / 2), wheel.pitch - wheel.wire,
                kLengthTol);
    EXPECT_GT(g.delta1, g.delta2);
  }
}

TEST(WheelGeometry, ThinWireLimitIsTheRegularPolygon) {
  // d → 0: the polygon becomes regular with 2z sides t, R = t / (2 sin(π/2z)).
  constexpr double kThinWireLengthTol = 1e-9;  // [m] a wire of d = 1e-9 m moves R by O(d)
  constexpr double kThinWireAngleTol = 1e-7;   // [rad] δ1 − δ2 ≈ 1.2e-8 rad for d = 1e-9 m
  const PocketWheel wheel{0.064, 1e-9, 8};
  const WheelGeometry g = wheel_geometry(wheel);
  EXPECT_NEAR(g.pitch_radius, 0.064 / (2.0 * std::sin(std::numbers::pi / 16.0)),
              kThinWireLengthTol);
  EXPECT_NEAR(g.delta1, g.delta2, kThinWireAngleTol);  // δ1 − δ2 ≈ 2d/(R cos(π/2z))
}

TEST(WheelGeometry, ValidateReportsAllProblemsAtOnce) {
  const auto issues = validate(PocketWheel{0.018, 0.064, 2});
  ASSERT_EQ(issues.size(), 2u);
  EXPECT_EQ(issues[0].field, "pitch");
  EXPECT_NE(issues[0].expected.find("greater than the wire diameter"), std::string::npos);
  EXPECT_EQ(issues[1].field, "teeth");
  EXPECT_EQ(validate(PocketWheel{NAN, -1.0, 8}).size(), 2u);
  EXPECT_THROW(wheel_geometry(PocketWheel{0.064, 0.064, 8}), InputError);
}

TEST(WheelGeometry, AWireThickerThanHalfThePitchIsRefusedOnTheWire) {
  // 2d ≤ t: a link's inner length holds its two neighbours' wires. t/2 itself is laid; above it,
  // though t − d > 0 keeps the joint polygon's formulas finite, the chain cannot be assembled.
  EXPECT_TRUE(validate(PocketWheel{0.064, 0.032, 8}).empty());
  const auto issues = validate(PocketWheel{0.064, 0.040, 8});
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].field, "wire");
  EXPECT_NE(issues[0].expected.find("at most t/2 = 0.032 m"), std::string::npos)
      << issues[0].expected;
  // d ≥ t keeps its own message on the pitch, not a second one on the wire
  const auto both = validate(PocketWheel{0.018, 0.064, 8});
  ASSERT_EQ(both.size(), 1u);
  EXPECT_EQ(both[0].field, "pitch");
}

}  // namespace
}  // namespace catena::pocketwheel
