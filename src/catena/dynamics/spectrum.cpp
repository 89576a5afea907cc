#include "catena/dynamics/spectrum.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace catena::dynamics {

void fft(std::vector<std::complex<double>>& a) {
  const std::size_t n = a.size();
  if (n == 0 || (n & (n - 1)) != 0) throw std::invalid_argument("fft: size not a power of two");
  // bit-reversal permutation
  for (std::size_t i = 1, j = 0; i < n; ++i) {
    std::size_t bit = n >> 1;
    for (; j & bit; bit >>= 1) j ^= bit;
    j ^= bit;
    if (i < j) std::swap(a[i], a[j]);
  }
  // butterflies; each stage's twiddles from cos/sin directly (no drift from repeated products)
  for (std::size_t len = 2; len <= n; len <<= 1) {
    const double angle = -2.0 * std::numbers::pi / static_cast<double>(len);
    const std::size_t half = len / 2;
    std::vector<std::complex<double>> w(half);
    for (std::size_t k = 0; k < half; ++k) w[k] = std::polar(1.0, angle * static_cast<double>(k));
    for (std::size_t start = 0; start < n; start += len) {
      for (std::size_t k = 0; k < half; ++k) {
        const std::complex<double> u = a[start + k], v = a[start + k + half] * w[k];
        a[start + k] = u + v;
        a[start + k + half] = u - v;
      }
    }
  }
}

Spectrum amplitude_spectrum(const std::vector<double>& signal, double dt, std::size_t padding) {
  if (signal.size() < 4) throw std::invalid_argument("amplitude_spectrum: fewer than 4 samples");
  if (!(dt > 0.0 && std::isfinite(dt)))
    throw std::invalid_argument("amplitude_spectrum: dt must be > 0 and finite");
  if (padding == 0) throw std::invalid_argument("amplitude_spectrum: padding must be >= 1");
  const std::size_t n = std::min(signal.size(), kMaxSpectrumSamples);
  const std::size_t first = signal.size() - n;
  // the window first, then its weighted mean removed: the DC bin is zero and a tone over a
  // fraction of a cycle does not shift the baseline (the plain mean would, by A/(2π cycles))
  std::vector<double> w(n);
  double window_sum = 0.0, mean = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    w[k] = 0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * static_cast<double>(k) /
                                static_cast<double>(n - 1));
    window_sum += w[k];
    mean += w[k] * signal[first + k];
  }
  mean /= window_sum;
  std::size_t length = 1;
  while (length < padding * n && length < kMaxSpectrumLength) length <<= 1;
  while (length < n) length <<= 1;  // never shorter than the signal
  std::vector<std::complex<double>> a(length, 0.0);
  for (std::size_t k = 0; k < n; ++k) a[k] = w[k] * (signal[first + k] - mean);
  fft(a);
  Spectrum s;
  s.samples = n;
  s.length = length;
  const std::size_t bins = length / 2 + 1;
  s.frequency.resize(bins);
  s.amplitude.resize(bins);
  for (std::size_t m = 0; m < bins; ++m) {
    s.frequency[m] = static_cast<double>(m) / (static_cast<double>(length) * dt);
    const double scale = (m == 0 || 2 * m == length) ? 1.0 : 2.0;  // one-sided
    s.amplitude[m] = scale * std::abs(a[m]) / window_sum;
  }
  return s;
}

}  // namespace catena::dynamics
