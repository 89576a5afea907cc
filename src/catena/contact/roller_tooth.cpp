#include "catena/contact/roller_tooth.hpp"

#include <algorithm>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

namespace catena::contact {
namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kArcminute = kPi / (180.0 * 60.0);  // [rad]
constexpr double kMaxLength = 10.0;                  // [m] roller and tooth sizes
}  // namespace

std::vector<Issue> validate(const RollerTooth& c) {
  std::vector<Issue> issues;
  // Lengths up to 10 m: beyond them the slice law's limit load π·E*·b²/(4R) overflows.
  for (const auto& [key, value] :
       {std::pair{"roller_diameter", c.roller_diameter},
        std::pair{"roller_length", c.roller_length}, std::pair{"tooth_radius", c.tooth_radius}}) {
    check::finite_positive(issues, key, value, "m");
    if (std::isfinite(value) && value > kMaxLength)
      issues.push_back({key, check::format_si(value, "m"),
                        "a length 0 < x ≤ " + check::format_si(kMaxLength, "m")});
  }
  // The tooth's constants are reported under their own names, and only when they differ from
  // the roller's: one bad --modulus for both bodies is one problem, not two.
  const bool same = c.tooth.modulus == c.roller.modulus && c.tooth.poisson == c.roller.poisson;
  for (const auto& [e, prefix] : {std::pair{&c.roller, ""}, std::pair{&c.tooth, "tooth_"}}) {
    if (same && e == &c.tooth) break;
    check::finite_positive(issues, (std::string(prefix) + "modulus").c_str(), e->modulus, "Pa");
    if (!(e->poisson >= 0.0 && e->poisson < 0.5)) {
      issues.push_back(
          {std::string(prefix) + "poisson", check::format_si(e->poisson, ""), "0 ≤ ν < 0.5"});
    }
  }
  if (issues.empty() && c.profile == Profile::kConcave &&
      c.tooth_radius <= 0.5 * c.roller_diameter) {
    issues.push_back(
        {"tooth_radius", check::format_si(c.tooth_radius, "m"),
         "a concave flank radius r1 > D_p/2 = " + check::format_si(0.5 * c.roller_diameter, "m") +
             " (the roller must fit in the hollow)"});
  }
  return issues;
}

double reduced_radius(const RollerTooth& c) {
  const double sign = c.profile == Profile::kConvex ? 1.0 : -1.0;
  return c.roller_diameter * c.tooth_radius /
         (2.0 * (c.tooth_radius + sign * 0.5 * c.roller_diameter));
}

double paper_stress(double load, double modulus, double length, double radius) {
  return 0.418 * std::sqrt(load * modulus / (length * radius));  // 001 eq. (1)
}

HertzResult hertz(const RollerTooth& c, double load) {
  throw_if_any(validate(c));
  const LineContact lc =
      line_contact(load / c.roller_length, reduced_radius(c), contact_modulus(c.roller, c.tooth));
  // Johnson (1985) §4.2: beneath a plane-strain Hertz contact the principal shear stress peaks at
  // z = 0.786 b with τ1 = 0.300 p0, independent of ν (checked numerically in the tests).
  return {lc.peak_pressure, lc.half_width, 0.300 * lc.peak_pressure, 0.786 * lc.half_width};
}

std::optional<double> skew_gamma(double pitch) {
  // 001, below eq. (2): γ by chain pitch.
  constexpr std::pair<double, double> kTable[] = {
      {12.7e-3, 0.0023}, {15.875e-3, 0.00195}, {19.05e-3, 0.0016}, {25.4e-3, 0.0012}};
  for (auto [p, g] : kTable) {
    if (std::abs(pitch - p) < 1e-6) return g;
  }
  return std::nullopt;
}

double skew_from_gauge(double dh, double base) { return std::atan(dh / base); }

double load_factor(double gamma, double skew, double skew_factor) {
  const double arcmin = skew * skew_factor / kArcminute;  // φ_p in arc-minutes (001, eq. 2)
  return 1.0 + gamma * arcmin * arcmin;
}

LineApproach line_approach(const RollerTooth& c) {
  return line_approach(c.roller, c.tooth, reduced_radius(c), 0.5 * c.roller_diameter);
}

