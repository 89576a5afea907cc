#include "catena/pocketwheel/run_on.hpp"

#include <algorithm>
#include <array>
#include <boost/math/tools/minima.hpp>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <utility>

#include "geometry_detail.hpp"

namespace catena::pocketwheel {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kEventTol = 1e-12;  // [rad] two events closer than this are one event
constexpr int kFeasibilityGrid = 256;

double central_angle(double radius, double chord) {
  return 2.0 * std::asin(chord / (2.0 * radius));
}

// Wraps an angle to (−π, π].
double wrap(double angle) {
  angle = std::remainder(angle, 2.0 * kPi);
  return angle <= -kPi ? angle + 2.0 * kPi : angle;
}

// Among candidate crank angles u (seating positions), the largest one strictly below `below`:
// the first one the turning wheel reaches (θ falls with φ).
std::optional<double> first_reached(std::initializer_list<double> candidates, double below) {
  std::optional<double> best;
  for (double u : candidates) {
    if (!std::isfinite(u)) continue;
    // candidates are defined modulo 2π; bring each just below `below`
    u = below - std::fmod(below - wrap(u) + 4.0 * kPi, 2.0 * kPi);
    if (below - u < kEventTol) u -= 2.0 * kPi;  // an event at the phase start is the previous one
    if (!best || u > *best) best = u;
  }
  return best;
}

// The joint `link` ahead of the crank at angle u, along the unit direction (cx, cy): distance of
// that joint from the pitch circle; used to reject spurious branches of the closed forms.
bool lands_on_circle(double radius, double u, double link, double dir_x, double dir_y) {
  const double x = -radius * std::sin(u) + link * dir_x;
  const double y = radius * std::cos(u) + link * dir_y;
  return std::abs(std::hypot(x, y) - radius) < 1e-9 * radius;
}

struct SeatingInput {
  double radius, height, end, crank0, span, link, begin;
};

// Slider: the next joint, `link` along the bar from the crank, lands on the pitch circle when the
// chord of that link points along the bar. With θm = u + δ/2 and h = R cos u − H:
// L sin θm = h  ⇔  A sin u + B cos u = −H, A = L cos(δ/2), B = L sin(δ/2) − R.
// This is the general form of 003 eqs. (27)–(29) and (32)–(34).
std::optional<double> slider_seating(const SeatingInput& in) {
  const double half = 0.5 * central_angle(in.radius, in.link);
  const double a = in.span * std::cos(half);
  const double b = in.span * std::sin(half) - in.radius;
  const double rho = std::hypot(a, b);
  if (rho < std::abs(in.height) || in.span <= in.link) return std::nullopt;
  const double psi = std::atan2(b, a);
  const double s = std::asin(-in.height / rho);
  const auto u = first_reached({s - psi, kPi - s - psi}, in.crank0 - in.begin);
  if (!u) return std::nullopt;
  const double h = in.radius * std::cos(*u) - in.height;
  const double along = std::sqrt(std::max(0.0, in.span * in.span - h * h));
  // the bar points from the crank upstream (−x) to the guided point
  if (!lands_on_circle(in.radius, *u, in.link, -along / in.span, -h / in.span)) return std::nullopt;
  return in.crank0 - *u;
}

// Pivot: the span runs from the crank to the guide's edge E = (−l, H); the next joint lands when
// the link's chord points at E: (R cos u − H) cos θm = (l − R sin u) sin θm, which reduces to
// √(H² + l²) cos(θm − β) = R cos(δ/2), β = atan2(l, H).
std::optional<double> pivot_seating(const SeatingInput& in) {
  const double half = 0.5 * central_angle(in.radius, in.link);
  const double reach = std::hypot(in.height, in.end);
  const double c = in.radius * std::cos(half) / reach;
  if (std::abs(c) > 1.0) return std::nullopt;
  const double beta = std::atan2(in.end, in.height);
  const double gap = std::acos(c);
  const auto u = first_reached({beta - gap - half, beta + gap - half}, in.crank0 - in.begin);
  if (!u) return std::nullopt;
  const double dx = in.end - in.radius * std::sin(*u);
  const double dy = in.radius * std::cos(*u) - in.height;
  const double span = std::hypot(dx, dy);
  if (span <= in.link || !lands_on_circle(in.radius, *u, in.link, -dx / span, -dy / span)) {
    return std::nullopt;
  }
  return in.crank0 - *u;
}

// Smallest S² = L² − h² over a slider phase (the bar must reach the guide line).
double min_slider_clearance(const RunOnPlan& plan, const Phase& phase) {
  double worst = std::numeric_limits<double>::infinity();
  const double r = plan.geometry.pitch_radius;
  for (int i = 0; i <= kFeasibilityGrid; ++i) {
    const double phi = phase.begin + (phase.end - phase.begin) * i / kFeasibilityGrid;
    const double h = r * std::cos(phase.crank_angle0 - phi) - plan.guide_height;
    worst = std::min(worst, phase.span * phase.span - h * h);
  }
  return worst;
}

// Builds the forced-run-on phases for one order of the two links (first, second). Returns
// nothing when that order is not a consistent period (a seating outside the period, or the span
// too short to reach the guide).
std::optional<RunOnPlan> forced_plan(RunOnPlan plan, double theta0, double first, double second) {
  const double r = plan.geometry.pitch_radius;
  const double period = plan.geometry.tooth_angle;
  const double l = plan.guide.end_distance;
  const bool slider = plan.guide.span_model == SpanModel::kSlider;
  plan.first_link = first;
  plan.span0 = l - r * std::sin(theta0);
  double crank = theta0;
  double span = plan.span0;
  double seated = 0.0;
  double begin = 0.0;
  for (double link : {first, second}) {
    const SeatingInput in{r, plan.guide_height, l, crank, span, link, begin};
    const auto seat = slider ? slider_seating(in) : pivot_seating(in);
    if (!seat || *seat > period + kEventTol) return std::nullopt;
    Phase phase{begin, std::min(*seat, period), crank, link, span, seated - plan.span0};
    plan.phases.push_back(phase);
    crank += central_angle(r, link);
    span -= link;
    seated += link;
    begin = phase.end;
  }
  if (period - begin > kEventTol) {
    plan.phases.push_back({begin, period, crank, first, span, seated - plan.span0});
  }
  for (const Phase& phase : plan.phases) {
    if (phase.end - phase.begin <= 0.0 && &phase != &plan.phases.front()) return std::nullopt;
    if (slider && min_slider_clearance(plan, phase) <= 0.0) return std::nullopt;
  }
  if (plan.phases.front().end <= kEventTol) return std::nullopt;  // J1 already seated at φ = 0
  // Seating events in [0, 2π/z): the ends of all phases but the last; with two phases the
  // second seating falls on 2π/z, which is the event at φ = 0 of the period.
  for (std::size_t i = 0; i + 1 < plan.phases.size(); ++i)
    plan.seating_angles.push_back(plan.phases[i].end);
  if (plan.phases.size() == 2) plan.seating_angles.push_back(0.0);
  std::sort(plan.seating_angles.begin(), plan.seating_angles.end());
  return plan;
}

RunOnPlan free_plan(RunOnPlan plan) {
  const WheelGeometry& g = plan.geometry;
  const double half_period = 0.5 * g.tooth_angle;  // π/z
  const double r = g.pitch_radius;
  const double t_minus_d = 2.0 * r * std::sin(0.5 * g.delta2);
  const double t_plus_d = 2.0 * r * std::sin(0.5 * g.delta1);
  // 003 eqs. (1)–(4): the crank joint sits at θ = δ1/2 at φ = 0 (its t + d link just seated);
  // the t − d link seats when θ = −δ2/2, i.e. at φ = π/z, and the next crank starts at +δ2/2.
  // The strand keeps its direction and translates with the crank: x is the crank's travel.
  const double x_half = r * (std::sin(0.5 * g.delta1) + std::sin(0.5 * g.delta2));  // = t
  plan.phases = {{0.0, half_period, 0.5 * g.delta1, t_minus_d, 0.0, 0.0},
                 {half_period, g.tooth_angle, 0.5 * g.delta1 + g.delta2, t_plus_d, 0.0, x_half}};
  plan.seating_angles = {0.0, half_period};
  plan.first_link = t_minus_d;
  return plan;
}

// `g` is the geometry of `wheel`, derived once by the caller (the bisection in
// minimum_end_distance calls this some 80 times for the same wheel).
std::optional<RunOnPlan> try_plan(const PocketWheel& wheel, const WheelGeometry& g,
                                  const Guide& guide) {
  RunOnPlan plan;
  plan.geometry = g;
  plan.guide = guide;
  if (guide.kind == GuideKind::kNone) return free_plan(plan);
  double theta0 = 0.0;  // crank angle at which the span lies along the guide line (y = H)
  switch (guide.kind) {
    case GuideKind::kChordal:
      plan.guide_height = g.chordal_height;
      theta0 = 0.5 * g.delta1;
      break;
    case GuideKind::kTangential:
      plan.guide_height = g.pitch_radius;
      theta0 = 0.0;
      break;
    default:
      plan.guide_height = guide.height;
      theta0 = std::acos(std::clamp(guide.height / g.pitch_radius, -1.0, 1.0));
      break;
  }
  const double t_plus_d = wheel.pitch + wheel.wire;
  const double t_minus_d = wheel.pitch - wheel.wire;
  // Which link seats first after φ = 0 is a matter of phase: take the order that gives a
  // consistent period and, of two, the one whose crank seated last before φ = 0. This yields the
  // paper's orders: t − d first for the chordal guide (the only consistent one), t + d first for
  // the tangential guide (eq. 29 uses δ1). See docs/models/pocketwheel.md.
  std::optional<RunOnPlan> best;
  double best_lag = std::numeric_limits<double>::infinity();
  for (auto [first, second] : {std::pair{t_minus_d, t_plus_d}, std::pair{t_plus_d, t_minus_d}}) {
    auto candidate = forced_plan(plan, theta0, first, second);
    if (!candidate) continue;
    const double lag = g.tooth_angle - candidate->phases[1].end;
    if (lag < best_lag - kEventTol) {
      best_lag = lag;
      best = std::move(candidate);
    }
  }
  return best;
}

// Smallest guide end distance for which the period is consistent (bisection on feasibility).
double minimum_end_distance(const PocketWheel& wheel, const WheelGeometry& g, Guide guide) {
  const double r = g.pitch_radius;
  double lo = r;
  double hi = r + 4.0 * (wheel.pitch + wheel.wire);
  guide.end_distance = hi;
  for (int i = 0; i < 20 && !try_plan(wheel, g, guide); ++i) {
    hi *= 2.0;
    guide.end_distance = hi;
  }
  for (int i = 0; i < 60; ++i) {
    guide.end_distance = 0.5 * (lo + hi);
    (try_plan(wheel, g, guide) ? hi : lo) = guide.end_distance;
  }
  return hi;
}

// validate(wheel, guide), also handing out the wheel's geometry in `g` once the wheel is valid,
// so that plan_run_on validates the wheel and derives its geometry once per run.
std::vector<Issue> validate_with_geometry(const PocketWheel& wheel, const Guide& guide,
                                          WheelGeometry& g) {
  std::vector<Issue> issues = validate(wheel);
  if (issues.empty()) g = detail::geometry_of_valid(wheel);
  if (guide.kind == GuideKind::kNone) return issues;
  check::finite_positive(issues, "guide_end", guide.end_distance, "m");
  if (guide.kind == GuideKind::kHeight)
    check::finite_positive(issues, "guide_height", guide.height, "m");
  if (!issues.empty()) return issues;
  // Far beyond the wheel the strand's kinematics lose the wheel's radius to round-off (the
  // l − R·sin θ of every phase): a range, not a bogus minimum, names the problem.
  constexpr double kMaxEndRadii = 1e6;  // 2000 m (12 000·R) still agrees with free run-on
  if (guide.end_distance <= g.pitch_radius) {
    issues.push_back(
        {"guide_end", check::format_si(guide.end_distance, "m"),
         "a guide end outside the pitch circle: l > R = " + check::format_si(g.pitch_radius, "m")});
  } else if (guide.end_distance > kMaxEndRadii * g.pitch_radius) {
    issues.push_back({"guide_end", check::format_si(guide.end_distance, "m"),
                      "a guide end R < l ≤ 10⁶·R: " + check::format_si(g.pitch_radius, "m") +
                          " < l ≤ " + check::format_si(kMaxEndRadii * g.pitch_radius, "m")});
  }
  if (guide.kind == GuideKind::kHeight && (guide.height < g.chordal_height * (1.0 - 1e-12) ||
                                           guide.height > g.pitch_radius * (1.0 + 1e-12))) {
    issues.push_back(
        {"guide_height", check::format_si(guide.height, "m"),
         "H between the chordal height R·cos(δ1/2) = " + check::format_si(g.chordal_height, "m") +
             " and the tangential R = " + check::format_si(g.pitch_radius, "m")});
  }
  return issues;
}

}  // namespace

