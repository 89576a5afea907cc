// `catena drive` and `catena drive select` as scripts call them: the JSON contract of issue 16
// §3, the link rounding and offset-link diagnostics, refusals naming the flag, the B-series
// diagnostic, the drawing.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "../read_text.hpp"
#include "cli_run.hpp"

namespace {

constexpr double kRelTol = 1e-12;  // [1] the same numbers in two fields

const std::string kDrive =
    "drive --chain 08A --teeth 17,51 --speed 1000rpm --power 3kW --mass-per-metre 0.6kg/m ";

bool has_code(const nlohmann::json& j, const std::string& code) {
  for (const auto& d : j["diagnostics"])
    if (d["code"] == code) return true;
  return false;
}

TEST(DriveCli, JsonCarriesTheContractFields) {
  const CliRun r = run(kDrive + "--center-distance 500mm --service-factor 1.3 --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"links", "center_distance", "center_distance_formula", "chain_length",
                          "speed_ratio", "chain_speed", "chordal_variation", "wrap_angle",
                          "span_length", "tension", "shaft_load", "rating", "units", "diagnostics"})
    EXPECT_TRUE(j.contains(key)) << key;
  for (const char* key : {"driver", "driven"}) {
    EXPECT_TRUE(j["wrap_angle"][key].is_number()) << key;
    EXPECT_TRUE(j["shaft_load"][key].is_number()) << key;
  }
  for (const char* key : {"tight", "centrifugal"}) EXPECT_TRUE(j["tension"][key].is_number());
  for (const char* key :
       {"plate_fatigue", "roller_impact", "rated_power", "design_power", "margin"})
    EXPECT_TRUE(j["rating"][key].is_number()) << key;
  EXPECT_EQ(j["links"].get<int>() % 2, 0);
  EXPECT_TRUE(has_code(j, "drive.links_rounded_up"));
  EXPECT_EQ(j["units"]["center_distance"], "m");
  EXPECT_NEAR(j["rating"]["design_power"].get<double>(), 3900.0, kRelTol * 3900.0);
  // v = z1 p n1: 17 × 12.7 mm × 1000/60 s⁻¹
  EXPECT_NEAR(j["chain_speed"].get<double>(), 17 * 0.0127 * 1000 / 60.0, kRelTol);
}

TEST(DriveCli, OddLinksNeedAnOffsetLink) {
  const CliRun r = run(kDrive + "--links 101 --service-factor 1 --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["links"].get<int>(), 101);
  EXPECT_TRUE(has_code(j, "drive.offset_link"));
}

TEST(DriveCli, RefusalsNameTheFlag) {
  // rating an A-series chain needs the service factor: no invented default
  CliRun r = run(kDrive + "--links 100");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--service-factor"), std::string::npos) << r.err;
  // one of the centre distance and the link count
  r = run(kDrive + "--links 100 --center-distance 500mm --service-factor 1");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("not both"), std::string::npos) << r.err;
  r = run(kDrive + "--service-factor 1");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--center-distance"), std::string::npos) << r.err;
  // the catalogue has no mass per metre yet: the centrifugal tension needs it
  r =
      run("drive --chain 08A --teeth 17,51 --speed 1000rpm --power 3kW --links 100 "
          "--service-factor 1");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--mass-per-metre"), std::string::npos) << r.err;
  r =
      run("drive --chain 08A --teeth 17 --speed 1000rpm --power 3kW --mass-per-metre 0.6kg/m "
          "--links 100 --service-factor 1");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--teeth"), std::string::npos) << r.err;
  r = run(kDrive + "--links 20 --service-factor 1");  // shorter than round both sprockets
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--links"), std::string::npos) << r.err;
  r = run(kDrive + "--links 100 --service-factor 1 --strands 5");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--strands"), std::string::npos) << r.err;
}

// A centre distance that needs more links than --links allows (100000) is refused as that flag
// would be: before, 1e12 mm came out as 696057022 links (the count of 1.05e14 cut to an int) and
// 1e9 mm solved a 10⁸-link wrap for minutes.
TEST(DriveCli, CentreDistanceBeyondTheLinkCountIsRefused) {
  for (const char* a : {"1e12mm", "1e9mm", "1e300mm"}) {
    const CliRun r = run(kDrive + "--center-distance " + a + " --service-factor 1");
    EXPECT_EQ(r.status, 2) << a << ": " << r.out;
    EXPECT_NE(r.err.find("--center-distance"), std::string::npos) << a << ": " << r.err;
    EXPECT_NE(r.err.find("at most 100000 links: at most "), std::string::npos)
        << a << ": " << r.err;
  }
}

