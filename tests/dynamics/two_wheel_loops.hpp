// Test and benchmark helper: the two 12B loops over two equal wheels that tests and benchmarks
// step — the conveyor of validation (6b) on its guides and the benchmarks' two-sprocket drive —
// built in one place so that a test and the benchmark it stands for run the same model from the
// same start. Header-only: tests/ includes it as "two_wheel_loops.hpp", bench/ as
// "../tests/dynamics/two_wheel_loops.hpp".
#pragma once

#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

#include "catena/dynamics/integrator.hpp"

namespace catena::dynamics::testing {

// Two equal ISO 606 wheels (`teeth` teeth, the chain's pitch, roller diameter and inner width)
// `span` pitches apart on the x axis, seats of k_c = `contact_stiffness`, c_c = `contact_damping`:
// the driver at the origin turning counter-clockwise at `omega`, the driven wheel at (span · p, 0)
// with inertia `inertia` and load torque `load` — the pair every loop here and the drive's
// validation (tests/validation/dynamics_drive_test.cpp) run on.
struct EqualWheels {
  double pitch = 0.01905;          // [m] 12B
  double roller = 0.01207;         // [m] d1
  double width = 0.01168;          // [m] b1
  int teeth = 20;                  // z
  int span = 90;                   // pitches between the centres
  double omega = 30.0;             // [rad/s] the driver
  double inertia = 0.05;           // [kg·m²] the driven wheel
  double load = 0.0;               // [N·m] on the driven wheel
  double contact_stiffness = 2e8;  // [N/m]
  double contact_damping = 800.0;  // [N·s/m]
};
inline std::vector<Sprocket> equal_wheels(const EqualWheels& d) {
  Sprocket a = iso606_sprocket(d.pitch, d.roller, d.width, d.teeth, 0.0, 0.0, d.contact_stiffness,
                               d.contact_damping);
  a.driver = true;
  a.speed = d.omega;
  Sprocket b = iso606_sprocket(d.pitch, d.roller, d.width, d.teeth, d.span * d.pitch, 0.0,
                               d.contact_stiffness, d.contact_damping);
  b.inertia = d.inertia;
  b.load_torque = d.load;
  return {a, b};
}

// The conveyor loop of validation (6b) (examples/dynamics_conveyor.toml): a closed 12B chain over
// two z-tooth wheels `span_links` pitches apart, the driver at `omega`, a free tail idler,
// gravity; both runs carried by level rails (the rollers on top, with Coulomb friction) from
// `guide_gap` pitches after one wheel to as many before the other, at the mean height of the
// polygon's tangent point, R sin(π/z)/(π/z), each with a lead-in arc at its entry end. Each rail
// is cut into `pieces` collinear pieces end to end (1: the example's one rail a run; 0: no
// guides at all — the loop sags under gravity). With `incline` β ≠ 0 the whole loop — wheels,
// rails, lead-ins and chain — is turned by −β about the driver's centre, gravity staying −y: the
// tail wheel below the driver and both runs' rails inclined at β, rising towards the driver (β < 0:
// falling towards it), the runs still ±level from the line of centres. With `load_per_metre` q_L >
// 0 the upper run's rail pieces carry that conveyed load (Guide::load_per_metre;
// docs/models/dynamics.md, "A conveyed load"), its lead-in none.
struct Conveyor {
  int teeth = 16;
  int span_links = 60;
  int guide_gap = 3;             // pitches from each wheel's tangent point to the guide's end
  int pieces = 1;                // collinear pieces each rail is cut into (0: no guides)
  double pitch = 0.01905;        // [m] 12B
  double roller = 0.01207;       // [m] d1
  double width = 0.01168;        // [m] b1
  double mass_per_metre = 1.25;  // [kg/m]
  double node_mass = 0.0;        // [kg] 0: mass_per_metre × pitch (the benchmarks give 0.0238)
  double stiffness = 5e7;        // [N/m] per link
  double pretension = 20.0;      // [N]
  double omega = 5.0;            // [rad/s] driver
  double inertia = 0.002;        // [kg·m²] tail idler
  double friction = 0.3;         // μ on the guides
  double gravity = 9.81;         // [m/s²]
  double incline = 0.0;          // [rad] β, the line of centres rising towards the driver
  double load_per_metre = 0.0;   // [kg/m] q_L on the upper (carrying) run's rail pieces
  bool load_inertia = false;     // the load's mass moves with the chain (Guide::load_inertia)
  double load_speed = 0.0;       // [m/s] u, the material's arriving speed (Guide::load_speed)
};

struct Loop {
  Model model;
  State state;
  double level = 0.0;  // [m] the height of the runs' roller centres on the rails (±level)
};

// Turns a loop's wheels, guides and chain (positions, velocities, the wheels' seat angles) by
// `phi` counter-clockwise about the origin: the same loop in a frame turned against gravity.
inline void turn_loop(Model& model, State& s, double phi) {
  const double c = std::cos(phi), sn = std::sin(phi);
  auto turn = [&](double& x, double& y) {
    const double u = x;
    x = c * u - sn * y;
    y = sn * u + c * y;
  };
  for (Sprocket& w : model.sprockets) {
    turn(w.centre_x, w.centre_y);
    turn(w.takeup_dx, w.takeup_dy);
  }
  for (Guide& g : model.guides) {
    turn(g.x0, g.y0);
    turn(g.x1, g.y1);
    turn(g.centre_x, g.centre_y);
    g.start_angle += phi;
    g.end_angle += phi;
  }
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    turn(s.x[i], s.y[i]);
    turn(s.vx[i], s.vy[i]);
  }
  for (double& a : s.angle) a += phi;
}

