// `catena wear` as scripts call it: the JSON contract, CSV, errors, case files.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "../read_text.hpp"
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
  const std::string text = read_text(html);
  EXPECT_NE(text.find("Elongation of the rolling-hinge chain"), std::string::npos);
  std::filesystem::remove(html);
}

// tension_source = loop: the articulations' tensions are `catena loop`'s own numbers for the
// same file, at the entry and exit of its sprockets (the tail sprocket, a turn given by a factor,
// and the drive; not the bend guide, given by wrap and friction), and the wear is the wear under
// that list of tensions given by hand, at the loop's speed and path length.
TEST(WearCli, LoadsFromTheLoopAreTheLoopCommandsTensions) {
  const std::string file = kExamples + "/000_wear_loop.toml";
  const auto loop = json_of("loop " + file + " --format json");
  const auto wear = json_of("run " + file)["analyses"]["wear"];
  ASSERT_TRUE(wear.contains("loads")) << wear.dump().substr(0, 200);
  const auto& loads = wear["loads"];
  EXPECT_EQ(loads["source"], "loop");
  // the sprockets, read from `catena loop`'s points by their names in the file
  std::vector<double> expected;
  std::vector<std::string> where;
  for (const auto& p : loop["points"]) {
    const std::string name = p["name"];
    if (name == "tail sprocket" || name == "head drive sprocket") {
      expected.push_back(p["tension"].get<double>());
      where.push_back(name + (p["at"] == "start" ? " entry" : " exit"));
    }
  }
  ASSERT_EQ(expected.size(), 4u);
  ASSERT_EQ(loads["tensions"].size(), 4u);
  ASSERT_EQ(loads["points"].size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(loads["tensions"][i].get<double>(), expected[i]) << where[i];
    EXPECT_EQ(loads["points"][i]["name"].get<std::string>() + " " +
                  loads["points"][i]["at"].get<std::string>(),
              where[i]);
  }
  // the drive: tight side in, slack side out
  EXPECT_EQ(loads["tensions"][2].get<double>(), loop["tight_tension"].get<double>());
  EXPECT_EQ(loads["tensions"][3].get<double>(), loop["slack_tension"].get<double>());
  EXPECT_EQ(loads["speed"].get<double>(), loop["speed"].get<double>());
  EXPECT_EQ(loads["loop_length"].get<double>(), loop["length"].get<double>());
  EXPECT_EQ(loads["speed_from"], "loop");
  EXPECT_EQ(loads["loop_length_from"], "loop");
  EXPECT_EQ(wear["sliding_per_pass"]["articulations"], 4);
  // the same wear from the tensions given by hand
  std::string list;
  for (double t : expected) list += (list.empty() ? "" : ",") + nlohmann::json(t).dump() + "N";
  const auto by_hand =
      json_of("wear --hinge rolling --pitch 125mm --teeth 8 --strokes 2 --tension " + list +
              " --speed " + nlohmann::json(loop["speed"].get<double>()).dump() + " --loop-length " +
              nlohmann::json(loop["length"].get<double>()).dump() +
              "m --wear-coefficient 1e-4 --contact-length 24mm --friction 0.15 --pin-diameter 40mm "
              "--half-thickness 8mm --plate-radius 15mm --format json");
  for (const char* key : {"1.5", "2", "3"})
    EXPECT_NEAR(wear["life_hours"][key].get<double>(), by_hand["life_hours"][key].get<double>(),
                1e-12 * by_hand["life_hours"][key].get<double>())
        << key;
  EXPECT_EQ(wear["elongation"], by_hand["elongation"]);
  // the command line reads the same file's [loop] with --loop
  const auto cli = json_of(
      "wear --hinge rolling --pitch 125mm --teeth 8 --strokes 2 --tension-source loop --loop " +
      file +
      " --wear-coefficient 1e-4 --contact-length 24mm --friction 0.15 --pin-diameter 40mm "
      "--half-thickness 8mm --plate-radius 15mm --format json");
  EXPECT_EQ(cli["loads"], loads);
  EXPECT_EQ(cli["life_hours"], wear["life_hours"]);
}

TEST(WearCli, LoadsFromTheLoopRefuseWhatContradictsIt) {
  const std::string file = kExamples + "/000_wear_loop.toml";
  const std::string base =
      "wear --hinge rolling --pitch 125mm --teeth 8 --strokes 2 --tension-source loop "
      "--wear-coefficient 1e-4 --contact-length 24mm --friction 0.15 --pin-diameter 40mm "
      "--half-thickness 8mm --plate-radius 15mm";
  // no loop to read
  const CliRun none = run(base);
  EXPECT_EQ(none.status, 2);
  EXPECT_NE(none.err.find("--loop = (missing)"), std::string::npos) << none.err;
  // a file without a [loop] table, named as the flag that gave it
  const CliRun empty = run(base + " --loop " + kExamples + "/000_wear_benches.toml");
  EXPECT_EQ(empty.status, 2);
  EXPECT_NE(empty.err.find("--loop = (missing)"), std::string::npos) << empty.err;
  // two sprockets give four articulations; another speed than the loop's
  const CliRun bad = run(base + " --loop " + file + " --articulations 6 --speed 0.5");
  EXPECT_EQ(bad.status, 2);
  for (const char* flag : {"--articulations", "--speed"})
    EXPECT_NE(bad.err.find(flag), std::string::npos) << flag << "\n" << bad.err;
  // the given mode still needs its tension, speed and loop length, each named
  const CliRun given = run(
      "wear --hinge rolling --pitch 125mm --teeth 8 --wear-coefficient 1e-4 --contact-length 24mm "
      "--friction 0.15 --pin-diameter 40mm --half-thickness 8mm --plate-radius 15mm");
  EXPECT_EQ(given.status, 2);
  for (const char* flag : {"--tension", "--speed", "--loop-length"})
    EXPECT_NE(given.err.find(flag), std::string::npos) << flag << "\n" << given.err;
  // a tension given beside the loop is not used, and the output says so
  const auto j = json_of(base + " --loop " + file + " --tension 3.5kN --format json");
  EXPECT_NE(j["diagnostics"].dump().find("wear.tension_not_used"), std::string::npos);
  EXPECT_EQ(j["loads"]["tensions"].size(), 4u);
  // a case file without a [loop] table: named
  const auto tmp = std::filesystem::temp_directory_path() / "catena_wear_noloop.toml";
  {
    std::string text = read_text(kExamples + "/000_wear_benches.toml");
    const auto at = text.find("wear_coefficient = 1e-4\n");
    text.insert(at, "tension_source = \"loop\"\n");
    std::ofstream(tmp) << text;
  }
  const CliRun noloop = run("run " + tmp.string());
  EXPECT_EQ(noloop.status, 2);
  EXPECT_NE(noloop.err.find("[loop]"), std::string::npos) << noloop.err;
  std::filesystem::remove(tmp);
}

}  // namespace
