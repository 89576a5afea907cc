#include "catena/hinge/synthesis.hpp"

#include <algorithm>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <limits>
#include <numbers>

#include "catena/hinge/kinematics.hpp"

namespace catena::hinge {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kInf = std::numeric_limits<double>::infinity();
// The root solves below hand TOMS 748 the end values they have already computed for the bracket
// checks instead of letting it evaluate them again. Its overload without end values spends 2 of
// its 200 allowed evaluations on them, so the same limit is 198 here.
constexpr boost::uintmax_t kSolveIterations = 200 - 2;

// Area of the intersection of two circles (radii r, s; centre distance D).
double lens(double r, double s, double dist) {
  if (dist >= r + s) return 0.0;
  if (dist <= std::abs(r - s)) return kPi * std::min(r, s) * std::min(r, s);
  const double alpha =
      std::acos(std::clamp((dist * dist + r * r - s * s) / (2 * dist * r), -1.0, 1.0));
  const double beta =
      std::acos(std::clamp((dist * dist + s * s - r * r) / (2 * dist * s), -1.0, 1.0));
  return r * r * (alpha - std::sin(2 * alpha) / 2) + s * s * (beta - std::sin(2 * beta) / 2);
}

// Area of the d circle beyond the chord x = a (flat face).
double segment(double r0, double a) {
  if (a >= r0) return 0.0;
  return r0 * r0 * std::acos(a / r0) - a * std::sqrt(r0 * r0 - a * a);
}

Diagnostic diagnostic(Diagnostic::Severity severity, const char* code, std::string message,
                      double value, double limit, const char* unit) {
  return {severity, code, std::move(message), value, limit, unit};
}

std::string mm(double metres) { return check::format_si(metres * 1e3, "mm"); }
std::string degrees(double rad) { return check::format_si(rad * 180.0 / kPi, "") + "°"; }

}  // namespace

double x_n1(double d, double a, double r1) {
  return (0.25 * d * d + a * (a + 2.0 * r1)) / (2.0 * (a + r1));  // 000 eq. (4)
}

double psi1_max(double d, double a, double r1) {
  // 000 eq. (5): cos Ψ1max = (a + R1 − x)/R1 = 1 − (d²/4 − a²)/(2R1(R1 + a))
  const double c = 1.0 - (0.25 * d * d - a * a) / (2.0 * r1 * (r1 + a));
  return std::acos(std::clamp(c, -1.0, 1.0));
}

double r1_max(double d, double a, double gmax) {
  // 000 eq. (7) with γmax of eq. (12) in place of π/z: the root of Ψ1max(R1) = γmax.
  // 1 − cos γ cancels to 0 for γ below ~1e-8 (z ~ 1e9 teeth: R1max came out NaN and a hinge
  // sweep blamed --plate-radius, issue 18); 2 sin²(γ/2) is the same without the cancellation,
  // used only for small γ so that every result of a sprocket with z < 3000 stays bit for bit.
  const double one_minus_cos =
      gmax < 1e-3 ? 2.0 * std::pow(std::sin(0.5 * gmax), 2) : 1.0 - std::cos(gmax);
  return 0.5 * (-a + std::sqrt(a * a + 2.0 * (0.25 * d * d - a * a) / one_minus_cos));
}

std::optional<double> r2_eq6(double d, double a, double r1, double gmax) {
  // 000 eq. (6): γmax = Ψ1max (R2 − R1)/R2 (eqs. 2–3) ⇒ R2 = R1 Ψ1max / (Ψ1max − γmax), both
  // angles in radians. Conclusion 7's R2 = 35.4 mm for R1 = 34 mm is out of reach of this form;
  // taken with Ψ1max in degrees it gives such near-conformal pairs (docs/models/hinge.md,
  // test Paper000.ThesisR2_35_4IsEq6WithPsi1maxInDegreesForInputsTheSummaryDoesNotPrint).
  const double psi = psi1_max(d, a, r1);
  if (psi < gmax) return std::nullopt;
  if (psi == gmax) return kInf;
  return r1 * psi / (psi - gmax);
}

double section_area(double d, double a, double face_radius) {
  const double r0 = 0.5 * d;
  const double cut = (face_radius == 0.0 || !std::isfinite(face_radius))
                         ? segment(r0, a)
                         : lens(r0, face_radius, a + face_radius);
  // 000 eq. (10) subtracts 4(A1 + A2) = 2 lenses of the R1 circle; the true faces are R2 arcs.
  return kPi * r0 * r0 - 2.0 * cut;
}