const char* to_string(GuideKind kind) {
  switch (kind) {
    case GuideKind::kNone:
      return "none";
    case GuideKind::kChordal:
      return "chordal";
    case GuideKind::kTangential:
      return "tangential";
    case GuideKind::kHeight:
      return "height";
  }
  return "unknown";
}

const char* to_string(SpanModel model) { return model == SpanModel::kSlider ? "slider" : "pivot"; }

std::vector<Issue> validate(const PocketWheel& wheel, const Guide& guide) {
  WheelGeometry g;
  return validate_with_geometry(wheel, guide, g);
}

RunOnPlan plan_run_on(const PocketWheel& wheel, const Guide& guide) {
  WheelGeometry g;
  throw_if_any(validate_with_geometry(wheel, guide, g));
  Guide resolved = guide;
  if (guide.kind == GuideKind::kHeight) {
    resolved.height = std::min(guide.height, g.pitch_radius);
  }
  if (auto plan = try_plan(wheel, g, resolved)) return std::move(*plan);
  const double l_min = minimum_end_distance(wheel, g, resolved);
  throw InputError({{"guide_end", check::format_si(guide.end_distance, "m"),
                     "a guide end far enough from the wheel for the free span (" +
                         std::string(to_string(guide.span_model)) +
                         " model) to carry the chain over a whole tooth period: l ≥ " +
                         check::format_si(l_min, "m")}});
}

