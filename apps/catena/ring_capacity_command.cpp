// catena ring capacity: seed 002 eq. (9) and the mass comparison;
// catena ring design: size a fibre-wound link for a breaking force
// (docs/models/composite_capacity.md). Both are subcommands of `catena ring` (ring_command.cpp
// calls add_ring_capacity/add_ring_design).
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <sstream>

#include "catena/composite/capacity.hpp"
#include "cli_support.hpp"
#include "commands.hpp"

namespace catena::cli {
namespace {

using io::QuantityKind;
using nlohmann::ordered_json;
using namespace catena::composite;

constexpr const char* kSource =
    "seed 002 eq. (9) and its example; micromechanics: rule of mixtures, Halpin-Tsai "
    "(Halpin & Kardos 1976; Jones, Mechanics of Composite Materials, 2nd ed. 1999, sec. 3.3-3.4)";

// A number followed by one of `units` (factor to SI); a bare number takes units[0].
struct UnitFactor {
  const char* name;
  double factor;
};

std::optional<double> with_units(FlagReader& in, const std::string& flag, const std::string& text,
                                 std::initializer_list<UnitFactor> units, const char* expected) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  std::string unit(end);
  while (!unit.empty() && unit.front() == ' ') unit.erase(0, 1);
  if (end == text.c_str() || !std::isfinite(v)) {
    in.add({flag, "'" + text + "'", expected});
    return std::nullopt;
  }
  if (unit.empty()) return v * units.begin()->factor;
  for (const UnitFactor& u : units)
    if (unit == u.name) return v * u.factor;
  in.add({flag, "'" + text + "'", expected});
  return std::nullopt;
}

std::optional<double> area(FlagReader& in, const std::string& flag, const std::string& text) {
  return with_units(in, flag, text,
                    {{"mm^2", 1e-6},
                     {"mm2", 1e-6},
                     {"mm²", 1e-6},
                     {"cm^2", 1e-4},
                     {"cm2", 1e-4},
                     {"m^2", 1.0},
                     {"m2", 1.0}},
                    "an area: mm^2 (bare number), cm^2 or m^2, e.g. 22.7mm^2");
}

std::optional<double> density(FlagReader& in, const std::string& flag, const std::string& text) {
  return with_units(
      in, flag, text,
      {{"kg/m^3", 1.0}, {"kg/m3", 1.0}, {"g/cm^3", 1e3}, {"g/cm3", 1e3}, {"g/cc", 1e3}},
      "a density: kg/m^3 (bare number) or g/cm^3, e.g. 2.56g/cm^3");
}

std::optional<double> number(FlagReader& in, const std::string& flag, const std::string& text,
                             const char* expected) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0' || !std::isfinite(v)) {
    in.add({flag, "'" + text + "'", expected});
    return std::nullopt;
  }
  return v;
}

// Model issues for values that parsed: a NaN stands for a flag already reported as missing or
// unreadable, so its model issue would repeat it. Everything is then reported at once.
void add_parsed_model_issues(FlagReader& in, const std::vector<Issue>& model) {
  std::vector<Issue> keep;
  for (const Issue& i : model)
    if (i.value.rfind("nan", 0) != 0 && i.value.rfind("-nan", 0) != 0) keep.push_back(i);
  in.add_model_issues(keep);
}

void missing(FlagReader& in, const std::string& flag, const std::string& text, const char* what) {
  if (text.empty()) in.add({flag, "(missing)", what});
}

// ---------------------------------------------------------------------------------------------
// catena ring capacity

struct CapacityFlags {
  std::string alpha, sum_sigma_r, k_max, fibre_strength, fibre_area, load;
  std::string E_r, E_phi, G, nu_phi_r, inner_radius, outer_radius, harmonics;
  std::string steel_mass, link_mass, format = "table", output;
};

