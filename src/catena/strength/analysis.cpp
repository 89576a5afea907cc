// `strength` — strength checks of the roller and plates of a conveyor chain hinge (seed 000
// §1.5): load layouts 1 and 2, the roller's M and Q diagrams, eqs. (22)-(23), Hertz for the
// rolling hinge, the plate's dangerous sections (fig. 21) — as an analysis.
#include "catena/strength/analysis.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>
#include <tuple>

#include "catena/io/record.hpp"

namespace catena::strength {
namespace {

using analysis::format_g;
using analysis::Inputs;
using analysis::Record;
using analysis::Value;

constexpr const char* kPlateKey[4] = {"lower_outer", "lower_inner", "upper_inner", "upper_outer"};

constexpr const char* kFour =
    "1 or 4 comma-separated lengths, bottom to top: lower outer, lower inner, upper inner, upper "
    "outer plate";

bool rolling(const Inputs& in) { return in.text("hinge") == "rolling"; }

// Four plate values bottom to top (lower outer, lower inner, upper inner, upper outer); one value
// is repeated to all four. NaN when absent or not 1 or 4 values (the check reports those).
std::array<double, 4> four(const Inputs& in, std::string_view key) {
  std::array<double, 4> out{NAN, NAN, NAN, NAN};
  if (!in.present(key)) return out;
  const std::vector<double>& v = in.list(key);
  if (v.size() == 1) out.fill(v[0]);
  if (v.size() == 4) std::copy(v.begin(), v.end(), out.begin());
  return out;
}

// The model's input from the bound values: what is absent takes the meaning the command gave it
// (no hole diameter: the pin's; no exit tension: 0; no load height: midway between the inner
// plates); what could not be read is NaN.
Input to_input(const Inputs& in) {
  Input x;
  Hinge& h = x.hinge;
  h.heights = four(in, "heights");
  h.widths = four(in, "widths");
  h.pin_diameter = in.number("pin_diameter");
  h.bore = in.number("bore");
  h.hole_diameter = in.present("hole_diameter") ? in.number("hole_diameter") : 0.0;
  h.plate_width = in.number("plate_width");
  h.end_distance = in.number("end_distance");
  h.stress_concentration = in.number("stress_concentration");
  h.kind = rolling(in) ? HingeKind::kRolling : HingeKind::kSliding;
  if (h.kind == HingeKind::kSliding) {
    h.contact_angle = in.number("contact_angle");
  } else {
    h.r1 = in.number("plate_radius");
    h.r2 = in.number("roller_radius");
  }
  h.modulus = in.number("modulus");
  h.poisson = in.number("poisson");

  Loads& l = x.loads;
  l.tension = in.number("tension");
  l.link_angle = in.number("link_angle");
  const bool tooth = in.present("tooth_force"), exit = in.present("exit_tension");
  if (tooth && !exit) {
    l.exit_tension = l.tension - in.number("tooth_force");  // collinear links: N = S − S2
  } else if (!tooth) {
    l.exit_tension = exit ? in.number("exit_tension") : 0.0;
  }
  l.tooth_width = in.number("tooth_width");
  l.load_height =
      in.present("load_height") ? in.number("load_height") : 0.5 * (h.heights[1] + h.heights[2]);

  Material& m = x.material;
  m.roller_yield = in.number("roller_yield");
  m.plate_yield = in.number("plate_yield");
  m.plate_ultimate = in.present("plate_ultimate") ? in.number("plate_ultimate") : 0.0;
  if (h.kind == HingeKind::kSliding)
    m.allowable_pressure = in.number("allowable_pressure");
  else
    m.allowable_contact = in.number("allowable_contact");
  m.required = in.number("safety_factor");
  const std::string& layout = in.text("layout");
  x.layouts = layout == "1" ? Layouts::kOne : layout == "2" ? Layouts::kTwo : Layouts::kBoth;
  return x;
}

// The rules between inputs, and every problem in the order the inputs are read: the binder's
// problems of each value at its place among the rules (values a hinge kind does not read are not
// reported), then the model's own checks — except for the values already reported (those were
// read as NaN).
void check(const Inputs& in, std::vector<Issue>& issues) {
  std::vector<Issue> bound = std::move(issues);
  issues.clear();
  const std::vector<analysis::Parameter>& parameters = *in.parameters();
  auto known = [&](const std::string& key) {
    for (const analysis::Parameter& p : parameters) {
      if (p.name == key) return true;
    }
    return false;
  };
  for (const Issue& issue : bound) {
    if (!known(issue.field)) issues.push_back(issue);  // not an input of 'strength'
  }
  auto take = [&](std::string_view key) {
    for (const Issue& issue : bound) {
      if (issue.field == key) issues.push_back(issue);
    }
  };
  auto take_required = [&](std::string_view key, const char* what) {
    if (!in.present(key))
      issues.push_back({std::string(key), "(missing)", what});
    else
      take(key);
  };
  // an empty part of a list ("1,,2") is not a value of its own
  auto take_four = [&](std::string_view key) {
    for (const Issue& issue : bound) {
      if (issue.field == key && issue.value != "''") issues.push_back(issue);
    }
    const std::size_t n = in.list(key).size();
    if (in.present(key) && n != 1 && n != 4)
      issues.push_back({std::string(key), in.text(key), kFour});
  };
  take_four("heights");
  take_four("widths");
  for (const char* key : {"pin_diameter", "bore", "hole_diameter", "plate_width", "end_distance",
                          "stress_concentration", "hinge"})
    take(key);
  const bool roll = rolling(in);
  if (!roll) {
    take("contact_angle");
  } else {
    take_required("plate_radius", "R1 for a rolling hinge");
    take_required("roller_radius", "R2 for a rolling hinge");
  }
  for (const char* key : {"modulus", "poisson", "tension", "link_angle"}) take(key);
  const bool tooth = in.present("tooth_force"), exit = in.present("exit_tension");
  if (tooth && exit) {
    issues.push_back({"tooth_force", in.text("tooth_force"),
                      "either --tooth-force or --exit-tension, not both"});
  } else if (tooth) {
    if (in.number("link_angle") != 0.0)
      issues.push_back(
          {"tooth_force", in.text("tooth_force"),
           "collinear links only (--link-angle 0); with a link angle give --exit-tension"});
    take("tooth_force");
    const double n = in.number("tooth_force"), s = in.number("tension");
    if (std::isfinite(n) && std::isfinite(s) && !(n >= 0.0 && n <= s))
      issues.push_back(
          {"tooth_force", in.text("tooth_force"),
           "0 ≤ N ≤ S = " + format_g(s) + " N (collinear: the seated link cannot push)"});
  } else {
    take("exit_tension");
  }
  for (const char* key :
       {"tooth_width", "load_height", "roller_yield", "plate_yield", "plate_ultimate"})
    take(key);
  if (!roll)
    take_required("allowable_pressure", "[p], the allowable specific pressure of a sliding hinge");
  else
    take_required("allowable_contact", "[σ_H], the allowable Hertz stress of a rolling hinge");
  for (const char* key : {"safety_factor", "layout"}) take(key);
  for (Issue& issue : validate(to_input(in))) {
    if (issue.value.find("nan") == std::string::npos) issues.push_back(std::move(issue));
  }
}

Value number_or_null(double v) { return std::isfinite(v) ? Value(v) : Value(); }

Value to_value(const StrengthAnalysis& a) {
  const Result& r = a.result;
  const bool roll = a.input.hinge.kind == HingeKind::kRolling;
  Value checks = Value::array();
  double worst = INFINITY;
  for (const Check& c : r.checks) {
    checks.push_back(Value::object({{"name", c.name},
                                    {"section", c.section},
                                    {"stress", c.stress},
                                    {"allowable", c.allowable},
                                    {"required", c.required},
                                    {"safety_factor", number_or_null(c.safety_factor)},
                                    {"ok", c.ok}}));
    worst = std::min(worst, c.safety_factor / c.required);
  }
  Value layouts = Value::object(), diagrams = Value::object();
  for (const LayoutResult& lr : r.layouts) {
    const std::string key = "layout_" + std::to_string(lr.loads.layout);
    Value lj = Value::object();
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
    layouts[key] = std::move(lj);
    Value d =
        Value::object({{"x", lr.diagram.x}, {"M", lr.diagram.moment}, {"Q", lr.diagram.shear}});
    if (lr.planar) {
      std::vector<double> mr, qr;
      for (std::size_t i = 0; i < lr.diagram.x.size(); ++i) {
        mr.push_back(std::hypot(lr.diagram.moment[i], lr.diagram.moment_y[i]));
        qr.push_back(std::hypot(lr.diagram.shear[i], lr.diagram.shear_y[i]));
      }
      d["My"] = lr.diagram.moment_y;
      d["Qy"] = lr.diagram.shear_y;
      d["M_resultant"] = mr;
      d["Q_resultant"] = qr;
    }
    diagrams[key] = std::move(d);
  }
  const Contact& c = r.contact;
  Value contact = Value::object({{"layout", c.layout},
                                 {"plate", kPlateKey[c.plate]},
                                 {"N", c.force},
                                 {"B", c.width},
                                 {"r", c.radius},
                                 {"gamma", c.angle},
                                 {"c", c.c},
                                 {"A", c.area},
                                 {"p", c.p}});
  contact["hertz"] = c.hertz ? Value::object({{"p0", c.peak},
                                              {"half_width", c.half_width},
                                              {"effective_radius", c.effective_radius}})
                             : Value();

  Value j = Value::object();
  j["model"] = "strength.roller_plates";
  j["source"] =
      "000 §1.5 figs. 20-21, eqs. (22)-(23) (reconstructed load layouts: the free link's "
      "plates S/2 each, the tooth N, the seated link's plates by statics; uniform loads over "
      "the plate thickness; Hertz line contact, Johnson 1985 §4.2)";
  j["hinge"] = roll ? "rolling" : "sliding";
  j["min_safety_margin"] = number_or_null(worst);
  j["checks"] = std::move(checks);
  j["layouts"] = std::move(layouts);
  j["diagrams"] = std::move(diagrams);
  j["contact"] = std::move(contact);
  j["units"] = analysis::units_value({{"stress", "Pa"},
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
                                      {"effective_radius", "m"}});
  j["diagnostics"] = analysis::diagnostics_value(r.diagnostics);
  return j;
}

// The M and Q diagrams, layout after layout.
std::vector<analysis::Column> csv_columns(const Result& r) {
  std::vector<analysis::Column> cols{{"layout", {}}, {"x", {}}, {"M", {}}, {"Q", {}}};
  for (const LayoutResult& lr : r.layouts) {
    for (std::size_t i = 0; i < lr.diagram.x.size(); ++i) {
      cols[0].values.push_back(lr.loads.layout);
      cols[1].values.push_back(lr.diagram.x[i]);
      cols[2].values.push_back(lr.diagram.moment[i]);
      cols[3].values.push_back(lr.diagram.shear[i]);
    }
  }
  return cols;
}

std::string to_table(const StrengthAnalysis& a) {
  const Result& r = a.result;
  const Loads& l = a.input.loads;
  const bool roll = a.input.hinge.kind == HingeKind::kRolling;
  std::ostringstream t;
  t << "Catena strength: roller and plates of a " << (roll ? "rolling" : "sliding")
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
                  k.stress / 1e6, k.allowable / 1e6, k.safety_factor, k.required, k.section.c_str(),
                  k.ok ? "" : "  FAILS");
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
  const Contact& c = r.contact;
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
  return t.str();
}

// The report: the checks as a grid, M and Q along the roller per layout (at an angle: the
// resultants' magnitudes).
void add_report(const Value& r, Record& rec) {
  analysis::Grid grid{
      "Safety factors",
      {"check", "section", "stress [MPa]", "allowable [MPa]", "n", "required", "ok"},
      {},
      {}};
  const auto cell = io::format_cell;  // %.6g, yes/no, — for null
  for (const Value& c : r.at("checks").as_array()) {
    grid.rows.push_back({c.at("name").as_string(), c.at("section").as_string(),
                         cell(c.at("stress"), 1e-6), cell(c.at("allowable"), 1e-6),
                         cell(c.at("safety_factor"), 1.0), cell(c.at("required"), 1.0),
                         cell(c.at("ok"), 1.0)});
  }
  rec.grids.push_back(std::move(grid));
  const Value& d = r.at("diagrams");
  for (const auto& [key, title, unit, scale] :
       {std::tuple<const char*, const char*, const char*, double>{
            "M", "Bending moment along the roller", "M [N·m]", 1.0},
        {"Q", "Shear force along the roller", "Q [kN]", 1e-3}}) {
    analysis::Chart c;
    c.title = title;
    c.x_label = "z [mm]";
    c.y_label = unit;
    for (const auto& [layout, diagram] : d.as_object()) {
      std::string k = key;
      if (diagram.contains(k + "_resultant")) k += "_resultant";
      c.traces.push_back({layout + (k == key ? "" : " |" + std::string(key) + "|"),
                          diagram.at("x").numbers(1e3), diagram.at(k).numbers(scale)});
    }
    rec.charts.push_back(std::move(c));
  }
}

Record describe(const StrengthAnalysis& a, const Inputs&) {
  Record rec;
  rec.data = to_value(a);
  rec.diagnostics = a.result.diagnostics;
  rec.table = to_table(a);
  rec.columns = csv_columns(a.result);
  add_report(rec.data, rec);
  rec.labels = {{"min_safety_margin", "Least safety factor / required n/[n]", ""},
                {"layouts", "", ""},
                {"layout_1", "Layout 1", ""},
                {"layout_2", "Layout 2", ""},
                {"plate_force.lower_outer", "Plate force, lower outer F21", "kN"},
                {"plate_force.lower_inner", "Plate force, lower inner F11", "kN"},
                {"plate_force.upper_inner", "Plate force, upper inner F12", "kN"},
                {"plate_force.upper_outer", "Plate force, upper outer F22", "kN"},
                {"plate_force_y.lower_outer", "Plate force across, lower outer F21y", "kN"},
                {"plate_force_y.lower_inner", "Plate force across, lower inner F11y", "kN"},
                {"plate_force_y.upper_inner", "Plate force across, upper inner F12y", "kN"},
                {"plate_force_y.upper_outer", "Plate force across, upper outer F22y", "kN"},
                {"tooth_force", "Tooth force N", "kN"},
                {"tooth_force_direction", "Tooth force direction", ""},
                {"moment_max", "Largest bending moment M_max", "N·m"},
                {"moment_at", "… at z", ""},
                {"shear_max", "Largest shear force Q_max", "kN"},
                {"shear_at", "… at z", ""},
                {"force_residual", "Force balance residual", ""},
                {"moment_residual", "Moment balance residual", "N·m"},
                {"contact.layout", "Contact: layout", ""},
                {"contact.plate", "Contact: plate", ""},
                {"contact.N", "Contact force N", "kN"},
                {"contact.B", "Contact length B", ""},
                {"contact.r", "Contact radius r", ""},
                {"contact.gamma", "Contact angle γ", ""},
                {"contact.c", "Contact chord c, eq. (22)", ""},
                {"contact.A", "Contact area A", ""},
                {"contact.p", "Mean contact pressure p, eq. (23)", ""},
                {"contact.hertz.p0", "Hertz peak pressure p0", ""},
                {"contact.hertz.half_width", "Hertz half-width b", ""},
                {"contact.hertz.effective_radius", "Effective radius R*", ""}};
  return rec;
}

analysis::Analysis make() {
  using namespace analysis;
  using K = QuantityKind;
  // a plain number with a default and its own words for an unreadable value
  auto expecting = [](Parameter p, std::string expected) {
    p.expected = std::move(expected);
    return p;
  };
  Analysis a;
  a.name = "strength";
  a.command = {"strength"};
  a.title = "Strength of the roller and plates: M and Q diagrams, safety factors (seed 000 §1.5)";
  a.help =
      "Strength checks of the roller and plates: M/Q diagrams, contact, safety factors (seed 000 "
      "§1.5)";
  a.seed = "000 §1.5";
  a.docs = "docs/models/strength.md";
  a.chain_types = {"rolling-hinge", "sliding-hinge"};
  a.formats = {.table = true, .csv = true, .drawing = false};
  Parameter hinge =
      choice("hinge", {"sliding", "rolling"}, "hinge kind (case files: from chain.type)") |
      Default{"sliding"};
  hinge.cli_only = true;  // a case file's chain.type chooses it (the variants below)
  a.parameters = {
      quantity("heights", K::kLength,
               "plate mid-plane heights, bottom to top: lower outer, lower inner, upper inner, "
               "upper outer (as catena warp)") |
          Required{kFour} | ListOf{},
      quantity("widths", K::kLength, "plate thicknesses B_i, 1 or 4") | Required{kFour} | ListOf{},
      quantity("pin_diameter", K::kLength, "roller (pin) diameter d") |
          Required{"d of the roller (pin)"} | Alias{"roller_diameter"},
      quantity("bore", K::kLength, "inner diameter of a hollow roller") | Default{"0"},
      quantity("hole_diameter", K::kLength, "plate hole/aperture d_h (default d)"),
      quantity("plate_width", K::kLength, "b, the plate's depth across the chain line") |
          Required{"b, the plate's depth across the chain line"},
      quantity("end_distance", K::kLength, "e, hole centre to plate end along the chain line") |
          Required{"e, from the hole centre to the plate's end"},
      expecting(number("stress_concentration", "K_t on the net section (1: nominal stress)") |
                    Default{"1"},
                "K_t ≥ 1, a plain number"),
      hinge,
      quantity("contact_angle", K::kAngle,
               "sliding hinge: the pin's contact arc γ of eq. (22) (180deg: c = d)") |
          Default{"180deg"},
      quantity("plate_radius", K::kLength, "rolling hinge: plate convex radius R1") | Alias{"r1"},
      quantity("roller_radius", K::kLength, "rolling hinge: roller concave radius R2 > R1") |
          Alias{"r2"},
      quantity("modulus", K::kStress, "E") | Default{"210GPa"},
      expecting(number("poisson", "nu") | Default{"0.3"}, "0 ≤ ν < 0.5, a plain number"),
      quantity("tension", K::kForce, "S, the free link's chain tension") |
          Required{"S, the free link's tension"},
      quantity("link_angle", K::kAngle, "θ between the free and the seated link (0: collinear)") |
          Default{"0"},
      quantity("tooth_force", K::kForce,
               "N on the roller with collinear links, 0 ≤ N ≤ S (sets S2 = S − N; default: S2 "
               "given or 0, i.e. N = S)"),
      quantity("exit_tension", K::kForce,
               "S2, the seated link's tension (default 0: the tooth takes all)"),
      quantity("tooth_width", K::kLength,
               "width of the tooth load along the roller (0: a point load)") |
          Default{"0"},
      quantity("load_height", K::kLength,
               "L1, the tooth load's height (default: midway between the inner plates)"),
      quantity("roller_yield", K::kStress, "σ_y of the roller") | Required{"σ_y of the roller"},
      quantity("plate_yield", K::kStress, "σ_y of the plates") | Required{"σ_y of the plates"},
      quantity("plate_ultimate", K::kStress, "σ_u of the plates: adds a net-section check"),
      quantity("allowable_pressure", K::kStress,
               "sliding hinge: allowable specific pressure [p] of eq. (23)"),
      quantity("allowable_contact", K::kStress, "rolling hinge: allowable Hertz stress [sigma_H]"),
      expecting(
          number("safety_factor", "required safety factor against yield/ultimate") | Default{"1.5"},
          "the required safety factor > 0"),
      choice("layout", {"1", "2", "both"}, "1 (inner link seated), 2 (outer link seated) or both") |
          Default{"both"},
  };
  a.check = check;
  set_functions<StrengthAnalysis>(a, strength_analysis_run, describe);
  a.variants = {{"rolling-hinge", {{{"hinge", "rolling"}}, {}}},
                {"sliding-hinge", {{{"hinge", "sliding"}}, {"plate_radius", "roller_radius"}}}};
  return a;
}

}  // namespace

StrengthAnalysis strength_analysis_run(const analysis::Inputs& in) {
  StrengthAnalysis a;
  a.input = to_input(in);
  a.result = assess(a.input);
  return a;
}

const analysis::Analysis& strength_analysis() {
  static const analysis::Analysis a = make();
  return a;
}

}  // namespace catena::strength
