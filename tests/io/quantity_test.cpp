#include "catena/io/quantity.hpp"

#include <gtest/gtest.h>

#include <numbers>

namespace catena::io {
namespace {

constexpr double kRelTol = 1e-12;  // [1] relative, unit conversions: round-off
// [SI unit of the quantity] keeps the bound positive when the expected value is 0
constexpr double kZeroFloorTol = 1e-300;
constexpr double kDeg = std::numbers::pi / 180.0;

double parse(const char* text, QuantityKind kind) { return parse_quantity(text, kind, "--flag"); }

struct Accepted {
  const char* text;
  QuantityKind kind;
  double si;
};

class AcceptedSpelling : public ::testing::TestWithParam<Accepted> {};

TEST_P(AcceptedSpelling, ConvertsToSi) {
  const Accepted& c = GetParam();
  EXPECT_NEAR(parse(c.text, c.kind), c.si, kRelTol * std::abs(c.si) + kZeroFloorTol) << c.text;
}

INSTANTIATE_TEST_SUITE_P(
    Spellings, AcceptedSpelling,
    ::testing::Values(
        Accepted{"64mm", QuantityKind::kLength, 0.064},
        Accepted{"64 mm", QuantityKind::kLength, 0.064},
        Accepted{"0.064m", QuantityKind::kLength, 0.064},
        Accepted{"64", QuantityKind::kLength, 0.064},  // bare: mm
        Accepted{"  64  ", QuantityKind::kLength, 0.064},
        Accepted{"2.5in", QuantityKind::kLength, 0.0635},
        Accepted{"1.5e3 mm", QuantityKind::kLength, 1.5},
        Accepted{"5 1/s", QuantityKind::kAngularSpeed, 5.0},
        Accepted{"5", QuantityKind::kAngularSpeed, 5.0},  // bare: 1/s
        Accepted{"5 rad/s", QuantityKind::kAngularSpeed, 5.0},
        Accepted{"5 s-1", QuantityKind::kAngularSpeed, 5.0},
        Accepted{"47.75 rpm", QuantityKind::kAngularSpeed, 47.75 * std::numbers::pi / 30.0},
        Accepted{"60 rev/min", QuantityKind::kAngularSpeed, 2.0 * std::numbers::pi},
        Accepted{"20deg", QuantityKind::kAngle, 20.0 * kDeg},
        Accepted{"20 degree", QuantityKind::kAngle, 20.0 * kDeg},
        Accepted{"20°", QuantityKind::kAngle, 20.0 * kDeg},
        Accepted{"20", QuantityKind::kAngle, 20.0 * kDeg},  // bare: degree
        Accepted{"42 arcmin", QuantityKind::kAngle, 0.7 * kDeg},
        Accepted{"0°42'", QuantityKind::kAngle, 0.7 * kDeg},
        Accepted{"3°26′", QuantityKind::kAngle, (3.0 + 26.0 / 60.0) * kDeg},
        Accepted{"1°30'36\"", QuantityKind::kAngle, 1.51 * kDeg},
        Accepted{"0.5 rad", QuantityKind::kAngle, 0.5},
        Accepted{"29.4kN", QuantityKind::kForce, 29400.0},
        Accepted{"1200", QuantityKind::kForce, 1200.0},
        Accepted{"210GPa", QuantityKind::kStress, 210e9},
        Accepted{"350", QuantityKind::kStress, 350e6},  // bare: MPa
        Accepted{"40kg", QuantityKind::kMass, 40.0}, Accepted{"500 g", QuantityKind::kMass, 0.5},
        Accepted{"2 min", QuantityKind::kTime, 120.0},
        Accepted{"20 Hz", QuantityKind::kFrequency, 20.0},
        Accepted{"20", QuantityKind::kFrequency, 20.0},  // bare: Hz
        Accepted{"1200 1/min", QuantityKind::kFrequency, 20.0},
        Accepted{"2 kHz", QuantityKind::kFrequency, 2000.0},
        Accepted{"0", QuantityKind::kLength, 0.0},  // zero, which UDUNITS cannot scale by
        Accepted{"0mm", QuantityKind::kLength, 0.0}, Accepted{"0 m", QuantityKind::kLength, 0.0},
        Accepted{"-5 mm", QuantityKind::kLength, -0.005},
        Accepted{"0.5 m/s", QuantityKind::kSpeed, 0.5},
        Accepted{"0.5", QuantityKind::kSpeed, 0.5},  // bare: m/s
        Accepted{"30 m/min", QuantityKind::kSpeed, 0.5},
        Accepted{"1.8 km/h", QuantityKind::kSpeed, 0.5},
        Accepted{"150 N/m", QuantityKind::kForcePerLength, 150.0},
        Accepted{"150", QuantityKind::kForcePerLength, 150.0},  // bare: N/m
        Accepted{"0.15 kN/m", QuantityKind::kForcePerLength, 150.0},
        Accepted{"0.15 N/mm", QuantityKind::kForcePerLength, 150.0},
        Accepted{"10 kgf/m", QuantityKind::kForcePerLength, 98.0665},
        Accepted{"22.7mm^2", QuantityKind::kArea, 22.7e-6},
        Accepted{"22.7", QuantityKind::kArea, 22.7e-6},  // bare: mm^2
        Accepted{"2.56g/cm^3", QuantityKind::kDensity, 2560.0},
        Accepted{"1200", QuantityKind::kDensity, 1200.0},  // bare: kg/m^3
        Accepted{"7.5kW", QuantityKind::kPower, 7500.0},
        Accepted{"7.5", QuantityKind::kPower, 7500.0},  // bare: kW
        Accepted{"750 W", QuantityKind::kPower, 750.0},
        Accepted{"10 hp", QuantityKind::kPower, 7456.999},  // UDUNITS-2: 745.6999 W
        Accepted{"1.25 kg/m", QuantityKind::kMassPerLength, 1.25},
        Accepted{"1.25", QuantityKind::kMassPerLength, 1.25},  // bare: kg/m
        Accepted{"1250 g/m", QuantityKind::kMassPerLength, 1.25}));

struct Rejected {
  const char* text;
  QuantityKind kind;
  const char* why;  // a fragment the message must contain
};

class RejectedSpelling : public ::testing::TestWithParam<Rejected> {};

TEST_P(RejectedSpelling, NamesFlagValueAndExpectation) {
  const Rejected& c = GetParam();
  std::vector<Issue> issues;
  EXPECT_FALSE(parse_quantity(c.text, c.kind, "--pitch", issues).has_value()) << c.text;
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].field, "--pitch");
  EXPECT_EQ(issues[0].value, std::string("'") + c.text + "'");
  EXPECT_NE(issues[0].expected.find(c.why), std::string::npos) << issues[0].expected;
}

