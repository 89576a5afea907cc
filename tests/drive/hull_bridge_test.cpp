// The polygon wrap's hull bridge (hull_bridge) against the algorithm it replaced, kept here as
// the reference: every vertex's dot product with the bridge's outward normal (the first largest
// wins), then the walk to the neighbours outside the line, each vertex's sine and cosine taken
// afresh. The library finds the extreme vertex from the direction's angle and takes each
// vertex's sine and cosine once; the indices must be the same for every valid input, ties
// included. Input outside the valid range is refused, every bad field named in one message.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "catena/drive/layout.hpp"

namespace catena::drive {
namespace {

constexpr double kPi = std::numbers::pi;

struct V {
  double x, y;
};

V vertex(const PitchPolygon& p, int i) {
  const int k = ((i % p.teeth) + p.teeth) % p.teeth;
  const double t = p.phase + 2 * kPi * k / p.teeth;
  return {p.x + p.radius * std::cos(t), p.y + p.radius * std::sin(t)};
}

double turn(V o, V a, V b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

int first_largest(const PitchPolygon& p, V out) {
  int best = 0;
  double best_dot = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < p.teeth; ++i) {
    const V v = vertex(p, i);
    const double dot = v.x * out.x + v.y * out.y;
    if (dot > best_dot) {
      best_dot = dot;
      best = i;
    }
  }
  return best;
}

// The reference: the bridge from a to b with both polygons on its left, as it was computed.
std::pair<int, int> reference_bridge(const PitchPolygon& a, const PitchPolygon& b) {
  const V d{b.x - a.x, b.y - a.y};
  const V out{d.y, -d.x};
  int ia = first_largest(a, out), ib = first_largest(b, out);
  const double tol = 1e-14 * std::pow(std::hypot(d.x, d.y) + a.radius + b.radius, 2);
  auto wrap = [](int i, int n) { return ((i % n) + n) % n; };
  for (int guard = 0; guard < 4 * (a.teeth + b.teeth); ++guard) {
    bool changed = false;
    for (int step : {1, -1}) {
      if (turn(vertex(a, ia), vertex(b, ib), vertex(a, ia + step)) < -tol) {
        ia = wrap(ia + step, a.teeth);
        changed = true;
      }
      if (turn(vertex(a, ia), vertex(b, ib), vertex(b, ib + step)) < -tol) {
        ib = wrap(ib + step, b.teeth);
        changed = true;
      }
    }
    if (!changed) break;
  }
  return {ia, ib};
}

std::string describe(const PitchPolygon& p) {
  char s[200];
  std::snprintf(s, sizeof s, "{%.17g, %.17g, r %.17g, phase %.17g, z %d}", p.x, p.y, p.radius,
                p.phase, p.teeth);
  return s;
}

// Both directions (the lower and the upper span) against the reference; the count of mismatches.
int mismatches(const PitchPolygon& a, const PitchPolygon& b) {
  int bad = 0;
  for (const auto& [from, to] : {std::pair{a, b}, std::pair{b, a}}) {
    const auto got = hull_bridge(from, to), want = reference_bridge(from, to);
    if (got != want) {
      ++bad;
      ADD_FAILURE() << describe(from) << " -> " << describe(to) << ": (" << got.first << ", "
                    << got.second << ") against the reference's (" << want.first << ", "
                    << want.second << ")";
    }
  }
  return bad;
}

// Random drives as polygon_hull lays them (sprocket 1 at the origin, sprocket 2 on the x axis),
// and turned about a centre anywhere: z 6–150, any phase, centre distances from the pitch
// circles touching to a thousand pitches.
TEST(HullBridge, SameIndicesAsTheScanOnRandomDrives) {
  std::mt19937 rng(21);
  std::uniform_int_distribution<int> teeth(6, 150), way(0, 3);
  std::uniform_real_distribution<double> unit(0, 1), phase(-20, 20);
  int bad = 0;
  for (int trial = 0; trial < 6000 && bad < 10; ++trial) {
    const double pitch = 0.00635 * (1 + 7 * unit(rng));
    const int z1 = teeth(rng), z2 = teeth(rng);
    const double r1 = pitch_radius(pitch, z1), r2 = pitch_radius(pitch, z2);
    const double touch = r1 + r2;
    double a = 0;
    switch (way(rng)) {
      case 0:
        a = touch * (1 + 1e-9 * unit(rng));
        break;  // the solver's lower bracket
      case 1:
        a = touch * (1 + 0.1 * unit(rng));
        break;  // close
      case 2:
        a = touch + 1000 * pitch * unit(rng);
        break;
      default:
        a = touch * (1 + 1e3 * unit(rng));
        break;
    }
    PitchPolygon p1{0, 0, r1, phase(rng), z1}, p2{a, 0, r2, phase(rng), z2};
    if (trial % 2) {  // turned and moved off the origin
      const double angle = 2 * kPi * unit(rng), cx = 10 * unit(rng) - 5, cy = 10 * unit(rng) - 5;
      p1.x = cx;
      p1.y = cy;
      p2.x = cx + a * std::cos(angle);
      p2.y = cy + a * std::sin(angle);
    }
    bad += mismatches(p1, p2);
  }
  EXPECT_EQ(bad, 0);
}

// Two sprockets of 6–150 teeth on a 12.7 mm pitch drawn from rng: their teeth and pitch radii.
struct ToothPair {
  int z1, z2;
  double r1, r2;
};
ToothPair random_teeth(std::mt19937& rng) {
  std::uniform_int_distribution<int> teeth(6, 150);
  const int z1 = teeth(rng), z2 = teeth(rng);
  constexpr double pitch = 0.0127;
  return {z1, z2, pitch_radius(pitch, z1), pitch_radius(pitch, z2)};
}

// Two vertices equally far from the bridge's normal: the first (lower index) of equal dot
// products wins, then the walk's tolerance decides. The phase −π/z puts vertices 0 and 1 at
// exactly ∓π/z (2π/z is computed as twice π/z), equal in x to the last bit: a tie of both
// polygons for the normal +x (sprocket 2 straight above sprocket 1). Near ties: a few ulps to
// 1e-9 rad off.
TEST(HullBridge, SameIndicesAsTheScanAtTies) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0, 1);
  int bad = 0, exact_ties = 0;
  for (int trial = 0; trial < 3000 && bad < 10; ++trial) {
    const auto [z1, z2, r1, r2] = random_teeth(rng);
    const double a = (r1 + r2) * (trial % 3 == 0 ? 1 + 1e-9 : 1 + 20 * unit(rng));
    PitchPolygon p1{0, 0, r1, -(kPi / z1), z1}, p2{0, a, r2, -(kPi / z2), z2};
    if (trial % 2 == 0) {
      if (vertex(p1, 0).x == vertex(p1, 1).x && vertex(p2, 0).x == vertex(p2, 1).x) ++exact_ties;
      bad += mismatches(p1, p2);
    } else {
      // near ties in polygon_hull's own layout: a vertex pair straddling the normal −y, rotated
      // by a whole number of teeth and nudged
      const double nudge[] = {0, 1e-16, -1e-16, 4e-16, -4e-16, 1e-13, -1e-13, 1e-9, -1e-9};
      const double e = nudge[trial / 2 % 9];
      const int j1 = static_cast<int>(unit(rng) * z1), j2 = static_cast<int>(unit(rng) * z2);
      PitchPolygon q1{0, 0, r1, -kPi / 2 - kPi / z1 + 2 * kPi * j1 / z1 + e, z1};
      PitchPolygon q2{a, 0, r2, kPi / 2 - kPi / z2 + 2 * kPi * j2 / z2 - e, z2};
      bad += mismatches(q1, q2);
    }
  }
  EXPECT_EQ(bad, 0);
  std::printf("exact ties (both polygons): %d of the 1500 constructed\n", exact_ties);
  EXPECT_GT(exact_ties, 1000) << "the constructed ties must be exact";
}

