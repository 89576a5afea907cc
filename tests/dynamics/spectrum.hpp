// Test helper: the spectral peaks of a sampled signal, from its Hann-windowed discrete-time
// Fourier transform (what an FFT samples, evaluated on a finer grid and refined by golden-section
// search on the continuous transform so that a peak is located to a small fraction of a bin).
// No expected frequency goes in: the peaks are found over a whole band.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

namespace catena::dynamics::testing {

// The signal with its mean removed and the Hann window applied.
inline std::vector<double> windowed(const std::vector<double>& s) {
  const std::size_t n = s.size();
  double mean = 0.0;
  for (double v : s) mean += v;
  mean /= static_cast<double>(n);
  std::vector<double> w(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double hann = 0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * static_cast<double>(k) /
                                             static_cast<double>(n - 1));
    w[k] = hann * (s[k] - mean);
  }
  return w;
}

// |Σ v_k e^{−iωkΔt}| of the windowed signal v.
inline double dtft_magnitude(const std::vector<double>& v, double dt, double f) {
  const double step = -2.0 * std::numbers::pi * f * dt;
  const double cs = std::cos(step), sn = std::sin(step);
  double re = 0.0, im = 0.0, cr = 1.0, ci = 0.0;  // e^{−iωkΔt} by rotation
  for (double x : v) {
    re += x * cr;
    im += x * ci;
    const double nr = cr * cs - ci * sn;
    ci = cr * sn + ci * cs;
    cr = nr;
  }
  return std::hypot(re, im);
}

// The `count` strongest local maxima of the spectrum in (f_min, f_max], each refined, returned in
// increasing frequency.
inline std::vector<double> spectral_peaks(const std::vector<double>& signal, double dt,
                                          double f_min, double f_max, std::size_t count) {
  const std::vector<double> s = windowed(signal);
  const double duration = dt * static_cast<double>(s.size());
  const double df = 0.25 / duration;            // four grid points a bin
  std::vector<std::pair<double, double>> grid;  // (f, magnitude)
  for (double f = f_min; f <= f_max; f += df) grid.emplace_back(f, dtft_magnitude(s, dt, f));
  std::vector<std::pair<double, double>> maxima;  // (magnitude, f)
  for (std::size_t i = 1; i + 1 < grid.size(); ++i) {
    if (grid[i].second > grid[i - 1].second && grid[i].second >= grid[i + 1].second) {
      maxima.emplace_back(grid[i].second, grid[i].first);
    }
  }
  std::sort(maxima.rbegin(), maxima.rend());
  if (maxima.size() > count) maxima.resize(count);
  std::vector<double> peaks;
  const double golden = (std::sqrt(5.0) - 1.0) / 2.0;
  for (const auto& m : maxima) {
    double a = m.second - df, b = m.second + df;
    for (int it = 0; it < 40; ++it) {
      const double c = b - golden * (b - a), d = a + golden * (b - a);
      if (dtft_magnitude(s, dt, c) > dtft_magnitude(s, dt, d)) {
        b = d;
      } else {
        a = c;
      }
    }
    peaks.push_back(0.5 * (a + b));
  }
  std::sort(peaks.begin(), peaks.end());
  return peaks;
}

}  // namespace catena::dynamics::testing
