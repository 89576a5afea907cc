#include "catena/hinge/aperture.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace catena::hinge {
namespace {

constexpr double kPi = std::numbers::pi;

double wrap_2pi(double a) {
  a = std::fmod(a, 2.0 * kPi);
  return a < 0.0 ? a + 2.0 * kPi : a;
}

}  // namespace

std::vector<Point> roller_outline(const Hinge& h, double r2, int per_arc) {
  const std::vector<Point> c = feature_points(h, r2);  // (+x,+y), (+x,−y), (−x,+y), (−x,−y)
  const double r0 = 0.5 * h.pin_diameter;
  const double a = h.half_thickness;
  const bool flat = h.face == Face::kFlat || !std::isfinite(r2);
  std::vector<Point> out;
  auto circle_arc = [&](Point from, Point to) {  // counter-clockwise on the d circle
    const double t0 = std::atan2(from.y, from.x);
    double t1 = std::atan2(to.y, to.x);
    if (t1 <= t0) t1 += 2.0 * kPi;
    for (int i = 0; i < per_arc; ++i) {
      const double t = t0 + (t1 - t0) * i / per_arc;
      out.push_back({r0 * std::cos(t), r0 * std::sin(t)});
    }
  };
  auto face = [&](double side, Point from, Point to) {  // from → to along the working face
    for (int i = 0; i < per_arc; ++i) {
      const double y = from.y + (to.y - from.y) * i / per_arc;
      const double x = flat ? a : a + r2 - std::sqrt(r2 * r2 - y * y);
      out.push_back({side * x, y});
    }
  };
  circle_arc(c[0], c[2]);  // top of the d circle
  face(-1.0, c[2], c[3]);  // −x face, downwards
  circle_arc(c[3], c[1]);  // bottom
  face(1.0, c[1], c[0]);   // +x face, upwards
  return out;
}