std::optional<double> a_min_eq10(double d, double r1, double tension, double allowable_shear) {
  const double need = tension / allowable_shear;  // 000 eq. (10), right-hand side
  const double r0 = 0.5 * d;
  auto excess = [&](double a) { return section_area(d, a, r1) - need; };
  const double at_r0 = excess(r0);
  if (at_r0 < 0.0) return std::nullopt;  // even the uncut circle is too small
  const double at_0 = excess(0.0);
  if (at_0 >= 0.0) return 0.0;
  boost::uintmax_t iterations = kSolveIterations;
  auto [lo, hi] = boost::math::tools::toms748_solve(
      excess, 0.0, r0, at_0, at_r0, boost::math::tools::eps_tolerance<double>(50), iterations);
  return 0.5 * (lo + hi);
}

std::optional<JointLimit> a_min_at_r1max(double d, double gmax, double tension,
                                         double allowable_shear) {
  const double need = tension / allowable_shear;
  auto excess = [&](double a) { return section_area(d, a, r1_max(d, a, gmax)) - need; };
  const double lo = 1e-9 * d, hi = 0.5 * d * (1 - 1e-9);
  const double at_lo = excess(lo);
  if (at_lo >= 0.0) return JointLimit{0.0, r1_max(d, 0.0, gmax)};
  const double at_hi = excess(hi);
  if (at_hi < 0.0) return std::nullopt;
  boost::uintmax_t iterations = kSolveIterations;
  auto [a, b] = boost::math::tools::toms748_solve(
      excess, lo, hi, at_lo, at_hi, boost::math::tools::eps_tolerance<double>(50), iterations);
  const double a_min = 0.5 * (a + b);
  return JointLimit{a_min, r1_max(d, a_min, gmax)};
}

double rolling_limit(double friction, double r1, double r2) {
  const double ratio = std::isfinite(r2) && r2 != 0.0 ? r1 / r2 : 0.0;
  return std::atan(friction) * (1.0 - ratio);  // 000 eq. (21)
}

std::vector<Issue> validate(const Loads& l) {
  std::vector<Issue> issues;
  auto positive = [&](const char* field, const std::optional<double>& v, const char* unit) {
    if (v) check::finite_positive(issues, field, *v, unit);
  };
  positive("tension", l.tension, "N");
  positive("allowable_shear", l.allowable_shear, "Pa");
  positive("contact_length", l.contact_length, "m");
  positive("allowable_contact", l.allowable_contact, "Pa");
  // One problem per value: plate and roller share --modulus and --poisson, so the roller's
  // are checked only when they differ from the plate's.
  const bool same = l.roller.modulus == l.plate.modulus && l.roller.poisson == l.plate.poisson;
  for (const Elastic* e : {&l.plate, &l.roller}) {
    if (same && e == &l.roller) break;
    check::finite_positive(issues, "modulus", e->modulus, "Pa");
    if (!std::isfinite(e->poisson) || e->poisson < 0.0 || e->poisson >= 0.5) {
      issues.push_back({"poisson", check::format_si(e->poisson, ""), "0 ≤ ν < 0.5"});
    }
  }
  if (l.friction && (!std::isfinite(*l.friction) || *l.friction < 0.0)) {
    issues.push_back({"friction", check::format_si(*l.friction, ""), "a friction factor f ≥ 0"});
  }
  return issues;
}

