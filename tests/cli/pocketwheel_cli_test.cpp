// `catena pocketwheel` as scripts call it: the CLI contract.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "cli_run.hpp"

namespace {

constexpr double kMicronTol = 1e-6;        // [m] R = 0.164283 m, written here to 1 µm
constexpr double kExactLengthTol = 1e-15;  // [m] the same radius under two names
constexpr double kTimeTol = 1e-12;         // [s] the tooth period 2π/(zω) ≈ 0.16 s
constexpr double kAngleTol = 1e-12;        // [rad] the last sample's φ = 2π/z
constexpr double kForceTol = 1e-9;         // [N] −m·a_x for a 40 kg strand: round-off
constexpr double kSpeedTol = 1e-9;         // [m/s] the numerical solver against the closed form

const char* kPaper = "pocketwheel --pitch 64mm --wire 18mm --teeth 8 --omega 5";

TEST(PocketwheelCli, JsonCarriesTheContractFieldsInSi) {
  const CliRun r =
      run(std::string(kPaper) +
          " --guide tangential --guide-end 256mm --strand-mass 40kg --points 721 --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"pitch_radius", "delta1", "delta2", "transverse_displacement", "period",
                          "guide_height", "seating_angles", "extremes", "series", "units"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_NEAR(j["pitch_radius"].get<double>(), 0.164283, kMicronTol);
  EXPECT_NEAR(j["guide_height"].get<double>(), j["pitch_radius"].get<double>(), kExactLengthTol);
  EXPECT_NEAR(j["period"].get<double>(), 2 * 3.14159265358979 / 8 / 5, kTimeTol);
  for (const char* key : {"vx_min", "vx_max", "ax_min", "ax_max"})
    EXPECT_TRUE(j["extremes"].contains(key));
  const auto& s = j["series"];
  for (const char* key : {"phi", "time", "x", "vx", "ax", "inertial_force"}) {
    ASSERT_TRUE(s.contains(key)) << key;
    EXPECT_EQ(s[key].size(), 721u) << key;
  }
  EXPECT_FALSE(s.contains("vy")) << "vy only for free run-on";
  EXPECT_EQ(s["x"][0].get<double>(), 0.0);
  EXPECT_NEAR(s["phi"][720].get<double>(), 2 * 3.14159265358979 / 8, kAngleTol);
  EXPECT_NEAR(s["inertial_force"][5].get<double>(), -40.0 * s["ax"][5].get<double>(), kForceTol);
  for (const char* key :
       {"pitch_radius", "period", "x", "vx", "ax", "inertial_force", "seating_angles"}) {
    EXPECT_TRUE(j["units"].contains(key)) << key;
  }
  EXPECT_EQ(j["units"]["ax"], "m/s^2");
  EXPECT_TRUE(r.err.empty()) << "stderr must stay quiet on success: " << r.err;
}

TEST(PocketwheelCli, FreeRunOnHasTransverseSeriesAndNullGuideHeight) {
  const CliRun r = run(std::string(kPaper) + " --guide none --points 5 --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["guide_height"].is_null());
  EXPECT_EQ(j["series"]["vy"].size(), 5u);
  EXPECT_EQ(j["series"]["ay"].size(), 5u);
}

TEST(PocketwheelCli, CsvIsAHeaderAndTheSeries) {
  const CliRun r = run(std::string(kPaper) + " --guide chordal --points 11 --format csv");
  ASSERT_EQ(r.status, 0) << r.err;
  std::istringstream in(r.out);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, "phi,time,x,vx,ax");
  int rows = 0;
  for (std::string line; std::getline(in, line);) ++rows;
  EXPECT_EQ(rows, 11);
}

TEST(PocketwheelCli, UnitsAreAcceptedInAnySpelling) {
  const CliRun a =
      run("pocketwheel --pitch 0.064m --wire '18 mm' --teeth 8 --omega '47.746 rpm' --format json "
          "--points 3");
  const CliRun b =
      run("pocketwheel --pitch 64 --wire 18 --teeth 8 --omega 5 --format json --points 3");
  ASSERT_EQ(a.status, 0) << a.err;
  ASSERT_EQ(b.status, 0) << b.err;
  constexpr double kRpmTol = 1e-4;  // [rad/s] 47.746 rpm is 5 rad/s to 5 digits (4.99995)
  EXPECT_NEAR(nlohmann::json::parse(a.out)["omega"].get<double>(), 5.0, kRpmTol);
  EXPECT_EQ(nlohmann::json::parse(a.out)["pitch_radius"],
            nlohmann::json::parse(b.out)["pitch_radius"]);
}

TEST(PocketwheelCli, BadInputNamesEveryFlagAndWritesNothing) {
  const auto out = std::filesystem::temp_directory_path() / "catena_cli_should_not_exist.json";
  std::filesystem::remove(out);
  const CliRun r =
      run("pocketwheel --pitch 5kg --wire 18mm --teeth 2 --omega '5 Hz' --format json --output " +
          out.string());
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(r.out.empty());
  EXPECT_FALSE(std::filesystem::exists(out));
  EXPECT_NE(r.err.find("--pitch = '5kg'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("wrong dimension"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--teeth = '2'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--omega = '5 Hz'"), std::string::npos) << r.err;
}

TEST(PocketwheelCli, InfeasibleGeometryStatesTheLimit) {
  CliRun r = run("pocketwheel --pitch 18mm --wire 18mm --teeth 8 --omega 5");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("greater than the wire diameter"), std::string::npos) << r.err;
  r = run("pocketwheel --pitch 64mm --wire 40mm --teeth 8 --omega 5");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--wire = 0.04 m: expected a wire diameter d at most t/2 = 0.032 m"),
            std::string::npos)
      << r.err;
  r = run(std::string(kPaper) + " --guide tangential --guide-end 100mm");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(
      r.err.find(
          "--guide-end = 0.1 m: expected a guide end outside the pitch circle: l > R = 0.164283 m"),
      std::string::npos)
      << r.err;
  r = run(std::string(kPaper) + " --guide height --guide-height 150mm");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--guide-height"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("0.159085 m"), std::string::npos) << r.err;
  r = run(std::string(kPaper) + " --guide chordal --guide-end 165mm");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("l ≥ 0.169"), std::string::npos) << r.err;
  r = run(std::string(kPaper) + " --guide height");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("required with --guide height"), std::string::npos) << r.err;
}

