// Test helper: the slack start's checks shared by tests/dynamics/slack_start_test.cpp and the slow
// tier's tests/validation/dynamics_multispan_slow_test.cpp — every link one pitch, the laid path's
// joints' turns, a span's tangency to its wheels by plain geometry — and the two lower runs that
// sag with `slack_spans = "all"`, laid tangent with their shares. Header-only.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "catena/dynamics/chain.hpp"
#include "catena/dynamics/integrator.hpp"
#include "catena/dynamics/layout.hpp"
#include "catenary_closed_form.hpp"

namespace catena::dynamics::testing {

// 12B (ISO 606): pitch, roller diameter
inline constexpr double kPitch = 0.01905, kRoller = 0.01207;

// The pitch radius [m] of a 12B wheel of z teeth.
inline double pitch_radius(int z) { return 0.5 * kPitch / std::sin(std::numbers::pi / z); }

// Every link of the start `st` one pitch (1e-11; the closing link, node N - 1 to node 0, within
// `closing`, the slack solve's tolerance on the walk's end) and the chain N p long, N = `links`
// (1e-9 relative); `what` names the case in a failure. Returns the links' largest miss of the
// pitch [m].
inline double expect_every_link_one_pitch(const State& st, int links, const std::string& what,
                                          double closing = 1e-11 * kPitch) {
  double length = 0.0, worst = 0.0;
  for (std::size_t i = 0; i < st.nodes(); ++i) {
    const std::size_t j = (i + 1) % st.nodes();
    const double l = std::hypot(st.x[j] - st.x[i], st.y[j] - st.y[i]);
    EXPECT_NEAR(l, kPitch, j == 0 ? closing : 1e-11 * kPitch) << what << " link " << i;
    length += l;
    worst = std::max(worst, std::abs(l - kPitch));
  }
  EXPECT_NEAR(length, links * kPitch, 1e-9 * links * kPitch) << what;
  return worst;
}

// The turn [rad] of the laid path from the end of piece j to the start of the next (their
// tangents' angle; a straight span's its chord's direction).
inline double joint_turn(const BeltPath& laid, std::size_t j) {
  auto tangent = [](const PathPiece& q, double along) {
    if (q.arc || q.sag) return sag_point(q, along);
    PathPoint t;
    t.tx = (q.x1 - q.x0) / q.length;
    t.ty = (q.y1 - q.y0) / q.length;
    return t;
  };
  const PathPiece& a = laid.pieces[j];
  const PathPiece& b = laid.pieces[(j + 1) % laid.pieces.size()];
  const PathPoint u = tangent(a, a.length), v = tangent(b, 0.0);
  return std::atan2(u.tx * v.ty - u.ty * v.tx, u.tx * v.tx + u.ty * v.ty);
}

// The largest turn [rad] (its size) at any joint of the laid path (`joint_turn`).
inline double largest_joint_turn(const BeltPath& laid) {
  double turn = 0.0;
  for (std::size_t j = 0; j < laid.pieces.size(); ++j)
    turn = std::max(turn, std::abs(joint_turn(laid, j)));
  return turn;
}

// How far span k of `laid` is from tangent to both its wheels, by plain geometry (not the
// tangency conditions the code solves, nor its tangents cut at θ = atan sinh t): the catenary's
// ends (sag_point, from its a and u) against the wraps' ends on the circles given (`gap`), their
// distances to the centres against the radii (`radius`), and the catenary's direction there
// against the circle's counter-clockwise tangent, taken from the radius vector (`angle`).
struct TangentFit {
  double gap = 0.0, radius = 0.0;  // [m]
  double angle = 0.0;              // [rad]
};
inline TangentFit tangent_fit(const BeltPath& laid, std::size_t k,
                              const std::vector<Circle>& circles) {
  const PathPiece& q = laid.pieces[k];
  const PathPiece& w0 = laid.pieces[k - 1];
  const PathPiece& w1 = laid.pieces[(k + 1) % laid.pieces.size()];
  TangentFit fit;
  auto at_end = [&](const PathPoint& p, const Circle& c, double wrap_end) {
    fit.gap = std::max(fit.gap, std::hypot(p.x - (c.x + c.radius * std::cos(wrap_end)),
                                           p.y - (c.y + c.radius * std::sin(wrap_end))));
    const double rx = p.x - c.x, ry = p.y - c.y, d = std::hypot(rx, ry);
    fit.radius = std::max(fit.radius, std::abs(d - c.radius));
    const double tx = -ry / d, ty = rx / d;
    fit.angle =
        std::max(fit.angle, std::abs(std::atan2(tx * p.ty - ty * p.tx, tx * p.tx + ty * p.ty)));
  };
  at_end(sag_point(q, 0.0), circles[w0.wheel], w0.to);
  at_end(sag_point(q, q.length), circles[w1.wheel], w1.from);
  return fit;
}
inline void expect_tangent_fit(const BeltPath& laid, std::size_t k,
                               const std::vector<Circle>& circles, const std::string& what) {
  const TangentFit fit = tangent_fit(laid, k, circles);
  EXPECT_LT(fit.gap, 1e-12) << what;
  EXPECT_LT(fit.radius, 1e-12) << what;
  EXPECT_LT(fit.angle, 1e-9) << what;
  std::printf(
      "%s: tangent fit: ends off the wraps' %.3g m, off the circles %.3g m, off their "
      "tangents %.3g rad\n",
      what.c_str(), fit.gap, fit.radius, fit.angle);
}

// Slack in two lower runs that share no wheel (`slack_spans = "all"`): wheels at (0, `high`) and
// (1.0, `high`) m, and at (0.4, 0) and (0.6, 0) m; a back-side wheel at (0.5, `lift`) m lifts the
// chain between the two low wheels over its top, and one at (0.5, `lift` + 0.12) m presses the
// return run down, so that the two lower runs, 0 -> 1 and 3 -> 4, are the only spans that sag
// (`sagging_spans`: every other span touches a wheel on the back of the chain); `teeth` the six
// wheels' teeth in that order (z 17 each by default).
struct TwoRuns {
  std::vector<Circle> circles;
  std::vector<int> teeth;
  BeltPath path;
  std::vector<std::size_t> spans;
  double chords = 0.0;  // [m] the spans' lengths, summed
};
inline TwoRuns two_lower_runs(double high = 0.25, double lift = 0.15,
                              const std::vector<int>& teeth = {17, 17, 17, 17, 17, 17}) {
  TwoRuns t;
  t.teeth = teeth;
  const double x[] = {0.0, 0.4, 0.5, 0.6, 1.0, 0.5},
               y[] = {high, 0.0, lift, 0.0, high, lift + 0.12};
  for (std::size_t w = 0; w < 6; ++w)
    t.circles.push_back({x[w], y[w], pitch_radius(teeth[w]), w == 2 || w == 5});
  t.path = belt_path(t.circles, 0);
  t.spans = sagging_spans(t.path);
  t.chords = span_chords(t.path, t.spans);
  return t;
}

// The lowest point [m] of a laid catenary piece: the closed form through its ends (the test's own
// solve), its vertex where that lies between them, else the lower end.
inline double catenary_lowest(const PathPiece& q) {
  const ClosedForm c = closed_form(q.x0, q.y0, q.x1, q.y1, q.length);
  return c.x0 > q.x0 && c.x0 < q.x1 ? c.y(c.x0, q.x0, q.y0) : std::min(q.y0, q.y1);
}

// Each span's own extra [m] in the laid path: its length beyond its chord plus what it cut off the
// wraps either side (negative: the wraps are shorter).
inline double own_extra(const BeltPath& path, const BeltPath& laid, std::size_t k) {
  const std::size_t n = path.pieces.size(), after = (k + 1) % n;
  return laid.pieces[k].length - path.pieces[k].length +
         (laid.pieces[k - 1].length - path.pieces[k - 1].length) +
         (laid.pieces[after].length - path.pieces[after].length);
}

// Span k of a start laid as its tangent catenary with its share: its own extra e c_k / Σc (1e-9 of
// its chord), tangent to both its wheels by plain geometry (tangent_fit); `what` names the case.
inline void expect_run_tangent_with_share(const TwoRuns& t, const BeltPath& laid, std::size_t k,
                                          const std::string& what) {
  ASSERT_TRUE(laid.pieces[k].catenary) << what << " span " << k;
  const double e = laid.length - t.path.length, c = t.path.pieces[k].length;
  EXPECT_NEAR(own_extra(t.path, laid, k), e * c / t.chords, 1e-9 * c) << what << " span " << k;
  expect_tangent_fit(laid, k, t.circles, what + ", span " + std::to_string(k));
}

// Both spans of a start beyond their half circles laid as their tangent catenaries with their
// shares (`expect_run_tangent_with_share`), and each one's a and lowest point against the tangent
// catenary of its share (the test's own solve of the tangency and length conditions,
// `tangent_catenary`, for equal wheels: z 17 each) to 1e-9; `what` names the case.
inline void expect_both_runs_tangent(const TwoRuns& t, const BeltPath& laid,
                                     const std::string& what) {
  const double e = laid.length - t.path.length, r = pitch_radius(17);
  for (const std::size_t k : t.spans) {
    expect_run_tangent_with_share(t, laid, k, what);
    const PathPiece& q = laid.pieces[k];
    const double c = t.path.pieces[k].length, share = e * c / t.chords;
    const Circle &from = t.circles[q.wheel], &to = t.circles[q.next];
    const TangentCatenary own = tangent_catenary(to.x - from.x, to.y - from.y, r, c, share);
    EXPECT_NEAR(q.hang_a / own.a, 1.0, 1e-9) << what << " span " << k;
    EXPECT_NEAR(catenary_lowest(q), from.y - tangent_catenary_depth(own, r), 1e-9)
        << what << " span " << k;
    std::printf("%s, span %zu: share %.6f mm, a %.6f mm (own solve %.6f), lowest %.6f mm\n",
                what.c_str(), k, share * 1e3, q.hang_a * 1e3, own.a * 1e3,
                catenary_lowest(q) * 1e3);
  }
}

// A series' changes from one sample to the next: their mean and the largest (for the continuity
// checks: no step's change far above the mean step's).
struct StepChanges {
  double mean = 0.0, most = 0.0;
};
inline StepChanges step_changes(const std::vector<double>& v) {
  StepChanges c;
  for (std::size_t i = 1; i < v.size(); ++i) {
    c.mean += std::abs(v[i] - v[i - 1]) / static_cast<double>(v.size() - 1);
    c.most = std::max(c.most, std::abs(v[i] - v[i - 1]));
  }
  return c;
}

}  // namespace catena::dynamics::testing