PointKinematics evaluate_phase(const RunOnPlan& plan, std::size_t index, double phi) {
  const Phase& p = plan.phases[index];
  const double r = plan.geometry.pitch_radius;
  const double theta = p.crank_angle0 - phi;
  const double sin_t = std::sin(theta);
  const double cos_t = std::cos(theta);
  PointKinematics k;
  if (plan.guide.kind == GuideKind::kNone) {
    // 003 eqs. (1)–(4), (10)–(13) with the factor ω restored in (1)–(4): v = ωR cos θ.
    k.x = p.travel0 + r * (std::sin(p.crank_angle0 - p.begin) - sin_t);
    k.dx = r * cos_t;
    k.d2x = r * sin_t;
    k.y = r * cos_t;
    k.dy = r * sin_t;
    k.d2y = -r * cos_t;
    return k;
  }
  const double h = r * cos_t - plan.guide_height;  // height of the crank above the guide line
  const double dh = r * sin_t;                     // dh/dφ
  if (plan.guide.span_model == SpanModel::kSlider) {
    // Slider-crank: x = l + x_c − √(L² − h²); 003 eqs. (14)–(17), (26), (30), (31), (35)
    // with the span lengths of the geometry (see docs/models/pocketwheel.md).
    const double s = std::sqrt(p.span * p.span - h * h);
    k.x = plan.guide.end_distance - r * sin_t - s;
    // dx/dφ: 003 eqs. (18)–(21), (36)–(39); d²x/dφ²: (22)–(25), (40)–(43). As printed, (19),
    // (21) have the wrong sign of the second term, (22), (24), (41), (43) the wrong sign of the
    // bracket, (22)–(25) lose the factor cos(δ1/2) (here inside h r cos θ, h = R(cos θ − c)), and
    // (20), (21), (24), (25), (38), (39), (42), (43) print a span one pitch too long; shown by
    // tests/validation/pocketwheel_paper_test.cpp (Paper003.ChordalEq19…–ChordalEq25…,
    // Paper003.Tangential…Eq43…), and the corrected forms here by the external reference
    // (pocketwheel_independent_test.cpp).
    k.dx = r * cos_t + h * dh / s;
    k.d2x = r * sin_t + (dh * dh - h * r * cos_t) / s + h * h * dh * dh / (s * s * s);
    return k;
  }
  // Pivot: x = |E − J_c| + Σ seated links − |E − J_0(0)|.
  const double u = plan.guide.end_distance - r * sin_t;  // horizontal distance from E to crank
  const double du = r * cos_t;
  const double dist = std::hypot(u, h);
  const double rate = (u * du + h * dh) / dist;
  k.x = p.travel0 + dist;
  k.dx = rate;
  k.d2x = (r * r + u * r * sin_t - h * r * cos_t - rate * rate) / dist;
  return k;
}

