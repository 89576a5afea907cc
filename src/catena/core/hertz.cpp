#include "catena/core/hertz.hpp"

#include <cmath>
#include <limits>
#include <numbers>

namespace catena {

double contact_modulus(const Elastic& a, const Elastic& b) {
  return 1.0 /
         ((1.0 - a.poisson * a.poisson) / a.modulus + (1.0 - b.poisson * b.poisson) / b.modulus);
}

double conformal_radius(double r_convex, double r_concave) {
  if (!std::isfinite(r_concave) || r_concave == 0.0) return r_convex;
  return r_convex * r_concave / (r_concave - r_convex);
}

LineContact line_contact(double load_per_length, double radius, double modulus) {
  LineContact c;
  c.half_width = std::sqrt(4.0 * load_per_length * radius / (std::numbers::pi * modulus));
  c.peak_pressure = std::sqrt(load_per_length * modulus / (std::numbers::pi * radius));
  return c;
}

}  // namespace catena
