// The drive layout against independent numerics: the exact polygon wrap rebuilt pin by pin, its
// centre distance against the textbook formula, shaft-load equilibrium with the wrapped chain's
// centrifugal force integrated numerically, chordal speed variation from a sampled polygon.
#include "catena/drive/layout.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace catena::drive {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kP = 0.01905;        // [m] 12B pitch
constexpr double kLinkTol = 1e-9;     // [1] |link − p| / p, the tolerance
constexpr double kHullTol = 1e-12;    // [m] a seated pin on or inside the other span lines
constexpr double kEqualTol = 1e-12;   // [1] relative, equal sprockets: exact = formula
constexpr double kForceTol = 1e-9;    // [1] relative, shaft loads vs the numerical integral
constexpr double kChordalTol = 1e-9;  // [1] sampled polygon vs 1 − cos(π/z)

struct P {
  double x, y;
};

// The pins of a wrap rebuilt here from the solver's description: the seated pins on each
// pitch polygon, the spans divided into their link counts.
std::vector<P> rebuild(const PolygonWrap& w, int z1, int z2) {
  const double r1 = kP / (2 * std::sin(kPi / z1)), r2 = kP / (2 * std::sin(kPi / z2));
  auto v1 = [&](int i) {
    const double t = w.phase1 + 2 * kPi * i / z1;
    return P{r1 * std::cos(t), r1 * std::sin(t)};
  };
  auto v2 = [&](int j) {
    const double t = w.phase2 + 2 * kPi * j / z2;
    return P{w.center_distance + r2 * std::cos(t), r2 * std::sin(t)};
  };
  std::vector<P> pins;
  for (int i = 0; i < w.wrap1; ++i) pins.push_back(v1(w.seat1_in + i));
  const P a = v1(w.seat1_in + w.wrap1), b = v2(w.seat2_in);
  for (int k = 0; k < w.span_lower; ++k)
    pins.push_back({a.x + (b.x - a.x) * k / w.span_lower, a.y + (b.y - a.y) * k / w.span_lower});
  for (int j = 0; j < w.wrap2; ++j) pins.push_back(v2(w.seat2_in + j));
  const P c = v2(w.seat2_in + w.wrap2), d = v1(w.seat1_in);
  for (int k = 0; k < w.span_upper; ++k)
    pins.push_back({c.x + (d.x - c.x) * k / w.span_upper, c.y + (d.y - c.y) * k / w.span_upper});
  return pins;
}

void expect_taut_wrap(int z1, int z2, int links, double phase1) {
  const PolygonWrap w = polygon_wrap(kP, z1, z2, links, phase1);
  const std::vector<P> pins = rebuild(w, z1, z2);
  ASSERT_EQ(static_cast<int>(pins.size()), links) << z1 << "/" << z2;
  for (std::size_t i = 0; i < pins.size(); ++i) {
    const P& a = pins[i];
    const P& b = pins[(i + 1) % pins.size()];
    EXPECT_NEAR(std::hypot(b.x - a.x, b.y - a.y) / kP, 1.0, kLinkTol)
        << "link " << i << " of " << links << ", z " << z1 << "/" << z2;
  }
  // taut: every pin of both pitch polygons lies on or inside the chain (a convex loop)
  const double r1 = kP / (2 * std::sin(kPi / z1)), r2 = kP / (2 * std::sin(kPi / z2));
  std::vector<P> vertices;
  for (int i = 0; i < z1; ++i)
    vertices.push_back(
        {r1 * std::cos(w.phase1 + 2 * kPi * i / z1), r1 * std::sin(w.phase1 + 2 * kPi * i / z1)});
  for (int j = 0; j < z2; ++j)
    vertices.push_back({w.center_distance + r2 * std::cos(w.phase2 + 2 * kPi * j / z2),
                        r2 * std::sin(w.phase2 + 2 * kPi * j / z2)});
  for (std::size_t i = 0; i < pins.size(); ++i) {
    const P& a = pins[i];
    const P& b = pins[(i + 1) % pins.size()];
    for (const P& q : vertices) {
      const double side = ((b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x)) / kP;
      EXPECT_GE(side, -kHullTol) << "a sprocket pin outside the chain at link " << i;
    }
  }
  // the library's own pin list is the same chain
  const auto listed = wrap_pins(w, kP, z1, z2);
  ASSERT_EQ(listed.size(), pins.size() + 1);
}

TEST(DriveLayout, PolygonWrapPinsAreOnePitchApartAndTaut) {
  expect_taut_wrap(17, 65, 104, 0.0);
  expect_taut_wrap(17, 65, 104, 0.1);
  expect_taut_wrap(19, 38, 120, 0.05);
  expect_taut_wrap(9, 80, 160, 0.2);
  expect_taut_wrap(25, 25, 90, 0.3);
  expect_taut_wrap(21, 57, 131, 0.0);  // odd count
}

