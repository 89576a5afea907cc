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

// 08A (p = 12.7 mm), 17/51 teeth: the pitch circles touch at r1 + r2 [mm].
double touching_08a_17_51() {
  const double pi = std::acos(-1.0);
  return 12.7 / (2 * std::sin(pi / 17)) + 12.7 / (2 * std::sin(pi / 51));
}

// The valid centre distances are a window: the pitch circles apart (more than r1 + r2) and at
// most the 100000 links --links allows. Beyond it, a centre distance is refused as that flag
// would be, with the window named: before, 1e12 mm asked X = 1.05e11 links (cut to an int:
// 1907661562) and 1e9 mm solved a 10⁸-link wrap for minutes; a tiny one, whose Δ²p/a term
// grows without bound, exited 1 (1e-3 mm: 139482 links beyond the exact solver's range; 1e-9 mm:
// 1.39e11 beyond round_up_even's; 1e-320 m: an infinite count).
TEST(DriveCli, CentreDistanceOutsideItsWindowIsRefused) {
  for (const char* a : {"1e12mm", "1e9mm", "1e300mm", "1e-3mm", "1e-9mm", "1e-320m", "100mm"}) {
    const CliRun r = run(kDrive + "--center-distance " + a + " --service-factor 1");
    EXPECT_EQ(r.status, 2) << a << ": " << r.out << r.err;
    EXPECT_NE(r.err.find("--center-distance"), std::string::npos) << a << ": " << r.err;
    const std::string window = "that needs at most 100000 links: more than r1 + r2 = ";
    const std::size_t at = r.err.find(window);
    ASSERT_NE(at, std::string::npos) << a << ": " << r.err;
    const double touch = std::stod(r.err.substr(at + window.size()));
    EXPECT_NEAR(touch, touching_08a_17_51(), 1e-5 * touch) << a << ": " << r.err;
    EXPECT_NE(r.err.find(" mm, at most ", at), std::string::npos) << a << ": " << r.err;
  }
  // just apart: the least chain round both sprockets, solved
  char apart[64];
  std::snprintf(apart, sizeof apart, "%.9gmm", touching_08a_17_51() * (1 + 1e-6));
  const CliRun ok = run(kDrive + "--center-distance " + apart + " --service-factor 1");
  EXPECT_EQ(ok.status, 0) << ok.err;
}

// The window is checked with the other inputs: every problem reported at once.
TEST(DriveCli, LayoutProblemsAreReportedWithTheOthers) {
  for (const char* length :
       {"--center-distance 1e12mm", "--center-distance 1e-3mm", "--links 20"}) {
    const CliRun r =
        run("drive --chain 08A --teeth 17,51 --speed 1000rpm --power=-3kW "
            "--mass-per-metre 0.6kg/m --service-factor 1 " +
            std::string(length));
    EXPECT_EQ(r.status, 2) << length << ": " << r.err;
    EXPECT_NE(r.err.find("--power"), std::string::npos) << length << ": " << r.err;
    const std::string flag = std::string(length).substr(0, std::string(length).find(' '));
    EXPECT_NE(r.err.find(flag + " = "), std::string::npos) << length << ": " << r.err;
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

// Finite tensions beyond the layout's ±1e307 N (a slack tension of 2e307 N): the shaft load is
// still the formula's, |((t + s) cos γ, (t − s) sin γ)| with t and s the spans' pulls less the
// centrifugal tension and γ = asin((r2 − r1)/a) — recomputed here from the output's tensions and
// centre distance. (A pull along the line of centres, t + s, missed it by 0.18 %.)
TEST(DriveCli, HugeFiniteTensionsKeepTheShaftLoadFormula) {
  const CliRun r =
      run("drive --chain 12B --teeth 17,34 --links 100 --power 5kW --slack-tension 2e307N "
          "--speed 2e-303 --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const double pi = std::acos(-1.0), p = 0.01905;
  const double r1 = p / (2 * std::sin(pi / 17)), r2 = p / (2 * std::sin(pi / 34));
  ASSERT_EQ(j["units"]["center_distance"], "m");
  const double a = j["center_distance"].get<double>();
  const double gamma = std::asin((r2 - r1) / a);
  const double c = j["tension"]["centrifugal"].get<double>();
  const double t = j["tension"]["tight"].get<double>() - c,
               s = j["tension"]["slack"].get<double>() - c;
  ASSERT_GT(t, 1e307);
  const double load = std::hypot((t + s) * std::cos(gamma), (t - s) * std::sin(gamma));
  EXPECT_NEAR(j["shaft_load"]["driver"].get<double>(), load, 1e-12 * load);
  EXPECT_EQ(j["shaft_load"]["driven"], j["shaft_load"]["driver"]);
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