// Tensions that overflow (a speed of 1e-310 rad/s: the effective pull P/v is infinite) leave the
// shaft loads infinite, reported as not finite, the analysis run (the layout's shaft_loads
// refuses such tensions); at 1e-300 rad/s (P/v = 9.7e304 N) they are computed.
TEST(DriveCli, OverflowingTensionsLeaveTheShaftLoadsInfinite) {
  const std::string drive = "drive --chain 12B --teeth 17,34 --links 100 --power 5kW --speed ";
  CliRun r = run(drive + "1e-310 --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["tension"]["tight"].is_null());
  EXPECT_TRUE(j["shaft_load"]["driver"].is_null());
  EXPECT_TRUE(j["shaft_load"]["driven"].is_null());
  EXPECT_NE(r.err.find("'shaft_load.driver' is not finite (+inf)"), std::string::npos) << r.err;
  EXPECT_TRUE(j["center_distance"].is_number());
  r = run(drive + "1e-300 --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["shaft_load"]["driver"].get<double>(), j["tension"]["tight"].get<double>(),
              1e-12 * j["tension"]["tight"].get<double>());
}

TEST(DriveCli, BSeriesIsNotRatedAndSaysSo) {
  const CliRun r =
      run("drive --chain 12B --teeth 17,34 --speed 500rpm --power 5kW --mass-per-metre 1.2kg/m "
          "--links 110 --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_FALSE(j.contains("rating"));
  EXPECT_TRUE(has_code(j, "drive.no_rating"));
}

TEST(DriveCli, TableAndDrawing) {
  const auto dir = std::filesystem::temp_directory_path();
  const auto svg = dir / "catena_cli_drive.svg", dxf = dir / "catena_cli_drive.dxf";
  const CliRun r = run(kDrive + "--links 100 --service-factor 1 --svg " + svg.string() + " --dxf " +
                       dxf.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("centre distance, polygon wrap"), std::string::npos) << r.out;
  const std::string svg_text = read_text(svg), dxf_text = read_text(dxf);
  EXPECT_NE(svg_text.find("<svg"), std::string::npos);
  EXPECT_NE(dxf_text.find("CHAIN"), std::string::npos);
  std::filesystem::remove(svg);
  std::filesystem::remove(dxf);
}

TEST(DriveCli, SelectListsChainsWithTheirMargin) {
  const CliRun r =
      run("drive select --power 5kW --speed 900rpm --ratio 3 --service-factor 1.4 --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_FALSE(j["candidates"].empty());
  double previous = 0;
  for (const auto& c : j["candidates"]) {
    EXPECT_GE(c["margin"].get<double>(), 1.0);
    EXPECT_GE(c["pitch"].get<double>(), previous);
    previous = c["pitch"].get<double>();
  }
  EXPECT_TRUE(has_code(j, "drive.select.unrated"));
  const CliRun missing = run("drive select --power 5kW --speed 900rpm --ratio 3");
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("--service-factor"), std::string::npos) << missing.err;
}

// The example case runs `drive` as the command line does, and the report draws its layout.
TEST(DriveCli, ExampleCaseGivesWhatTheCommandGives) {
  const std::string example = std::string(CATENA_EXAMPLES_DIR) + "/drive_12B.toml";
  const CliRun c = run("run " + example);
  ASSERT_EQ(c.status, 0) << c.err;
  const CliRun d =
      run("drive --chain 12B --teeth 17,34 --center-distance 600mm --speed 500rpm --power 5kW "
          "--slack 2mm --format json");
  ASSERT_EQ(d.status, 0) << d.err;
  EXPECT_EQ(nlohmann::json::parse(c.out)["analyses"]["drive"], nlohmann::json::parse(d.out));
  const CliRun s = run("sprocket --chain 12B --teeth 17 --format json");
  ASSERT_EQ(s.status, 0) << s.err;
  EXPECT_EQ(nlohmann::json::parse(c.out)["analyses"]["sprocket"], nlohmann::json::parse(s.out));
  const auto html = std::filesystem::temp_directory_path() / "catena_cli_drive_report.html";
  const CliRun r = run("report " + example + " -o " + html.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string text = read_text(html);
  EXPECT_NE(text.find("<div class=\"drawing\">"), std::string::npos);
  EXPECT_NE(text.find("Taut centre distance of the polygon wrap"), std::string::npos);
  std::filesystem::remove(html);
}

}  // namespace
