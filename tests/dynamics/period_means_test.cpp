// The standard error of a mean over serially correlated period means (period_means.hpp; docs/
// models/dynamics.md, "Pocket wheel: the example's means"), against synthetic AR(1) sequences
// of known lag-1 autocorrelation ρ and innovation deviation σ, independent of the simulator: the
// true standard deviation of the mean of n terms of a stationary AR(1) is
// σ/√(1 − ρ²) · √((1 + 2 Σ_{k=1}^{n−1} (1 − k/n) ρ^k)/n).
#include "catena/dynamics/period_means.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace {

using catena::dynamics::kCorrelationMax;
using catena::dynamics::kCorrelationMinPeriods;
using catena::dynamics::period_means_error;
using catena::dynamics::PeriodMeansError;
using catena::dynamics::periods_to_settle;

// n terms of a stationary AR(1) about `level`: x_{i+1} − level = ρ (x_i − level) + σ ε_i
std::vector<double> ar1(std::mt19937_64& rng, int n, double rho, double sigma, double level) {
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<double> x;
  double y = sigma / std::sqrt(1 - rho * rho) * normal(rng);  // from the stationary law
  for (int i = 0; i < n; ++i) {
    x.push_back(level + y);
    y = rho * y + sigma * normal(rng);
  }
  return x;
}

double true_sd_of_mean(int n, double rho, double sigma) {
  double g = 0;
  for (int k = 1; k < n; ++k) g += (1.0 - double(k) / n) * std::pow(rho, k);
  return sigma / std::sqrt(1 - rho * rho) * std::sqrt((1 + 2 * g) / n);
}

struct Check {
  double ratio = 0;     // √(mean of error²) / the true deviation of the mean
  double coverage = 0;  // the share of replicas whose |x̄ − level| ≤ 2 errors
};

// `independent`: the periods taken as independent (s/√n), the estimate before the correlation
Check replicas(int n, double rho, bool independent) {
  constexpr int kReplicas = 4000;
  constexpr double kSigma = 250.0, kLevel = 1500.0;  // N: of the pocket example's periods
  std::mt19937_64 rng(21 + n + static_cast<int>(100 * rho));
  double e2 = 0, covered = 0;
  for (int r = 0; r < kReplicas; ++r) {
    const std::vector<double> x = ar1(rng, n, rho, kSigma, kLevel);
    double mean = 0;
    for (double v : x) mean += v / n;
    const PeriodMeansError e = period_means_error(x);
    const double error = independent ? e.sd / std::sqrt(double(n)) : e.error;
    e2 += error * error;
    covered += std::abs(mean - kLevel) <= 2 * error ? 1 : 0;
  }
  return {std::sqrt(e2 / kReplicas) / true_sd_of_mean(n, rho, kSigma), covered / kReplicas};
}

// The pocket example's 10 s and 20 s windows (31, 63 periods) and a short one (12), at the
// correlations measured on its periods (up to 0.30 over 20 s and 0.46 over 10 s with the
// bilateral links, 0.12-0.14 over 10 s with the tension-only ones) and twice that, 4000 replicas
// each. 31 and 63 periods: the error's rms is within −5 %/+20 % of the true deviation of the mean
// and ±2 errors cover it in 89-99 % of replicas (a normal mean's 95.4 %; measured 1.03-1.13 and
// 0.91-0.96); 12 periods, where ρ is barely estimable: rms within −5 %/+35 % (measured 1.21-1.28),
// coverage at least 83 % (0.85-0.95). Taking the periods as independent, s/√n, fails at
// ρ = 0.3 and 0.6: its rms is 1/√((1 + ρ)/(1 − ρ)) of the truth (measured 0.72-0.73 and
// 0.48-0.50) and its coverage 0.82-0.85 and 0.63-0.68.
TEST(PeriodMeans, StandardErrorOfCorrelatedMeansMatchesAr1) {
  for (int n : {12, 31, 63}) {
    const bool few = n < 20;
    for (double rho : {0.0, 0.3, 0.6}) {
      const Check c = replicas(n, rho, false);
      EXPECT_GT(c.ratio, 0.95) << n << " " << rho;
      EXPECT_LT(c.ratio, few ? 1.35 : 1.2) << n << " " << rho;
      EXPECT_GT(c.coverage, few ? 0.83 : 0.89) << n << " " << rho;
      EXPECT_LT(c.coverage, 0.99) << n << " " << rho;
      const Check old = replicas(n, rho, true);
      if (rho == 0.0) {
        EXPECT_NEAR(old.ratio, 1.0, 0.05) << n;  // independent periods: s/√n is right
      } else {
        EXPECT_LT(old.ratio, 0.8) << n << " " << rho;  // outside the bounds above
        if (!few) {
          EXPECT_LT(old.coverage, 0.89) << n << " " << rho;
        }
      }
    }
  }
}

