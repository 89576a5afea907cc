// An independent rolling simulation of the hinge, for tests: the roller's working face is rolled
// on the plate's working arc without slip by geometry alone. Both curves are plain parametric
// curves; arc lengths are integrated numerically (Gauss–Kronrod), the contact is where equal
// arc lengths meet, the roller's pose is the rigid motion that lays its face point and tangent
// onto the plate's. Nothing here uses the thesis' eqs. (1)–(19) or the library's closed forms.
#pragma once

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <functional>

#include "catena/hinge/hinge.hpp"
#include "catena/hinge/kinematics.hpp"

namespace catena::hinge::testing {

struct Vec {
  double x = 0.0;
  double y = 0.0;
};

using Curve = std::function<Vec(double)>;

// Fourth-order central difference of a curve.
inline Vec tangent(const Curve& c, double u, double h) {
  const Vec m2 = c(u - 2 * h), m1 = c(u - h), p1 = c(u + h), p2 = c(u + 2 * h);
  return {(m2.x - 8 * m1.x + 8 * p1.x - p2.x) / (12 * h),
          (m2.y - 8 * m1.y + 8 * p1.y - p2.y) / (12 * h)};
}

// Arc length of c over [0, u] and its inverse.
inline double arc_length(const Curve& c, double u, double h) {
  if (u == 0.0) return 0.0;
  auto speed = [&](double t) {
    const Vec d = tangent(c, t, h);
    return std::hypot(d.x, d.y);
  };
  return boost::math::quadrature::gauss_kronrod<double, 61>::integrate(speed, 0.0, u, 4, 1e-14);
}

inline double parameter_at(const Curve& c, double s, double u_max, double h) {
  if (s == 0.0) return 0.0;
  boost::uintmax_t it = 200;
  auto [lo, hi] =
      boost::math::tools::toms748_solve([&](double u) { return arc_length(c, u, h) - s; }, 0.0,
                                        u_max, boost::math::tools::eps_tolerance<double>(50), it);
  return 0.5 * (lo + hi);
}

struct SimulatedPose {
  double gamma = 0.0;  // [rad] roller turn relative to the plate (the roller is rotated by −γ)
  Vec contact;         // plate frame
  Vec centre;          // roller centre in the plate frame
  double rotation = 0.0;   // [rad] rotation of the roller body in the plate frame
  double beta = 0.0;       // [rad] angle between the contact normal and the plate axis
  Vec body(Vec p) const {  // a roller body point in the plate frame
    const double c = std::cos(rotation), s = std::sin(rotation);
    return {centre.x + c * p.x - s * p.y, centre.y + s * p.x + c * p.y};
  }
};

class RollingSimulation {
 public:
  // Plate arc: circle of radius R1 about O1 = (a + R1, e) in the plate frame, contact starting at
  // (a, e) and moving to +y. Roller face in its body frame (centre at the origin): the circle of
  // radius R2 about (a + R2, 0) (concave) or the line x = a (flat), starting at (a, e).
  explicit RollingSimulation(const Hinge& h, double r2) {
    const double a = h.half_thickness;
    const double r1 = h.plate_radius;
    const double e = h.face == Face::kFlat ? flat_contact_offset(h) : 0.0;
    scale_ = r1;
    plate_ = [=](double u) {
      return Vec{a + r1 - r1 * std::cos(u / r1), e + r1 * std::sin(u / r1)};
    };
    if (h.face == Face::kFlat || !std::isfinite(r2)) {
      face_ = [=](double v) { return Vec{a, e + v}; };
    } else {
      face_ = [=](double v) { return Vec{a + r2 - r2 * std::cos(v / r2), r2 * std::sin(v / r2)}; };
    }
  }

  // Pose after rolling an arc length s along both curves.
  SimulatedPose at_arc(double s) const {
    const double h = 1e-4 * scale_;
    const double u = parameter_at(plate_, s, 4.0 * scale_, h);
    const double v = parameter_at(face_, s, 4.0 * scale_, h);
    const Vec p = plate_(u), q = face_(v);
    const Vec tp = tangent(plate_, u, h), tq = tangent(face_, v, h);
    SimulatedPose pose;
    pose.rotation = std::atan2(tp.y, tp.x) - std::atan2(tq.y, tq.x);
    pose.gamma = -pose.rotation;
    pose.contact = {p.x, p.y};
    const double c = std::cos(pose.rotation), sn = std::sin(pose.rotation);
    pose.centre = {p.x - (c * q.x - sn * q.y), p.y - (sn * q.x + c * q.y)};
    // contact normal ⟂ tangent; the plate axis is x
    pose.beta = std::abs(std::atan2(tp.x, tp.y));  // angle of the normal (tp rotated by −90°) to x
    return pose;
  }

  // Pose at the mutual link angle φ (γ = φ/2), found by bracketing the rolled arc length.
  SimulatedPose at_phi(double phi) const {
    if (phi == 0.0) return at_arc(0.0);
    boost::uintmax_t it = 200;
    auto [lo, hi] = boost::math::tools::toms748_solve(
        [&](double s) { return at_arc(s).gamma - 0.5 * phi; }, 0.0, 2.0 * scale_,
        boost::math::tools::eps_tolerance<double>(48), it);
    return at_arc(0.5 * (lo + hi));
  }

 private:
  Curve plate_, face_;
  double scale_ = 1.0;
};

}  // namespace catena::hinge::testing
