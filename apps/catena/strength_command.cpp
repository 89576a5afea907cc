// catena strength: safety factors of the roller and plates of a conveyor chain hinge (seed 000
// §1.5): load layouts 1 and 2, the roller's M and Q diagrams, eqs. (22)-(23), Hertz for the
// rolling hinge, the plate's dangerous sections (fig. 21).
#include <CLI/CLI.hpp>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>

#include "catena/strength/strength.hpp"
#include "cli_support.hpp"
#include "commands.hpp"

namespace catena::cli {
namespace {

using io::QuantityKind;
using nlohmann::ordered_json;
using namespace catena::strength;

constexpr const char* kPlateKey[4] = {"lower_outer", "lower_inner", "upper_inner", "upper_outer"};

struct StrengthFlags {
  std::string tension, tooth_force, exit_tension, link_angle = "0", load_height, tooth_width = "0",
                                                  layout = "both";
  std::string hinge = "sliding", heights, widths, diameter, bore = "0", hole, plate_width,
              end_distance, stress_concentration = "1", contact_angle = "180deg", r1, r2,
              modulus = "210GPa", poisson = "0.3";
  std::string roller_yield, plate_yield, plate_ultimate, allowable_pressure, allowable_contact,
      safety_factor = "1.5";
  std::string format = "table", output;
};

// Four plate values bottom to top (lower outer, lower inner, upper inner, upper outer); one value
// is repeated to all four.
std::array<double, 4> four(FlagReader& in, const std::string& flag, const std::string& text) {
  std::array<double, 4> out{NAN, NAN, NAN, NAN};
  const char* what =
      "1 or 4 comma-separated lengths, bottom to top: lower outer, lower inner, "
      "upper inner, upper outer plate";
  if (text.empty()) {
    in.add({flag, "(missing)", what});
    return out;
  }
  std::vector<double> v;
  for (const auto& p : split_commas(text))
    v.push_back(in.quantity(flag, p, QuantityKind::kLength).value_or(NAN));
  if (v.size() == 1) v.assign(4, v[0]);
  if (v.size() != 4) {
    in.add({flag, text, what});
    return out;
  }
  for (std::size_t i = 0; i < 4; ++i) out[i] = v[i];
  return out;
}

ordered_json number_or_null(double v) {
  return std::isfinite(v) ? ordered_json(v) : ordered_json();
}

int run_strength(const StrengthFlags& f) {
  FlagReader in;
  Input x;
  Hinge& h = x.hinge;
  h.heights = four(in, "--heights", f.heights);
  h.widths = four(in, "--widths", f.widths);
  h.pin_diameter = in.required_quantity("--pin-diameter", f.diameter, QuantityKind::kLength,
                                        "d of the roller (pin)");
  h.bore = in.quantity("--bore", f.bore, QuantityKind::kLength).value_or(NAN);
  h.hole_diameter =
      f.hole.empty() ? 0.0
                     : in.quantity("--hole-diameter", f.hole, QuantityKind::kLength).value_or(NAN);
  h.plate_width = in.required_quantity("--plate-width", f.plate_width, QuantityKind::kLength,
                                       "b, the plate's depth across the chain line");
  h.end_distance = in.required_quantity("--end-distance", f.end_distance, QuantityKind::kLength,
                                        "e, from the hole centre to the plate's end");
  h.stress_concentration = in.required_number("--stress-concentration", f.stress_concentration,
                                              "K_t ≥ 1, a plain number");
  h.kind = f.hinge == "rolling" ? HingeKind::kRolling : HingeKind::kSliding;
  if (h.kind == HingeKind::kSliding) {
    h.contact_angle =
        in.quantity("--contact-angle", f.contact_angle, QuantityKind::kAngle).value_or(NAN);
  } else {
    h.r1 = in.required_quantity("--plate-radius", f.r1, QuantityKind::kLength,
                                "R1 for a rolling hinge");
    h.r2 = in.required_quantity("--roller-radius", f.r2, QuantityKind::kLength,
                                "R2 for a rolling hinge");
  }
  h.modulus = in.quantity("--modulus", f.modulus, QuantityKind::kStress).value_or(NAN);
  h.poisson = in.required_number("--poisson", f.poisson, "0 ≤ ν < 0.5, a plain number");

  Loads& l = x.loads;
  l.tension = in.required_quantity("--tension", f.tension, QuantityKind::kForce,
                                   "S, the free link's tension");
  l.link_angle = in.quantity("--link-angle", f.link_angle, QuantityKind::kAngle).value_or(NAN);
  if (!f.tooth_force.empty() && !f.exit_tension.empty()) {
    in.add({"--tooth-force", f.tooth_force, "either --tooth-force or --exit-tension, not both"});
  } else if (!f.tooth_force.empty()) {
    // collinear links: N = S − S2
    if (l.link_angle != 0.0)
      in.add({"--tooth-force", f.tooth_force,
              "collinear links only (--link-angle 0); with a link angle give --exit-tension"});
    const double n =
        in.quantity("--tooth-force", f.tooth_force, QuantityKind::kForce).value_or(NAN);
    if (std::isfinite(n) && std::isfinite(l.tension) && !(n >= 0.0 && n <= l.tension))
      in.add(
          {"--tooth-force", f.tooth_force,
           "0 ≤ N ≤ S = " + format_g(l.tension) + " N (collinear: the seated link cannot push)"});
    l.exit_tension = l.tension - n;
  } else {
    l.exit_tension =
        f.exit_tension.empty()
            ? 0.0
            : in.quantity("--exit-tension", f.exit_tension, QuantityKind::kForce).value_or(NAN);
  }
  l.tooth_width = in.quantity("--tooth-width", f.tooth_width, QuantityKind::kLength).value_or(NAN);
  // default L1: midway between the inner plates' mid-planes
  l.load_height =
      f.load_height.empty()
          ? 0.5 * (h.heights[1] + h.heights[2])
          : in.quantity("--load-height", f.load_height, QuantityKind::kLength).value_or(NAN);

  Material& m = x.material;
  m.roller_yield = in.required_quantity("--roller-yield", f.roller_yield, QuantityKind::kStress,
                                        "σ_y of the roller");
  m.plate_yield = in.required_quantity("--plate-yield", f.plate_yield, QuantityKind::kStress,
                                       "σ_y of the plates");
  m.plate_ultimate =
      f.plate_ultimate.empty()
          ? 0.0
          : in.quantity("--plate-ultimate", f.plate_ultimate, QuantityKind::kStress).value_or(NAN);
  if (h.kind == HingeKind::kSliding)
    m.allowable_pressure =
        in.required_quantity("--allowable-pressure", f.allowable_pressure, QuantityKind::kStress,
                             "[p], the allowable specific pressure of a sliding hinge");
  else
    m.allowable_contact =
        in.required_quantity("--allowable-contact", f.allowable_contact, QuantityKind::kStress,
                             "[σ_H], the allowable Hertz stress of a rolling hinge");
  m.required =
      in.required_number("--safety-factor", f.safety_factor, "the required safety factor > 0");
  x.layouts = f.layout == "1" ? Layouts::kOne : f.layout == "2" ? Layouts::kTwo : Layouts::kBoth;
  // every problem at once: the model's checks too, except for the values the flags above
  // already reported (those were read as NaN)
  std::vector<Issue> model;
  for (Issue& is : validate(x))
    if (is.value.find("nan") == std::string::npos) model.push_back(std::move(is));
  in.add_model_issues(model);
  in.throw_if_any();

  const Result r = assess(x);
  const bool rolling = h.kind == HingeKind::kRolling;
  ordered_json checks = ordered_json::array();
  double worst = INFINITY;
  for (const Check& c : r.checks) {
    checks.push_back({{"name", c.name},
                      {"section", c.section},
                      {"stress", c.stress},
                      {"allowable", c.allowable},
                      {"required", c.required},
                      {"safety_factor", number_or_null(c.safety_factor)},
                      {"ok", c.ok}});
    worst = std::min(worst, c.safety_factor / c.required);
  }
  const ordered_json diags = diagnostics_json(r.diagnostics);
  ordered_json layouts = ordered_json::object(), diagrams = ordered_json::object();
  std::ostringstream csv;
  csv << "layout,x,M,Q\n";
  for (const LayoutResult& lr : r.layouts) {
    const std::string key = "layout_" + std::to_string(lr.loads.layout);
    ordered_json lj;
    for (std::size_t i = 0; i < 4; ++i) lj["plate_force"][kPlateKey[i]] = lr.loads.plate_force[i];
    lj["tooth_force"] = std::hypot(lr.loads.tooth.force, lr.loads.tooth_y);
    if (lr.planar) {
      for (std::size_t i = 0; i < 4; ++i)
        lj["plate_force_y"][kPlateKey[i]] = lr.loads.plate_force_y[i];
      lj["tooth_force_direction"] = std::atan2(lr.loads.tooth_y, lr.loads.tooth.force);
    }
    lj["moment_max"] = lr.extremes.moment;
    lj["moment_at"] = lr.extremes.moment_at;
    lj["shear_max"] = lr.extremes.shear;
    lj["shear_at"] = lr.extremes.shear_at;
    lj["force_residual"] = lr.force_residual;
    lj["moment_residual"] = lr.moment_residual;
    layouts[key] = lj;
    diagrams[key] = {{"x", lr.diagram.x}, {"M", lr.diagram.moment}, {"Q", lr.diagram.shear}};
    if (lr.planar) {
      std::vector<double> mr, qr;
      for (std::size_t i = 0; i < lr.diagram.x.size(); ++i) {
        mr.push_back(std::hypot(lr.diagram.moment[i], lr.diagram.moment_y[i]));
        qr.push_back(std::hypot(lr.diagram.shear[i], lr.diagram.shear_y[i]));
      }
      diagrams[key]["My"] = lr.diagram.moment_y;
      diagrams[key]["Qy"] = lr.diagram.shear_y;
      diagrams[key]["M_resultant"] = mr;
      diagrams[key]["Q_resultant"] = qr;
    }
    for (std::size_t i = 0; i < lr.diagram.x.size(); ++i)
      csv << lr.loads.layout << "," << format_g(lr.diagram.x[i], 12) << ","
          << format_g(lr.diagram.moment[i], 12) << "," << format_g(lr.diagram.shear[i], 12) << "\n";
  }
  const Contact& c = r.contact;
  ordered_json contact{{"layout", c.layout},
                       {"plate", kPlateKey[c.plate]},
                       {"N", c.force},
                       {"B", c.width},
                       {"r", c.radius},
                       {"gamma", c.angle},
                       {"c", c.c},
                       {"A", c.area},
                       {"p", c.p}};
  contact["hertz"] = c.hertz ? ordered_json{{"p0", c.peak},
                                            {"half_width", c.half_width},
                                            {"effective_radius", c.effective_radius}}
                             : ordered_json();

  std::string text;
  if (f.format == "json") {
    ordered_json j;
    j["model"] = "strength.roller_plates";
    j["source"] =
        "000 §1.5 figs. 20-21, eqs. (22)-(23) (reconstructed load layouts: the free link's "
        "plates S/2 each, the tooth N, the seated link's plates by statics; uniform loads over "
        "the plate thickness; Hertz line contact, Johnson 1985 §4.2)";
    j["hinge"] = rolling ? "rolling" : "sliding";
    j["min_safety_margin"] = number_or_null(worst);
    j["checks"] = checks;
    j["layouts"] = layouts;
    j["diagrams"] = diagrams;
    j["contact"] = contact;
    j["units"] = {{"stress", "Pa"},
                  {"allowable", "Pa"},
                  {"required", "1"},
                  {"safety_factor", "1"},
                  {"min_safety_margin", "1"},
                  {"x", "m"},
                  {"M", "N*m"},
                  {"Q", "N"},
                  {"plate_force", "N"},
                  {"tooth_force", "N"},
                  {"lower_outer", "N"},
                  {"plate_force_y", "N"},
                  {"tooth_force_direction", "rad"},
                  {"My", "N*m"},
                  {"Qy", "N"},
                  {"M_resultant", "N*m"},
                  {"Q_resultant", "N"},
                  {"lower_inner", "N"},
                  {"upper_inner", "N"},
                  {"upper_outer", "N"},
                  {"moment_max", "N*m"},
                  {"moment_at", "m"},
                  {"shear_max", "N"},
                  {"shear_at", "m"},
                  {"force_residual", "N"},
                  {"moment_residual", "N*m"},
                  {"N", "N"},
                  {"B", "m"},
                  {"r", "m"},
                  {"gamma", "rad"},
                  {"c", "m"},
                  {"A", "m^2"},
                  {"p", "Pa"},
                  {"p0", "Pa"},
                  {"half_width", "m"},
                  {"effective_radius", "m"}};
    j["diagnostics"] = diags;
    text = j.dump(2) + "\n";
  } else if (f.format == "csv") {
    text = csv.str();
  } else {
    std::ostringstream t;
    t << "Catena strength: roller and plates of a " << (rolling ? "rolling" : "sliding")
      << "-friction hinge (seed 000 §1.5; S = " << format_g(l.tension / 1e3, 4)
      << " kN, S2 = " << format_g(l.exit_tension / 1e3, 4) << " kN at "
      << format_g(l.link_angle * 180.0 / std::numbers::pi, 4)
      << "°, tooth N = " << format_g(std::hypot(tooth_force(l)[0], tooth_force(l)[1]) / 1e3, 4)
      << " kN at L1 = " << format_g(l.load_height * 1e3, 4) << " mm)\n\n";
    char line[512];
    std::snprintf(line, sizeof line, "  %-24s %12s %15s %8s %8s  %s\n", "check", "stress [MPa]",
                  "allowable [MPa]", "n", "n req", "section");
    t << line;
    for (const Check& k : r.checks) {
      std::snprintf(line, sizeof line, "  %-24s %12.4g %15.4g %8.3g %8.3g  %s%s\n", k.name.c_str(),
                    k.stress / 1e6, k.allowable / 1e6, k.safety_factor, k.required,
                    k.section.c_str(), k.ok ? "" : "  FAILS");
      t << line;
    }
    t << "\n  layout  plate forces [kN] (lower outer, lower inner, upper inner, upper outer)"
         "   M_max [N·m] at z [mm]   Q_max [kN]\n";
    for (const LayoutResult& lr : r.layouts) {
      const auto& p = lr.loads.plate_force;
      std::snprintf(line, sizeof line, "  %6d  %8.4g %8.4g %8.4g %8.4g %38.4g at %-8.4g %10.4g\n",
                    lr.loads.layout, p[0] / 1e3, p[1] / 1e3, p[2] / 1e3, p[3] / 1e3,
                    lr.extremes.moment, lr.extremes.moment_at * 1e3, lr.extremes.shear / 1e3);
      t << line;
      if (lr.planar) {
        const auto& y = lr.loads.plate_force_y;
        std::snprintf(line, sizeof line, "     (y)  %8.4g %8.4g %8.4g %8.4g   (M, Q: resultants)\n",
                      y[0] / 1e3, y[1] / 1e3, y[2] / 1e3, y[3] / 1e3);
        t << line;
      }
    }
    t << "\n  contact (" << kPlateKey[c.plate] << ", layout " << c.layout
      << "): N = " << format_g(c.force / 1e3, 4) << " kN, eq. (22) c = " << format_g(c.c * 1e3, 4)
      << " mm, eq. (23) p = N/(c·B) = " << format_g(c.p / 1e6, 4) << " MPa";
    if (c.hertz)
      t << "; Hertz p0 = " << format_g(c.peak / 1e6, 4)
        << " MPa (b = " << format_g(c.half_width * 1e3, 4) << " mm; p is the mean pressure π/4·p0)";
    t << "\n";
    if (!r.diagnostics.empty()) t << "\n";
    for (const Diagnostic& d : r.diagnostics)
      t << "  " << to_string(d.severity) << ": " << d.message << "\n";
    text = t.str();
  }
  write_text_output(f.output, text);
  return 0;
}

}  // namespace

std::function<int()> add_strength(CLI::App& app) {
  auto f = std::make_shared<StrengthFlags>();
  CLI::App* c = app.add_subcommand(
      "strength",
      "Strength checks of the roller and plates: M/Q diagrams, contact, safety factors (seed 000 "
      "§1.5)");
  c->add_option("--tension", f->tension, "S, the free link's chain tension (bare: N)");
  c->add_option("--tooth-force", f->tooth_force,
                "N on the roller with collinear links, 0 ≤ N ≤ S (sets S2 = S − N; default: S2 "
                "given or 0, i.e. N = S; bare: N)");
  c->add_option("--exit-tension", f->exit_tension,
                "S2, the seated link's tension (default 0: the tooth takes all; bare: N)");
  c->add_option("--link-angle", f->link_angle,
                "θ between the free and the seated link (default 0: collinear; bare: degree)");
  c->add_option("--load-height", f->load_height,
                "L1, the tooth load's height (default: midway between the inner plates; bare: mm)");
  c->add_option("--tooth-width", f->tooth_width,
                "width of the tooth load along the roller (default 0: a point load; bare: mm)");
  c->add_option("--layout", f->layout, "1 (inner link seated), 2 (outer link seated) or both")
      ->check(CLI::IsMember({"1", "2", "both"}));
  c->add_option("--hinge", f->hinge, "sliding (default) or rolling")
      ->check(CLI::IsMember({"sliding", "rolling"}));
  c->add_option("--heights", f->heights,
                "plate mid-plane heights, bottom to top: lower outer, lower inner, upper inner, "
                "upper outer (as catena warp; bare: mm)");
  c->add_option("--widths", f->widths, "plate thicknesses B_i, 1 or 4 (bare: mm)");
  c->add_option("--pin-diameter,--roller-diameter", f->diameter,
                "roller (pin) diameter d (bare: mm)");
  c->add_option("--bore", f->bore, "inner diameter of a hollow roller (default 0; bare: mm)");
  c->add_option("--hole-diameter", f->hole, "plate hole/aperture d_h (default d; bare: mm)");
  c->add_option("--plate-width", f->plate_width,
                "b, the plate's depth across the chain line (bare: mm)");
  c->add_option("--end-distance", f->end_distance,
                "e, hole centre to plate end along the chain line (bare: mm)");
  c->add_option("--stress-concentration", f->stress_concentration,
                "K_t on the net section (default 1: nominal stress)");
  c->add_option("--contact-angle", f->contact_angle,
                "sliding hinge: the pin's contact arc γ of eq. (22) (default 180deg: c = d; bare: "
                "degree)");
  c->add_option("--plate-radius,--r1", f->r1, "rolling hinge: plate convex radius R1 (bare: mm)");
  c->add_option("--roller-radius,--r2", f->r2,
                "rolling hinge: roller concave radius R2 > R1 (bare: mm)");
  c->add_option("--modulus", f->modulus, "E (default 210GPa)");
  c->add_option("--poisson", f->poisson, "nu (default 0.3)");
  c->add_option("--roller-yield", f->roller_yield, "σ_y of the roller (bare: MPa)");
  c->add_option("--plate-yield", f->plate_yield, "σ_y of the plates (bare: MPa)");
  c->add_option("--plate-ultimate", f->plate_ultimate,
                "σ_u of the plates: adds a net-section check (bare: MPa)");
  c->add_option("--allowable-pressure", f->allowable_pressure,
                "sliding hinge: allowable specific pressure [p] of eq. (23) (bare: MPa)");
  c->add_option("--allowable-contact", f->allowable_contact,
                "rolling hinge: allowable Hertz stress [sigma_H] (bare: MPa)");
  c->add_option("--safety-factor", f->safety_factor,
                "required safety factor against yield/ultimate (default 1.5)");
  c->add_option("--format", f->format, "table|json|csv (csv: the M and Q diagrams)")
      ->check(CLI::IsMember({"table", "json", "csv"}));
  c->add_option("--output", f->output, "write the output to FILE");
  return [f]() { return run_strength(*f); };
}

}  // namespace catena::cli
