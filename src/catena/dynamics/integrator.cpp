// The energy-conserving implicit midpoint step with Newton's method on the chain's block
// tridiagonal Jacobian (include/catena/dynamics/integrator.hpp; docs/models/dynamics.md).
#include "catena/dynamics/integrator.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace catena::dynamics {

std::vector<Issue> validate(const IntegratorOptions& options) {
  std::vector<Issue> out;
  check::finite_positive(out, "step", options.step, "s");
  if (options.max_iterations < 1 || options.max_iterations > 1000) {
    out.push_back(
        {"max_iterations", std::to_string(options.max_iterations), "an integer in [1, 1000]"});
  }
  if (!std::isfinite(options.tolerance) || !(options.tolerance >= 1e-15) ||
      !(options.tolerance <= 1e-2)) {
    out.push_back({"tolerance", check::format_si(options.tolerance, ""),
                   "a number in [1e-15, 1e-2] (a fraction of the pitch)"});
  }
  if (!std::isfinite(options.theta) || !(options.theta >= 0.5) || !(options.theta <= 1.0)) {
    out.push_back({"theta", check::format_si(options.theta, ""), "a number in [0.5, 1]"});
  }
  return out;
}

namespace {
std::size_t checked_nodes(const Model& model, const IntegratorOptions& options) {
  std::vector<Issue> issues = validate(model);
  std::vector<Issue> more = validate(options);
  issues.insert(issues.end(), more.begin(), more.end());
  throw_if_any(issues);
  return model.nodes();
}
}  // namespace

Integrator::Integrator(const Model& model, IntegratorOptions options)
    : options_(options),
      solver_(checked_nodes(model, options), model.closed),
      ux_(model.nodes()),
      uy_(model.nodes()),
      l0_(model.links()),
      delta_(model.nodes()) {}

double Integrator::assemble(const Model& model, const State& s, bool jacobian) {
  const std::size_t n = model.nodes();
  const double h = options_.step;
  const double th = options_.theta;
  const double k = model.axial_stiffness;
  const double c = model.axial_damping;
  const double p = model.pitch;
  // Residual R(u) = (m/hθ)(u − x₀ − h v₀) + α m (u − x₀) − h (Σ f + m g) and its Jacobian
  // J = (m/hθ + α m) I + h Σ A; the system is J δ = −R.
  for (std::size_t i = 0; i < n; ++i) {
    const double m = model.mass[i];
    const double dx = ux_[i] - s.x[i], dy = uy_[i] - s.y[i];
    const double inertia = m / (h * th);
    if (jacobian) {
      solver_.diag[i] = {inertia + model.drag * m, 0.0, 0.0, inertia + model.drag * m};
      solver_.lower[i] = {};
      solver_.upper[i] = {};
    }
    solver_.rhs[i] = {
        -(inertia * (dx - h * s.vx[i]) + model.drag * m * dx - h * m * model.gravity_x),
        -(inertia * (dy - h * s.vy[i]) + model.drag * m * dy - h * m * model.gravity_y)};
  }
  for (std::size_t j = 0; j < model.links(); ++j) {
    const std::size_t a = j, b = (j + 1) % n;
    const double d0x = s.x[b] - s.x[a], d0y = s.y[b] - s.y[a];
    const double d1x = ux_[b] - ux_[a], d1y = uy_[b] - uy_[a];
    const double l0 = l0_[j];
    const double l1 = std::sqrt(
        d1x * d1x + d1y * d1y);  // sqrt, not hypot: no overflow at chain scales, and faster
    const double lt = (1.0 - th) * l0 + th * l1;
    const double mx = (1.0 - th) * d0x + th * d1x, my = (1.0 - th) * d0y + th * d1y;
    // φ = [k (l_θ − p) + c (l₁ − l₀)/h] / l_θ; the force on node a is φ d_θ, on node b −φ d_θ.
    // At θ = ½ the work over the step is exactly the change of ½ k (l − p)² plus the damper's
    // loss c (l₁ − l₀)²/h (Simo & Tarnow 1992).
    const double phi = (k * (lt - p) + c * (l1 - l0) / h) / lt;
    const double fx = h * phi * mx, fy = h * phi * my;
    solver_.rhs[a].x += fx;
    solver_.rhs[a].y += fy;
    solver_.rhs[b].x -= fx;
    solver_.rhs[b].y -= fy;
    if (!jacobian) continue;
    // A = ∂(φ d_θ)/∂d₁ = θ φ I + d_θ ⊗ (∂φ/∂l₁) d₁/l₁,  ∂φ/∂l₁ = [(k θ + c/h) − θ φ] / l_θ.
    const double dphi = ((k * th + c / h) - th * phi) / lt;
    const double gx = l1 > 0.0 ? dphi * d1x / l1 : 0.0;
    const double gy = l1 > 0.0 ? dphi * d1y / l1 : 0.0;
    const Mat2 hA{h * (th * phi + mx * gx), h * mx * gy, h * my * gx, h * (th * phi + my * gy)};
    Mat2& daa = solver_.diag[a];
    Mat2& dbb = solver_.diag[b];
    daa = {daa.a + hA.a, daa.b + hA.b, daa.c + hA.c, daa.d + hA.d};
    dbb = {dbb.a + hA.a, dbb.b + hA.b, dbb.c + hA.c, dbb.d + hA.d};
    // block (a, b) is upper[a] (the corner upper[n−1] when b = 0); block (b, a) is lower[b].
    solver_.upper[a] = {-hA.a, -hA.b, -hA.c, -hA.d};
    solver_.lower[b] = {-hA.a, -hA.b, -hA.c, -hA.d};
  }
  if (!model.pinned.empty()) {
    for (std::size_t i = 0; i < n; ++i) {
      if (!model.is_pinned(i)) continue;
      solver_.rhs[i] = {};
      if (!jacobian) continue;
      solver_.diag[i] = {1.0, 0.0, 0.0, 1.0};
      solver_.lower[i] = {};
      solver_.upper[i] = {};
      if (model.closed || i + 1 < n) solver_.lower[(i + 1) % n] = {};
      if (model.closed || i > 0) solver_.upper[(i + n - 1) % n] = {};
    }
  }
  double norm2 = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    norm2 += solver_.rhs[i].x * solver_.rhs[i].x + solver_.rhs[i].y * solver_.rhs[i].y;
  }
  return norm2;
}

