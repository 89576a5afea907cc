// The report's spectrum (include/catena/dynamics/spectrum.hpp) and chart helpers
// (report_charts.hpp): the FFT against a direct DFT written here, the amplitude spectrum's peaks
// and amplitudes on synthetic signals with known tones, and the size bounds of the charts.
#include "catena/dynamics/spectrum.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <random>
#include <stdexcept>

#include "catena/dynamics/report_charts.hpp"

namespace catena::dynamics {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(Fft, EqualsTheDirectSumOnRandomInput) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::size_t n : {1u, 2u, 4u, 8u, 64u, 512u}) {
    std::vector<std::complex<double>> a(n);
    for (auto& v : a) v = {u(rng), u(rng)};
    const auto x = a;
    fft(a);
    double scale = 0.0, worst = 0.0;
    for (std::size_t m = 0; m < n; ++m) {
      std::complex<double> sum = 0.0;
      for (std::size_t k = 0; k < n; ++k)
        sum += x[k] * std::polar(1.0, -2.0 * kPi * static_cast<double>((k * m) % n) /
                                          static_cast<double>(n));
      worst = std::max(worst, std::abs(sum - a[m]));
      scale = std::max(scale, std::abs(sum));
    }
    EXPECT_LE(worst, 1e-12 * std::max(1.0, scale)) << "n = " << n;
  }
}

TEST(Fft, RefusesSizesThatAreNotPowersOfTwo) {
  std::vector<std::complex<double>> a(12);
  EXPECT_THROW(fft(a), std::invalid_argument);
  std::vector<std::complex<double>> none;
  EXPECT_THROW(fft(none), std::invalid_argument);
}

// The largest local maxima of a spectrum: (frequency, amplitude), strongest first.
std::vector<std::pair<double, double>> peaks(const Spectrum& s, std::size_t count) {
  std::vector<std::pair<double, double>> found;
  for (std::size_t m = 1; m + 1 < s.amplitude.size(); ++m)
    if (s.amplitude[m] > s.amplitude[m - 1] && s.amplitude[m] >= s.amplitude[m + 1])
      found.emplace_back(s.frequency[m], s.amplitude[m]);
  std::sort(found.begin(), found.end(),
            [](const auto& a, const auto& b) { return a.second > b.second; });
  if (found.size() > count) found.resize(count);
  return found;
}

TEST(AmplitudeSpectrum, FindsKnownTonesWithTheirAmplitudes) {
  // a mean, three tones off the bins (a frequency resolution of 1/(n dt) = 0.977 Hz) and a
  // little noise; n is not a power of two
  const double dt = 1e-3;
  const std::size_t n = 1023;
  const std::vector<std::pair<double, double>> tones = {
      {24.83, 40.0}, {49.66, 12.0}, {211.3, 5.0}};  // (Hz, amplitude)
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 0.05);
  std::vector<double> x(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double t = static_cast<double>(k) * dt;
    x[k] = 950.0 + noise(rng);
    for (const auto& [f, a] : tones) x[k] += a * std::sin(2.0 * kPi * f * t + 0.3 * f);
  }
  const Spectrum s = amplitude_spectrum(x, dt);
  EXPECT_EQ(s.samples, n);
  EXPECT_EQ(s.length, 4096u);  // padded 4x, to a power of two
  EXPECT_DOUBLE_EQ(s.frequency[1], 1.0 / (4096 * dt));
  EXPECT_NEAR(s.frequency.back(), 0.5 / dt, 1e-9);
  EXPECT_LT(s.amplitude[0], 0.01);  // the mean is removed
  auto found = peaks(s, 3);
  ASSERT_EQ(found.size(), 3u);
  std::sort(found.begin(), found.end());
  const double bin = 1.0 / (4096 * dt);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(found[i].first, tones[i].first, bin) << "tone " << i;
    // zero padding 4x: the Hann window's scalloping is under 1 %; the noise adds little
    EXPECT_NEAR(found[i].second, tones[i].second, 0.015 * tones[i].second) << "tone " << i;
  }
}