LineApproach line_approach(const Elastic& a, const Elastic& b, double rho, double r_ref) {
  LineApproach l;
  l.e_star = contact_modulus(a, b);
  l.rho = rho;
  l.r_ref = r_ref;
  for (const Elastic* e : {&a, &b}) l.compliance += (1.0 - e->poisson * e->poisson) / e->modulus;
  // 2 ln(4R_ref/b) = 2 ln(4R_ref) − ln(4ρ/(πE*)) − ln q
  l.a = l.compliance / kPi;
  l.c = 2.0 * std::log(4.0 * l.r_ref) - std::log(4.0 * l.rho / (kPi * l.e_star)) - 1.0;
  return l;
}

double LineApproach::approach(double q) const {
  if (q <= 0.0) return 0.0;
  const double b = std::sqrt(4.0 * q * rho / (kPi * e_star));
  const double log_term = 2.0 * std::log(4.0 * r_ref / b) - 1.0;
  return q / kPi * compliance * log_term;
}

double LineApproach::load(double delta) const {
  if (!(delta > 0.0)) return 0.0;
  // f(u) = u + ln(C − u) − ln(δ/A), u = ln q: increasing and concave on u < C − 1, so a Newton
  // step from anywhere there lands at or left of the root and the iterates then rise to it
  // monotonically; a step past the bracket's top C − 1 is halved back into it
  const double target = std::log(delta / a), top = c - 1.0;
  if (!(target < top)) return NAN;  // δ(e^top) = A e^top is the branch's largest approach
  // the start: with v = C − u the root solves v − ln v = s, s = C − ln(δ/A) > 1, i.e.
  // v = −W₋₁(−e^(−s)); the first five terms of W₋₁'s asymptotic series (Corless et al. 1996,
  // §4), v ≈ s + L + L/s − L(L − 2)/(2s²) + L(2L² − 9L + 6)/(6s³), L = ln s, are within
  // 0.02 of it for s ≥ 2 and 3e-4 for s ≥ 5 (0.1 as s → 1), so two Newton steps reach round-off
  // for s ≥ 3.5 (a 12B seat's loads below 2 kN) and three up to the cap, where four or five did
  // from s + L
  const double s = c - target, l = std::log(s), r = 1.0 / s;
  const double v =
      s + l + r * (l + r * (-0.5 * l * (l - 2.0) + r * l * (2.0 * l * l - 9.0 * l + 6.0) / 6.0));
  double u = c - v;
  if (!(u < top)) u = top - 1.0;  // v > s > 1 makes this unreachable but for round-off
  for (int it = 0; it < 60; ++it) {
    const double d = c - u;
    const double f = u + std::log(d) - target;
    const double step = f / (1.0 - 1.0 / d);
    double next = u - step;
    if (!(next < top)) next = 0.5 * (u + top);
    // the error left after a Newton step is |f''|/(2f')·step² = step²/(2 d (d − 1)); stop once
    // twice that is below 1e-16 |u| (a half unit in the last place), without a step to confirm it
    const double dn = c - next;
    const bool done = step * step <= 1e-16 * std::max(1.0, std::abs(next)) * dn * (dn - 1.0);
    u = next;
    if (done) break;
  }
  return std::exp(u);
}

double LineApproach::energy(double q) const {
  if (q <= 0.0) return 0.0;
  return a * q * q * (0.5 * (c - std::log(q)) - 0.25);
}

double slice_approach(const RollerTooth& c, double q) { return line_approach(c).approach(q); }

namespace {
// Largest load per length for which δ(q) still increases: b = 4R_ref/e (beyond it the
// plane-strain approach formula is outside its range). LineApproach::max_load() is the same value
// as e^(C−1), and LineApproach::load the same inverse by Newton, but both round differently in
// the last digit, which moves the last digit of examples/001_roller_chain_skew.toml's slice
// loads: the slice model keeps this form and the bracketed root.
double slice_load_limit(const RollerTooth& c) {
  const double b_max = 4.0 * 0.5 * c.roller_diameter / std::exp(1.0);
  return kPi * contact_modulus(c.roller, c.tooth) * b_max * b_max / (4.0 * reduced_radius(c));
}

// Inverse of slice_approach on its increasing branch; clamps at the limit.
double slice_load(const RollerTooth& c, double delta, double q_max) {
  if (delta <= 0.0) return 0.0;
  if (slice_approach(c, q_max) <= delta) return q_max;
  boost::uintmax_t it = 100;
  auto [lo, up] =
      boost::math::tools::toms748_solve([&](double q) { return slice_approach(c, q) - delta; }, 0.0,
                                        q_max, boost::math::tools::eps_tolerance<double>(48), it);
  return 0.5 * (lo + up);
}
}  // namespace

