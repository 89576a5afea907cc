// The belt path round a set of pitch circles and a closed loop of nodes placed on it
// (include/catena/dynamics/layout.hpp; docs/models/dynamics.md, "Command").
#include "catena/dynamics/layout.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>
#include <utility>

namespace catena::dynamics {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTwoPi = 2.0 * std::numbers::pi;

// The path with each piece's start at the sum of the lengths before it, and its length the sum.
BeltPath with_starts(BeltPath out) {
  double along = 0.0;
  for (PathPiece& r : out.pieces) {
    r.start = along;
    along += r.length;
  }
  out.length = along;
  return out;
}

// x reduced to [0, 2π), with values within `eps` below 2π taken as 0 (a tangent that coincides
// with the current one up to rounding).
double turn(double x, double eps = 1e-12) {
  double r = std::fmod(x, kTwoPi);
  if (r < 0.0) r += kTwoPi;
  if (r > kTwoPi - eps) r -= kTwoPi;
  return std::max(r, 0.0);
}

// The outward normal angle of the outer common tangent that leaves circle a and arrives on circle
// b with the loop running counter-clockwise (the hull on the left of the travel): the normal n
// with a·n + Ra = b·n + Rb, on the right of the direction from a to b.
double tangent_normal(const Circle& a, const Circle& b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double d = std::hypot(dx, dy);
  const double c = std::clamp((a.radius - b.radius) / d, -1.0, 1.0);
  return std::atan2(dy, dx) - std::acos(c);
}

struct Edge {
  std::size_t from = 0, to = 0;
  double normal = 0.0;
};

// The signed radius: the chain's point on a wheel is c + ρ n, n the right-hand normal of the
// travel; ρ = R inside the loop (the wheel on the travel's left), −R on its back (on its right).
double signed_radius(const Circle& c) { return c.back ? -c.radius : c.radius; }

// The right-hand normal's angle of the common tangent that leaves circle a and arrives on circle b
// with each on its own side: a·n + ρa = b·n + ρb (an outer tangent between two wheels on one side,
// a crossed one between wheels on opposite sides).
double signed_tangent_normal(const Circle& a, const Circle& b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double d = std::hypot(dx, dy);
  const double c = std::clamp((signed_radius(a) - signed_radius(b)) / d, -1.0, 1.0);
  return std::atan2(dy, dx) - std::acos(c);
}

}  // namespace

bool segments_cross(double px0, double py0, double px1, double py1, double qx0, double qy0,
                    double qx1, double qy1) {
  auto side = [](double ax, double ay, double bx, double by, double cx, double cy) {
    return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
  };
  const double d1 = side(qx0, qy0, qx1, qy1, px0, py0), d2 = side(qx0, qy0, qx1, qy1, px1, py1);
  const double d3 = side(px0, py0, px1, py1, qx0, qy0), d4 = side(px0, py0, px1, py1, qx1, qy1);
  const double lp = std::hypot(px1 - px0, py1 - py0), lq = std::hypot(qx1 - qx0, qy1 - qy0);
  const double eps = 1e-12 * std::max(lp, lq);
  // |side| is the distance from the line times the segment's length
  if (lp > 0.0 && lq > 0.0 && std::abs(d1) <= eps * lq && std::abs(d2) <= eps * lq &&
      std::abs(d3) <= eps * lp && std::abs(d4) <= eps * lp) {
    // collinear: project q's ends on p's direction and compare the intervals
    const double ux = (px1 - px0) / lp, uy = (py1 - py0) / lp;
    const double a = (qx0 - px0) * ux + (qy0 - py0) * uy, b = (qx1 - px0) * ux + (qy1 - py0) * uy;
    return std::max(a, b) >= -eps && std::min(a, b) <= lp + eps;
  }
  return d1 * d2 <= 0.0 && d3 * d4 <= 0.0;
}

double segment_distance(double x, double y, double x0, double y0, double x1, double y1) {
  const double ux = x1 - x0, uy = y1 - y0, l2 = ux * ux + uy * uy;
  const double t = l2 > 0.0 ? std::clamp(((x - x0) * ux + (y - y0) * uy) / l2, 0.0, 1.0) : 0.0;
  return std::hypot(x - x0 - t * ux, y - y0 - t * uy);
}

namespace {

std::string wheel_name(std::size_t i) { return "sprocket[" + std::to_string(i) + "]"; }

// The distance from (x, y) to the counter-clockwise arc about (cx, cy) of `radius` from angle a0
// to a1 (a0 < a1 < a0 + 2π): to the circle where the point's angle is within the arc, else to
// the nearer end.
double arc_distance(double x, double y, double cx, double cy, double radius, double a0, double a1) {
  const double a = std::atan2(y - cy, x - cx) - a0;
  const double along = a - kTwoPi * std::floor(a / kTwoPi);
  if (along <= a1 - a0) return std::abs(std::hypot(x - cx, y - cy) - radius);
  return std::min(std::hypot(x - cx - radius * std::cos(a0), y - cy - radius * std::sin(a0)),
                  std::hypot(x - cx - radius * std::cos(a1), y - cy - radius * std::sin(a1)));
}

// The distance from (x, y) to a guide's surface: its segment, or its arc (`arc_distance`).
double guide_distance(const Guide& g, double x, double y) {
  if (g.kind == Guide::Kind::kStraight) return segment_distance(x, y, g.x0, g.y0, g.x1, g.y1);
  return arc_distance(x, y, g.centre_x, g.centre_y, g.radius, g.start_angle, g.end_angle);
}

// Appends to `path` the arc on wheel `w` from the chain's angle `from` turning by `wrap` in
// `sense` (+1 counter-clockwise, −1 on the back), then the span from its end to wheel `to` at the
// tangent's normal angle `normal` (the point at the signed radius there), each placed at `along`
// on the path, which advances past both.
void append_arc_and_span(BeltPath& path, const std::vector<Circle>& circles, std::size_t w,
                         std::size_t to, double from, double wrap, double sense, double normal,
                         double& along) {
  const Circle& c = circles[w];
  PathPiece arc;
  arc.arc = true;
  arc.wheel = w;
  arc.next = w;
  arc.sense = sense;
  arc.cx = c.x;
  arc.cy = c.y;
  arc.radius = c.radius;
  arc.from = from;
  arc.to = from + sense * wrap;
  arc.x0 = c.x + c.radius * std::cos(arc.from);
  arc.y0 = c.y + c.radius * std::sin(arc.from);
  arc.x1 = c.x + c.radius * std::cos(arc.to);
  arc.y1 = c.y + c.radius * std::sin(arc.to);
  arc.length = c.radius * wrap;
  arc.start = along;
  along += arc.length;
  path.pieces.push_back(arc);
  path.order.push_back(w);
  const Circle& d = circles[to];
  const double rd = signed_radius(d);
  PathPiece span;
  span.wheel = w;
  span.next = to;
  span.x0 = arc.x1;
  span.y0 = arc.y1;
  span.x1 = d.x + rd * std::cos(normal);
  span.y1 = d.y + rd * std::sin(normal);
  span.length = std::hypot(span.x1 - span.x0, span.y1 - span.y0);
  span.start = along;
  along += span.length;
  path.pieces.push_back(span);
}

// The serpentine path: the wheels in their given order (from `first`), tangent k leaving wheel
// order[k] for order[k + 1] on the sides the wheels are on, each wheel's arc from the tangent
// arriving to the one leaving, turned the way its side wraps it.
BeltPath serpentine_path(const std::vector<Circle>& circles, std::size_t first) {
  BeltPath path;
  const std::size_t n = circles.size();
  std::vector<Edge> edges(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t a = (first + k) % n, b = (first + k + 1) % n;
    edges[k] = {a, b, signed_tangent_normal(circles[a], circles[b])};
    // two wheels on opposite sides need a crossed tangent: their pitch circles must be apart
    const double d = std::hypot(circles[b].x - circles[a].x, circles[b].y - circles[a].y);
    if (!(std::abs(signed_radius(circles[a]) - signed_radius(circles[b])) < d))
      path.faults.push_back({b, "no tangent from " + wheel_name(a) + " to " + wheel_name(b) +
                                    ": their pitch circles overlap"});
  }
  if (!path.faults.empty()) return path;
  double along = 0.0, turning = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const Edge& in = edges[(k + n - 1) % n];
    const Edge& out = edges[k];
    const Circle& c = circles[out.from];
    const double sense = c.back ? -1.0 : 1.0;
    // the chain's point is at c + ρ n: at the normal's angle inside, opposite it on the back
    const double wrap = turn(sense * (out.normal - in.normal), 1e-9);
    if (!(wrap > 1e-9))
      path.faults.push_back({out.from, "the chain only touches " + wheel_name(out.from) +
                                           " (its wrap is 0): move it into the chain's path"});
    turning += sense * wrap;
    append_arc_and_span(path, circles, out.from, out.to,
                        std::remainder(in.normal + (c.back ? kPi : 0.0), kTwoPi), wrap, sense,
                        out.normal, along);
  }
  path.length = along;
  // a simple loop run counter-clockwise turns its tangent once round, +2π
  if (path.faults.empty() && std::abs(turning - kTwoPi) > 1e-6)
    path.faults.push_back(
        {n,
         "the wheels in the order given (a row per wheel, counter-clockwise round the loop) "
         "make a path that turns " +
             std::to_string(static_cast<long>(std::lround(turning * 180.0 / kPi))) +
             " deg, not once round counter-clockwise (360 deg): list the wheels "
             "counter-clockwise and put each on the side of the chain it runs on"});
  // spans crossing one another or running through a wheel other than their two
  std::vector<const PathPiece*> spans;
  for (const PathPiece& q : path.pieces)
    if (!q.arc) spans.push_back(&q);
  for (std::size_t i = 0; i < spans.size(); ++i) {
    const PathPiece& a = *spans[i];
    for (std::size_t j = i + 1; j < spans.size(); ++j) {
      const PathPiece& b = *spans[j];
      if (segments_cross(a.x0, a.y0, a.x1, a.y1, b.x0, b.y0, b.x1, b.y1))
        path.faults.push_back({a.wheel, "the span " + wheel_name(a.wheel) + " -> " +
                                            wheel_name(a.next) + " crosses the span " +
                                            wheel_name(b.wheel) + " -> " + wheel_name(b.next) +
                                            ": the path must not cross itself"});
    }
    for (std::size_t w = 0; w < n; ++w) {
      if (w == a.wheel || w == a.next) continue;
      const Circle& c = circles[w];
      if (segment_distance(c.x, c.y, a.x0, a.y0, a.x1, a.y1) < c.radius)
        path.faults.push_back({w, "the span " + wheel_name(a.wheel) + " -> " + wheel_name(a.next) +
                                      " runs through " + wheel_name(w) +
                                      "'s pitch circle: the path must not cross a wheel"});
    }
  }
  if (!path.faults.empty()) path.pieces.clear();
  return path;
}

}  // namespace

BeltPath belt_path(const std::vector<Circle>& circles, std::size_t first) {
  BeltPath path;
  const std::size_t n = circles.size();
  if (n < 2 || first >= n) return path;
  if (std::any_of(circles.begin(), circles.end(), [](const Circle& c) { return c.back; }))
    return serpentine_path(circles, first);
  // Gift wrapping on circles: start at the circle whose pitch circle reaches lowest (the support
  // in the direction −y), then repeatedly take the outer tangent that turns the normal least
  // counter-clockwise, until the first tangent comes round again.
  std::size_t cur = 0;
  for (std::size_t i = 1; i < n; ++i) {
    if (circles[i].radius - circles[i].y > circles[cur].radius - circles[cur].y + 1e-12) cur = i;
  }
  double normal = -kPi / 2;
  std::vector<Edge> edges;
  bool closed = false;
  for (std::size_t iter = 0; iter < 2 * n + 2; ++iter) {
    std::size_t best = n;
    double best_turn = INFINITY, best_reach = -1.0;
    for (std::size_t j = 0; j < n; ++j) {
      if (j == cur) continue;
      const double t = turn(tangent_normal(circles[cur], circles[j]) - normal);
      const double reach = std::hypot(circles[j].x - circles[cur].x, circles[j].y - circles[cur].y);
      // on a common tangent of three circles, the far one: the middle one only touches it
      if (t < best_turn - 1e-12 || (std::abs(t - best_turn) <= 1e-12 && reach > best_reach)) {
        best = j;
        best_turn = t;
        best_reach = reach;
      }
    }
    const Edge e{cur, best, normal + best_turn};
    if (!edges.empty() && e.from == edges[0].from && e.to == edges[0].to) {
      closed = true;
      break;
    }
    edges.push_back(e);
    cur = best;
    normal = e.normal;
  }
  std::vector<int> visits(n, 0);
  for (const Edge& e : edges) ++visits[e.from];
  for (std::size_t i = 0; i < n; ++i)
    if (!closed || visits[i] != 1) path.unwrapped.push_back(i);
  if (!path.unwrapped.empty()) return path;
  // every wheel once: put the edge that arrives on `first` last
  const auto arrives =
      std::find_if(edges.begin(), edges.end(), [&](const Edge& e) { return e.to == first; });
  std::rotate(edges.begin(), arrives + 1, edges.end());
  double along = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const Edge& in = edges[(k + n - 1) % n];
    const Edge& out = edges[k];
    const double wrap = turn(out.normal - in.normal, 1e-9);
    if (!(wrap > 1e-9)) path.unwrapped.push_back(out.from);  // touches the path at a point
    append_arc_and_span(path, circles, out.from, out.to, std::remainder(in.normal, kTwoPi), wrap,
                        1.0, out.normal, along);
  }
  path.length = along;
  if (!path.unwrapped.empty()) path.pieces.clear();
  return path;
}

