// The pocket-wheel example's mean span tensions in the step (issue 21; docs/models/dynamics.md,
// "Pocket wheel: the example's means"). The loop's response does not repeat with the tooth
// period: a change of 1e-9 in the pretension grows to the full scatter within half a second, so
// the window's mean over whole tooth periods is a sample, and what converges in the step is the
// mean within its standard error, not the sample. Checked here: the summary's standard error
// and the periods' scatter against the series (the period means computed here, their error by
// period_means.hpp's estimator, tested on AR(1) sequences in tests/dynamics/
// period_means_test.cpp), the means at h and h/2 over a
// 10 s run within three combined standard errors, the load (tight − slack) and the driven
// wheel's torque closer; the 1 s example's sensitivity: a 1e-9 change of the pretension parts
// its span tensions by the end; and the 3-period error the example reports against the scatter
// of 3-period windows of a 40 s run.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <vector>

#include "../read_text.hpp"
#include "catena/dynamics/period_means.hpp"
#include "cli_run.hpp"

namespace {

namespace fs = std::filesystem;
constexpr double kPi = std::numbers::pi;
const std::string kExample = std::string(CATENA_EXAMPLES_DIR) + "/dynamics_pocketwheel.toml";

nlohmann::json dynamics(const std::string& file, const std::string& options) {
  const CliRun r = run("dynamics " + file + " " + options + " --format json");
  EXPECT_EQ(r.status, 0) << r.err;
  return r.status == 0 ? nlohmann::json::parse(r.out) : nlohmann::json();
}

// A span's samples summed over each whole driver tooth period T = 2π/(zω) from t0 to the run's
// end, (t0 + iT, t0 + (i+1)T]; t0 half the run is the summary's window.
struct PeriodSums {
  std::vector<double> sum, count;
};

PeriodSums period_sums(const nlohmann::json& j, int span, double t0) {
  const auto time = j["time"].get<std::vector<double>>();
  const auto x = j["span"][span]["tension"].get<std::vector<double>>();
  const double period = 2 * kPi / (8 * 5.0);
  const int periods = static_cast<int>(std::floor((time.back() - t0) / period));
  PeriodSums p{std::vector<double>(periods, 0.0), std::vector<double>(periods, 0.0)};
  for (std::size_t k = 0; k < time.size(); ++k) {
    const double u = (time[k] - t0) / period;
    if (u <= 0 || u > periods) continue;
    const int i = std::min(periods - 1, static_cast<int>(std::ceil(u)) - 1);
    p.sum[i] += x[k];
    p.count[i] += 1;
  }
  return p;
}

// The mean over the periods [first, last) and the period means' error (period_means.hpp), as the
// command reports them for a window of those periods.
struct Spread {
  double mean = 0;
  int periods = 0;
  catena::dynamics::PeriodMeansError e;
};

Spread spread(const PeriodSums& p, std::size_t first, std::size_t last) {
  Spread s;
  s.periods = static_cast<int>(last - first);
  double all = 0, n = 0;
  std::vector<double> means;
  for (std::size_t i = first; i < last; ++i) {
    all += p.sum[i];
    n += p.count[i];
    means.push_back(p.sum[i] / p.count[i]);
  }
  s.mean = all / n;
  s.e = catena::dynamics::period_means_error(means);
  return s;
}

Spread spread(const nlohmann::json& j, int span) {
  const PeriodSums p = period_sums(j, span, j["time"].back().get<double>() / 2);
  return spread(p, 0, p.sum.size());
}

// The example with the pretension 1e-9 larger (1000.000001 N), in a file of this process's own
// (removed by the caller).
std::string perturbed_example() {
  std::string s = read_text(kExample);
  const std::string from = "pretension = \"1000 N\"";
  const std::size_t at = s.find(from);
  EXPECT_NE(at, std::string::npos);
  if (at != std::string::npos) s.replace(at, from.size(), "pretension = \"1000.000001 N\"");
  const fs::path path =
      fs::temp_directory_path() / ("catena_pocket_means_" + std::to_string(::getpid()) + ".toml");
  std::ofstream(path) << s;
  return path.string();
}

TEST(DynamicsPocketMeansCli, MeansAgreeInTheStepWithinTheirStandardError) {
  // 10 s: the window holds 31 tooth periods (measured with the flat links bilateral: 2028.5 ±
  // 90.5 and 1407.9 ± 88.9 N at h = 0.1 ms, 1973.5 ± 78.5 and 1350.7 ± 76.7 N at 0.05 ms: 0.46
  // and 0.49 combined errors; with every round link tension-only 1907.9 ± 60.3, 1286.5 ± 59.4,
  // 1952.2 ± 49.9 and 1331.8 ± 48.7 N)
  const auto a = dynamics(kExample, "--duration 10s --step 0.1ms");
  const auto b = dynamics(kExample, "--duration 10s --step 0.05ms");
  ASSERT_FALSE(a.is_null() || b.is_null());
  for (int k = 0; k < 2; ++k) {
    const std::string key = "span_" + std::to_string(k);
    const Spread sa = spread(a, k), sb = spread(b, k);
    EXPECT_EQ(sa.periods, 31);
    for (const auto& [j, s] : {std::pair{&a, sa}, std::pair{&b, sb}}) {
      const auto& sum = (*j)["summary"][key];
      EXPECT_EQ((*j)["summary"]["window_periods"].get<int>(), s.periods);
      EXPECT_NEAR(sum["mean_tension"].get<double>(), s.mean, 1e-9 * s.mean);
      EXPECT_NEAR(sum["period_tension_sd"].get<double>(), s.e.sd, 1e-9 * s.e.sd);
      EXPECT_NEAR(sum["mean_tension_error"].get<double>(), s.e.error, 1e-9 * s.e.error);
      // 31 periods: their lag-1 autocorrelation estimated (measured 0.48 and 0.46 at h = 0.1 ms,
      // the error 90.5 and 88.9 N against s/√n = 53.2 and 53.3 N; 0.39 and 0.37 at 0.05 ms,
      // inflation 1.51 and 1.48; with every round link tension-only 0.28 and 0.28, 0.25 and
      // 0.23), the error s/√n inflated by it
      ASSERT_TRUE(sum["period_correlation"].is_number()) << key;
      EXPECT_NEAR(sum["period_correlation"].get<double>(), s.e.correlation, 1e-12) << key;
      EXPECT_NEAR(sum["effective_periods"].get<double>(), s.e.effective_periods, 1e-9) << key;
      // the cause, pinned: the periods' means scatter (measured 15-21 % of the mean over these
      // 10 s; 11-19 % with every round link tension-only; 12-22 % over 20 s with the bilateral
      // links); a loop whose response repeated with
      // the tooth period would have s ≈ 0
      EXPECT_GT(s.e.sd, 0.05 * s.mean) << key;
    }
    EXPECT_EQ(a["units"]["mean_tension_error"], "N");
    EXPECT_EQ(a["units"]["period_correlation"], "1");
    EXPECT_LT(std::abs(sa.mean - sb.mean), 3 * std::hypot(sa.e.error, sb.e.error))
        << key << ": " << sa.mean << " ± " << sa.e.error << " against " << sb.mean << " ± "
        << sb.e.error;
  }
  // what the spans carry converges closer than their level: the load (tight − slack; measured
  // 620.6 and 622.9 N) and the driven wheel's torque (99.975 and 99.976 N m)
  auto load = [](const nlohmann::json& j) {
    return j["summary"]["span_0"]["mean_tension"].get<double>() -
           j["summary"]["span_1"]["mean_tension"].get<double>();
  };
  EXPECT_NEAR(load(a) / load(b), 1.0, 0.015);
  EXPECT_NEAR(a["summary"]["sprocket_1"]["mean_torque"].get<double>(),
              b["summary"]["sprocket_1"]["mean_torque"].get<double>(), 0.2);
  // both runs say their means are not settled to 1 %, naming the duration
  for (const auto* j : {&a, &b}) {
    ASSERT_EQ((*j)["diagnostics"].size(), 1u) << (*j)["diagnostics"].dump();
    EXPECT_EQ((*j)["diagnostics"][0]["code"], "dynamics.means_not_settled");
    const std::string message = (*j)["diagnostics"][0]["message"];
    for (const char* text :
         {"dynamics.duration = 10 s", "of the largest span mean tension (span 0's",
          "allowing for the periods' lag-1 autocorrelation"})
      EXPECT_NE(message.find(text), std::string::npos) << text << "\n" << message;
  }
}

TEST(DynamicsPocketMeansCli, ExampleDivergesFromAPretensionFarBelowTheTolerance) {
  // The loop is chaotic: the example and the same with the pretension 1e-9 larger (1 µN, far
  // below the Newton tolerance) share their trajectory at first and part once the difference has
  // grown (to the full scatter by about 0.4 s). Compared over the last half second (the summary's
  // window) sample by sample, not through their 3-period means (one draw of a heavy-tailed
  // scatter: over the 41 draws' pairs the replaced pair test's "> 1 %" bound failed 14 %).
  // Measured: the rms difference of the span tensions is 1.74 and 1.84 × the example's own
  // standard deviation there (1152 and 1048 N against 661 and 570 N); over 66 perturbations of
  // 0.1-10 µN, the smaller span's ratio 0.76-2.2 (median 1.27), so 0.25 holds it with a margin
  // of 3 on the least of them. A loop that was not chaotic would keep the difference at its
  // start's size (2.2e-3 N rms over the first 50 ms: a ratio of 3e-6); the example against
  // itself gives 0 (checked to fail).
  const auto a = dynamics(kExample, "");
  const std::string perturbed = perturbed_example();
  const auto b = dynamics(perturbed, "");
  fs::remove(perturbed);
  ASSERT_FALSE(a.is_null() || b.is_null());
  const auto time = a["time"].get<std::vector<double>>();
  ASSERT_EQ(time, b["time"].get<std::vector<double>>());
  for (int k = 0; k < 2; ++k) {
    const auto xa = a["span"][k]["tension"].get<std::vector<double>>();
    const auto xb = b["span"][k]["tension"].get<std::vector<double>>();
    double n = 0, sum = 0, squares = 0, difference = 0;
    for (std::size_t i = 0; i < time.size(); ++i) {
      if (time[i] <= time.back() / 2) continue;
      n += 1;
      sum += xa[i];
      squares += xa[i] * xa[i];
      difference += (xa[i] - xb[i]) * (xa[i] - xb[i]);
    }
    const double sd = std::sqrt(squares / n - (sum / n) * (sum / n));
    EXPECT_GT(std::sqrt(difference / n), 0.25 * sd) << "span " << k << ": sd " << sd;
  }
}

// A series' sample mean, variance (n − 1), lag-1 autocorrelation and kurtosis (m4/m2²).
struct SeriesStats {
  double mean = 0, variance = 0, lag1 = 0, kurtosis = 0;
};

SeriesStats series_stats(const std::vector<double>& x) {
  const double n = static_cast<double>(x.size());
  SeriesStats s;
  for (double v : x) s.mean += v / n;
  double m2 = 0, m4 = 0, lag = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double d = x[i] - s.mean;
    m2 += d * d;
    m4 += d * d * d * d;
    if (i + 1 < x.size()) lag += d * (x[i + 1] - s.mean);
  }
  s.variance = m2 / (n - 1);
  s.lag1 = lag / m2;
  s.kurtosis = n * m4 / (m2 * m2);
  return s;
}

