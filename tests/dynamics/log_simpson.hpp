// Quadrature over a contact's depth that spans many decades (a line contact's force from first
// touch): Simpson's rule in s = ln g.
#pragma once

#include <cmath>

namespace catena::dynamics::testing {

// ∫ f(g) dg over [from, to] (0 < from < to) by Simpson's rule in s = ln g, 16000 intervals:
// ∫ f(e^s) e^s ds.
template <class F>
double simpson_in_log(double from, double to, F f) {
  const int n = 16000;
  const double a = std::log(from), b = std::log(to), h = (b - a) / n;
  double sum = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double g = std::exp(a + i * h);
    sum += (i == 0 || i == n ? 1.0 : (i % 2 ? 4.0 : 2.0)) * f(g) * g;
  }
  return sum * h / 3.0;
}

}  // namespace catena::dynamics::testing