Catenary catenary_through(double h, double v, double length) {
  Catenary out;
  if (!(h > 0.0) || !(length > std::hypot(h, v)) || !std::isfinite(length)) return out;
  // sinh ξ / ξ = √(S² − v²) / h with ξ = h / 2a (sinh ξ / ξ rises from 1 on ξ > 0): bracketed
  // by doubling, then bisected to the last bit
  const double ratio = std::sqrt(length * length - v * v) / h;
  double lo = 0.0, hi = 1.0;
  while (std::sinh(hi) / hi < ratio && hi < 700.0) hi *= 2.0;
  for (int it = 0; it < 300; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (!(mid > lo && mid < hi)) break;
    (std::sinh(mid) / mid < ratio ? lo : hi) = mid;
  }
  out.a = h / (lo + hi);
  out.u = 0.5 * h - out.a * std::atanh(v / length);
  return out;
}

namespace {

// A catenary piece's height at t = (X − u)/a (X along from its first end): y0 + a (cosh t −
// cosh(u/a)).
double catenary_height(const PathPiece& q, double t) {
  return q.y0 + q.hang_a * (std::cosh(t) - std::cosh(q.hang_u / q.hang_a));
}

}  // namespace

PathPoint sag_point(const PathPiece& q, double along) {
  PathPoint p;
  if (q.catenary) {
    // the arc length from the first end: a (sinh((X − u)/a) + sinh(u/a)), inverted
    const double a = q.hang_a, u = q.hang_u;
    const double t = std::asinh(along / a - std::sinh(u / a));  // (X − u)/a
    p.x = q.x0 + u + a * t;
    p.y = catenary_height(q, t);
    p.tx = 1.0 / std::cosh(t);
    p.ty = std::tanh(t);
    return p;
  }
  const double t = q.from + q.sense * along / q.radius;
  const double c = std::cos(t), sn = std::sin(t);
  p.x = q.cx + q.radius * c;
  p.y = q.cy + q.radius * sn;
  p.tx = -q.sense * sn;
  p.ty = q.sense * c;
  return p;
}

PathPoint path_point(const BeltPath& path, double s) {
  PathPoint p;
  double u = std::fmod(s, path.length);
  if (u < 0.0) u += path.length;
  const auto it = std::upper_bound(path.pieces.begin(), path.pieces.end(), u,
                                   [](double x, const PathPiece& q) { return x < q.start; });
  const std::size_t k =
      it == path.pieces.begin() ? 0 : static_cast<std::size_t>(it - path.pieces.begin()) - 1;
  const PathPiece& q = path.pieces[k];
  p.piece = k;
  const double along = std::clamp(u - q.start, 0.0, q.length);
  if (q.arc || q.sag) {
    const PathPoint on = sag_point(q, along);
    p.x = on.x;
    p.y = on.y;
    p.tx = on.tx;
    p.ty = on.ty;
  } else {
    const double f = q.length > 0.0 ? along / q.length : 0.0;
    p.x = q.x0 + f * (q.x1 - q.x0);
    p.y = q.y0 + f * (q.y1 - q.y0);
    p.tx = q.length > 0.0 ? (q.x1 - q.x0) / q.length : 1.0;
    p.ty = q.length > 0.0 ? (q.y1 - q.y0) / q.length : 0.0;
  }
  return p;
}

namespace {

// Whether a catenary piece lies within the arc lengths [s, s + reach] of the path (the pieces
// from the one at s on).
bool catenary_ahead(const BeltPath& path, std::size_t piece, double u, double reach) {
  for (std::size_t k = 0; k < path.pieces.size(); ++k) {
    const PathPiece& q = path.pieces[(piece + k) % path.pieces.size()];
    const double start = q.start + (piece + k >= path.pieces.size() ? path.length : 0.0);
    if (k > 0 && start > u + reach) return false;
    if (q.catenary) return true;
  }
  return false;
}

// The next node forward of the one at arc length s: the first point of the path at chord h from
// it. Exact within one piece (an arc: the chord's angle 2 asin(h/2R); a span: h itself); across
// pieces by bisection on the arc length (the chord grows monotonically over the 1.6 h searched:
// the pitch radius is at least 1.3 p at z = 8, where an arc of 1.6 h spans a chord of 1.5 h).
// Near a catenary the chord need not grow: its lowest point may be tighter than h, and a sloped
// span's catenary meets the far wheel at a kink (it climbs into the wheel almost vertically while
// the wrap leaves along the chord's direction), where the path nearly folds back. There the
// path is marched in steps of h/16 to the first point whose chord reaches h, and that step is
// bisected; NaN when no point within the path's length reaches h.
double next_node(const BeltPath& path, double s, double h) {
  const PathPoint p = path_point(path, s);
  const PathPiece& q = path.pieces[p.piece];
  double u = std::fmod(s, path.length);
  if (u < 0.0) u += path.length;
  const double along = u - q.start;
  if (!q.catenary && (q.arc || q.sag) && h < 2.0 * q.radius) {
    const double step = 2.0 * q.radius * std::asin(h / (2.0 * q.radius));
    if (along + step <= q.length) return s + step;
  } else if (!q.arc && !q.catenary && along + h <= q.length) {
    return s + h;
  }
  double lo = s, hi = s + 1.6 * h;
  if (catenary_ahead(path, p.piece, u, 1.6 * h)) {
    const double step = h / 16.0;
    const int steps = static_cast<int>(std::ceil(path.length / step));
    for (int k = 1;; ++k) {
      if (k > steps) return NAN;
      const PathPoint m = path_point(path, s + k * step);
      if (std::hypot(m.x - p.x, m.y - p.y) >= h) {
        lo = s + (k - 1) * step;
        hi = s + k * step;
        break;
      }
    }
  }
  for (int it = 0; it < 200 && hi - lo > 1e-15 * path.length; ++it) {
    const double mid = 0.5 * (lo + hi);
    const PathPoint m = path_point(path, mid);
    if (std::hypot(m.x - p.x, m.y - p.y) < h)
      lo = mid;
    else
      hi = mid;
  }
  return 0.5 * (lo + hi);
}

// The arc lengths of nodes 0..N from node 0 at `start` (node N where the walk would put the next
// one after N − 1).
std::vector<double> walk(const BeltPath& path, double h, int nodes, double start = 0.0) {
  std::vector<double> s(static_cast<std::size_t>(nodes) + 1, start);
  for (std::size_t k = 1; k < s.size(); ++k) s[k] = next_node(path, s[k - 1], h);
  return s;
}

// How far past node 0 once round the loop the walk's node N lands (`walk` at chord `h` from node 0
// at `start`): 0 where the N links close the loop, positive where they overshoot.
double walk_miss(const BeltPath& path, double h, int nodes, double start) {
  return walk(path, h, nodes, start).back() - start - path.length;
}

}  // namespace

double path_links(const BeltPath& path, double spacing) {
  if (path.pieces.empty() || !(spacing > 0.0)) return NAN;
  double s = 0.0;
  const double limit = 2.0 * path.length / spacing + 10.0;
  for (int k = 0; k < limit; ++k) {
    const double next = next_node(path, s, spacing);
    if (next >= path.length) return k + (path.length - s) / (next - s);
    s = next;
  }
  return NAN;
}

namespace {

// `place_loop` with node 0 at arc length `start` (the slack start's phase, `slack_solve`).
LoopPlacement place_loop_from(const BeltPath& path, const std::vector<Circle>& circles,
                              const std::vector<int>& teeth, int nodes, double pitch,
                              double start) {
  LoopPlacement out;
  if (path.pieces.empty() || nodes < 3 || !(pitch > 0.0)) return out;
  const double length = path.length;
  auto miss = [&](double h) { return walk_miss(path, h, nodes, start); };
  // secant on the chord: the walk's end moves with it almost in proportion
  double h0 = pitch, g0 = miss(h0);
  double h1 = h0 * length / (g0 + length), g1 = miss(h1);
  for (int it = 0; it < 60 && std::abs(g1) > 1e-12 * length; ++it) {
    if (g1 == g0) break;
    const double h2 = h1 - g1 * (h1 - h0) / (g1 - g0);
    h0 = h1;
    g0 = g1;
    h1 = h2;
    if (!(h1 > 0.5 * pitch && h1 < 2.0 * pitch)) return out;
    g1 = miss(h1);
  }
  if (!(std::abs(g1) <= 1e-9 * length)) return out;
  out.spacing = h1;
  out.s = walk(path, h1, nodes, start);
  out.s.pop_back();
  // each wheel: the wrapped rollers' angles along its arc; the seats (2π/z apart) placed so that
  // the largest offset either way is the same
  const std::size_t n = circles.size();
  out.angle.assign(n, 0.0);
  out.wrapped.assign(n, 0);
  out.seat_offset.assign(n, 0.0);
  std::vector<double> first(n, NAN), lo(n, 0.0), hi(n, 0.0);
  for (const double s : out.s) {
    const PathPoint p = path_point(path, s);
    const PathPiece& q = path.pieces[p.piece];
    if (!q.arc) continue;
    double u = std::fmod(s, length);
    if (u < 0.0) u += length;
    const double theta = q.from + q.sense * (u - q.start) / q.radius;
    const std::size_t w = q.wheel;
    const double tau = kTwoPi / teeth[w];
    if (std::isnan(first[w])) first[w] = theta;
    const double d = theta - first[w];
    const double off = d - std::nearbyint(d / tau) * tau;
    lo[w] = std::min(lo[w], off);
    hi[w] = std::max(hi[w], off);
    ++out.wrapped[w];
  }
  for (std::size_t w = 0; w < n; ++w) {
    if (std::isnan(first[w])) {
      out.seat_offset[w] = NAN;
      continue;
    }
    out.angle[w] = first[w] + 0.5 * (lo[w] + hi[w]);
    out.seat_offset[w] = 2.0 * circles[w].radius * std::sin(0.25 * (hi[w] - lo[w]));
  }
  return out;
}

}  // namespace

LoopPlacement place_loop(const BeltPath& path, const std::vector<Circle>& circles,
                         const std::vector<int>& teeth, int nodes, double pitch) {
  return place_loop_from(path, circles, teeth, nodes, pitch, 0.0);
}

std::size_t slack_span(const BeltPath& path) {
  // a wheel on the back of the chain (wrapped clockwise) has the span's outward side, where the
  // sag bulges, towards it: a span touching one does not sag
  std::vector<std::size_t> back;
  for (const PathPiece& q : path.pieces)
    if (q.arc && q.sense < 0.0) back.push_back(q.wheel);
  auto on_back = [&back](std::size_t w) {
    return std::find(back.begin(), back.end(), w) != back.end();
  };
  std::size_t best = path.pieces.size();
  double lowest = INFINITY;
  for (std::size_t k = 0; k < path.pieces.size(); ++k) {
    const PathPiece& q = path.pieces[k];
    if (q.arc || !(q.length > 0.0) || on_back(q.wheel) || on_back(q.next)) continue;
    const double ny = -(q.x1 - q.x0) / q.length;  // the right-hand normal's y
    if (ny < lowest - 1e-12) {
      lowest = ny;
      best = k;
    }
  }
  return best;
}