INSTANTIATE_TEST_SUITE_P(
    Spellings, RejectedSpelling,
    ::testing::Values(Rejected{"5kg", QuantityKind::kLength, "wrong dimension"},
                      Rejected{"", QuantityKind::kLength, "empty"},
                      Rejected{"abc", QuantityKind::kLength, "UDUNITS-2"},
                      Rejected{"mm", QuantityKind::kLength, "UDUNITS-2"},
                      Rejected{"5 furlongs/fortnight", QuantityKind::kLength, "wrong dimension"},
                      Rejected{"nan", QuantityKind::kLength, "not finite"},
                      Rejected{"inf mm", QuantityKind::kLength, "a length"},
                      Rejected{"1e999", QuantityKind::kLength, "not finite"},
                      Rejected{"5 Hz", QuantityKind::kAngularSpeed, "Hz"},
                      Rejected{"5 kHz", QuantityKind::kAngularSpeed, "Hz"},
                      Rejected{"300 1/min", QuantityKind::kAngularSpeed, "ambiguous"},
                      Rejected{"5 m/s", QuantityKind::kAngularSpeed, "wrong dimension"},
                      Rejected{"2 mm/m", QuantityKind::kAngle, "no angle unit"},
                      Rejected{"3 m/m", QuantityKind::kAngle, "no angle unit"},
                      Rejected{"20 mm", QuantityKind::kAngle, "wrong dimension"},
                      Rejected{"3 MPa", QuantityKind::kForce, "wrong dimension"},
                      Rejected{"20 rpm", QuantityKind::kFrequency, "does not count cycles"},
                      Rejected{"5 rad/s", QuantityKind::kFrequency, "does not count cycles"},
                      Rejected{"5 N", QuantityKind::kFrequency, "wrong dimension"},
                      Rejected{"5 1/s", QuantityKind::kSpeed, "wrong dimension"},
                      Rejected{"5 rpm", QuantityKind::kSpeed, "wrong dimension"},
                      Rejected{"5 m", QuantityKind::kSpeed, "wrong dimension"},
                      Rejected{"15 kg/m", QuantityKind::kForcePerLength, "kgf/m"},
                      Rejected{"150 N", QuantityKind::kForcePerLength, "wrong dimension"},
                      Rejected{"150 Pa", QuantityKind::kForcePerLength, "wrong dimension"},
                      Rejected{"3kg", QuantityKind::kArea, "wrong dimension"},
                      Rejected{"1200 kg/m", QuantityKind::kDensity, "wrong dimension"},
                      Rejected{"7.5 kN", QuantityKind::kPower, "wrong dimension"},
                      Rejected{"1.25 N/m", QuantityKind::kMassPerLength, "wrong dimension"}));

