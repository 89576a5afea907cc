#include "catena/dynamics/period_means.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace catena::dynamics {

PeriodMeansError period_means_error(std::span<const double> means) {
  PeriodMeansError e;
  const std::size_t size = means.size();
  if (size < 2) return e;
  const double n = static_cast<double>(size);
  double mean = 0.0;
  for (double m : means) mean += m;
  mean /= n;
  double ss = 0.0, lag = 0.0;
  for (std::size_t i = 0; i < size; ++i) {
    ss += (means[i] - mean) * (means[i] - mean);
    if (i + 1 < size) lag += (means[i] - mean) * (means[i + 1] - mean);
  }
  e.periods = static_cast<int>(size);
  e.sd = std::sqrt(ss / (n - 1));
  double rho = 0.0;
  if (e.periods < kCorrelationMinPeriods) {
    e.correlation = std::numeric_limits<double>::quiet_NaN();
  } else if (ss > 0.0) {
    rho = std::clamp((n * lag / ss + 1.0) / (n - 3.0), 0.0, kCorrelationMax);
    e.correlation = rho;
  } else {
    // equal means (s = 0): no correlation to speak of, and none needed (the bias correction
    // would give 1/(n − 3)); means that are not finite: none estimated
    e.correlation = ss == 0.0 ? 0.0 : std::numeric_limits<double>::quiet_NaN();
  }
  double g = 0.0, power = 1.0;
  for (std::size_t k = 1; k < size && rho > 0.0; ++k) {
    power *= rho;
    g += (1.0 - static_cast<double>(k) / n) * power;
  }
  // n ≥ 10 and ρ ≤ 0.8 keep n − 1 − 2g ≥ 1: g < ρ/(1 − ρ) ≤ 4
  e.effective_periods = n / (1.0 + 2.0 * g);
  e.error = e.sd / std::sqrt(n);
  if (g > 0.0) e.error *= std::sqrt((n - 1.0) * (1.0 + 2.0 * g) / (n - 1.0 - 2.0 * g));
  return e;
}

double periods_to_settle(const PeriodMeansError& e, double scale, double bound) {
  if (!(scale > 0.0) || !(bound > 0.0) || e.periods < 2)
    return std::numeric_limits<double>::infinity();
  return e.periods * std::pow(e.error / (bound * scale), 2);
}

}  // namespace catena::dynamics