SliceResult slice_model(const RollerTooth& c, double load, double skew, const SliceOptions& o) {
  std::vector<Issue> issues = validate(c);
  check::finite_positive(issues, "load", load, "N");
  check::finite(issues, "skew", skew, "rad");
  if (std::abs(skew) >= 0.5 * kPi)
    issues.push_back({"skew", check::format_si(skew, "rad"), "|φ| < 90°"});
  if (o.slices < 3) issues.push_back({"slices", std::to_string(o.slices), "at least 3 slices"});
  throw_if_any(issues);
  const int n = o.slices;
  const double w = c.roller_length / n;
  const double slope = std::tan(std::abs(skew));
  SliceResult r;
  for (int k = 0; k < n; ++k) r.s.push_back(-0.5 * c.roller_length + (k + 0.5) * w);
  const double q_mean = load / c.roller_length;
  const double q_max = slice_load_limit(c);
  if (!std::isfinite(q_max) || !(q_max > 0)) {  // guarded by validate's ranges; never a bracket
    throw InputError({{"roller_diameter", check::format_si(c.roller_diameter, "m"),
                       "a roller whose slice-law limit load is finite (smaller D_p, r1, E)"}});
  }
  if (q_mean * n >=
      q_max * (n - 1)) {  // even spread over the roller it would exceed the law's range
    throw InputError({{"load", check::format_si(load, "N"),
                       "a load below " + check::format_si(q_max * c.roller_length, "N") +
                           " for the slice model's compliance law (b < 4R/e)"}});
  }
  auto total = [&](double delta0) {
    double sum = 0.0;
    for (double s : r.s) sum += slice_load(c, delta0 - s * slope, q_max) * w;
    return sum;
  };
  // bracket δ0: at −(L/2)·tan φ no slice touches; δ0 < 0 when less than half the roller carries
  double lo = -0.5 * c.roller_length * slope;
  double hi = slice_approach(c, q_mean) + 0.5 * c.roller_length * slope;
  for (int guard = 0; total(hi) < load; ++guard) {
    if (guard > 200 || hi > 1.0) {
      throw InputError(
          {{"load", check::format_si(load, "N"),
            "a load the skewed roller can carry within the slice law's range (b < 4R/e "
            "at every slice)"}});
    }
    hi = 2.0 * hi + 1e-9;
  }
  boost::uintmax_t it = 200;
  auto [a, b] =
      boost::math::tools::toms748_solve([&](double d0) { return total(d0) - load; }, lo, hi,
                                        boost::math::tools::eps_tolerance<double>(48), it);
  r.iterations = static_cast<int>(it);
  r.approach = 0.5 * (a + b);
  const double e_star = contact_modulus(c.roller, c.tooth);
  for (double s : r.s) {
    const double q = slice_load(c, r.approach - s * slope, q_max);
    r.q.push_back(q);
    r.load_sum += q * w;
  }
  // The peak and the loaded length are taken from the solved approach itself, not from the
  // slice centres: the most loaded point is the roller's end s = −L/2, and the gap closes at
  // s = δ0/tan φ. (At slice centres both would carry an O(Δs) mesh error.)
  r.peak_load = slice_load(c, r.approach + 0.5 * c.roller_length * slope, q_max);
  if (r.peak_load >= q_max * (1.0 - 1e-12)) {
    throw InputError(
        {{"load", check::format_si(load, "N"),
          "a load whose skewed end load stays below " + check::format_si(q_max, "N/m") +
              " per length, the slice law's range (b < 4R/e)"}});
  }
  r.loaded_length =
      slope == 0.0 ? c.roller_length
                   : std::clamp(r.approach / slope + 0.5 * c.roller_length, 0.0, c.roller_length);
  const LineContact peak = line_contact(r.peak_load, reduced_radius(c), e_star);
  r.stress_peak = peak.peak_pressure;
  r.peak_half_width = peak.half_width;
  return r;
}

}  // namespace catena::contact
