// `catena ring capacity` and `catena ring design` as scripts call them: the paper's example,
// the analysed mode, SI JSON with units and diagnostics, every input problem at once (exit 2).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "cli_run.hpp"

namespace {

// Tolerances. The JSON is SI with doubles at full precision.
constexpr double kAreaMm2Tol = 0.005;  // [mm²] the paper's 22.68 mm²: half a unit of the last digit
constexpr double kLoadTol = 1e-6;      // [N] loads of ~3e4 N: round-off
constexpr double kRelTol = 1e-9;       // [1] relative, the same load by (9) and by 2Fσ/K
constexpr double kRatioTol = 1e-12;    // [1] O(1) factors and ratios by one formula
// [1] Σσ̃_r ≈ 1.4 of the analysed ring: its contact integral against equilibrium
constexpr double kEquilibriumTol = 1e-6;
constexpr double kLengthTol = 1e-15;  // [m] a 2 mm pitch passed through: round-off
constexpr double kAreaTol = 1e-15;    // [m²] leg areas of ~2e-5 m² by hand: ~5e-11 relative

const std::string kPaper =
    "ring capacity --alpha 0.42 --sum-sigma-r 0.2662 --k-max 4.173 --fibre-strength 2500MPa ";

const std::string kDesign =
    "ring design --load 32900N --fibre-modulus 72.4GPa --fibre-poisson 0.22 "
    "--fibre-strength 2500MPa --fibre-density 2.56g/cm^3 --matrix-modulus 3.5GPa "
    "--matrix-poisson 0.35 --matrix-density 1200 --fibre-fraction 0.7 --thickness 6mm ";

std::set<std::string> flags_in(const std::string& err) {
  std::set<std::string> out;
  for (const char* f :
       {"--alpha", "--sum-sigma-r", "--k-max", "--fibre-strength", "--fibre-area", "--load",
        "--E-phi", "--G", "--inner-radius", "--nu-phi-r", "--pitch", "--fibre-fraction",
        "--fibre-density", "--thickness", "--steel-mass", "--link-mass"})
    if (err.find(std::string("  ") + f + " =") != std::string::npos) out.insert(f);
  return out;
}

TEST(RingCapacityCli, PaperExampleSizesTheArea) {
  const CliRun r = run(kPaper +
                       "--load 29700N --steel-mass 0.337kg --link-mass 0.035kg "
                       "--format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["mode"], "coefficients");
  EXPECT_NEAR(j["fibre_area"].get<double>() * 1e6, 22.68, kAreaMm2Tol);
  EXPECT_NEAR(j["load"].get<double>(), 29700.0, kLoadTol);
  EXPECT_NEAR(j["eq9_factor"].get<double>(), 0.2662 / (0.42 * 0.58 * 4.173), kRatioTol);
  EXPECT_NEAR(j["mass"]["ratio"].get<double>(), 0.337 / 0.035, kRatioTol);
  EXPECT_EQ(j["units"]["fibre_area"], "m^2");
  EXPECT_EQ(j["units"]["load"], "N");
  // (9) exceeds 2Fσ/K by Σσ̃_r/(α(1−α)) = 1.093: an info diagnostic with both values
  bool found = false;
  for (const auto& d : j["diagnostics"])
    if (d["code"] == "ring.capacity.eq9_above_concentration_capacity") {
      found = true;
      EXPECT_NEAR(d["limit"].get<double>(), 0.42 * 0.58, kRatioTol);
    }
  EXPECT_TRUE(found) << r.out;
}

TEST(RingCapacityCli, GivenAreaGivesTheLoadAndTheTableSaysSo) {
  const CliRun r = run(kPaper + "--fibre-area 22.7mm^2");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("P max, eq. (9) [N]       29722"), std::string::npos) << r.out;
}

TEST(RingCapacityCli, AnalysedModeUsesTheRingsConcentration) {
  const CliRun r =
      run("ring capacity --E-r 10GPa --E-phi 40GPa --G 4GPa --nu-phi-r 0.28 "
          "--inner-radius 4.2mm --outer-radius 10mm --fibre-strength 2500MPa "
          "--fibre-area 22.7mm^2 --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["mode"], "analysed");
  const double a = j["alpha"].get<double>();
  EXPECT_NEAR(a, 0.42, kRatioTol);
  EXPECT_NEAR(j["ring_sum_sigma_r"].get<double>(), (1 - a) / a, kEquilibriumTol);
  EXPECT_NEAR(j["sum_sigma_r"].get<double>(), a * (1 - a), kRatioTol);
  // consistent normalisation: (9) equals 2Fσ/K
  EXPECT_NEAR(j["load"].get<double>(), j["load_concentration"].get<double>(),
              kRelTol * j["load"].get<double>());
  EXPECT_NEAR(j["load"].get<double>(), 2 * 22.7e-6 * 2500e6 / j["k_max"].get<double>(), kLoadTol);
  EXPECT_GT(j["k_max"].get<double>(), 1.0);
}

TEST(RingCapacityCli, EveryProblemAtOnce) {
  const CliRun r =
      run("ring capacity --alpha 1.5 --k-max 0.5 --fibre-strength -3MPa "
          "--fibre-area 1 --load 3 --steel-mass 1");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(flags_in(r.err),
            (std::set<std::string>{"--alpha", "--sum-sigma-r", "--k-max", "--fibre-strength",
                                   "--fibre-area", "--link-mass"}))
      << r.err;
  const CliRun m =
      run("ring capacity --alpha 0.4 --E-phi x --G 4GPa --fibre-strength 1GPa "
          "--fibre-area 1");
  EXPECT_EQ(m.status, 2);
  const auto f = flags_in(m.err);
  EXPECT_TRUE(f.count("--alpha") && f.count("--E-phi") && f.count("--inner-radius")) << m.err;
  const CliRun bad_area = run(kPaper + "--fibre-area 3kg");
  EXPECT_EQ(bad_area.status, 2);
  EXPECT_NE(bad_area.err.find("an area"), std::string::npos) << bad_area.err;
}

TEST(RingDesignCli, JsonDesignCarriesTheContract) {
  const CliRun r = run(kDesign +
                       "--pitch 50mm --alpha 0.4,0.5,0.6 --steel-strength 600MPa "
                       "--steel-thickness 6mm --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["scan"].size(), 3u);
  const auto& d = j["design"];
  EXPECT_GT(d["outer_radius"].get<double>(), d["inner_radius"].get<double>());
  EXPECT_NEAR(d["inner_radius"].get<double>() / d["outer_radius"].get<double>(),
              d["alpha"].get<double>(), kRatioTol);
  // the leg section carries P at the hoop strength over K: A = PK/(2σ_c)
  EXPECT_NEAR(d["leg_area"].get<double>(),
              32900 * d["k"].get<double>() / (2 * j["lamina"]["strength"].get<double>()), kAreaTol);
  for (const auto& p : j["scan"])
    EXPECT_GE(p["mass"]["total"].get<double>(), d["mass"]["total"].get<double>());
  EXPECT_GT(j["steel"]["mass_ratio"].get<double>(), 1.0);
  EXPECT_EQ(j["units"]["mass"], "kg");
  EXPECT_TRUE(j["diagnostics"].is_array());
}

TEST(RingDesignCli, ShortPitchIsADiagnosticAndBadInputIsExit2) {
  const CliRun r = run(kDesign + "--pitch 2mm --alpha 0.5 --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  bool found = false;
  for (const auto& d : j["diagnostics"])
    if (d["code"] == "ring.design.pitch_too_small") {
      found = true;
      EXPECT_EQ(d["severity"], "infeasible");
      EXPECT_NEAR(d["value"].get<double>(), 2e-3, kLengthTol);
    }
  EXPECT_TRUE(found) << r.out;
  const CliRun bad =
      run("ring design --load -1 --fibre-fraction 2 --fibre-density 3kg "
          "--thickness 6 --pitch 20");
  EXPECT_EQ(bad.status, 2);
  const auto f = flags_in(bad.err);
  EXPECT_TRUE(f.count("--load") && f.count("--fibre-fraction") && f.count("--fibre-density"))
      << bad.err;
  const CliRun table = run(kDesign + "--pitch 200mm");
  ASSERT_EQ(table.status, 0) << table.err;
  EXPECT_NE(table.out.find("<- lightest"), std::string::npos) << table.out;
}

}  // namespace
