// Test helper: the loop the seat laws' Newton tests take (seat_line_law_test.cpp,
// seat_discrete_gradient_test.cpp), built in one place so that each law's matrix is checked at the
// same pressed start.
#pragma once

#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

#include "catena/dynamics/integrator.hpp"
#include "two_wheel_loops.hpp"

namespace catena::dynamics::testing {

// A closed 12B loop over two z = 12 wheels 10 pitches apart, the driver at 13 rad/s, the driven
// wheel free (J = 0.01 kg·m², load torque `load`), the links 0.1 % short (about 950 N of tension),
// every seated roller pressed 0 … 3 µm into its seat (drawn from one seeded generator: the same
// depths whatever the laws). What the tests vary is the seats' law and options: damping c_c,
// Coulomb friction μ, the discrete gradient, and the line law (of the chain's inner width b1)
// instead of the linear penalty of k_c = 2e8 N/m.
struct PressedLoop {
  double contact_damping = 800.0;  // [N·s/m]
  double friction = 0.0;           // μ in the seats
  bool discrete_gradient = false;  // Sprocket::discrete_gradient
  bool line_law = false;           // use_line_law on both wheels
  double load = 0.0;               // [N·m] on the driven wheel
};
inline Loop pressed_loop(const PressedLoop& d) {
  constexpr int kTeeth = 12, kSpan = 10;
  constexpr double kOmega = 13.0;
  const EqualWheels wheels{.teeth = kTeeth,
                           .span = kSpan,
                           .omega = kOmega,
                           .inertia = 0.01,
                           .load = d.load,
                           .contact_damping = d.contact_damping};
  const auto n = static_cast<std::size_t>(kTeeth + 2 * kSpan);
  Loop l;
  l.model = uniform_chain(n, true, wheels.pitch * (1 - 1e-3), 0.0238, 5e7, 100.0, false);
  l.model.sprockets = equal_wheels(wheels);
  for (Sprocket& w : l.model.sprockets) {
    if (d.line_law) use_line_law(w, wheels.width);
    w.friction = d.friction;
    w.discrete_gradient = d.discrete_gradient;
  }
  const Sprocket& w0 = l.model.sprockets[0];
  l.state = two_sprocket_loop(kTeeth, kSpan, wheels.pitch, w0.pitch_radius, kOmega);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> depth(0.0, 3e-6);
  const double clearance = w0.seat_radius - w0.roller_radius;
  for (std::size_t i = 0; i < n; ++i) {
    for (const Sprocket& w : l.model.sprockets) {
      const double dx = l.state.x[i] - w.centre_x, dy = l.state.y[i] - w.centre_y;
      const double r = std::hypot(dx, dy);
      if (std::abs(r - w.pitch_radius) > 1e-9) continue;
      const double in = clearance + depth(rng);
      l.state.x[i] -= in * dx / r;
      l.state.y[i] -= in * dy / r;
    }
  }
  return l;
}

// The Newton tests' iterate on a pressed loop: every node one explicit step on, x + h v, jittered
// by ±1 µm (seed 3: the same draws whatever the laws) so that rollers enter and leave their seats
// over the step, and the driven wheel's angle ψ + h ω + `turn` last (`size` = 2 n + 1 unknowns).
inline std::vector<double> pressed_iterate(const Loop& l, std::size_t size, double h, double turn) {
  const std::size_t n = l.model.nodes();
  std::vector<double> u(size);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> jitter(-1e-6, 1e-6);
  for (std::size_t i = 0; i < n; ++i) {
    u[2 * i] = l.state.x[i] + h * l.state.vx[i] + jitter(rng);
    u[2 * i + 1] = l.state.y[i] + h * l.state.vy[i] + jitter(rng);
  }
  u[2 * n] = l.state.angle[1] + h * l.state.speed[1] + turn;
  return u;
}

}  // namespace catena::dynamics::testing
