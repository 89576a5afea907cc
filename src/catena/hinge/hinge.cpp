#include "catena/hinge/hinge.hpp"

#include <cmath>
#include <numbers>
#include <string>

namespace catena::hinge {

std::vector<Issue> validate(const Hinge& h) {
  std::vector<Issue> issues;
  check::finite_positive(issues, "pin_diameter", h.pin_diameter, "m");
  check::finite_positive(issues, "half_thickness", h.half_thickness, "m");
  check::finite_positive(issues, "plate_radius", h.plate_radius, "m");
  if (h.teeth < 3) issues.push_back({"teeth", std::to_string(h.teeth), "an integer z ≥ 3"});
  if (h.strokes < 1 || (h.teeth >= 3 && 2 * h.strokes >= h.teeth)) {
    issues.push_back({"strokes", std::to_string(h.strokes),
                      "an integer m ≥ 1 with m < z/2 (γmax = 180°·m/z must stay below 90°)"});
  }
  if (std::isfinite(h.pin_diameter) && std::isfinite(h.half_thickness) && h.half_thickness > 0 &&
      h.pin_diameter > 0 && 2.0 * h.half_thickness >= h.pin_diameter) {
    issues.push_back({"half_thickness", check::format_si(h.half_thickness, "m"),
                      "a half-thickness a < d/2 = " + check::format_si(0.5 * h.pin_diameter, "m") +
                          " (the working faces must cut the roller's circle)"});
  }
  if (issues.empty()) {
    // Below (d/2 − a)/2 the plate's R1 circle lies inside the roller's circle: N1 (eq. 4) does
    // not exist and eqs. (5)–(7) lose their meaning.
    const double lowest = 0.5 * (0.5 * h.pin_diameter - h.half_thickness);
    if (h.plate_radius <= lowest) {
      issues.push_back({"plate_radius", check::format_si(h.plate_radius, "m"),
                        "R1 > (d/2 − a)/2 = " + check::format_si(lowest, "m") +
                            " (a smaller plate arc lies inside the roller's circle: no point N1)"});
    }
  }
  if (h.face == Face::kConcave && h.roller_radius != 0.0) {
    if (!std::isfinite(h.roller_radius) || h.roller_radius <= h.plate_radius) {
      issues.push_back({"roller_radius", check::format_si(h.roller_radius, "m"),
                        "R2 > R1 = " + check::format_si(h.plate_radius, "m") +
                            " (a concave face must be flatter than the plate's arc), or 0 for "
                            "eq. (6)"});
    }
  }
  if (h.face == Face::kFlat && issues.empty()) {
    const double chord =
        std::sqrt(0.25 * h.pin_diameter * h.pin_diameter - h.half_thickness * h.half_thickness);
    if (!std::isfinite(h.face_half_length) || h.face_half_length <= 0.0 ||
        h.face_half_length > chord * (1 + 1e-12)) {
      issues.push_back(
          {"face_half_length", check::format_si(h.face_half_length, "m"),
           "half the flat face length, 0 < a_f ≤ √(d²/4 − b²) = " + check::format_si(chord, "m")});
    }
    if (!std::isfinite(h.loaded_length) || h.loaded_length < 0.0 ||
        h.loaded_length > 2.0 * h.face_half_length) {
      issues.push_back({"loaded_length", check::format_si(h.loaded_length, "m"),
                        "0 ≤ c ≤ 2·a_f (the initial contact lies on the face)"});
    }
  }
  return issues;
}

double gamma_max(const Hinge& h) {
  return std::numbers::pi * h.strokes / h.teeth;  // 000 eq. (12); eq. (3) for m = 1
}

double flat_contact_offset(const Hinge& h) { return h.loaded_length - h.face_half_length; }

}  // namespace catena::hinge