// Outcomes are remembered (sweeps read the same texts at every point): a text read again, by
// another field or as another kind, gives what the parser gives the first time.
TEST(Quantity, ARememberedOutcomeIsTheParsersOwnForThatTextAndKind) {
  for (int round = 0; round < 2; ++round) {
    std::vector<Issue> issues;
    EXPECT_EQ(parse_quantity("20", QuantityKind::kLength, "a", issues), 0.020);
    EXPECT_EQ(parse_quantity("20", QuantityKind::kAngle, "b", issues), 20 * kDeg);
    EXPECT_FALSE(parse_quantity("8 kg", QuantityKind::kLength, "c", issues).has_value());
    EXPECT_FALSE(parse_quantity("8 kg", QuantityKind::kLength, "d", issues).has_value());
    EXPECT_EQ(parse_quantity("8 kg", QuantityKind::kMass, "e", issues), 8.0);
    ASSERT_EQ(issues.size(), 2u) << round;
    EXPECT_EQ(issues[0].field, "c");
    EXPECT_EQ(issues[1].field, "d");
    EXPECT_EQ(issues[0].expected, issues[1].expected);
    EXPECT_NE(issues[0].expected.find("wrong dimension"), std::string::npos);
  }
}

// Found by fuzzing (tests/fuzz/regressions/quantity/): a degrees-minutes-seconds part too long
// for a double escaped as std::out_of_range from std::stod, an internal error.
TEST(Quantity, AnOverlongDegreesMinutesSecondsPartIsReadNotThrown) {
  const std::string huge = "1" + std::string(400, '0') + "°30'";    // 1e400 degrees
  const std::string tiny = "0." + std::string(400, '0') + "1°30'";  // 1e-401 degrees and 30'
  const std::string huge_minutes = "1°" + std::string(400, '9') + "'";
  std::vector<Issue> issues;
  EXPECT_FALSE(parse_quantity(huge, QuantityKind::kAngle, "--skew", issues).has_value());
  EXPECT_FALSE(parse_quantity(huge_minutes, QuantityKind::kAngle, "--skew", issues).has_value());
  ASSERT_EQ(issues.size(), 2u);
  EXPECT_NE(issues[0].expected.find("not finite"), std::string::npos) << issues[0].expected;
  EXPECT_NE(issues[1].expected.find("not finite"), std::string::npos) << issues[1].expected;
  EXPECT_NEAR(parse(tiny.c_str(), QuantityKind::kAngle), 0.5 * kDeg, kRelTol * 0.5 * kDeg);
}

TEST(Quantity, ThrowingOverloadCarriesTheIssue) {
  try {
    parse_quantity("5kg", QuantityKind::kLength, "--pitch");
    FAIL();
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("--pitch = '5kg'"), std::string::npos) << error.what();
  }
}

TEST(Quantity, DefaultUnitsAreDocumented) {
  EXPECT_STREQ(default_unit(QuantityKind::kLength), "mm");
  EXPECT_STREQ(default_unit(QuantityKind::kAngularSpeed), "1/s");
  EXPECT_STREQ(default_unit(QuantityKind::kForce), "N");
  EXPECT_STREQ(default_unit(QuantityKind::kStress), "MPa");
  EXPECT_STREQ(default_unit(QuantityKind::kAngle), "degree");
  EXPECT_STREQ(si_unit(QuantityKind::kAngularSpeed), "rad/s");
  EXPECT_STREQ(default_unit(QuantityKind::kSpeed), "m/s");
  EXPECT_STREQ(si_unit(QuantityKind::kSpeed), "m/s");
  EXPECT_STREQ(default_unit(QuantityKind::kForcePerLength), "N/m");
  EXPECT_STREQ(si_unit(QuantityKind::kForcePerLength), "N/m");
}

}  // namespace
}  // namespace catena::io

namespace {

// UDUNITS-2's composed factors can be a few ulps off an exact decimal; the parser gives the
// decimal (docs/units.md). rpm's 2π/60 is no short decimal and stays as it is.
TEST(Quantity, ExactDecimalFactorsStayExact) {
  using catena::io::parse_quantity;
  using catena::io::QuantityKind;
  EXPECT_EQ(parse_quantity("2.56 g/cm^3", QuantityKind::kDensity, "rho"), 2.56 * 1000.0);
  EXPECT_EQ(parse_quantity("1 g/cm^3", QuantityKind::kDensity, "rho"), 1000.0);
  EXPECT_EQ(parse_quantity("64mm", QuantityKind::kLength, "pitch"), 64 * 0.001);
  EXPECT_EQ(parse_quantity("60 rpm", QuantityKind::kAngularSpeed, "omega"),
            60 * (2.0 * 3.14159265358979323846 / 60.0));
}

}  // namespace
