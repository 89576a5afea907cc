// `catena engagement` as scripts call it: the CLI contract.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "cli_run.hpp"

namespace {

constexpr double kResidualTol = 1e-9;  // [1] equilibrium residual, relative to the load
constexpr double kAngleTol = 1e-12;    // [rad] the last point's γ = π/2
// [N] the thesis prints F2 to 0.1 kN: half a unit at its start (29.4 kN, = F1 for any flank)
constexpr double kStartForceTol = 50.0;
// [N] at γΣ = 90° F1 ⟂ F2, so |F_N| = √(F1² + F2²) up to the two rolling forces c_r·F ≈ 30 N
constexpr double kEndBalanceTol = 100.0;
constexpr double kForceTol = 1e-9;  // [N] the rolling resistance c_r·F2 ≈ 29.4 N: round-off

const std::string kSliding =
    "engagement --hinge sliding --pitch 125mm --teeth 8 --strokes 2 --tension 29.4kN "
    "--friction 0.15";
const std::string kRolling =
    "engagement --hinge rolling --pitch 125mm --teeth 8 --strokes 2 --tension 29.4kN "
    "--pin-diameter 40mm --half-thickness 8mm --plate-radius 15mm";

TEST(EngagementCli, SlidingJsonCarriesTheContractFieldsInSi) {
  const CliRun r = run(kSliding + " --points 31 --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"series", "roller_turns", "diagnostics", "units"})
    EXPECT_TRUE(j.contains(key)) << key;
  for (const char* key : {"gamma", "F2", "FN", "xi", "rolling_resistance", "residual"}) {
    ASSERT_TRUE(j["series"].contains(key)) << key;
    EXPECT_EQ(j["series"][key].size(), 31u) << key;
  }
  EXPECT_NEAR(j["series"]["gamma"][30].get<double>(), 3.14159265358979 / 2, kAngleTol);
  EXPECT_TRUE(j["series"]["xi"][0].is_null());  // no ξ for a sliding hinge
  for (const auto& v : j["series"]["residual"]) EXPECT_LE(v.get<double>(), kResidualTol);
  EXPECT_EQ(j["units"]["F2"], "N");
  EXPECT_EQ(j["units"]["gamma"], "rad");
  EXPECT_TRUE(j["roller_turns"].is_array());
  EXPECT_EQ(j["wrap"]["rollers"], 2);
  EXPECT_EQ(j["wrap"]["tension"].size(), 3u);
  EXPECT_EQ(j["units"]["torque"], "N*m");
}

TEST(EngagementCli, RollingJsonAndCsv) {
  const CliRun r = run(kRolling + " --flank-angle 21.6deg --points 11 --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["series"]["F2"][0].get<double>(), 29.4e3, kStartForceTol);
  // The flank 21.6° is fitted to the thesis' F2(γΣ) = 12.7 kN (docs/models/engagement.md), so
  // F2's end value is not asserted; the roller's force balance across the JSON fields is.
  const double f2_end = j["series"]["F2"][10].get<double>();
  EXPECT_NEAR(j["series"]["FN"][10].get<double>(), std::hypot(29.4e3, f2_end), kEndBalanceTol);
  // the larger of c_r·F1 and c_r·F2: at γ = 0 F2 starts just above F1 (both resistances press
  // the roller onto the tooth, F_N(0) > 0)
  const double f2_start = j["series"]["F2"][0].get<double>();
  EXPECT_GT(f2_start, 29.4e3);
  EXPECT_GT(j["series"]["FN"][0].get<double>(), 0.0);
  EXPECT_NEAR(j["series"]["rolling_resistance"][0].get<double>(), 1e-3 * f2_start, kForceTol);
  for (const auto& v : j["series"]["residual"]) EXPECT_LE(v.get<double>(), kResidualTol);
  EXPECT_GE(j["roller_turns"].size(), 1u);
  const CliRun c = run(kRolling + " --points 5 --format csv");
  ASSERT_EQ(c.status, 0) << c.err;
  EXPECT_EQ(c.out.substr(0, c.out.find('\n')), "gamma,F2,FN,xi,rolling_resistance,residual");
  EXPECT_EQ(std::count(c.out.begin(), c.out.end(), '\n'), 6);
}

TEST(EngagementCli, TableRuns) {
  const CliRun r = run(kSliding);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("roller turns"), std::string::npos);
}

TEST(EngagementCli, InvalidInputExitsTwoWithEveryProblem) {
  const CliRun r = run("engagement --hinge wobbly --pitch -5mm --tension 3kg --strokes 0");
  EXPECT_EQ(r.status, 2);
  for (const char* flag : {"--hinge", "--teeth", "--tension", "--strokes"})
    EXPECT_NE(r.err.find(flag), std::string::npos) << flag << "\n" << r.err;
  const CliRun mixed = run(kSliding + " --plate-radius 34mm --rolling-coefficient 0.01");
  EXPECT_EQ(mixed.status, 2);
  EXPECT_NE(mixed.err.find("--plate-radius"), std::string::npos);
  EXPECT_NE(mixed.err.find("--rolling-coefficient"), std::string::npos);
  const CliRun rolling = run(kRolling + " --friction 0.1");
  EXPECT_EQ(rolling.status, 2);
  EXPECT_NE(rolling.err.find("--friction"), std::string::npos);
  const CliRun flank = run(kRolling + " --flank-angle 60deg --rolling-coefficient -1");
  EXPECT_EQ(flank.status, 2);
  EXPECT_NE(flank.err.find("--flank-angle"), std::string::npos) << flank.err;
  EXPECT_NE(flank.err.find("--rolling-coefficient"), std::string::npos) << flank.err;
  const CliRun wrap = run(kSliding + " --wrap-angle 400deg");
  EXPECT_EQ(wrap.status, 2);
  EXPECT_NE(wrap.err.find("--wrap-angle"), std::string::npos);
  const CliRun missing = run("engagement --hinge rolling --pitch 125mm --teeth 8 --tension 1kN");
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("--pin-diameter"), std::string::npos);
}

TEST(EngagementCli, LockedSlidingHingeIsADiagnosticNotAnError) {
  // f = 1, the largest accepted since issue 18, above tan ε(γΣ) = tan(45° − 10°) = 0.70
  const CliRun r =
      run("engagement --hinge sliding --pitch 125mm --teeth 8 --strokes 2 --tension 29.4kN "
          "--friction 1 --flank-angle 10deg --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_GE(j["diagnostics"].size(), 1u);
  EXPECT_EQ(j["diagnostics"][0]["code"], "engagement.link2_slack");
}

}  // namespace

// A sprocket torque of 0 (radial tooth normals) says why, and what the chain's tension drop puts
// on the sprocket instead; a tilted flank has a torque and no such line.
TEST(EngagementCli, AZeroTorqueIsExplained) {
  const std::string radial =
      "engagement --hinge sliding --pitch 125mm --teeth 8 --strokes 2 "
      "--tension 29.4kN ";
  const CliRun frictionless = run(radial);
  ASSERT_EQ(frictionless.status, 0) << frictionless.err;
  EXPECT_NE(frictionless.out.find("sprocket torque 0 kN*m"), std::string::npos);
  EXPECT_NE(frictionless.out.find("the tension passes every roller unchanged"), std::string::npos)
      << frictionless.out;
  const CliRun friction = run(radial + "--friction 0.15");
  ASSERT_EQ(friction.status, 0) << friction.err;
  EXPECT_NE(friction.out.find("the tension drop times R·cos(gammaSigma/2), 0.509906 kN*m"),
            std::string::npos)
      << friction.out;
  const CliRun tilted = run(radial + "--friction 0.15 --flank-angle 20deg");
  ASSERT_EQ(tilted.status, 0) << tilted.err;
  EXPECT_EQ(tilted.out.find("radial tooth normals"), std::string::npos) << tilted.out;
}