Synthesis synthesize(const Hinge& h, const Loads& loads) {
  std::vector<Issue> issues = validate(h);
  const std::vector<Issue> load_issues = validate(loads);
  issues.insert(issues.end(), load_issues.begin(), load_issues.end());
  throw_if_any(issues);
  using S = Diagnostic::Severity;
  Synthesis s;
  const double d = h.pin_diameter;
  const double a = h.half_thickness;
  const double r1 = h.plate_radius;
  s.gamma_max = gamma_max(h);
  s.phi_max = 2.0 * s.gamma_max;
  s.x_n1 = x_n1(d, a, r1);
  s.psi1_max = psi1_max(d, a, r1);
  s.r1_max = r1_max(d, a, s.gamma_max);
  const bool flat = h.face == Face::kFlat;
  if (flat) {
    s.r2 = kInf;
  } else if (h.roller_radius > 0.0) {
    s.r2 = h.roller_radius;
  } else if (const auto r2 = r2_eq6(d, a, r1, s.gamma_max); r2 && std::isfinite(*r2)) {
    s.r2 = *r2;
    s.r2_from_eq6 = true;
  } else {
    s.r2 = kInf;
    s.r2_from_eq6 = true;
    s.diagnostics.push_back(
        diagnostic(S::kInfeasible, "hinge.r1_exceeds_r1max",
                   "R1 = " + mm(r1) + " ≥ R1max = " + mm(s.r1_max) +
                       " (eq. 7): no concave face reaches γmax = " + degrees(s.gamma_max) +
                       " within the roller (R2 → ∞ at R1max); choose R1 < R1max or flat faces",
                   r1, s.r1_max, "m"));
  }

  // Arc of the roller's face left beyond the contact at φmax (negative: contact runs off).
  const std::vector<Point> corners = feature_points(h, s.r2);
  if (flat) {
    const double reach = flat_contact_offset(h) + r1 * s.gamma_max;
    s.face_margin = h.face_half_length - reach;
  } else if (std::isfinite(s.r2)) {
    const double edge = std::acos(std::clamp((a + s.r2 - corners[0].x) / s.r2, -1.0, 1.0));
    const Pose end = pose(h, s.r2, s.phi_max);
    s.face_margin = s.r2 * (edge - end.psi2);
  } else {
    s.face_margin = corners[0].y - r1 * s.gamma_max;
  }
  if (s.face_margin < 0.0) {
    s.diagnostics.push_back(diagnostic(S::kInfeasible, "hinge.contact_leaves_face",
                                       "the contact runs " + mm(-s.face_margin) +
                                           " beyond the roller's working face before the "
                                           "links reach φmax = " +
                                           degrees(s.phi_max),
                                       s.face_margin, 0.0, "m"));
  }

  s.section_area_eq10 = section_area(d, a, r1);
  s.section_area = section_area(d, a, flat ? 0.0 : s.r2);
  if (loads.tension && loads.allowable_shear) {
    const double need = *loads.tension / *loads.allowable_shear;
    s.a_min = a_min_eq10(d, r1, *loads.tension, *loads.allowable_shear);
    s.step1 = a_min_at_r1max(d, s.gamma_max, *loads.tension, *loads.allowable_shear);
    s.shear_stress = *loads.tension / s.section_area;
    if (!s.a_min) {
      s.diagnostics.push_back(diagnostic(
          S::kInfeasible, "hinge.shear_section_too_small",
          "even the uncut roller circle (" + check::format_si(kPi * d * d / 4 * 1e6, "mm²") +
              ") is smaller than F/[τ] = " + check::format_si(need * 1e6, "mm²") +
              " (eq. 10): a larger pin diameter d is needed",
          kPi * d * d / 4, need, "m^2"));
    } else if (a < *s.a_min) {
      s.diagnostics.push_back(diagnostic(
          S::kInfeasible, "hinge.half_thickness_below_a_min",
          "a = " + mm(a) + " < a_min = " + mm(*s.a_min) + " of the shear condition (eq. 10)", a,
          *s.a_min, "m"));
    }
    if (*s.shear_stress > *loads.allowable_shear) {
      s.diagnostics.push_back(
          diagnostic(S::kInfeasible, "hinge.shear_stress",
                     "shear stress F/A = " + check::format_si(*s.shear_stress / 1e6, "MPa") +
                         " on the true section exceeds [τ] = " +
                         check::format_si(*loads.allowable_shear / 1e6, "MPa"),
                     *s.shear_stress, *loads.allowable_shear, "Pa"));
    }
  }
  if (loads.tension && loads.contact_length) {
    const double radius = conformal_radius(r1, flat ? kInf : s.r2);
    const LineContact c = line_contact(*loads.tension / *loads.contact_length, radius,
                                       contact_modulus(loads.plate, loads.roller));
    s.contact_stress = c.peak_pressure;
    s.contact_half_width = c.half_width;
    if (loads.allowable_contact && c.peak_pressure > *loads.allowable_contact) {
      s.diagnostics.push_back(diagnostic(
          S::kInfeasible, "hinge.contact_stress",
          "Hertz contact stress σH = " + check::format_si(c.peak_pressure / 1e6, "MPa") +
              " exceeds [σH] = " + check::format_si(*loads.allowable_contact / 1e6, "MPa"),
          c.peak_pressure, *loads.allowable_contact, "Pa"));
    }
  }
  if (loads.friction) {
    s.rolling_limit = rolling_limit(*loads.friction, r1, s.r2);
    if (*s.rolling_limit < s.gamma_max) {
      s.diagnostics.push_back(diagnostic(
          S::kWarning, "hinge.rolling_limit_below_working_turn",
          "with the roller held, friction f = " + check::format_si(*loads.friction, "") +
              " keeps the hinge rolling only up to a roller turn γ = " + degrees(*s.rolling_limit) +
              " (eq. 21), below γmax = " + degrees(s.gamma_max) +
              ": the plate's figured aperture must guide the roller beyond it",
          *s.rolling_limit, s.gamma_max, "rad"));
    }
  }
  return s;
}

}  // namespace catena::hinge
