// The hinges' friction couple (include/catena/dynamics/hinge_friction.hpp; docs/models/dynamics.md,
// "Hinges").
#include "catena/dynamics/hinge_friction.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace catena::dynamics {

std::vector<Issue> validate(const HingeFriction& hinge, double pitch) {
  std::vector<Issue> out;
  // the arm is a fraction of a pin radius or a rolling lever: far below the pitch
  if (!std::isfinite(hinge.arm) || hinge.arm < 0.0 ||
      (std::isfinite(pitch) && pitch > 0.0 && hinge.arm >= 0.5 * pitch)) {
    out.push_back({"hinge.arm", check::format_si(hinge.arm, "m"),
                   "a finite value in [0, p/2) m (mu r or c_r R*)"});
  }
  if (!std::isfinite(hinge.rate_band) || !(hinge.rate_band > 0.0) || hinge.rate_band > 100.0) {
    out.push_back({"hinge.rate_band", check::format_si(hinge.rate_band, "rad/s"),
                   "a value in (0, 100] rad/s"});
  }
  // the stick law: a spring of finite stiffness ≥ 0, with friction to stick by
  if (!std::isfinite(hinge.stick_stiffness) || hinge.stick_stiffness < 0.0) {
    out.push_back({"hinge.stick_stiffness", check::format_si(hinge.stick_stiffness, "N*m/rad"),
                   "a finite value >= 0 N*m/rad (0: the regularised law)"});
  } else if (hinge.stick_stiffness > 0.0 && !(hinge.arm > 0.0)) {
    out.push_back({"hinge.stick_stiffness", check::format_si(hinge.stick_stiffness, "N*m/rad"),
                   "0 on a frictionless hinge (arm 0: nothing to stick with)"});
  }
  if (!std::isfinite(hinge.stick_damping) || hinge.stick_damping < 0.0) {
    out.push_back({"hinge.stick_damping", check::format_si(hinge.stick_damping, "N*m*s/rad"),
                   "a finite value >= 0 N*m*s/rad"});
  } else if (hinge.stick_damping > 0.0 && !(hinge.stick_stiffness > 0.0)) {
    out.push_back({"hinge.stick_damping", check::format_si(hinge.stick_damping, "N*m*s/rad"),
                   "0 without hinge.stick_stiffness (the damper sits beside the stick spring)"});
  }
  return out;
}

std::vector<Issue> validate_pin_links(const HingeFriction& hinge, std::size_t links, bool closed) {
  std::vector<Issue> out;
  // round a closed loop of an odd count the alternation meets itself: two outer links (0 and
  // links − 1) at node 0, an offset link, which is not modelled
  if (hinge.active() && hinge.pin_load == PinLoad::kPinLink && closed && links % 2 != 0) {
    out.push_back({"links", std::to_string(links),
                   "an even count with pin_load = \"pin_link\" (inner and outer links "
                   "alternate round the loop; an odd count needs an offset link, not modelled)"});
  }
  return out;
}

double rolling_hinge_arm(double rolling_coefficient, double plate_radius, double face_radius) {
  const double reduced = std::isinf(face_radius)
                             ? plate_radius
                             : plate_radius * face_radius / (face_radius - plate_radius);
  return rolling_coefficient * reduced;
}

HingeCouple hinge_couple(const HingeFriction& hinge, double axial_stiffness, const double rest[2],
                         const double x0[3], const double y0[3], const double x1[3],
                         const double y1[3], double theta, double step, std::size_t node,
                         double deflection) {
  double length0[2], length1[2];
  for (int j = 0; j < 2; ++j) {
    const double d0x = x0[j + 1] - x0[j], d0y = y0[j + 1] - y0[j];
    const double d1x = x1[j + 1] - x1[j], d1y = y1[j + 1] - y1[j];
    length0[j] = std::sqrt(d0x * d0x + d0y * d0y);
    length1[j] = std::sqrt(d1x * d1x + d1y * d1y);
  }
  return hinge_couple(hinge, axial_stiffness, rest, x0, y0, x1, y1, theta, step, length0, length1,
                      true, node, deflection);
}

HingeCouple hinge_couple(const HingeFriction& hinge, double axial_stiffness, const double rest[2],
                         const double x0[3], const double y0[3], const double x1[3],
                         const double y1[3], double theta, double step, const double length0[2],
                         const double length1[2], bool jacobian, std::size_t node,
                         double deflection) {
  HingeCouple hc;
  hinge_couple(hinge, axial_stiffness, rest, x0, y0, x1, y1, theta, step, length0, length1, hc,
               jacobian, node, deflection);
  return hc;
}

void hinge_couple(const HingeFriction& hinge, double axial_stiffness, const double rest[2],
                  const double x0[3], const double y0[3], const double x1[3], const double y1[3],
                  double theta, double step, const double length0[2], const double length1[2],
                  HingeCouple& hc, bool jacobian, std::size_t node, double deflection) {
  HingeLink link[2];
  for (int j = 0; j < 2; ++j) {
    hinge_link(x0[j + 1] - x0[j], y0[j + 1] - y0[j], x1[j + 1] - x1[j], y1[j + 1] - y1[j],
               length0[j], length1[j], rest[j], axial_stiffness, theta, link[j], jacobian);
  }
  hinge_couple(hinge, link[0], link[1], step, hc, jacobian, node, theta, deflection);
}

}  // namespace catena::dynamics
