// The belt path round a set of pitch circles and the loop placed on it (dynamics/layout.hpp)
// against independent computations: the closed form of two unequal circles, the convex hull of
// densely sampled circles (Andrew's monotone chain), the two-wheel start of two_sprocket_loop, and
// the placement's chords, closure and seat offsets recomputed from the node positions.
#include "catena/dynamics/layout.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <tuple>
#include <vector>

#include "catena/dynamics/chain.hpp"

namespace catena::dynamics {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kPitch = 0.01905;  // 12B

double pitch_radius(int z) { return 0.5 * kPitch / std::sin(kPi / z); }

// L = 2C cos β + R1 (π + 2β) + R2 (π − 2β), sin β = (R1 − R2)/C: the crossed-free belt over two
// pulleys (any machine-elements text, e.g. Shigley's, "flat belts, open drive"), its tangent
// points at the normal angles ±(π/2 − β) on both circles.
TEST(DynamicsLayout, TwoUnequalCirclesGiveTheOpenBeltClosedForm) {
  for (const auto& [r1, r2, c] :
       {std::tuple{0.1, 0.03, 0.4}, std::tuple{0.05, 0.049, 0.2}, std::tuple{0.2, 0.02, 0.25}}) {
    const BeltPath path = belt_path({{0.0, 0.0, r1}, {c, 0.0, r2}}, 0);
    ASSERT_TRUE(path.unwrapped.empty());
    ASSERT_EQ(path.pieces.size(), 4u);
    const double beta = std::asin((r1 - r2) / c);
    const double closed = 2 * c * std::cos(beta) + r1 * (kPi + 2 * beta) + r2 * (kPi - 2 * beta);
    EXPECT_NEAR(path.length, closed, 1e-14 * closed);
    // the wraps: π + 2β on the larger wheel, π − 2β on the smaller
    EXPECT_NEAR(path.pieces[0].to - path.pieces[0].from, kPi + 2 * beta, 1e-13);
    EXPECT_NEAR(path.pieces[2].to - path.pieces[2].from, kPi - 2 * beta, 1e-13);
    // the lower span leaves the larger wheel at the normal −(π/2 − β) and arrives on the smaller
    // one at the same normal
    const PathPiece& lower = path.pieces[1];
    const double a = -(kPi / 2 - beta);
    EXPECT_NEAR(lower.x0, r1 * std::cos(a), 1e-15);
    EXPECT_NEAR(lower.y0, r1 * std::sin(a), 1e-15);
    EXPECT_NEAR(lower.x1, c + r2 * std::cos(a), 1e-15);
    EXPECT_NEAR(lower.y1, r2 * std::sin(a), 1e-15);
    EXPECT_NEAR(lower.length, c * std::cos(beta), 1e-15);
  }
}

// The convex hull of points, counter-clockwise (Andrew's monotone chain), as indices.
std::vector<std::size_t> hull(const std::vector<std::array<double, 2>>& p) {
  std::vector<std::size_t> idx(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) idx[i] = i;
  std::sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) { return p[a] < p[b]; });
  auto cross = [&](std::size_t o, std::size_t a, std::size_t b) {
    return (p[a][0] - p[o][0]) * (p[b][1] - p[o][1]) - (p[a][1] - p[o][1]) * (p[b][0] - p[o][0]);
  };
  std::vector<std::size_t> h(2 * idx.size());
  std::size_t k = 0;
  for (const std::size_t i : idx) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], i) <= 0) --k;
    h[k++] = i;
  }
  for (std::size_t j = idx.size() - 1, t = k + 1; j-- > 0;) {
    const std::size_t i = idx[j];
    while (k >= t && cross(h[k - 2], h[k - 1], i) <= 0) --k;
    h[k++] = i;
  }
  h.resize(k - 1);
  return h;
}

