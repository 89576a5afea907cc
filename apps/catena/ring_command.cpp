// catena ring: the fibre-reinforced polymer link as an orthotropic ring stretched by two rigid
// smooth half-discs (seed 002). Stresses on the φ = 0 and φ = π/2 sections, the contact
// pressure, the load P the link carries for the imposed opening 2δ.
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>

#include "catena/composite/ring.hpp"
#include "cli_support.hpp"
#include "commands.hpp"

namespace catena::cli {
namespace {

using io::QuantityKind;
using nlohmann::ordered_json;
using namespace catena::composite;

struct RingFlags {
  std::string inner_radius, outer_radius, thickness, E_r, E_phi, G, nu_phi_r, gap;
  std::string harmonics, nodes, points = "41", method = "exact";
  bool unilateral = false, field = false;
  std::string format = "table", output;
};

ordered_json section(const Result& r, const std::vector<double>& sr, const std::vector<double>& sp,
                     const std::vector<double>& tau) {
  return {{"r", r.r}, {"sigma_r", sr}, {"sigma_phi", sp}, {"tau", tau}};
}

int run_ring(const RingFlags& f) {
  FlagReader in;
  Ring ring;
  ring.inner_radius = in.required_quantity("--inner-radius", f.inner_radius, QuantityKind::kLength,
                                           "r1, the pin's (half-discs') radius");
  ring.outer_radius = in.required_quantity("--outer-radius", f.outer_radius, QuantityKind::kLength,
                                           "r2 > r1, the ring's outer radius");
  ring.thickness = in.required_quantity("--thickness", f.thickness, QuantityKind::kLength,
                                        "t, the ring's thickness (plane stress)");
  ring.E_r = in.required_quantity("--E-r", f.E_r, QuantityKind::kStress, "radial Young's modulus");
  ring.E_phi = in.required_quantity("--E-phi", f.E_phi, QuantityKind::kStress,
                                    "hoop (fibre) Young's modulus");
  ring.G = in.required_quantity("--G", f.G, QuantityKind::kStress, "in-plane shear modulus G_rphi");
  ring.nu_phi_r = in.required_number(
      "--nu-phi-r", f.nu_phi_r, "nu_phi_r = -eps_r/eps_phi under pure hoop stress, a plain number");
  ring.gap = in.required_quantity("--gap", f.gap, QuantityKind::kLength,
                                  "the full opening 2*delta between the half-discs");
  Options o;
  o.method = f.method == "sweep" ? Method::kSweep : Method::kExact;
  o.unilateral = f.unilateral;
  if (!f.harmonics.empty()) o.harmonics = in.integer("--harmonics", f.harmonics, 0).value_or(-1);
  if (!f.nodes.empty()) o.nodes = in.integer("--nodes", f.nodes, 0).value_or(-1);
  o.points = in.integer("--points", f.points, 0).value_or(-1);
  if (!f.nodes.empty() && o.method != Method::kSweep)
    in.add({"--nodes", f.nodes, "only with --method sweep (the exact solver has no grid)"});
  // the model's checks too, so that every problem is reported at once; a field that could not be
  // read (NaN) has been reported already
  const std::map<std::string, double> read = {{"inner_radius", ring.inner_radius},
                                              {"outer_radius", ring.outer_radius},
                                              {"thickness", ring.thickness},
                                              {"E_r", ring.E_r},
                                              {"E_phi", ring.E_phi},
                                              {"G", ring.G},
                                              {"nu_phi_r", ring.nu_phi_r},
                                              {"gap", ring.gap}};
  std::vector<Issue> issues;
  for (Issue& is : validate(ring)) {
    const auto it = read.find(is.field);
    if (it != read.end() && std::isnan(it->second)) continue;
    issues.push_back(is);
  }
  for (Issue& is : validate(o))
    if (!(is.field == "harmonics" && o.harmonics < 0) && !(is.field == "nodes" && o.nodes < 0) &&
        !(is.field == "points" && o.points < 0))
      issues.push_back(is);
  for (Issue& is : issues) {  // model field names → the flags'
    if (is.field == "E_r") is.field = "E-r";
    if (is.field == "E_phi") is.field = "E-phi";
  }
  in.add_model_issues(issues);
  in.throw_if_any();

  const Result r = analyse(ring, o);
  constexpr double kDeg = 180.0 / std::numbers::pi;
  std::string text;
  if (f.format == "json") {
    ordered_json j;
    j["model"] = "composite.orthotropic_ring";
    j["source"] =
        "002 eqs. (1)-(8): cylindrically orthotropic ring, plane stress, stretched by two rigid "
        "smooth half-discs; inner condition U_r = Delta*|cos phi|, tau = 0 (the paper's G0 = 2/pi "
        "reading), outer edge free; even-harmonic Fourier series";
    j["load"] = r.load;
    j["mean_stress"] = r.mean_stress;
    j["sections"]["0"] = section(r, r.sigma_r_0, r.sigma_phi_0, r.tau_0);
    j["sections"]["90"] = section(r, r.sigma_r_90, r.sigma_phi_90, r.tau_90);
    j["contact"] = {{"phi", r.contact_phi},
                    {"pressure", r.contact_pressure},
                    {"angle", r.contact_angle},
                    {"unilateral", o.unilateral},
                    {"iterations", r.contact_iterations}};
    j["stress_concentration"] = r.stress_concentration;
    j["corner"] = {{"r", ring.inner_radius},
                   {"phi", 0.5 * std::numbers::pi},
                   {"sigma_phi", r.corner_sigma_phi},
                   {"harmonics", r.summary.harmonics},
                   {"note", "singular where the half-discs meet: grows with the harmonic count"}};
    if (f.field)
      j["field"] = {{"r", r.r},
                    {"phi", r.contact_phi},
                    {"sigma_r", r.field_sigma_r},
                    {"sigma_phi", r.field_sigma_phi},
                    {"tau", r.field_tau},
                    {"layout", "[phi index][r index]"}};
    j["max_shear"] = {{"tau", r.max_shear}, {"r", r.max_shear_r}, {"phi", r.max_shear_phi}};
    j["sum_sigma_r"] = r.sum_sigma_r;
    j["load_contact"] = r.load_contact;
    j["summary"] = {{"method", r.summary.method},
                    {"harmonics", r.summary.harmonics},
                    {"nodes", r.summary.nodes},
                    {"fallbacks", r.summary.fallbacks},
                    {"truncation_change", r.summary.truncation_change},
                    {"richardson_error", r.summary.richardson_error},
                    {"equilibrium_residual",
                     std::abs(r.load - r.load_contact) / std::max(std::abs(r.load), 1e-300)}};
    j["diagnostics"] = diagnostics_json(r.diagnostics);
    j["units"] = {{"load", "N"},
                  {"mean_stress", "Pa"},
                  {"r", "m"},
                  {"sigma_r", "Pa"},
                  {"sigma_phi", "Pa"},
                  {"tau", "Pa"},
                  {"phi", "rad"},
                  {"pressure", "Pa"},
                  {"angle", "rad"},
                  {"stress_concentration", "1"},
                  {"sum_sigma_r", "1"},
                  {"load_contact", "N"},
                  {"truncation_change", "1"},
                  {"richardson_error", "1"}};
    text = j.dump(2) + "\n";
  } else if (f.format == "csv") {
    std::ostringstream csv;
    csv << "r,sigma_r_0,sigma_phi_0,tau_0,sigma_r_90,sigma_phi_90,tau_90\n";
    char line[256];
    for (std::size_t i = 0; i < r.r.size(); ++i) {
      std::snprintf(line, sizeof line, "%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g\n", r.r[i],
                    r.sigma_r_0[i], r.sigma_phi_0[i], r.tau_0[i], r.sigma_r_90[i],
                    r.sigma_phi_90[i], r.tau_90[i]);
      csv << line;
    }
    text = csv.str();
  } else {
    std::ostringstream t;
    char line[1024];
    t << "Catena ring: orthotropic link on two rigid half-discs (seed 002; " << r.summary.method
      << " solver, " << r.summary.harmonics << " harmonics"
      << (r.summary.nodes > 0 ? ", " + std::to_string(r.summary.nodes) + " intervals" : "")
      << (o.unilateral ? ", unilateral contact" : ", bilateral contact") << ")\n\n";
    std::snprintf(line, sizeof line,
                  "  load P              %10.5g kN   (from the contact: %.5g kN)\n"
                  "  mean stress         %10.5g MPa  (P / 2(r2 - r1)t)\n"
                  "  stress conc. K      %10.5g      (max sigma_phi at 90 deg, r >= r1 + 5%%)\n"
                  "  corner sigma_phi    %10.5g MPa  (r1, 90 deg; grows with harmonics)\n"
                  "  max |tau|           %10.5g MPa  at r = %.4g mm, phi = %.3g deg\n"
                  "  sum sigma~_r        %10.5g      (eq. 9)\n"
                  "  contact angle       %10.5g deg\n"
                  "  truncation change   %10.3g      (N/2 -> N)\n",
                  r.load / 1e3, r.load_contact / 1e3, r.mean_stress / 1e6, r.stress_concentration,
                  r.corner_sigma_phi / 1e6, std::abs(r.max_shear) / 1e6, r.max_shear_r * 1e3,
                  r.max_shear_phi * kDeg, r.sum_sigma_r, r.contact_angle * kDeg,
                  r.summary.truncation_change);
    t << line;
    if (r.summary.nodes > 0) {
      std::snprintf(line, sizeof line, "  Richardson error    %10.3g      (of mean stress)\n",
                    r.summary.richardson_error);
      t << line;
    }
    t << "\n   r [mm]   sigma_r(0) sigma_phi(0)  sigma_r(90) sigma_phi(90)   [MPa]\n";
    for (std::size_t i = 0; i < r.r.size(); ++i) {
      std::snprintf(line, sizeof line, "  %7.4f %12.5g %12.5g %12.5g %12.5g\n", r.r[i] * 1e3,
                    r.sigma_r_0[i] / 1e6, r.sigma_phi_0[i] / 1e6, r.sigma_r_90[i] / 1e6,
                    r.sigma_phi_90[i] / 1e6);
      t << line;
    }
    for (const auto& d : r.diagnostics)
      t << "\n  " << to_string(d.severity) << " " << d.code << ": " << d.message;
    t << "\n";
    text = t.str();
  }
  write_text_output(f.output, text);
  return 0;
}

}  // namespace

std::function<int()> add_ring(CLI::App& app) {
  auto f = std::make_shared<RingFlags>();
  CLI::App* c = app.add_subcommand(
      "ring", "Fibre-reinforced polymer link: orthotropic ring on two rigid half-discs (seed 002)");
  c->add_option("--inner-radius", f->inner_radius, "r1 (bare: mm)");
  c->add_option("--outer-radius", f->outer_radius, "r2 (bare: mm)");
  c->add_option("--thickness", f->thickness, "t (bare: mm)");
  c->add_option("--E-r", f->E_r, "radial modulus E_r (bare: MPa)");
  c->add_option("--E-phi", f->E_phi, "hoop (fibre) modulus E_phi (bare: MPa)");
  c->add_option("--G", f->G, "shear modulus G_rphi (bare: MPa)");
  c->add_option("--nu-phi-r", f->nu_phi_r, "-eps_r/eps_phi under pure hoop stress");
  c->add_option("--gap", f->gap, "the full opening 2*delta (bare: mm)");
  c->add_option("--harmonics", f->harmonics,
                "highest even harmonic N (default 2*ceil(100/(1 - r1/r2)), at least 40)");
  c->add_option("--nodes", f->nodes, "sweep intervals m (default: h*N/alpha <= 0.1)");
  c->add_option("--points", f->points, "output radii from r1 to r2, odd (default 41)");
  c->add_option("--method", f->method, "exact (default, powers r^lambda) or sweep (the paper's)")
      ->check(CLI::IsMember({"exact", "sweep"}));
  c->add_flag("--unilateral", f->unilateral,
              "let the ring separate where the half-disc would pull on it");
  c->add_flag("--field", f->field,
              "JSON: add the stresses over the quarter ring (91 angles x the output radii)");
  c->add_option("--format", f->format, "table|json|csv")
      ->check(CLI::IsMember({"table", "json", "csv"}));
  c->add_option("--output", f->output, "write the output to FILE");
  // `catena ring capacity` (eq. 9, the mass comparison) and `catena ring design` (sizing):
  // ring_capacity_command.cpp; the ring's own flags stay optional at parse time for them
  auto cap = add_ring_capacity(*c);
  auto des = add_ring_design(*c);
  CLI::App* cap_app = c->get_subcommand("capacity");
  CLI::App* des_app = c->get_subcommand("design");
  return [f, cap, des, cap_app, des_app]() {
    if (cap_app->parsed()) return cap();
    if (des_app->parsed()) return des();
    return run_ring(*f);
  };
}

}  // namespace catena::cli
