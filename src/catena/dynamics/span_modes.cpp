#include "catena/dynamics/span_modes.hpp"

#include <cmath>
#include <numbers>

namespace catena::dynamics {

SpanFrequencies span_frequencies(double length, double tension, double mass_per_metre, double speed,
                                 double link_stiffness, double pitch) {
  const bool valid = std::isfinite(length) && std::isfinite(tension) &&
                     std::isfinite(mass_per_metre) && std::isfinite(speed) &&
                     std::isfinite(link_stiffness) && std::isfinite(pitch) && pitch > 0.0 &&
                     length >= pitch && tension > 0.0 && mass_per_metre > 0.0 && speed >= 0.0 &&
                     link_stiffness > 0.0;
  if (!valid) return {NAN, NAN};
  constexpr double kPi = std::numbers::pi;
  SpanFrequencies f;
  const double c2 = tension / mass_per_metre, v2 = speed * speed;
  // (1/2L) c (1 − v²/c²) = (c² − v²) / (2 L c)
  if (c2 > v2) f.transverse = (c2 - v2) / (2.0 * length * std::sqrt(c2));
  f.longitudinal = std::sqrt(link_stiffness / (mass_per_metre * pitch)) / kPi *
                   std::sin(kPi * pitch / (2.0 * length));
  return f;
}

}  // namespace catena::dynamics
