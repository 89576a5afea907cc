// The pocket wheel's dynamic set-ups shared by its tests (pocket_test.cpp,
// pocket_discrete_gradient_test.cpp): a strand unwinding from a driver (docs/models/dynamics.md,
// "Pocket wheel: unwinding") and a link thrown radially onto a wheel. Ø18×64 on z = 8, centred at
// the origin, c = 0.1 mm, k_c = 1e8 N/m, links 0.42 kg/m at 1e8 N/m.
#pragma once

#include <cmath>
#include <cstddef>
#include <numbers>

#include "catena/dynamics/chain.hpp"
#include "catena/dynamics/pocket_wheel.hpp"

namespace catena::dynamics::testing {

struct PocketSetup {
  Sprocket wheel;
  Model model;
  State state;
  double polar = 0.0;  // [rad] a thrown link's leading joint's polar angle
};

// A strand at 1 kN comes in level over the top of a driver turning clockwise at 5 rad/s (the top
// runs along +x), wraps half a turn (node 21 at the top vertex, 8 joints in their pockets) and
// leaves level at the bottom towards −x (20 links), the strand's ends pulled by constant forces
// (1 kN and `slack`).
struct Unwinding {
  double slack = 200.0;            // [N] at the slack strand's end
  bool release = false;            // Sprocket::pocket_release
  double contact_damping = 0.0;    // [N·s/m] the pockets'
  double link_damping = 0.0;       // [N·s/m] the links'
  double mouth = 0.0;              // [m] Sprocket::pocket_mouth
  bool discrete_gradient = false;  // Sprocket::discrete_gradient
};
inline PocketSetup unwinding_setup(const Unwinding& o) {
  constexpr double kPi = std::numbers::pi;
  const double t = 0.064, d = 0.018, k = 1e8, ft = 1000.0;
  Sprocket w = pocket_wheel(t, d, 8, 0.0, 0.0, 1e-4, 1e8, o.contact_damping);
  w.pocket_release = o.release;
  w.pocket_mouth = o.mouth;
  w.discrete_gradient = o.discrete_gradient;
  w.driver = true;
  w.speed = -5.0;  // clockwise: the top runs along +x
  const double r = w.pitch_radius, d1 = w.pocket_angle, d2 = 2 * kPi / 8 - d1;
  const int c = 21, wrap = 8, bottom = 20;  // node c at the top vertex; link c is t − d (odd)
  const auto n = static_cast<std::size_t>(c + wrap + bottom + 1);
  Model m = uniform_chain(n, false, t, 0.42, k, o.link_damping, false);
  m.alternation = d;
  m.sprockets = {w};
  m.loads = {{.node = 0, .fx = -ft, .fy = 0.0}, {.node = n - 1, .fx = -o.slack, .fy = 0.0}};
  State s(n, 1);
  s.angle = {kPi / 2};  // vertex 0 at the top
  s.speed = {-5.0};
  double x = 0.0;
  for (int i = c; i >= 0; --i) {  // the tight strand, level through the top vertex
    s.x[i] = x;
    s.y[i] = r;
    s.vx[i] = 5 * r;
    if (i > 0) x -= m.rest_length(static_cast<std::size_t>(i - 1)) + ft / k;
  }
  double polar = kPi / 2;
  for (int j = 1; j <= wrap; ++j) {  // half a turn: δ2, δ1, … down to the bottom vertex
    polar -= (j % 2 == 1) ? d2 : d1;
    const auto i = static_cast<std::size_t>(c + j);
    s.x[i] = r * std::cos(polar);
    s.y[i] = r * std::sin(polar);
    s.vx[i] = 5 * s.y[i];
    s.vy[i] = -5 * s.x[i];
  }
  x = s.x[c + wrap];
  for (std::size_t i = c + wrap + 1; i < n; ++i) {  // the slack strand, level towards −x
    x -= m.rest_length(i - 1) + o.slack / k;
    s.x[i] = x;
    s.y[i] = -r;
    s.vx[i] = -5 * r;
  }
  return {w, m, s, 0.0};
}

// A free link's two joints radial onto a wheel (driven: inertia 0.2 kg·m², its angle an unknown;
// else a driver) turning at `spin` [rad/s] from ψ = 0: the leading joint `above` [m] over the
// mouth R + c/2, `off` [m] along the pitch circle from vertex 1, both moving in at `inward` [m/s],
// turning with the wheel and sliding along it at `slip` [m/s].
struct Fall {
  double off = 0.0, above = 0.0, inward = 0.0, spin = 0.0, slip = 0.0;
  bool driven = false;
  double contact_damping = 0.0, link_damping = 0.0;  // [N·s/m]
  bool body = true;                                  // Sprocket::pocket_body
  double friction = 0.0;                             // the pockets' μ
  bool discrete_gradient = false;
};
inline PocketSetup fall_setup(const Fall& o) {
  Model m = uniform_chain(2, false, 0.064, 0.42, 1e8, o.link_damping, false);
  m.alternation = 0.018;
  Sprocket w = pocket_wheel(0.064, 0.018, 8, 0.0, 0.0, 1e-4, 1e8, o.contact_damping);
  w.pocket_body = o.body;
  w.friction = o.friction;
  w.discrete_gradient = o.discrete_gradient;
  w.driver = !o.driven;
  w.inertia = 0.2;
  w.speed = o.spin;
  m.sprockets = {w};
  State s(2, 1);
  s.angle = {0.0};  // vertex 1 at δ1, vertex 2 at 2π/8
  s.speed = {o.spin};
  const double polar = w.pocket_angle + o.off / w.pitch_radius;
  const double start = w.pitch_radius + 0.5 * w.pocket_clearance + o.above;
  for (int i = 0; i < 2; ++i) {
    const double rho = start + i * m.rest_length(0);
    const double cx = std::cos(polar), sn = std::sin(polar);
    s.x[i] = rho * cx;
    s.y[i] = rho * sn;
    s.vx[i] = -o.inward * cx - o.spin * s.y[i] - o.slip * sn;
    s.vy[i] = -o.inward * sn + o.spin * s.x[i] + o.slip * cx;
  }
  return {w, m, s, polar};
}

}  // namespace catena::dynamics::testing