int run_capacity(const CapacityFlags& f) {
  FlagReader in;
  const bool analysed = !(f.E_r.empty() && f.E_phi.empty() && f.G.empty() && f.nu_phi_r.empty() &&
                          f.inner_radius.empty() && f.outer_radius.empty());
  Eq9 e;
  Ring ring;
  Options options;
  if (analysed) {
    for (const auto& [flag, text] :
         {std::pair{"--alpha", &f.alpha}, std::pair{"--sum-sigma-r", &f.sum_sigma_r},
          std::pair{"--k-max", &f.k_max}})
      if (!text->empty())
        in.add({flag, *text,
                "not with the elastic constants (α, Σσ̃_r and K then come from the ring "
                "analysis)"});
    const char* need = "required with the ring's elastic constants";
    missing(in, "--E-r", f.E_r, need);
    missing(in, "--E-phi", f.E_phi, need);
    missing(in, "--G", f.G, need);
    missing(in, "--nu-phi-r", f.nu_phi_r, need);
    missing(in, "--inner-radius", f.inner_radius, need);
    missing(in, "--outer-radius", f.outer_radius, need);
    ring.E_r = in.quantity("--E-r", f.E_r, QuantityKind::kStress).value_or(NAN);
    ring.E_phi = in.quantity("--E-phi", f.E_phi, QuantityKind::kStress).value_or(NAN);
    ring.G = in.quantity("--G", f.G, QuantityKind::kStress).value_or(NAN);
    ring.nu_phi_r = number(in, "--nu-phi-r", f.nu_phi_r, "a ratio ≥ 0").value_or(NAN);
    ring.inner_radius =
        in.quantity("--inner-radius", f.inner_radius, QuantityKind::kLength).value_or(NAN);
    ring.outer_radius =
        in.quantity("--outer-radius", f.outer_radius, QuantityKind::kLength).value_or(NAN);
    ring.thickness = 1e-3;  // K and Σσ̃_r do not depend on t or the opening (linear problem)
    ring.gap = 1e-3 * ring.inner_radius;
    if (!f.harmonics.empty())
      options.harmonics = in.integer("--harmonics", f.harmonics, 2).value_or(0);
  } else {
    const char* need = "required (or give the ring's elastic constants and radii instead)";
    missing(in, "--alpha", f.alpha, need);
    missing(in, "--sum-sigma-r", f.sum_sigma_r, need);
    missing(in, "--k-max", f.k_max, need);
    e.alpha = number(in, "--alpha", f.alpha, "0 < α < 1").value_or(NAN);
    e.sum_sigma_r = number(in, "--sum-sigma-r", f.sum_sigma_r, "a number > 0").value_or(NAN);
    e.k_max = number(in, "--k-max", f.k_max, "a number ≥ 1").value_or(NAN);
  }
  missing(in, "--fibre-strength", f.fibre_strength, "σ^a, the reinforcement's strength");
  e.fibre_strength =
      in.quantity("--fibre-strength", f.fibre_strength, QuantityKind::kStress).value_or(NAN);
  if (f.fibre_area.empty() == f.load.empty())
    in.add({"--fibre-area", f.fibre_area.empty() ? "(missing)" : f.fibre_area,
            "exactly one of --fibre-area (gives P_max) and --load (gives the area)"});
  const auto fibre_area = area(in, "--fibre-area", f.fibre_area);
  const auto load = in.quantity("--load", f.load, QuantityKind::kForce);
  const auto steel_mass = in.quantity("--steel-mass", f.steel_mass, QuantityKind::kMass);
  const auto link_mass_given = in.quantity("--link-mass", f.link_mass, QuantityKind::kMass);
  if (steel_mass.has_value() != link_mass_given.has_value())
    in.add({steel_mass ? "--link-mass" : "--steel-mass", "(missing)",
            "--steel-mass and --link-mass go together (mass comparison)"});
  for (const auto& [flag, v] :
       {std::pair{"--steel-mass", steel_mass}, std::pair{"--link-mass", link_mass_given}})
    if (v && !(*v > 0)) in.add({flag, format_g(*v) + " kg", "a mass > 0 kg"});
  std::vector<Issue> model;
  if (analysed) {
    model = validate(ring);
    for (auto& i : validate(options)) model.push_back(i);
    std::vector<Issue> strength;
    check::finite_positive(strength, "fibre_strength", e.fibre_strength, "Pa");
    for (auto& i : strength) model.push_back(i);
  } else {
    model = validate(e);
  }
  if (fibre_area) check::finite_positive(model, "fibre_area", *fibre_area, "m^2");
  if (load) check::finite_positive(model, "load", *load, "N");
  add_parsed_model_issues(in, model);
  in.throw_if_any();

  double ring_sum = NAN;
  std::vector<Diagnostic> diags;
  ordered_json summary;
  if (analysed) {
    const Result res = analyse(ring, options);
    e.alpha = ring.inner_radius / ring.outer_radius;
    e.k_max = res.stress_concentration;
    e.sum_sigma_r = consistent_sum_sigma_r(e.alpha);
    ring_sum = res.sum_sigma_r;
    diags = res.diagnostics;
    summary = {{"method", res.summary.method},
               {"harmonics", res.summary.harmonics},
               {"truncation_change", res.summary.truncation_change}};
  }
  const double factor = eq9_factor(e);
  const double F = fibre_area ? *fibre_area : area_for_load(e, *load);
  const double P = capacity(e, F);
  const double p_concentration = capacity_from_concentration(F, e.fibre_strength, e.k_max);
  const double uniform = 2.0 * F * e.fibre_strength;
  const double consistent = consistent_sum_sigma_r(e.alpha);
  if (factor > 1.0)
    diags.push_back({Diagnostic::Severity::kWarning, "ring.capacity.eq9_above_uniform_strength",
                     "eq. (9) gives more than the uniform-stress strength 2Fσ^a: Σσ̃_r/(α(1−α)K) "
                     "> 1 (value: that factor); check the normalisation of Σσ̃_r (with the mean "
                     "stress of catena ring it is (1−α)/α and does not belong in eq. (9))",
                     factor, 1.0});
  else if (factor * e.k_max > 1.0 + 1e-9)
    diags.push_back({Diagnostic::Severity::kInfo, "ring.capacity.eq9_above_concentration_capacity",
                     "eq. (9) exceeds the capacity from the stress concentration, 2Fσ^a/K, by the "
                     "factor Σσ̃_r/(α(1−α)); they agree when Σσ̃_r = α(1−α) (value: Σσ̃_r, limit: "
                     "α(1−α))",
                     e.sum_sigma_r, consistent});

  std::string text;
  if (f.format == "json") {
    ordered_json j;
    j["model"] = "composite.ring_capacity";
    j["source"] = kSource;
    j["mode"] = analysed ? "analysed" : "coefficients";
    j["alpha"] = e.alpha;
    j["sum_sigma_r"] = e.sum_sigma_r;
    j["k_max"] = e.k_max;
    j["fibre_strength"] = e.fibre_strength;
    j["fibre_area"] = F;
    j["load"] = P;
    j["eq9_factor"] = factor;
    j["load_concentration"] = p_concentration;
    j["load_uniform"] = uniform;
    j["consistent_sum_sigma_r"] = consistent;
    if (analysed) {
      j["ring_sum_sigma_r"] = ring_sum;
      j["summary"] = summary;
    }
    if (steel_mass) {
      j["mass"] = {{"link", *link_mass_given},
                   {"steel", *steel_mass},
                   {"ratio", *steel_mass / *link_mass_given}};
    }
    j["units"] = {{"alpha", "1"},
                  {"sum_sigma_r", "1"},
                  {"k_max", "1"},
                  {"fibre_strength", "Pa"},
                  {"fibre_area", "m^2"},
                  {"load", "N"},
                  {"eq9_factor", "1"},
                  {"load_concentration", "N"},
                  {"load_uniform", "N"},
                  {"consistent_sum_sigma_r", "1"},
                  {"ring_sum_sigma_r", "1"},
                  {"mass", "kg"}};
    j["diagnostics"] = diagnostics_json(diags);
    text = j.dump(2) + "\n";
  } else {
    std::ostringstream t;
    t << "Catena ring capacity: eq. (9) of seed 002, P = Σσ̃_r/(α(1−α)K)·2Fσ^a\n\n";
    t << "  alpha = r1/r2            " << format_g(e.alpha, 5) << "\n";
    t << "  sum sigma_r              " << format_g(e.sum_sigma_r, 5)
      << (analysed ? "  (α(1−α): the normalisation that makes (9) = 2Fσ^a/K)" : "") << "\n";
    if (analysed) t << "  ring's own sum sigma_r   " << format_g(ring_sum, 5) << "  ((1−α)/α)\n";
    t << "  K max                    " << format_g(e.k_max, 5) << "\n";
    t << "  fibre strength [MPa]     " << format_g(e.fibre_strength / 1e6, 6) << "\n";
    t << "  fibre area F [mm^2]      " << format_g(F * 1e6, 5) << (fibre_area ? "" : "  (sized)")
      << "\n";
    t << "  P max, eq. (9) [N]       " << format_g(P, 6) << "\n";
    t << "  2Fσ^a/K [N]              " << format_g(p_concentration, 6) << "\n";
    t << "  2Fσ^a [N]                " << format_g(uniform, 6) << "\n";
    if (steel_mass)
      t << "  mass: link " << format_g(*link_mass_given, 4) << " kg, steel "
        << format_g(*steel_mass, 4) << " kg, steel/link "
        << format_g(*steel_mass / *link_mass_given, 4) << "\n";
    for (const auto& d : diags) t << "\n  " << to_string(d.severity) << ": " << d.message << "\n";
    text = t.str();
  }
  write_text_output(f.output, text);
  return 0;
}

