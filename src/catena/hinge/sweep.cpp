#include "catena/hinge/sweep.hpp"

#include <algorithm>
#include <boost/math/tools/minima.hpp>
#include <cmath>

#include "catena/core/progress.hpp"
#include "catena/hinge/kinematics.hpp"

namespace catena::hinge {

double max_pitch_change(const Hinge& hinge, double r2, int samples) {
  const double phi_max = 2.0 * gamma_max(hinge);
  auto magnitude = [&](double phi) { return std::abs(pitch_change(hinge, r2, phi)); };
  int best = 0;
  double worst = 0.0;
  for (int i = 0; i < samples; ++i) {
    const double v = magnitude(phi_max * i / (samples - 1));
    if (v > worst) worst = v, best = i;
  }
  if (best > 0 && best + 1 < samples) {  // an interior maximum: refine it (Brent)
    const double step = phi_max / (samples - 1);
    const auto [at, value] = boost::math::tools::brent_find_minima(
        [&](double phi) { return -magnitude(phi); }, (best - 1) * step, (best + 1) * step, 50);
    (void)at;
    worst = std::max(worst, -value);
  }
  return worst;
}

Sweep sweep(const Hinge& hinge, const Loads& loads, int count) {
  std::vector<Issue> issues = validate(hinge);
  if (hinge.face != Face::kConcave) {
    issues.push_back({"face", "flat", "concave faces: the sweep chooses R2 by eq. (6)"});
  }
  if (count < 2) issues.push_back({"count", std::to_string(count), "at least 2 values of R1"});
  throw_if_any(issues);
  const double d = hinge.pin_diameter;
  const double a = hinge.half_thickness;
  const double lo = 0.5 * (0.5 * d - a) * 1.001;  // the R1 circle must cut the d circle
  const double hi = r1_max(d, a, gamma_max(hinge)) * 0.999;
  Sweep out;
  ProgressLoop loop(static_cast<std::size_t>(count), "values of R1");
  for (int i = 0; i < count; ++i) {
    loop.step(static_cast<std::size_t>(i));
    Hinge h = hinge;
    h.roller_radius = 0.0;
    h.plate_radius = lo + (hi - lo) * i / (count - 1);
    const Synthesis s = synthesize(h, loads);
    SweepRow row;
    row.r1 = h.plate_radius;
    row.r2 = s.r2;
    row.psi1_max = s.psi1_max;
    row.effective_radius = conformal_radius(row.r1, row.r2);
    row.contact_stress = s.contact_stress;
    row.rolling_limit = s.rolling_limit;
    row.a_min = s.a_min;
    row.max_pitch_change = max_pitch_change(h, s.r2);
    row.face_margin = s.face_margin;
    row.feasible = std::none_of(
        s.diagnostics.begin(), s.diagnostics.end(),
        [](const Diagnostic& g) { return g.severity == Diagnostic::Severity::kInfeasible; });
    out.rows.push_back(row);
    loop.step(static_cast<std::size_t>(i) + 1);
  }
  out.criterion =
      "feasible row with the lowest Hertz contact stress (largest effective radius R* = R1R2/(R2 "
      "- R1))";
  for (std::size_t i = 0; i < out.rows.size(); ++i) {
    if (!out.rows[i].feasible) continue;
    if (!out.best || out.rows[i].effective_radius > out.rows[*out.best].effective_radius)
      out.best = i;
  }
  return out;
}

}  // namespace catena::hinge
