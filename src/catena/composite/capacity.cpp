// Link capacity (seed 002 eq. (9)), mass, micromechanics and the design helper.
// Derivations and sources: docs/models/composite_capacity.md.
#include "catena/composite/capacity.hpp"

#include <cmath>
#include <limits>
#include <numbers>

namespace catena::composite {
namespace {

constexpr double kPi = std::numbers::pi;

// Appends an issue unless lo < value < hi (open interval), naming the range.
void open_range(std::vector<Issue>& out, const char* field, double value, double lo, double hi,
                const char* unit, const char* what) {
  if (std::isfinite(value) && value > lo && value < hi) return;
  out.push_back({field, check::format_si(value, unit), what});
}

// The reference ring on which K is computed: K and Σσ̃_r do not depend on r2, t or the gap
// (linear, scale-free problem), only on α and the elastic constants.
Ring reference_ring(const Lamina& l, double alpha) {
  Ring r;
  r.outer_radius = 0.01;
  r.inner_radius = alpha * r.outer_radius;
  r.thickness = 0.001;
  r.E_r = l.E_r;
  r.E_phi = l.E_phi;
  r.G = l.G;
  r.nu_phi_r = l.nu_phi_r;
  r.gap = 1e-3 * r.inner_radius;
  return r;
}

std::vector<double> default_alphas() {
  std::vector<double> a;
  for (int i = 0; i <= 12; ++i) a.push_back(0.30 + 0.05 * i);
  return a;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Eq. (9)

std::vector<Issue> validate(const Eq9& e) {
  std::vector<Issue> out;
  open_range(out, "alpha", e.alpha, 0.0, 1.0, "", "0 < α = r1/r2 < 1");
  check::finite_positive(out, "sum_sigma_r", e.sum_sigma_r, "");
  if (!std::isfinite(e.k_max) || e.k_max < 1.0)
    out.push_back({"k_max", check::format_si(e.k_max, ""),
                   "a concentration factor ≥ 1 (max stress / mean stress)"});
  check::finite_positive(out, "fibre_strength", e.fibre_strength, "Pa");
  return out;
}

double eq9_factor(const Eq9& e) {
  throw_if_any(validate(e));
  return e.sum_sigma_r / (e.alpha * (1.0 - e.alpha) * e.k_max);
}

double capacity(const Eq9& e, double fibre_area) {
  auto issues = validate(e);
  check::finite_positive(issues, "fibre_area", fibre_area, "m^2");
  throw_if_any(issues);
  return eq9_factor(e) * 2.0 * fibre_area * e.fibre_strength;
}

double area_for_load(const Eq9& e, double load) {
  auto issues = validate(e);
  check::finite_positive(issues, "load", load, "N");
  throw_if_any(issues);
  return load / (eq9_factor(e) * 2.0 * e.fibre_strength);
}

double consistent_sum_sigma_r(double alpha) {
  std::vector<Issue> issues;
  open_range(issues, "alpha", alpha, 0.0, 1.0, "", "0 < α = r1/r2 < 1");
  throw_if_any(issues);
  return alpha * (1.0 - alpha);
}

double capacity_from_concentration(double leg_area, double strength, double k) {
  std::vector<Issue> issues;
  check::finite_positive(issues, "leg_area", leg_area, "m^2");
  check::finite_positive(issues, "strength", strength, "Pa");
  if (!std::isfinite(k) || k < 1.0)
    issues.push_back({"k_max", check::format_si(k, ""), "a concentration factor ≥ 1"});
  throw_if_any(issues);
  return 2.0 * leg_area * strength / k;
}

// ---------------------------------------------------------------------------------------------
// Micromechanics

double rule_of_mixtures(double pf, double pm, double vf) { return vf * pf + (1.0 - vf) * pm; }

double inverse_rule_of_mixtures(double pf, double pm, double vf) {
  return 1.0 / (vf / pf + (1.0 - vf) / pm);
}

double halpin_tsai(double pf, double pm, double xi, double vf) {
  const double ratio = pf / pm;
  const double eta = (ratio - 1.0) / (ratio + xi);
  return pm * (1.0 + xi * eta * vf) / (1.0 - eta * vf);
}

std::vector<Issue> validate(const Fibre& f, const Matrix& m, double vf) {
  std::vector<Issue> out;
  check::finite_positive(out, "fibre_modulus", f.modulus, "Pa");
  open_range(out, "fibre_poisson", f.poisson, -1e-300, 0.5, "", "0 ≤ ν_f < 0.5");
  check::finite_positive(out, "fibre_strength", f.strength, "Pa");
  check::finite_positive(out, "fibre_density", f.density, "kg/m^3");
  check::finite_positive(out, "matrix_modulus", m.modulus, "Pa");
  open_range(out, "matrix_poisson", m.poisson, -1e-300, 0.5, "", "0 ≤ ν_m < 0.5");
  check::finite_positive(out, "matrix_density", m.density, "kg/m^3");
  if (std::isfinite(f.modulus) && std::isfinite(m.modulus) && f.modulus > 0 && m.modulus > 0 &&
      !(m.modulus < f.modulus))
    out.push_back(
        {"matrix_modulus", check::format_si(m.modulus, "Pa"),
         "E_m < E_f = " + check::format_si(f.modulus, "Pa") + " (the fibre is the stiff phase)"});
  if (!std::isfinite(vf) || vf < 0.0 || vf > 0.9069)
    out.push_back({"fibre_fraction", check::format_si(vf, ""),
                   "0 ≤ V_f ≤ 0.9069 (hexagonal packing of round fibres, π/(2√3))"});
  return out;
}

Lamina ring_lamina(const Fibre& f, const Matrix& m, double vf) {
  throw_if_any(validate(f, m, vf));
  const double gf = f.modulus / (2.0 * (1.0 + f.poisson));
  const double gm = m.modulus / (2.0 * (1.0 + m.poisson));
  Lamina l;
  l.fibre_fraction = vf;
  l.E_phi = rule_of_mixtures(f.modulus, m.modulus, vf);
  l.E_r = halpin_tsai(f.modulus, m.modulus, 2.0, vf);
  l.G = halpin_tsai(gf, gm, 1.0, vf);
  l.nu_phi_r = rule_of_mixtures(f.poisson, m.poisson, vf);
  // Fibres fail first (ε_f < ε_m): at the fibre failure strain the matrix carries E_m σ_f/E_f.
  l.strength = vf * f.strength + (1.0 - vf) * m.modulus * f.strength / f.modulus;
  l.density = rule_of_mixtures(f.density, m.density, vf);
  return l;
}

// ---------------------------------------------------------------------------------------------
// Mass

std::vector<Issue> validate(const LinkGeometry& g) {
  std::vector<Issue> out;
  check::finite_positive(out, "inner_radius", g.inner_radius, "m");
  check::finite_positive(out, "outer_radius", g.outer_radius, "m");
  check::finite_positive(out, "thickness", g.thickness, "m");
  check::finite_positive(out, "pitch", g.pitch, "m");
  check::finite_positive(out, "band_density", g.band_density, "kg/m^3");
  check::finite_positive(out, "insert_density", g.insert_density, "kg/m^3");
  if (g.inner_radius > 0 && g.outer_radius > 0 && !(g.inner_radius < g.outer_radius))
    out.push_back({"inner_radius", check::format_si(g.inner_radius, "m"),
                   "r1 < r2 = " + check::format_si(g.outer_radius, "m")});
  if (g.inner_radius > 0 && g.pitch > 0 && !(g.pitch > 2.0 * g.inner_radius))
    out.push_back({"pitch", check::format_si(g.pitch, "m"),
                   "p > 2 r1 = " + check::format_si(2.0 * g.inner_radius, "m") +
                       " (the two pins must not overlap)"});
  return out;
}

LinkMass link_mass(const LinkGeometry& g) {
  throw_if_any(validate(g));
  LinkMass m;
  const double r1 = g.inner_radius, r2 = g.outer_radius;
  m.band_length = 2.0 * g.pitch + kPi * (r1 + r2);
  m.band_area = (r2 - r1) * g.thickness;
  m.insert_area = 2.0 * r1 * g.pitch - kPi * r1 * r1;
  m.band = g.band_density * m.band_area * m.band_length;
  m.insert = g.insert_density * m.insert_area * g.thickness;
  m.total = m.band + m.insert;
  return m;
}

std::vector<Issue> validate(const SteelPlate& s, double load) {
  std::vector<Issue> out;
  check::finite_positive(out, "load", load, "N");
  check::finite_positive(out, "steel_strength", s.strength, "Pa");
  check::finite_positive(out, "steel_thickness", s.thickness, "m");
  check::finite_positive(out, "steel_density", s.density, "kg/m^3");
  check::finite_positive(out, "pitch", s.pitch, "m");
  if (!std::isfinite(s.hole_radius) || s.hole_radius < 0.0)
    out.push_back({"hole_radius", check::format_si(s.hole_radius, "m"), "a radius ≥ 0 m"});
  return out;
}

SteelPlateResult steel_plate(const SteelPlate& s, double load) {
  auto issues = validate(s, load);
  throw_if_any(issues);
  SteelPlateResult r;
  r.net_area = load / s.strength;
  r.width = 2.0 * s.hole_radius + r.net_area / s.thickness;
  if (!(s.pitch > r.width)) {
    issues.push_back({"pitch", check::format_si(s.pitch, "m"),
                      "p > plate width w = " + check::format_si(r.width, "m") +
                          " (the plate outline must be a stadium)"});
    throw_if_any(issues);
  }
  r.face_area =
      r.width * s.pitch + kPi * r.width * r.width / 4.0 - 2.0 * kPi * s.hole_radius * s.hole_radius;
  r.mass = s.density * s.thickness * r.face_area;
  return r;
}

// ---------------------------------------------------------------------------------------------
// Design helper

std::vector<Issue> validate(const DesignInput& d) {
  auto out = validate(d.fibre, d.matrix, d.fibre_fraction);
  if (std::isfinite(d.fibre_fraction) && d.fibre_fraction == 0.0)
    out.push_back({"fibre_fraction", "0", "0 < V_f ≤ 0.9069 (a design needs fibres)"});
  check::finite_positive(out, "load", d.load, "N");
  check::finite_positive(out, "thickness", d.thickness, "m");
  check::finite_positive(out, "pitch", d.pitch, "m");
  check::finite_positive(out, "insert_density", d.insert_density, "kg/m^3");
  for (double a : d.alphas)
    if (!std::isfinite(a) || a < 0.05 || a > 0.95)
      out.push_back({"alpha", check::format_si(a, ""),
                     "0.05 ≤ α = r1/r2 ≤ 0.95 (the ring solver's default harmonics stay ≤ 4000)"});
  if (d.alphas.size() > 50)
    out.push_back({"alpha", std::to_string(d.alphas.size()) + " values", "at most 50 values"});
  if (d.steel_strength != 0.0) {
    check::finite_positive(out, "steel_strength", d.steel_strength, "Pa");
    check::finite_positive(out, "steel_thickness", d.steel_thickness, "m");
    check::finite_positive(out, "steel_density", d.steel_density, "kg/m^3");
  } else if (d.steel_thickness != 0.0) {
    out.push_back({"steel_strength", "0", "σ_B > 0 when a steel plate thickness is given"});
  }
  for (Issue& i : validate(d.analysis)) out.push_back(i);
  return out;
}

Design design(const DesignInput& d) {
  throw_if_any(validate(d));
  Design out;
  out.lamina = ring_lamina(d.fibre, d.matrix, d.fibre_fraction);
  const Lamina& l = out.lamina;
  const auto alphas = d.alphas.empty() ? default_alphas() : d.alphas;
  double best_mass = std::numeric_limits<double>::infinity();
  double lightest_any = std::numeric_limits<double>::infinity();
  bool any_feasible = false;
  std::vector<std::vector<Diagnostic>> ring_diagnostics;
  for (std::size_t i = 0; i < alphas.size(); ++i) {
    DesignPoint p;
    p.alpha = alphas[i];
    const Result res = analyse(reference_ring(l, p.alpha), d.analysis);
    ring_diagnostics.push_back(res.diagnostics);
    p.k = res.stress_concentration;
    p.sum_sigma_r = res.sum_sigma_r;
    p.leg_area = d.load * p.k / (2.0 * l.strength);
    p.fibre_area = l.fibre_fraction * p.leg_area;
    p.outer_radius = p.leg_area / ((1.0 - p.alpha) * d.thickness);
    p.inner_radius = p.alpha * p.outer_radius;
    p.feasible = d.pitch > 2.0 * p.inner_radius;
    if (p.feasible) {
      p.mass = link_mass(
          {p.inner_radius, p.outer_radius, d.thickness, d.pitch, l.density, d.insert_density});
      if (p.mass.total < best_mass) {
        best_mass = p.mass.total;
        out.best = i;
      }
      any_feasible = true;
    } else {
      // the band alone, for information; the insert cannot exist
      p.mass.band_length = 2.0 * d.pitch + kPi * (p.inner_radius + p.outer_radius);
      p.mass.band_area = p.leg_area;
      p.mass.band = l.density * p.leg_area * p.mass.band_length;
      p.mass.total = p.mass.band;
      if (!any_feasible && p.mass.total < lightest_any) {
        lightest_any = p.mass.total;
        out.best = i;
      }
    }
    out.scan.push_back(p);
  }
  // the ring analysis's own findings (e.g. contact tension under bilateral contact) for the
  // chosen α
  out.diagnostics = ring_diagnostics[out.best];
  if (!any_feasible) {
    const DesignPoint& p = out.scan[out.best];
    out.diagnostics.push_back(
        {Diagnostic::Severity::kInfeasible, "ring.design.pitch_too_small",
         "no α gives pins that clear each other: the pitch must exceed 2 r1; the smallest r1 "
         "needed is shown as the limit",
         d.pitch, 2.0 * p.inner_radius, "m"});
  }
  if (d.steel_strength > 0.0) {
    const DesignPoint& p = out.scan[out.best];
    const double width = 2.0 * p.inner_radius + d.load / (d.steel_strength * d.steel_thickness);
    if (d.pitch > width) {
      out.has_steel = true;
      out.steel = steel_plate(
          {d.steel_strength, d.steel_thickness, d.steel_density, d.pitch, p.inner_radius}, d.load);
      out.mass_ratio = out.steel.mass / p.mass.total;
    } else {
      out.diagnostics.push_back(
          {Diagnostic::Severity::kWarning, "ring.design.steel_plate_too_wide",
           "the steel plate that carries the load (width 2 r1 + P/(σ_B t_s)) is wider than the "
           "pitch; no steel comparison",
           width, d.pitch, "m"});
    }
  }
  return out;
}

}  // namespace catena::composite