TEST(AmplitudeSpectrum, AToneOnABinReadsItsAmplitude) {
  const double dt = 0.01;
  const std::size_t n = 256;
  std::vector<double> x(n);
  const double f = 10.0 / (static_cast<double>(n) * dt);  // bin 10 of the unpadded transform
  for (std::size_t k = 0; k < n; ++k)
    x[k] = 3.0 * std::cos(2.0 * kPi * f * static_cast<double>(k) * dt);
  const Spectrum s = amplitude_spectrum(x, dt, 1);
  EXPECT_EQ(s.length, n);
  EXPECT_NEAR(s.amplitude[10], 3.0, 0.03);  // the window over n − 1 intervals: ±1 % at most
  EXPECT_LT(s.amplitude[20], 1e-3);
}

TEST(AmplitudeSpectrum, IsBoundedAndRefusesBadInput) {
  std::vector<double> x(kMaxSpectrumSamples + 1000, 1.0);
  for (std::size_t k = 0; k < 1000; ++k) x[k] = 1e6;  // outside the last kMax samples
  const Spectrum s = amplitude_spectrum(x, 1.0);
  EXPECT_EQ(s.samples, kMaxSpectrumSamples);
  EXPECT_EQ(s.length, kMaxSpectrumLength);
  for (double a : s.amplitude) EXPECT_LT(a, 1e-9);  // the cut part is not seen
  EXPECT_THROW(amplitude_spectrum({1.0, 2.0, 3.0}, 1.0), std::invalid_argument);
  EXPECT_THROW(amplitude_spectrum({1, 2, 3, 4}, 0.0), std::invalid_argument);
  EXPECT_THROW(amplitude_spectrum({1, 2, 3, 4}, NAN), std::invalid_argument);
  EXPECT_THROW(amplitude_spectrum({1, 2, 3, 4}, 1.0, 0), std::invalid_argument);
}

TEST(DynamicsReportCharts, DecimationKeepsEachBucketsExtremes) {
  std::vector<double> t(10000), y(10000);
  for (std::size_t k = 0; k < t.size(); ++k) {
    t[k] = static_cast<double>(k);
    y[k] = std::sin(0.01 * static_cast<double>(k));
  }
  y[4321] = 50.0;  // a spike, one sample wide
  y[777] = -50.0;
  const analysis::Trace d = decimated("y", t, y, 200);
  EXPECT_EQ(d.x.size(), 200u);
  EXPECT_TRUE(std::is_sorted(d.x.begin(), d.x.end()));
  EXPECT_EQ(*std::max_element(d.y.begin(), d.y.end()), 50.0);
  EXPECT_EQ(*std::min_element(d.y.begin(), d.y.end()), -50.0);
  const analysis::Trace all = decimated("y", {0, 1, 2}, {3, 4, 5}, 200);
  EXPECT_EQ(all.y, (std::vector<double>{3, 4, 5}));
}

TEST(DynamicsReportCharts, MeshMarkersAreTheHarmonicsOfZOmega) {
  const double omega = 13.0;
  const double f = 12 * omega / (2 * kPi);  // 24.83 Hz
  const auto m = mesh_markers(12, omega, 80.0);
  ASSERT_EQ(m.size(), 3u);  // 24.8, 49.7, 74.5 Hz; 99.3 is above 80
  for (std::size_t k = 0; k < m.size(); ++k)
    EXPECT_DOUBLE_EQ(m[k].x, static_cast<double>(k + 1) * f);
  EXPECT_NE(m[0].label.find("24.83 Hz"), std::string::npos);
  EXPECT_EQ(mesh_markers(12, omega, 1e6).size(), static_cast<std::size_t>(kSpectrumHarmonics));
  EXPECT_TRUE(mesh_markers(12, 0.0, 100.0).empty());
}

TEST(DynamicsReportCharts, FrameCountIsBounded) {
  EXPECT_EQ(frame_count(32, 300), kMaxFrames);
  EXPECT_EQ(frame_count(10000, 300), 2u);
  const std::size_t f = frame_count(800, 300);
  EXPECT_LE(f * (800 + 1 + 300), kMaxFramePoints);
  EXPECT_GT((f + 1) * (800 + 1 + 300), kMaxFramePoints);
}

}  // namespace
}  // namespace catena::dynamics
