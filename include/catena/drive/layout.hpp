// Two-sprocket chain drive layout: the textbook link count and centre distance, and the exact
// centre distance of the polygon wrap (pins seated on both pitch polygons, both spans taut, a
// chain of X rigid links), solved numerically. Lengths in m, angles in rad.
//
// Valid input. Every function checks its arguments at entry and throws one std::invalid_argument
// ("<function>: N invalid argument(s):" and one line per bad argument: its name as below, its
// value and its valid range) naming every bad argument at once:
// - pitch: 1e-90 m to 1e90 m (the pitch radii and centre distances then stay within hull_bridge's
//   range, so the hull's arithmetic stays finite and normal);
// - teeth, z1, z2: 3 to 1000 (the `drive` analysis's range);
// - links (a whole count): 2 to 100000 (the `drive` analysis's range; odd counts allowed);
// - center_distance: finite, at most 1e100 m, and more than r1 + r2 (the pitch circles apart)
//   where the sprockets are placed (polygon_hull, span_angle, shaft_loads; links_for: any
//   1e-9 pitch ≤ a ≤ 1e100 m, its count then finite);
// - phases finite; tensions finite within ±1e307 N (their sums and differences stay finite).
// hull_bridge has its own ranges (below).
// Valid input of a design that cannot be built (too short a chain) is not an argument error:
// center_distance_formula returns NaN, polygon_wrap throws std::domain_error.
#pragma once

#include <utility>
#include <vector>