// The estimated correlation itself: over 4000 replicas of 63 terms its mean is within 0.02 of
// ρ (measured 0.296 and 0.589 at ρ = 0.3 and 0.6; the plain lag-1 estimate's mean is
// ρ − (1 + 3ρ)/n, measured 0.266 and 0.545); a negative ρ is clamped to 0 (the error then s/√n),
// one near 1 to kCorrelationMax.
TEST(PeriodMeans, CorrelationIsUnbiasedAndClamped) {
  std::mt19937_64 rng(63);
  for (double rho : {0.3, 0.6}) {
    double sum = 0;
    for (int r = 0; r < 4000; ++r)
      sum += period_means_error(ar1(rng, 63, rho, 1.0, 0.0)).correlation;
    EXPECT_NEAR(sum / 4000, rho, 0.02) << rho;
  }
  const std::vector<double> alternating = {1, -1, 1, -1, 1, -1, 1, -1, 1, -1, 1, -1};
  const PeriodMeansError a = period_means_error(alternating);
  EXPECT_EQ(a.correlation, 0.0);
  EXPECT_DOUBLE_EQ(a.error, a.sd / std::sqrt(12.0));
  EXPECT_DOUBLE_EQ(a.effective_periods, 12.0);
  std::vector<double> trend;  // r1 near 1: clamped
  for (int i = 0; i < 20; ++i) trend.push_back(i);
  const PeriodMeansError t = period_means_error(trend);
  EXPECT_EQ(t.correlation, kCorrelationMax);
  EXPECT_GT(t.error, 2 * t.sd / std::sqrt(20.0));
  EXPECT_LT(t.effective_periods, 20.0 / 3);
}

// Too few periods to estimate a correlation: the means are taken as independent, and said to
// be (correlation NaN); fewer than 2: nothing.
TEST(PeriodMeans, FewPeriodsAreTakenAsIndependent) {
  const std::vector<double> three = {1959.0, 1700.0, 2250.0};
  const PeriodMeansError e = period_means_error(three);
  EXPECT_EQ(e.periods, 3);
  EXPECT_TRUE(std::isnan(e.correlation));
  EXPECT_DOUBLE_EQ(e.effective_periods, 3.0);
  EXPECT_NEAR(e.sd, 275.155, 0.001);  // of 1959, 1700, 2250 (mean 1969.67)
  EXPECT_DOUBLE_EQ(e.error, e.sd / std::sqrt(3.0));
  std::vector<double> squares;
  for (int i = 0; i < kCorrelationMinPeriods; ++i) squares.push_back(i * i);
  EXPECT_TRUE(std::isfinite(period_means_error(squares).correlation));
  squares.pop_back();
  EXPECT_TRUE(std::isnan(period_means_error(squares).correlation));
  EXPECT_EQ(period_means_error(std::vector<double>{5.0}).periods, 0);
  EXPECT_EQ(period_means_error(std::vector<double>{}).periods, 0);
}