// Ties across the index's wrap: the last vertex and vertex 0 straddle the normal (the scan takes
// vertex 0, the lower index, although the last comes first going round). Off the origin the
// centre's term rounds the dot products, and pairs within a few ulps of symmetric tie exactly.
TEST(HullBridge, SameIndicesAsTheScanAtTiesAcrossVertexZero) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0, 1);
  int bad = 0, exact_ties = 0;
  for (int trial = 0; trial < 3000 && bad < 10; ++trial) {
    const auto [z1, z2, r1, r2] = random_teeth(rng);
    const double a = (r1 + r2) * (1 + 20 * unit(rng)), angle = 2 * kPi * unit(rng);
    const double nudge[] = {0, 1e-16, -1e-16, 1e-15, -1e-15};
    const double e = nudge[trial % 5];
    const double theta = angle - kPi / 2;  // the direction of the bridge's normal
    PitchPolygon p1{1 + 4 * unit(rng), 1 + 4 * unit(rng), r1, theta + kPi / z1 + e, z1};
    PitchPolygon p2{p1.x + a * std::cos(angle), p1.y + a * std::sin(angle), r2,
                    theta + kPi / z2 - e, z2};
    const V out{p2.y - p1.y, p1.x - p2.x};
    auto dot = [&](V v) { return v.x * out.x + v.y * out.y; };
    if (dot(vertex(p1, 0)) == dot(vertex(p1, z1 - 1)) ||
        dot(vertex(p2, 0)) == dot(vertex(p2, z2 - 1)))
      ++exact_ties;
    bad += mismatches(p1, p2);
  }
  EXPECT_EQ(bad, 0);
  std::printf("ties across vertex 0: %d of the 3000 exact\n", exact_ties);
  EXPECT_GT(exact_ties, 300) << "the constructed ties must be exact";
}