BeltPath sag_span(const BeltPath& path, std::size_t piece, double extra) {
  BeltPath out = path;
  if (piece >= path.pieces.size() || path.pieces[piece].arc || !(extra > 0.0)) {
    out.pieces.clear();
    return out;
  }
  PathPiece& q = out.pieces[piece];
  const double c = std::hypot(q.x1 - q.x0, q.y1 - q.y0), arc = c + extra;
  // the half angle φ of the arc: sin φ / φ = c / arc (decreasing on (0, π]), by bisection
  const double ratio = c / arc;
  if (!(ratio > 2.0 / kPi)) {
    // beyond a half circle: the catenary of that length, hanging below its chord, so only on a
    // span whose outward side is down (travelling towards +x)
    const Catenary hang = extra <= kCatenaryMostExtra * c
                              ? catenary_through(q.x1 - q.x0, q.y1 - q.y0, arc)
                              : Catenary{};
    if (!std::isfinite(hang.a) || !std::isfinite(hang.u)) {
      out.pieces.clear();
      return out;
    }
    q.sag = true;
    q.catenary = true;
    q.hang_a = hang.a;
    q.hang_u = hang.u;
    q.length = arc;
    return with_starts(std::move(out));
  }
  double lo = 1e-12, hi = 0.5 * kPi;
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    (std::sin(mid) / mid > ratio ? lo : hi) = mid;
  }
  const double phi = 0.5 * (lo + hi);
  const double rho = 0.5 * c / std::sin(phi);
  // the bulge to the right of the travel; the centre on the left of the chord's middle, so the
  // chain runs counter-clockwise about it
  const double ux = (q.x1 - q.x0) / c, uy = (q.y1 - q.y0) / c;
  const double mx = 0.5 * (q.x0 + q.x1), my = 0.5 * (q.y0 + q.y1);
  q.sag = true;
  q.sense = 1.0;
  q.radius = rho;
  q.cx = mx - uy * rho * std::cos(phi);
  q.cy = my + ux * rho * std::cos(phi);
  q.from = std::atan2(q.y0 - q.cy, q.x0 - q.cx);
  q.to = q.from + 2.0 * phi;
  q.length = 2.0 * rho * phi;
  return with_starts(std::move(out));
}

// the most points the sag check samples along one arc (bounded work: sag_limit bisects over it)
constexpr double kMaxSagSamples = 1e6;

namespace {

// The samples along an arc `length` long [m] that the sag and lead-in checks take: a quarter
// roller apart, at least 512 and at most kMaxSagSamples (an arc longer than 2.5e5 rollers — a
// roller under 0.24 mm on a 60 m span — is sampled more coarsely).
int arc_samples(double length, double roller) {
  const double want = std::ceil(length / (0.25 * roller));
  return static_cast<int>(want > 512.0 ? (want < kMaxSagSamples ? want : kMaxSagSamples) : 512.0);
}

// A catenary's height at x (x0 ≤ x ≤ x1).
double catenary_y(const PathPiece& q, double x) {
  return catenary_height(q, (x - q.x0 - q.hang_u) / q.hang_a);
}

// Sample j of n along a span (j/n of the way): a catenary's point at that share of its length, a
// sagging arc's at that share of its angle, a straight span's at that share of its chord.
PathPoint span_sample(const PathPiece& q, int j, int n) {
  if (q.catenary) return sag_point(q, q.length * j / n);
  PathPoint p;
  if (q.sag) {
    const double a = q.from + (q.to - q.from) * j / n;
    p.x = q.cx + q.radius * std::cos(a);
    p.y = q.cy + q.radius * std::sin(a);
  } else {
    p.x = q.x0 + (q.x1 - q.x0) * j / n;
    p.y = q.y0 + (q.y1 - q.y0) * j / n;
  }
  return p;
}

// The distance from (x, y) to a catenary piece between the arc lengths `from` and `to`: the
// nearest of 256 samples, then golden-section search over the samples either side of it (the
// distance is smooth along the curve; within a sample's spacing it has one minimum where the
// spacing is small against the curve's radius, at least a).
double catenary_distance(const PathPiece& q, double x, double y, double from, double to) {
  auto at = [&](double along) {
    const PathPoint p = sag_point(q, along);
    return std::hypot(p.x - x, p.y - y);
  };
  const int n = 256;
  const double step = (to - from) / n;
  int best = 0;
  double least = INFINITY;
  for (int j = 0; j <= n; ++j) {
    const double d = at(from + step * j);
    if (d < least) {
      least = d;
      best = j;
    }
  }
  double lo = from + step * std::max(best - 1, 0), hi = from + step * std::min(best + 1, n);
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int it = 0; it < 80; ++it) {
    const double m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo);
    if (at(m1) < at(m2))
      hi = m2;
    else
      lo = m1;
  }
  return std::min(least, at(0.5 * (lo + hi)));
}

// A sagging piece's bounding box: its ends and, on a catenary, its lowest point; on an arc the
// box of its whole circle.
void sag_box(const PathPiece& q, double& x0, double& y0, double& x1, double& y1) {
  if (!q.catenary) {
    x0 = q.cx - q.radius;
    y0 = q.cy - q.radius;
    x1 = q.cx + q.radius;
    y1 = q.cy + q.radius;
    return;
  }
  x0 = q.x0;
  x1 = q.x1;
  y1 = std::max(q.y0, q.y1);
  y0 = q.hang_u > 0.0 && q.hang_u < q.x1 - q.x0 ? catenary_y(q, q.x0 + q.hang_u)
                                                : std::min(q.y0, q.y1);
}

// A piece's bounding box: a wrap's whole circle, a sagging piece's sag_box, a straight span's
// ends (either first).
void piece_box(const PathPiece& q, double& x0, double& y0, double& x1, double& y1) {
  x0 = q.x0;
  y0 = q.y0;
  x1 = q.x1;
  y1 = q.y1;
  if (q.arc) {
    x0 = q.cx - q.radius;
    y0 = q.cy - q.radius;
    x1 = q.cx + q.radius;
    y1 = q.cy + q.radius;
  } else if (q.sag) {
    sag_box(q, x0, y0, x1, y1);
  }
}

// Whether the box of the corners (x0, y0) and (x1, y1) (either first) comes within `margin` of
// the box [lo_x, hi_x] × [lo_y, hi_y].
bool boxes_near(double x0, double y0, double x1, double y1, double lo_x, double lo_y, double hi_x,
                double hi_y, double margin) {
  return std::min(x0, x1) <= hi_x + margin && std::max(x0, x1) >= lo_x - margin &&
         std::min(y0, y1) <= hi_y + margin && std::max(y0, y1) >= lo_y - margin;
}

}  // namespace

std::string sag_obstacle(const BeltPath& laid, std::size_t piece,
                         const std::vector<Circle>& circles, const std::vector<double>& tip,
                         const std::vector<Guide>& guides, double roller, double pitch) {
  if (piece >= laid.pieces.size() || !laid.pieces[piece].sag) return "the sagging span";
  const PathPiece& q = laid.pieces[piece];
  // a catenary whose lowest point turns tighter than a roller's radius: its two strands there
  // lie within a roller's diameter of each other (the checks below skip the piece itself); a
  // grows smaller as the extra grows, so what is refused stays refused
  if (q.catenary && q.hang_a < 0.5 * roller) {
    char text[160];
    std::snprintf(text, sizeof text,
                  "its own other strand (the catenary's lowest curvature radius a = %.4g mm is "
                  "below the roller's radius d1/2 = %.4g mm)",
                  q.hang_a * 1e3, 0.5 * roller * 1e3);
    return text;
  }
  const int samples = arc_samples(q.length, roller);
  // inside the circular segment the sag sweeps (between the chord and the arc): the segments of
  // a growing sag are nested, so an obstacle once inside stays inside
  const double ux = q.x1 - q.x0, uy = q.y1 - q.y0, chord = std::hypot(ux, uy);
  auto swept = [&](double x, double y) {
    const double out = ((x - q.x0) * uy - (y - q.y0) * ux) / chord;  // to the right of the travel
    // a catenary's segment: below the chord (x1 > x0) and above the curve
    if (q.catenary) return out > 0.0 && x > q.x0 && x < q.x1 && y > catenary_y(q, x);
    return out > 0.0 && std::hypot(x - q.cx, y - q.cy) < q.radius;
  };
  for (std::size_t w = 0; w < circles.size(); ++w)
    if (w != q.wheel && w != q.next && swept(circles[w].x, circles[w].y))
      return wheel_name(w) + "'s teeth";
  for (std::size_t g = 0; g < guides.size(); ++g) {
    const Guide& gd = guides[g];
    for (int j = 0; j <= 256; ++j) {
      const double f = j / 256.0;
      const double a = gd.start_angle + f * (gd.end_angle - gd.start_angle);
      const bool straight = gd.kind == Guide::Kind::kStraight;
      const double x =
          straight ? gd.x0 + f * (gd.x1 - gd.x0) : gd.centre_x + gd.radius * std::cos(a);
      const double y =
          straight ? gd.y0 + f * (gd.y1 - gd.y0) : gd.centre_y + gd.radius * std::sin(a);
      if (swept(x, y)) return "guide[" + std::to_string(g) + "]";
    }
  }
  for (std::size_t k = 0; k < laid.pieces.size(); ++k) {
    const PathPiece& r = laid.pieces[k];
    if (k == piece || r.arc) continue;
    for (int j = 1; j < 256; ++j) {
      // a straight span's points, or another sagging span's along its arc (two sags may face
      // each other across a notch of a serpentine path)
      const PathPoint on = span_sample(r, j, 256);
      if (swept(on.x, on.y)) return "the span " + wheel_name(r.wheel) + " -> " + wheel_name(r.next);
    }
  }
  for (int j = 0; j <= samples; ++j) {
    const PathPoint on = span_sample(q, j, samples);
    const double x = on.x, y = on.y;
    for (std::size_t w = 0; w < circles.size(); ++w) {
      if (w == q.wheel || w == q.next) continue;
      if (std::hypot(x - circles[w].x, y - circles[w].y) < tip[w] + 0.5 * roller)
        return wheel_name(w) + "'s teeth";
    }
    for (std::size_t g = 0; g < guides.size(); ++g)
      if (guide_distance(guides[g], x, y) < 0.5 * roller) return "guide[" + std::to_string(g) + "]";
    const double along = q.length * j / samples;
    if (along < pitch || along > q.length - pitch) continue;
    for (std::size_t k = 0; k < laid.pieces.size(); ++k) {
      const PathPiece& r = laid.pieces[k];
      if (k == piece || r.arc) continue;
      // another sagging span: its arc but for a pitch at either end (on its wheels)
      if (r.catenary && !(r.length > 2.0 * pitch)) continue;
      const double end = r.sag && !r.catenary ? pitch / r.radius : 0.0;
      if (r.sag && !r.catenary && !(r.to - r.from > 2.0 * end)) continue;
      const double gap = r.catenary ? catenary_distance(r, x, y, pitch, r.length - pitch)
                         : r.sag
                             ? arc_distance(x, y, r.cx, r.cy, r.radius, r.from + end, r.to - end)
                             : segment_distance(x, y, r.x0, r.y0, r.x1, r.y1);
      if (gap < roller) return "the span " + wheel_name(r.wheel) + " -> " + wheel_name(r.next);
    }
  }
  return {};
}

// The largest extra length in [0, most] that `clear` allows (`most` itself if it does), by
// bisection to 1e-6 of `scale` (the segments of a growing sag are nested, so what is inside
// stays inside: the clear extras are an interval from 0).
namespace {

template <class Clear>
double largest_clear_extra(double most, double scale, Clear clear) {
  if (clear(most)) return most;
  double lo = 0.0, hi = most;
  while (hi - lo > 1e-6 * scale) {
    const double mid = 0.5 * (lo + hi);
    (clear(mid) ? lo : hi) = mid;
  }
  return lo;
}

// The largest clear extra up to the half circle's `half` (a hair inside), as before the catenary;
// when the half circle is clear, on along the catenaries from a hair beyond it up to `longest`
// (a catenary's segment and a half circle's are not nested, but the catenaries' are: bisected
// apart), or the half circle's extra when the first catenary is not clear or not laid.
template <class Clear>
double largest_clear_sag(double half, double longest, double scale, Clear clear) {
  const double arcs = largest_clear_extra(half * (1.0 - 1e-9), scale, clear);
  if (arcs < half * (1.0 - 1e-9)) return arcs;
  const double from = half * (1.0 + 1e-9);
  if (!clear(from)) return arcs;
  return from + largest_clear_extra(longest * (1.0 - 1e-9) - from, scale,
                                    [&](double more) { return clear(from + more); });
}

}  // namespace

