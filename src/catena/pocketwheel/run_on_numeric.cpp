#include "catena/pocketwheel/run_on_numeric.hpp"

#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

namespace catena::pocketwheel::numeric {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kScanSteps = 4000;  // scan resolution for seating events over one period

Vec2 rotate(Vec2 p, double angle) {  // counter-clockwise by `angle`
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  return {c * p.x - s * p.y, s * p.x + c * p.y};
}

double norm(Vec2 p) { return std::hypot(p.x, p.y); }

// The wheel turns clockwise in this frame (the top moves towards +x).
Vec2 crank_at(const NumericPhase& phase, double phi) {
  return rotate(phase.crank_begin, -(phi - phase.begin));
}

// Guided point of the slider: G = (g, H) with |G − J| = L, g < J.x (Newton on the constraint).
Vec2 guided_point(Vec2 crank, double height, double span) {
  double g = crank.x - span;
  for (int i = 0; i < 60; ++i) {
    const double f =
        (g - crank.x) * (g - crank.x) + (height - crank.y) * (height - crank.y) - span * span;
    const double df = 2.0 * (g - crank.x);
    const double step = f / df;
    g -= step;
    if (std::abs(step) <= 1e-16 * (std::abs(g) + span)) break;  // converged to rounding
  }
  return {g, height};
}

// Where the free span points from the crank: towards the guided point, the guide edge, or
// straight upstream for free run-on.
Vec2 span_target(const NumericPlan& plan, const NumericPhase& phase, Vec2 crank) {
  switch (plan.guide.kind) {
    case GuideKind::kNone:
      return {crank.x - 1.0, crank.y};
    default:
      if (plan.guide.span_model == SpanModel::kSlider)
        return guided_point(crank, plan.height, phase.span);
      return {-plan.guide.end_distance, plan.height};
  }
}

// Signed distance of the next joint from the pitch circle (> 0 while it is outside).
double next_joint_gap(const NumericPlan& plan, const NumericPhase& phase, double phi) {
  const Vec2 crank = crank_at(phase, phi);
  const Vec2 target = span_target(plan, phase, crank);
  const Vec2 along{target.x - crank.x, target.y - crank.y};
  const double n = norm(along);
  const Vec2 next{crank.x + phase.link * along.x / n, crank.y + phase.link * along.y / n};
  return norm(next) - plan.radius;
}

// First φ after phase.begin at which the next joint reaches the pitch circle, up to `limit`.
std::optional<double> find_seating(const NumericPlan& plan, const NumericPhase& phase,
                                   double limit) {
  const double step = plan.period / kScanSteps;
  double a = phase.begin + 1e-9;
  double fa = next_joint_gap(plan, phase, a);
  if (!std::isfinite(fa) || fa <= 0.0) return std::nullopt;
  for (double b = a + step; a < limit; b += step) {
    const double fb = next_joint_gap(plan, phase, b);
    if (!std::isfinite(fb)) return std::nullopt;
    if (fb <= 0.0) {
      boost::uintmax_t iterations = 200;
      auto [lo, hi] = boost::math::tools::toms748_solve(
          [&](double phi) { return next_joint_gap(plan, phase, phi); }, a, b, fa, fb,
          boost::math::tools::eps_tolerance<double>(52), iterations);
      return 0.5 * (lo + hi);
    }
    a = b;
    fa = fb;
  }
  return std::nullopt;
}

std::optional<NumericPlan> try_order(NumericPlan plan, Vec2 crank0, double first, double second,
                                     bool free) {
  double seated = 0.0;
  double offset = 0.0;
  NumericPhase phase{0.0, 0.0, crank0, first, 0.0, 0.0};
  const Vec2 edge{-plan.guide.end_distance, plan.height};
  const double span0 = free ? 0.0 : std::hypot(crank0.x - edge.x, crank0.y - edge.y);
  phase.span = span0;
  phase.offset = free ? 0.0 : -span0;
  for (double link : {first, second}) {
    phase.link = link;
    const auto seat = find_seating(plan, phase, plan.period + 0.01);
    if (!seat || *seat > plan.period + 1e-10) return std::nullopt;
    phase.end = std::min(*seat, plan.period);
    plan.phases.push_back(phase);
    // the next joint, now seated, becomes the crank
    const Vec2 crank = crank_at(phase, phase.end);
    const Vec2 target = span_target(plan, phase, crank);
    const double n = std::hypot(target.x - crank.x, target.y - crank.y);
    const Vec2 next{crank.x + link * (target.x - crank.x) / n,
                    crank.y + link * (target.y - crank.y) / n};
    seated += link;
    NumericPhase following{phase.end, 0.0, next, 0.0, 0.0, 0.0};
    if (free) {
      offset += crank.x - phase.crank_begin.x;
      following.offset = offset;
    } else {
      following.span = std::hypot(target.x - next.x, target.y - next.y);
      following.offset = seated - span0;
    }
    phase = following;
  }
  if (plan.period - phase.begin > 1e-10) {
    phase.end = plan.period;
    phase.link = first;
    plan.phases.push_back(phase);
  } else {
    plan.phases.back().end = plan.period;
  }
  if (plan.phases.front().end <= 1e-10) return std::nullopt;
  for (std::size_t i = 0; i + 1 < plan.phases.size(); ++i)
    plan.seating_angles.push_back(plan.phases[i].end);
  if (plan.phases.size() == 2) plan.seating_angles.insert(plan.seating_angles.begin(), 0.0);
  return plan;
}

// pitch_radius() for a wheel already validated (plan() has checked it with the guide).
double pitch_radius_of_valid(const PocketWheel& wheel) {
  const double t = wheel.pitch;
  const double d = wheel.wire;
  auto closure = [&](double r) {
    return std::asin((t + d) / (2.0 * r)) + std::asin((t - d) / (2.0 * r)) - kPi / wheel.teeth;
  };
  double lo = 0.5 * (t + d);
  double hi = lo;
  while (closure(hi) > 0.0) hi *= 2.0;
  boost::uintmax_t iterations = 200;
  auto [a, b] = boost::math::tools::toms748_solve(
      closure, lo, hi, boost::math::tools::eps_tolerance<double>(53), iterations);
  return 0.5 * (a + b);
}

}  // namespace

