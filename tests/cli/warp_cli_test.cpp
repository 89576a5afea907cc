// `catena warp` as scripts call it: sweeps, formats, SI JSON with units and diagnostics, errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "cli_run.hpp"

namespace {

constexpr double kForceTol = 1e-6;    // [N] ΣF of ~3e4 N joint forces against F
constexpr double kShareTol = 1e-9;    // [1] the upper share (F12 + F22)/(F11 + F21) − 1
constexpr double kLengthTol = 1e-12;  // [m] a 1 mm clearance passed through

const std::string kWarp =
    "warp --heights 0,10mm,50mm,60mm --stiffness 2e8 --widths 8mm --roller-diameter 24mm ";

TEST(WarpCli, JsonSweepCarriesContractFields) {
  const CliRun r = run(kWarp + "--force 30kN,40kN --load-height 30mm,36mm,42mm --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["points"].size(), 6u);
  EXPECT_TRUE(j.contains("units"));
  EXPECT_TRUE(j["diagnostics"].is_array());
  for (const auto& p : j["points"]) {
    double sum = 0;
    for (const char* k : {"F21", "F11", "F12", "F22"}) sum += p["joint_force"][k].get<double>();
    EXPECT_NEAR(sum, p["force"].get<double>(), kForceTol);
    EXPECT_TRUE(p["solver"]["converged"].get<bool>());
  }
  // symmetric layout, equal joints, load at mid-height: equal upper and lower loads
  EXPECT_NEAR(j["points"][0]["upper_share"].get<double>(), 0.0, kShareTol);
}

TEST(WarpCli, CsvAndTable) {
  const CliRun csv = run(kWarp + "--force 30kN --load-height 30mm,40mm --format csv");
  ASSERT_EQ(csv.status, 0) << csv.err;
  EXPECT_EQ(csv.out.rfind("force,load_height,F21", 0), 0u);
  EXPECT_EQ(std::count(csv.out.begin(), csv.out.end(), '\n'), 3);
  const CliRun table = run(kWarp + "--force 30kN --load-height 30mm");
  ASSERT_EQ(table.status, 0) << table.err;
  EXPECT_NE(table.out.find("F12 [kN]"), std::string::npos);
}

TEST(WarpCli, OpenJointIsADiagnosticWithItsLimit) {
  const CliRun r = run(kWarp +
                       "--clearances 0,0,0,1mm --force 10kN --load-height 30mm "
                       "--format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  bool found = false;
  for (const auto& d : j["diagnostics"])
    if (d["code"] == "warp.joint_open.F22") {
      found = true;
      EXPECT_NEAR(d["limit"].get<double>(), 1e-3, kLengthTol);
    }
  EXPECT_TRUE(found) << r.out;
}

TEST(WarpCli, ASweepReportsEachDiagnosticOnceAtItsWorstPoint) {
  // the open joint fires at every (F, L1) of the sweep: one entry, counted, at the worst point
  const CliRun r = run(kWarp +
                       "--clearances 0,0,0,1mm --force 5kN,10kN --load-height 28mm,30mm "
                       "--format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  int entries = 0;
  for (const auto& d : j["diagnostics"]) {
    if (d["code"] != "warp.joint_open.F22") continue;
    ++entries;
    EXPECT_EQ(d["points"].get<int>(), 4);
    // its value is the largest over the four points of the sweep
    const CliRun one =
        run(kWarp + "--clearances 0,0,0,1mm --force " + std::to_string(d["force"].get<double>()) +
            "N --load-height " + std::to_string(d["load_height"].get<double>() * 1e3) +
            "mm --format json");
    ASSERT_EQ(one.status, 0) << one.err;
    const auto single = nlohmann::json::parse(one.out);  // named: the loop must not outlive it
    for (const auto& e : single["diagnostics"]) {
      if (e["code"] == d["code"]) {
        EXPECT_DOUBLE_EQ(e["value"].get<double>(), d["value"].get<double>());
      }
    }
  }
  EXPECT_EQ(entries, 1) << r.out;
}

TEST(WarpCli, InvalidInputListsEveryProblemAndExits2) {
  const CliRun missing = run("warp --hinge rolling --force 3kN");
  EXPECT_EQ(missing.status, 2);
  for (const char* flag : {"--heights", "--stiffness", "--widths", "--pin-diameter",
                           "--plate-radius", "--roller-radius", "--load-height"})
    EXPECT_NE(missing.err.find(flag), std::string::npos) << flag << "\n" << missing.err;
  const CliRun bad =
      run("warp --heights 0,10mm,5mm,60mm --stiffness -1 --widths 8mm --roller-diameter 24mm "
          "--force -3kN --load-height 90mm");
  EXPECT_EQ(bad.status, 2);
  for (const char* what : {"F12 height", "stiffness", "force", "load"})
    EXPECT_NE(bad.err.find(what), std::string::npos) << what << "\n" << bad.err;
  EXPECT_EQ(run(kWarp + "--force 3kN,x --load-height 30mm").status, 2);
  EXPECT_EQ(run(kWarp + "--force 3kN --load-height 30mm --stiffness 1,2").status, 2);
}

}  // namespace