namespace {

// Whether every span of `pieces` in the lay `laid` is clear of everything, the other sags included
// (`sag_obstacle`); not where the lay is refused (empty).
bool lay_clear(const BeltPath& laid, const std::vector<std::size_t>& pieces,
               const std::vector<Circle>& circles, const std::vector<double>& tip,
               const std::vector<Guide>& guides, double roller, double pitch) {
  if (laid.pieces.empty()) return false;
  for (const std::size_t k : pieces)
    if (!sag_obstacle(laid, k, circles, tip, guides, roller, pitch).empty()) return false;
  return true;
}

// The largest clear extra of the spans `pieces` (their chords `total` long) sharing it in
// proportion to their chords, each laid as a start lays it (`slack_lay`) and checked against
// everything, the other sags included (`sag_obstacle`): up to the half circle the arcs between
// the tangent points (`sag_spans`); beyond it the tangent lay (`tangent_spans`), else, where that
// is refused, the lay between the tangent points; where the tangent lay keeps less than a pitch
// (2 asin(p / 2r)) of any wrap, both must be clear (which one a start lays there depends on where
// its rollers fall: a wheel left with no roller falls back to the other). Within a band below the
// half circle a count whose lay between the tangent points would pass it is laid tangent at an e
// a little below it (level 600 mm, z 17 both, 98 links: 342.414 against the half circle's
// 342.478 mm): there both the arcs and the tangent lay must be clear. For one span the band is a
// pitch (measured: over 37–61° slopes the counts laid tangent closed at most 0.582 p below it);
// for more, the spans' kinks there (`sag_spans_band`: a link across a kink φ takes up to
// `kink_link_extra` more path; docs/models/dynamics.md, "The band below the half circle"). Where
// the tangent lay cuts the limit in the band, a count laid as arcs may still take more
// (`sag_spans_arcs_limit`).
double spans_limit(const BeltPath& path, const std::vector<std::size_t>& pieces, double total,
                   const std::vector<Circle>& circles, const std::vector<double>& tip,
                   const std::vector<Guide>& guides, double roller, double pitch) {
  const double half = (0.5 * kPi - 1.0) * total;
  // one span: a pitch (measured: 0.582 p at most over 37–61° slopes); more: from their kinks
  const double band = pieces.size() == 1 ? pitch : sag_spans_band(path, pieces, pitch);
  const std::size_t n = path.pieces.size();
  auto short_wrap = [&](const PathPiece& w) {
    return !(w.to - w.from >= 2.0 * std::asin(std::min(1.0, 0.5 * pitch / w.radius)));
  };
  auto clear_lay = [&](const BeltPath& laid) {
    return lay_clear(laid, pieces, circles, tip, guides, roller, pitch);
  };
  auto clear = [&](double extra) {
    const bool below = extra <= half;
    const BeltPath tangent = extra > half - band ? tangent_spans(path, pieces, extra) : BeltPath{};
    if (below) {
      if (!clear_lay(sag_spans(path, pieces, extra))) return false;
      return tangent.pieces.empty() || clear_lay(tangent);
    }
    if (tangent.pieces.empty()) return clear_lay(sag_spans(path, pieces, extra));
    if (!clear_lay(tangent)) return false;
    bool bare = false;
    for (const std::size_t k : pieces)
      bare = bare || short_wrap(tangent.pieces[k - 1]) || short_wrap(tangent.pieces[(k + 1) % n]);
    return !bare || clear_lay(sag_spans(path, pieces, extra));
  };
  // the arcs up to the half circle, then the catenaries (sag_span refuses beyond the longest)
  return largest_clear_sag(half, kCatenaryMostExtra * total, total, clear);
}

}  // namespace

double sag_limit(const BeltPath& path, std::size_t piece, const std::vector<Circle>& circles,
                 const std::vector<double>& tip, const std::vector<Guide>& guides, double roller,
                 double pitch) {
  if (piece >= path.pieces.size() || path.pieces[piece].arc) return 0.0;
  return spans_limit(path, {piece}, path.pieces[piece].length, circles, tip, guides, roller, pitch);
}

double sag_spans_limit(const BeltPath& path, const std::vector<std::size_t>& pieces,
                       const std::vector<Circle>& circles, const std::vector<double>& tip,
                       const std::vector<Guide>& guides, double roller, double pitch) {
  if (pieces.size() == 1) return sag_limit(path, pieces[0], circles, tip, guides, roller, pitch);
  const double total = span_chords(path, pieces);
  if (!(total > 0.0)) return 0.0;
  // every span laid with its share, each checked against everything, the other sags included
  return spans_limit(path, pieces, total, circles, tip, guides, roller, pitch);
}

double sag_spans_arcs_limit(const BeltPath& path, const std::vector<std::size_t>& pieces,
                            const std::vector<Circle>& circles, const std::vector<double>& tip,
                            const std::vector<Guide>& guides, double roller, double pitch) {
  const double total = span_chords(path, pieces);
  if (!(total > 0.0)) return 0.0;
  const double half = (0.5 * kPi - 1.0) * total;
  return largest_clear_extra(half * (1.0 - 1e-9), total, [&](double extra) {
    return lay_clear(sag_spans(path, pieces, extra), pieces, circles, tip, guides, roller, pitch);
  });
}

double sag_spans_band(const BeltPath& path, const std::vector<std::size_t>& pieces, double pitch) {
  const double total = span_chords(path, pieces);
  if (!(total > 0.0)) return 0.0;
  const BeltPath beyond = sag_spans(path, pieces, (0.5 * kPi - 1.0) * total * (1.0 + 1e-9));
  double band = 0.0;
  for (const std::size_t k : pieces) {
    double turn0 = 0.5 * kPi, turn1 = 0.5 * kPi;  // the half circle's arc meets its chord square
    if (!beyond.pieces.empty() && beyond.pieces[k].catenary) {
      // the catenary's unit tangents at both ends against the chord's direction
      const PathPiece& q = beyond.pieces[k];
      const double cx = q.x1 - q.x0, cy = q.y1 - q.y0, c = std::hypot(cx, cy);
      auto turn = [&](double along) {
        const PathPoint at = sag_point(q, along);
        return std::acos(std::clamp((at.tx * cx + at.ty * cy) / c, -1.0, 1.0));
      };
      turn0 = std::max(turn0, turn(0.0));
      turn1 = std::max(turn1, turn(q.length));
    }
    band += kink_link_extra(turn0, pitch) + kink_link_extra(turn1, pitch);
  }
  return band;
}

// kink_link_extra (layout.hpp): |A − B|² = a² + b² + 2ab cos φ = p² gives (a + b)² = p² + 2ab (1 −
// cos φ) <= p² + (a + b)² (1 − cos φ)/2; a = b <= p holds up to 120°, and past it the most is at
// a = p, b = −2 p cos φ (continuous at 120°, both p).
double kink_link_extra(double turn, double pitch) {
  return turn <= 2.0 * kPi / 3.0 ? pitch * (1.0 / std::cos(0.5 * turn) - 1.0)
                                 : -2.0 * pitch * std::cos(turn);
}

double span_chords(const BeltPath& path, const std::vector<std::size_t>& pieces) {
  double total = 0.0;
  for (const std::size_t k : pieces) {
    if (k >= path.pieces.size() || path.pieces[k].arc) return 0.0;
    total += path.pieces[k].length;
  }
  return total;
}

namespace {

// What a lead-in arc's check measures: its samples (`arc_samples` of them along the arc's surface,
// laid once for the prefilter's box and, when `lead_in_reach` is asked to keep them, the check),
// the path's pieces it may approach (off the spans the rail carries) with the least distance each
// allows, and the other guides it may run into; only those whose bounding box comes within a
// roller radius of the samples' (no other can come that close to a sample: the prefilter changes
// no verdict, it only skips work).
struct LeadInReach {
  std::vector<double> x, y;  // [m] the samples, when kept (empty for a count of the work)
  std::vector<std::size_t> pieces;
  std::vector<double> least;  // [m], for each of `pieces`
  std::vector<std::size_t> guides;
};

// a wheel's wrap (clockwise on the back: its angles the other way round), a sagging span's arc, a
// straight span
double piece_gap(const PathPiece& q, double x, double y) {
  return q.arc        ? arc_distance(x, y, q.cx, q.cy, q.radius, std::min(q.from, q.to),
                                     std::max(q.from, q.to))
         : q.catenary ? catenary_distance(q, x, y, 0.0, q.length)
         : q.sag      ? arc_distance(x, y, q.cx, q.cy, q.radius, q.from, q.to)
                      : segment_distance(x, y, q.x0, q.y0, q.x1, q.y1);
}

LeadInReach lead_in_reach(const BeltPath& path, const Guide& rail, const Guide& arc,
                          const std::vector<Guide>& guides, const std::vector<std::size_t>& skip,
                          double roller, bool keep_samples) {
  const double r = 0.5 * roller;
  LeadInReach out;
  // the spans the rail carries: a point within a roller's diameter of its surface (the rollers
  // riding on it; a straight rail's segment or an arc's); the arc bends away from them
  std::vector<bool> carried(path.pieces.size(), false);
  for (std::size_t k = 0; k < path.pieces.size(); ++k) {
    const PathPiece& q = path.pieces[k];
    for (int j = 0; !q.arc && !carried[k] && j <= 256; ++j) {
      const PathPoint on = span_sample(q, j, 256);
      carried[k] = guide_distance(rail, on.x, on.y) < roller;
    }
  }
  // the rail's ends: a straight rail's (x0, y0) and (x1, y1), an arc's surface points at its start
  // and end angles
  const bool straight = rail.kind == Guide::Kind::kStraight;
  const double rx0 = straight ? rail.x0 : rail.centre_x + rail.radius * std::cos(rail.start_angle);
  const double ry0 = straight ? rail.y0 : rail.centre_y + rail.radius * std::sin(rail.start_angle);
  const double rx1 = straight ? rail.x1 : rail.centre_x + rail.radius * std::cos(rail.end_angle);
  const double ry1 = straight ? rail.y1 : rail.centre_y + rail.radius * std::sin(rail.end_angle);
  // the rail's end the arc is laid at (the rail's end nearer one of the arc's ends)
  const double sx = arc.centre_x + arc.radius * std::cos(arc.start_angle);
  const double sy = arc.centre_y + arc.radius * std::sin(arc.start_angle);
  const double fx = arc.centre_x + arc.radius * std::cos(arc.end_angle);
  const double fy = arc.centre_y + arc.radius * std::sin(arc.end_angle);
  auto to_arc_ends = [&](double x, double y) {
    return std::min(std::hypot(x - sx, y - sy), std::hypot(x - fx, y - fy));
  };
  const bool first = to_arc_ends(rx0, ry0) <= to_arc_ends(rx1, ry1);
  const double ex = first ? rx0 : rx1, ey = first ? ry0 : ry1;
  const double sweep = arc.end_angle - arc.start_angle;
  const int samples = arc_samples(arc.radius * sweep, roller);
  if (keep_samples) {
    out.x.reserve(static_cast<std::size_t>(samples) + 1);
    out.y.reserve(static_cast<std::size_t>(samples) + 1);
  }
  double lo_x = INFINITY, lo_y = INFINITY, hi_x = -INFINITY, hi_y = -INFINITY;
  for (int j = 0; j <= samples; ++j) {
    const double a = arc.start_angle + sweep * j / samples;
    const double x = arc.centre_x + arc.radius * std::cos(a);
    const double y = arc.centre_y + arc.radius * std::sin(a);
    if (keep_samples) {
      out.x.push_back(x);
      out.y.push_back(y);
    }
    lo_x = std::min(lo_x, x);
    lo_y = std::min(lo_y, y);
    hi_x = std::max(hi_x, x);
    hi_y = std::max(hi_y, y);
  }
  auto near_box = [&](double x0, double y0, double x1, double y1) {
    return boxes_near(x0, y0, x1, y1, lo_x, lo_y, hi_x, hi_y, r);
  };
  auto near_circle = [&](double cx, double cy, double radius) {
    return near_box(cx - radius, cy - radius, cx + radius, cy + radius);
  };
  // each piece the arc may approach: no closer than a roller radius, or than the rail's end
  // already is when that is nearer (a rail that runs to a wheel's tangent point: its arc may not
  // close in on the wrap beyond where the rail ends, but is not refused for where the rail ends)
  for (std::size_t k = 0; k < path.pieces.size(); ++k) {
    const PathPiece& q = path.pieces[k];
    if (carried[k]) continue;
    double bx0 = 0.0, by0 = 0.0, bx1 = 0.0, by1 = 0.0;
    piece_box(q, bx0, by0, bx1, by1);
    if (!near_box(bx0, by0, bx1, by1)) continue;
    out.pieces.push_back(k);
    // (the arc's first sample is the rail's end: a hair below it, for its rounding)
    const double end = piece_gap(q, ex, ey);
    out.least.push_back(end < r ? end - 1e-9 * roller : r);
  }
  for (std::size_t g = 0; g < guides.size(); ++g) {
    if (std::find(skip.begin(), skip.end(), g) != skip.end()) continue;
    const Guide& gd = guides[g];
    if (gd.kind == Guide::Kind::kStraight ? near_box(gd.x0, gd.y0, gd.x1, gd.y1)
                                          : near_circle(gd.centre_x, gd.centre_y, gd.radius))
      out.guides.push_back(g);
  }
  return out;
}

}  // namespace

