// The catenary through two points with a given length, solved by the tests themselves (not by the
// layout's catenary_through): the slack start's catenary tests and the command's; and the
// catenary tangent to two equal circles (not by the layout's tangent_span).
#pragma once

#include <algorithm>
#include <cmath>

// The catenary through (xa, ya) and (xb, yb) `length` long: bisection on a in
// 2a sinh(d/2a) = √(S² − h²) (d = xb − xa, h = yb − ya, S the length); a and x0 with
// y = y_A + a (cosh((x − x0)/a) − cosh((x_A − x0)/a)).
struct ClosedForm {
  double a = 0.0, x0 = 0.0;
  double y(double x, double xa, double ya) const {
    return ya + a * (std::cosh((x - x0) / a) - std::cosh((xa - x0) / a));
  }
};
inline ClosedForm closed_form(double xa, double ya, double xb, double yb, double length) {
  const double d = xb - xa, h = yb - ya;
  double lo = 1e-6, hi = 1e3;
  for (int i = 0; i < 300; ++i) {
    const double mid = 0.5 * (lo + hi);
    (2.0 * mid * std::sinh(d / (2.0 * mid)) > std::sqrt(length * length - h * h) ? lo : hi) = mid;
  }
  ClosedForm c;
  c.a = 0.5 * (lo + hi);
  c.x0 = 0.5 * (xa + xb) - c.a * std::atanh(h / length);
  return c;
}

// The catenary tangent from below to two circles of radius r, centres d = (dx, dy) apart, with
// the path's extra `extra` (the catenary's length less the taut span's c and the two wraps'
// shortening r (θc − θ0) + r (θ1 − θc), θ = atan sinh t): the tests' own solve, in a (the layout's
// `tangent_span` solves in the slope t0 with a eliminated). At fixed a > r the centres' offsets
// from the vertex, x(t) = a t − r tanh t and y(t) = a (cosh t − 1) + r / cosh t, rise along x: t1
// from x(t1) − x(t0) = dx by bisection, then t0 from y(t1) − y(t0) = dy (rising in t0); then a from
// the extra (falling in a). Where no t1 above tc meets x (a too large: the catenary's x run
// between the tangent points exceeds dx already at tc) or the two conditions are not met to 1e-9
// of the chord, `at` gives NANs, which the bisection on a takes as a too large; returns {a, t0,
// t1}, all NAN where the solve found no tangent catenary (an explicit failure, not a bracket's
// end).
struct TangentCatenary {
  double a = NAN, t0 = NAN, t1 = NAN;
};
inline TangentCatenary tangent_catenary(double dx, double dy, double r, double c, double extra) {
  const double theta_c = std::atan2(dy, dx), tc = std::asinh(std::tan(theta_c));
  auto bisect = [](double lo, double hi, auto rising) {
    for (int it = 0; it < 300 && hi - lo > 0.0; ++it) {
      const double mid = 0.5 * (lo + hi);
      if (!(mid > lo && mid < hi)) break;
      (rising(mid) < 0.0 ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  };
  auto at = [&](double a) {
    auto x = [&](double t) { return a * t - r * std::tanh(t); };
    auto y = [&](double t) { return a * (std::cosh(t) - 1.0) + r / std::cosh(t); };
    auto t1_of = [&](double t0) {
      return bisect(tc, 30.0, [&](double t1) { return x(t1) - x(t0) - dx; });
    };
    TangentCatenary out;
    const double t0 = bisect(-30.0, tc, [&](double s0) { return y(t1_of(s0)) - y(s0) - dy; });
    const double t1 = t1_of(t0);
    if (!(std::abs(x(t1) - x(t0) - dx) <= 1e-9 * c && std::abs(y(t1) - y(t0) - dy) <= 1e-9 * c))
      return out;
    out.a = a;
    out.t0 = t0;
    out.t1 = t1;
    return out;
  };
  auto extra_of = [&](const TangentCatenary& s) {
    return s.a * (std::sinh(s.t1) - std::sinh(s.t0)) - c -
           r * (theta_c - std::atan(std::sinh(s.t0))) - r * (std::atan(std::sinh(s.t1)) - theta_c);
  };
  const TangentCatenary out = at(bisect(r * (1.0 + 1e-9), 100.0 * r, [&](double a) {
    const double e = extra_of(at(a));
    return std::isnan(e) ? 1.0 : extra - e;  // not solved: a too large
  }));
  return std::abs(extra_of(out) - extra) <= 1e-9 * c ? out : TangentCatenary{};
}

// The lowest point of that catenary below circle 0's centre: the point of slope sinh t0 on circle
// 0 is r / cosh t0 below the centre, the curve's lowest point (its vertex, t = 0, where it lies
// between the tangent points, else the nearer end) a (cosh t0 − cosh t) below that.
inline double tangent_catenary_depth(const TangentCatenary& s, double r) {
  const double lowest = std::clamp(0.0, s.t0, s.t1);
  return r / std::cosh(s.t0) + s.a * (std::cosh(s.t0) - std::cosh(lowest));
}