// Where the angle cannot locate the vertex (a huge phase or centre, extreme scales, one vertex:
// at z = 1 the gap 2 sin²(π/z) is rounding), within the valid input, the same indices still; so
// too for 2–6 teeth and 10⁵ teeth, which the angle locates.
TEST(HullBridge, SameIndicesAsTheScanOnDegenerateInput) {
  const PitchPolygon base1{0, 0, 0.05, 0.3, 17}, base2{0.4, 0, 0.1, 1.1, 34};
  int bad = 0;
  for (double phase : {1e6, 1e10, 1e13, 1e15, 1e17, 1e300, -1e17}) {
    PitchPolygon p1 = base1;
    p1.phase = phase;
    bad += mismatches(p1, base2);
  }
  for (double shift : {1e8, 1e12, 1e14, 1e15}) {
    PitchPolygon p1 = base1, p2 = base2;
    p1.x += shift;
    p2.x += shift;
    p1.y -= shift;
    p2.y -= shift;
    bad += mismatches(p1, p2);
  }
  // scaled within the valid range: the scan's bridge, and the unscaled drive's
  for (double scale : {1e-90, 1e-50, 1e50, 1e90}) {
    const PitchPolygon p1{0, 0, 0.05 * scale, 0.3, 17}, p2{0.4 * scale, 0, 0.1 * scale, 1.1, 34};
    bad += mismatches(p1, p2);
    EXPECT_EQ(hull_bridge(p1, p2), hull_bridge(base1, base2)) << scale;
    EXPECT_EQ(hull_bridge(p2, p1), hull_bridge(base2, base1)) << scale;
  }
  for (int z = 1; z <= 6; ++z) {
    for (double phase = -3; phase < 3; phase += 0.37) {
      const PitchPolygon p1{0, 0, 0.05, phase, z}, p2{0.3, 0.01, 0.07, -phase, z + 1};
      bad += mismatches(p1, p2);
    }
  }
  // equal sprockets in line, their near and far edges parallel to the line of centres within
  // rounding: where the walk starts decides which end of the edge it keeps
  for (int z = 6; z <= 30; ++z) {
    for (double phase : {kPi / 2 - kPi / z, -kPi / 2 - kPi / z, kPi / 2, -kPi / 2 + 1e-15}) {
      const PitchPolygon p1{0, 0, 0.05, phase, z}, p2{0.3, 0, 0.05, phase, z};
      bad += mismatches(p1, p2);
    }
  }
  const PitchPolygon many1{0, 0, 30.0, 0.7, 100000}, many2{70.0, 1.0, 20.0, -0.2, 65000};
  bad += mismatches(many1, many2);
  EXPECT_EQ(bad, 0);
}

// The valid range's ends are accepted and bridged as the scan bridges them.
TEST(HullBridge, SameIndicesAsTheScanAtTheValidRangesEnds) {
  int bad = 0;
  bad += mismatches({0, 0, 30.0, 0.7, 1000000}, {70.0, 1.0, 20.0, -0.2, 1});
  bad += mismatches({-1e100, 1e100, 4e99, 0.3, 17}, {1e100, -1e100, 1e100, 1.1, 34});
  bad += mismatches({0, 0, 1e-100, 0.3, 17}, {3e-100, 1e-100, 1e-100, 1.1, 34});
  // the centres apart by the least double more than the radii
  bad += mismatches({0, 0, 0.25, 0.3, 17}, {std::nextafter(0.5, 1.0), 0, 0.25, 1.1, 34});
  EXPECT_EQ(bad, 0);
}