std::string lead_in_obstacle(const BeltPath& path, const Guide& rail, const Guide& arc,
                             const std::vector<Guide>& guides, const std::vector<std::size_t>& skip,
                             double roller) {
  const double r = 0.5 * roller;
  const LeadInReach reach = lead_in_reach(path, rail, arc, guides, skip, roller, true);
  for (std::size_t j = 0; j < reach.x.size(); ++j) {
    const double x = reach.x[j], y = reach.y[j];
    for (std::size_t i = 0; i < reach.pieces.size(); ++i) {
      const PathPiece& q = path.pieces[reach.pieces[i]];
      if (piece_gap(q, x, y) < reach.least[i])
        return q.arc ? "the chain on " + wheel_name(q.wheel)
                     : "the span " + wheel_name(q.wheel) + " -> " + wheel_name(q.next);
    }
    for (const std::size_t g : reach.guides)
      if (guide_distance(guides[g], x, y) < r) return "guide[" + std::to_string(g) + "]";
  }
  return {};
}

double lead_in_work(const BeltPath& path, const Guide& rail, const Guide& arc,
                    const std::vector<Guide>& guides, const std::vector<std::size_t>& skip,
                    double roller) {
  // the samples counted, not kept (up to 1e6 + 1 of them, and the bisections ask again and again)
  const LeadInReach reach = lead_in_reach(path, rail, arc, guides, skip, roller, false);
  const int samples = arc_samples(arc.radius * (arc.end_angle - arc.start_angle), roller);
  return (samples + 1.0) * static_cast<double>(reach.pieces.size() + reach.guides.size());
}

LeadInLimit lead_in_limit(const BeltPath& path, const Guide& rail, const LeadIn& lead,
                          const std::vector<Guide>& guides, const std::vector<std::size_t>& skip,
                          double roller) {
  auto clear = [&](const LeadIn& trial) {
    for (const Guide& arc : lead_in_arcs(rail, trial))
      if (!lead_in_obstacle(path, rail, arc, guides, skip, roller).empty()) return false;
    return true;
  };
  LeadInLimit out;
  // the radius at the sweep given (the arcs are not nested in R: bisected from 0, where the
  // arc shrinks to the rail's end), and the sweep at the radius given (nested: exact)
  out.radius = largest_clear_extra(lead.radius, lead.radius, [&](double radius) {
    LeadIn trial = lead;
    trial.radius = radius;
    return clear(trial);
  });
  out.angle = largest_clear_extra(lead.angle, lead.angle, [&](double angle) {
    LeadIn trial = lead;
    trial.angle = angle;
    return clear(trial);
  });
  return out;
}

namespace {

// The path's samples for the cuts: an eighth of a roller radius apart (arc_samples's quarter of
// half the roller radius), at least 512, at most kMaxSagSamples.
int cut_samples(const BeltPath& path, const Guide& rail) {
  return arc_samples(path.length, 0.5 * rail.roller_radius);
}

// The rail with its surface moved by `shift` away from its rollers' side.
Guide rail_moved(const Guide& rail, double shift) {
  Guide out = rail;
  if (rail.kind == Guide::Kind::kStraight) {
    const GuideFrame f = guide_frame(rail);  // the free side's normal n = (−u_y, u_x)
    out.x0 += shift * f.uy;
    out.y0 -= shift * f.ux;
    out.x1 += shift * f.uy;
    out.y1 -= shift * f.ux;
  } else {
    out.radius += rail.inside ? shift : -shift;
  }
  return out;
}

// The box rail_cut visits: the rail's (guide_bounds) for every move of it up to kRailCutReach
// roller radii (a straight rail's at both ends of the move; an arc's larger circle), padded by
// `pad` (the samples' spacing: a sample's reach beyond the rail's ends and past the band).
GuideBounds cut_box(const Guide& rail, double pad) {
  const GuideBounds a = guide_bounds(rail);
  const Guide far = rail_moved(rail, kRailCutReach * rail.roller_radius);
  const bool grows = rail.kind == Guide::Kind::kStraight || rail.inside;
  const GuideBounds b = grows ? guide_bounds(far) : a;  // outside: the circle shrinks within a
  return {std::min(a.x_lo, b.x_lo) - pad, std::max(a.x_hi, b.x_hi) + pad,
          std::min(a.y_lo, b.y_lo) - pad, std::max(a.y_hi, b.y_hi) + pad};
}

// The samples of the path rail_cut visits, as `visit(piece, first, last)` (the sample indices
// j in [first, last] of the path's n at arc lengths L j/n, a sample either side more for the
// rounding): of each piece whose box (piece_box) meets `box`, those of a straight span within
// the box (clipped as Liang and Barsky clip a line), of a wrap or a sagging piece all of them.
// The samples outside are nowhere near the rail's contact.
template <class Visit>
void cut_ranges(const BeltPath& path, const GuideBounds& box, int n, Visit&& visit) {
  const double per = n / path.length;  // samples per metre
  for (std::size_t k = 0; k < path.pieces.size(); ++k) {
    const PathPiece& q = path.pieces[k];
    double t0 = 0.0, t1 = 1.0;  // the share of the piece to visit
    if (!q.arc && !q.sag) {
      const double d[2] = {q.x1 - q.x0, q.y1 - q.y0}, o[2] = {q.x0, q.y0};
      const double lo[2] = {box.x_lo, box.y_lo}, hi[2] = {box.x_hi, box.y_hi};
      for (int i = 0; i < 2 && t0 <= t1; ++i) {
        if (d[i] == 0.0) {
          if (!(o[i] >= lo[i] && o[i] <= hi[i])) t1 = -1.0;
          continue;
        }
        const double a = (lo[i] - o[i]) / d[i], b = (hi[i] - o[i]) / d[i];
        t0 = std::max(t0, std::min(a, b));
        t1 = std::min(t1, std::max(a, b));
      }
      if (!(t0 <= t1)) continue;
    } else {
      double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;
      piece_box(q, x0, y0, x1, y1);
      if (!boxes_near(x0, y0, x1, y1, box.x_lo, box.y_lo, box.x_hi, box.y_hi, 0.0)) continue;
    }
    const double from = std::max(std::floor((q.start + t0 * q.length) * per) - 1.0, 0.0);
    const double to = std::min(std::ceil((q.start + t1 * q.length) * per) + 1.0, n - 1.0);
    if (from <= to) visit(k, from, to);
  }
}

// The least s ≥ 0 in none of the open intervals (lo, hi): exact.
double least_clear(std::vector<std::pair<double, double>>& intervals) {
  std::sort(intervals.begin(), intervals.end());
  double s = 0.0;
  for (const auto& [lo, hi] : intervals) {
    if (!(lo < s)) break;  // s lies before this interval and every later one
    s = std::max(s, hi);
  }
  return s;
}

// The longest stretch of [0, length] a `hair` clear of each of `cuts` (sorted): its ends in
// `from`, `to` (to ≤ from: none).
void longest_clear(const std::vector<double>& cuts, double length, double hair, double& from,
                   double& to) {
  from = to = 0.0;
  for (std::size_t k = 0; k <= cuts.size(); ++k) {
    const double a = k == 0 ? 0.0 : cuts[k - 1] + hair;
    const double b = k == cuts.size() ? length : cuts[k] - hair;
    if (b - a > to - from) {
      from = a;
      to = b;
    }
  }
}

}  // namespace

double rail_cut_work(const BeltPath& path, const Guide& rail) {
  if (path.pieces.empty() || !(path.length > 0.0) || !(rail.roller_radius > 0.0)) return 0.0;
  const int n = cut_samples(path, rail);
  double work = 0.0;
  cut_ranges(path, cut_box(rail, path.length / n), n,
             [&](std::size_t, double from, double to) { work += to - from + 1.0; });
  return work;
}

RailCut rail_cut(const BeltPath& path, const Guide& rail) {
  RailCut out;
  if (path.pieces.empty() || !(path.length > 0.0) || !(rail.roller_radius > 0.0)) return out;
  const double r = rail.roller_radius;
  const int n = cut_samples(path, rail);
  const double spacing = path.length / n;
  const GuideFrame frame = guide_frame(rail);
  const bool straight = rail.kind == Guide::Kind::kStraight;
  const double length = straight ? frame.length : rail.end_angle - rail.start_angle;
  // a point of the path lies within a sample's spacing of a sample (along the path); so its place
  // along the rail within that along a straight rail, and round an arc within that at the
  // contact's least distance from its centre (R − r; every point in a contact of the rail moved
  // away is farther): `hair`
  const double inner = rail.radius - r;
  const double hair = straight ? spacing : inner > 0.0 ? spacing / inner : kTwoPi;

  std::vector<double> cuts, touches;                    // along the rail
  std::vector<std::pair<double, double>> clear, touch;  // the moves that cut, that touch
  // the rail moved by s lowers every gap by s and keeps its ends: a point lies in its contact for
  // s in (g − 2r, g) and past its surface for s in (g − 2r, g − r); between two samples the gap
  // takes every value between theirs (to the path's curvature over a spacing, µm), so each
  // stretch between neighbouring samples with either between the rail's ends adds the intervals
  // of both gaps' range (a stretch across an end: at most a spacing's gap more than the least)
  auto moves = [&](double lo, double hi) {
    if (hi > 0.0) touch.emplace_back(lo - 2.0 * r, hi);
    if (hi - r > 0.0) clear.emplace_back(lo - 2.0 * r, hi - r);
  };
  cut_ranges(path, cut_box(rail, spacing), n, [&](std::size_t, double from, double to) {
    double last_gap = NAN;
    bool last_between = false;
    for (double j = from; j <= to; ++j) {
      const PathPoint p = path_point(path, path.length * j / n);
      const GuideSpot at = guide_spot(rail, frame, p.x, p.y);
      const double g = at.gap;
      if (at.between || last_between)
        moves(j > from ? std::min(g, last_gap) : g, j > from ? std::max(g, last_gap) : g);
      last_gap = g;
      last_between = at.between;
      if (!at.between || !(g < 2.0 * r) || !(g > 0.0)) continue;
      touches.push_back(at.along);
      if (!(g > r)) continue;
      cuts.push_back(at.along);
      if (!(g > out.depth)) continue;
      const PathPiece& q = path.pieces[p.piece];
      out.piece = q.arc ? "the chain on " + wheel_name(q.wheel)
                        : "the span " + wheel_name(q.wheel) + " -> " + wheel_name(q.next);
      out.depth = g;
      out.x = p.x;
      out.y = p.y;
      out.along = at.along;
    }
  });
  if (cuts.empty()) return out;
  // the longest part over no cut, and over no contact: between two samples (or one and an end),
  // a hair inside them (a cut between the samples lies up to a hair beyond them)
  std::sort(cuts.begin(), cuts.end());
  std::sort(touches.begin(), touches.end());
  double from = 0.0, to = 0.0;
  longest_clear(cuts, length, hair, from, to);
  if (to > from) {
    out.clear_from = from;
    out.clear_to = to;
  }
  longest_clear(touches, length, hair, from, to);
  if (to > from) {
    out.touch_from = from;
    out.touch_to = to;
  }
  // the least moves, within a roller's diameter and two (an arc kept larger than the roller)
  auto within = [&](double shift, double most) {
    return shift <= most * r && (straight || rail_moved(rail, shift).radius > r);
  };
  // (a nanometre's hair beyond the interval's open end, for the moved rail's rounding)
  const double shift = least_clear(clear) + 1e-9, touching = least_clear(touch) + 1e-9;
  if (within(shift, 2.0)) out.shift = shift;
  if (within(touching, kRailCutReach)) out.touching = touching;
  return out;
}