// The duration asked for: the periods that bring the error to the bound of the given scale,
// n′ = n (error/(bound scale))² (= (s/(bound scale))² for independent means). Against the loop's
// largest span mean a slack span whose mean is a few newtons asks for as many periods as the tight
// span's scatter would (here 225 for s = 300 N against 2000 N), not (300/4/0.01)² = 5.6e7 (about 18
// 000 hours of the example's 0.157 s periods) against its own 4 N.
TEST(PeriodMeans, PeriodsToSettleAgainstTheScale) {
  PeriodMeansError slack;
  slack.periods = 3;
  slack.sd = 300.0;
  slack.error = 300.0 / std::sqrt(3.0);
  slack.correlation = std::nan("");
  EXPECT_NEAR(periods_to_settle(slack, 2000.0, 0.01), 225.0, 1e-9);
  EXPECT_NEAR(periods_to_settle(slack, 4.0, 0.01), 5.625e7, 1e-3);
  EXPECT_TRUE(std::isinf(periods_to_settle(slack, 0.0, 0.01)));
  EXPECT_TRUE(std::isinf(periods_to_settle(slack, -3.0, 0.01)));
  EXPECT_TRUE(std::isinf(periods_to_settle(PeriodMeansError{}, 2000.0, 0.01)));
}

// With a correlation estimated the periods asked for follow the error as reported (its finite-n
// factor), so they exceed the window's own whenever the error is above the bound. The large-n
// factor (1 + ρ)/(1 − ρ) alone is below the finite-n one (n = 10, ρ = 0.5: by 1/1.054) and asked
// for fewer periods than the window held when the error was up to 5 % above the bound; the
// example below is such a window (the old rule gives 9.9 periods for a window of 10).
TEST(PeriodMeans, PeriodsToSettleExceedTheWindowWhenTheErrorIsAboveTheBound) {
  std::mt19937_64 rng(7);
  int checked = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const std::vector<double> x = ar1(rng, 10 + trial % 30, 0.5, 50.0, 2000.0);
    const PeriodMeansError e = period_means_error(x);
    if (!(e.correlation > 0.0)) continue;
    // the scale at which the error is 1.02 times the 1 % bound
    const double scale = e.error / (1.02 * 0.01);
    EXPECT_GT(periods_to_settle(e, scale, 0.01), e.periods) << trial;
    ++checked;
  }
  EXPECT_GT(checked, 100);
  // the window of 10 periods at ρ = 0.5 by hand: g = Σ (1 − k/10) 0.5^k, the finite-n factor
  PeriodMeansError e;
  e.periods = 10;
  e.sd = 1.0;
  e.correlation = 0.5;
  double g = 0.0;
  for (int k = 1; k < 10; ++k) g += (1.0 - k / 10.0) * std::pow(0.5, k);
  e.error = std::sqrt(9.0 * (1.0 + 2.0 * g) / (9.0 - 2.0 * g) / 10.0);
  const double scale = e.error / (1.02 * 0.01);
  EXPECT_NEAR(periods_to_settle(e, scale, 0.01), 10.0 * 1.02 * 1.02, 1e-9);
  EXPECT_LT(std::pow(e.sd / (0.01 * scale), 2) * 3.0, 10.0);  // the large-n rule: 9.87 periods
}

// Equal means: no correlation (0, not the bias correction's 1/(n − 3)), the error 0; means that
// are not finite: the correlation not estimated (NaN), the error not finite.
TEST(PeriodMeans, EqualOrNonFiniteMeans) {
  const std::vector<double> equal(12, 1500.0);
  const PeriodMeansError e = period_means_error(equal);
  EXPECT_EQ(e.correlation, 0.0);
  EXPECT_EQ(e.error, 0.0);
  EXPECT_EQ(e.effective_periods, 12.0);
  std::vector<double> bad(12, 1500.0);
  bad[4] = std::nan("");
  const PeriodMeansError b = period_means_error(bad);
  EXPECT_TRUE(std::isnan(b.correlation));
  EXPECT_FALSE(std::isfinite(b.error));
  bad[4] = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(std::isnan(period_means_error(bad).correlation));
}

}  // namespace