TEST(PocketwheelCli, OutputFileAndCsvSideFile) {
  const auto dir = std::filesystem::temp_directory_path();
  const auto json = dir / "catena_cli_out.json";
  const auto csv = dir / "catena_cli_out.csv";
  const CliRun r = run("pocketwheel --example --format json --output " + json.string() + " --csv " +
                       csv.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(r.out.empty());
  const auto j = nlohmann::json::parse(read_text(json));
  ASSERT_TRUE(j.is_array());
  EXPECT_EQ(j.size(), 3u);  // free, chordal, tangential
  std::istringstream in(read_text(csv));
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header.rfind("phi,time,x_none,vx_none,ax_none,vy_none,ay_none,x_chordal", 0), 0u)
      << header;
  std::filesystem::remove(json);
  std::filesystem::remove(csv);
}

TEST(PocketwheelCli, NumericMethodAgreesWithClosedForms) {
  const CliRun a = run(std::string(kPaper) + " --guide tangential --format json --points 101");
  const CliRun b =
      run(std::string(kPaper) + " --guide tangential --format json --points 101 --method numeric");
  ASSERT_EQ(a.status, 0);
  ASSERT_EQ(b.status, 0);
  const auto ja = nlohmann::json::parse(a.out);
  const auto jb = nlohmann::json::parse(b.out);
  for (std::size_t i = 1; i + 1 < 101; ++i) {
    EXPECT_NEAR(ja["series"]["vx"][i].get<double>(), jb["series"]["vx"][i].get<double>(),
                kSpeedTol);
  }
}

}  // namespace

namespace {

TEST(PocketwheelCli, CommandLineErrorsExitWithStatus2AndNothingHalfWritten) {
  EXPECT_EQ(run("pocketwheel --example --format yaml").status, 2);
  EXPECT_EQ(run("pocketwheel --example --no-such-flag").status, 2);
  EXPECT_EQ(run("").status, 2);
  EXPECT_EQ(run("--version").status, 0);
  const auto csv = std::filesystem::temp_directory_path() / "catena_cli_partial.csv";
  std::filesystem::remove(csv);
  const CliRun r =
      run("pocketwheel --example --csv " + csv.string() + " --output /nonexistent/dir/x.json");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--output"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(csv)) << "the CSV must not be left behind";
}

}  // namespace