namespace catena::drive {

inline constexpr int kMinTeeth = 3, kMaxTeeth = 1000;         ///< the valid tooth counts
inline constexpr int kMinLinks = 2, kMaxLinks = 100000;       ///< the valid whole link counts
inline constexpr double kMinPitch = 1e-90, kMaxPitch = 1e90;  ///< [m] the valid pitches
inline constexpr double kMaxCenterDistance = 1e100;           ///< [m] the largest valid a
inline constexpr double kMaxTension =
    1e307;  ///< [N] the largest valid |tension| (sums stay finite)

/// Pitch radius of a sprocket, p / (2 sin(π/z)) [m].
double pitch_radius(double pitch, int teeth);

/// The link count for centre distance a (not rounded):
/// X = 2a/p + (z1 + z2)/2 + ((z2 − z1)/2π)² p/a. Any 1e-9 p ≤ a ≤ 1e100 m (touching or
/// overlapping pitch circles too: the count of the textbook formula), where X is finite (at most
/// about 2.5e13 below, 2e190 above); it is not a count the drive can use beyond kMaxLinks.
double links_for(double pitch, int z1, int z2, double center_distance);

/// `links` rounded up to the next even whole number (a count within 1e-9 above a whole one is
/// that one). Valid: 1e-9 < links ≤ 2147483646 (the even count fits an int).
int round_up_even(double links);

/// The textbook centre distance for X links:
/// a = (p/4)[X − Σ/2 + √((X − Σ/2)² − 8Δ²)], Σ = z1 + z2, Δ = (z2 − z1)/2π.
/// NaN when the root is imaginary (too few links). Valid: 0 < links ≤ 1e100 (not whole too).
double center_distance_formula(double pitch, int z1, int z2, double links);

/// One taut polygon wrap: sprocket 1 at (0, 0), sprocket 2 at (a, 0); the pins seated on
/// sprocket 1 are at angles phase1 + 2πi/z1, on sprocket 2 at phase2 + 2πj/z2 (counter-clockwise
/// index). The chain runs counter-clockwise around the hull: over sprocket 1 from pin `seat1_in`
/// to `seat1_out` (`wrap1` links), the lower span (`span_lower` links) to sprocket 2's pin
/// `seat2_in`, over sprocket 2 to `seat2_out` (`wrap2` links), the upper span (`span_upper` links)
/// back to `seat1_in`.
struct PolygonWrap {
  double center_distance = 0.0;       ///< [m]
  double phase1 = 0.0, phase2 = 0.0;  ///< [rad]
  int seat1_in = 0, seat1_out = 0, seat2_in = 0, seat2_out = 0;
  int wrap1 = 0, wrap2 = 0, span_lower = 0, span_upper = 0;
  /// [m] the upper and lower span lengths as solved (each a whole number of pitches)
  double upper_length = 0.0, lower_length = 0.0;
};

/// The hull of both pitch polygons at centre distance a and the given phases: which pins bound
/// the spans and the spans' lengths (wrap counts and span lengths, span link counts left 0).
/// Valid: center_distance more than r1 + r2, phase1 and phase2 finite.
PolygonWrap polygon_hull(double pitch, int z1, int z2, double center_distance, double phase1,
                         double phase2);

/// A pitch polygon: `teeth` vertices (the seated pins) on the circle of `radius` about (x, y), at
/// angles phase + 2πi/teeth, i = 0 … teeth − 1 (counter-clockwise) [m, rad].
struct PitchPolygon {
  double x = 0.0, y = 0.0, radius = 0.0, phase = 0.0;
  int teeth = 0;
};

/// The bridge of the convex hull of two disjoint pitch polygons from `a` to `b`, both polygons
/// on its left (polygon_hull's spans): (vertex index in a, vertex index in b). Valid input:
/// x, y finite within ±1e100 m, radius 1e-100 to 1e100 m, phase finite, 1 to 10⁶ teeth (beyond,
/// the walk's rounding tolerance hides a vertex's neighbours), and the centres apart by more than
/// a.radius + b.radius. Otherwise throws one std::invalid_argument naming every bad field
/// (`a.radius`, `b.teeth`, …) with its valid range. The vertices are computed in double: a phase
/// or centre so large that its rounding nears a pitch blurs them (the indices are the computed
/// vertices').
std::pair<int, int> hull_bridge(const PitchPolygon& a, const PitchPolygon& b);

/// The taut wrap of `links` rigid links for the driver at `phase1`: centre distance and the
/// driven sprocket's phase such that both spans are whole numbers of links. Throws
/// std::domain_error when the chain is too short to pass around both sprockets (valid input);
/// std::invalid_argument for input outside the ranges above (phase1 finite).
PolygonWrap polygon_wrap(double pitch, int z1, int z2, int links, double phase1);

/// The exact centre distance over one pitch of driver rotation (the taut chain's centre distance
/// varies with the phase when z1 ≠ z2): its least and largest value, and the wrap at the least.
struct ExactCenterDistance {
  double min = 0.0, max = 0.0;  ///< [m]
  PolygonWrap at_min;
  std::vector<double> phases, values;  ///< [rad], [m] the samples over one driver pitch
};
ExactCenterDistance exact_center_distance(double pitch, int z1, int z2, int links);

/// The forces of the chain on the two shafts [N], x along the line of centres (driver → driven),
/// y up: the tight (upper) span's tension `tight` and the slack (lower) span's `slack` along the
/// spans of the pitch circles' common tangents at centre distance a, less the centrifugal
/// tension `centrifugal` in each, which the wrapped chain's own centrifugal force balances.
/// Valid: center_distance more than r1 + r2; tight, slack, centrifugal within ±1e307 N.
struct ShaftLoads {
  double driver_x = 0.0, driver_y = 0.0, driven_x = 0.0, driven_y = 0.0;
};
ShaftLoads shaft_loads(double pitch, int z1, int z2, double center_distance, double tight,
                       double slack, double centrifugal);

/// The spans' inclination γ = asin((r2 − r1)/a) to the line of centres [rad] (r: pitch radii).
/// Valid: center_distance more than r1 + r2.
double span_angle(double pitch, int z1, int z2, double center_distance);

/// Every pin of the wrap, in chain order (links + 1 points, the last equal to the first) [m].
/// Valid: a wrap as polygon_wrap solves it for this pitch and these teeth: w.center_distance more
/// than r1 + r2, w.phase1 and w.phase2 finite, the seats 0 to z − 1, w.wrap1 0 to z1 − 1 and
/// w.wrap2 0 to z2 − 1 with w.seat1_out = (w.seat1_in + w.wrap1) mod z1 and w.seat2_out =
/// (w.seat2_in + w.wrap2) mod z2, w.span_lower and w.span_upper 1 to 100000, and the link count
/// w.wrap1 + w.wrap2 + w.span_lower + w.span_upper at most 100000 (the lengths are not used).
std::vector<std::pair<double, double>> wrap_pins(const PolygonWrap& w, double pitch, int z1,
                                                 int z2);

}  // namespace catena::drive