TEST(DynamicsPocketMeansCli, ThreePeriodErrorMatchesTheScatterOfStationaryWindows) {
  // The example reports its 3 periods' mean with the error s/√3 (period_means_error below 10
  // periods: the periods taken as independent). Checked against the scatter it claims to
  // measure: one 40 s run of the example cut, from the example's own window start (0.5 s; its
  // first window is the example's), into W = 83 consecutive 3-period windows, each window's mean
  // over its samples and its error from period_means_error on its 3 period means, as the command
  // computes them. If the periods were independent, E[e²] = Var(window mean); with their lag-1
  // correlation ρ (AR(1); 3 periods cannot estimate it, the run's 251 can: period_means_error's
  // bias-corrected ρ over all of them), Var(mean of 3) = σ²/3 (1 + (4ρ + 2ρ²)/3) and
  // E[s²] = σ² (1 − (2ρ + ρ²)/3), so S²/ē² → F(ρ) = (1 + (4ρ + 2ρ²)/3) / (1 − (2ρ + ρ²)/3), S² the
  // windows' means' sample variance, ē² their errors' mean square. Asserted: |L| < 3.29 σ_L,
  // L = ln(S²/ē²) − ln F(ρ̂), where (chi-square: Var ln(χ²_ν/ν) ≈ 2/ν)
  //  * S² over W means of kurtosis κ and lag-1 correlation r1: Var(S²)/σ⁴ ≈ ((κ − 1) + 4 r1²)
  //    /(W − 1) (Box 1953 for κ; Bartlett 1946 for the correlation, lag 1 only), so
  //    ν1 = 2(W − 1)/((κ − 1) + 4 r1²), κ the windows' own but at least 3 (a normal's);
  //  * ē² over W errors e² of relative variance v and lag-1 correlation r_e: ν2 = 2W/(v (1 +
  //    2 r_e)), v at least 1 (s² of 3 independent normal means: χ²₂) and r_e at least 0;
  //  * ρ̂ over n = 251 periods: sd √((1 − ρ²)/n), times d ln F/dρ (2 at ρ = 0);
  //  σ_L² = 2/ν1 + 2/ν2 + that², the three taken as independent (S² and ρ̂ rise together, which
  //  narrows L: conservative). 3.29 σ is a normal's two-sided 0.1 %.
  // The periods' correlation depends on where the grid of periods is cut: on the example's grid
  // it is near 0, on a grid 0.3 T later near 0.3 (there the 3-period error is low by √F). Both
  // grids are checked. Measured on the example (h = 0.1 ms), on its grid: S/ē = 0.83 on both
  // spans (the 3-period means' sd 159 and 158 N, rms error 191 and 189 N), ρ̂ = 0 (the periods'
  // r1 −0.08, clamped), the windows' r1 −0.03, κ 3.1, v 0.94, r_e −0.06: L = −0.37, σ_L = 0.23, a
  // bound of 0.76; 0.3 T later: S/ē = 1.03, ρ̂ = 0.18, v 1.77: L = −0.30, σ_L = 0.25. Over 33
  // independent 40 s runs (the example and the pretension 1000 N + 7.3k µN, k = 1..32: the
  // draws part by 0.5 s), on the example's grid L has mean 0.025 and sd 0.18 against σ_L
  // 0.23-0.37 (the model is wider than the runs), the largest |L|/σ_L 1.6, S/ē 0.83-1.49
  // (geometric mean 1.06), ρ̂ 0-0.26; 0.3 T later L −0.04 ± 0.14, the largest |L|/σ_L 1.2, S/ē
  // 1.03-2.07 (1.35), ρ̂ 0.15-0.50; three runs at h = 0.05 ms: |L|/σ_L ≤ 1.14 on both grids. The
  // bound is at least 0.76, 4 of the runs' deviations: a false alarm (another draw of the same
  // scatter, as a tolerance-level change of the code gives) is well below 1 %. The error scaled
  // by 0.5 or 2 gives L = 1.02 and −1.76 (1.08 and −1.69 0.3 T later) on the example: checked to
  // fail. CPU: the 40 s run about 4.2 s.
  const auto j = dynamics(kExample, "--duration 40s");
  const auto example = dynamics(kExample, "");
  ASSERT_FALSE(j.is_null() || example.is_null());
  // the 1 s example's window starts at half its last sample's time, the 40 s run's sample 1000
  ASSERT_EQ(j["time"][1000], example["time"].back());
  const double period = 2 * kPi / (8 * 5.0);
  constexpr int kWindow = 3;
  for (const double offset : {0.0, 0.3}) {
    const double t0 = j["time"][1000].get<double>() / 2 + offset * period;
    for (int k = 0; k < 2; ++k) {
      const std::string key = "span_" + std::to_string(k);
      const PeriodSums p = period_sums(j, k, t0);
      const std::size_t periods = p.sum.size(), windows = periods / kWindow;
      ASSERT_EQ(periods, 251u);
      std::vector<double> mean, error2;
      for (std::size_t w = 0; w < windows; ++w) {
        const Spread s = spread(p, kWindow * w, kWindow * (w + 1));
        ASSERT_EQ(s.e.periods, kWindow);
        ASSERT_TRUE(std::isnan(s.e.correlation));  // taken as independent, as the example's
        mean.push_back(s.mean);
        error2.push_back(s.e.error * s.e.error);
      }
      if (offset == 0.0) {  // the first window is the example's: its summary's mean and error
        const auto& summary = example["summary"][key];
        EXPECT_NEAR(mean[0], summary["mean_tension"].get<double>(), 1e-9 * mean[0]);
        EXPECT_NEAR(std::sqrt(error2[0]), summary["mean_tension_error"].get<double>(),
                    1e-9 * mean[0]);
      }
      const double rho = spread(p, 0, periods).e.correlation, n = static_cast<double>(periods);
      ASSERT_TRUE(std::isfinite(rho));
      const SeriesStats m = series_stats(mean), e = series_stats(error2);
      const double W = static_cast<double>(windows);
      const double nu1 = 2 * (W - 1) / (std::max(m.kurtosis, 3.0) - 1 + 4 * m.lag1 * m.lag1);
      const double nu2 =
          2 * W / (std::max(e.variance / (e.mean * e.mean), 1.0) * (1 + 2 * std::max(e.lag1, 0.0)));
      const double a = 1 + (4 * rho + 2 * rho * rho) / 3, b = 1 - (2 * rho + rho * rho) / 3;
      const double dlnf = (4 + 4 * rho) / 3 / a + (2 + 2 * rho) / 3 / b;
      const double sigma = std::sqrt(2 / nu1 + 2 / nu2 + dlnf * dlnf * (1 - rho * rho) / n);
      const double l = std::log(m.variance / e.mean) - std::log(a / b);
      EXPECT_LT(std::abs(l), 3.29 * sigma)
          << key << ", grid " << offset << " T later: L " << l << ", S " << std::sqrt(m.variance)
          << " N, rms error " << std::sqrt(e.mean) << " N, rho " << rho << ", windows' r1 "
          << m.lag1 << ", kurtosis " << m.kurtosis << ", sigma_L " << sigma;
    }
  }
}

}  // namespace