// Random sets of 2–6 circles: the path's length against the perimeter of the convex hull of
// 4000 points on each circle (which falls short of the true length by the chords' error,
// L (π/M)²/6 ≈ 1e-7 L), the wheels it wraps and their order against the owners of
// the hull's points, and every span a common tangent with every circle on its left.
TEST(DynamicsLayout, PathMatchesTheHullOfSampledCircles) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  constexpr int kSamples = 4000;
  int wrapped_sets = 0, with_inner = 0;
  for (int trial = 0; trial < 50; ++trial) {
    const int n = 2 + trial % 5;
    std::vector<Circle> c;
    while (static_cast<int>(c.size()) < n) {
      const Circle x{u(rng), u(rng), 0.02 + 0.15 * u(rng)};
      bool ok = true;
      for (const Circle& y : c)  // no circle inside another (the path is not defined then)
        if (std::hypot(x.x - y.x, x.y - y.y) <= std::abs(x.radius - y.radius) + 1e-3) ok = false;
      if (ok) c.push_back(x);
    }
    std::vector<std::array<double, 2>> pts;
    std::vector<std::size_t> owner;
    for (std::size_t i = 0; i < c.size(); ++i)
      for (int k = 0; k < kSamples; ++k) {
        const double t = 2 * kPi * k / kSamples;
        pts.push_back({c[i].x + c[i].radius * std::cos(t), c[i].y + c[i].radius * std::sin(t)});
        owner.push_back(i);
      }
    const std::vector<std::size_t> h = hull(pts);
    double perimeter = 0.0;
    std::vector<std::size_t> order;  // the owners along the hull, runs collapsed
    for (std::size_t k = 0; k < h.size(); ++k) {
      const auto& a = pts[h[k]];
      const auto& b = pts[h[(k + 1) % h.size()]];
      perimeter += std::hypot(b[0] - a[0], b[1] - a[1]);
      if (order.empty() || order.back() != owner[h[k]]) order.push_back(owner[h[k]]);
    }
    while (order.size() > 1 && order.front() == order.back()) order.pop_back();
    std::vector<std::size_t> distinct = order;
    std::sort(distinct.begin(), distinct.end());
    const bool once = std::adjacent_find(distinct.begin(), distinct.end()) == distinct.end();

    const BeltPath path = belt_path(c, order.front());
    if (!once || order.size() != c.size()) {
      // some circle is inside the hull (or met twice): reported, no path
      EXPECT_FALSE(path.unwrapped.empty()) << "trial " << trial;
      EXPECT_TRUE(path.pieces.empty());
      for (const std::size_t i : path.unwrapped) {
        if (!once) continue;
        EXPECT_EQ(std::count(order.begin(), order.end(), i), 0) << "trial " << trial;
      }
      ++with_inner;
      continue;
    }
    ++wrapped_sets;
    ASSERT_TRUE(path.unwrapped.empty()) << "trial " << trial;
    EXPECT_EQ(path.order, order) << "trial " << trial;
    EXPECT_GE(path.length, perimeter);
    EXPECT_NEAR(path.length / perimeter, 1.0, 2e-7) << "trial " << trial;
    for (const PathPiece& q : path.pieces) {
      if (q.arc) continue;
      const Circle& a = c[q.wheel];
      const Circle& b = c[q.next];
      EXPECT_NEAR(std::hypot(q.x0 - a.x, q.y0 - a.y), a.radius, 1e-14);
      EXPECT_NEAR(std::hypot(q.x1 - b.x, q.y1 - b.y), b.radius, 1e-14);
      const double tx = (q.x1 - q.x0) / q.length, ty = (q.y1 - q.y0) / q.length;
      for (const Circle& k : c) {  // left of the travel by at least the radius (tangent: equal)
        const double left = tx * (k.y - q.y0) - ty * (k.x - q.x0);
        EXPECT_GE(left, k.radius - 1e-14);
      }
      EXPECT_NEAR(tx * (a.y - q.y0) - ty * (a.x - q.x0), a.radius, 1e-14);
      EXPECT_NEAR(tx * (b.y - q.y0) - ty * (b.x - q.x0), b.radius, 1e-14);
    }
  }
  EXPECT_GT(wrapped_sets, 20);
  EXPECT_GT(with_inner, 3);
}

// Two equal wheels a whole number of pitches apart: the placement is two_sprocket_loop's start
// (the loop the command has always built), with the chord the pitch and every roller on a seat.
TEST(DynamicsLayout, EqualWheelsOnALineGiveTheTwoSprocketStart) {
  for (const auto& [z, m] : {std::pair{12, 10}, std::pair{20, 90}, std::pair{9, 3}}) {
    const double r = pitch_radius(z);
    const std::vector<Circle> c{{0.0, 0.0, r}, {m * kPitch, 0.0, r}};
    const BeltPath path = belt_path(c, 0);
    ASSERT_TRUE(path.unwrapped.empty());
    const int n = z + 2 * m;
    if (z % 2 == 0) {
      EXPECT_NEAR(path_links(path, kPitch), n, 1e-9);
    }
    const LoopPlacement place = place_loop(path, c, {z, z}, n, kPitch);
    ASSERT_EQ(place.s.size(), static_cast<std::size_t>(n));
    if (z % 2 != 0) continue;  // odd z: half a seat over, still closed (checked below)
    EXPECT_NEAR(place.spacing, kPitch, 1e-14);
    const State ref = two_sprocket_loop(z, m, kPitch, r, 13.0);
    const State got = loop_state(path, c, place, 13.0 * r);
    for (std::size_t i = 0; i < got.nodes(); ++i) {
      EXPECT_NEAR(got.x[i], ref.x[i], 1e-13) << i;
      EXPECT_NEAR(got.y[i], ref.y[i], 1e-13) << i;
      EXPECT_NEAR(got.vx[i], ref.vx[i], 1e-12) << i;
      EXPECT_NEAR(got.vy[i], ref.vy[i], 1e-12) << i;
    }
    const double tau = 2 * kPi / z;
    for (std::size_t w = 0; w < 2; ++w) {
      EXPECT_NEAR(std::remainder(got.angle[w] - ref.angle[w], tau), 0.0, 1e-12);
      EXPECT_NEAR(got.speed[w], 13.0, 1e-12);
      EXPECT_LT(place.seat_offset[w], 1e-12);
      EXPECT_GE(place.wrapped[w], z / 2);  // the roller at the departure point: either side
    }
  }
}