double pitch_radius(const PocketWheel& wheel) {
  throw_if_any(validate(wheel));
  return pitch_radius_of_valid(wheel);
}

NumericPlan plan(const PocketWheel& wheel, const Guide& guide) {
  throw_if_any(validate(wheel, guide));
  NumericPlan plan;
  plan.radius = pitch_radius_of_valid(wheel);
  plan.period = 2.0 * kPi / wheel.teeth;
  plan.guide = guide;
  const double r = plan.radius;
  const double t = wheel.pitch;
  const double d = wheel.wire;
  const bool free = guide.kind == GuideKind::kNone;
  // The chordal guide is the line of a seated t + d link: its half chord is (t + d)/2.
  const double chordal = std::sqrt(r * r - 0.25 * (t + d) * (t + d));
  switch (guide.kind) {
    case GuideKind::kNone:
    case GuideKind::kChordal:
      plan.height = chordal;
      break;
    case GuideKind::kTangential:
      plan.height = r;
      break;
    case GuideKind::kHeight:
      plan.height = std::min(guide.height, r);
      break;
  }
  // At φ = 0 the crank is where the pitch circle meets the line y = H, upstream.
  const Vec2 crank0{-std::sqrt(std::max(0.0, r * r - plan.height * plan.height)), plan.height};
  if (free) {
    // Free run-on: at φ = 0 the crank's t + d link has just seated, the t − d link is next.
    if (auto p = try_order(plan, crank0, t - d, t + d, true)) return *p;
    throw InputError({{"guide", "none", "a consistent free run-on (internal)"}});
  }
  std::optional<NumericPlan> best;
  double best_lag = std::numeric_limits<double>::infinity();
  for (auto [first, second] : {std::pair{t - d, t + d}, std::pair{t + d, t - d}}) {
    auto candidate = try_order(plan, crank0, first, second, false);
    if (!candidate) continue;
    const double lag = plan.period - candidate->phases[1].end;
    if (lag < best_lag - 1e-10) {
      best_lag = lag;
      best = std::move(candidate);
    }
  }
  if (!best) {
    throw InputError({{"guide_end", check::format_si(guide.end_distance, "m"),
                       "a guide end far enough for a consistent period (numerical solver)"}});
  }
  return *best;
}

Vec2 position(const NumericPlan& plan, std::size_t index, double phi) {
  const NumericPhase& phase = plan.phases[index];
  const Vec2 crank = crank_at(phase, phi);
  if (plan.guide.kind == GuideKind::kNone)
    return {phase.offset + crank.x - phase.crank_begin.x, crank.y};
  if (plan.guide.span_model == SpanModel::kSlider) {
    return {guided_point(crank, plan.height, phase.span).x + plan.guide.end_distance, 0.0};
  }
  const double span = std::hypot(crank.x + plan.guide.end_distance, crank.y - plan.height);
  return {phase.offset + span, 0.0};
}

PointKinematics evaluate_phase(const NumericPlan& plan, std::size_t index, double phi,
                               double step) {
  // Fourth-order central differences on the phase's own position function.
  const Vec2 m2 = position(plan, index, phi - 2.0 * step);
  const Vec2 m1 = position(plan, index, phi - step);
  const Vec2 c0 = position(plan, index, phi);
  const Vec2 p1 = position(plan, index, phi + step);
  const Vec2 p2 = position(plan, index, phi + 2.0 * step);
  auto first = [&](double a, double b, double c, double e) {
    return (a - 8.0 * b + 8.0 * c - e) / (12.0 * step);
  };
  auto second = [&](double a, double b, double c, double e, double f) {
    return (-a + 16.0 * b - 30.0 * c + 16.0 * e - f) / (12.0 * step * step);
  };
  PointKinematics k;
  k.x = c0.x;
  k.dx = first(m2.x, m1.x, p1.x, p2.x);
  k.d2x = second(m2.x, m1.x, c0.x, p1.x, p2.x);
  k.y = c0.y;
  k.dy = first(m2.y, m1.y, p1.y, p2.y);
  k.d2y = second(m2.y, m1.y, c0.y, p1.y, p2.y);
  return k;
}

PointKinematics evaluate(const NumericPlan& plan, double phi, double step) {
  if (phi >= plan.period) {
    PointKinematics k = evaluate_phase(plan, 0, 0.0, step);
    k.x += position(plan, plan.phases.size() - 1, plan.period).x;
    return k;
  }
  std::size_t index = 0;
  while (index + 1 < plan.phases.size() && phi >= plan.phases[index].end) ++index;
  return evaluate_phase(plan, index, phi, step);
}

RunOnResult run_on(const PocketWheel& wheel, const Guide& guide, const Sampling& sampling) {
  throw_if_any(validate(sampling));
  const NumericPlan numeric = plan(wheel, guide);
  // Describe the numerically found phases in closed-form terms for reporting and extremes.
  RunOnPlan described = plan_run_on(wheel, guide);
  described.seating_angles = numeric.seating_angles;
  return sample_run_on(described, sampling,
                       [&numeric](double phi) { return evaluate(numeric, phi); });
}

}  // namespace catena::pocketwheel::numeric
