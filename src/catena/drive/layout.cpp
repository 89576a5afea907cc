// Two-sprocket layout: textbook link count and centre distance; the exact polygon wrap.
#include "catena/drive/layout.hpp"

#include <algorithm>
#include <array>
#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/core/progress.hpp"

namespace catena::drive {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kPhaseSamples = 32;   // driven-sprocket phases sampled per tooth to bracket a root
constexpr int kDriverSamples = 16;  // driver phases sampled per tooth for the least/largest a

struct Point {
  double x, y;
};

Point operator-(Point a, Point b) { return {a.x - b.x, a.y - b.y}; }
double cross(Point o, Point a, Point b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}
double distance(Point a, Point b) { return std::hypot(a.x - b.x, a.y - b.y); }

struct Polygon {
  Point centre;
  double radius, phase;
  int teeth;
  Point operator[](int i) const {
    const int k = ((i % teeth) + teeth) % teeth;
    const double t = phase + 2 * kPi * k / teeth;
    return {centre.x + radius * std::cos(t), centre.y + radius * std::sin(t)};
  }
};

int wrap_index(int i, int n) { return ((i % n) + n) % n; }

double dot(Point v, Point u) { return v.x * u.x + v.y * u.y; }

// A polygon's vertices as the bridge search asks for them, each one's sine and cosine taken once:
// the search touches a few neighbouring vertices, each several times. A direct-mapped table of
// the last ones computed (keyed by the index modulo its size; a clash computes again).
class Vertices {
 public:
  explicit Vertices(const Polygon& p) : p_(p) { keys_.fill(-1); }
  Point operator[](int i) {
    const int k = wrap_index(i, p_.teeth);
    const auto slot = static_cast<std::size_t>(k) % kSlots;
    if (keys_[slot] != k) {
      keys_[slot] = k;
      points_[slot] = p_[k];
    }
    return points_[slot];
  }

 private:
  static constexpr std::size_t kSlots = 16;
  const Polygon& p_;
  std::array<int, kSlots> keys_{};
  std::array<Point, kSlots> points_{};
};

// The vertex extreme in the direction `out`: of the largest dot product, the first (lowest
// index) of equal ones. Every vertex scanned.
int extreme_by_scan(const Polygon& p, Point out) {
  int best = 0;
  double best_dot = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < p.teeth; ++i) {
    const double d = dot(p[i], out);
    if (d > best_dot) {
      best_dot = d;
      best = i;
    }
  }
  return best;
}

// The same vertex from the three nearest the direction of `out`. The vertex nearest it in angle,
// n, is δ ≤ π/z away, its neighbour on the other side of `out`, n', 2π/z − δ; every other vertex
// is at least 2π/z + δ away, so its dot product is below n's by at least
// g = 2 r |out| sin²(π/z). The rounding of the computed dot products (the phase's, the centre's
// and the products' few ulps) is far below g/2 where `gap > noise` below (noise overstates it
// more than ten times), so no vertex but n' can equal or pass n as computed. The estimate
// k = round((atan2(out) − phase) z/2π) is n or, at a near tie, n': k ± 1 holds both. Among those
// the first largest is the scan's, ties included (with two vertices k ± 1 is both, and one has
// no gap). Where the arithmetic cannot be bounded so (non-finite or degenerate input, a huge
// phase or centre) the scan decides.
int extreme(const Polygon& p, Point out, Vertices& v) {
  constexpr int kReach = 1;
  const double z = p.teeth;
  const double gap = 2 * std::pow(std::sin(kPi / z), 2);
  const double centre = std::abs(p.centre.x) + std::abs(p.centre.y);
  const double noise = 1e-14 * (std::abs(p.phase) + 2 * kPi + 1 + centre / p.radius);
  const double size = std::abs(out.x) + std::abs(out.y);
  const double turns = (std::atan2(out.y, out.x) - p.phase) * z / (2 * kPi);
  // (a non-finite phase or centre or a NaN radius fails the first test, an infinite radius or a
  // non-finite normal the second, a radius ≤ 0 or a zero normal the last)
  if (!(gap > noise) || !((centre + p.radius) * size < 1e300) || !(p.radius * size > 1e-200))
    return extreme_by_scan(p, out);
  // |turns| < 2⁵³ here (gap > noise bounds the phase), so the rounding and fmod are exact
  double k0 = std::fmod(std::round(turns), z);
  if (k0 < 0) k0 += z;
  const int k = static_cast<int>(k0);
  int best = -1;
  double best_dot = 0;
  for (int j = -kReach; j <= kReach; ++j) {
    const int i = wrap_index(k + j, p.teeth);
    const double d = dot(v[i], out);
    if (best < 0 || d > best_dot || (d == best_dot && i < best)) {
      best = i;
      best_dot = d;
    }
  }
  return best;
}

