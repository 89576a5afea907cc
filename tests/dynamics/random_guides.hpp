// Test helper: random guides (straight rails and circular arcs of any orientation and span) and
// points on or near a guide's surface, for the property tests of the guides' contact, bounds and
// node hint (guide_test.cpp, guide_hint_test.cpp). Each caller gives its own ranges; the draws
// are made in a fixed order, so that a seed gives the same guides and points every time.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "catena/dynamics/chain.hpp"

namespace catena::dynamics::testing {

// The fixed rail of the guides' and lead-ins' contact tests: straight from (−0.2, 0.1) to
// (0.5, 0.3) m, inclined, its free side up-left; a 12B roller (r = 6.035 mm), contact stiffness
// 1e7 N/m, damping 200 N·s/m, friction `mu`.
inline Guide inclined_rail(double mu) {
  Guide g;
  g.kind = Guide::Kind::kStraight;
  g.x0 = -0.2;
  g.y0 = 0.1;
  g.x1 = 0.5;
  g.y1 = 0.3;
  g.roller_radius = 0.006035;
  g.contact_stiffness = 1e7;
  g.contact_damping = 200.0;
  g.friction = mu;
  return g;
}

// `rail`'s contact (roller radius, penalty, damper, friction, stick) on an arc guide: of surface
// `radius` about (cx, cy) from `start` to `end` [rad] counter-clockwise, the rollers outside it or
// `inside`. The fixed arcs of the guides', stick and lead-in tests.
inline Guide arc_rail(const Guide& rail, double cx, double cy, double radius, double start,
                      double end, bool inside) {
  Guide g = rail;
  g.kind = Guide::Kind::kArc;
  g.x0 = g.y0 = g.x1 = g.y1 = 0.0;
  g.centre_x = cx;
  g.centre_y = cy;
  g.radius = radius;
  g.start_angle = start;
  g.end_angle = end;
  g.inside = inside;
  return g;
}

// The ranges the guides are drawn from (uniform in each).
struct GuideRanges {
  double roller_lo = 1e-3, roller_hi = 2e-2;  // [m] roller radius r
  double centre = 5.0;                       // [m] first end or arc centre in [−centre, centre]²
  double length_lo = 1e-3, length_hi = 2.0;  // [m] a straight rail's length
  // [m] an arc's radius: from max(radius_lo, radius_over_roller × r) to radius_hi
  double radius_lo = 0.0, radius_over_roller = 1.01, radius_hi = 1.0;
  double span_lo = 1e-3;  // [rad] an arc's angular span, from this to 2π
};

// A guide with contact stiffness 1e7 N/m, damping 100 N·s/m and μ = 0.3: a straight rail when
// `kind` is even, else an arc (inside when kind % 4 == 1, outside when kind % 4 == 3).
// Draws, in order: r, the centre's x and y, then the length and direction (straight) or the
// radius, start angle and span (arc).
inline Guide random_guide(std::mt19937_64& rng, int kind, const GuideRanges& g_range) {
  constexpr double kPi = std::numbers::pi;
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  auto uni = [&](double a, double b) { return a + (b - a) * u01(rng); };
  Guide g;
  g.roller_radius = uni(g_range.roller_lo, g_range.roller_hi);
  g.contact_stiffness = 1e7;
  g.contact_damping = 100.0;
  g.friction = 0.3;
  const double cx = uni(-g_range.centre, g_range.centre), cy = uni(-g_range.centre, g_range.centre);
  if (kind % 2 == 0) {
    g.kind = Guide::Kind::kStraight;
    const double len = uni(g_range.length_lo, g_range.length_hi), dir = uni(-kPi, kPi);
    g.x0 = cx;
    g.y0 = cy;
    g.x1 = cx + len * std::cos(dir);
    g.y1 = cy + len * std::sin(dir);
  } else {
    g.kind = Guide::Kind::kArc;
    g.centre_x = cx;
    g.centre_y = cy;
    const double radius_lo =
        std::max(g_range.radius_lo, g_range.radius_over_roller * g.roller_radius);
    g.radius = uni(radius_lo, g_range.radius_hi);
    g.start_angle = uni(-kPi, kPi);
    g.end_angle = g.start_angle + uni(g_range.span_lo, 2.0 * kPi);
    g.inside = kind % 4 == 1;
  }
  return g;
}

// The point at the fraction `along` of guide `g` (0 and 1 its ends; beyond them off the ends) at
// `offset` from its centre line: along the rail's left normal (its free side), or radially out
// from an arc's circle.
inline void point_near(const Guide& g, double along, double offset, double& x, double& y) {
  if (g.kind == Guide::Kind::kStraight) {
    const double ax = g.x1 - g.x0, ay = g.y1 - g.y0, len = std::hypot(ax, ay);
    const double s = along * len;
    x = g.x0 + ax / len * s - ay / len * offset;
    y = g.y0 + ay / len * s + ax / len * offset;
  } else {
    const double a = g.start_angle + along * (g.end_angle - g.start_angle);
    x = g.centre_x + (g.radius + offset) * std::cos(a);
    y = g.centre_y + (g.radius + offset) * std::sin(a);
  }
}

}  // namespace catena::dynamics::testing