// The square ends (layout.hpp): every guide's two ends found once and matched in x order,
// O(G log G + matches); then each end's segment, from the roller line's point (the surface's end
// plus r n, where a roller touching the end has its centre) to r behind the surface (g from 0 to
// 2r, counted short of the face's reach, square_end_reach), against the chords between the path's
// samples near it (cut_ranges over the segment's box padded by a sample's spacing: a chord crossing
// it has an end within that of it), a chord counted only where it runs into the rail; a roller
// leaving a square end sheds its force at once instead, which the conveyor example's lower rail
// does at its exit end 0.31 mm deep.
std::vector<SquareEnd> square_ends(const BeltPath& path, const std::vector<Guide>& guides,
                                   const std::vector<std::size_t>& rails) {
  std::vector<SquareEnd> ends;
  // each end's surface point, its free side's unit normal and the rail's direction into it
  std::vector<std::array<double, 6>> at;
  auto end_of = [](const Guide& g, bool start) {
    if (g.kind == Guide::Kind::kStraight) {
      const GuideFrame f = guide_frame(g);
      const double in = start ? 1.0 : -1.0;
      return std::array<double, 6>{
          start ? g.x0 : g.x1, start ? g.y0 : g.y1, -f.uy, f.ux, in * f.ux, in * f.uy};
    }
    const double a = start ? g.start_angle : g.end_angle;
    const double c = std::cos(a), s = std::sin(a), sgn = g.inside ? -1.0 : 1.0;
    const double in = start ? 1.0 : -1.0;  // counter-clockwise from start_angle
    return std::array<double, 6>{
        g.centre_x + g.radius * c, g.centre_y + g.radius * s, sgn * c, sgn * s, -in * s, in * c};
  };
  // every guide's two ends once (2 g its start, 2 g + 1 its end), in x order
  std::vector<std::array<double, 6>> all(2 * guides.size());
  for (std::size_t g = 0; g < guides.size(); ++g) {
    all[2 * g] = end_of(guides[g], true);
    all[2 * g + 1] = end_of(guides[g], false);
  }
  std::vector<std::size_t> by_x;  // the finite ones (a strict order)
  for (std::size_t j = 0; j < all.size(); ++j)
    if (std::isfinite(all[j][0]) && std::isfinite(all[j][1])) by_x.push_back(j);
  std::sort(by_x.begin(), by_x.end(), [&](std::size_t a, std::size_t b) {
    return all[a][0] < all[b][0] || (all[a][0] == all[b][0] && a < b);
  });
  for (std::size_t k = 0; k < rails.size(); ++k) {
    const double eps = guides[rails[k]].contact_smoothing;
    for (const bool start : {true, false}) {
      const std::size_t self = 2 * rails[k] + (start ? 0 : 1);
      const std::array<double, 6>& e = all[self];
      bool joined = false;
      auto o = std::lower_bound(by_x.begin(), by_x.end(), e[0] - eps,
                                [&](std::size_t j, double x) { return all[j][0] < x; });
      // the rail's own other end closes it only as a ring (an arc sweeping more than a half
      // turn): a rail shorter than ε is a sliver with two square ends, not a closed rail
      const Guide& g = guides[rails[k]];
      const bool ring = g.kind != Guide::Kind::kStraight && g.end_angle - g.start_angle > kPi;
      // how deep the joined guides' faces cover this one's: a guide joined tangentially (the same
      // free side's normal, running on beyond the end) shares the face's line and covers it to
      // its reach (an arc with the rollers outside: to its centre); any other join, all of it
      double cover = 0.0;
      std::size_t under = SIZE_MAX;
      for (; o != by_x.end() && all[*o][0] <= e[0] + eps; ++o) {
        if (*o == self || (!ring && *o == (self ^ 1)) ||
            !(std::hypot(all[*o][0] - e[0], all[*o][1] - e[1]) <= eps))
          continue;
        joined = true;
        const std::array<double, 6>& j = all[*o];
        const bool tangent =
            j[2] * e[2] + j[3] * e[3] > 1.0 - 1e-9 && j[4] * e[4] + j[5] * e[5] < -(1.0 - 1e-9);
        const double reach = tangent ? square_end_reach(guides[*o / 2]) : INFINITY;
        if (reach > cover) {
          cover = reach;
          under = *o / 2;
        }
      }
      if (joined && !(cover < square_end_reach(g))) continue;
      ends.push_back({k, start, e[0], e[1], 0.0, e[2], e[3], e[4], e[5], joined ? cover : 0.0,
                      joined ? under : SIZE_MAX});
      at.push_back(e);
    }
  }
  if (ends.empty() || path.pieces.empty() || !(path.length > 0.0)) return ends;
  for (std::size_t k = 0; k < ends.size(); ++k) {
    const Guide& rail = guides[rails[ends[k].rail]];
    const double rr = rail.roller_radius;
    if (!(rr > 0.0)) continue;
    const double reach = square_end_reach(rail) / (2.0 * rr);  // of the segment, off from there
    const double square = ends[k].from / (2.0 * rr);           // square from there on
    const int n = cut_samples(path, rail);
    const double pad = path.length / n;
    const auto& e = at[k];
    // the segment A + t d, t in [0, 1]: A the roller line's point (g = 0), d 2r along −n
    const double ax = e[0] + rr * e[2], ay = e[1] + rr * e[3];
    const double dx = -2.0 * rr * e[2], dy = -2.0 * rr * e[3];
    const GuideBounds box{std::min(ax, ax + dx) - pad, std::max(ax, ax + dx) + pad,
                          std::min(ay, ay + dy) - pad, std::max(ay, ay + dy) + pad};
    auto sample = [&](double j) { return path_point(path, path.length * j / n); };
    cut_ranges(path, box, n, [&](std::size_t, double from, double to) {
      // the chords from the sample before `from` to the one after `to` (round the closed path)
      PathPoint p = sample(from > 0.0 ? from - 1.0 : n - 1.0);
      for (double j = from; j <= to + 1.0; ++j) {
        const PathPoint q = sample(j < n ? j : j - n);
        const double cx = q.x - p.x, cy = q.y - p.y;
        const double qx = p.x - ax, qy = p.y - ay;
        p = q;
        const double den = cx * dy - cy * dx;
        if (den == 0.0) continue;  // parallel: it meets the normal at no single depth
        // A + t d = P + u c
        const double t = (qy * cx - qx * cy) / den;
        const double u = (qy * dx - qx * dy) / den;
        if (!(t >= square && t < reach && u >= 0.0 && u <= 1.0)) continue;
        if (cx * e[4] + cy * e[5] < 0.0) continue;  // leaving the rail there
        ends[k].depth = std::max(ends[k].depth, 2.0 * rr * t);
      }
    });
  }
  return ends;
}

// The face's reach (layout.hpp): the contact is off at g >= 2r (guide_contact); on an arc with the
// rollers outside the face passes the centre at g = ρ + r, past which it lies on the opposite
// radius, outside the sweep, where the arc has no contact.
double square_end_reach(const Guide& rail) {
  const double most = 2.0 * rail.roller_radius;
  const bool outside = rail.kind == Guide::Kind::kArc && !rail.inside;
  return outside ? std::min(most, rail.radius + rail.roller_radius) : most;
}

// The strike (layout.hpp): each end's roller-line point A = the surface's end + r n; a node's
// move P0 -> P1 crosses the end's face (the line through A along n) into the rail where its
// coordinate along the rail into it, (P - A)·t, goes from <= 0 to > 0; its g there is
// -(P - A)·n at the crossing, interpolated along the move. O(ends × nodes), run once, when a step
// has failed.
std::optional<EndStrike> square_end_strike(const std::vector<SquareEnd>& ends,
                                           const std::vector<Guide>& guides,
                                           const std::vector<std::size_t>& rails,
                                           std::span<const double> x, std::span<const double> y,
                                           std::span<const double> vx, std::span<const double> vy,
                                           double h) {
  std::optional<EndStrike> out;
  const std::size_t n = std::min({x.size(), y.size(), vx.size(), vy.size()});
  for (std::size_t k = 0; k < ends.size(); ++k) {
    const SquareEnd& e = ends[k];
    if (e.rail >= rails.size() || rails[e.rail] >= guides.size()) continue;
    const Guide& rail = guides[rails[e.rail]];
    const double r = rail.roller_radius, eps = rail.contact_smoothing;
    const double reach = square_end_reach(rail);
    const double ax = e.x + r * e.nx, ay = e.y + r * e.ny;
    for (std::size_t i = 0; i < n; ++i) {
      const double px = x[i] - ax, py = y[i] - ay;
      const double mx = h * vx[i], my = h * vy[i];
      const double a0 = px * e.tx + py * e.ty, a1 = a0 + mx * e.tx + my * e.ty;
      if (!(a0 <= 0.0 && a1 > 0.0)) continue;  // (a NaN fails too)
      const double f = -a0 / (a1 - a0);
      const double g = -((px + f * mx) * e.nx + (py + f * my) * e.ny);
      if (!(g > std::max(eps, e.from) && g < reach)) continue;
      if (!out || g > out->depth) out = EndStrike{k, i, g};
    }
  }
  return out;
}

// A lead-in's far end (layout.hpp): the roller on the far end's face, d = R + r − g from the arc's
// centre at α from the end's normal, lies d cos α along that normal from the centre, which is R
// behind the rail's surface: (R + r) − d cos α below the rail's roller line. A path parallel to the
// end's tangent at that depth G meets the arc's roller line (radius R + r) where cos θ = (R + r −
// G)/(R + r), within the sweep (θ <= α) exactly when (R + r)(1 − cos α) >= G.
double lead_in_rail_depth(double radius, double angle, double roller, double g) {
  return radius + roller - (radius + roller - g) * std::cos(angle);
}
double lead_in_clear_radius(double angle, double roller, double depth) {
  return depth / (1.0 - std::cos(angle)) - roller;
}
double lead_in_clear_angle(double radius, double roller, double depth) {
  const double c = 1.0 - depth / (radius + roller);
  return c >= 0.0 ? std::acos(c) : NAN;
}

// A parallel roller's strike (layout.hpp): G − (R + r)(1 − cos α) = g cos α, so the clearance's
// radius at α exceeds R by g cos α / (1 − cos α); counted from a billionth of R on (cos of a
// quarter turn in doubles is 6e-17, not 0).
bool lead_in_parallel_strike(double radius, double angle, double roller, double g) {
  const double least =
      lead_in_clear_radius(angle, roller, lead_in_rail_depth(radius, angle, roller, g));
  return least > radius * (1.0 + 1e-9);
}

std::vector<std::size_t> sagging_spans(const BeltPath& path) {
  std::vector<std::size_t> back, out;
  for (const PathPiece& q : path.pieces)
    if (q.arc && q.sense < 0.0) back.push_back(q.wheel);
  auto on_back = [&back](std::size_t w) {
    return std::find(back.begin(), back.end(), w) != back.end();
  };
  for (std::size_t k = 0; k < path.pieces.size(); ++k) {
    const PathPiece& q = path.pieces[k];
    if (!q.arc && q.length > 0.0 && !on_back(q.wheel) && !on_back(q.next)) out.push_back(k);
  }
  return out;
}

namespace {

// `lay_one(path, k, share)` for every span k of `pieces` in turn, span k's share of `extra` in
// proportion to its chord (one span: the whole extra, exactly); empty where a span's lay is.
template <class LayOne>
BeltPath lay_shares(const BeltPath& path, const std::vector<std::size_t>& pieces, double extra,
                    LayOne lay_one) {
  const double total = span_chords(path, pieces);
  if (!(total > 0.0)) return BeltPath{};
  BeltPath out = path;
  for (const std::size_t k : pieces) {
    out = lay_one(out, k, pieces.size() == 1 ? extra : extra * path.pieces[k].length / total);
    if (out.pieces.empty()) return out;
  }
  return out;
}

}  // namespace

BeltPath sag_spans(const BeltPath& path, const std::vector<std::size_t>& pieces, double extra) {
  return lay_shares(path, pieces, extra, [](const BeltPath& p, std::size_t k, double share) {
    return sag_span(p, k, share);
  });
}

LoopPlacement place_slack_loop(const BeltPath& path, const std::vector<Circle>& circles,
                               const std::vector<int>& teeth, int nodes, double pitch,
                               BeltPath& laid) {
  const std::size_t span = slack_span(path);
  if (span >= path.pieces.size()) {
    laid = BeltPath{};
    return {};
  }
  return place_slack_loop(path, circles, teeth, nodes, pitch, laid, {span});
}

