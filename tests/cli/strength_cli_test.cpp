// `catena strength` as scripts call it: the JSON contract (SI, units, checks, diagrams, contact,
// diagnostics), table and CSV, the layouts, both hinge types, and every input error at once.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>

#include "cli_run.hpp"

namespace {

// Tolerances. The JSON is SI with doubles at full precision: the CLI's values differ from the
// hand values below by round-off only (loads ~1e4 N, moments ~1e2 N·m, stresses ~1e7-1e9 Pa).
constexpr double kRatioTol = 1e-9;       // [1] safety factors and their ratios
constexpr double kForceTol = 1e-9;       // [N] plate forces
constexpr double kResultantTol = 1e-6;   // [N] |N| of ~3e4 N through a square root
constexpr double kMomentTol = 1e-9;      // [N·m] bending moments
constexpr double kLengthTol = 1e-12;     // [m] the contact chord c, ~4e-2 m
constexpr double kStressTol = 1e-3;      // [Pa] hand formulas for stresses of ~5e7 Pa
constexpr double kFineStressTol = 1e-6;  // [Pa] the same Hertz pressure (~3e8 Pa) in two places
constexpr double kHertzRelTol = 1e-6;    // [1] relative, the mean pressure against p0

const std::string kHinge =
    "strength --heights '0, 8 mm, 48 mm, 56 mm' --widths 8mm --pin-diameter 40mm "
    "--plate-width 90mm --end-distance 45mm --tension 30kN --roller-yield 600MPa "
    "--plate-yield 400MPa ";
const std::string kSliding = kHinge + "--allowable-pressure 60MPa ";
const std::string kRolling =
    kHinge +
    "--hinge rolling --plate-radius 34mm --roller-radius 35.4mm --allowable-contact 1600MPa ";

nlohmann::json run_json(const std::string& args) {
  const CliRun r = run(args + " --format json");
  EXPECT_EQ(r.status, 0) << args << "\n" << r.err;
  return r.status == 0 ? nlohmann::json::parse(r.out) : nlohmann::json{};
}

TEST(StrengthCli, JsonCarriesTheContract) {
  const auto j = run_json(kSliding);
  for (const char* key : {"checks", "diagrams", "contact", "diagnostics", "units", "layouts"})
    EXPECT_TRUE(j.contains(key)) << key;
  const nlohmann::json checks = j["checks"];
  ASSERT_FALSE(checks.empty());
  for (const auto& c : checks) {
    for (const char* key : {"name", "section", "stress", "allowable", "safety_factor", "ok"})
      EXPECT_TRUE(c.contains(key)) << key;
    EXPECT_NEAR(c["safety_factor"].get<double>(),
                c["allowable"].get<double>() / c["stress"].get<double>(), kRatioTol);
  }
  // both layouts by default, each with its diagram; by hand (symmetric, N = S at mid-height):
  // layout 1: M_max = S/2 · 28 mm = 420 N·m, layout 2: S/2 · 20 mm = 300 N·m
  ASSERT_TRUE(j["diagrams"].contains("layout_1"));
  ASSERT_TRUE(j["diagrams"].contains("layout_2"));
  EXPECT_NEAR(j["layouts"]["layout_1"]["moment_max"].get<double>(), 420.0, kMomentTol);
  EXPECT_NEAR(j["layouts"]["layout_2"]["moment_max"].get<double>(), 300.0, kMomentTol);
  const nlohmann::json d = j["diagrams"]["layout_1"];
  ASSERT_EQ(d["x"].size(), d["M"].size());
  ASSERT_EQ(d["x"].size(), d["Q"].size());
  double mmax = 0;
  for (const auto& m : d["M"]) mmax = std::max(mmax, std::abs(m.get<double>()));
  EXPECT_NEAR(mmax, 420.0, kMomentTol);
  // the sliding hinge's contact: eq. (22) with γ = 180°: c = d; eq. (23) p = 15 kN/(40 × 8 mm²)
  EXPECT_NEAR(j["contact"]["c"].get<double>(), 0.040, kLengthTol);
  EXPECT_NEAR(j["contact"]["p"].get<double>(), 15e3 / (0.040 * 0.008), kStressTol);
  EXPECT_TRUE(j["contact"]["hertz"].is_null());
  EXPECT_EQ(j["units"]["stress"], "Pa");
  EXPECT_EQ(j["units"]["M"], "N*m");
  EXPECT_TRUE(j["diagnostics"].empty());
}

TEST(StrengthCli, RollingHingeGivesHertz) {
  const auto j = run_json(kRolling);
  ASSERT_TRUE(j["contact"]["hertz"].is_object());
  const double p0 = j["contact"]["hertz"]["p0"].get<double>();
  EXPECT_NEAR(j["contact"]["p"].get<double>(), std::numbers::pi / 4 * p0, kHertzRelTol * p0);
  bool found = false;
  for (const auto& c : j["checks"])
    if (c["name"] == "hinge.contact") {
      found = true;
      EXPECT_NEAR(c["stress"].get<double>(), p0, kFineStressTol);
    }
  EXPECT_TRUE(found);
}

TEST(StrengthCli, OneLayoutAndSafetyFactorsScaleWithLoad) {
  const auto one = run_json(kSliding + "--layout 2");
  EXPECT_FALSE(one["diagrams"].contains("layout_1"));
  EXPECT_TRUE(one["diagrams"].contains("layout_2"));
  const auto twice = run_json(
      "strength --heights '0, 8 mm, 48 mm, 56 mm' --widths 8mm --pin-diameter 40mm "
      "--plate-width 90mm --end-distance 45mm --tension 60kN --roller-yield 600MPa "
      "--plate-yield 400MPa --allowable-pressure 60MPa --layout 2");
  ASSERT_EQ(one["checks"].size(), twice["checks"].size());
  for (std::size_t i = 0; i < one["checks"].size(); ++i)
    EXPECT_NEAR(one["checks"][i]["safety_factor"].get<double>() /
                    twice["checks"][i]["safety_factor"].get<double>(),
                2.0, kRatioTol);
}

TEST(StrengthCli, FailingCheckIsADiagnosticWithTheLimit) {
  const auto j = run_json(kHinge + "--allowable-pressure 30MPa");  // p = 46.9 MPa
  ASSERT_FALSE(j["diagnostics"].empty());
  bool found = false;
  for (const auto& d : j["diagnostics"])
    if (d["code"] == "strength.hinge.pressure") {
      found = true;
      EXPECT_EQ(d["severity"], "infeasible");
      EXPECT_NEAR(d["limit"].get<double>(), 30e6, kStressTol);
      EXPECT_NEAR(d["value"].get<double>(), 15e3 / (0.040 * 0.008), kStressTol);
    }
  EXPECT_TRUE(found);
}

TEST(StrengthCli, TableAndCsv) {
  const CliRun table = run(kSliding);
  ASSERT_EQ(table.status, 0) << table.err;
  for (const char* s : {"roller.bending", "plate.shear_out", "hinge.pressure", "eq. (23)"})
    EXPECT_NE(table.out.find(s), std::string::npos) << s;
  const CliRun csv = run(kSliding + "--format csv");
  ASSERT_EQ(csv.status, 0) << csv.err;
  EXPECT_EQ(csv.out.rfind("layout,x,M,Q\n", 0), 0u);
  const auto j = run_json(kSliding);
  const auto rows = static_cast<std::size_t>(std::count(csv.out.begin(), csv.out.end(), '\n'));
  EXPECT_EQ(rows,
            1 + j["diagrams"]["layout_1"]["x"].size() + j["diagrams"]["layout_2"]["x"].size());
}

TEST(StrengthCli, EveryProblemAtOnceExitTwo) {
  const CliRun r =
      run("strength --heights '0, 8 mm, 48 mm, 56 mm' --widths 8mm --pin-diameter 40mm "
          "--plate-width 30mm --hole-diameter 41mm --end-distance 10mm --tension 30kN "
          "--tooth-force 40kN --roller-yield -3 --load-height 80mm --hinge rolling "
          "--plate-radius 34mm --roller-radius 30mm");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(r.out.empty());
  for (const char* flag :
       {"--plate-yield", "--allowable-contact", "--hole-diameter", "--end-distance",
        "--tooth-force", "--roller-yield", "--load-height", "--roller-radius"})
    EXPECT_NE(r.err.find(flag), std::string::npos) << flag << "\n" << r.err;
  EXPECT_EQ(run(kSliding + "--layout 3").status, 2);
  std::string bad_unit = kSliding;
  bad_unit.replace(bad_unit.find("30kN"), 4, "3parsec");
  EXPECT_EQ(run(bad_unit).status, 2);
}

TEST(StrengthCli, LinksAtAnAngle) {
  // θ = 90°: the tooth takes S along the chain line and S2 sideways, |N| = √(S² + S2²)
  const auto j = run_json(kSliding + "--exit-tension 10kN --link-angle 90");
  const nlohmann::json l1 = j["layouts"]["layout_1"];
  EXPECT_NEAR(l1["tooth_force"].get<double>(), std::hypot(30e3, 10e3), kResultantTol);
  ASSERT_TRUE(l1.contains("plate_force_y"));
  EXPECT_NEAR(l1["plate_force_y"]["lower_inner"].get<double>() +
                  l1["plate_force_y"]["upper_inner"].get<double>(),
              10e3, kForceTol);
  const nlohmann::json d = j["diagrams"]["layout_1"];
  for (const char* key : {"My", "Qy", "M_resultant", "Q_resultant"})
    EXPECT_EQ(d[key].size(), d["x"].size()) << key;
  double mmax = 0;
  for (const auto& m : d["M_resultant"]) mmax = std::max(mmax, m.get<double>());
  EXPECT_LE(mmax, l1["moment_max"].get<double>() + kMomentTol);
  // collinear --tooth-force N is --exit-tension S − N
  EXPECT_EQ(run_json(kSliding + "--tooth-force 20kN"), run_json(kSliding + "--exit-tension 10kN"));
  // refused: both at once; --tooth-force with an angle; the tooth pulling
  EXPECT_EQ(run(kSliding + "--tooth-force 20kN --exit-tension 10kN").status, 2);
  const CliRun angle = run(kSliding + "--tooth-force 20kN --link-angle 30");
  EXPECT_EQ(angle.status, 2);
  EXPECT_NE(angle.err.find("--exit-tension"), std::string::npos) << angle.err;
  const CliRun pull = run(kSliding + "--exit-tension 40kN");
  EXPECT_EQ(pull.status, 2);
  EXPECT_NE(pull.err.find("--exit-tension"), std::string::npos) << pull.err;
}

TEST(StrengthCli, SlidingHingeCaseFileGivesWhatTheCommandGives) {
  // chain.type = sliding-hinge implies --hinge sliding; the shared pin diameter, tension and
  // material values reach the analysis, the rolling-hinge radii of [chain] do not
  const auto path = std::filesystem::temp_directory_path() / "catena_case_strength_sliding.toml";
  std::ofstream(path) << "[chain]\ntype = \"sliding-hinge\"\npin_diameter = \"40 mm\"\n"
                         "plate_radius = \"34 mm\"\n[loads]\ntension = \"30 kN\"\n"
                         "[material]\nallowable_pressure = \"60 MPa\"\n"
                         "[analyses.strength]\nheights = \"0, 8 mm, 48 mm, 56 mm\"\n"
                         "widths = \"8 mm\"\nplate_width = \"90 mm\"\nend_distance = \"45 mm\"\n"
                         "roller_yield = \"600 MPa\"\nplate_yield = \"400 MPa\"\n";
  const CliRun r = run("run " + path.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["analyses"]["strength"], run_json(kSliding));
  EXPECT_EQ(j["analyses"]["strength"]["hinge"], "sliding");
  std::filesystem::remove(path);
}

}  // namespace
