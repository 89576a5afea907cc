// Chain–sprocket engagement forces (seed 000 §1.6.1–1.6.2); see docs/models/engagement.md.
#include "catena/engagement/engagement.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <utility>

#include "catena/core/progress.hpp"
#include "catena/hinge/kinematics.hpp"
#include "catena/hinge/synthesis.hpp"

namespace catena::engagement {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kBisections = 200;   // far more than the 53 halvings a double can resolve
constexpr int kBracketScan = 512;  // scan steps per γΣ for the sign change of ΣM(ξ)

double cross(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

std::string num(double v) { return check::format_si(v, ""); }

void common_issues(std::vector<Issue>& out, double tension, int teeth, int strokes,
                   double flank_angle, int points) {
  check::finite_positive(out, "tension", tension, "N");
  if (teeth < 3) out.push_back({"teeth", std::to_string(teeth), "a whole number z >= 3"});
  if (strokes < 1 || 2 * strokes >= teeth) {
    out.push_back({"strokes", std::to_string(strokes), "a whole number 1 <= m < z/2"});
  }
  if (teeth >= 3 && strokes >= 1 && 2 * strokes < teeth) {
    const double alpha = 0.5 * kPi - 0.5 * gamma_sigma(teeth, strokes);
    if (!(std::abs(flank_angle) < alpha)) {
      out.push_back({"flank_angle", num(flank_angle) + " rad",
                     "|psi| < alpha = 90 deg - 180 deg*m/z = " + num(alpha) + " rad"});
    }
  } else if (!std::isfinite(flank_angle)) {
    out.push_back({"flank_angle", num(flank_angle), "a finite angle"});
  }
  if (points < 2) out.push_back({"points", std::to_string(points), "at least 2"});
}

// γ of sample i of n over [0, γΣ], both ends exact.
double sample_gamma(double gs, int i, int n) {
  return i + 1 == n ? gs : gs * static_cast<double>(i) / static_cast<double>(n - 1);
}

// The roller's radius of the concave faces: given, or eq. (6) of the hinge model.
std::optional<double> face_radius(const hinge::Hinge& h) {
  if (h.roller_radius > 0.0) return h.roller_radius;
  return hinge::r2_eq6(h.pin_diameter, h.half_thickness, h.plate_radius, hinge::gamma_max(h));
}

}  // namespace

double gamma_sigma(int teeth, int strokes) {
  // 000 §1.6.2: γΣ = 360°·m/z
  return 2.0 * kPi * static_cast<double>(strokes) / static_cast<double>(teeth);
}

Angles angles(int teeth, int strokes, double flank_angle) {
  Angles a;
  a.gamma_sigma = gamma_sigma(teeth, strokes);
  a.alpha = 0.5 * kPi - 0.5 * a.gamma_sigma;  // reconstruction of fig. 25 (docs, figure E1)
  a.psi = flank_angle;
  a.theta = a.gamma_sigma + a.alpha - a.psi;  // φ + α − ψ with φ = γΣ
  a.epsilon = epsilon_at(a, a.gamma_sigma);
  a.beta1 = beta1_at(a, a.gamma_sigma);
  return a;
}

double epsilon_at(const Angles& a, double gamma) { return a.theta - gamma; }
double beta1_at(const Angles& a, double gamma) { return 0.5 * kPi - epsilon_at(a, gamma); }

std::vector<Issue> validate(const SlidingInput& in) {
  std::vector<Issue> out;
  common_issues(out, in.tension, in.teeth, in.strokes, in.flank_angle, in.points);
  if (!(in.friction >= 0.0) || !std::isfinite(in.friction)) {
    out.push_back({"friction", num(in.friction), "a friction factor f >= 0"});
  }
  if (!std::isfinite(in.tooth_friction)) {
    out.push_back({"tooth_friction", num(in.tooth_friction), "a friction factor >= 0"});
  }
  // Friction factors above 1 are outside any steel pair (0.05–0.3) and, at 1e300, overflow the
  // wrap's torque (issue 18): refused with the range.
  for (const auto& [field, f] :
       {std::pair{"friction", in.friction}, std::pair{"tooth_friction", in.tooth_friction}}) {
    if (std::isfinite(f) && f > 1.0)
      out.push_back({field, num(f), "a friction factor 0 <= f <= 1 (steel pairs: 0.05-0.3)"});
  }
  check::finite_positive(out, "journal_diameter", in.journal_diameter, "m");
  check::finite_positive(out, "tooth_diameter", in.tooth_diameter, "m");
  return out;
}

std::vector<Issue> validate(const RollingInput& in) {
  std::vector<Issue> out = hinge::validate(in.hinge);
  common_issues(out, in.tension, in.hinge.teeth, in.hinge.strokes, in.flank_angle, in.points);
  if (in.hinge.face != hinge::Face::kConcave) {
    out.push_back({"face", "flat", "concave roller faces (the flat-face hinge is not modelled)"});
  }
  if (!(in.rolling_coefficient >= 0.0) || !(in.rolling_coefficient < 0.5)) {
    out.push_back({"rolling_coefficient", num(in.rolling_coefficient), "0 <= c_r < 0.5"});
  }
  if (!(in.tooth_arm >= 0.0) || !(in.tooth_arm < 0.5 * in.hinge.pin_diameter)) {
    out.push_back({"tooth_arm", num(in.tooth_arm) + " m", "0 <= lambda1 < d/2"});
  }
  if (out.empty() && !face_radius(in.hinge)) {
    out.push_back({"plate_radius", num(in.hinge.plate_radius) + " m",
                   "R1 <= R1max so that eq. (6) gives R2, or a given roller_radius"});
  }
  return out;
}

// ---------------------------------------------------------------- sliding hinge (§1.6.1)

namespace {

struct SlidingForces {
  double f2 = 0.0, n = 0.0;
};

SlidingForces sliding_forces(const SlidingInput& in, const Angles& a, double gamma) {
  const double f1 = in.friction;
  const double eps = epsilon_at(a, gamma);
  const double theta = a.theta;  // φ + α − ψ
  SlidingForces s;
  s.f2 = in.tension * (std::sin(eps) - f1 * std::cos(eps)) / std::sin(theta);        // 000 eq. (26)
  s.n = in.tension * (std::cos(eps) + f1 * std::sin(eps)) - s.f2 * std::cos(theta);  // eq. (27)
  return s;
}

// > 0 when the roller turns: 000 eq. (25) minus its right side; < 0: eq. (24).
double turn_margin(const SlidingInput& in, const SlidingForces& s) {
  const double f = in.friction;
  const double ft = in.tooth_friction < 0.0 ? f : in.tooth_friction;
  return f * in.tension * 0.5 * in.journal_diameter -
         (f * s.f2 * 0.5 * in.journal_diameter + ft * s.n * 0.5 * in.tooth_diameter);
}

}  // namespace

Result solve_sliding(const SlidingInput& in) {
  throw_if_any(validate(in));
  Result r;
  r.angles = angles(in.teeth, in.strokes, in.flank_angle);
  const Angles& a = r.angles;
  const double f1 = in.tension;
  bool slack = false, lift = false;
  double min_fn = 0.0;  // [N] the most negative tooth reaction, for the lift-off diagnostic
  const auto points = static_cast<std::size_t>(std::max(in.points, 0));
  ProgressLoop loop(points, "points");
  for (int i = 0; i < in.points; ++i) {
    loop.step(static_cast<std::size_t>(i));
    Sample s;
    s.gamma = sample_gamma(a.gamma_sigma, i, in.points);
    const SlidingForces fs = sliding_forces(in, a, s.gamma);
    s.f2 = fs.f2;
    s.fn = fs.n;
    s.friction_force = in.friction * f1;
    s.roller_turns = turn_margin(in, fs) > 0.0;
    // residual of ΣX, ΣY in the roller frame (figure E1), not in the axes of (26)–(27)
    const double b = beta1_at(a, s.gamma);  // tooth normal n = (sin β1, −cos β1)
    const double rx = -f1 + s.f2 * std::cos(s.gamma) + s.fn * std::sin(b);
    const double ry = s.f2 * std::sin(s.gamma) - s.fn * std::cos(b) + s.friction_force;
    s.residual = std::max(std::abs(rx), std::abs(ry)) / f1;
    slack = slack || s.f2 <= 0.0;
    lift = lift || s.fn < 0.0;
    min_fn = std::min(min_fn, s.fn);
    r.max_residual = std::max(r.max_residual, s.residual);
    r.series.push_back(s);
  }
  loop.step(points);
  // ranges where (25) holds, ends refined by bisection on the margin of (25)
  auto margin = [&](double g) { return turn_margin(in, sliding_forces(in, a, g)); };
  auto edge = [&](double lo, double hi) {
    const bool lo_turns = margin(lo) > 0.0;
    for (int k = 0; k < kBisections && hi - lo > 1e-15; ++k) {
      const double mid = 0.5 * (lo + hi);
      ((margin(mid) > 0.0) == lo_turns ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  };
  const std::vector<Sample>& ser = r.series;
  for (std::size_t i = 0; i < ser.size(); ++i) {
    if (!ser[i].roller_turns) continue;
    Range rg;
    rg.from = i == 0 ? 0.0 : edge(ser[i - 1].gamma, ser[i].gamma);
    std::size_t j = i;
    while (j + 1 < ser.size() && ser[j + 1].roller_turns) ++j;
    rg.to = j + 1 == ser.size() ? a.gamma_sigma : edge(ser[j].gamma, ser[j + 1].gamma);
    r.roller_turns.push_back(rg);
    i = j;
  }
  if (slack) {
    r.diagnostics.push_back({Diagnostic::Severity::kInfeasible, "engagement.link2_slack",
                             "F2 <= 0: the braking force f1*F1 alone balances F1 (f1 >= tan(eps)); "
                             "eq. (26) does not describe a loaded link 2",
                             in.friction, std::tan(epsilon_at(a, a.gamma_sigma))});
  }
  if (lift) {
    r.diagnostics.push_back(
        {Diagnostic::Severity::kInfeasible, "engagement.tooth_lift_off",
         "N < 0 somewhere: the roller would leave the tooth (value: the least N; "
         "limit: 0)",
         min_fn, 0.0, "N"});
  }
  return r;
}

// ---------------------------------------------------------------- rolling hinge (§1.6.2)

Offset contact_offset(const hinge::Hinge& h, double r2, double theta) {
  // The hinge model's pose at mutual turn φ = 2θ turns the roller by θ relative to each plate
  // (000 eq. 3): M1 − O2 is the contact seen from the roller centre (eqs. 8–9, 18–19).
  const hinge::Pose p = hinge::pose(h, r2, 2.0 * std::abs(theta));
  Offset o{p.contact.x - p.centre.x, p.contact.y - p.centre.y};
  if (theta < 0.0) o.y = -o.y;  // the hinge is symmetric about the plate axis
  return o;
}

namespace {

// The contact points from the roller centre in the frame of figure E1 at (γ, ξ).
struct Contacts {
  double r1x = 0.0, r1y = 0.0, r2x = 0.0, r2y = 0.0;
};

Contacts contacts(const hinge::Hinge& h, double r2, double gamma, double xi) {
  Contacts c;
  // link 1: plate frame x = global x, y mirrored (the roller turns +ξ, the model turns it −θ)
  const Offset o1 = contact_offset(h, r2, xi);
  c.r1x = o1.x;
  c.r1y = -o1.y;
  // link 2: plate frame = global turned by γ + π; roller turned by γ − ξ relative to it
  const Offset o2 = contact_offset(h, r2, gamma - xi);
  const double cg = std::cos(gamma + kPi), sg = std::sin(gamma + kPi);
  c.r2x = o2.x * cg - o2.y * sg;
  c.r2y = o2.x * sg + o2.y * cg;
  return c;
}

// The state of system (28) at (γ, ξ) with F2, F_N from ΣX = ΣY = 0; `moment` is ΣM_O.
struct State {
  double f2 = 0.0, fn = 0.0, f1k = 0.0, f2k = 0.0, moment = 0.0;
  double r1x = 0.0, r1y = 0.0, r2x = 0.0, r2y = 0.0;  // contact points from the roller centre
  double sigma1 = 0.0, sigma2 = 0.0;                  // senses of the rolling resistances
};

// Senses of the relative rolling assumed over the engagement (checked after solving): the
// roller turns forwards relative to link 1 (ξ̇ ≥ 0) and backwards relative to link 2 and the
// tooth (ξ̇ − γ̇ ≤ 0).
constexpr double kSense1 = 1.0, kSense2 = -1.0, kSenseTooth = -1.0;

State state(const RollingInput& in, double r2, double beta1, double gamma, double xi) {
  State s;
  const double f1 = in.tension;
  const double c = in.rolling_coefficient;
  const double tx = -std::sin(xi), ty = std::cos(xi);  // roller faces' tangent, turned by ξ
  const Contacts k = contacts(in.hinge, r2, gamma, xi);
  s.r1x = k.r1x;
  s.r1y = k.r1y;
  s.r2x = k.r2x;
  s.r2y = k.r2y;
  // 000 eq. (28): F_jk·t·sgn ẋ1j, the classical rolling-resistance force, against the travel
  // of the contact along the face. Rolling without slip, the contact runs along the roller's
  // face circle by the arc R2·ψ2, ψ2 = θ·R1/(R2 − R1) (eqs. 1–2; R2 > R1): towards +y of the
  // hinge model's frame as the roller–plate turn θ grows, at the face's middle along its tangent.
  // Link 1's frame mirrors y and link 2's turns it by π, so in figure E1 the contact travels
  // along −t as ξ grows (kSense1) and as γ − ξ grows (−kSense2): both resistances act along +t.
  // Their moments about the centre then turn the roller with its rolling on each plate, not
  // against it: a tangential force at the contact cannot oppose both the travel and the spin.
  // rolling_residual re-derives these senses from the contact positions.
  s.sigma1 = kSense1;
  s.sigma2 = -kSense2;
  // 000 eq. (28), ΣX and ΣY, linear in F2 and F_N (F_jk = c_r·F_j):
  //   −F1 + F2 cos γ + F_N sin β1 + σ1 c F1 tx + σ2 c F2 tx = 0
  //    F2 sin γ − F_N cos β1 + σ1 c F1 ty + σ2 c F2 ty = 0
  const double a11 = std::cos(gamma) + s.sigma2 * c * tx, a12 = std::sin(beta1);
  const double a21 = std::sin(gamma) + s.sigma2 * c * ty, a22 = -std::cos(beta1);
  const double b1 = f1 - s.sigma1 * c * f1 * tx, b2 = -s.sigma1 * c * f1 * ty;
  const double det = a11 * a22 - a12 * a21;
  s.f2 = (b1 * a22 - a12 * b2) / det;
  s.fn = (a11 * b2 - b1 * a21) / det;
  s.f1k = c * f1;
  s.f2k = c * s.f2;
  // 000 eq. (28), ΣM_O: link tensions at their contact points, the rolling resistances there,
  // and the couple λ1·F_N of the tooth's shifted normal force, which opposes the roller's
  // rolling on the tooth (not (28)'s printed sense: docs/models/engagement.md)
  s.moment = cross(s.r1x, s.r1y, -f1, 0.0) +
             cross(s.r2x, s.r2y, s.f2 * std::cos(gamma), s.f2 * std::sin(gamma)) +
             cross(s.r1x, s.r1y, s.sigma1 * s.f1k * tx, s.sigma1 * s.f1k * ty) +
             cross(s.r2x, s.r2y, s.sigma2 * s.f2k * tx, s.sigma2 * s.f2k * ty) -
             kSenseTooth * in.tooth_arm * s.fn;
  return s;
}

// Residual of all three equations of (28), re-evaluated from the solution's F2, F_N, ξ. The
// senses of the rolling resistances are derived here afresh, not taken from `state`: each acts
// against the travel of its contact along the roller's face, found from the contact positions
// with the roller turned by ±h relative to that plate in the assumed sense (below). The tooth
// turns with link 2, so the roller rolls on it in link 2's sense; λ1·F_N opposes that.
double rolling_residual(const RollingInput& in, double r2, double beta1, const State& s,
                        double gamma, double xi) {
  const double f1 = in.tension;
  const double c = in.rolling_coefficient;
  // The contact's travel round its face's centre of curvature C (body (±(a + R2), 0)) when the
  // roller turns by ±h relative to the plate in the assumed sense, carried to t by the face's
  // tangent at its middle (body (±a, 0)); the resistance acts against it.
  constexpr double kTurnStep = 1e-6;  // [rad] the contact runs ≥ R1·h: far above round-off
  const double arm = in.hinge.half_thickness + r2;
  auto against_travel = [&](bool link1, double sense) {
    const double side = link1 ? 1.0 : -1.0;  // link 1 presses the +x face, link 2 the −x face
    auto from_centre = [&](double x) {       // contact − C in figure E1 at roller turn x
      const Contacts k = contacts(in.hinge, r2, gamma, x);
      const double cx = side * arm * std::cos(x), cy = side * arm * std::sin(x);
      return link1 ? std::pair{k.r1x - cx, k.r1y - cy} : std::pair{k.r2x - cx, k.r2y - cy};
    };
    const auto [ax, ay] = from_centre(xi - sense * kTurnStep);
    const auto [bx, by] = from_centre(xi + sense * kTurnStep);
    const double round_c = cross(ax, ay, bx, by);  // > 0: the contact travels anticlockwise
    // anticlockwise round C at the face's middle, where contact − C = Rot(ξ)(−side·R2, 0)
    const double middle_t =
        cross(-side * std::cos(xi), -side * std::sin(xi), -std::sin(xi), std::cos(xi));
    return (round_c > 0.0) == (middle_t > 0.0) ? -1.0 : 1.0;
  };
  // turning the roller by +h relative to link 1 is ξ + h; relative to link 2 (angle ξ − γ) too
  const double sigma1 = against_travel(true, kSense1);
  const double sigma2 = against_travel(false, kSense2);
  const double tx = -std::sin(xi), ty = std::cos(xi);
  const double k1x = sigma1 * c * f1 * tx, k1y = sigma1 * c * f1 * ty;
  const double k2x = sigma2 * c * s.f2 * tx, k2y = sigma2 * c * s.f2 * ty;
  const double f2x = s.f2 * std::cos(gamma), f2y = s.f2 * std::sin(gamma);
  const double nx = s.fn * std::sin(beta1), ny = -s.fn * std::cos(beta1);
  const double sx = -f1 + f2x + nx + k1x + k2x;
  const double sy = f2y + ny + k1y + k2y;
  const double sm = s.r1y * f1 + (s.r2x * f2y - s.r2y * f2x) + (s.r1x * k1y - s.r1y * k1x) +
                    (s.r2x * k2y - s.r2y * k2x) - kSense2 * in.tooth_arm * s.fn;
  return std::max(
      {std::abs(sx) / f1, std::abs(sy) / f1, std::abs(sm) / (f1 * in.hinge.half_thickness)});
}

}  // namespace

Sample solve_rolling_at(const RollingInput& in, double r2, double gamma) {
  const Angles a = angles(in.hinge.teeth, in.hinge.strokes, in.flank_angle);
  const double beta1 = beta1_at(a, gamma);
  auto m = [&](double xi) { return state(in, r2, beta1, gamma, xi).moment; };
  // ΣM(ξ) = 0: the root nearest to the symmetric split ξ = γ/2 (the branch that starts at ξ = 0
  // for γ = 0; farther roots come from the contact running round the plate's arc), by an
  // outward scan over ±γΣ and bisection
  const double c = 0.5 * gamma, h = a.gamma_sigma / kBracketScan;
  double lo = NAN, hi = NAN;
  if (m(c) == 0.0) lo = hi = c;
  for (int k = 1; k <= 2 * kBracketScan && std::isnan(lo); ++k) {
    for (double dir : {1.0, -1.0}) {
      const double x0 = c + dir * (k - 1) * h, x1 = c + dir * k * h;
      if ((m(x0) <= 0.0) != (m(x1) <= 0.0)) {
        lo = std::min(x0, x1), hi = std::max(x0, x1);
        break;
      }
    }
  }
  Sample out;
  out.gamma = gamma;
  if (std::isnan(lo)) {
    out.xi = out.f2 = out.fn = out.residual = NAN;
    return out;
  }
  const bool lo_neg = m(lo) <= 0.0;
  for (int k = 0; k < kBisections && hi - lo > 0.0; ++k) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    ((m(mid) <= 0.0) == lo_neg ? lo : hi) = mid;
  }
  const double xi = std::abs(m(lo)) <= std::abs(m(hi)) ? lo : hi;
  const State s = state(in, r2, beta1, gamma, xi);
  out.xi = xi;
  out.f2 = s.f2;
  out.fn = s.fn;
  out.f1k = s.f1k;
  out.f2k = s.f2k;
  out.residual = rolling_residual(in, r2, beta1, s, gamma, xi);
  return out;
}

Result solve_rolling(const RollingInput& in) {
  throw_if_any(validate(in));
  const double r2 = *face_radius(in.hinge);
  Result r;
  r.angles = angles(in.hinge.teeth, in.hinge.strokes, in.flank_angle);
  const double gs = r.angles.gamma_sigma;
  const double psi_max =
      hinge::psi1_max(in.hinge.pin_diameter, in.hinge.half_thickness, in.hinge.plate_radius);
  bool unsolved = false, lift = false, senses = false;
  double min_fn = 0.0;  // [N] the most negative tooth reaction, for the lift-off diagnostic
  double worst_turn = 0.0, worst_psi = 0.0;
  const auto points = static_cast<std::size_t>(std::max(in.points, 0));
  ProgressLoop loop(points, "points");
  for (int i = 0; i < in.points; ++i) {
    loop.step(static_cast<std::size_t>(i));
    Sample s = solve_rolling_at(in, r2, sample_gamma(gs, i, in.points));
    if (std::isnan(s.xi)) {
      unsolved = true;
    } else {
      lift = lift || s.fn < 0.0;
      min_fn = std::min(min_fn, s.fn);
      r.max_residual = std::max(r.max_residual, s.residual);
      worst_turn = std::max({worst_turn, std::abs(s.xi), std::abs(s.gamma - s.xi)});
      for (double th : {s.xi, s.gamma - s.xi}) {
        worst_psi = std::max(worst_psi, hinge::pose(in.hinge, r2, 2.0 * std::abs(th)).psi1);
      }
      if (!r.series.empty() && !std::isnan(r.series.back().xi)) {
        const Sample& p = r.series.back();
        senses = senses || s.xi < p.xi || (s.gamma - s.xi) < (p.gamma - p.xi);
      }
    }
    r.series.push_back(s);
  }
  loop.step(points);
  for (std::size_t i = 1; i < r.series.size(); ++i) {
    if (!(r.series[i].xi > r.series[i - 1].xi)) continue;
    Range rg{r.series[i - 1].gamma, r.series[i].gamma};
    while (i + 1 < r.series.size() && r.series[i + 1].xi > r.series[i].xi)
      rg.to = r.series[++i].gamma;
    r.roller_turns.push_back(rg);
  }
  // The turn the faces were designed for: eq. (6) makes R2 for gammaMax = 180 deg*m/z (eq. 12);
  // a given R2 was made for its own turn, eq. (6) solved for it: gamma = psi1max*(1 - R1/R2).
  const bool given_r2 = in.hinge.roller_radius > 0.0 && std::isfinite(psi_max);
  const double design_turn =
      given_r2 ? psi_max * (1.0 - in.hinge.plate_radius / r2) : hinge::gamma_max(in.hinge);
  if (unsolved) {
    r.diagnostics.push_back({Diagnostic::Severity::kInfeasible, "engagement.no_equilibrium",
                             "no roller turn xi balances the moments of (28) at some gamma", 0, 0});
  }
  if (lift) {
    r.diagnostics.push_back(
        {Diagnostic::Severity::kInfeasible, "engagement.tooth_lift_off",
         "F_N < 0 somewhere: the roller would leave the tooth (value: the least "
         "F_N; limit: 0)",
         min_fn, 0.0, "N"});
  }
  if (senses) {
    r.diagnostics.push_back({Diagnostic::Severity::kWarning, "engagement.rolling_sense",
                             "xi does not grow (or gamma - xi does not) everywhere: the assumed "
                             "senses of the rolling resistances are contradicted",
                             0.0, 0.0});
  }
  if (worst_turn > design_turn * (1.0 + 1e-12)) {
    r.diagnostics.push_back(
        {Diagnostic::Severity::kWarning, "engagement.beyond_design_turn",
         given_r2 ? "the roller turns relative to a plate beyond the turn psi1_max*(1 - R1/R2) "
                    "that the given R2 was designed for (eq. 6 solved for the turn)"
                  : "the roller turns relative to a plate beyond the hinge's gamma_max = "
                    "180 deg*m/z (eq. 12) it was designed for",
         worst_turn, design_turn, "rad"});
  }
  if (worst_psi > psi_max) {
    r.diagnostics.push_back({Diagnostic::Severity::kInfeasible, "engagement.contact_off_arc",
                             "the contact runs beyond the plate's working arc (psi1 > psi1_max, "
                             "eq. 5)",
                             worst_psi, psi_max, "rad"});
  }
  return r;
}

Wrap wrap(const Result& r, double tension, double pitch, double wrap_angle) {
  std::vector<Issue> issues;
  check::finite_positive(issues, "tension", tension, "N");
  check::finite_positive(issues, "pitch", pitch, "m");
  if (!(wrap_angle > 0.0) || !(wrap_angle <= 2.0 * kPi)) {
    issues.push_back({"wrap_angle", num(wrap_angle) + " rad", "0 < wrap angle <= 2 pi"});
  }
  if (r.series.empty() || std::isnan(r.series.back().f2)) {
    issues.push_back({"result", "(empty)", "a solved engagement ending at gamma = gammaSigma"});
  }
  throw_if_any(issues);
  const Angles& a = r.angles;
  const double q = r.series.back().f2 / tension;  // F2/F1 of a completed engagement
  const double p = r.series.back().fn / tension;  // F_N/F1
  Wrap w;
  w.pitch_radius = pitch / (2.0 * std::sin(0.5 * a.gamma_sigma));
  w.rollers = std::max(1, static_cast<int>(std::lround(wrap_angle / a.gamma_sigma)));
  w.tension.push_back(tension);
  for (int k = 0; k < w.rollers; ++k) {
    const double fk = w.tension.back();
    w.tooth_load.push_back(p * fk);
    w.tension.push_back(q * fk);
    // the tooth normal at roller k is the radius tilted by ψ: its moment about the sprocket axis
    w.torque += w.pitch_radius * p * fk * std::sin(a.psi);
  }
  return w;
}

}  // namespace catena::engagement
