// Fretting latent period of the fits of multi-strand roller chains (seed 001: Vikulov, eq. 1).
//
// τ = K1·Ra·exp(K2·A·N·f/Ra): Ra the arithmetic mean roughness, A the amplitude of relative slip,
// N the normal load, f the vibration frequency; K1 (lubricant regeneration, working conditions)
// and K2 (boundary-film capacity, surface strength) are empirical and have no defaults. The
// exponent is dimensionless, so K2 is in s/N and K1 in s/m (τ in s). Fretting resistance falls
// with amplitude, load and frequency — the paper's premise — only if K2 < 0; K2 ≥ 0 is rejected.
#pragma once

#include <vector>

#include "catena/core/error.hpp"

namespace catena::contact {

struct Fretting {
  double roughness = 0.0;  ///< [m] Ra
  double amplitude = 0.0;  ///< [m] A
  double load = 0.0;       ///< [N] N
  double frequency = 0.0;  ///< [1/s] f (vibration frequency, cycles per second)
  double k1 = 0.0;         ///< [s/m] K1 > 0
  double k2 = 0.0;         ///< [s/N] K2 < 0
};

std::vector<Issue> validate(const Fretting& f);

/// [s] τ, eq. (1). Throws InputError for invalid input.
double latent_period(const Fretting& f);

}  // namespace catena::contact