// The bridge of the hull of two disjoint convex polygons from A to B with both polygons on its
// left: its end vertices' indices and points. From the vertices extreme in the bridge's outward
// normal, each end steps to a neighbour that lies more than the tolerance outside the line.
struct Bridge {
  int ia, ib;
  Point pa, pb;
};

Bridge bridge(const Polygon& a, const Polygon& b) {
  const Point d = b.centre - a.centre;
  const Point out{d.y, -d.x};  // right normal: the bridge is extreme in this direction
  Vertices va(a), vb(b);
  int ia = extreme(a, out, va), ib = extreme(b, out, vb);
  const double scale = std::pow(std::hypot(d.x, d.y) + a.radius + b.radius, 2);
  const double tol = 1e-14 * scale;
  for (int guard = 0; guard < 4 * (a.teeth + b.teeth); ++guard) {
    bool changed = false;
    for (int step : {1, -1}) {
      if (cross(va[ia], vb[ib], va[ia + step]) < -tol) {
        ia = wrap_index(ia + step, a.teeth);
        changed = true;
      }
      if (cross(va[ia], vb[ib], vb[ib + step]) < -tol) {
        ib = wrap_index(ib + step, b.teeth);
        changed = true;
      }
    }
    if (!changed) break;
  }
  return {ia, ib, va[ia], vb[ib]};
}

double perimeter(const PolygonWrap& w, double pitch) {
  return (w.wrap1 + w.wrap2) * pitch + w.upper_length + w.lower_length;
}

// The upper span's distance from a whole number of pitches, in pitches: in [−1/2, 1/2]. Where the
// hull's end pin changes, the span grows or shrinks by exactly one pitch, so this is continuous
// there; it jumps only where the span is half a pitch off.
double upper_offset(const PolygonWrap& w, double pitch) {
  const double n = w.upper_length / pitch;
  return n - std::round(n);
}

// Input validation of the public functions: each check appends the issues of its arguments,
// `refuse` throws them all at once. The public functions validate at entry, then call the
// unchecked functions below them, which call each other (the solvers call them many times).

void refuse(const char* function, const std::vector<Issue>& issues) {
  if (issues.empty()) return;
  std::string text =
      std::string(function) + ": " + std::to_string(issues.size()) + " invalid argument(s):";
  for (const Issue& issue : issues) text += "\n  " + to_string(issue);
  throw std::invalid_argument(text);
}

bool check_pitch(std::vector<Issue>& issues, double pitch) {
  if (pitch >= kMinPitch && pitch <= kMaxPitch) return true;
  issues.push_back({"pitch", check::format_si(pitch, "m"), "1e-90 m to 1e+90 m"});
  return false;
}

bool check_teeth(std::vector<Issue>& issues, const char* name, int z) {
  if (z >= kMinTeeth && z <= kMaxTeeth) return true;
  issues.push_back({name, std::to_string(z),
                    std::to_string(kMinTeeth) + " to " + std::to_string(kMaxTeeth) + " teeth"});
  return false;
}

