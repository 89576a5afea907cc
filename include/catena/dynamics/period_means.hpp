// The standard error of a mean over whole periods when the periods' means are serially
// correlated, and how long a run would settle it (docs/models/dynamics.md, "Pocket wheel: the
// example's means"). `catena dynamics` reports it for a pocket-wheel loop, whose response does
// not repeat with the tooth period.
#pragma once

#include <span>

namespace catena::dynamics {

/// Below this many periods the lag-1 autocorrelation is not estimated (its sampling deviation,
/// about 1/√n, would be 0.3 or more) and the periods' means are taken as independent.
inline constexpr int kCorrelationMinPeriods = 10;
/// The largest lag-1 autocorrelation used: an estimate above it is clamped (the AR(1) inflation
/// (1 + ρ)/(1 − ρ) would otherwise grow without bound on an estimate's sampling error).
inline constexpr double kCorrelationMax = 0.8;

/// The window's mean over n period means x_i and its standard error.
struct PeriodMeansError {
  int periods = 0;  ///< n (0: fewer than 2 means, nothing estimated)
  double sd = 0.0;  ///< s, the means' sample standard deviation (n − 1 in the denominator)
  /// ρ, the lag-1 autocorrelation used: r1 = Σ (x_i − x̄)(x_{i+1} − x̄) / Σ (x_i − x̄)² with
  /// Kendall's and Marriott–Pope's bias correction for an AR(1) of unknown mean
  /// (E[r1] ≈ ρ − (1 + 3ρ)/n: ρ = (n r1 + 1)/(n − 3)), clamped to [0, kCorrelationMax]. NaN
  /// when n < kCorrelationMinPeriods: the means are then taken as independent (ρ = 0).
  double correlation = 0.0;
  /// n / (1 + 2 g), g = Σ_{k=1}^{n−1} (1 − k/n) ρ^k (Bayley & Hammersley 1946): the number of
  /// independent means whose mean has the same variance; n when the means are independent.
  double effective_periods = 0.0;
  /// The standard error of x̄ for an AR(1) sequence of lag-1 autocorrelation ρ:
  /// Var(x̄) = σ² (1 + 2g)/n and E[s²] = σ² (1 − 2g/(n − 1)), so
  /// error² = s²/n · (n − 1)(1 + 2g)/(n − 1 − 2g); s/√n when ρ = 0.
  double error = 0.0;
};

/// The estimate from the period means (fewer than 2: periods = 0 and nothing else set).
PeriodMeansError period_means_error(std::span<const double> means);

/// The window's periods that would bring the standard error to `bound` × `scale` (scale > 0):
/// n′ = n (error / (bound · scale))², the error falling as 1/√n at the correlation estimated (for
/// large n, (s / (bound · scale))² (1 + ρ)/(1 − ρ); (s / (bound · scale))² when the means are
/// taken as independent). n′ > n whenever the error is above the bound (the large-n factor
/// alone, below the finite-n one, could ask for fewer periods than the window already has).
/// Infinite when scale or bound is not positive or fewer than 2 means were given.
double periods_to_settle(const PeriodMeansError& e, double scale, double bound);

}  // namespace catena::dynamics
