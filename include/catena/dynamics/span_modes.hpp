// The first natural frequencies of a free chain span between two wheels, from its mean running
// tension: what a chain engineer holds against the tooth-mesh frequency (resonance), and what
// `catena dynamics` reports per span and the report marks on the span-tension spectrum.
#pragma once

namespace catena::dynamics {

/// First natural frequencies of a span [Hz].
struct SpanFrequencies {
  /// Transverse, of the axially moving string (C. D. Mote Jr., Shock Vib. Dig. 4 (1972) 2–11;
  /// J. A. Wickert, C. D. Mote Jr., J. Appl. Mech. 57 (1990) 738–744): f1 = (1/2L) c (1 − v²/c²),
  /// c² = T/q. 0 when T ≤ q v² (the span has no transverse stiffness at this speed).
  double transverse = 0.0;
  /// Longitudinal, of the span as a chain of L/p links of stiffness k and node mass q p held at
  /// both ends (the rollers at the tangent points): f1 = (1/π) √(k / (q p)) sin(π p / 2L), the
  /// fixed–fixed spring–mass chain's lowest eigenvalue (exact for a whole number of links; its
  /// continuum limit is (1/2L) √(k p / q)).
  double longitudinal = 0.0;
};

/// `length` L [m] between the tangent points, `tension` T [N] (the mean running tension),
/// `mass_per_metre` q [kg/m], `speed` v [m/s] (the chain's), `link_stiffness` k [N/m] (one
/// link's axial stiffness), `pitch` p [m]. Every input positive and finite (speed ≥ 0), and
/// L ≥ p; NaN otherwise.
SpanFrequencies span_frequencies(double length, double tension, double mass_per_metre, double speed,
                                 double link_stiffness, double pitch);

}  // namespace catena::dynamics