// ---------------------------------------------------------------------------------------------
// catena ring design

struct DesignFlags {
  std::string load, fibre_modulus, fibre_poisson, fibre_strength, fibre_density;
  std::string matrix_modulus, matrix_poisson, matrix_density, fibre_fraction;
  std::string thickness, pitch, insert_density = "1130", alpha;
  std::string steel_strength, steel_thickness, steel_density = "7850", harmonics;
  std::string format = "table", output;
};

int run_design(const DesignFlags& f) {
  FlagReader in;
  DesignInput d;
  const char* need = "required";
  missing(in, "--load", f.load, "the required breaking force");
  missing(in, "--fibre-modulus", f.fibre_modulus, need);
  missing(in, "--fibre-poisson", f.fibre_poisson, need);
  missing(in, "--fibre-strength", f.fibre_strength, need);
  missing(in, "--fibre-density", f.fibre_density, need);
  missing(in, "--matrix-modulus", f.matrix_modulus, need);
  missing(in, "--matrix-poisson", f.matrix_poisson, need);
  missing(in, "--matrix-density", f.matrix_density, need);
  missing(in, "--fibre-fraction", f.fibre_fraction, need);
  missing(in, "--thickness", f.thickness, "t, the band width (r2 follows from it)");
  missing(in, "--pitch", f.pitch, "p, the pin centre distance");
  d.load = in.quantity("--load", f.load, QuantityKind::kForce).value_or(NAN);
  d.fibre.modulus =
      in.quantity("--fibre-modulus", f.fibre_modulus, QuantityKind::kStress).value_or(NAN);
  d.fibre.poisson = number(in, "--fibre-poisson", f.fibre_poisson, "0 ≤ ν < 0.5").value_or(NAN);
  d.fibre.strength =
      in.quantity("--fibre-strength", f.fibre_strength, QuantityKind::kStress).value_or(NAN);
  d.fibre.density = density(in, "--fibre-density", f.fibre_density).value_or(NAN);
  d.matrix.modulus =
      in.quantity("--matrix-modulus", f.matrix_modulus, QuantityKind::kStress).value_or(NAN);
  d.matrix.poisson = number(in, "--matrix-poisson", f.matrix_poisson, "0 ≤ ν < 0.5").value_or(NAN);
  d.matrix.density = density(in, "--matrix-density", f.matrix_density).value_or(NAN);
  d.fibre_fraction =
      number(in, "--fibre-fraction", f.fibre_fraction, "0 < V_f ≤ 0.9069").value_or(NAN);
  d.thickness = in.quantity("--thickness", f.thickness, QuantityKind::kLength).value_or(NAN);
  d.pitch = in.quantity("--pitch", f.pitch, QuantityKind::kLength).value_or(NAN);
  d.insert_density = density(in, "--insert-density", f.insert_density).value_or(NAN);
  if (!f.alpha.empty())
    for (const auto& p : split_commas(f.alpha))
      d.alphas.push_back(
          number(in, "--alpha", p, "0.05 ≤ α ≤ 0.95, or a comma list").value_or(NAN));
  if (!f.steel_strength.empty() || !f.steel_thickness.empty()) {
    missing(in, "--steel-strength", f.steel_strength, "with --steel-thickness");
    missing(in, "--steel-thickness", f.steel_thickness, "with --steel-strength");
    d.steel_strength =
        in.quantity("--steel-strength", f.steel_strength, QuantityKind::kStress).value_or(NAN);
    d.steel_thickness =
        in.quantity("--steel-thickness", f.steel_thickness, QuantityKind::kLength).value_or(NAN);
    d.steel_density = density(in, "--steel-density", f.steel_density).value_or(NAN);
  }
  if (!f.harmonics.empty())
    d.analysis.harmonics = in.integer("--harmonics", f.harmonics, 2).value_or(0);
  add_parsed_model_issues(in, validate(d));
  in.throw_if_any();

  const Design out = design(d);
  const Lamina& l = out.lamina;
  const DesignPoint& b = out.scan[out.best];
  std::string text;
  if (f.format == "json") {
    ordered_json j;
    j["model"] = "composite.ring_design";
    j["source"] = kSource;
    j["load"] = d.load;
    j["lamina"] = {{"fibre_fraction", l.fibre_fraction},
                   {"E_phi", l.E_phi},
                   {"E_r", l.E_r},
                   {"G", l.G},
                   {"nu_phi_r", l.nu_phi_r},
                   {"strength", l.strength},
                   {"density", l.density}};
    auto point = [&](const DesignPoint& p) {
      return ordered_json{
          {"alpha", p.alpha},
          {"k", p.k},
          {"sum_sigma_r", p.sum_sigma_r},
          {"inner_radius", p.inner_radius},
          {"outer_radius", p.outer_radius},
          {"thickness", d.thickness},
          {"leg_area", p.leg_area},
          {"fibre_area", p.fibre_area},
          {"mass", {{"band", p.mass.band}, {"insert", p.mass.insert}, {"total", p.mass.total}}},
          {"feasible", p.feasible}};
    };
    j["design"] = point(b);
    ordered_json scan = ordered_json::array();
    for (const auto& p : out.scan) scan.push_back(point(p));
    j["scan"] = scan;
    if (out.has_steel)
      j["steel"] = {{"net_area", out.steel.net_area}, {"width", out.steel.width},
                    {"thickness", d.steel_thickness}, {"face_area", out.steel.face_area},
                    {"mass", out.steel.mass},         {"mass_ratio", out.mass_ratio}};
    j["units"] = {
        {"load", "N"},      {"E_phi", "Pa"},       {"E_r", "Pa"},         {"G", "Pa"},
        {"strength", "Pa"}, {"density", "kg/m^3"}, {"inner_radius", "m"}, {"outer_radius", "m"},
        {"thickness", "m"}, {"leg_area", "m^2"},   {"fibre_area", "m^2"}, {"net_area", "m^2"},
        {"width", "m"},     {"face_area", "m^2"},  {"mass", "kg"},        {"alpha", "1"},
        {"k", "1"},         {"sum_sigma_r", "1"},  {"mass_ratio", "1"},   {"fibre_fraction", "1"},
        {"nu_phi_r", "1"}};
    j["diagnostics"] = diagnostics_json(out.diagnostics);
    text = j.dump(2) + "\n";
  } else {
    std::ostringstream t;
    t << "Catena ring design: fibre-wound link for P = " << format_g(d.load, 6) << " N\n\n";
    t << "  ring constants (V_f " << format_g(l.fibre_fraction, 3) << "): E_phi "
      << format_g(l.E_phi / 1e9, 4) << " GPa, E_r " << format_g(l.E_r / 1e9, 4) << " GPa, G "
      << format_g(l.G / 1e9, 4) << " GPa, nu_phi_r " << format_g(l.nu_phi_r, 3)
      << ", hoop strength " << format_g(l.strength / 1e6, 5) << " MPa, density "
      << format_g(l.density, 5) << " kg/m^3\n\n";
    t << "   alpha      K   r1 [mm]   r2 [mm]  A leg [mm^2]  F fibre [mm^2]  mass [g]\n";
    for (std::size_t i = 0; i < out.scan.size(); ++i) {
      const auto& p = out.scan[i];
      char line[200];
      std::snprintf(line, sizeof line, "  %6.3f %6.3f %9.4g %9.4g %13.4g %15.4g %9.4g%s\n", p.alpha,
                    p.k, p.inner_radius * 1e3, p.outer_radius * 1e3, p.leg_area * 1e6,
                    p.fibre_area * 1e6, p.mass.total * 1e3,
                    !p.feasible     ? "  pins overlap (p <= 2 r1)"
                    : i == out.best ? "  <- lightest"
                                    : "");
      t << line;
    }
    if (out.has_steel)
      t << "\n  steel plate: width " << format_g(out.steel.width * 1e3, 4) << " mm, thickness "
        << format_g(d.steel_thickness * 1e3, 4) << " mm, mass " << format_g(out.steel.mass * 1e3, 4)
        << " g; steel/composite " << format_g(out.mass_ratio, 4) << "\n";
    for (const auto& dg : out.diagnostics)
      t << "\n  " << to_string(dg.severity) << ": " << dg.message << "\n";
    text = t.str();
  }
  write_text_output(f.output, text);
  return 0;
}

}  // namespace