Aperture aperture(const Hinge& h, double r2, const ApertureOptions& o) {
  const int n = o.rays;
  const double step = 2.0 * kPi / n;
  const double c = o.clearance;
  std::vector<double> reach(static_cast<std::size_t>(n), 0.0);
  const std::vector<Point> body = roller_outline(h, r2);
  const double phi_max = 2.0 * gamma_max(h);
  auto ray_index = [&](double angle) {
    return static_cast<int>(std::floor(wrap_2pi(angle) / step));
  };
  std::vector<std::vector<Point>> placed;
  for (int k = 0; k < o.poses; ++k) {
    const Pose p = pose(h, r2, phi_max * k / (o.poses - 1));
    std::vector<Point>& q = placed.emplace_back(body.size());
    for (std::size_t i = 0; i < body.size(); ++i) q[i] = roller_point(p, body[i]);
    for (std::size_t i = 0; i < q.size(); ++i) {
      // the outline itself: each segment against the rays whose directions it spans
      const Point s0 = q[i];
      const Point s1 = q[(i + 1) % q.size()];
      const double a0 = std::atan2(s0.y, s0.x);
      double span = std::remainder(std::atan2(s1.y, s1.x) - a0, 2.0 * kPi);
      const int first = ray_index(std::min(a0, a0 + span));
      const int count = static_cast<int>(std::ceil(std::abs(span) / step)) + 1;
      for (int j = first; j <= first + count; ++j) {
        const double t = (j % n) * step;
        const double ux = std::cos(t), uy = std::sin(t);
        const double dx = s1.x - s0.x, dy = s1.y - s0.y;
        const double den = ux * dy - uy * dx;
        if (std::abs(den) < 1e-300) continue;
        const double along = (s0.x * dy - s0.y * dx) / den;  // distance on the ray
        const double frac = (s0.x * uy - s0.y * ux) / den;   // position on the segment
        if (along > 0.0 && frac >= 0.0 && frac <= 1.0) {
          double& r = reach[static_cast<std::size_t>(j % n)];
          r = std::max(r, along);
        }
      }
      // the clearance: the farthest reach of a disc of radius c about each outline point
      if (c > 0.0) {
        const double dist = std::hypot(s0.x, s0.y);
        const double half = dist > c ? std::asin(c / dist) : kPi;
        const double a = std::atan2(s0.y, s0.x);
        for (int j = ray_index(a - half);
             j <= ray_index(a - half) + static_cast<int>(2 * half / step) + 1; ++j) {
          const double t = (j % n) * step;
          const double ux = std::cos(t), uy = std::sin(t);
          const double proj = s0.x * ux + s0.y * uy;
          const double off = s0.x * uy - s0.y * ux;
          if (std::abs(off) > c) continue;
          double& r = reach[static_cast<std::size_t>(j % n)];
          r = std::max(r, proj + std::sqrt(c * c - off * off));
        }
      }
    }
  }
  // The plate's working arc bounds the hole where it is nearer (no clearance on it).
  const bool flat = h.face == Face::kFlat || !std::isfinite(r2);
  const double r1 = h.plate_radius;
  const Point o1{h.half_thickness + r1,
                 flat && h.face == Face::kFlat ? flat_contact_offset(h) : 0.0};
  const double psi_end = pose(h, r2, phi_max).psi1;
  Aperture out;
  out.clearance = c;
  // Reach of the swept, dilated region along one ray (brute force over all outlines).
  auto reach_along = [&](double t) {
    const double ux = std::cos(t), uy = std::sin(t);
    double r = 0.0;
    for (const std::vector<Point>& q : placed) {
      for (std::size_t i = 0; i < q.size(); ++i) {
        const Point s0 = q[i], s1 = q[(i + 1) % q.size()];
        const double dx = s1.x - s0.x, dy = s1.y - s0.y;
        const double den = ux * dy - uy * dx;
        if (std::abs(den) > 1e-300) {
          const double along = (s0.x * dy - s0.y * dx) / den;
          const double frac = (s0.x * uy - s0.y * ux) / den;
          if (along > 0.0 && frac >= 0.0 && frac <= 1.0) r = std::max(r, along);
        }
        const double off = s0.x * uy - s0.y * ux;
        if (c > 0.0 && std::abs(off) <= c)
          r = std::max(r, s0.x * ux + s0.y * uy + std::sqrt(c * c - off * off));
      }
    }
    return r;
  };
  // Rays: the uniform set, and a dense fan around the end of the working arc, where the hole's
  // boundary leaves the arc almost along the rays (a coarse fan would cut the roller's corner).
  std::vector<std::pair<double, double>> rays;  // (angle, reach)
  for (int j = 0; j < n; ++j) rays.push_back({j * step, reach[static_cast<std::size_t>(j)]});
  const Point arc_end{o1.x - r1 * std::cos(psi_end), o1.y + r1 * std::sin(psi_end)};
  const double end_angle = wrap_2pi(std::atan2(arc_end.y, arc_end.x));
  constexpr int kFan = 400;
  for (int j = -kFan / 2; j <= kFan / 2; ++j) {
    const double t = wrap_2pi(end_angle + 4.0 * step * j / kFan);
    rays.push_back({t, reach_along(t)});
  }
  std::sort(rays.begin(), rays.end());
  out.contour.reserve(rays.size());
  for (auto [t, swept] : rays) {
    const double ux = std::cos(t), uy = std::sin(t);
    double r = swept;
    // near intersection of the ray with the R1 circle: the plate's working arc bounds the hole
    const double b = ux * o1.x + uy * o1.y;
    const double disc = b * b - (o1.x * o1.x + o1.y * o1.y - r1 * r1);
    if (disc >= 0.0) {
      const double hit = b - std::sqrt(disc);
      const double px = hit * ux - o1.x, py = hit * uy - o1.y;  // from O1 to the hit point
      const double psi = std::atan2(py, -px);                   // M = O1 + R1(−cos Ψ, sin Ψ)
      const double far = b + std::sqrt(disc);
      // where the swept region reaches past the circle's far side, the ray passes the tip of the
      // plate's lobe at the end of the working arc: the hole goes round it (the tip is cut off)
      if (hit > 0.0 && psi >= -0.5 * kPi && psi <= psi_end && hit < r && r < far) {
        r = hit;
        ++out.working_points;
      }
    }
    out.contour.push_back({r * ux, r * uy});
  }
  return out;
}

}  // namespace catena::hinge