// Random three- and four-wheel layouts of unequal wheels: the nodes close the loop with one chord
// (the closing link included), run forward along the path, and each wheel's seat offset is the
// largest distance of a roller on its pitch circle from the nearest seat of the wheel as turned,
// recomputed here from the positions.
TEST(DynamicsLayout, PlacementClosesTheLoopAndSeatsTheWrappedRollers) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int placed = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const std::size_t n = 3 + trial % 2;
    std::vector<int> teeth;
    std::vector<Circle> c;
    for (std::size_t i = 0; i < n; ++i) {
      const int z = 9 + static_cast<int>(u(rng) * 30);
      const double a = 2 * kPi * (static_cast<double>(i) + 0.3 * u(rng)) / static_cast<double>(n);
      const double d = 0.25 + 0.2 * u(rng);
      teeth.push_back(z);
      c.push_back({d * std::cos(a), d * std::sin(a), pitch_radius(z)});
    }
    const BeltPath path = belt_path(c, 0);
    if (!path.unwrapped.empty()) continue;
    const double f = path_links(path, kPitch);
    const int count = static_cast<int>(std::lround(f));
    const LoopPlacement place = place_loop(path, c, teeth, count, kPitch);
    ASSERT_EQ(place.s.size(), static_cast<std::size_t>(count)) << "trial " << trial;
    ++placed;
    // the chord is longer than the pitch when the path takes more than `count` pitches
    EXPECT_EQ(place.spacing > kPitch, f > count) << f;
    EXPECT_LT(std::abs(place.spacing - kPitch), kPitch * std::abs(f - count) / count * 1.5 + 1e-15);
    const State st = loop_state(path, c, place, 1.0);
    for (std::size_t i = 0; i < st.nodes(); ++i) {
      const std::size_t j = (i + 1) % st.nodes();
      EXPECT_NEAR(std::hypot(st.x[j] - st.x[i], st.y[j] - st.y[i]), place.spacing, 1e-12)
          << "trial " << trial << " link " << i;
      if (j != 0) {
        EXPECT_GT(place.s[j], place.s[i]);
      }
      EXPECT_NEAR(std::hypot(st.vx[i], st.vy[i]), 1.0, 1e-12);
    }
    for (std::size_t w = 0; w < n; ++w) {
      const double tau = 2 * kPi / teeth[w];
      double worst = 0.0;
      int on = 0;
      for (std::size_t i = 0; i < st.nodes(); ++i) {
        const double dx = st.x[i] - c[w].x, dy = st.y[i] - c[w].y;
        if (std::abs(std::hypot(dx, dy) - c[w].radius) > 1e-12) continue;
        ++on;
        const double off = std::remainder(std::atan2(dy, dx) - st.angle[w], tau);
        worst = std::max(worst, 2 * c[w].radius * std::sin(0.5 * std::abs(off)));
      }
      EXPECT_EQ(on, place.wrapped[w]) << "trial " << trial << " wheel " << w;
      EXPECT_NEAR(worst, place.seat_offset[w], 1e-12) << "trial " << trial << " wheel " << w;
    }
  }
  EXPECT_GT(placed, 20);
}

// The spans' sampled links on two_sprocket_loop's start: with an odd number of pitches between
// the centres, exactly one link of each span has its middle at the spans' middle x = C/2 (the
// span's nodes sit at whole pitches from a wheel's centre), at the pitch radius above and below.
TEST(DynamicsLayout, SpanMiddleLinksOfTheTwoSprocketStart) {
  for (const auto& [z, m] : {std::pair{12, 11}, std::pair{17, 31}, std::pair{9, 3}}) {
    const double r = pitch_radius(z);
    const State s = two_sprocket_loop(z, m, kPitch, r, 5.0);
    const std::size_t n = s.nodes();
    const auto [upper, lower] = span_middle_links(s, m * kPitch);
    for (const auto& [j, side] : {std::pair{upper, 1.0}, std::pair{lower, -1.0}}) {
      const std::size_t e = (j + 1) % n;
      EXPECT_NEAR(0.5 * (s.x[j] + s.x[e]), 0.5 * m * kPitch, 1e-12) << z << " " << m;
      EXPECT_NEAR(s.y[j], side * r, 1e-12) << z << " " << m;
      EXPECT_NEAR(s.y[e], side * r, 1e-12) << z << " " << m;
    }
  }
}

}  // namespace
}  // namespace catena::dynamics
