// The ANSI rating formulas: constants per chain number, the A-series mapping, strand factors.
#include "catena/drive/rating.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace catena::drive {
namespace {

constexpr double kExactTol = 1e-12;  // [1] relative, the same formula evaluated twice

TEST(DriveRating, ConstantsPerChainNumber) {
  for (int n : {25, 35}) {
    const auto c = ansi_constants(n);
    ASSERT_TRUE(c);
    EXPECT_EQ(c->kr, 29.0);
    EXPECT_EQ(c->k, 0.004);
  }
  const auto c41 = ansi_constants(41);
  ASSERT_TRUE(c41);
  EXPECT_EQ(c41->k, 0.0022);
  EXPECT_EQ(c41->kr, 3.4);
  for (int n : {40, 50, 60, 80, 100, 120, 140, 160, 180, 200, 240}) {
    const auto c = ansi_constants(n);
    ASSERT_TRUE(c) << n;
    EXPECT_EQ(c->kr, 17.0);
    EXPECT_EQ(c->k, 0.004);
  }
  EXPECT_FALSE(ansi_constants(30));
  EXPECT_FALSE(ansi_constants(260));
  EXPECT_FALSE(ansi_constants(45));
}

TEST(DriveRating, IsoASeriesMapsToAnsiNumbersAndBSeriesToNothing) {
  EXPECT_EQ(ansi_number("08A"), 40);
  EXPECT_EQ(ansi_number("10a"), 50);
  EXPECT_EQ(ansi_number("12A"), 60);
  EXPECT_EQ(ansi_number("16A"), 80);
  EXPECT_EQ(ansi_number("20A"), 100);
  EXPECT_FALSE(ansi_number("08B"));
  EXPECT_FALSE(ansi_number("12B"));
  EXPECT_FALSE(ansi_number("05B"));
  EXPECT_FALSE(ansi_number("8A"));
}

TEST(DriveRating, StrandFactors) {
  EXPECT_EQ(strand_factor(1), 1.0);
  EXPECT_EQ(strand_factor(2), 1.7);
  EXPECT_EQ(strand_factor(3), 2.5);
  EXPECT_EQ(strand_factor(4), 3.3);
  EXPECT_FALSE(strand_factor(5));
  EXPECT_FALSE(strand_factor(0));
}

// rated = min(H1, H2) × strand factor, in W; the margin is rated / (P K_s); H1 grows with the
// speed, H2 falls, so the governing limit changes from fatigue to impact.
TEST(DriveRating, RatedPowerIsTheLowerEnvelopeTimesTheStrandFactor) {
  const AnsiConstants c = *ansi_constants(40);
  const double pitch = 0.0127;
  double previous_h1 = 0, previous_h2 = 1e300;
  bool fatigue_seen = false, impact_seen = false;
  for (double rpm : {50.0, 200.0, 1000.0, 3000.0, 6000.0}) {
    const Rating r = rate(c, pitch, 17, rpm, 3, 2000.0, 1.3);
    EXPECT_GT(r.plate_fatigue, previous_h1);
    EXPECT_LT(r.roller_impact, previous_h2);
    previous_h1 = r.plate_fatigue;
    previous_h2 = r.roller_impact;
    EXPECT_NEAR(r.rated_power, 2.5 * std::min(r.plate_fatigue, r.roller_impact),
                kExactTol * r.rated_power);
    EXPECT_NEAR(r.design_power, 2600.0, kExactTol * 2600.0);
    EXPECT_NEAR(r.margin, r.rated_power / 2600.0, kExactTol * r.margin);
    (r.governed_by_impact ? impact_seen : fatigue_seen) = true;
  }
  EXPECT_TRUE(fatigue_seen);
  EXPECT_TRUE(impact_seen);
}

}  // namespace
}  // namespace catena::drive