StepReport Integrator::step(const Model& model, State& s) {
  const std::size_t n = model.nodes();
  const double h = options_.step;
  const double th = options_.theta;
  const double tol = options_.tolerance * model.pitch;
  constexpr int kMaxBacktracks = 12;

  for (std::size_t j = 0; j < model.links(); ++j) {
    const std::size_t b = (j + 1) % n;
    const double dx = s.x[b] - s.x[j], dy = s.y[b] - s.y[j];
    l0_[j] = std::sqrt(dx * dx + dy * dy);
  }
  // Predictor: constant velocity.
  for (std::size_t i = 0; i < n; ++i) {
    ux_[i] = s.x[i] + h * s.vx[i];
    uy_[i] = s.y[i] + h * s.vy[i];
  }

  StepReport report;
  double norm2 = assemble(model, s, true);
  for (int iter = 1; iter <= options_.max_iterations; ++iter) {
    report.solve = solver_.solve(delta_);
    report.iterations = iter;
    if (report.solve != SolveStatus::kSolved) return report;
    double correction = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      if (!std::isfinite(delta_[i].x) || !std::isfinite(delta_[i].y)) {
        report.solve = SolveStatus::kSingularPivot;
        return report;
      }
      ux_[i] += delta_[i].x;
      uy_[i] += delta_[i].y;
      correction = std::max({correction, std::abs(delta_[i].x), std::abs(delta_[i].y)});
    }
    report.last_correction = correction;
    if (correction <= tol) {
      report.converged = true;
      break;
    }
    // Backtracking: halve the step while the residual grows (far from the solution, a whip of
    // the chain turns links by large angles within a step and the full Newton step overshoots).
    double next = assemble(model, s, true);
    double lambda = 1.0;
    for (int b = 0; b < kMaxBacktracks && !(next < norm2); ++b) {
      lambda *= 0.5;
      for (std::size_t i = 0; i < n; ++i) {
        ux_[i] -= lambda * delta_[i].x;
        uy_[i] -= lambda * delta_[i].y;
      }
      next = assemble(model, s, true);
      ++report.backtracks;
    }
    norm2 = next;
  }
  if (!report.converged) return report;
  for (std::size_t i = 0; i < n; ++i) {
    if (model.is_pinned(i)) continue;
    // x₁ = x₀ + h ((1 − θ) v₀ + θ v₁)
    const double vx = (ux_[i] - s.x[i] - h * (1.0 - th) * s.vx[i]) / (h * th);
    const double vy = (uy_[i] - s.y[i] - h * (1.0 - th) * s.vy[i]) / (h * th);
    s.x[i] = ux_[i];
    s.y[i] = uy_[i];
    s.vx[i] = vx;
    s.vy[i] = vy;
  }
  s.time += h;
  return report;
}

}  // namespace catena::dynamics