std::function<int()> add_ring_capacity(CLI::App& ring) {
  auto f = std::make_shared<CapacityFlags>();
  CLI::App* c = ring.add_subcommand(
      "capacity", "Link capacity by eq. (9) of seed 002, and the mass comparison");
  c->add_option("--alpha", f->alpha, "alpha = r1/r2 of eq. (9)");
  c->add_option("--sum-sigma-r", f->sum_sigma_r, "Σσ̃_r of eq. (9) (the paper's normalisation)");
  c->add_option("--k-max", f->k_max, "K_σ^max of eq. (9)");
  c->add_option("--fibre-strength", f->fibre_strength, "σ^a, reinforcement strength (bare: MPa)");
  c->add_option("--fibre-area", f->fibre_area, "F, reinforcement area (bare: mm^2); or --load");
  c->add_option("--load", f->load, "P to size F for (bare: N); or --fibre-area");
  c->add_option("--E-r", f->E_r, "instead of --alpha/--sum-sigma-r/--k-max: radial modulus");
  c->add_option("--E-phi", f->E_phi, "hoop (fibre) modulus");
  c->add_option("--G", f->G, "shear modulus G_rφ");
  c->add_option("--nu-phi-r", f->nu_phi_r, "−ε_r/ε_φ under hoop stress");
  c->add_option("--inner-radius", f->inner_radius, "r1 (bare: mm)");
  c->add_option("--outer-radius", f->outer_radius, "r2 (bare: mm)");
  c->add_option("--harmonics", f->harmonics, "ring solver harmonics (default: converged)");
  c->add_option("--steel-mass", f->steel_mass, "steel link mass for the comparison (bare: kg)");
  c->add_option("--link-mass", f->link_mass, "composite link mass for the comparison (bare: kg)");
  c->add_option("--format", f->format, "table|json")->check(CLI::IsMember({"table", "json"}));
  c->add_option("--output", f->output, "write the output to FILE");
  return [f]() { return run_capacity(*f); };
}

