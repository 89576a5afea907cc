// The spans' first natural frequencies (dynamics/span_modes.hpp) against numerics that do not
// use their closed forms: the lowest eigenvalue of the fixed–fixed spring–mass chain by inverse
// iteration on its tridiagonal stiffness, and the moving string's lowest root of the boundary
// condition u(0) = u(L) = 0 found by bisection on its travelling-wave solution.
#include "catena/dynamics/span_modes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <random>
#include <tuple>
#include <vector>

namespace catena::dynamics {
namespace {

constexpr double kPi = std::numbers::pi;

// The lowest ω² of n − 1 equal masses m between n springs k, both ends held: inverse iteration
// (Thomas solve of the tridiagonal K x = M y) to convergence.
double lowest_omega2(int links, double k, double m) {
  const int n = links - 1;
  std::vector<double> x(static_cast<std::size_t>(n), 1.0), y(x), c(x), d(x);
  double lambda = 0.0;
  for (int it = 0; it < 20000; ++it) {
    // solve (k · tridiag(−1, 2, −1)) y = m x
    for (int i = 0; i < n; ++i) d[i] = m * x[i];
    c[0] = -1.0 / 2.0;
    d[0] = d[0] / (2.0 * k);
    for (int i = 1; i < n; ++i) {
      const double den = 2.0 * k + k * c[i - 1];
      c[i] = -k / den;
      d[i] = (d[i] + k * d[i - 1]) / den;
    }
    y[n - 1] = d[n - 1];
    for (int i = n - 2; i >= 0; --i) y[i] = d[i] - c[i] * y[i + 1];
    // Rayleigh quotient of y: (yᵀ K y) / (yᵀ M y)
    double num = 0.0, den = 0.0;
    for (int i = 0; i < n; ++i) {
      const double left = i > 0 ? y[i - 1] : 0.0, right = i + 1 < n ? y[i + 1] : 0.0;
      num += y[i] * k * (2.0 * y[i] - left - right);
      den += m * y[i] * y[i];
    }
    const double next = num / den;
    double norm = 0.0;
    for (double v : y) norm = std::max(norm, std::abs(v));
    for (int i = 0; i < n; ++i) x[i] = y[i] / norm;
    if (it > 10 && std::abs(next - lambda) <= 1e-15 * next) return next;
    lambda = next;
  }
  return lambda;
}

// u = e^{iωt}(e^{i k1 x} − e^{i k2 x}) with k the roots of (c² − v²) k² − 2 v ω k − ω² = 0 solves
// the moving string u_tt + 2 v u_xt + (v² − c²) u_xx = 0 and u(0) = 0; u(L) = 0 picks ω. Its
// lowest positive root by a scan and bisection on Im of e^{-i k2 L} u(L) (real-valued here).
double moving_string_f1(double L, double c, double v) {
  auto residual = [&](double w) {
    const double a = c * c - v * v, b = -2.0 * v * w, cc = -w * w;
    const double disc = std::sqrt(b * b - 4.0 * a * cc);
    const double k1 = (-b + disc) / (2.0 * a), k2 = (-b - disc) / (2.0 * a);
    return std::sin(0.5 * (k1 - k2) * L);  // |e^{ik1L} − e^{ik2L}| = 2|sin((k1 − k2)L/2)|
  };
  const double dw = 1e-3 * kPi * c / L;
  double lo = dw, hi = 2.0 * dw;
  while (residual(lo) * residual(hi) > 0.0) lo = hi, hi += dw;
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    (residual(lo) * residual(mid) <= 0.0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi) / (2.0 * kPi);
}

TEST(SpanModes, LongitudinalIsTheSpringMassChainsLowestEigenvalue) {
  const double pitch = 0.01905, q = 1.25, k = 5e7;
  for (int links : {2, 3, 10, 37, 200}) {
    const double f = span_frequencies(links * pitch, 500.0, q, 2.0, k, pitch).longitudinal;
    const double exact = std::sqrt(lowest_omega2(links, k, q * pitch)) / (2.0 * kPi);
    EXPECT_NEAR(f / exact, 1.0, 1e-10) << links;
  }
  // the continuum limit (1/2L) √(k p / q)
  const double L = 400 * pitch;
  EXPECT_NEAR(span_frequencies(L, 500.0, q, 0.0, k, pitch).longitudinal /
                  (std::sqrt(k * pitch / q) / (2.0 * L)),
              1.0, 2e-5);
}

TEST(SpanModes, TransverseIsTheMovingStringsLowestRoot) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 200; ++i) {
    const double L = 0.05 + 2.0 * u(rng), q = 0.2 + 8.0 * u(rng), T = 10.0 + 2e4 * u(rng);
    const double c = std::sqrt(T / q), v = 0.95 * c * u(rng);
    const double f = span_frequencies(L, T, q, v, 1e8, 0.01).transverse;
    EXPECT_NEAR(f / moving_string_f1(L, c, v), 1.0, 1e-9) << L << " " << T << " " << q << " " << v;
  }
  // at rest, the string's c/2L; at or above v = c, no transverse stiffness
  EXPECT_DOUBLE_EQ(span_frequencies(0.5, 400.0, 1.0, 0.0, 1e8, 0.01).transverse, 20.0);
  EXPECT_EQ(span_frequencies(0.5, 400.0, 1.0, 20.0, 1e8, 0.01).transverse, 0.0);
  EXPECT_EQ(span_frequencies(0.5, 400.0, 1.0, 30.0, 1e8, 0.01).transverse, 0.0);
}

TEST(SpanModes, InvalidInputIsNaN) {
  for (const auto& [L, T, q, v, k, p] :
       {std::tuple{0.005, 100.0, 1.0, 1.0, 1e8, 0.01}, std::tuple{0.5, 0.0, 1.0, 1.0, 1e8, 0.01},
        std::tuple{0.5, 100.0, 0.0, 1.0, 1e8, 0.01}, std::tuple{0.5, 100.0, 1.0, -1.0, 1e8, 0.01},
        std::tuple{0.5, 100.0, 1.0, 1.0, 0.0, 0.01},
        std::tuple{0.5, double(NAN), 1.0, 1.0, 1e8, 0.01},
        std::tuple{0.5, 100.0, 1.0, double(INFINITY), 1e8, 0.01}}) {
    const SpanFrequencies f = span_frequencies(L, T, q, v, k, p);
    EXPECT_TRUE(std::isnan(f.transverse) && std::isnan(f.longitudinal)) << L << " " << T;
  }
}

}  // namespace
}  // namespace catena::dynamics