// The pitch and both tooth counts; whether all three are valid (the pitch radii computable).
bool check_sprockets(std::vector<Issue>& issues, double pitch, int z1, int z2) {
  const bool p = check_pitch(issues, pitch);
  const bool t1 = check_teeth(issues, "z1", z1);
  const bool t2 = check_teeth(issues, "z2", z2);
  return p && t1 && t2;
}

double radius_of(double pitch, int teeth) { return pitch / (2 * std::sin(kPi / teeth)); }

double angle_of(double pitch, int z1, int z2, double a) {
  return std::asin((radius_of(pitch, z2) - radius_of(pitch, z1)) / a);
}

// A centre distance at which the pitch circles are apart (when the sprockets are valid; else
// only its own range is known).
void check_apart(std::vector<Issue>& issues, const char* name, double a, bool sprockets,
                 double pitch, int z1, int z2) {
  if (sprockets) {
    const double touch = radius_of(pitch, z1) + radius_of(pitch, z2);
    if (!(a > touch && a <= kMaxCenterDistance))
      issues.push_back({name, check::format_si(a, "m"),
                        "more than r1 + r2 = " + check::format_si(touch, "m") +
                            " (the pitch circles apart), at most 1e+100 m"});
  } else if (!(a > 0 && a <= kMaxCenterDistance)) {
    issues.push_back({name, check::format_si(a, "m"),
                      "more than r1 + r2 (the pitch circles apart), at most 1e+100 m"});
  }
}

void check_links(std::vector<Issue>& issues, int links) {
  if (!(links >= kMinLinks && links <= kMaxLinks))
    issues.push_back({"links", std::to_string(links),
                      std::to_string(kMinLinks) + " to " + std::to_string(kMaxLinks) + " links"});
}

void check_tension(std::vector<Issue>& issues, const char* name, double value) {
  if (!(std::abs(value) <= kMaxTension))
    issues.push_back({name, check::format_si(value, "N"), "a finite value within ±1e+307 N"});
}

PolygonWrap hull_of(double pitch, int z1, int z2, double a, double phase1, double phase2) {
  const Polygon p1{{0, 0}, radius_of(pitch, z1), phase1, z1};
  const Polygon p2{{a, 0}, radius_of(pitch, z2), phase2, z2};
  PolygonWrap w;
  w.center_distance = a;
  w.phase1 = phase1;
  w.phase2 = phase2;
  const Bridge lower = bridge(p1, p2);  // left to right
  const Bridge upper = bridge(p2, p1);  // right to left
  w.seat1_out = lower.ia;
  w.seat2_in = lower.ib;
  w.seat2_out = upper.ia;
  w.seat1_in = upper.ib;
  w.wrap1 = wrap_index(w.seat1_out - w.seat1_in, z1);
  w.wrap2 = wrap_index(w.seat2_out - w.seat2_in, z2);
  w.lower_length = distance(lower.pa, lower.pb);
  w.upper_length = distance(upper.pa, upper.pb);
  return w;
}

}  // namespace

double pitch_radius(double pitch, int teeth) {
  std::vector<Issue> issues;
  check_pitch(issues, pitch);
  check_teeth(issues, "teeth", teeth);
  refuse("pitch_radius", issues);
  return radius_of(pitch, teeth);
}

// links_for's least centre distance, in pitches (Δ²p/a then stays finite, at most 2.5e13)
constexpr double kLeastDistance = 1e-9;

double links_for(double pitch, int z1, int z2, double a) {
  std::vector<Issue> issues;
  const bool sprockets = check_sprockets(issues, pitch, z1, z2);
  if (!(a <= kMaxCenterDistance && (sprockets ? a >= kLeastDistance * pitch : a > 0)))
    issues.push_back(
        {"center_distance", check::format_si(a, "m"),
         "at least 1e-9 pitch" +
             (sprockets ? " = " + check::format_si(kLeastDistance * pitch, "m") : std::string()) +
             ", at most 1e+100 m"});
  refuse("links_for", issues);
  const double delta = (z2 - z1) / (2 * kPi);
  return 2 * a / pitch + (z1 + z2) / 2.0 + delta * delta * pitch / a;
}

