// `catena contact` and `catena fretting` as scripts call them.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>

#include "../read_text.hpp"
#include "cli_run.hpp"

namespace {

// Tolerances. The JSON carries doubles to full precision, so the CLI's values differ from the
// formulas written here only by the round-off of those formulas.
constexpr double kRatioTol = 1e-9;        // [1] load factors and stress ratios of order 1
constexpr double kExactRatioTol = 1e-12;  // [1] the same load factor from two runs
constexpr double kAngleTol = 1e-12;       // [rad] skews of ~1e-2 rad converted from arcmin
constexpr double kRadiusTol = 1e-12;      // [m] the reduced radius, ~1e-2 m
constexpr double kLengthTol = 1e-15;      // [m] loaded lengths of ~2e-3 m: round-off
constexpr double kLoadTol = 1e-6;         // [N] loads of 1e3 to 4e3 N
constexpr double kStressTol = 1.0;        // [Pa] contact stresses of ~1e9 Pa: 1e-9 relative
constexpr double kPeakStressTol = 1e-6;   // [Pa] the same slice-model peak (~2e9 Pa) from two runs
constexpr double kRelTol = 1e-9;          // [1] relative, the same value by two formulas
constexpr double kHertzRelTol = 1e-6;     // [1] relative, the Hertz peak pressure written out here
constexpr double kTimeTol = 1e-9;         // [s] the latent period, ~6e2 s

const std::string kContact =
    "contact --roller-diameter 11.91mm --roller-length 12.7mm --tooth-radius 15.56mm --profile "
    "concave "
    "--modulus 210GPa --poisson 0.3 --load 1kN --pitch 19.05mm";

TEST(ContactCli, JsonCarriesTheContractFields) {
  const CliRun r = run(kContact + " --skew 0.7deg --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"reduced_radius", "load_factor", "effective_load", "contact_stress",
                          "hertz_stress", "half_width", "slice_model", "units"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_NEAR(j["load_factor"].get<double>(), 1 + 0.0016 * 42 * 42, kRatioTol);
  EXPECT_NEAR(j["effective_load"].get<double>(), 1000 * (1 + 0.0016 * 42 * 42), kLoadTol);
  // the paper's formula with its printed 0.418
  const double rho = j["reduced_radius"].get<double>();
  EXPECT_NEAR(j["contact_stress"].get<double>(),
              0.418 * std::sqrt(j["effective_load"].get<double>() * 210e9 / (12.7e-3 * rho)),
              kStressTol);
  for (const char* key : {"stress_peak", "loaded_length", "distribution"})
    EXPECT_TRUE(j["slice_model"].contains(key));
  EXPECT_EQ(j["slice_model"]["distribution"]["s"].size(), 201u);
}

TEST(ContactCli, GaugeChainAndSweep) {
  const CliRun gauge =
      run(kContact + " --skew-gauge-dh 0.155mm --skew-gauge-base 12.7mm --format json");
  ASSERT_EQ(gauge.status, 0) << gauge.err;
  EXPECT_NEAR(nlohmann::json::parse(gauge.out)["skew"].get<double>(), std::atan(0.155 / 12.7),
              kAngleTol);
  const CliRun chain =
      run("contact --chain 12B --tooth-radius 15.56mm --load 1kN --skew '0°42′' --format json");
  ASSERT_EQ(chain.status, 0) << chain.err;
  const CliRun sweep =
      run("contact --chain 12B --tooth-radius 15.56mm --load 1kN --skew-sweep 0deg:3deg:30arcmin "
          "--format json");
  ASSERT_EQ(sweep.status, 0) << sweep.err;
  EXPECT_EQ(nlohmann::json::parse(sweep.out)["skew"].size(), 7u);
}

TEST(ContactCli, NoSilentExtrapolationOfGamma) {
  CliRun r =
      run("contact --roller-diameter 19.05mm --roller-length 18.9mm --tooth-radius 25mm --load 1kN "
          "--pitch 31.75mm");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--gamma"), std::string::npos) << r.err;
  r =
      run("contact --roller-diameter 19.05mm --roller-length 18.9mm --tooth-radius 25mm --load 1kN "
          "--pitch 31.75mm --gamma 0.001 --skew 0");
  EXPECT_EQ(r.status, 0) << r.err;
  r = run(kContact + " --skew 5kg --chain 99X");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--skew = '5kg'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--chain"), std::string::npos) << r.err;
}

// Every catalogued chain: its pitch in the paper's γ table runs; any other is refused with the
// chain, its pitch and why (the paper's measured pitches), and runs with --gamma.
TEST(ContactCli, EveryCataloguedChainRunsOrSaysWhyNot) {
  for (const char* chain : {"05B", "06B", "08A", "08B", "10A", "10B", "12A", "12B", "16A", "16B",
                            "20A", "20B", "24A", "24B", "28A", "28B", "32A", "32B"}) {
    const std::string base =
        std::string("contact --chain ") + chain + " --tooth-radius 40mm --load 1kN --skew 0.5deg";
    const double p = std::stod(std::string(chain).substr(0, 2)) * 25.4 / 16;
    const bool tabulated = p > 12 && p < 26;
    const CliRun r = run(base);
    if (tabulated) {
      EXPECT_EQ(r.status, 0) << chain << r.err;
      continue;
    }
    EXPECT_EQ(r.status, 2) << chain;
    EXPECT_NE(r.err.find(std::string("for ") + chain), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("--gamma"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("12.7, 15.875, 19.05 and 25.4 mm"), std::string::npos) << r.err;
    EXPECT_EQ(run(base + " --gamma 0.001").status, 0) << chain;
  }
}

nlohmann::json contact_json(const std::string& extra) {
  const CliRun r = run(kContact + " " + extra + " --format json");
  EXPECT_EQ(r.status, 0) << extra << "\n" << r.err;
  return r.status == 0 ? nlohmann::json::parse(r.out) : nlohmann::json{};
}

// The slice model's short-patch caveat is a finding of the analysis (JSON and report), not a
// note of the text table only; a long patch has none.
TEST(ContactCli, ShortPatchIsADiagnosticInJson) {
  const CliRun short_patch =
      run("contact --chain 12B --load 1kN --tooth-radius 15.56mm --profile concave "
          "--skew 1deg --format json");
  ASSERT_EQ(short_patch.status, 0) << short_patch.err;
  const auto j = nlohmann::json::parse(short_patch.out);
  ASSERT_EQ(j["diagnostics"].size(), 1u);
  EXPECT_EQ(j["diagnostics"][0]["code"], "contact.short_patch");
  EXPECT_EQ(j["diagnostics"][0]["severity"], "info");
  EXPECT_LT(j["diagnostics"][0]["value"].get<double>(), 5.0);
  EXPECT_NEAR(j["diagnostics"][0]["value"].get<double>(),
              j["slice_model"]["loaded_length"].get<double>() /
                  j["slice_model"]["peak_half_width"].get<double>(),
              kRelTol);
  const CliRun aligned = run(kContact + " --skew 0 --format json");
  ASSERT_EQ(aligned.status, 0) << aligned.err;
  EXPECT_TRUE(nlohmann::json::parse(aligned.out)["diagnostics"].empty());
}

TEST(ContactCli, HertzValuesAtTheEffectiveLoad) {
  // Plane-strain Hertz, steel on steel: E* = E/(2(1 − ν²)), p0 = √(P′E*/(πρ)), b = √(4P′ρ/(πE*))
  const auto j = contact_json("--skew 30arcmin");
  const double rho = j["reduced_radius"].get<double>();
  EXPECT_NEAR(rho, 11.91 * 15.56 / (2 * (15.56 - 0.5 * 11.91)) * 1e-3, kRadiusTol);
  const double p = j["effective_load"].get<double>() / 12.7e-3;
  const double e_star = 210e9 / (2 * (1 - 0.09));
  EXPECT_NEAR(j["hertz_stress"].get<double>(), std::sqrt(p * e_star / (std::numbers::pi * rho)),
              kHertzRelTol * j["hertz_stress"].get<double>());
  EXPECT_NEAR(j["half_width"].get<double>(), std::sqrt(4 * p * rho / (std::numbers::pi * e_star)),
              kRelTol * j["half_width"].get<double>());
  EXPECT_NEAR(j["hertz_stress_nominal"].get<double>(),
              j["hertz_stress"].get<double>() / std::sqrt(j["load_factor"].get<double>()),
              kStressTol);
  // A softer tooth changes the general Hertz stress but not the paper's steel formula (3).
  const auto soft = contact_json("--skew 30arcmin --tooth-modulus 105GPa --tooth-poisson 0.35");
  const double e_soft = 1 / ((1 - 0.09) / 210e9 + (1 - 0.35 * 0.35) / 105e9);
  EXPECT_NEAR(soft["hertz_stress"].get<double>() / j["hertz_stress"].get<double>(),
              std::sqrt(e_soft / e_star), kRatioTol);
  EXPECT_EQ(soft["contact_stress"].get<double>(), j["contact_stress"].get<double>());
}

TEST(ContactCli, SkewFactorScalesTheSkewOnce) {
  // K_φ = 0.65 on a measured 60′ is the design skew 39′, in eq. (2) and in the slice model alike.
  const auto k = contact_json("--skew 60arcmin --skew-factor 0.65");
  const auto d = contact_json("--skew 39arcmin");
  EXPECT_NEAR(k["load_factor"].get<double>(), 1 + 0.0016 * 39 * 39, kRatioTol);
  EXPECT_NEAR(k["design_skew"].get<double>(), 39 * std::numbers::pi / 10800, kAngleTol);
  EXPECT_NEAR(k["load_factor"].get<double>(), d["load_factor"].get<double>(), kExactRatioTol);
  EXPECT_NEAR(k["slice_model"]["stress_peak"].get<double>(),
              d["slice_model"]["stress_peak"].get<double>(),
              kRelTol * d["slice_model"]["stress_peak"].get<double>());
  EXPECT_NEAR(k["slice_model"]["load_sum"].get<double>(), 1000.0, kLoadTol);
}

TEST(ContactCli, SweepValuesCsvTableAndOutputFile) {
  const CliRun json = run(kContact + " --skew-sweep 0deg:1deg:15arcmin --format json");
  ASSERT_EQ(json.status, 0) << json.err;
  const auto j = nlohmann::json::parse(json.out);
  ASSERT_EQ(j["skew"].size(), 5u);
  for (int i = 0; i < 5; ++i) {
    const double arcmin = 15.0 * i;
    EXPECT_NEAR(j["skew"][i].get<double>(), arcmin * std::numbers::pi / 10800, kAngleTol);
    EXPECT_NEAR(j["load_factor"][i].get<double>(), 1 + 0.0016 * arcmin * arcmin, kRatioTol);
    if (i > 0) {
      EXPECT_GT(j["slice_stress_peak"][i].get<double>(),
                j["slice_stress_peak"][i - 1].get<double>());
      EXPECT_LT(j["slice_loaded_length"][i].get<double>(),
                j["slice_loaded_length"][i - 1].get<double>() + kLengthTol);
    }
  }
  // the aligned point of the sweep is the single-point run at zero skew
  EXPECT_NEAR(j["slice_stress_peak"][0].get<double>(),
              contact_json("--skew 0")["slice_model"]["stress_peak"].get<double>(), kPeakStressTol);

  const CliRun csv = run(kContact + " --skew-sweep 0deg:1deg:15arcmin --format csv");
  ASSERT_EQ(csv.status, 0) << csv.err;
  EXPECT_EQ(csv.out.rfind("skew,load_factor,effective_load,contact_stress,", 0), 0u) << csv.out;
  EXPECT_EQ(std::count(csv.out.begin(), csv.out.end(), '\n'), 6);

  const CliRun table = run(kContact + " --skew 0.7deg");
  ASSERT_EQ(table.status, 0) << table.err;
  for (const char* label : {"load factor", "contact stress eq. (3)", "slice model: peak stress"})
    EXPECT_NE(table.out.find(label), std::string::npos) << label;

  const auto path = std::filesystem::temp_directory_path() / "catena_contact_cli_output.json";
  std::filesystem::remove(path);
  const CliRun file = run(kContact + " --skew 0.7deg --format json --output " + path.string());
  ASSERT_EQ(file.status, 0) << file.err;
  EXPECT_TRUE(file.out.empty());
  const std::string content = read_text(path);
  EXPECT_EQ(content, run(kContact + " --skew 0.7deg --format json").out);
  std::filesystem::remove(path);
}

TEST(ContactCli, BadSkewAndSliceRequestsAreRejected) {
  struct Case {
    std::string args, fragment;
  };
  for (const Case& c : std::vector<Case>{
           {"", "--skew = (missing)"},
           {"--skew 1deg --skew-sweep 0deg:1deg:1arcmin", "not both"},
           {"--skew-sweep 0deg:95deg:1deg", "-90°"},
           {"--skew-sweep 0deg:1deg:1arcmin:5deg", "three angles"},
           {"--skew-sweep 1deg:0deg:1arcmin", "FROM ≤ TO"},
           {"--skew 1deg --slices 50000000", "20001"},
           {"--skew 1deg --slices 2", "≥ 3"},
           {"--skew-sweep 0deg:80deg:1arcmin --slices 20001", "slices × sweep points"},
           {"--skew 1deg --modulus -5GPa", "--modulus"},
       }) {
    const CliRun r = run(kContact + " " + c.args);
    EXPECT_EQ(r.status, 2) << c.args;
    EXPECT_NE(r.err.find(c.fragment), std::string::npos) << c.args << "\n" << r.err;
  }
  // one bad modulus shared by both bodies is reported once
  const CliRun r = run(kContact + " --skew 1deg --modulus -5GPa");
  EXPECT_EQ(r.err.find("--modulus"), r.err.rfind("--modulus")) << r.err;
}

TEST(FrettingCli, LatentPeriodAndTheSignOfK2) {
  CliRun r =
      run("fretting --roughness 0.8um --amplitude 5um --load 2kN --frequency 20Hz --k1 1e9 --k2 "
          "-1e-6 --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NEAR(nlohmann::json::parse(r.out)["latent_period"].get<double>(), 800 * std::exp(-0.25),
              kTimeTol);
  r = run(
      "fretting --roughness 0.8um --amplitude 5um --load 2kN --frequency 20Hz --k1 1e9 --k2 1e-6");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--k2"), std::string::npos) << r.err;
  r = run("fretting --roughness 0.8um --amplitude 5um --load 2kN --frequency 20Hz");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--k1 = (missing)"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--k2 = (missing)"), std::string::npos) << r.err;
  // rpm counts radians, not cycles: a frequency must be given in Hz or 1/min
  r =
      run("fretting --roughness 0.8um --amplitude 5um --load 2kN --frequency 20rpm --k1 1e9 --k2 "
          "-1e-6");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--frequency"), std::string::npos) << r.err;
  r =
      run("fretting --roughness 0.8um --amplitude 5um --load 2kN --frequency '1200 1/min' --k1 1e9 "
          "--k2 -1e-6 --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NEAR(nlohmann::json::parse(r.out)["latent_period"].get<double>(), 800 * std::exp(-0.25),
              kTimeTol);
}

}  // namespace
