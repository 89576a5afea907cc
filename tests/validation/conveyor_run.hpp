// Test helper: validation (6b)'s conveyor (tests/dynamics/two_wheel_loops.hpp) stepped at a fixed
// step, with the tension of a link sampled at probes fixed in the conveyor's own frame — along its
// line of centres from the driver's centre, on the upper or the lower run — so that a level and an
// inclined conveyor are probed at the same points (tests/validation/dynamics_conveyor_*_test.cpp).
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

#include "../dynamics/period_mean.hpp"
#include "../dynamics/two_wheel_loops.hpp"
#include "catena/dynamics/chain.hpp"
#include "catena/dynamics/integrator.hpp"

namespace catena::dynamics::testing {

// A probe: the time series of the tension of the link whose middle is nearest `x` along the line
// of centres, on the upper (above the line) or the lower run, and of that link's speed along itself
// (its middle's velocity along the link, unsigned: the chain's speed there).
struct ConveyorProbe {
  double x = 0.0;
  bool upper = true;
  std::vector<double> tension;
  std::vector<double> speed;  // [m/s]
};

struct ConveyorRun {
  std::vector<double> time;
  std::vector<ConveyorProbe> probes;
  std::vector<double> friction_work;  // [J] the state's accumulated friction work after each step
  std::vector<double> load_work;      // [J] the state's accumulated work of the rails' loads
  // [J] the state's accumulated catch and discharge works (Guide::load_inertia; ≤ 0)
  std::vector<double> catch_work, discharge_work;
  // [J] the arriving material's kinetic energy so far (Guide::load_speed; part of catch_work)
  std::vector<double> arrival_work;
  // [J] the state's accumulated works of the links' dampers, the seats' and guides' contact
  // dampers, and the rest of the dissipative forces (drag, seat and hinge friction, take-up
  // dampers)
  std::vector<double> damper_work, contact_damping_work, other_work;
  // [J] the driver's accumulated work on the chain after each step: the chain's torque on it at
  // each step's θ point (Integrator::applied_torque) over the step's turn
  std::vector<double> drive_work;
  // [J] the loop's energy (Energy::total) at each of run_conveyor's `energy_at` times (after the
  // step that ends nearest it; NaN for a time no step ends near)
  std::vector<double> energy;
  // the sample (index into `time`, `friction_work`, `drive_work`) each `energy` was taken at: a
  // balance takes the works at the same sample as the energy (size_t(-1) where `energy` is NaN)
  std::vector<std::size_t> energy_sample;
};

// Validation (6b)'s probes, in the conveyor's frame: the slack side (the lower run between the
// driver and its guide), the tight side (the upper run between its guide and the driver), three
// points a quarter, half and three quarters along the upper guide, and its entry.
inline std::vector<ConveyorProbe> conveyor_probes(const Conveyor& d) {
  const double p = d.pitch, centre = d.span_links * p;
  const double x_lo = d.guide_gap * p, x_hi = (d.span_links - d.guide_gap) * p;
  const double guide = x_hi - x_lo;
  return {{1.5 * p, false, {}},
          {1.5 * p, true, {}},
          {x_lo + 0.25 * guide, true, {}},
          {x_lo + 0.5 * guide, true, {}},
          {x_lo + 0.75 * guide, true, {}},
          {centre - 1.5 * p, true, {}}};
}

// Steps conveyor `d` for `duration` at `step` (θ = 0.6), sampling every probe after each step. A
// step that does not converge fails the test and ends the run. `lift` raises the start by that
// much [m] along y (picometres: the same run perturbed at the Newton tolerance's level, for the
// level test's window means' scatter). The loop's energy is taken only at the times `energy_at`
// (a window's ends): at every step it would cost a third of the run.
inline ConveyorRun run_conveyor(const Conveyor& d, std::vector<ConveyorProbe> probes,
                                double duration, double step, double lift = 0.0,
                                const std::vector<double>& energy_at = {}) {
  Loop loop = conveyor_loop(d);
  const Model& model = loop.model;
  State& s = loop.state;
  for (double& y : s.y) y += lift;
  const std::size_t n = model.nodes();
  // the conveyor's frame: u along the line of centres (driver to tail), w across it (upper run +)
  const double ux = std::cos(d.incline), uy = -std::sin(d.incline);
  Integrator integ(model, {.step = step, .theta = 0.6});
  std::vector<double> tension(model.links());
  ConveyorRun out;
  out.probes = std::move(probes);
  out.energy.assign(energy_at.size(), NAN);
  out.energy_sample.assign(energy_at.size(), static_cast<std::size_t>(-1));
  const int steps = static_cast<int>(std::lround(duration / step));
  double drive_work = 0.0;
  for (int k = 0; k < steps; ++k) {
    const double angle0 = s.angle[0];
    const StepReport rep = integ.step(model, s);
    if (!rep.converged) {
      ADD_FAILURE() << "step " << k << " did not converge";
      break;
    }
    link_tensions(model, s, tension);
    for (ConveyorProbe& p : out.probes) {
      std::size_t best = 0;
      double gap = INFINITY;
      for (std::size_t j = 0; j < n; ++j) {
        const std::size_t e = (j + 1) % n;
        const double xm = 0.5 * (s.x[j] + s.x[e]), ym = 0.5 * (s.y[j] + s.y[e]);
        const double u = xm * ux + ym * uy, w = -xm * uy + ym * ux;
        if ((w > 0.0) != p.upper) continue;
        if (std::abs(u - p.x) < gap) {
          gap = std::abs(u - p.x);
          best = j;
        }
      }
      p.tension.push_back(tension[best]);
      const std::size_t e = (best + 1) % n;
      const double lx = s.x[e] - s.x[best], ly = s.y[e] - s.y[best];
      const double vx = 0.5 * (s.vx[best] + s.vx[e]), vy = 0.5 * (s.vy[best] + s.vy[e]);
      p.speed.push_back(std::abs(vx * lx + vy * ly) / std::hypot(lx, ly));
    }
    out.time.push_back(s.time);
    out.friction_work.push_back(s.friction_work);
    out.load_work.push_back(s.load_work);
    out.catch_work.push_back(s.load_catch_work);
    out.discharge_work.push_back(s.load_discharge_work);
    out.arrival_work.push_back(s.load_arrival_work);
    out.damper_work.push_back(s.damper_work);
    out.contact_damping_work.push_back(s.contact_damping_work);
    out.other_work.push_back(s.drag_work + s.seat_friction_work + s.hinge_work +
                             s.takeup_damper_work);
    drive_work -= integ.applied_torque()[0] * (s.angle[0] - angle0);
    out.drive_work.push_back(drive_work);
    for (std::size_t i = 0; i < energy_at.size(); ++i) {
      if (std::abs(s.time - energy_at[i]) < 0.5 * step) {
        out.energy[i] = energy(model, s).total();
        out.energy_sample[i] = out.time.size() - 1;
      }
    }
  }
  return out;
}

// The steady means of a conveyor's run (the inclined and the loaded conveyor's tests): validation
// (6b)'s probes' mean tensions and the works' mean powers over the whole tooth periods after t0.
struct ConveyorMeans {
  double slack = 0.0, tight = 0.0, upper_entry = 0.0;
  double along[3] = {0.0, 0.0, 0.0};  // a quarter, half and three quarters along the upper guide
  double along_x[3] = {0.0, 0.0, 0.0};
  double friction_power = 0.0;  // [W] −(friction work)/time over the window
  double drive_power = 0.0;     // [W] the driver's work on the chain/time over the window
  double load_power = 0.0;      // [W] the rails' loads' work on the chain/time over the window
  // [W] −(the catch's work)/time and −(the discharge's work)/time over the window (load_inertia)
  double catch_power = 0.0, discharge_power = 0.0;
  // [W] the arriving material's kinetic energy/time over the window (Guide::load_speed): the
  // catch's loss is catch_power + arrival_power
  double arrival_power = 0.0;
  // The work balance over the window, between the samples its ends' energies were taken at: each
  // term the power [W] it takes from the chain, −(its work)/time (the drive's and the loads' the
  // power they give), `energy_rate` the loop's energy change/time and `numerical` the θ-method's
  // rest, −(ΔE − Σ the works)/time (docs/models/dynamics.md, "Work balance").
  struct Balance {
    double drive = 0.0, load = 0.0, friction = 0.0, damper = 0.0, contact_damping = 0.0;
    double other = 0.0, load_catch = 0.0, discharge = 0.0, energy_rate = 0.0, numerical = 0.0;
  } balance;
};

// Conveyor `d` run for `duration` at h = 0.1 ms, its means over the whole tooth periods after
// t0 (0.4 s: the window's choice, tests/validation/dynamics_conveyor_incline_test.cpp).
inline ConveyorMeans conveyor_means(const Conveyor& d, double duration = 2.0, double t0 = 0.4) {
  const double step = 1e-4;
  const double period = 2 * std::numbers::pi / (d.teeth * d.omega);
  const long steps = std::lround(duration / step);
  // the window's ends (as below, from the last step's time, here its nominal one)
  const double t_last = static_cast<double>(steps) * step;
  const ConveyorRun r = run_conveyor(d, conveyor_probes(d), duration, step, 0.0,
                                     {t0, t0 + std::floor((t_last - t0) / period) * period});
  EXPECT_EQ(r.time.size(), static_cast<std::size_t>(steps));
  ConveyorMeans m;
  if (r.time.empty() || r.time.back() < t0 + 0.1) return m;
  auto mean = [&](std::size_t k) {
    return mean_over_periods(r.time, r.probes[k].tension, t0, period);
  };
  m.slack = mean(0);
  m.tight = mean(1);
  for (std::size_t k = 0; k < 3; ++k) {
    m.along[k] = mean(k + 2);
    m.along_x[k] = r.probes[k + 2].x;
  }
  m.upper_entry = mean(5);
  const double t_end = t0 + std::floor((r.time.back() - t0) / period) * period;
  double w0 = 0.0, w1 = 0.0, p0 = 0.0, p1 = 0.0, l0 = 0.0, l1 = 0.0;
  double c0 = 0.0, c1 = 0.0, d0 = 0.0, d1 = 0.0, a0 = 0.0, a1 = 0.0;
  for (std::size_t k = 0; k < r.time.size(); ++k) {
    if (r.time[k] <= t0) w0 = r.friction_work[k], p0 = r.drive_work[k], l0 = r.load_work[k];
    if (r.time[k] <= t_end) w1 = r.friction_work[k], p1 = r.drive_work[k], l1 = r.load_work[k];
    if (r.time[k] <= t0) c0 = r.catch_work[k], d0 = r.discharge_work[k], a0 = r.arrival_work[k];
    if (r.time[k] <= t_end) c1 = r.catch_work[k], d1 = r.discharge_work[k], a1 = r.arrival_work[k];
  }
  m.arrival_power = (a1 - a0) / (t_end - t0);
  m.catch_power = -(c1 - c0) / (t_end - t0);
  m.discharge_power = -(d1 - d0) / (t_end - t0);
  m.friction_power = -(w1 - w0) / (t_end - t0);
  m.drive_power = (p1 - p0) / (t_end - t0);
  m.load_power = (l1 - l0) / (t_end - t0);
  const std::size_t a = r.energy_sample[0], b = r.energy_sample[1];
  EXPECT_TRUE(a < r.time.size() && b < r.time.size() && a < b) << "the window's energies";
  if (!(a < r.time.size() && b < r.time.size() && a < b)) return m;
  const double span = r.time[b] - r.time[a];
  auto rate = [&](const std::vector<double>& work) { return (work[b] - work[a]) / span; };
  ConveyorMeans::Balance& e = m.balance;
  e.drive = rate(r.drive_work);
  e.load = rate(r.load_work);
  e.friction = -rate(r.friction_work);
  e.damper = -rate(r.damper_work);
  e.contact_damping = -rate(r.contact_damping_work);
  e.other = -rate(r.other_work);
  e.load_catch = -rate(r.catch_work);
  e.discharge = -rate(r.discharge_work);
  e.energy_rate = (r.energy[1] - r.energy[0]) / span;
  e.numerical = -(e.energy_rate - e.drive - e.load + e.friction + e.damper + e.contact_damping +
                  e.other + e.load_catch + e.discharge);
  return m;
}

}  // namespace catena::dynamics::testing
