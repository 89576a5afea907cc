// The catenary through two points with a given length, solved by the tests themselves (not by the
// layout's catenary_through): the slack start's catenary tests and the command's.
#pragma once

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