// The model and its start: every roller seated on the wheels at the pitch-line speed, the
// straight runs lifted onto the rails' level. Guides in the order upper run's pieces (left to
// right), lower run's pieces, upper lead-in, lower lead-in.
inline Loop conveyor_loop(const Conveyor& d) {
  constexpr double kPi = std::numbers::pi;
  constexpr double kContactStiffness = 2e8;  // [N/m] the seats, as in validation (6)
  constexpr double kContactDamping = 800.0;  // [N·s/m]
  constexpr double kNose = 0.05;             // [m] the lead-in arc's radius
  const int z = d.teeth, m = d.span_links;
  const auto n = static_cast<std::size_t>(z + 2 * m);
  Loop out;
  Model& model = out.model;
  const double node_mass = d.node_mass > 0.0 ? d.node_mass : d.mass_per_metre * d.pitch;
  model = uniform_chain(n, true, d.pitch - d.pretension / d.stiffness, node_mass, d.stiffness,
                        100.0, false);
  model.gravity_y = -d.gravity;
  const double centre = m * d.pitch;
  model.sprockets = equal_wheels({.pitch = d.pitch,
                                  .roller = d.roller,
                                  .width = d.width,
                                  .teeth = z,
                                  .span = m,
                                  .omega = d.omega,
                                  .inertia = d.inertia,
                                  .contact_stiffness = kContactStiffness,
                                  .contact_damping = kContactDamping});
  const Sprocket& a = model.sprockets[0];
  // the guides carry the runs at the mean height of the polygon's tangent point (the seat at the
  // top swings through ±π/z): the chain runs level onto the wheels on average
  const double r = 0.5 * d.roller, radius = a.pitch_radius;
  const double level = radius * std::sin(kPi / z) / (kPi / z);
  out.level = level;
  const double x_lo = d.guide_gap * d.pitch, x_hi = (m - d.guide_gap) * d.pitch;
  if (d.pieces > 0) {
    for (const double y : {level, -level}) {
      for (int k = 0; k < d.pieces; ++k) {
        Guide g;  // left to right: the free side (rollers) on top, on both runs
        g.x0 = x_lo + (x_hi - x_lo) * k / d.pieces;
        g.x1 = x_lo + (x_hi - x_lo) * (k + 1) / d.pieces;
        g.y0 = g.y1 = y - r;
        g.roller_radius = r;
        g.contact_stiffness = 1e7;
        g.contact_damping = 100.0;
        g.friction = d.friction;
        if (y > 0.0) g.load_per_metre = d.load_per_metre;  // the carrying run's
        g.load_inertia = y > 0.0 && d.load_inertia && d.load_per_metre > 0.0;
        if (g.load_inertia) g.load_speed = d.load_speed;
        model.guides.push_back(g);
      }
    }
    // Each run's entry end is a rounded nose — a convex arc of radius 50 mm tangent to the rail,
    // falling away over 60° — as real guides have a lead-in: a roller arriving a little low (the
    // polygon swings the free span up and down) rides up it instead of striking the rail's end.
    for (const bool upper : {true, false}) {
      const Guide& rail = model.guides[upper ? 0 : static_cast<std::size_t>(d.pieces)];
      Guide nose = rail;
      nose.kind = Guide::Kind::kArc;
      nose.load_per_metre = 0.0;  // the rail carries the load, not its lead-in
      nose.load_inertia = false;
      nose.load_speed = 0.0;
      nose.radius = kNose;
      nose.centre_x = upper ? x_hi : x_lo;  // the upper run travels −x and enters at x_hi
      nose.centre_y = rail.y0 - kNose;
      nose.start_angle = upper ? kPi / 6 : kPi / 2;
      nose.end_angle = upper ? kPi / 2 : 5 * kPi / 6;
      model.guides.push_back(nose);
    }
  }
  out.state = two_sprocket_loop(z, m, d.pitch, radius, d.omega);
  State& s = out.state;
  for (std::size_t i = 0; i < n; ++i) {  // the straight runs start on the guides' level
    if (s.x[i] > 0.5 * d.pitch && s.x[i] < centre - 0.5 * d.pitch)
      s.y[i] = s.y[i] > 0 ? level : -level;
  }
  if (d.incline != 0.0) turn_loop(model, s, -d.incline);
  return out;
}