TEST(DriveLayout, EqualSprocketsGiveTheFormulaExactly) {
  // X − z even: two parallel spans of (X − z)/2 links at every phase
  for (int z : {12, 17, 20}) {
    for (int links : {z % 2 == 0 ? 60 : 61, z % 2 == 0 ? 100 : 101}) {
      const ExactCenterDistance e = exact_center_distance(kP, z, z, links);
      const double expected = (links - z) * kP / 2;
      EXPECT_NEAR(e.min, expected, kEqualTol * expected) << z << " " << links;
      EXPECT_NEAR(e.max, expected, kEqualTol * expected) << z << " " << links;
      EXPECT_NEAR(center_distance_formula(kP, z, z, links), expected, kEqualTol * expected);
    }
  }
  // X − z odd: spans of n and n + 1 links cannot both be parallel to the line of centres, so
  // the taut centre distance varies with the phase, round the formula's value
  const ExactCenterDistance e = exact_center_distance(kP, 17, 17, 60);
  const double formula = center_distance_formula(kP, 17, 17, 60);
  EXPECT_LT(e.min, formula);
  EXPECT_GT(e.max, formula);
}

// The textbook formula against the polygon wrap: the difference stays below the two pitch
// polygons' chordal rise (the most a seated chain can differ from the circles), and relative to
// a it shrinks as the centre distance grows.
TEST(DriveLayout, ExactCentreDistanceApproachesTheFormula) {
  const int z1 = 17, z2 = 65;
  const double r1 = pitch_radius(kP, z1), r2 = pitch_radius(kP, z2);
  const double rise = r1 * (1 - std::cos(kPi / z1)) + r2 * (1 - std::cos(kPi / z2));
  std::vector<double> relative;
  for (double ap : {20.0, 40.0, 80.0, 160.0}) {
    const int links = round_up_even(links_for(kP, z1, z2, ap * kP));
    const double formula = center_distance_formula(kP, z1, z2, links);
    const ExactCenterDistance e = exact_center_distance(kP, z1, z2, links);
    EXPECT_LE(e.min, e.max);
    EXPECT_LT(std::abs(e.min - formula), rise) << "a/p " << ap;
    EXPECT_LT(std::abs(e.max - formula), rise) << "a/p " << ap;
    relative.push_back(std::abs(e.min - formula) / formula);
  }
  EXPECT_LT(relative.back(), relative.front() / 4);
}

TEST(DriveLayout, LinksRoundUpToEven) {
  EXPECT_EQ(round_up_even(102.95), 104);
  EXPECT_EQ(round_up_even(103.2), 104);
  EXPECT_EQ(round_up_even(104.0), 104);
  EXPECT_EQ(round_up_even(104.0000001), 106);
  // X from a and a from X invert each other (before rounding)
  const double x = links_for(kP, 17, 51, 0.6);
  EXPECT_NEAR(center_distance_formula(kP, 17, 51, x), 0.6, 1e-12);
}

// Shaft loads: the span tensions' vector sum less the wrapped chain's centrifugal force,
// integrated here over the wrap; the two shafts carry equal and opposite loads.
TEST(DriveLayout, ShaftLoadsBalanceAndCancelTheCentrifugalTension) {
  const int z1 = 17, z2 = 51;
  const double a = 0.6, tight = 5000, centrifugal = 300, slack = centrifugal + 120;
  const ShaftLoads l = shaft_loads(kP, z1, z2, a, tight, slack, centrifugal);
  EXPECT_NEAR(l.driver_x + l.driven_x, 0.0, 1e-9);
  EXPECT_NEAR(l.driver_y + l.driven_y, 0.0, 1e-9);
  // independent: the pitch-circle tangents and a midpoint sum over the driver's wrap
  const double r1 = kP / (2 * std::sin(kPi / z1)), r2 = kP / (2 * std::sin(kPi / z2));
  const double g = std::asin((r2 - r1) / a);
  double fx = tight * std::cos(g) + slack * std::cos(g);
  double fy = tight * std::sin(g) - slack * std::sin(g);
  // chain on the driver from the upper tangent point (angle π/2 + g) round the far side to the
  // lower (3π/2 − g): its centrifugal force q v²/r per unit length, outward, pulls the sprocket
  // outward-from-the-chain's-view, i.e. it is taken off the spans' pull
  const int n = 200000;
  const double from = kPi / 2 + g, to = 3 * kPi / 2 - g;
  for (int k = 0; k < n; ++k) {
    const double t = from + (to - from) * (k + 0.5) / n;
    const double ds = (to - from) / n;  // q v² / r · r dθ = q v² dθ
    fx += centrifugal * std::cos(t) * ds;
    fy += centrifugal * std::sin(t) * ds;
  }
  EXPECT_NEAR(l.driver_x, fx, kForceTol * tight);
  EXPECT_NEAR(l.driver_y, fy, kForceTol * tight);
}

// Chordal action: the span leaves the polygon at the height of its highest pin, so the chain
// speed is ω times that height; sampled over one pitch of rotation.
TEST(DriveLayout, ChordalVariationFromASampledPolygon) {
  for (int z : {9, 12, 17, 25, 40}) {
    const double r = pitch_radius(kP, z);
    double vmax = 0, vmin = 1e9;
    const int samples = 20001;
    for (int s = 0; s < samples; ++s) {
      const double phase = 2 * kPi / z * s / (samples - 1);
      double top = -1e9;
      for (int i = 0; i < z; ++i) top = std::max(top, r * std::sin(phase + 2 * kPi * i / z));
      vmax = std::max(vmax, top);
      vmin = std::min(vmin, top);
    }
    EXPECT_NEAR((vmax - vmin) / vmax, 1 - std::cos(kPi / z), kChordalTol) << z;
  }
}

}  // namespace
}  // namespace catena::drive