int round_up_even(double links) {
  constexpr double kMax = std::numeric_limits<int>::max() - 1;  // the largest even int
  // (a count within 1e-9 of a whole one is that one: 1e-9 and less would round to 0)
  if (!(links > 1e-9 && links <= kMax))
    refuse("round_up_even",
           {{"links", check::format_si(links, ""), "more than 1e-9, at most 2147483646"}});
  const double up = std::ceil(links - 1e-9);  // a whole count computed a few ulps high stays
  const auto n = static_cast<std::int64_t>(up);
  return static_cast<int>(n % 2 == 0 ? n : n + 1);
}

double center_distance_formula(double pitch, int z1, int z2, double links) {
  std::vector<Issue> issues;
  check_sprockets(issues, pitch, z1, z2);
  if (!(links > 0 && links <= 1e100))
    issues.push_back({"links", check::format_si(links, ""), "more than 0, at most 1e+100"});
  refuse("center_distance_formula", issues);
  const double sigma = z1 + z2, delta = (z2 - z1) / (2 * kPi);
  const double m = links - sigma / 2;
  const double disc = m * m - 8 * delta * delta;
  if (!(disc >= 0) || !(m > 0)) return NAN;
  return pitch / 4 * (m + std::sqrt(disc));
}

PolygonWrap polygon_hull(double pitch, int z1, int z2, double a, double phase1, double phase2) {
  std::vector<Issue> issues;
  const bool sprockets = check_sprockets(issues, pitch, z1, z2);
  check_apart(issues, "center_distance", a, sprockets, pitch, z1, z2);
  check::finite(issues, "phase1", phase1, "rad");
  check::finite(issues, "phase2", phase2, "rad");
  refuse("polygon_hull", issues);
  return hull_of(pitch, z1, z2, a, phase1, phase2);
}

std::pair<int, int> hull_bridge(const PitchPolygon& a, const PitchPolygon& b) {
  // Lengths bounded so that the walk's tolerance 1e-14 (|b − a| + r_a + r_b)² and the dot and
  // cross products of coordinates stay finite and normal (no overflow, no digits lost to
  // underflow).
  constexpr double kMaxLength = 1e100, kMinRadius = 1e-100;  // [m]
  // The walk tells a vertex's neighbours from the bridge's line by their offset, about
  // 2π² r |b − a| / z² in the cross product, against its tolerance: at 10⁶ teeth the offset is
  // about 250 times the tolerance with the centres a diameter apart, only twice it with them a
  // thousand radii apart. Beyond, the walk could not tell the polygon from its circle.
  constexpr int kMaxBridgeTeeth = 1000000;
  std::vector<Issue> issues;
  bool placed = true;  // every centre coordinate and radius in range
  auto polygon = [&](const std::string& name, const PitchPolygon& p) {
    for (const auto& [field, value] : {std::pair{".x", p.x}, std::pair{".y", p.y}})
      if (!(std::abs(value) <= kMaxLength)) {
        placed = false;
        issues.push_back(
            {name + field, check::format_si(value, "m"), "a finite value within ±1e+100 m"});
      }
    if (!(p.radius >= kMinRadius && p.radius <= kMaxLength)) {
      placed = false;
      issues.push_back({name + ".radius", check::format_si(p.radius, "m"), "1e-100 m to 1e+100 m"});
    }
    check::finite(issues, (name + ".phase").c_str(), p.phase, "rad");
    if (p.teeth < 1 || p.teeth > kMaxBridgeTeeth)
      issues.push_back({name + ".teeth", std::to_string(p.teeth),
                        "1 to 1000000 (beyond, the walk cannot tell a polygon from its circle)"});
  };
  polygon("a", a);
  polygon("b", b);
  if (placed) {  // disjoint polygons: the centres apart by more than the radii
    const double apart = std::hypot(b.x - a.x, b.y - a.y), touch = a.radius + b.radius;
    if (!(apart > touch))
      issues.push_back({"|(b.x, b.y) - (a.x, a.y)|", check::format_si(apart, "m"),
                        "more than a.radius + b.radius = " + check::format_si(touch, "m")});
  }
  refuse("hull_bridge", issues);
  const Bridge r =
      bridge({{a.x, a.y}, a.radius, a.phase, a.teeth}, {{b.x, b.y}, b.radius, b.phase, b.teeth});
  return {r.ia, r.ib};
}

