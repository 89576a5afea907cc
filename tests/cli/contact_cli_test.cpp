// `catena contact` and `catena fretting` as scripts call them.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "cli_run.hpp"

namespace {

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
  EXPECT_NEAR(j["load_factor"].get<double>(), 1 + 0.0016 * 42 * 42, 1e-9);
  EXPECT_NEAR(j["effective_load"].get<double>(), 1000 * (1 + 0.0016 * 42 * 42), 1e-6);
  // the paper's formula with its printed 0.418
  const double rho = j["reduced_radius"].get<double>();
  EXPECT_NEAR(j["contact_stress"].get<double>(),
              0.418 * std::sqrt(j["effective_load"].get<double>() * 210e9 / (12.7e-3 * rho)), 1);
  for (const char* key : {"stress_peak", "loaded_length", "distribution"})
    EXPECT_TRUE(j["slice_model"].contains(key));
  EXPECT_EQ(j["slice_model"]["distribution"]["s"].size(), 201u);
}

TEST(ContactCli, GaugeChainAndSweep) {
  const CliRun gauge =
      run(kContact + " --skew-gauge-dh 0.155mm --skew-gauge-base 12.7mm --format json");
  ASSERT_EQ(gauge.status, 0) << gauge.err;
  EXPECT_NEAR(nlohmann::json::parse(gauge.out)["skew"].get<double>(), std::atan(0.155 / 12.7),
              1e-12);
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
          "--pitch 31.75mm --gamma 0.001");
  EXPECT_EQ(r.status, 0) << r.err;
  r = run(kContact + " --skew 5kg --chain 99X");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--skew = '5kg'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--chain"), std::string::npos) << r.err;
}

TEST(FrettingCli, LatentPeriodAndTheSignOfK2) {
  CliRun r =
      run("fretting --roughness 0.8um --amplitude 5um --load 2kN --frequency 20Hz --k1 1e9 --k2 "
          "-1e-6 --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NEAR(nlohmann::json::parse(r.out)["latent_period"].get<double>(), 800 * std::exp(-0.25),
              1e-9);
  r = run(
      "fretting --roughness 0.8um --amplitude 5um --load 2kN --frequency 20Hz --k1 1e9 --k2 1e-6");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--k2"), std::string::npos) << r.err;
  r = run("fretting --roughness 0.8um --amplitude 5um --load 2kN --frequency 20Hz");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--k1"), std::string::npos) << r.err;
}

}  // namespace
