// `warp` — roller warp in the vertical plane (seed 000 §1.4), swept over L1 and F — as an
// analysis.
#include "catena/warp/analysis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include "catena/core/progress.hpp"

namespace catena::warp {
namespace {

using analysis::format_g;
using analysis::Inputs;
using analysis::Record;
using analysis::Value;

constexpr const char* kNames[4] = {"F21", "F11", "F12", "F22"};
constexpr const char* kFour =
    "four values, bottom to top: lower outer, lower inner, upper inner, upper outer";
constexpr std::size_t kMaxPoints = 100000;

// The inputs in the order they are read; the problems come out in this order.
const std::vector<std::string> kOrder = {
    "heights", "clearances", "widths",       "stiffness",     "exponent", "pin_diameter", "modulus",
    "poisson", "hinge",      "plate_radius", "roller_radius", "force",    "load_height"};

// Per-joint lists take one value (for all four) or four; the stiffness in SI takes plain numbers
// (an empty part is a missing one); R1 and R2 belong to the rolling hinge (a sliding one does
// not read them); the sweep has at most kMaxPoints points.
void check(const Inputs& in, std::vector<Issue>& issues) {
  const bool rolling = in.text("hinge") == "rolling";
  std::vector<Issue> added;
  for (const char* key : {"heights", "clearances", "widths"}) {
    const std::size_t n = in.list(key).size();
    if (in.present(key) && n != 1 && n != 4)
      added.push_back({key, in.text(key), std::string(kFour) + ": 1 or 4 comma-separated values"});
  }
  for (Issue& issue : issues) {
    if (issue.field == "stiffness" && issue.value == "''") issue.value = "(missing)";
  }
  if (!in.present("stiffness")) {
    added.push_back({"stiffness", "(missing)", "k of R = k·g^n in SI (N/m^n), 1 or 4 values"});
  } else if (in.list("stiffness").size() != 1 && in.list("stiffness").size() != 4) {
    added.push_back({"stiffness", in.text("stiffness"), "1 or 4 values"});
  }
  if (rolling) {
    if (!in.given("plate_radius"))
      added.push_back({"plate_radius", "(missing)", "R1 for a rolling hinge"});
    if (!in.given("roller_radius"))
      added.push_back({"roller_radius", "(missing)", "R2 for a rolling hinge"});
  }
  std::vector<Issue> out =
      analysis::in_read_order(issues, added, kOrder, [&](const std::string& key) {
        return rolling || (key != "plate_radius" && key != "roller_radius");
      });
  const double forces = static_cast<double>(in.list("force").size()),
               heights = static_cast<double>(in.list("load_height").size());
  if (forces * heights > static_cast<double>(kMaxPoints)) {
    out.push_back({"force", format_g(forces) + " × " + format_g(heights) + " points",
                   "at most 100000 sweep points"});
  }
  issues = std::move(out);
}

// One value for all four joints, or four.
std::vector<double> four(const std::vector<double>& values) {
  return values.size() == 1 ? std::vector<double>(4, values.front()) : values;
}

Value to_value(const WarpAnalysis& a) {
  Value points = Value::array();
  for (const auto& [load, r] : a.points) {
    Value p = Value::object();
    p["force"] = load.force;
    p["load_height"] = load.height;
    for (std::size_t i = 0; i < 4; ++i) p["joint_force"][kNames[i]] = r.force[i];
    for (std::size_t i = 0; i < 4; ++i) p["deformation"][kNames[i]] = r.deformation[i];
    for (std::size_t i = 0; i < 4; ++i) p["deflection"][kNames[i]] = r.deflection[i];
    for (std::size_t i = 0; i < 4; ++i) p["contact_stress"][kNames[i]] = r.contact_stress[i];
    p["tilt"] = r.tilt;
    p["upper_share"] = r.upper_share;
    p["moment_max"] = r.moment_max;
    p["bending_stress"] = r.bending_stress;
    p["force_residual"] = r.force_residual;
    p["moment_residual"] = r.moment_residual;
    p["solver"] = Value::object({{"converged", r.summary.converged},
                                 {"iterations", r.summary.iterations},
                                 {"residual", r.summary.residual},
                                 {"termination", r.summary.termination},
                                 {"tolerance", r.summary.tolerance},
                                 {"equilibrium_residual", r.summary.equilibrium_residual},
                                 {"equilibrium_tolerance", r.summary.equilibrium_tolerance}});
    points.push_back(std::move(p));
  }
  Value diagnostics = Value::array();
  for (const WarpAnalysis::Finding& f : a.findings) {
    const Diagnostic& d = f.diagnostic;
    diagnostics.push_back(Value::object({{"severity", to_string(d.severity)},
                                         {"code", d.code},
                                         {"message", d.message},
                                         {"value", d.value},
                                         {"limit", d.limit},
                                         {"force", f.load.force},
                                         {"load_height", f.load.height},
                                         {"points", f.points}}));
  }
  Value j = Value::object();
  j["model"] = "warp.roller_four_joints";
  j["source"] =
      "000 §1.4 figs. 12-18 (reconstructed: Euler-Bernoulli roller on unilateral power-law "
      "joints, Levina & Reshetov 1971; Hertz line contact, Johnson 1985 §4.2)";
  j["hinge"] = a.warp.kind == HingeKind::kRolling ? "rolling" : "sliding";
  j["exponent"] = a.warp.exponent;
  j["points"] = std::move(points);
  j["units"] = analysis::units_value({{"force", "N"},
                                      {"load_height", "m"},
                                      {"joint_force", "N"},
                                      {"deformation", "m"},
                                      {"deflection", "m"},
                                      {"contact_stress", "Pa"},
                                      {"tilt", "rad"},
                                      {"upper_share", "1"},
                                      {"moment_max", "N*m"},
                                      {"bending_stress", "Pa"},
                                      {"force_residual", "N"},
                                      {"moment_residual", "N*m"},
                                      {"residual", "N"},
                                      {"tolerance", "N"},
                                      {"equilibrium_residual", "N"},
                                      {"equilibrium_tolerance", "N"},
                                      {"stiffness", "N/m^n"},
                                      {"exponent", "1"}});
  j["diagnostics"] = std::move(diagnostics);
  return j;
}

std::vector<analysis::Column> csv_columns(const WarpAnalysis& a) {
  std::vector<analysis::Column> cols;
  for (const char* name :
       {"force", "load_height", "F21", "F11", "F12", "F22", "delta21", "delta11", "delta12",
        "delta22", "tilt", "upper_share", "bending_stress", "stress21", "stress11", "stress12",
        "stress22", "converged", "iterations"})
    cols.push_back({name, {}, 12});
  cols.push_back({"residual", {}, 6});
  for (const auto& [load, r] : a.points) {
    std::vector<double> row = {load.force, load.height};
    row.insert(row.end(), r.force.begin(), r.force.end());
    row.insert(row.end(), r.deformation.begin(), r.deformation.end());
    row.insert(row.end(), {r.tilt, r.upper_share, r.bending_stress});
    row.insert(row.end(), r.contact_stress.begin(), r.contact_stress.end());
    row.insert(row.end(), {r.summary.converged ? 1.0 : 0.0,
                           static_cast<double>(r.summary.iterations), r.summary.residual});
    for (std::size_t c = 0; c < cols.size(); ++c) cols[c].values.push_back(row[c]);
  }
  return cols;
}

std::string to_table(const WarpAnalysis& a) {
  std::ostringstream table;
  table << "Catena warp: roller on four joints with clearance (seed 000 §1.4; "
        << (a.warp.kind == HingeKind::kRolling ? "rolling" : "sliding")
        << " hinge)\n\n    F [kN]  L1 [mm]  F21 [kN]  F11 [kN]  F12 [kN]  F22 [kN]  upper/lower-1  "
           "tilt [mrad]  sigma F12 [MPa]  sigma_b [MPa]\n";
  for (const auto& [load, r] : a.points) {
    char line[256];
    std::snprintf(
        line, sizeof line, "  %8.4g %8.4g %9.4g %9.4g %9.4g %9.4g %14.4g %12.4g %16.4g %14.4g%s\n",
        load.force / 1e3, load.height * 1e3, r.force[0] / 1e3, r.force[1] / 1e3, r.force[2] / 1e3,
        r.force[3] / 1e3, r.upper_share, r.tilt * 1e3, r.contact_stress[kF12] / 1e6,
        r.bending_stress / 1e6, r.summary.converged ? "" : "  NOT CONVERGED");
    table << line;
  }
  return table.str();
}

// The report's chart: one line per load F, the upper plates' share of the load versus its
// height L1.
analysis::Chart share_chart(const WarpAnalysis& a) {
  std::map<double, std::pair<std::vector<double>, std::vector<double>>> by_force;
  for (const auto& [load, r] : a.points) {
    auto& [x, y] = by_force[load.force];
    x.push_back(load.height * 1e3);
    y.push_back(r.upper_share * 100);
  }
  analysis::Chart c;
  c.title = "Share of the load on the upper plates versus the load height L1";
  c.x_label = "L1 [mm]";
  c.y_label = "upper share [%]";
  for (const auto& [force, xy] : by_force) {
    char name[48];
    std::snprintf(name, sizeof name, "F = %.4g kN", force * 1e-3);
    c.traces.push_back({name, xy.first, xy.second});
  }
  return c;
}

Record describe(const WarpAnalysis& a, const Inputs&) {
  Record rec;
  rec.data = to_value(a);
  for (const WarpAnalysis::Finding& f : a.findings) rec.diagnostics.push_back(f.diagnostic);
  rec.table = to_table(a);
  rec.columns = csv_columns(a);
  rec.charts.push_back(share_chart(a));
  // the report: every load point with its joint forces, as the text table has them
  analysis::Grid grid{"Load points",
                      {"F [kN]", "L1 [mm]", "F21 [kN]", "F11 [kN]", "F12 [kN]", "F22 [kN]",
                       "upper share [%]", "tilt [mrad]", "σ F12 [MPa]", "σb [MPa]", "converged"},
                      {},
                      {},
                      true,
                      ""};
  for (const auto& [load, r] : a.points) {
    // 5 digits; round-off of a symmetric state (a share of 1e-10 %) is shown as the 0 it is
    auto g = [](double v) { return std::abs(v) < 1e-6 ? std::string("0") : format_g(v, 5); };
    grid.rows.push_back({g(load.force / 1e3), g(load.height * 1e3), g(r.force[0] / 1e3),
                         g(r.force[1] / 1e3), g(r.force[2] / 1e3), g(r.force[3] / 1e3),
                         g(r.upper_share * 100), g(r.tilt * 1e3), g(r.contact_stress[kF12] / 1e6),
                         g(r.bending_stress / 1e6), r.summary.converged ? "yes" : "no"});
  }
  rec.grids.push_back(std::move(grid));
  return rec;
}

analysis::Analysis make() {
  using namespace analysis;
  using K = QuantityKind;
  Analysis a;
  a.name = "warp";
  a.command = {"warp"};
  a.title = "Roller warp: the roller on four plate joints with clearance (seed 000 §1.4)";
  a.help = "Roller warp: joint forces, tilt and stresses versus L1 and F (seed 000 §1.4)";
  a.seed = "000 §1.4";
  a.docs = "docs/models/warp.md";
  a.chain_types = {"rolling-hinge", "sliding-hinge"};
  a.formats = {.table = true, .csv = true, .drawing = false};
  a.parameters = {
      quantity("heights", K::kLength,
               "joint heights, bottom to top: lower outer, lower inner, upper inner, upper outer "
               "(e.g. 0,10mm,50mm,60mm)") |
          ListOf{} | Required{kFour},
      quantity("clearances", K::kLength, "radial clearances c_i, 1 or 4") | ListOf{} |
          Default{"0,0,0,0"},
      quantity("widths", K::kLength, "plate thicknesses B_i, 1 or 4") | ListOf{} | Required{kFour},
      // not Required: its message when missing differs from a part's (see `check`)
      [] {
        Parameter p = number("stiffness", "k of R = k·g^n in SI N/m^n, 1 or 4 values") | ListOf{};
        p.expected = "k in SI (N/m^n), a plain number";
        return p;
      }(),
      [] {
        Parameter p = number("exponent", "n of the joint law in [1, 3]") | Default{"1"};
        p.expected = "n in [1, 3]";
        return p;
      }(),
      quantity("pin_diameter", K::kLength, "roller (pin) diameter d, as catena hinge") |
          Required{"d of the roller"} | Alias{"roller_diameter"},
      quantity("modulus", K::kStress, "E") | Default{"210GPa"},
      [] {
        Parameter p = number("poisson", "nu") | Default{"0.3"};
        p.expected = "0 ≤ ν < 0.5";
        return p;
      }(),
      // chain.type decides it in a case file
      choice("hinge", {"sliding", "rolling"}, "the hinge") | Default{"sliding"} | CliOnly{},
      quantity("plate_radius", K::kLength,
               "rolling hinge: plate convex radius R1 (required with --hinge rolling)") |
          Alias{"r1"},
      quantity("roller_radius", K::kLength,
               "rolling hinge: roller concave radius R2 > R1 (required with --hinge rolling)") |
          Alias{"r2"},
      quantity("force", K::kForce, "tooth load F, or a comma-separated sweep (30kN,35kN,40kN)") |
          ListOf{} | Required{"F, one value or a comma-separated sweep"},
      quantity("load_height", K::kLength, "L1, or a comma-separated sweep") | ListOf{} |
          Required{"L1 (from the lower outer joint's datum), one value or a sweep"},
  };
  a.check = check;
  a.variants = {
      {"rolling-hinge", {{{"hinge", "rolling"}}, {}}},
      {"sliding-hinge", {{{"hinge", "sliding"}}, {"plate_radius", "roller_radius"}}},
  };
  set_functions<WarpAnalysis>(a, warp_analysis_run, describe);
  return a;
}

}  // namespace

WarpAnalysis warp_analysis_run(const analysis::Inputs& in) {
  WarpAnalysis a;
  Warp& w = a.warp;
  const std::vector<double> z = four(in.list("heights")), c = four(in.list("clearances")),
                            k = four(in.list("stiffness")), b = four(in.list("widths"));
  for (std::size_t i = 0; i < 4; ++i) w.supports[i] = {z[i], c[i], k[i], b[i]};
  w.exponent = in.number("exponent");
  w.roller_diameter = in.number("pin_diameter");
  w.modulus = in.number("modulus");
  w.poisson = in.number("poisson");
  w.kind = in.text("hinge") == "rolling" ? HingeKind::kRolling : HingeKind::kSliding;
  if (w.kind == HingeKind::kRolling) {
    w.r1 = in.number("plate_radius");
    w.r2 = in.number("roller_radius");
  }
  const std::vector<double>& forces = in.list("force");
  const std::vector<double>& heights = in.list("load_height");
  std::vector<Issue> issues;
  for (double F : forces)
    for (double L : heights)
      for (auto& is : validate(w, {F, L})) {
        bool seen = false;
        for (const auto& e : issues) seen |= e.field == is.field && e.value == is.value;
        if (!seen) issues.push_back(is);
      }
  // the model's field names → the parameters' (shared with catena hinge)
  for (Issue& is : issues) {
    if (is.field == "roller_diameter") is.field = "pin_diameter";
    if (is.field == "r1") is.field = "plate_radius";
    if (is.field == "r2") is.field = "roller_radius";
  }
  throw_if_any(issues);
  std::map<std::string, std::pair<std::size_t, double>> worst;  // code → (index, value/limit)
  ProgressLoop loop(forces.size() * heights.size(), "points");
  for (double F : forces)
    for (double L : heights) {
      loop.step(a.points.size());
      const Load load{F, L};
      a.points.push_back({load, solve(w, load)});
      for (const Diagnostic& d : a.points.back().result.diagnostics) {
        const double excess = d.limit > 0.0 ? d.value / d.limit : d.value;
        const auto seen = worst.find(d.code);
        if (seen != worst.end()) {
          WarpAnalysis::Finding& f = a.findings[seen->second.first];
          ++f.points;
          if (!(excess > seen->second.second)) continue;
          seen->second.second = excess;
          f.diagnostic.value = d.value;
          f.diagnostic.limit = d.limit;
          f.load = load;
          continue;
        }
        worst[d.code] = {a.findings.size(), excess};
        a.findings.push_back({d, load, 1});
      }
    }
  loop.step(a.points.size());
  return a;
}

const analysis::Analysis& warp_analysis() {
  static const analysis::Analysis a = make();
  return a;
}

}  // namespace catena::warp