namespace {

PolygonWrap wrap_of(double pitch, int z1, int z2, int links, double phase1) {
  const double r1 = radius_of(pitch, z1), r2 = radius_of(pitch, z2);
  const double a_lo = (r1 + r2) * (1 + 1e-9), a_hi = links * pitch / 2;
  // the centre distance at which the hull is `links` pitches round, for the driven phase φ2
  auto taut = [&](double phase2) -> double {
    auto excess = [&](double a) {
      return perimeter(hull_of(pitch, z1, z2, a, phase1, phase2), pitch) / pitch - links;
    };
    if (excess(a_lo) > 0 || !(a_hi > a_lo))
      throw std::domain_error("the chain is too short to pass round both sprockets");
    if (excess(a_hi) <= 0) return a_hi;
    boost::math::tools::eps_tolerance<double> tol(std::numeric_limits<double>::digits - 2);
    std::uintmax_t iterations = 200;
    const auto [lo, hi] = boost::math::tools::toms748_solve(excess, a_lo, a_hi, tol, iterations);
    return (lo + hi) / 2;
  };
  auto offset = [&](double phase2) {
    return upper_offset(hull_of(pitch, z1, z2, taut(phase2), phase1, phase2), pitch);
  };
  const double period = 2 * kPi / z2;
  std::vector<double> phases, offsets;
  for (int k = 0; k <= kPhaseSamples; ++k) {
    check_cancelled();  // each sample solves for the taut centre distance (1000 teeth: ms)
    phases.push_back(period * k / kPhaseSamples);
    offsets.push_back(offset(phases.back()));
  }
  PolygonWrap best;
  bool found = false;
  constexpr double kTouch = 1e-12;  // [pitches] a sample that is a root (equal sprockets in line)
  for (int k = 0; k < kPhaseSamples; ++k) {
    check_cancelled();
    const double g0 = offsets[k], g1 = offsets[k + 1];
    if (std::abs(g0) > 0.25 || std::abs(g1) > 0.25) continue;  // the jump at half a pitch
    double phase2;
    if (std::abs(g0) <= kTouch) {
      phase2 = phases[k];
    } else if (std::abs(g1) <= kTouch) {
      continue;  // found as the next interval's start
    } else if (g0 * g1 > 0) {
      if (std::min(std::abs(g0), std::abs(g1)) > 2.0 / kPhaseSamples) continue;
      // no sign change, but the offset may touch zero inside (a root where the span's end pin
      // changes): the least |offset| in the interval
      const auto m = boost::math::tools::brent_find_minima(
          [&](double phase) { return std::abs(offset(phase)); }, phases[k], phases[k + 1],
          std::numeric_limits<double>::digits / 2);
      if (!(m.second <= kTouch)) continue;
      phase2 = m.first;
    } else {
      boost::math::tools::eps_tolerance<double> tol(std::numeric_limits<double>::digits - 2);
      std::uintmax_t iterations = 200;
      const auto [lo, hi] = boost::math::tools::toms748_solve(offset, phases[k], phases[k + 1], g0,
                                                              g1, tol, iterations);
      phase2 = (lo + hi) / 2;
    }
    PolygonWrap w = hull_of(pitch, z1, z2, taut(phase2), phase1, phase2);
    w.span_upper = static_cast<int>(std::lround(w.upper_length / pitch));
    w.span_lower = links - w.wrap1 - w.wrap2 - w.span_upper;
    if (w.span_upper < 1 || w.span_lower < 1) continue;
    if (!found || w.center_distance < best.center_distance) best = w;
    found = true;
  }
  if (!found) throw std::domain_error("no taut polygon wrap found for this phase");
  return best;
}

}  // namespace