// hull_bridge's message for input it must refuse; empty if it returned.
std::string refusal(const PitchPolygon& a, const PitchPolygon& b) {
  try {
    (void)hull_bridge(a, b);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// Each bad field alone, in either polygon: refused, the one problem named with its valid range.
TEST(HullBridge, RefusesEachBadField) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const PitchPolygon ok1{0, 0, 0.05, 0.3, 17}, ok2{0.4, 0, 0.1, 1.1, 34};
  struct Case {
    const char* field;
    const char* range;
    void (*set)(PitchPolygon&, double);
    std::vector<double> values;
  };
  const Case cases[] = {
      {"x",
       "a finite value within ±1e+100 m",
       [](PitchPolygon& p, double v) { p.x = v; },
       {nan, inf, -inf, 2e100, -2e100}},
      {"y",
       "a finite value within ±1e+100 m",
       [](PitchPolygon& p, double v) { p.y = v; },
       {nan, inf, -inf, 2e100}},
      {"radius",
       "1e-100 m to 1e+100 m",
       [](PitchPolygon& p, double v) { p.radius = v; },
       {nan, inf, -inf, 0.0, -0.05, 1e-101, 2e100}},
      {"phase", "a finite value", [](PitchPolygon& p, double v) { p.phase = v; }, {nan, inf, -inf}},
      {"teeth",
       "1 to 1000000",
       [](PitchPolygon& p, double v) { p.teeth = static_cast<int>(v); },
       {0, -3, 1000001, -2147483648.0}},
  };
  int refused = 0;
  for (const Case& c : cases) {
    for (double value : c.values) {
      for (int which = 0; which < 2; ++which) {
        PitchPolygon a = ok1, b = ok2;
        c.set(which == 0 ? a : b, value);
        const std::string name = std::string(which == 0 ? "a." : "b.") + c.field;
        const std::string text = refusal(a, b);
        EXPECT_TRUE(contains(text, "1 invalid argument(s)"))
            << name << " " << value << ": " << text;
        EXPECT_TRUE(contains(text, "\n  " + name + " = ")) << name << " " << value << ": " << text;
        EXPECT_TRUE(contains(text, ": expected " + std::string(c.range)))
            << name << " " << value << ": " << text;
        refused += !text.empty();
      }
    }
  }
  EXPECT_EQ(refused, 46);
}

// Coincident, overlapping and touching circles: no bridge of disjoint polygons exists.
TEST(HullBridge, RefusesPolygonsNotApart) {
  const PitchPolygon a{0, 0, 0.25, 0.3, 17};
  for (const auto& [x, y] : {std::pair{0.0, 0.0}, std::pair{0.1, 0.2}, std::pair{-0.3, 0.0},
                             std::pair{0.5, 0.0}, std::pair{0.3, -0.4}}) {
    const PitchPolygon b{x, y, 0.25, 1.1, 34};
    for (const std::string& text : {refusal(a, b), refusal(b, a)}) {
      EXPECT_TRUE(contains(text, "1 invalid argument(s)")) << x << ", " << y << ": " << text;
      EXPECT_TRUE(contains(text, "|(b.x, b.y) - (a.x, a.y)| = ")) << x << ", " << y << ": " << text;
      EXPECT_TRUE(contains(text, "expected more than a.radius + b.radius = 0.5 m"))
          << x << ", " << y << ": " << text;
    }
  }
  // 0.4 m apart, moved 1e16 m or more off: the centres coincide as rounded
  for (double shift : {1e16, 1e20}) {
    const PitchPolygon p1{shift, -shift, 0.05, 0.3, 17}, p2{shift + 0.4, -shift, 0.1, 1.1, 34};
    EXPECT_TRUE(contains(refusal(p1, p2), "|(b.x, b.y) - (a.x, a.y)| = 0 m")) << shift;
  }
}

// Every problem at once, one message: bad fields of both polygons, in the polygons' order.
TEST(HullBridge, RefusesEveryBadFieldAtOnce) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const PitchPolygon a{nan, 0, -1.0, inf, 0}, b{0.4, inf, 0.1, 1.1, 2000000};
  const std::string text = refusal(a, b);
  EXPECT_TRUE(contains(text, "hull_bridge: 6 invalid argument(s):")) << text;
  std::size_t at = 0;
  for (const char* field : {"a.x", "a.radius", "a.phase", "a.teeth", "b.y", "b.teeth"}) {
    const std::size_t next = text.find(std::string("\n  ") + field + " = ", at);
    EXPECT_NE(next, std::string::npos) << field << ": " << text;
    if (next != std::string::npos) at = next;
  }
  EXPECT_FALSE(contains(text, "a.y")) << text;
  EXPECT_FALSE(contains(text, "b.radius")) << text;
  // polygons not apart, with a bad phase and tooth count: all three
  const std::string three = refusal({0, 0, 0.25, nan, 17}, {0.3, 0, 0.25, 1.1, 0});
  EXPECT_TRUE(contains(three, "hull_bridge: 3 invalid argument(s):")) << three;
  for (const char* field : {"a.phase = ", "b.teeth = ", "|(b.x, b.y) - (a.x, a.y)| = 0.3 m"})
    EXPECT_TRUE(contains(three, field)) << field << ": " << three;
}

}  // namespace
}  // namespace catena::drive