PointKinematics evaluate(const RunOnPlan& plan, double phi) {
  const double period = plan.geometry.tooth_angle;
  if (phi >= period) {  // the start of the next period; x keeps counting
    PointKinematics k = evaluate_phase(plan, 0, 0.0);
    k.x += evaluate_phase(plan, plan.phases.size() - 1, period).x;
    return k;
  }
  std::size_t index = 0;
  while (index + 1 < plan.phases.size() && phi >= plan.phases[index].end) ++index;
  return evaluate_phase(plan, index, phi);
}

constexpr double kMaxOmega = 1e4;  // [rad/s]

std::vector<Issue> validate(const Sampling& sampling) {
  std::vector<Issue> issues;
  check::finite_positive(issues, "omega", sampling.omega, "rad/s");
  // 10⁴ rad/s (95 493 rpm) is far beyond any chain wheel (seed 003's runs at 5 1/s); above it the
  // run-on accelerations ω²·R overflow long before a design could need them (issue 18).
  if (std::isfinite(sampling.omega) && sampling.omega > kMaxOmega)
    issues.push_back({"omega", check::format_si(sampling.omega, "rad/s"),
                      "a wheel speed 0 < omega <= 10000 rad/s (95 493 rpm)"});
  if (sampling.points < 2) {
    issues.push_back({"points", std::to_string(sampling.points), "at least 2 samples"});
  }
  if (sampling.strand_mass)
    check::finite_positive(issues, "strand_mass", *sampling.strand_mass, "kg");
  return issues;
}