PolygonWrap polygon_wrap(double pitch, int z1, int z2, int links, double phase1) {
  std::vector<Issue> issues;
  check_sprockets(issues, pitch, z1, z2);
  check_links(issues, links);
  check::finite(issues, "phase1", phase1, "rad");
  refuse("polygon_wrap", issues);
  return wrap_of(pitch, z1, z2, links, phase1);
}

ExactCenterDistance exact_center_distance(double pitch, int z1, int z2, int links) {
  std::vector<Issue> issues;
  check_sprockets(issues, pitch, z1, z2);
  check_links(issues, links);
  refuse("exact_center_distance", issues);
  const double period = 2 * kPi / z1;
  auto a_at = [&](double phase1) { return wrap_of(pitch, z1, z2, links, phase1).center_distance; };
  // the driver phases sampled, then the two refinements (1000 teeth, 10⁵ links: 20 s)
  constexpr auto kSteps = static_cast<std::size_t>(kDriverSamples) + 2;
  ProgressLoop loop(kSteps, "driver phases");
  std::vector<double> values;
  for (int k = 0; k < kDriverSamples; ++k) {
    loop.step(static_cast<std::size_t>(k));
    values.push_back(a_at(period * k / kDriverSamples));
  }
  loop.step(kSteps - 2);
  const auto lo = std::min_element(values.begin(), values.end()) - values.begin();
  const auto hi = std::max_element(values.begin(), values.end()) - values.begin();
  const double step = period / kDriverSamples;
  constexpr int kBits = std::numeric_limits<double>::digits / 2;
  const auto at_min = boost::math::tools::brent_find_minima(
      a_at, period * static_cast<double>(lo) / kDriverSamples - step,
      period * static_cast<double>(lo) / kDriverSamples + step, kBits);
  loop.step(kSteps - 1);
  const auto at_max = boost::math::tools::brent_find_minima(
      [&](double phase1) { return -a_at(phase1); },
      period * static_cast<double>(hi) / kDriverSamples - step,
      period * static_cast<double>(hi) / kDriverSamples + step, kBits);
  loop.step(kSteps);
  ExactCenterDistance e;
  for (int k = 0; k < kDriverSamples; ++k) e.phases.push_back(period * k / kDriverSamples);
  e.values = values;
  e.at_min = wrap_of(pitch, z1, z2, links, at_min.first);
  e.min = std::min(e.at_min.center_distance, values[static_cast<std::size_t>(lo)]);
  if (values[static_cast<std::size_t>(lo)] < e.at_min.center_distance) {
    e.at_min = wrap_of(pitch, z1, z2, links, period * static_cast<double>(lo) / kDriverSamples);
    e.min = e.at_min.center_distance;
  }
  e.max = std::max(-at_max.second, values[static_cast<std::size_t>(hi)]);
  return e;
}

double span_angle(double pitch, int z1, int z2, double a) {
  std::vector<Issue> issues;
  const bool sprockets = check_sprockets(issues, pitch, z1, z2);
  check_apart(issues, "center_distance", a, sprockets, pitch, z1, z2);
  refuse("span_angle", issues);
  return angle_of(pitch, z1, z2, a);
}

ShaftLoads shaft_loads(double pitch, int z1, int z2, double a, double tight, double slack,
                       double centrifugal) {
  std::vector<Issue> issues;
  const bool sprockets = check_sprockets(issues, pitch, z1, z2);
  check_apart(issues, "center_distance", a, sprockets, pitch, z1, z2);
  check_tension(issues, "tight", tight);
  check_tension(issues, "slack", slack);
  check_tension(issues, "centrifugal", centrifugal);
  refuse("shaft_loads", issues);
  const double g = angle_of(pitch, z1, z2, a);
  const double t = tight - centrifugal, s = slack - centrifugal;
  ShaftLoads l;
  l.driver_x = (t + s) * std::cos(g);  // the spans pull the driver towards the driven sprocket
  l.driver_y = (t - s) * std::sin(g);
  l.driven_x = -l.driver_x;
  l.driven_y = -l.driver_y;
  return l;
}

