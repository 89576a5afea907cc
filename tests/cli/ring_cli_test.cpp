// `catena ring` as the contract writes it: flags with units, the JSON fields in SI,
// csv and table, --method sweep, --unilateral, and every input problem at once.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "cli_run.hpp"

namespace {

constexpr double kRadiusTol = 1e-12;   // [m] radii of ~1e-2 m passed through: round-off
constexpr double kEdgeRelTol = 1e-6;   // [1] of the mean stress: σ_r on the free edge, truncated
constexpr double kResidualTol = 1e-9;  // [1] the relative equilibrium residual |P − P_contact|/P
constexpr double kSweepRelTol = 1e-3;  // [1] relative, the sweep's load against the exact one

const std::string kRing =
    "ring --inner-radius 4.72mm --outer-radius 10mm --thickness 1mm --E-r 10GPa --E-phi 40GPa "
    "--G 4GPa --nu-phi-r 0.28 --gap 0.02mm ";

TEST(RingCli, JsonCarriesTheContractFields) {
  const CliRun r = run(kRing + "--harmonics 200 --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* k : {"load", "mean_stress", "sections", "contact", "stress_concentration",
                        "summary", "units", "diagnostics"})
    EXPECT_TRUE(j.contains(k)) << k;
  const double load = j["load"].get<double>();
  EXPECT_GT(load, 0.0);
  // mean stress is P / (2 (r2 − r1) t) in SI
  // [Pa/N] times the load [N] bounds a stress [Pa]: 1e-6 · 2(r2 − r1)t ≈ 1e-11 of the mean stress
  constexpr double kMeanStressTolPerLoad = 1e-6;
  EXPECT_NEAR(j["mean_stress"].get<double>(), load / (2 * (10e-3 - 4.72e-3) * 1e-3),
              kMeanStressTolPerLoad * load);
  for (const char* s : {"0", "90"}) {
    const auto& sec = j["sections"][s];
    ASSERT_EQ(sec["r"].size(), sec["sigma_phi"].size());
    ASSERT_EQ(sec["r"].size(), sec["sigma_r"].size());
    ASSERT_EQ(sec["r"].size(), sec["tau"].size());
    EXPECT_NEAR(sec["r"].front().get<double>(), 4.72e-3, kRadiusTol);  // metres, ascending
    EXPECT_NEAR(sec["r"].back().get<double>(), 10e-3, kRadiusTol);
    for (std::size_t i = 1; i < sec["r"].size(); ++i)
      EXPECT_GT(sec["r"][i].get<double>(), sec["r"][i - 1].get<double>());
    // free outer edge
    EXPECT_NEAR(sec["sigma_r"].back().get<double>(), 0.0,
                kEdgeRelTol * j["mean_stress"].get<double>());
  }
  EXPECT_EQ(j["contact"]["phi"].size(), j["contact"]["pressure"].size());
  EXPECT_EQ(j["summary"]["method"], "exact");
  EXPECT_EQ(j["summary"]["harmonics"], 200);
  EXPECT_LT(j["summary"]["equilibrium_residual"].get<double>(), kResidualTol);
  EXPECT_EQ(j["units"]["load"], "N");
  EXPECT_EQ(j["units"]["sigma_phi"], "Pa");
  // the bilateral contact pulls near phi = 90 deg: a diagnostic, not an error (exit 0)
  bool tension = false;
  for (const auto& d : j["diagnostics"]) tension |= d["code"] == "composite.contact_tension";
  EXPECT_TRUE(tension);
}

TEST(RingCli, SweepAgreesWithExactAndReportsItsGrid) {
  const CliRun ex = run(kRing + "--harmonics 100 --format json");
  const CliRun sw = run(kRing + "--harmonics 100 --method sweep --nodes 2000 --format json");
  ASSERT_EQ(ex.status, 0) << ex.err;
  ASSERT_EQ(sw.status, 0) << sw.err;
  const auto a = nlohmann::json::parse(ex.out);
  const auto b = nlohmann::json::parse(sw.out);
  EXPECT_EQ(b["summary"]["nodes"], 2000);
  EXPECT_GT(b["summary"]["richardson_error"].get<double>(), 0.0);
  EXPECT_NEAR(b["load"].get<double>(), a["load"].get<double>(),
              kSweepRelTol * a["load"].get<double>());
}

TEST(RingCli, UnilateralSeparatesAndCarriesLess) {
  // isotropic: E_r = E_phi, G = E/(2(1 + nu))
  const std::string iso =
      "ring --inner-radius 4.72mm --outer-radius 10mm --thickness 1mm --E-r 40GPa --E-phi 40GPa "
      "--G 15.625GPa --nu-phi-r 0.28 --gap 0.02mm --harmonics 120 --format json ";
  const CliRun bi = run(iso);
  const CliRun uni = run(iso + "--unilateral");
  ASSERT_EQ(uni.status, 0) << uni.err;
  const auto a = nlohmann::json::parse(bi.out);
  const auto b = nlohmann::json::parse(uni.out);
  EXPECT_TRUE(b["contact"]["unilateral"].get<bool>());
  EXPECT_LT(b["contact"]["angle"].get<double>(), M_PI / 2);
  EXPECT_LE(b["load"].get<double>(), a["load"].get<double>());
  for (const auto& d : b["diagnostics"]) EXPECT_NE(d["code"], "composite.contact_tension");
}

TEST(RingCli, FieldIsOptIn) {
  const CliRun plain = run(kRing + "--harmonics 40 --points 21 --format json");
  const CliRun field = run(kRing + "--harmonics 40 --points 21 --field --format json");
  ASSERT_EQ(field.status, 0) << field.err;
  EXPECT_FALSE(nlohmann::json::parse(plain.out).contains("field"));
  const auto j = nlohmann::json::parse(field.out);
  ASSERT_EQ(j["field"]["phi"].size(), j["field"]["sigma_phi"].size());
  EXPECT_EQ(j["field"]["sigma_phi"][0].size(), 21u);
  EXPECT_EQ(j["field"]["tau"][0][0], 0.0);  // τ = 0 on the symmetry section φ = 0
}

TEST(RingCli, CsvAndTable) {
  const CliRun csv = run(kRing + "--harmonics 60 --points 21 --format csv");
  ASSERT_EQ(csv.status, 0) << csv.err;
  EXPECT_EQ(csv.out.rfind("r,sigma_r_0,sigma_phi_0,tau_0,sigma_r_90,sigma_phi_90,tau_90\n", 0), 0u);
  EXPECT_EQ(std::count(csv.out.begin(), csv.out.end(), '\n'), 22);
  const CliRun table = run(kRing + "--harmonics 60");
  ASSERT_EQ(table.status, 0) << table.err;
  EXPECT_NE(table.out.find("load P"), std::string::npos);
  EXPECT_NE(table.out.find("stress conc. K"), std::string::npos);
}

TEST(RingCli, EveryProblemAtOnceWithExitTwo) {
  const CliRun r =
      run("ring --inner-radius 12mm --outer-radius 10mm --E-r=-1GPa --nu-phi-r x --gap 2kg "
          "--harmonics 1 --nodes 40");
  EXPECT_EQ(r.status, 2);
  for (const char* flag : {"--thickness", "--E-phi", "--G", "--nu-phi-r", "--gap", "--E-r",
                           "--inner-radius", "--harmonics", "--nodes"})
    EXPECT_NE(r.err.find(flag), std::string::npos) << flag << "\n" << r.err;
  EXPECT_NE(r.err.find("0.05 ≤ r1/r2 ≤ 0.995"), std::string::npos) << r.err;
}

}  // namespace
