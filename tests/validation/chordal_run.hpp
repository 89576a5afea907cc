// The polygonal action's set-up (tests/validation/dynamics_chordal_test.cpp, "Polygonal
// action" in docs/models/dynamics.md): one driver sprocket winding in a straight span held by a
// constant force, run and synchronously averaged over the tooth phase, and the kinematics it is
// checked against; shared by the quick chordal tests and the slow ones
// (dynamics_chordal_slow_test.cpp).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <vector>

#include "catena/dynamics/integrator.hpp"

namespace catena::dynamics::chordal {

inline constexpr double kPi = std::numbers::pi;

struct Chordal {
  int teeth = 12;
  int span_links = 40;
  double pitch = 0.01905;
  double roller = 0.01207;
  double width = 0.01168;
  double node_mass = 0.0238;
  double stiffness = 5e7;
  double damping = 2000.0;
  double force = 500.0;
  double chain_speed = 0.5;
  bool clearance = false;
  double contact_stiffness = 2e8;
  double contact_damping = 800.0;
  double duration = 0.4;
  double settle = 0.1;
  double step = 1e-4;
  double theta = 0.6;
  double seat_friction = 0.0;  // μ of the seats
  double span_from = 0.0;      // [m] the span's nodes are those beyond x > this (0: 2 p)
  // after every step, put the span (the nodes before the last seated roller) on the horizontal
  // line through that roller, moving with it: the span's quasi-static transverse state (below,
  // "the span's transverse swing")
  bool hold_transverse = false;
  // > 0: a pair of straight frictionless rails (Guide, the model's own rail contact) from x =
  // this outward past the far end, one under and one over the span's rollers, their centres at
  // the pitch radius (the top roller's height): the span's far links held across, free along —
  // the far end held by the model, as a drive's second wheel holds it (below, "The far end on
  // rails")
  double rails_from = 0.0;
};

struct Result {
  std::vector<double> far, centre;  // synchronously averaged, per phase bin
  double min_far = 0, max_far = 0;
  std::vector<double> phase, span;  // every sample after the settling time: tooth phase, speed
  std::vector<double> incline;      // the span's first link's angle to the x axis [rad]
  std::vector<double> length;       // [m] the span's length: far end to the last seated roller
  double far_lift = 0;              // [m] the far end's largest distance from the top's height
  bool converged = true;
};

inline Result run(const Chordal& d, int bins) {
  const int z = d.teeth, m = d.span_links, wrap = z / 2;
  const auto n = static_cast<std::size_t>(m + 1 + wrap);
  const double rest = d.pitch - d.force / d.stiffness;
  Model model = uniform_chain(n, false, rest, d.node_mass, d.stiffness, d.damping, false);
  // without clearance the seats are spaced at the links' rest length: the links between seated
  // rollers carry no tension and the last seated roller takes the span's (the quasi-static
  // theory); at the loaded pitch every wrapped link would carry the span's tension to the free
  // end, whose roller the flank cannot hold against it
  Sprocket w = iso606_sprocket(d.clearance ? d.pitch : rest, d.roller, d.width, z, 0.0, 0.0,
                               d.contact_stiffness, d.contact_damping);
  if (!d.clearance) w.seat_radius = w.roller_radius;
  w.driver = true;
  w.friction = d.seat_friction;
  const double r = w.pitch_radius, omega = d.chain_speed / r;
  w.speed = omega;
  model.sprockets = {w};
  model.loads = {{.node = 0, .fx = d.force, .fy = 0.0}};
  if (d.rails_from > 0) {
    Guide under;
    under.roller_radius = d.roller / 2;
    under.contact_stiffness = d.contact_stiffness;
    under.contact_damping = d.contact_damping;
    Guide over = under;
    // the free side is on the left going from the first end to the second: under carries the
    // rollers on top, over (drawn the other way) holds them from above
    const double far = (m + 2) * d.pitch;
    under.x0 = d.rails_from;
    under.x1 = far;
    under.y0 = under.y1 = r - under.roller_radius;
    over.x0 = far;
    over.x1 = d.rails_from;
    over.y0 = over.y1 = r + over.roller_radius;
    model.guides = {under, over};
  }
  State s(n, 1);
  for (int j = 0; j <= m; ++j) {
    s.x[j] = (m - j) * d.pitch;
    s.y[j] = r;
    s.vx[j] = -omega * r;
  }
  // the wrapped rollers at their links' rest length, inside their seats' clearance: no tension
  // behind the top roller at the start (the seats pass on a part of the span's tension only)
  const double rw = 0.5 * rest / std::sin(kPi / z);
  for (int k = 1; k <= wrap; ++k) {
    const double t = kPi / 2 + 2 * kPi * k / z;
    const std::size_t i = static_cast<std::size_t>(m + k);
    s.x[i] = rw * std::cos(t);
    s.y[i] = rw * std::sin(t);
    s.vx[i] = -omega * r * std::sin(t);
    s.vy[i] = omega * r * std::cos(t);
  }
  s.angle = {kPi / 2};
  s.speed = {omega};
  Integrator integ(model, {.step = d.step, .theta = d.theta});
  Result out;
  std::vector<double> far(bins, 0.0), centre(bins, 0.0);
  std::vector<int> count(bins, 0);
  out.min_far = INFINITY;
  out.max_far = -INFINITY;
  const int steps = static_cast<int>(std::lround(d.duration / d.step));
  const double tau = 2 * kPi / z;
  for (int k = 0; k < steps; ++k) {
    const StepReport rep = integ.step(model, s);
    if (!rep.converged) {
      ADD_FAILURE() << "step " << k << " did not converge";
      out.converged = false;
      break;
    }
    // the last seated roller: the span's node nearest the far end within 0.3 mm of the pitch
    // circle (a seated roller lies within its seat's clearance of it; the span's next node is a
    // pitch away from it, outside the circle by about p²/2R)
    std::size_t last = n;
    for (std::size_t i = 0; i < n && last == n; ++i)
      if (s.y[i] > 0 && std::hypot(s.x[i], s.y[i]) < r + 3e-4) last = i;
    if (last == n || last == 0) {
      ADD_FAILURE() << "no seated roller with a span at step " << k;
      out.converged = false;
      break;
    }
    if (d.hold_transverse) {
      for (std::size_t i = 0; i < last; ++i) {
        s.y[i] = s.y[last];
        s.vy[i] = s.vy[last];
      }
    }
    if (s.time < d.settle) continue;
    out.incline.push_back(std::atan2(s.y[last - 1] - s.y[last], s.x[last - 1] - s.x[last]));
    out.length.push_back(std::hypot(s.x[0] - s.x[last], s.y[0] - s.y[last]));
    out.far_lift = std::max(out.far_lift, std::abs(s.y[0] - r));
    // the far end's velocity along the line from it to the wheel's top
    const double ex = s.x[0], ey = s.y[0] - r, el = std::hypot(ex, ey);
    const double vfar = -(s.vx[0] * ex + s.vy[0] * ey) / el;
    double sum = 0.0;
    int cnt = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (s.x[i] > (d.span_from > 0 ? d.span_from : 2 * d.pitch) && s.y[i] > 0.5 * r)
        sum += -s.vx[i], ++cnt;
    double ph = std::fmod(s.angle[0] - kPi / 2, tau) / tau;
    if (ph < 0) ph += 1;
    const int b = std::min(bins - 1, static_cast<int>(ph * bins));
    out.phase.push_back(ph);
    out.span.push_back(sum / cnt);
    far[b] += vfar;
    centre[b] += sum / cnt;
    ++count[b];
    out.min_far = std::min(out.min_far, vfar);
    out.max_far = std::max(out.max_far, vfar);
  }
  for (int b = 0; b < bins; ++b) {
    out.far.push_back(far[b] / count[b]);
    out.centre.push_back(centre[b] / count[b]);
  }
  return out;
}

// The polygon's kinematics as the synchronous average sees it: the span straight and inextensible
// from the last seated roller — at φ from the top, φ = 2π phase/z (phase 0: a seat at the top; the
// next roller engages at phase ½, φ = −π/z), its centre at R (−sin φ, cos φ) — to a point the span
// passes through, whose distance from the roller is R ℓ(φ). The span moves at the rate its length
// grows as the wheel pulls it, v = ωR dℓ/dφ, so its mean over a phase bin is ωR Δℓ/Δφ exactly.
// The variation 1 − min/max of those means over `bins` equal bins.
template <class Length>
inline double binned_span_variation(int z, int bins, Length length) {
  const double tau = 2 * kPi / z;
  double lo = INFINITY, hi = -INFINITY;
  for (int b = 0; b < bins; ++b) {
    double p1 = static_cast<double>(b) / bins, p2 = static_cast<double>(b + 1) / bins;
    if (p1 >= 0.5) p1 -= 1, p2 -= 1;  // bins never straddle ½ (even bins)
    const double mean = (length(tau * p2) - length(tau * p1)) / (tau * (p2 - p1));
    lo = std::min(lo, mean);
    hi = std::max(hi, mean);
  }
  return 1 - lo / hi;
}

// The free far end: the span level, moving up and down with the roller (ℓ = sin φ + a constant),
// so v = ωR cos φ, the polygon's speed — its variation 1 − cos(π/z) unbinned.
inline double binned_variation(int z, int bins) {
  return binned_span_variation(z, bins, [](double phi) { return std::sin(phi); });
}

// The far end on rails at the top roller's height (Chordal::rails_from): the span pivots about
// the last roller on the rails, between the rails' wheel end x_e and x_e + p — taken at its mean,
// x_e + p/2 (the pivot's travel over a pitch moves the result by the order of (p/2L)²: at most
// 0.1 % of the variation, computed with the pivot hopping back a pitch as each roller reaches
// x_e, at z = 9–25 and 8 places of x_e within a pitch). ℓ is
// the distance to it: the span tilts by (R − R cos φ)/L, the roller's rise moves it along the span
// too, v = ωR (cos φ + sin φ (1 − cos φ) R/L) to first order, and the variation grows by the
// factor 1 + p/2L (at the engagement, φ = −π/z, R sin(π/z) = p/2).
inline double binned_variation(const Chordal& d, int bins) {
  if (!(d.rails_from > 0)) return binned_variation(d.teeth, bins);
  const double radius = 0.5 * d.pitch / std::sin(kPi / d.teeth);
  const double pivot = (d.rails_from + 0.5 * d.pitch) / radius;
  return binned_span_variation(d.teeth, bins, [pivot](double phi) {
    return std::hypot(pivot + std::sin(phi), 1 - std::cos(phi));
  });
}

// The span's speed averaged over `bins` equal bins of the tooth phase (NaN in a bin no sample
// fell in).
inline std::vector<double> simulated_profile(const Result& r, int bins) {
  std::vector<double> sum(bins, 0.0);
  std::vector<int> count(bins, 0);
  for (std::size_t k = 0; k < r.phase.size(); ++k) {
    const int b = std::min(bins - 1, static_cast<int>(r.phase[k] * bins));
    sum[b] += r.span[k];
    ++count[b];
  }
  for (int b = 0; b < bins; ++b) sum[b] = count[b] == 0 ? NAN : sum[b] / count[b];
  return sum;
}

// The variation 1 − min/max of bin means (NaN if a bin is empty).
inline double variation_of(const std::vector<double>& means) {
  double lo = INFINITY, hi = -INFINITY;
  for (const double m : means) {
    if (std::isnan(m)) return NAN;
    lo = std::min(lo, m);
    hi = std::max(hi, m);
  }
  return 1 - lo / hi;
}

// The span's speed averaged over `bins` phase bins, and its variation 1 − min/max.
inline double simulated_variation(const Result& r, int bins) {
  return variation_of(simulated_profile(r, bins));
}

// Validation (1)'s quasi-static set-up at z teeth (0.1 m/s, ISO seats with clearance, μ = 0.3;
// why: dynamics_chordal_test.cpp, PolygonalActionOnSeatsWithFriction).
inline Chordal quasi_static(int z, double chain_speed = 0.1) {
  Chordal d;
  d.teeth = z;
  d.clearance = true;
  d.seat_friction = 0.3;
  d.chain_speed = chain_speed;
  const int wrap = z / 2;
  d.duration = d.settle + (z - wrap - 2) * d.pitch / d.chain_speed;
  const double radius = 0.5 * d.pitch / std::sin(kPi / z);
  d.span_from = radius + d.pitch;  // the span's nodes clear of the wheel
  return d;
}

// The far end on rails (dynamics_chordal_slow_test.cpp, PolygonalActionWithTheFarEndOnRails): the
// rails from x_e = c p/(7.5 v) (+ `shift`), 48 links, the span's nodes those on the rails.
inline Chordal on_rails(Chordal d, double shift = 0.0) {
  const double wave_speed = std::sqrt(d.force * d.pitch / d.node_mass);
  d.rails_from = wave_speed * d.pitch / (7.5 * d.chain_speed) + shift;
  d.span_links = 48;
  d.span_from = d.rails_from;
  return d;
}

}  // namespace catena::dynamics::chordal
