// `catena hinge` and `catena hinge sweep` as scripts call them: the CLI contract.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "../read_text.hpp"
#include "cli_run.hpp"

namespace {

constexpr double kLengthTol = 1e-12;       // [m] lengths of ~1e-2 m by one formula: round-off
constexpr double kExactLengthTol = 1e-15;  // [m] an input length passed through
constexpr double kMicronTol = 1e-6;  // [m] lengths written here to 1 µm or finer (0.0395033 m)
constexpr double kPitchChangeTol = 1e-8;  // [m] Δt = −4.47004 mm, written to 6 digits
constexpr double kAngleTol = 1e-12;       // [rad] γmax = π/z

const std::string kHinge =
    "hinge --pin-diameter 40mm --half-thickness 8mm --plate-radius 20mm --teeth 8 --strokes 1";

TEST(HingeCli, JsonCarriesTheContractFieldsInSi) {
  const CliRun r = run(kHinge +
                       " --tension 29.4kN --allowable-shear 100MPa --contact-length 24mm "
                       "--modulus 210GPa --poisson 0.3 --allowable-contact 1200MPa --pitch 125mm "
                       "--friction 0.15 --points 101 --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key :
       {"x_N1", "psi1_max", "gamma_max", "R1_max", "R2", "a_min", "rolling_limit", "contact_stress",
        "pitch_change", "trajectories", "diagnostics", "units"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_NEAR(j["x_N1"].get<double>(), 0.014, kLengthTol);
  EXPECT_NEAR(j["R2"].get<double>(), 0.0395033, kMicronTol);
  EXPECT_NEAR(j["gamma_max"].get<double>(), 3.14159265358979 / 8, kAngleTol);
  EXPECT_EQ(j["pitch_change"]["phi"].size(), 101u);
  EXPECT_EQ(j["pitch_change"]["dt_over_t"].size(), 101u);
  EXPECT_EQ(j["pitch_change"]["dt"][0].get<double>(), 0.0);
  EXPECT_NEAR(j["pitch_change"]["dt"][100].get<double>(), -4.47004e-3, kPitchChangeTol);
  for (const char* key : {"phi", "M1x", "M1y", "O2x", "O2y"})
    EXPECT_EQ(j["trajectories"][key].size(), 101u);
  ASSERT_GE(j["diagnostics"].size(), 1u);  // the rolling limit is below γmax
  EXPECT_TRUE(j["diagnostics"][0].contains("code"));
  EXPECT_TRUE(j["diagnostics"][0].contains("message"));
  EXPECT_TRUE(j["diagnostics"][0].contains("limit"));
  EXPECT_EQ(j["units"]["contact_stress"], "Pa");
}

TEST(HingeCli, OptionalResultsAreNullWithoutTheirInputs) {
  const CliRun r = run(kHinge + " --format json --points 3");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["a_min"].is_null());
  EXPECT_TRUE(j["contact_stress"].is_null());
  EXPECT_TRUE(j["rolling_limit"].is_null());
  EXPECT_FALSE(j["pitch_change"].contains("dt_over_t"));
}

TEST(HingeCli, FlatFacesAndCsv) {
  const CliRun r =
      run(kHinge + " --flat --face-half-length 15mm --loaded-length 12mm --points 5 --format csv");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.substr(0, r.out.find('\n')), "phi,dt,M1x,M1y,O2x,O2y");
}

TEST(HingeCli, InfeasibleDesignIsADiagnosticNotAnError) {
  const CliRun r = run(
      "hinge --pin-diameter 40mm --half-thickness 8mm --plate-radius 50mm --teeth 8 --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["diagnostics"][0]["code"], "hinge.r1_exceeds_r1max");
  EXPECT_NEAR(j["diagnostics"][0]["limit"].get<double>(), 0.043149, kMicronTol);
}

TEST(HingeCli, BadInputNamesEveryFlag) {
  const CliRun r =
      run("hinge --pin-diameter 40kg --half-thickness 30mm --plate-radius 20mm --teeth 2");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--pin-diameter = '40kg'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--teeth = '2'"), std::string::npos) << r.err;
  const CliRun s = run(kHinge + " --roller-radius 10mm");
  EXPECT_EQ(s.status, 2);
  EXPECT_NE(s.err.find("--roller-radius"), std::string::npos) << s.err;
}

TEST(HingeCli, SweepPicksTheBestRow) {
  const CliRun refused =
      run("hinge sweep --pin-diameter 40mm --half-thickness 8mm --plate-radius 20mm --teeth 8");
  EXPECT_EQ(refused.status, 2);  // the sweep sets R1 itself: a given R1 is refused, not ignored
  EXPECT_NE(refused.err.find("--plate-radius"), std::string::npos) << refused.err;
  const CliRun s =
      run("hinge sweep --pin-diameter 40mm --half-thickness 8mm --teeth 8 "
          "--tension 29.4kN --contact-length 24mm --count 6 --format json");
  ASSERT_EQ(s.status, 0) << s.err;
  const auto j = nlohmann::json::parse(s.out);
  ASSERT_EQ(j["rows"].size(), 6u);
  ASSERT_FALSE(j["best"].is_null());
  const auto& best = j["rows"][j["best"].get<std::size_t>()];
  for (const auto& row : j["rows"]) {
    if (row["feasible"].get<bool>()) {
      EXPECT_LE(best["contact_stress"].get<double>(), row["contact_stress"].get<double>());
    }
  }
}

}  // namespace

namespace {

TEST(HingeCli, WritesTheApertureAsSvgAndDxf) {
  const auto dir = std::filesystem::temp_directory_path();
  const auto svg = dir / "catena_cli_hinge.svg";
  const auto dxf = dir / "catena_cli_hinge.dxf";
  const CliRun r = run(kHinge + " --clearance 0.3mm --format json --svg " + svg.string() +
                       " --dxf " + dxf.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["aperture"]["clearance"].get<double>(), 0.3e-3, kExactLengthTol);
  EXPECT_NEAR(j["aperture"]["ymin"].get<double>(), -0.0203, kMicronTol);
  const std::string svg_text = read_text(svg), dxf_text = read_text(dxf);
  EXPECT_NE(svg_text.find("</svg>"), std::string::npos);
  EXPECT_NE(dxf_text.find("APERTURE"), std::string::npos);
  EXPECT_NE(dxf_text.find("$INSUNITS"), std::string::npos);
  std::filesystem::remove(svg);
  std::filesystem::remove(dxf);
}

}  // namespace

// A misspelt flag or command is refused (exit 2) with the closest one named; a word far from
// every command gets no guess.
TEST(HingeCli, MisspeltFlagsAndCommandsGetADidYouMean) {
  const CliRun flag =
      run("hinge --pin-diameter 40 --half-thickness 8 --plate-radius 15 --teeth 8 "
          "--pich 125");
  EXPECT_EQ(flag.status, 2);
  EXPECT_NE(flag.err.find("'--pich': did you mean '--pitch'?"), std::string::npos) << flag.err;
  const CliRun sub = run("hinge sweep --pin-diameter 40 --half-thickness 8 --teeth 8 --cont 3");
  EXPECT_EQ(sub.status, 2);
  EXPECT_NE(sub.err.find("did you mean '--count'?"), std::string::npos) << sub.err;
  const CliRun command = run("hinje --pin-diameter 40");
  EXPECT_EQ(command.status, 2);
  EXPECT_NE(command.err.find("'hinje': did you mean 'hinge'?"), std::string::npos) << command.err;
  const CliRun far = run("xylophone");
  EXPECT_EQ(far.status, 2);
  EXPECT_EQ(far.err.find("did you mean"), std::string::npos) << far.err;
}