// The benchmarks' drive (bench/dynamics_bench.cpp, BM_DynamicsTwoSprocketDrive): a 200-link 12B
// loop over two equal sprockets (z = 20, 90 pitches apart, the polygons in phase), the driver at
// 30 rad/s (1.8 m/s), the driven wheel with J = 0.05 kg·m² and a 20 N·m load, gravity in the
// plane, links 5e7 N/m and 100 N·s/m stretched 1e-3 at the start, contacts k_c = 2e8 N/m,
// c_c = 800 N·s/m; started with every roller seated and moving at the pitch-line speed.
// `hinge_arm` > 0: with hinge friction of that arm (docs/models/dynamics.md, "Hinges").
inline Loop benchmark_drive(double hinge_arm = 0.0) {
  constexpr int kTeeth = 20, kSpan = 90;
  constexpr double kPitch = 0.01905, kOmega = 30.0;
  const auto n = static_cast<std::size_t>(kTeeth + 2 * kSpan);
  Loop out;
  Model& m = out.model;
  m = uniform_chain(n, true, kPitch * (1.0 - 1e-3), 0.0238, 5e7, 100.0, false);
  m.gravity_y = -9.81;
  m.sprockets = equal_wheels({.pitch = kPitch,
                              .roller = 0.01207,
                              .width = 0.01168,
                              .teeth = kTeeth,
                              .span = kSpan,
                              .omega = kOmega,
                              .inertia = 0.05,
                              .load = 20.0,
                              .contact_stiffness = 2e8,
                              .contact_damping = 800.0});
  m.hinge.arm = hinge_arm;
  out.state = two_sprocket_loop(kTeeth, kSpan, kPitch, m.sprockets[0].pitch_radius, kOmega);
  return out;
}

}  // namespace catena::dynamics::testing