namespace {

// The tangent lay of a catenary span (`tangent_span`): its slope parameters t0, t1 where it leaves
// wheel 0 and meets wheel 1, and its parameter a. NAN when not laid.
struct TangentCatenary {
  double a = NAN, t0 = NAN, t1 = NAN;
};

// A catenary of parameter a touching two circles (centres d = (dx, dy) apart, radii r0, r1), both
// on its upper side (the left of its travel towards +x), at the slope parameters t0 (circle 0)
// and t1 (circle 1): the point of slope sinh t is c + r (tanh t, −1/cosh t) on each, and the
// catenary from one to the other rises a (t1 − t0) along x and a (cosh t1 − cosh t0) along y, so
//   x:  a (t1 − t0) = dx + r1 tanh t1 − r0 tanh t0,
//   y:  a (cosh t1 − cosh t0) = dy − r1 / cosh t1 + r0 / cosh t0.
// `a` from x; returns y's residual (NAN where a is not positive).
double tangency_residual(double t0, double t1, double dx, double dy, double r0, double r1,
                         double& a) {
  a = (dx + r1 * std::tanh(t1) - r0 * std::tanh(t0)) / (t1 - t0);
  if (!(a > 0.0) || !std::isfinite(a)) return NAN;
  return a * (std::cosh(t1) - std::cosh(t0)) - dy + r1 / std::cosh(t1) - r0 / std::cosh(t0);
}

// The steps of the tangent lay's bracketing scans: t_c ± kTangentStep · 2^(k/4), k = 0 .. up to
// kTangentSteps (an offset of 1e5: in practice a scan ends before, where cosh overflows, at an
// offset of about 710, k ≈ 91, through its non-finite return; a slope sinh 40 = 1e17 is already
// steeper than any path of metres takes). Two roots within one step are not told apart: the
// least-sag root is the least within the scan's resolution.
constexpr double kTangentStep = 1e-4;
constexpr int kTangentSteps = 120;
double tangent_offset(int k) { return kTangentStep * std::exp2(0.25 * k); }

// The catenary tangent to both circles leaving circle 0 at the slope parameter t0 (< tc, the
// common tangent's): t1 the first root of the y residual above tc (the least sag: scanned up
// from tc in the steps above, then bisected to the last bit); NAN when none.
TangentCatenary tangent_from(double t0, double tc, double dx, double dy, double r0, double r1) {
  TangentCatenary out;
  double a = NAN;
  double lo = tc, at_lo = tangency_residual(t0, tc, dx, dy, r0, r1, a);
  if (!std::isfinite(at_lo)) return out;
  for (int k = 0; k <= kTangentSteps; ++k) {
    const double hi = tc + tangent_offset(k);
    const double at_hi = tangency_residual(t0, hi, dx, dy, r0, r1, a);
    if (!std::isfinite(at_hi)) return out;
    if ((at_lo > 0.0) != (at_hi > 0.0)) {
      double l = lo, h = hi;
      for (int it = 0; it < 200; ++it) {
        const double mid = 0.5 * (l + h);
        if (!(mid > l && mid < h)) break;
        const double g = tangency_residual(t0, mid, dx, dy, r0, r1, a);
        if (!std::isfinite(g)) return out;
        ((g > 0.0) == (at_lo > 0.0) ? l : h) = mid;
      }
      out.t0 = t0;
      out.t1 = 0.5 * (l + h);
      tangency_residual(t0, out.t1, dx, dy, r0, r1, out.a);
      return out;
    }
    lo = hi;
    at_lo = at_hi;
  }
  return out;
}

}  // namespace

namespace {

// Whether span `piece` of `path` can be laid tangent to its wheels (`tangent_span`): a straight
// span, not the first piece, between two wraps of its own wheels, both wrapped counter-clockwise
// (a span touching a back-side wheel does not sag), travelling towards +x (its outward side down:
// the catenary hangs below it).
bool tangent_eligible(const BeltPath& path, std::size_t piece) {
  const std::size_t n = path.pieces.size();
  if (piece >= n || piece == 0 || path.pieces[piece].arc || path.pieces[piece].sag) return false;
  const PathPiece& q = path.pieces[piece];
  const PathPiece& before = path.pieces[piece - 1];
  const PathPiece& after = path.pieces[(piece + 1) % n];
  return before.arc && after.arc && !(before.sense < 0.0) && !(after.sense < 0.0) &&
         before.wheel == q.wheel && after.wheel == q.next && q.x1 > q.x0 && q.length > 0.0;
}

}  // namespace

BeltPath tangent_span(const BeltPath& path, std::size_t piece, double extra) {
  BeltPath out = path;
  out.pieces.clear();
  if (!tangent_eligible(path, piece) || !(extra > 0.0)) return out;
  const std::size_t n = path.pieces.size();
  const PathPiece& q = path.pieces[piece];
  const PathPiece& before = path.pieces[piece - 1];
  const PathPiece& after = path.pieces[(piece + 1) % n];
  const double r0 = before.radius, r1 = after.radius;
  const double dx = after.cx - before.cx, dy = after.cy - before.cy;
  const double chord = q.length, theta_c = std::atan2(q.y1 - q.y0, q.x1 - q.x0);
  const double tc = std::asinh(std::tan(theta_c));
  // the length condition: the path's extra over the taut path, the catenary's length less the
  // chord and the two wraps' shortening r0 (θc − θ0) + r1 (θ1 − θc), θ = atan sinh t the slope's
  // angle; it grows as t0 falls from tc (the lay sagging deeper)
  auto extra_of = [&](const TangentCatenary& c) {
    return c.a * (std::sinh(c.t1) - std::sinh(c.t0)) - chord -
           r0 * (theta_c - std::atan(std::sinh(c.t0))) -
           r1 * (std::atan(std::sinh(c.t1)) - theta_c);
  };
  // bracketed by the scan down from tc, then bisected on t0 to the last bit
  double hi = tc, lo = NAN;
  for (int k = 0; k <= kTangentSteps; ++k) {
    const double t0 = tc - tangent_offset(k);
    const TangentCatenary c = tangent_from(t0, tc, dx, dy, r0, r1);
    if (!std::isfinite(c.a)) return out;
    if (extra_of(c) >= extra) {
      lo = t0;
      break;
    }
    hi = t0;
  }
  if (!std::isfinite(lo)) return out;
  TangentCatenary laid;
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (!(mid > lo && mid < hi)) break;
    const TangentCatenary c = tangent_from(mid, tc, dx, dy, r0, r1);
    if (!std::isfinite(c.a)) return out;
    (extra_of(c) >= extra ? lo : hi) = mid;
  }
  laid = tangent_from(lo, tc, dx, dy, r0, r1);
  if (!std::isfinite(laid.a)) return out;
  // the lay's own extra within 1e-9 of the one asked (a jump of the least-sag root is not laid)
  if (!(std::abs(extra_of(laid) - extra) <= 1e-9 * (chord + extra))) return out;
  // the free chain no more curved where it leaves a wheel than the wheel (a cosh² t ≥ r: else it
  // would cut into it) and each wrap kept (the shortening within it)
  const double shrink0 = theta_c - std::atan(std::sinh(laid.t0));
  const double shrink1 = std::atan(std::sinh(laid.t1)) - theta_c;
  const double wrap0 = before.to - before.from, wrap1 = after.to - after.from;
  if (!(laid.a * std::cosh(laid.t0) * std::cosh(laid.t0) >= r0) ||
      !(laid.a * std::cosh(laid.t1) * std::cosh(laid.t1) >= r1) || !(shrink0 >= 0.0) ||
      !(shrink1 >= 0.0) || !(shrink0 < wrap0) || !(shrink1 < wrap1))
    return out;
  out.pieces = path.pieces;
  PathPiece& w0 = out.pieces[piece - 1];
  PathPiece& span = out.pieces[piece];
  PathPiece& w1 = out.pieces[(piece + 1) % n];
  w0.to -= shrink0;
  w0.x1 = w0.cx + r0 * std::cos(w0.to);
  w0.y1 = w0.cy + r0 * std::sin(w0.to);
  w0.length = r0 * (w0.to - w0.from);
  w1.from += shrink1;
  w1.x0 = w1.cx + r1 * std::cos(w1.from);
  w1.y0 = w1.cy + r1 * std::sin(w1.from);
  w1.length = r1 * (w1.to - w1.from);
  span.x0 = w0.x1;
  span.y0 = w0.y1;
  span.x1 = w1.x0;
  span.y1 = w1.y0;
  span.sag = true;
  span.catenary = true;
  span.hang_a = laid.a;
  span.hang_u = -laid.a * laid.t0;
  span.length = laid.a * (std::sinh(laid.t1) - std::sinh(laid.t0));
  // the curve clear of its own two wheels' pitch circles (it touches them at its ends)
  const int samples = 4096;
  for (int j = 1; j < samples; ++j) {
    const PathPoint p = sag_point(span, span.length * j / samples);
    if (std::hypot(p.x - w0.cx, p.y - w0.cy) < r0 * (1.0 - 1e-9) ||
        std::hypot(p.x - w1.cx, p.y - w1.cy) < r1 * (1.0 - 1e-9)) {
      out.pieces.clear();
      return out;
    }
  }
  return with_starts(std::move(out));
}

BeltPath tangent_spans(const BeltPath& path, const std::vector<std::size_t>& pieces, double extra) {
  // each span's tangent lay depends on its two wheels and its own share alone; laid one after
  // another, a wrap between two slack spans is cut at both ends, the second cut checked against
  // what the first left of it (`tangent_span`: a wrap used up is refused); every span checked
  // first, so that one that can never be laid tangent refuses before any other is solved
  if (pieces.size() > 1)
    for (const std::size_t k : pieces)
      if (!tangent_eligible(path, k)) return BeltPath{};
  return lay_shares(path, pieces, extra, [](const BeltPath& p, std::size_t k, double share) {
    return tangent_span(p, k, share);
  });
}

namespace {

// The slack solve's answer: the extra length e and the arc length of node 0 (0 but where the
// walk from the path's start closes for no e, below).
struct SlackSolve {
  double extra = NAN;
  double start = 0.0;
  bool tangent =
      false;  // laid tangent to both wheels (`tangent_span`), not between the tangent points
};

// `miss` bisected over (lo, hi) to the last bit (`falls`: it is positive at lo), stopping at a
// non-finite miss or once the least |miss| met is at most `enough`: where that least was met.
struct LeastMiss {
  double at = NAN;
  double miss = INFINITY;
};
template <class Miss>
LeastMiss bisect_least(const Miss& miss, double lo, double hi, bool falls, double enough) {
  LeastMiss out;
  for (int it = 0; it < 200 && out.miss > enough; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (!(mid > lo && mid < hi)) break;
    const double g = miss(mid);
    if (!std::isfinite(g)) break;
    if (std::abs(g) < out.miss) {
      out.miss = std::abs(g);
      out.at = mid;
    }
    ((g > 0.0) == falls ? lo : hi) = mid;
  }
  return out;
}

// The phase at which N nodes walked at chord `pitch` close the loop on `sagging`: node 0's arc
// length over the first link from the path's start, scanned in 64 steps and each change of sign
// of the miss bisected; NAN when none closes. The miss is continuous in the phase but where a
// node passes a fold of the path (below, `slack_solve`), where it jumps back up by the span the
// fold skips; between those jumps it falls across every value of that span.
double closing_phase(const BeltPath& sagging, int nodes, double pitch, double tolerance) {
  auto miss = [&](double start) { return walk_miss(sagging, pitch, nodes, start); };
  const double first = next_node(sagging, 0.0, pitch);
  if (!(first > 0.0)) return NAN;
  const int steps = 64;
  double before = 0.0, at_before = miss(0.0);
  for (int j = 1; j <= steps; ++j) {
    const double here = first * j / steps, at_here = miss(here);
    if (std::isfinite(at_before) && std::isfinite(at_here) &&
        (at_before > 0.0) != (at_here > 0.0)) {
      // bisected to the last bit (the miss there a rounding: place_loop's chord solve then
      // moves the chord by no more than that over the walk's N links), then taken when it is
      // within `tolerance`, not a jump
      // (stopping at an exact 0 leaves the least and its place as the full run would)
      const LeastMiss least = bisect_least(miss, before, here, at_before > 0.0, 0.0);
      if (least.miss <= tolerance) return least.at;
    }
    before = here;
    at_before = at_here;
  }
  return NAN;
}

SlackSolve chord_end_solve(const BeltPath& path, const std::vector<std::size_t>& pieces, int nodes,
                           double pitch) {
  const double chain = nodes * pitch;
  if (path.pieces.empty() || nodes < 3 || !(pitch > 0.0) || pieces.empty() ||
      !(chain > path.length))
    return {};
  // the walk's miss at chord `pitch` with the spans sagging by `extra`: the end of node N's walk
  // against the laid path's length
  auto miss = [&](double extra) -> double {
    const BeltPath p = sag_spans(path, pieces, extra);
    if (p.pieces.empty()) return NAN;
    return walk_miss(p, pitch, nodes, 0.0);
  };
  // the most extra the spans take, every share a half circle (sag_span refuses beyond): a secant
  // step past it is pulled back half-way from the last iterate, so that a sag near its half
  // circle is still solved (a step into the refused range stopped the solve before)
  double spans = 0.0;
  for (const std::size_t k : pieces)
    if (k < path.pieces.size()) spans += path.pieces[k].length;
  const double most = (0.5 * kPi - 1.0) * spans * (1.0 - 1e-9);
  const double least = chain - path.length;
  double e0 = least, g0 = miss(e0);
  double e1 = 1.001 * e0 > most && e0 < most ? 0.5 * (e0 + most) : 1.001 * e0;
  double g1 = miss(e1);
  for (int it = 0; it < 60 && std::isfinite(g1) && std::abs(g1) > 1e-13 * chain; ++it) {
    if (g1 == g0 || !std::isfinite(g0)) break;
    double e2 = e1 - g1 * (e1 - e0) / (g1 - g0);
    if (e2 > most && e1 < most) e2 = 0.5 * (e1 + most);
    e0 = e1;
    g0 = g1;
    e1 = e2;
    if (!(e1 > 0.0)) break;
    g1 = miss(e1);
  }
  if (e1 > 0.0 && std::abs(g1) <= 1e-11 * chain) return {e1, 0.0};
  // the secant missed (it cycles where the miss bends sharply, e.g. 344 links on a notched path):
  // bisection between `least`, where the miss is not negative, and the half circle
  double lo = least, hi = most;
  double at_lo = miss(lo), at_hi = miss(hi);
  if (at_hi > 0.0) {
    // the walk overshoots even at the half circle: the catenaries beyond it, up to the longest
    // (a span that cannot hang as one, an upper run: refused as before)
    lo = std::max(least, (0.5 * kPi - 1.0) * spans * (1.0 + 1e-9));
    hi = kCatenaryMostExtra * spans * (1.0 - 1e-9);  // a hair inside, as the half circle
    at_lo = miss(lo);
    if (!std::isfinite(at_lo)) return {INFINITY, 0.0};
    at_hi = miss(hi);
    if (at_hi > 0.0) {
      // the walk from the path's start overshoots even at the longest catenary, but node 0's
      // phase may still close it there (at a fold of the path the miss, over the phase, falls
      // by up to the span the fold skips)
      const double start = closing_phase(sag_spans(path, pieces, hi), nodes, pitch, 1e-11 * chain);
      if (std::isfinite(start)) return {hi, start};
      return {INFINITY, 0.0};
    }
  }
  if (!(at_lo >= 0.0 && at_hi <= 0.0)) return {};
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (!(mid > lo && mid < hi)) {
      // the bracket closed on a jump of the miss over 0: a node there passes a fold of the path
      // (a sloped catenary climbing into its far wheel while the wrap leaves along the chord,
      // the path turning back by more than 90°), where the first point a pitch on leaves the
      // curve just short of the kink for one past it on the wheel. Every rule that picks one
      // such point per node jumps somewhere, so the walk from the path's start closes for no e;
      // node 0's phase is the freedom left: at this e the miss, over the phase, falls across
      // the whole jump, 0 included
      const double start = closing_phase(sag_spans(path, pieces, lo), nodes, pitch, 1e-11 * chain);
      if (std::isfinite(start)) return {lo, start};
      break;
    }
    const double g = miss(mid);
    if (std::abs(g) <= 1e-11 * chain) return {mid, 0.0};
    if (!std::isfinite(g)) break;
    (g > 0.0 ? lo : hi) = mid;
  }
  return {};
}

