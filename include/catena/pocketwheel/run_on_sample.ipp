// Implementation of sample_run_on (a template, so that the evaluator inlines).
#pragma once

#include <algorithm>
#include <iterator>

#include "catena/core/progress.hpp"

namespace catena::pocketwheel {

template <class Evaluate>
RunOnResult sample_run_on(const RunOnPlan& plan, const Sampling& sampling, Evaluate&& evaluate_at) {
  throw_if_any(validate(sampling));
  RunOnResult result;
  result.plan = plan;
  const double omega = sampling.omega;
  const double period_angle = plan.geometry.tooth_angle;
  result.period = period_angle / omega;
  const auto n = static_cast<std::size_t>(sampling.points);
  const bool free = plan.guide.kind == GuideKind::kNone;
  RunOnSeries& s = result.series;
  // Reserved, not resized: resize() would first write zeros over every series (at 10^6 points,
  // 40 MB written twice), only for the loop to overwrite them.
  s.phi.reserve(n);
  s.time.reserve(n);
  s.x.reserve(n);
  s.vx.reserve(n);
  s.ax.reserve(n);
  if (free) {
    s.vy.reserve(n);
    s.ay.reserve(n);
  }
  ProgressLoop loop(n, "points");
  for (std::size_t i = 0; i < n; ++i) {
    loop.step(i);
    // Both ends included; the last sample is exactly 2π/z.
    const double phi = i + 1 == n
                           ? period_angle
                           : period_angle * static_cast<double>(i) / static_cast<double>(n - 1);
    const PointKinematics k = evaluate_at(phi);
    s.phi.push_back(phi);
    s.time.push_back(phi / omega);
    s.x.push_back(k.x);
    s.vx.push_back(omega * k.dx);
    s.ax.push_back(omega * omega * k.d2x);
    if (free) {
      s.vy.push_back(omega * k.dy);
      s.ay.push_back(omega * omega * k.d2y);
    }
  }
  loop.step(n);
  if (sampling.strand_mass) {
    s.inertial_force.reserve(n);
    std::transform(s.ax.begin(), s.ax.end(), std::back_inserter(s.inertial_force),
                   [m = *sampling.strand_mass](double a) { return -m * a; });
  }
  result.extremes = extremes(plan, omega);
  return result;
}

}  // namespace catena::pocketwheel