std::function<int()> add_ring_design(CLI::App& ring) {
  auto f = std::make_shared<DesignFlags>();
  CLI::App* c = ring.add_subcommand(
      "design", "Size a fibre-wound link (r1, r2, mass) for a breaking force; steel comparison");
  c->add_option("--load", f->load, "required breaking force P (bare: N)");
  c->add_option("--fibre-modulus", f->fibre_modulus, "E_f (bare: MPa), e.g. 72.4GPa");
  c->add_option("--fibre-poisson", f->fibre_poisson, "ν_f");
  c->add_option("--fibre-strength", f->fibre_strength, "σ_f (bare: MPa)");
  c->add_option("--fibre-density", f->fibre_density, "ρ_f (bare: kg/m^3), e.g. 2.56g/cm^3");
  c->add_option("--matrix-modulus", f->matrix_modulus, "E_m (bare: MPa)");
  c->add_option("--matrix-poisson", f->matrix_poisson, "ν_m");
  c->add_option("--matrix-density", f->matrix_density, "ρ_m (bare: kg/m^3)");
  c->add_option("--fibre-fraction", f->fibre_fraction, "V_f");
  c->add_option("--thickness", f->thickness, "t, band width (bare: mm); r2 follows");
  c->add_option("--pitch", f->pitch, "p, pin centre distance (bare: mm)");
  c->add_option("--insert-density", f->insert_density, "polyamide insert (default 1130 kg/m^3)");
  c->add_option("--alpha", f->alpha, "r1/r2, one or a comma list (default 0.30..0.90 by 0.05)");
  c->add_option("--steel-strength", f->steel_strength, "steel plate σ_B for the comparison");
  c->add_option("--steel-thickness", f->steel_thickness, "steel plate thickness (bare: mm)");
  c->add_option("--steel-density", f->steel_density, "default 7850 kg/m^3");
  c->add_option("--harmonics", f->harmonics, "ring solver harmonics (default: converged)");
  c->add_option("--format", f->format, "table|json")->check(CLI::IsMember({"table", "json"}));
  c->add_option("--output", f->output, "write the output to FILE");
  return [f]() { return run_design(*f); };
}

}  // namespace catena::cli
