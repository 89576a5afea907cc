// Reproductions of published numbers for the chain drive (docs/models/drive.md):
// * issue 16's check value of the ANSI envelopes: #40, N1 = 17, 1000 rpm → H1 ≈ 5.48 hp,
//   H2 ≈ 21.6 hp;
// * Mott, Machine Elements in Mechanical Design, 4th ed., Example Problem 7-3: no. 40 chain
//   (p = 0.5 in), N1 = 17, N2 = 65, C = 30 pitches → L = 102.9 pitches, specified 104;
//   C = 30.54 pitches = 15.272 in; D1 = 2.721 in, D2 = 10.349 in.
// Each value is computed from the inputs and compared with the source's printed digits.
#include <gtest/gtest.h>

#include "catena/drive/layout.hpp"
#include "catena/drive/rating.hpp"

namespace catena::drive {
namespace {

constexpr double kInch = 0.0254;
// tolerances: half a unit of the source's last printed digit
constexpr double kHp2Digits = 0.005;  // [hp] "5.48"
constexpr double kHp1Digit = 0.05;    // [hp] "21.6"
constexpr double kPitches1 = 0.05;    // [1] "102.9", "30.54" is 0.005
constexpr double kPitches2 = 0.005;   // [1]
constexpr double kInch3 = 0.0005;     // [in] "15.272", "2.721", "10.349"

TEST(DriveReference, AnsiCheckValueOfTheIssue) {
  const AnsiConstants c = *ansi_constants(*ansi_number("08A"));
  EXPECT_EQ(c.number, 40);
  EXPECT_NEAR(plate_fatigue_hp(c, 17, 1000, 0.5), 5.48, kHp2Digits);
  EXPECT_NEAR(roller_impact_hp(c, 17, 1000, 0.5), 21.6, kHp1Digit);
}

TEST(DriveReference, MottExampleProblem7_3) {
  const double p = 0.5 * kInch;
  const int n1 = 17, n2 = 65;
  EXPECT_NEAR(2 * pitch_radius(p, n1) / kInch, 2.721, kInch3);
  EXPECT_NEAR(2 * pitch_radius(p, n2) / kInch, 10.349, kInch3);
  const double links = links_for(p, n1, n2, 30 * p);
  EXPECT_NEAR(links, 102.9, kPitches1);
  EXPECT_EQ(round_up_even(links), 104);  // "Specify the integer length, L = 104 pitches"
  const double c = center_distance_formula(p, n1, n2, 104);
  EXPECT_NEAR(c / p, 30.54, kPitches2);
  EXPECT_NEAR(c / kInch, 15.272, kInch3);
}

}  // namespace
}  // namespace catena::drive
