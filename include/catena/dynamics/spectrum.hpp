// The amplitude spectrum of a sampled signal (the report's span-tension spectrum, issue 21): the
// (window-weighted) mean removed, a Hann window, zero padding, and a radix-2 fast Fourier transform
// written here.
#pragma once

#include <complex>
#include <cstddef>
#include <vector>

namespace catena::dynamics {

/// The transform is bounded: at most this many samples (the last ones) are used, and the padded
/// length is at most kMaxSpectrumLength.
inline constexpr std::size_t kMaxSpectrumSamples = std::size_t{1} << 16;
inline constexpr std::size_t kMaxSpectrumLength = std::size_t{1} << 18;

/// In-place discrete Fourier transform X_m = Σ_k x_k e^{−2πi km/n} (iterative radix-2
/// Cooley–Tukey); n = a.size() must be a power of two (1 included), else std::invalid_argument.
void fft(std::vector<std::complex<double>>& a);

/// One-sided amplitude spectrum: amplitude[m] at frequency[m] = m / (n_fft Δt), m = 0 … n_fft/2.
struct Spectrum {
  std::vector<double> frequency;  ///< [Hz]
  std::vector<double> amplitude;  ///< in the signal's unit
  std::size_t samples = 0;        ///< samples transformed (after the cap)
  std::size_t length = 0;         ///< n_fft, the padded length
};

/// The amplitude spectrum of `signal` sampled every `dt` seconds: the Hann window
/// w_k = ½ − ½ cos(2πk/(n − 1)) applied after removing the window-weighted mean Σw_k x_k / Σw_k,
/// zero-padded to the power of two ≥ `padding`·n (at most kMaxSpectrumLength), and scaled by 2/Σw_k
/// so that a sinusoid of amplitude A on a bin reads A (between bins, less by the window's
/// scalloping: about 1 % at most at padding 4). A signal longer than kMaxSpectrumSamples is cut to
/// its last kMaxSpectrumSamples samples. Fewer than 4 samples, dt ≤ 0 or non-finite, or padding 0:
/// std::invalid_argument.
Spectrum amplitude_spectrum(const std::vector<double>& signal, double dt, std::size_t padding = 4);

}  // namespace catena::dynamics