// The extra e at which N nodes walked at chord `pitch` close the loop on the path with the spans
// `pieces` laid tangent to their wheels (`tangent_spans`): bisection between N p less the
// path's length (the miss not negative: a chord spans at least its pitch of the path) and the
// longest e the tangent lay takes (below), bisected to the last bit and taken when the least miss
// is within 1e-11 of N p; NAN when not found.
SlackSolve tangent_solve(const BeltPath& path, const std::vector<std::size_t>& pieces, int nodes,
                         double pitch) {
  const double spans = span_chords(path, pieces);
  if (!(spans > 0.0)) return {};
  const double chain = nodes * pitch;
  auto miss = [&](double extra) {
    const BeltPath p = tangent_spans(path, pieces, extra);
    return p.pieces.empty() ? NAN : walk_miss(p, pitch, nodes, 0.0);
  };
  double lo = chain - path.length, hi = kCatenaryMostExtra * spans * (1.0 - 1e-9);
  if (!(lo > 0.0 && lo < hi) || !(miss(lo) >= 0.0)) return {};
  // the bracket's upper end: the longest catenary's e where the tangent lay takes it, else (it
  // leaves a wheel more curved than the wheel, or uses a wrap up, short of it: z 11 and 41 at
  // 671 mm and 82.9°) stepped down towards `lo` by 2^(1/4) of the distance until laid, then
  // bisected between that and the step above to the last e laid
  double at_hi = miss(hi);
  if (!std::isfinite(at_hi)) {
    const double top = hi;
    double above = top;
    for (int k = 1; k <= kTangentSteps && !std::isfinite(at_hi); ++k) {  // to 2^-30 of it
      above = hi;
      hi = lo + (top - lo) * std::exp2(-0.25 * k);
      if (!(hi > lo)) return {};
      at_hi = miss(hi);
    }
    if (!std::isfinite(at_hi)) return {};
    for (int it = 0; it < 200 && at_hi > 0.0; ++it) {
      const double mid = 0.5 * (hi + above);
      if (!(mid > hi && mid < above)) break;
      const double g = miss(mid);
      if (std::isfinite(g)) {
        hi = mid;
        at_hi = g;
      } else {
        above = mid;
      }
    }
  }
  if (!(at_hi <= 0.0)) return {};
  // to the last bit (a miss at the tolerance would leave place_loop's chord solve moving the
  // links' chord off the pitch by up to 1e-11 of it), the least miss taken
  const LeastMiss least = bisect_least(miss, lo, hi, true, 1e-15 * chain);
  if (least.miss <= 1e-11 * chain) return {least.at, 0.0, true};
  return {};
}

// The slack solve: between the tangent points (`chord_end_solve`) where that closes on a
// circular arc (up to the half circle: every start laid so before is laid the same), else every
// span tangent to its wheels (`tangent_solve`: a hanging chain meets its wheels
// tangentially, one span's rest shape; with more, the shares in proportion to the chords are a
// start rule, not the rest shape, which puts every free span linked through free wheels on one
// directrix) where that closes, else the answer between the tangent points as
// it is (a catenary, across a fold or at node 0's phase, or refused). `between`, when given, gets
// the answer between the tangent points.
SlackSolve slack_solve(const BeltPath& path, const std::vector<std::size_t>& pieces, int nodes,
                       double pitch, SlackSolve* between = nullptr) {
  const SlackSolve chord = chord_end_solve(path, pieces, nodes, pitch);
  if (between != nullptr) *between = chord;
  if (pieces.empty() || path.pieces.empty()) return chord;
  if (std::isfinite(chord.extra) && chord.start == 0.0) {
    // (the shares in proportion to the chords: every span passes its half circle at one e)
    const BeltPath arc = sag_spans(path, pieces, chord.extra);
    if (!arc.pieces.empty() && !arc.pieces[pieces[0]].catenary) return chord;
  }
  const SlackSolve tangent = tangent_solve(path, pieces, nodes, pitch);
  return std::isfinite(tangent.extra) ? tangent : chord;
}

// The start of N nodes on `sagging` from node 0 at arc length `start`, or an empty placement where
// it leaves a wheel with no roller or a link off the pitch (below).
LoopPlacement lay_slack_loop(const BeltPath& sagging, const std::vector<Circle>& circles,
                             const std::vector<int>& teeth, int nodes, double pitch, double start) {
  // the wheels' seats as on a taut path: place_loop's chord solve lands on `pitch` itself here
  LoopPlacement out = place_loop_from(sagging, circles, teeth, nodes, pitch, start);
  if (out.s.empty()) return out;
  // every wheel with a roller on it (the tangent lay shortens its two wheels' wraps: at (30, −400)
  // mm, z 17 both, 80 links, the driven wheel's to 0.37 of a pitch, none seated on it), the
  // command's own rule for a start (analysis.cpp, slack_starts)
  for (const int w : out.wrapped)
    if (w == 0) return {};
  // every link one pitch (the closing one too), 1e-9 relative: a walk that found no point a
  // pitch on, or a link cut short, is not laid
  for (std::size_t i = 0; i < out.s.size(); ++i) {
    const PathPoint a = path_point(sagging, out.s[i]);
    const PathPoint b = path_point(sagging, out.s[(i + 1) % out.s.size()]);
    if (!(std::abs(std::hypot(b.x - a.x, b.y - a.y) - pitch) <= 1e-9 * pitch)) return {};
  }
  return out;
}

// A start with slack (`place_slack_loop`) and the e of its lay: `solved`'s, or (`solved` a
// tangent lay not laid) `between`'s; `extra` NAN where none is laid.
struct SlackLay {
  LoopPlacement placement;
  double extra = NAN;
};
SlackLay slack_lay(const BeltPath& path, const std::vector<Circle>& circles,
                   const std::vector<int>& teeth, int nodes, double pitch, BeltPath& laid,
                   const std::vector<std::size_t>& pieces, SlackSolve solved,
                   const SlackSolve& between) {
  laid = BeltPath{};
  if (!std::isfinite(solved.extra)) return {};
  if (solved.tangent) {
    const BeltPath sagging = tangent_spans(path, pieces, solved.extra);
    LoopPlacement out = lay_slack_loop(sagging, circles, teeth, nodes, pitch, solved.start);
    if (!out.s.empty()) {
      laid = sagging;
      return {out, solved.extra};
    }
    // the tangent lay not laid (a wheel left with no roller: at (60, −400) mm, z 17 both, 80
    // links, the driven wheel's wrap cut to 0.62 of a pitch): the lay between the tangent points
    // as it is, across its fold or at node 0's phase, laid as before the tangent lay (a = 6.3 mm
    // there), so that no start laid so before is refused
    solved = between;
    if (!std::isfinite(solved.extra)) return {};
  }
  const BeltPath sagging = sag_spans(path, pieces, solved.extra);
  LoopPlacement out = lay_slack_loop(sagging, circles, teeth, nodes, pitch, solved.start);
  if (out.s.empty()) return {out, NAN};
  laid = sagging;
  return {out, solved.extra};
}

}  // namespace

double slack_extra(const BeltPath& path, const std::vector<std::size_t>& pieces, int nodes,
                   double pitch) {
  return slack_solve(path, pieces, nodes, pitch).extra;
}

LoopPlacement place_slack_loop(const BeltPath& path, const std::vector<Circle>& circles,
                               const std::vector<int>& teeth, int nodes, double pitch,
                               BeltPath& laid, const std::vector<std::size_t>& pieces) {
  SlackSolve between;
  const SlackSolve solved = slack_solve(path, pieces, nodes, pitch, &between);
  return slack_lay(path, circles, teeth, nodes, pitch, laid, pieces, solved, between).placement;
}

double laid_slack_extra(const BeltPath& path, const std::vector<Circle>& circles,
                        const std::vector<int>& teeth, int nodes, double pitch,
                        const std::vector<std::size_t>& pieces) {
  SlackSolve between;
  const SlackSolve solved = slack_solve(path, pieces, nodes, pitch, &between);
  BeltPath laid;
  const SlackLay lay = slack_lay(path, circles, teeth, nodes, pitch, laid, pieces, solved, between);
  return lay.placement.s.empty() ? solved.extra : lay.extra;
}

LongestCount longest_count(int lo, int hi, const std::function<bool(int)>& starts, int scan) {
  for (int n = hi; n > lo; --n) {
    if (starts(n)) return {n, true};
    if (hi - n + 1 >= scan) {
      // the rest by bisection: lo + 1 .. n - 1 (a count that starts, not always the most)
      int top = n;  // does not start
      int bottom = lo + 1;
      if (bottom >= top || !starts(bottom)) return {};
      while (top - bottom > 1) {  // bottom starts, top does not
        const int mid = bottom + (top - bottom) / 2;
        (starts(mid) ? bottom : top) = mid;
      }
      return {bottom, false};
    }
  }
  return {};
}

std::string links_that_start_phrase(const LongestCount& longest, int given, int scan) {
  if (longest.links <= 0) return "no count starts so";
  const std::string n = std::to_string(longest.links);
  std::string text = longest.scanned ? "at most " + n + " links start so"
                                     : n + " links start so (found by bisection after the " +
                                           std::to_string(scan) +
                                           " counts below the limit failed; a larger count may "
                                           "start)";
  if (given > 0 && given <= longest.links)
    text += "; no start was found at exactly " + std::to_string(given) +
            " links (the counts that start are not an interval: at that count the walk at "
            "exactly one pitch closes nowhere, or leaves a wrapped roller beyond its seat's "
            "clearance)";
  return text;
}

State loop_state(const BeltPath& path, const std::vector<Circle>& circles,
                 const LoopPlacement& placement, double chain_speed) {
  State st(placement.s.size(), circles.size());
  for (std::size_t i = 0; i < placement.s.size(); ++i) {
    const PathPoint p = path_point(path, placement.s[i]);
    st.x[i] = p.x;
    st.y[i] = p.y;
    st.vx[i] = chain_speed * p.tx;
    st.vy[i] = chain_speed * p.ty;
  }
  for (std::size_t w = 0; w < circles.size(); ++w) {
    st.angle[w] = placement.angle[w];
    // a wheel on the back of the chain turns the other way (clockwise)
    st.speed[w] = (circles[w].back ? -chain_speed : chain_speed) / circles[w].radius;
  }
  return st;
}

}  // namespace catena::dynamics
