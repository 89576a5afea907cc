// `catena wear` as scripts call it: the JSON contract, CSV, errors, case files.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "cli_run.hpp"

namespace {

constexpr double kRelTol = 1e-9;  // [1] a closed form of the sliding hinge: round-off
const std::string kExamples = CATENA_EXAMPLES_DIR;

const std::string kCommon =
    "--pitch 125mm --teeth 8 --strokes 2 --tension 3.5kN --speed 0.34 --loop-length 10m "
    "--wear-coefficient 1e-4 --contact-length 24mm --friction 0.15";
const std::string kRolling = "wear --hinge rolling " + kCommon +
                             " --pin-diameter 40mm --half-thickness 8mm --plate-radius 15mm";
const std::string kSliding = "wear --hinge sliding " + kCommon;

nlohmann::json json_of(const std::string& args) {
  const CliRun r = run(args);
  EXPECT_EQ(r.status, 0) << args << "\n" << r.err;
  return r.status == 0 ? nlohmann::json::parse(r.out) : nlohmann::json{};
}

TEST(WearCli, JsonCarriesTheContractFields) {
  const auto j = json_of(kRolling + " --format json");
  for (const char* key : {"elongation", "life_hours", "wear_depth", "sliding_per_pass",
                          "calibration", "units", "diagnostics"})
    EXPECT_TRUE(j.contains(key)) << key;
  ASSERT_EQ(j["elongation"]["hours"].size(), j["elongation"]["percent"].size());
  EXPECT_GT(j["elongation"]["hours"].size(), 100u);
  for (const char* key : {"1.5", "2", "3"}) ASSERT_TRUE(j["life_hours"][key].is_number()) << key;
  EXPECT_LT(j["life_hours"]["1.5"].get<double>(), j["life_hours"]["2"].get<double>());
  EXPECT_LT(j["life_hours"]["2"].get<double>(), j["life_hours"]["3"].get<double>());
  // the thesis' chain: pivots ("rollers") and plates wear; it has no pin and no bush
  EXPECT_GT(j["wear_depth"]["roller"].get<double>(), 0.0);
  EXPECT_GT(j["wear_depth"]["plate"].get<double>(), 0.0);
  EXPECT_TRUE(j["wear_depth"]["pin"].is_null());
  EXPECT_TRUE(j["wear_depth"]["bush"].is_null());
  EXPECT_EQ(j["units"]["hours"], "h");
  EXPECT_EQ(j["units"]["percent"], "%");
  EXPECT_EQ(j["units"]["roller"], "m");
  EXPECT_EQ(j["calibration"]["fitted"], false);
  // friction alone rolls to eq. (21)'s 6.5 deg of a 45 deg plate turn: the rest slides (diagnosed)
  EXPECT_NE(j["diagnostics"].dump().find("wear.slides_beyond_rolling_limit"), std::string::npos);
  // the last point reaches the last limit
  EXPECT_GE(j["elongation"]["percent"].back().get<double>(), 3.0);
}

TEST(WearCli, SlidingHingeSlidesTheNeckThroughTheMutualTurn) {
  const auto j = json_of(kSliding + " --format json");
  const double pi = 3.14159265358979323846;
  // 4 articulations of 90 deg, the 40 mm neck: 4 * 20 mm * pi/2 in link 1's bores
  EXPECT_NEAR(j["sliding_per_pass"]["link1"].get<double>(), 4 * 0.020 * pi / 2, kRelTol * 0.1257);
  EXPECT_EQ(j["sliding_per_pass"]["link2"].get<double>(), 0.0);
  EXPECT_EQ(j["hinge"], "sliding");
}

TEST(WearCli, TableAndCsv) {
  const CliRun t = run(kSliding);
  ASSERT_EQ(t.status, 0) << t.err;
  EXPECT_NE(t.out.find("limit[%]"), std::string::npos);
  const CliRun c = run(kSliding + " --format csv");
  ASSERT_EQ(c.status, 0) << c.err;
  EXPECT_EQ(c.out.rfind("hours,percent,roller,plate", 0), 0u) << c.out.substr(0, 80);
}

TEST(WearCli, InvalidInputExitsTwoNamingEveryField) {
  const CliRun r =
      run("wear --hinge sliding --pitch 125mm --teeth 8 --tension -3kN --speed 0.34 "
          "--loop-length 10m --wear-coefficient 3 --contact-length 24mm "
          "--friction 0.15 --limits 1.5,80");
  EXPECT_EQ(r.status, 2);
  for (const char* flag : {"--tension", "--wear-coefficient", "--limits"})
    EXPECT_NE(r.err.find(flag), std::string::npos) << flag << "\n" << r.err;
  const CliRun mixed = run(kSliding + " --plate-radius 15mm");
  EXPECT_EQ(mixed.status, 2);
  EXPECT_NE(mixed.err.find("--plate-radius"), std::string::npos) << mixed.err;
  const CliRun missing = run("wear --hinge rolling " + kCommon);
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("--pin-diameter"), std::string::npos) << missing.err;
}

TEST(WearCli, ATensionPerArticulation) {
  // the slack side of the loop carries nothing: half the sliding of four loaded articulations
  const auto j = json_of(
      "wear --hinge sliding --pitch 125mm --teeth 8 --strokes 2 "
      "--tension 3.5kN,3.5kN,0,0 --speed 0.34 --loop-length 10m "
      "--wear-coefficient 1e-4 --contact-length 24mm --friction 0.15 "
      "--format json");
  EXPECT_EQ(j["sliding_per_pass"]["articulations"], 4);
  EXPECT_NEAR(j["sliding_per_pass"]["link1"].get<double>(), 2 * 0.020 * 3.14159265358979 / 2,
              1e-12);
  const CliRun bad =
      run("wear --hinge sliding --pitch 125mm --teeth 8 --strokes 2 --tension 3.5kN,1kN "
          "--articulations 4 --speed 0.34 --loop-length 10m --wear-coefficient 1e-4 "
          "--contact-length 24mm --friction 0.15");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("--tension"), std::string::npos) << bad.err;
}

TEST(WearCli, CaseFilesRunTheSameAnalysis) {
  const auto rolling = json_of("run " + kExamples + "/000_wear_benches.toml");
  ASSERT_TRUE(rolling["analyses"].contains("wear"));
  EXPECT_EQ(rolling["analyses"]["wear"], json_of(kRolling + " --format json"));
  EXPECT_EQ(rolling["analyses"]["wear-guided"],
            json_of(kRolling + " --rolling-limit guided --format json"));
  const auto sliding = json_of("run " + kExamples + "/000_wear_sliding.toml");
  EXPECT_EQ(sliding["analyses"]["wear"], json_of(kSliding + " --format json"));
  // the report renders the wear sections with their elongation charts
  const auto html = std::filesystem::temp_directory_path() / "catena_wear_report.html";
  const CliRun report = run("report " + kExamples + "/000_wear_benches.toml -o " + html.string());
  ASSERT_EQ(report.status, 0) << report.err;
  std::ifstream in(html);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("Elongation of the rolling-hinge chain"), std::string::npos);
  std::filesystem::remove(html);
}

}  // namespace
