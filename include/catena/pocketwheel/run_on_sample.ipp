// Implementation of sample_run_on (a template, so that the evaluator inlines).
#pragma once

#include <algorithm>

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
  s.phi.resize(n);
  s.time.resize(n);
  s.x.resize(n);
  s.vx.resize(n);
  s.ax.resize(n);
  if (free) {
    s.vy.resize(n);
    s.ay.resize(n);
  }
  for (std::size_t i = 0; i < n; ++i) {
    // Both ends included; the last sample is exactly 2π/z.
    const double phi = i + 1 == n
                           ? period_angle
                           : period_angle * static_cast<double>(i) / static_cast<double>(n - 1);
    const PointKinematics k = evaluate_at(phi);
    s.phi[i] = phi;
    s.time[i] = phi / omega;
    s.x[i] = k.x;
    s.vx[i] = omega * k.dx;
    s.ax[i] = omega * omega * k.d2x;
    if (free) {
      s.vy[i] = omega * k.dy;
      s.ay[i] = omega * omega * k.d2y;
    }
  }
  if (sampling.strand_mass) {
    s.inertial_force.resize(n);
    std::transform(s.ax.begin(), s.ax.end(), s.inertial_force.begin(),
                   [m = *sampling.strand_mass](double a) { return -m * a; });
  }
  result.extremes = extremes(plan, omega);
  return result;
}

}  // namespace catena::pocketwheel
