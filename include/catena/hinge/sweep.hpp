// Design sweep over the plate radius R1 (seed 000 §1.2: "assuming different values of R1, the
// optimal parameters of the hinge are determined").
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "catena/hinge/synthesis.hpp"

namespace catena::hinge {

struct SweepRow {
  double r1 = 0.0;                       ///< [m]
  double r2 = 0.0;                       ///< [m] eq. (6)
  double psi1_max = 0.0;                 ///< [rad]
  double effective_radius = 0.0;         ///< [m] R* = R1R2/(R2 − R1) of the contact
  std::optional<double> contact_stress;  ///< [Pa] with tension and contact length
  std::optional<double> rolling_limit;   ///< [rad] with friction
  std::optional<double> a_min;           ///< [m] with tension and [τ]
  double max_pitch_change = 0.0;         ///< [m] largest |Δt| over 0 ≤ φ ≤ φmax
  double face_margin = 0.0;              ///< [m]
  bool feasible = true;                  ///< no infeasible diagnostic
};

struct Sweep {
  std::vector<SweepRow> rows;
  std::optional<std::size_t> best;  ///< index of the chosen row (none if no row is feasible)
  std::string criterion;            ///< how `best` was chosen
};

/// Sweeps R1 over `count` values from just above the smallest radius for which N1 exists,
/// (d/2 − a)/2, to just below R1max, with R2 from eq. (6) and the hinge's a, z, m. The best row
/// is the feasible one with the lowest Hertz stress — equivalently the largest R* — since σH is
/// what limits a rolling hinge's life; ties are not expected. Concave faces only.
Sweep sweep(const Hinge& hinge, const Loads& loads, int count);

/// [m] largest |Δt| over [0, φmax]: `samples` turns, an interior maximum refined by Brent's
/// method (so the result does not depend on an output's sampling).
double max_pitch_change(const Hinge& hinge, double r2, int samples = 201);

}  // namespace catena::hinge