Extremes extremes(const RunOnPlan& plan, double omega) {
  constexpr int kGrid = 512;
  Extremes e{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
             std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  std::array<PointKinematics, kGrid + 1> grid;
  for (std::size_t index = 0; index < plan.phases.size(); ++index) {
    const Phase& p = plan.phases[index];
    const double step = (p.end - p.begin) / kGrid;
    if (step <= 0.0) continue;
    // of(k, which, sign): sign·v_x or sign·a_x; minimised over the phase.
    auto of = [omega](const PointKinematics& k, bool accel, double sign) {
      return sign * (accel ? omega * omega * k.d2x : omega * k.dx);
    };
    auto value = [&](double phi, bool accel, double sign) {
      return of(evaluate_phase(plan, index, phi), accel, sign);
    };
    // The grid's kinematics once for all four searches (min and max of v_x and of a_x).
    grid[0] = evaluate_phase(plan, index, p.begin);
    for (int i = 1; i <= kGrid; ++i) grid[i] = evaluate_phase(plan, index, p.begin + i * step);
    for (bool accel : {false, true}) {
      for (double sign : {1.0, -1.0}) {
        int best = 0;
        double best_value = of(grid[0], accel, sign);
        for (int i = 1; i <= kGrid; ++i) {
          const double v = of(grid[i], accel, sign);
          if (v < best_value) {
            best_value = v;
            best = i;
          }
        }
        if (best > 0 && best < kGrid) {  // interior: refine with Brent's method
          auto [at, refined] = boost::math::tools::brent_find_minima(
              [&](double phi) { return value(phi, accel, sign); }, p.begin + (best - 1) * step,
              p.begin + (best + 1) * step, 52);
          (void)at;
          best_value = std::min(best_value, refined);
        }
        double& slot = accel ? (sign > 0 ? e.ax_min : e.ax_max) : (sign > 0 ? e.vx_min : e.vx_max);
        slot = sign > 0 ? std::min(slot, best_value) : std::max(slot, -best_value);
      }
    }
  }
  return e;
}

RunOnResult run_on(const PocketWheel& wheel, const Guide& guide, const Sampling& sampling) {
  throw_if_any(validate(sampling));
  const RunOnPlan plan = plan_run_on(wheel, guide);
  return sample_run_on(plan, sampling, [&plan](double phi) { return evaluate(plan, phi); });
}

}  // namespace catena::pocketwheel
