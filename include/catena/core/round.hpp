// Rounding of the limits that messages name.
#pragma once

#include <cmath>

namespace catena::check {

/// x rounded down to `digits` significant digits (an upper limit named so that the value named is
/// inside); x itself when it is not finite and positive.
inline double down_to(double x, int digits) {
  if (!(x > 0.0) || !std::isfinite(x)) return x;
  const double unit = std::pow(10.0, std::floor(std::log10(x)) - (digits - 1));
  return std::floor(x / unit * (1.0 + 1e-12)) * unit;
}

}  // namespace catena::check