std::vector<std::pair<double, double>> wrap_pins(const PolygonWrap& w, double pitch, int z1,
                                                 int z2) {
  std::vector<Issue> issues;
  const bool sprockets = check_sprockets(issues, pitch, z1, z2);
  check_apart(issues, "w.center_distance", w.center_distance, sprockets, pitch, z1, z2);
  check::finite(issues, "w.phase1", w.phase1, "rad");
  check::finite(issues, "w.phase2", w.phase2, "rad");
  // each sprocket's seats and wrap: in range for its tooth count, the wrap ending at the seat out
  auto wrap = [&](const std::string& n, int z, int in, int out, int count) {
    const bool valid = z >= kMinTeeth && z <= kMaxTeeth;
    const std::string last = valid ? std::to_string(z - 1) : "z" + n + " - 1";
    bool ok = true;
    for (const auto& [field, value] :
         {std::pair{"w.seat" + n + "_in", in}, std::pair{"w.seat" + n + "_out", out},
          std::pair{"w.wrap" + n, count}})
      if (!(value >= 0 && (!valid || value < z))) {
        ok = false;
        issues.push_back({field, std::to_string(value), "0 to " + last});
      }
    if (valid && ok && out != (in + count) % z)
      issues.push_back({"w.seat" + n + "_out", std::to_string(out),
                        "(w.seat" + n + "_in + w.wrap" + n + ") mod z" + n + " = " +
                            std::to_string((in + count) % z) + ", where the wrap ends"});
  };
  wrap("1", z1, w.seat1_in, w.seat1_out, w.wrap1);
  wrap("2", z2, w.seat2_in, w.seat2_out, w.wrap2);
  const std::string spans = "1 to " + std::to_string(kMaxLinks) + " links";
  bool counted = true;
  for (const auto& [field, value] :
       {std::pair{"w.span_lower", w.span_lower}, std::pair{"w.span_upper", w.span_upper}})
    if (!(value >= 1 && value <= kMaxLinks)) {
      counted = false;
      issues.push_back({field, std::to_string(value), spans});
    }
  if (counted && w.wrap1 >= 0 && w.wrap1 <= kMaxTeeth && w.wrap2 >= 0 && w.wrap2 <= kMaxTeeth) {
    const int links = w.wrap1 + w.wrap2 + w.span_lower + w.span_upper;
    if (links > kMaxLinks)
      issues.push_back({"w.wrap1 + w.wrap2 + w.span_lower + w.span_upper", std::to_string(links),
                        "at most " + std::to_string(kMaxLinks) + " links"});
  }
  refuse("wrap_pins", issues);
  const Polygon p1{{0, 0}, radius_of(pitch, z1), w.phase1, z1};
  const Polygon p2{{w.center_distance, 0}, radius_of(pitch, z2), w.phase2, z2};
  std::vector<std::pair<double, double>> pins;
  auto add = [&](Point q) { pins.emplace_back(q.x, q.y); };
  auto span = [&](Point from, Point to, int n) {
    for (int k = 1; k < n; ++k) {
      const double t = static_cast<double>(k) / n;
      add({from.x + t * (to.x - from.x), from.y + t * (to.y - from.y)});
    }
  };
  for (int i = 0; i <= w.wrap1; ++i) add(p1[w.seat1_in + i]);
  span(p1[w.seat1_out], p2[w.seat2_in], w.span_lower);
  for (int j = 0; j <= w.wrap2; ++j) add(p2[w.seat2_in + j]);
  span(p2[w.seat2_out], p1[w.seat1_in], w.span_upper);
  add(p1[w.seat1_in]);
  return pins;
}

}  // namespace catena::drive
