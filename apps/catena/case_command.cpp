// catena run CASE / catena report [CASE]: one TOML case file describes a chain system; every
// analysis it names runs through the very subcommand a user would call (same flags, same
// validation, same JSON), and the results become one JSON tree or one HTML report.
//
// Adding a model to case files and reports: register its subcommand in register_analyses()
// and describe it in analysis_specs() (which chain types it applies to, its charts).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <regex>
#include <set>
#include <sstream>
#include <tuple>

#include "catena/io/case_file.hpp"
#include "catena/io/report.hpp"
#include "catena/io/sha256.hpp"
#include "cli_support.hpp"
#include "commands.hpp"

namespace catena::cli {

std::string_view plotly_js();          // embedded web/node_modules/plotly.js-dist-min/plotly.min.js
std::string_view default_case_toml();  // embedded examples/000_thesis_rolling_hinge.toml

namespace {

using nlohmann::ordered_json;

// ---------------------------------------------------------------------------------------------
// The registry

using ChartBuilder = std::function<void(const ordered_json& result, io::ReportSection& section)>;

struct AnalysisSpec {
  std::string name;                  ///< [analyses.<name>] in the case file
  std::vector<std::string> command;  ///< the subcommand path: {"hinge", "sweep"}
  std::string title;
  std::string docs;
  std::vector<std::string> chain_types;  ///< chain.type values it applies to
  std::set<std::string> not_shared;      ///< keys it must not take from the shared tables
  std::vector<std::string> extra_args;   ///< appended to the flags (e.g. a drawing to capture)
  ChartBuilder charts;
  /// Per chain type: flags the chain type implies (engagement: --hinge rolling) and shared keys
  /// that do not apply to it (a rolling hinge takes no sliding friction from [material]).
  struct ChainVariant {
    std::vector<std::string> args;
    std::set<std::string> not_shared;
  };
  std::map<std::string, ChainVariant> variants = {};
  /// The subcommand reads a table of the case file itself (loop: [loop] and [[loop.segment]]):
  /// the runner passes the case file's path as its positional argument.
  bool reads_case_file = false;
};

const std::vector<std::string> kChainTypes = {"rolling-hinge", "sliding-hinge", "roller-iso606",
                                              "round-link", "composite-link"};
// Shared tables: a key there goes to every analysis that has a flag of that name.
const std::vector<std::string> kSharedTables = {"chain", "sprocket", "loads", "material"};
// Keys of the shared tables that describe rather than feed a flag, and renamed keys.
const std::set<std::string> kDescriptive = {"chain.type", "chain.name", "chain.description"};
const std::map<std::string, std::string> kAliases = {{"chain.designation", "chain"}};
// Flags that choose output destinations: the case runner owns those.
const std::set<std::string> kOutputFlags = {"help", "format", "output", "csv",
                                            "svg",  "dxf",    "example"};

// Conversion of SI values to the units engineers read.
struct Display {
  std::string unit;
  double scale;
};
Display display(const std::string& si_unit) {
  static const std::map<std::string, Display> table = {{"m", {"mm", 1e3}},
                                                       {"m^2", {"mm²", 1e6}},
                                                       {"Pa", {"MPa", 1e-6}},
                                                       {"rad", {"°", 180.0 / std::numbers::pi}},
                                                       {"N/m", {"N/mm", 1e-3}},
                                                       {"1", {"", 1.0}},
                                                       {"1/arcmin^2", {"1/arcmin²", 1.0}}};
  const auto it = table.find(si_unit);
  return it == table.end() ? Display{si_unit, 1.0} : it->second;
}

std::vector<double> numbers(const ordered_json& array, double scale = 1.0) {
  std::vector<double> out;
  if (!array.is_array()) return out;
  for (const auto& v : array) out.push_back(v.is_number() ? v.get<double>() * scale : NAN);
  return out;
}

// Unit of a leaf key from the result's "units" object.
std::string unit_of(const ordered_json& result, const std::string& key) {
  if (result.contains("units") && result["units"].contains(key) && result["units"][key].is_string())
    return result["units"][key].get<std::string>();
  return "";
}

// A chart of y(x) for arrays inside `object` (x and y keys), in display units.
io::ReportChart series_chart(const ordered_json& result, const ordered_json& object,
                             const std::string& title, const std::string& x,
                             const std::vector<std::string>& ys, const std::string& y_label = "") {
  io::ReportChart chart;
  chart.title = title;
  const Display dx = display(unit_of(result, x));
  chart.x_label = x + (dx.unit.empty() ? "" : " [" + dx.unit + "]");
  std::string common_unit;
  for (const std::string& y : ys) {
    if (!object.contains(y)) continue;
    const Display dy = display(unit_of(result, y));
    common_unit = dy.unit;
    chart.traces.push_back({y, numbers(object[x], dx.scale), numbers(object[y], dy.scale)});
  }
  chart.y_label = (y_label.empty() ? (ys.size() == 1 ? ys[0] : std::string("value")) : y_label) +
                  (common_unit.empty() ? "" : " [" + common_unit + "]");
  return chart;
}

// Column `key` of an array of row objects.
ordered_json column(const ordered_json& rows, const std::string& key) {
  ordered_json out = ordered_json::array();
  for (const auto& row : rows) out.push_back(row.contains(key) ? row[key] : ordered_json());
  return out;
}

std::string format_value(const ordered_json& v, double scale);  // below, with the outputs

const std::vector<AnalysisSpec>& analysis_specs() {
  static const std::vector<AnalysisSpec> specs = {
      {"pocketwheel",
       {"pocketwheel"},
       "Round-link chain running onto a pocket wheel (seed 003)",
       "docs/models/pocketwheel.md",
       {"round-link"},
       {},
       {"--svg", "pocketwheel.svg"},
       [](const ordered_json& r, io::ReportSection& s) {
         if (!r.contains("series")) return;
         const ordered_json& series = r["series"];
         s.charts.push_back(
             series_chart(r, series, "Strand position over one tooth period", "phi", {"x"}));
         s.charts.push_back(
             series_chart(r, series, "Strand velocity", "phi", {"vx", "vy"}, "velocity"));
         s.charts.push_back(
             series_chart(r, series, "Strand acceleration", "phi", {"ax", "ay"}, "acceleration"));
         if (series.contains("inertial_force"))
           s.charts.push_back(series_chart(r, series, "Inertial force of the strand −M·a_x", "phi",
                                           {"inertial_force"}));
       }},
      {"hinge",
       {"hinge"},
       "Rolling-friction hinge: synthesis, kinematics, pitch change (seed 000 §1.2–1.3)",
       "docs/models/hinge.md",
       {"rolling-hinge"},
       {},
       {"--svg", "hinge.svg"},
       [](const ordered_json& r, io::ReportSection& s) {
         s.charts.push_back(series_chart(r, r["pitch_change"], "Pitch change over the roller turn",
                                         "phi", {"dt"}, "Δt"));
         const ordered_json& t = r["trajectories"];
         io::ReportChart paths;
         paths.title = "Contact point M1 and roller centre O2 (plate frame)";
         paths.x_label = "x [mm]";
         paths.y_label = "y [mm]";
         paths.equal_axes = true;
         paths.traces.push_back(
             {"contact point M1", numbers(t["M1x"], 1e3), numbers(t["M1y"], 1e3)});
         paths.traces.push_back(
             {"roller centre O2", numbers(t["O2x"], 1e3), numbers(t["O2y"], 1e3)});
         s.charts.push_back(paths);
       }},
      {"hinge_sweep",
       {"hinge", "sweep"},
       "Rolling-friction hinge: design sweep over R1 (seed 000 §1.2)",
       "docs/models/hinge.md",
       {"rolling-hinge"},
       {"plate_radius", "roller_radius", "pitch", "points", "clearance", "flat", "face_half_length",
        "loaded_length"},
       {},
       [](const ordered_json& r, io::ReportSection& s) {
         const ordered_json& rows = r["rows"];
         ordered_json table{{"R1", column(rows, "R1")},
                            {"contact_stress", column(rows, "contact_stress")},
                            {"rolling_limit", column(rows, "rolling_limit")},
                            {"max_pitch_change", column(rows, "max_pitch_change")}};
         s.charts.push_back(series_chart(r, table, "Hertz contact stress versus R1", "R1",
                                         {"contact_stress"}, "σH"));
         s.charts.push_back(series_chart(r, table, "Rolling limit versus R1", "R1",
                                         {"rolling_limit"}, "rolling limit"));
         s.charts.push_back(series_chart(r, table, "Largest pitch change versus R1", "R1",
                                         {"max_pitch_change"}, "|Δt|"));
       }},
      {"contact",
       {"contact"},
       "Roller–sprocket tooth contact with axis skew (seed 001)",
       "docs/models/contact.md",
       {"roller-iso606"},
       {},
       {},
       [](const ordered_json& r, io::ReportSection& s) {
         if (r.contains("slice_model")) {
           s.charts.push_back(series_chart(r, r["slice_model"]["distribution"],
                                           "Slice model: load along the roller", "s", {"q"}, "q"));
         } else if (r.contains("skew")) {  // a skew sweep
           io::ReportChart c = series_chart(r, r, "Contact stress versus skew", "skew",
                                            {"contact_stress", "slice_stress_peak"}, "stress");
           s.charts.push_back(c);
         }
       }},
      {"fretting",
       {"fretting"},
       "Fretting latent period of multi-strand chain joints (seed 001)",
       "docs/models/fretting.md",
       {"roller-iso606"},
       {},
       {},
       {}},
      {"engagement",
       {"engagement"},
       "Chain–sprocket engagement forces (seed 000 §1.6)",
       "docs/models/engagement.md",
       {"rolling-hinge", "sliding-hinge"},
       {},
       {},
       [](const ordered_json& r, io::ReportSection& s) {
         s.charts.push_back(series_chart(r, r["series"],
                                         "Link and tooth forces over the engagement", "gamma",
                                         {"F2", "FN"}, "force"));
         if (r.value("hinge", std::string()) == "rolling")
           s.charts.push_back(series_chart(r, r["series"], "Roller turn ξ over the engagement",
                                           "gamma", {"xi"}, "ξ"));
         if (r.contains("wrap") && r["wrap"].is_object()) {
           const ordered_json& w = r["wrap"];
           io::ReportChart c;
           c.title = "Tension before each seated roller around the sprocket";
           c.x_label = "roller k";
           c.y_label = "tension [" + unit_of(r, "tension") + "]";
           std::vector<double> k;
           for (std::size_t i = 0; i < w["tension"].size(); ++i) k.push_back(double(i));
           c.traces.push_back({"tension", k, numbers(w["tension"])});
           s.charts.push_back(c);
         }
       },
       {{"rolling-hinge",
         {{"--hinge", "rolling"},
          {"friction", "tooth_friction", "journal_diameter", "tooth_diameter"}}},
        {"sliding-hinge",
         {{"--hinge", "sliding"},
          {"pin_diameter", "half_thickness", "plate_radius", "roller_radius", "rolling_coefficient",
           "tooth_arm"}}}}},
      {"warp",
       {"warp"},
       "Roller warp: the roller on four plate joints with clearance (seed 000 §1.4)",
       "docs/models/warp.md",
       {"rolling-hinge", "sliding-hinge"},
       {},
       {},
       [](const ordered_json& r, io::ReportSection& s) {
         // one line per load F: the upper plates' share of the load versus its height L1
         std::map<double, std::pair<std::vector<double>, std::vector<double>>> by_force;
         for (const ordered_json& p : r["points"]) {
           auto& [x, y] = by_force[p["force"].get<double>()];
           x.push_back(p["load_height"].get<double>() * 1e3);
           y.push_back(p["upper_share"].is_number() ? p["upper_share"].get<double>() * 100 : NAN);
         }
         io::ReportChart c;
         c.title = "Share of the load on the upper plates versus the load height L1";
         c.x_label = "L1 [mm]";
         c.y_label = "upper share [%]";
         for (const auto& [force, xy] : by_force) {
           char name[48];
           std::snprintf(name, sizeof name, "F = %.4g kN", force * 1e-3);
           c.traces.push_back({name, xy.first, xy.second});
         }
         s.charts.push_back(c);
       },
       {{"rolling-hinge", {{"--hinge", "rolling"}, {}}},
        {"sliding-hinge", {{"--hinge", "sliding"}, {"plate_radius", "roller_radius"}}}}},
      {"strength",
       {"strength"},
       "Strength of the roller and plates: M and Q diagrams, safety factors (seed 000 §1.5)",
       "docs/models/strength.md",
       {"rolling-hinge", "sliding-hinge"},
       {},
       {},
       [](const ordered_json& r, io::ReportSection& s) {
         if (r.contains("checks") && r["checks"].is_array()) {
           io::ReportGrid grid{
               "Safety factors",
               {"check", "section", "stress [MPa]", "allowable [MPa]", "n", "required", "ok"},
               {},
               {}};
           for (const ordered_json& c : r["checks"]) {
             grid.rows.push_back({c.value("name", std::string()), c.value("section", std::string()),
                                  format_value(c["stress"], 1e-6),
                                  format_value(c["allowable"], 1e-6),
                                  format_value(c["safety_factor"], 1.0),
                                  format_value(c["required"], 1.0), format_value(c["ok"], 1.0)});
           }
           s.grids.push_back(std::move(grid));
         }
         if (!r.contains("diagrams") || !r["diagrams"].is_object()) return;
         const ordered_json& d = r["diagrams"];
         for (const auto& [key, title, unit, scale] :
              {std::tuple<const char*, const char*, const char*, double>{
                   "M", "Bending moment along the roller", "M [N·m]", 1.0},
               {"Q", "Shear force along the roller", "Q [kN]", 1e-3}}) {
           io::ReportChart c;
           c.title = title;
           c.x_label = "z [mm]";
           c.y_label = unit;
           for (auto it = d.begin(); it != d.end(); ++it) {
             // links at an angle: the resultant's magnitude
             std::string k = key;
             if (it.value().contains(k + "_resultant")) k += "_resultant";
             c.traces.push_back({it.key() + (k == key ? "" : " |" + std::string(key) + "|"),
                                 numbers(it.value()["x"], 1e3), numbers(it.value()[k], scale)});
           }
           s.charts.push_back(c);
         }
       },
       {{"rolling-hinge", {{"--hinge", "rolling"}, {}}},
        {"sliding-hinge", {{"--hinge", "sliding"}, {"plate_radius", "roller_radius"}}}}},
      {"ring",
       {"ring"},
       "Fibre-reinforced polymer link: orthotropic ring on two rigid half-discs (seed 002)",
       "docs/models/composite.md",
       {"composite-link"},
       {},
       {},
       [](const ordered_json& r, io::ReportSection& s) {
         // hoop stress across the two sections, and the contact pressure along the pin
         io::ReportChart c;
         c.title = "Hoop stress across the sections phi = 0 and phi = 90 deg";
         c.x_label = "r [mm]";
         c.y_label = "sigma_phi [MPa]";
         for (const char* key : {"0", "90"}) {
           const ordered_json& sec = r["sections"][key];
           std::vector<double> x, y;
           for (const auto& v : sec["r"]) x.push_back(v.get<double>() * 1e3);
           for (const auto& v : sec["sigma_phi"]) y.push_back(v.get<double>() * 1e-6);
           c.traces.push_back({std::string("phi = ") + key + " deg", x, y});
         }
         s.charts.push_back(c);
         io::ReportChart p;
         p.title = "Contact pressure on the pin";
         p.x_label = "phi [deg]";
         p.y_label = "pressure [MPa]";
         std::vector<double> x, y;
         for (const auto& v : r["contact"]["phi"]) x.push_back(v.get<double>() * 180.0 / M_PI);
         for (const auto& v : r["contact"]["pressure"]) y.push_back(v.get<double>() * 1e-6);
         p.traces.push_back({"pressure", x, y});
         s.charts.push_back(p);
       }},
      {"loop",
       {"loop"},
       "Conveyor loop: chain tension at every point by the contour method (seed 000 §1.5 fig. 19)",
       "docs/models/loop.md",
       kChainTypes,
       {},
       {},
       [](const ordered_json& r, io::ReportSection& s) {
         // tension along the path: a vertical step at each turn and over the drive sprocket
         io::ReportChart c;
         c.title = "Chain tension along the loop (from the drive sprocket's slack side)";
         c.x_label = "path length s [m]";
         c.y_label = "tension [kN]";
         std::vector<double> x, y;
         for (const ordered_json& p : r["points"]) {
           x.push_back(p["s"].get<double>());
           y.push_back(p["tension"].get<double>() * 1e-3);
         }
         c.traces.push_back({"tension", x, y});
         s.charts.push_back(c);
         io::ReportGrid grid{"Segments",
                             {"#", "name", "kind", "s start [m]", "s end [m]", "S in [kN]",
                              "S out [kN]", "ΔS [kN]"},
                             {},
                             {}};
         auto f = [](const ordered_json& v, double scale) {
           char b[32];
           std::snprintf(b, sizeof b, "%.5g", v.get<double>() * scale);
           return std::string(b);
         };
         for (const ordered_json& g : r["segments"])
           grid.rows.push_back({std::to_string(g["segment"].get<int>()),
                                g["name"].get<std::string>(), g["kind"].get<std::string>(),
                                f(g["s_start"], 1.0), f(g["s_end"], 1.0), f(g["tension_in"], 1e-3),
                                f(g["tension_out"], 1e-3), f(g["resistance"], 1e-3)});
         s.grids.push_back(std::move(grid));
       },
       {},
       true},
  };
  return specs;
}

// ---------------------------------------------------------------------------------------------
// Running the analyses of a case

struct AnalysisRun {
  const AnalysisSpec* spec;
  std::string name;  ///< the table's name: the spec's, or "<spec>-<label>" for one of several
  ordered_json result;
  std::vector<std::pair<std::string, std::string>> files;  // captured (flag, content)
};

struct CaseRun {
  io::CaseFile file;
  std::string hash;
  std::vector<AnalysisRun> runs;
};

// The options a subcommand path accepts, by case-file key (flag name with '_' for '-').
std::map<std::string, CLI::Option*> case_keys(CLI::App& app, const AnalysisSpec& spec) {
  std::map<std::string, CLI::Option*> keys;
  CLI::App* cmd = &app;
  for (const std::string& name : spec.command) {
    cmd = cmd->get_subcommand(name);
    for (CLI::Option* o : cmd->get_options()) {
      if (o->get_lnames().empty()) continue;
      std::string key = o->get_lnames().front();
      if (kOutputFlags.count(key)) continue;
      for (char& c : key) c = c == '-' ? '_' : c;
      keys[key] = o;
    }
  }
  if (spec.command.size() > 1) {
    for (const std::string& k : spec.not_shared) keys.erase(k);
  }
  // flags implied by chain.type (engagement's --hinge) are not the case file's to set
  for (const auto& [type, variant] : spec.variants) {
    for (const std::string& a : variant.args) {
      if (a.rfind("--", 0) != 0) continue;
      std::string key = a.substr(2);
      for (char& c : key) c = c == '-' ? '_' : c;
      keys.erase(key);
    }
  }
  return keys;
}

std::string default_unit_of(const CLI::Option* option) {
  static const std::regex bare(R"(bare(?: number)?: ([^;,)]+))");
  std::smatch m;
  const std::string& d = option->get_description();
  return std::regex_search(d, m, bare) ? m[1].str() : std::string();
}

CaseRun run_case(const io::CaseFile& file) {
  CaseRun out{file, io::sha256_hex(file.text), {}};
  std::vector<Issue> issues;
  const auto& specs = analysis_specs();

  // every key any analysis takes, for the shared tables and for suggestions
  CLI::App probe;
  register_analyses(probe);
  std::map<std::string, std::map<std::string, CLI::Option*>> keys_of;
  std::set<std::string> any_key;
  for (const AnalysisSpec& spec : specs) {
    keys_of[spec.name] = case_keys(probe, spec);
    for (const auto& [k, o] : keys_of[spec.name]) any_key.insert(k);
  }
  std::vector<std::string> spec_names;
  for (const AnalysisSpec& spec : specs) spec_names.push_back(spec.name);

  auto suggest = [](const std::string& word, const std::vector<std::string>& candidates) {
    const auto m = io::did_you_mean(word, candidates);
    return m ? " (did you mean '" + *m + "'?)" : std::string();
  };

  // the file's structure: top-level keys, shared tables, analyses
  const std::vector<std::string> top = {"title", "description", "chain",    "sprocket",
                                        "loads", "material",    "analyses", "loop"};
  for (const io::CaseValue& v : file.values) {
    const std::string head = v.path.substr(0, v.path.find('.'));
    if (std::find(top.begin(), top.end(), head) == top.end()) {
      issues.push_back({v.path, v.text,
                        "a known key: title, description, chain, sprocket, loads, "
                        "material, loop, analyses" +
                            suggest(head, top)});
    }
  }
  for (const std::string& t : file.tables) {
    const std::string head = t.substr(0, t.find('.'));
    if (std::find(top.begin(), top.end(), head) == top.end() && t.find('.') == std::string::npos)
      issues.push_back(
          {t, "(table)",
           "a known table: chain, sprocket, loads, material, loop, analyses" + suggest(head, top)});
  }
  const io::CaseValue* type = file.find("chain.type");
  std::string chain_type;
  if (!type) {
    issues.push_back({"chain.type", "(missing)",
                      "one of rolling-hinge, sliding-hinge, "
                      "roller-iso606, round-link, composite-link"});
  } else if (std::find(kChainTypes.begin(), kChainTypes.end(), type->text) == kChainTypes.end()) {
    issues.push_back({"chain.type", "'" + type->text + "'",
                      "one of rolling-hinge, sliding-hinge, roller-iso606, round-link, "
                      "composite-link" +
                          suggest(type->text, kChainTypes)});
  } else {
    chain_type = type->text;
  }

  // shared values: key → value; each must feed at least one analysis
  std::map<std::string, const io::CaseValue*> shared;
  std::vector<std::string> shared_candidates(any_key.begin(), any_key.end());
  for (const io::CaseValue& v : file.values) {
    const std::string head = v.path.substr(0, v.path.find('.'));
    if (std::find(kSharedTables.begin(), kSharedTables.end(), head) == kSharedTables.end())
      continue;
    if (kDescriptive.count(v.path)) continue;
    const std::string rest = v.path.substr(head.size() + 1);
    if (rest.find('.') != std::string::npos) {
      issues.push_back({v.path, v.text, "a value directly in [" + head + "]"});
      continue;
    }
    const auto alias = kAliases.find(v.path);
    const std::string key = alias != kAliases.end() ? alias->second : rest;
    if (!any_key.count(key)) {
      issues.push_back({v.path, v.text,
                        "a key some analysis takes" + suggest(rest, shared_candidates) +
                            " (docs/case_files.md lists them)"});
      continue;
    }
    if (shared.count(key)) {
      issues.push_back({v.path, v.text,
                        "one value per key: '" + key + "' is also given as " + shared[key]->path});
      continue;
    }
    shared[key] = &v;
  }

  // the analyses, in file order
  const std::vector<std::string> wanted = file.children("analyses");
  for (const io::CaseValue& v : file.values) {
    if (v.path.rfind("analyses.", 0) == 0 &&
        v.path.find('.', std::string("analyses.").size()) == std::string::npos)
      issues.push_back({v.path, v.text, "a table [" + v.path + "] of that analysis' options"});
  }
  if (wanted.empty() && file.find("analyses") == nullptr) {
    issues.push_back({"analyses", "(missing)",
                      "at least one [analyses.<name>] table; names: pocketwheel, hinge, "
                      "hinge_sweep, contact, fretting, engagement, warp, ring, loop, strength"});
  }
  struct Planned {
    const AnalysisSpec* spec;
    std::string name;
    std::vector<std::string> args;
    std::map<std::string, std::string> flag_to_path;
  };
  std::vector<Planned> planned;
  for (const std::string& name : wanted) {
    const auto it = std::find_if(specs.begin(), specs.end(), [&](const AnalysisSpec& s) {
      // "pocketwheel" or "pocketwheel-<label>": several runs of one
      // analysis, e.g. pocketwheel-free, pocketwheel-chordal
      return s.name == name || name.rfind(s.name + "-", 0) == 0;
    });
    if (it == specs.end()) {
      issues.push_back({"analyses." + name, "(table)",
                        "an analysis Catena has: pocketwheel, hinge, hinge_sweep, contact, "
                        "fretting, engagement, warp, ring, loop, strength" +
                            suggest(name, spec_names)});
      continue;
    }
    const AnalysisSpec& spec = *it;
    if (!chain_type.empty() && std::find(spec.chain_types.begin(), spec.chain_types.end(),
                                         chain_type) == spec.chain_types.end()) {
      std::string types;
      for (const auto& t : spec.chain_types) types += (types.empty() ? "" : ", ") + t;
      issues.push_back(
          {"analyses." + name, "(table)",
           "an analysis for chain.type = " + chain_type + "; '" + name + "' applies to " + types});
      continue;
    }
    const auto& keys = keys_of[spec.name];
    std::vector<std::string> key_names;
    for (const auto& [k, o] : keys) key_names.push_back(k);
    Planned p{&spec, name, {"catena"}, {}};
    for (const std::string& c : spec.command) p.args.push_back(c);
    std::map<std::string, const io::CaseValue*> given;
    const std::string prefix = "analyses." + name + ".";
    for (const io::CaseValue& v : file.values) {
      if (v.path.rfind(prefix, 0) != 0) continue;
      const std::string key = v.path.substr(prefix.size());
      if (kOutputFlags.count(key)) {
        issues.push_back({v.path, v.text,
                          "no output option in a case file: 'catena report' and "
                          "'catena run' choose the outputs"});
      } else if (!keys.count(key)) {
        issues.push_back({v.path, v.text,
                          "an option of '" + name + "'" + suggest(key, key_names) +
                              " (docs/cli.md lists them; '_' for '-')"});
      } else {
        given[key] = &v;
      }
    }
    const auto variant = spec.variants.find(chain_type);
    const AnalysisSpec::ChainVariant* chain_variant =
        variant == spec.variants.end() ? nullptr : &variant->second;
    for (const auto& [key, v] : shared) {
      if (keys.count(key) && !given.count(key) && !spec.not_shared.count(key) &&
          !(chain_variant && chain_variant->not_shared.count(key)))
        given[key] = v;
    }
    for (const auto& [key, v] : given) {
      const CLI::Option* option = keys.at(key);
      const std::string flag = "--" + option->get_lnames().front();
      p.flag_to_path[flag] = v->path;
      const bool is_flag = option->get_expected_max() == 0;  // a flag takes no value
      if (is_flag) {
        if (v->type != io::CaseValue::Type::kBoolean) {
          issues.push_back({v->path, v->text, "true or false"});
        } else if (v->text == "true") {
          p.args.push_back(flag);
        }
      } else if (v->type == io::CaseValue::Type::kBoolean ||
                 v->type == io::CaseValue::Type::kOther) {
        const std::string unit = default_unit_of(option);
        issues.push_back({v->path, v->text,
                          "a number or a string with a unit" +
                              (unit.empty() ? std::string() : " (bare number: " + unit + ")")});
      } else {
        p.args.push_back(flag);
        p.args.push_back(v->text);
      }
    }
    for (const std::string& a : spec.extra_args) p.args.push_back(a);
    if (spec.reads_case_file) p.args.push_back(file.name);
    if (chain_variant)
      for (const std::string& a : chain_variant->args) p.args.push_back(a);
    p.args.push_back("--format");
    p.args.push_back("json");
    planned.push_back(std::move(p));
  }
  // no stop here: the analyses that could be planned run too, so that a misspelt key and a
  // wrong unit elsewhere are reported together

  // run each through its own subcommand, collecting every analysis' input errors
  for (const Planned& p : planned) {
    CLI::App app;
    const auto actions = register_analyses(app);
    std::vector<const char*> argv;
    for (const std::string& a : p.args) argv.push_back(a.c_str());
    const std::string where = "analyses." + p.name;
    try {
      app.parse(static_cast<int>(argv.size()), argv.data());
      Capture capture;
      actions.at(p.spec->command.front())();
      AnalysisRun run{p.spec, p.name, ordered_json::parse(capture.stdout_text),
                      std::move(capture.files)};
      out.runs.push_back(std::move(run));
    } catch (const CLI::ParseError& e) {
      issues.push_back({where, "(options)", std::string("valid options: ") + e.what()});
    } catch (const InputError& e) {
      const auto& keys = keys_of[p.spec->name];
      for (Issue issue : e.issues()) {
        if (p.spec->reads_case_file && issue.field.rfind("--", 0) != 0) {
          issues.push_back(std::move(issue));  // it names the case file's own path and line
          continue;
        }
        // name the case-file path the value came from, or where a missing one belongs
        std::string key = issue.field.rfind("--", 0) == 0 ? issue.field.substr(2) : "";
        for (char& c : key) c = c == '-' ? '_' : c;
        const auto path = p.flag_to_path.find(issue.field);
        if (path != p.flag_to_path.end()) {
          issue.field = path->second;
        } else if (!key.empty() && keys.count(key)) {
          issue.field = where + "." + key;
        } else {
          issue.field = where + " (" + issue.field + ")";
        }
        issues.push_back(std::move(issue));
      }
    }
  }
  throw_if_any(issues);
  return out;
}

// ---------------------------------------------------------------------------------------------
// Outputs

ordered_json result_tree(const CaseRun& run) {
  ordered_json j;
  j["catena_version"] = CATENA_VERSION;
  j["case"] = run.file.name;
  j["case_sha256"] = run.hash;
  const io::CaseValue* title = run.file.find("title");
  j["title"] = title ? title->text : run.file.name;
  ordered_json analyses = ordered_json::object();
  for (const AnalysisRun& r : run.runs) analyses[r.name] = r.result;
  j["analyses"] = analyses;
  return j;
}

std::string format_value(const ordered_json& v, double scale) {
  if (v.is_number()) {
    char b[64];
    std::snprintf(b, sizeof b, "%.6g", v.get<double>() * scale);
    return b;
  }
  if (v.is_boolean()) return v.get<bool>() ? "yes" : "no";
  if (v.is_null()) return "—";
  if (v.is_string()) return v.get<std::string>();
  return v.dump();
}

// The scalars of a result (nested objects with dotted names), in display units.
void scalar_rows(const ordered_json& result, const ordered_json& object, const std::string& prefix,
                 std::vector<io::ReportRow>& rows) {
  static const std::set<std::string> skip = {"model", "source", "units", "diagnostics"};
  for (auto it = object.begin(); it != object.end(); ++it) {
    if (skip.count(it.key())) continue;
    const ordered_json& v = it.value();
    if (v.is_object()) {
      scalar_rows(result, v, prefix + it.key() + ".", rows);
    } else if (!v.is_array()) {
      const Display d = display(unit_of(result, it.key()));
      rows.push_back({prefix + it.key(), format_value(v, v.is_number() ? d.scale : 1.0), d.unit});
    } else if (v.size() <= 4 && !v.empty() && v[0].is_number()) {  // short vectors: list them
      const Display d = display(unit_of(result, it.key()));
      std::string text;
      for (const auto& e : v) text += (text.empty() ? "" : ", ") + format_value(e, d.scale);
      rows.push_back({prefix + it.key(), text, d.unit});
    }
  }
}

io::Report build_report(const CaseRun& run) {
  io::Report report;
  const io::CaseValue* title = run.file.find("title");
  report.title = title ? title->text : "Catena case " + run.file.name;
  report.case_name = run.file.name;
  report.case_hash = run.hash;
  report.version = CATENA_VERSION;
  CLI::App probe;
  register_analyses(probe);
  for (const io::CaseValue& v : run.file.values) {
    std::string unit;
    if (v.type == io::CaseValue::Type::kNumber && v.path.rfind("loop.", 0) == 0) {
      unit = loop_bare_unit(v.path);
    } else if (v.type == io::CaseValue::Type::kNumber) {
      // a bare number: name the default unit of the flag it feeds
      const std::string key = v.path.substr(v.path.rfind('.') + 1);
      for (const AnalysisSpec& spec : analysis_specs()) {
        const auto keys = case_keys(probe, spec);
        const auto alias = kAliases.find(v.path);
        const auto k = keys.find(alias != kAliases.end() ? alias->second : key);
        if (k != keys.end() && unit.empty()) unit = default_unit_of(k->second);
      }
    }
    report.inputs.push_back({v.path, v.text, unit});
  }
  for (const AnalysisRun& r : run.runs) {
    io::ReportSection s;
    s.id = r.name;
    s.title = r.spec->title;
    if (r.name != r.spec->name) s.title += " — " + r.name.substr(r.spec->name.size() + 1);
    s.docs = r.spec->docs;
    const ordered_json& j = r.result;
    s.source = j.value("source", std::string("see ") + r.spec->docs);
    if (j.contains("diagnostics")) {
      for (const auto& d : j["diagnostics"]) {
        io::ReportDiagnostic rd;
        rd.severity = d.value("severity", std::string("warning"));
        if (rd.severity == "infeasible") rd.severity = "error";
        rd.message = d.value("message", std::string());
        if (d.contains("limit") && d["limit"].is_number())
          rd.limit = format_value(d["limit"], 1.0) + " in SI units (m, rad, Pa, N)";
        s.diagnostics.push_back(rd);
      }
    }
    io::ReportTable results{"Results", {}};
    scalar_rows(j, j, "", results.rows);
    if (j.contains("rows") && j["rows"].is_array() && !j["rows"].empty()) {
      // a sweep: one grid row per design, the best one highlighted
      const ordered_json& rows = j["rows"];
      io::ReportGrid grid{"Designs", {}, {}, {}};
      for (auto it = rows[0].begin(); it != rows[0].end(); ++it) {
        const Display d = display(unit_of(j, it.key()));
        grid.columns.push_back(it.key() + (d.unit.empty() ? "" : " [" + d.unit + "]"));
      }
      const std::size_t best = j.contains("best") && j["best"].is_number_unsigned()
                                   ? j["best"].get<std::size_t>()
                                   : rows.size();
      for (std::size_t i = 0; i < rows.size(); ++i) {
        std::vector<std::string> cells;
        for (auto it = rows[i].begin(); it != rows[i].end(); ++it) {
          const Display d = display(unit_of(j, it.key()));
          cells.push_back(format_value(it.value(), it.value().is_number() ? d.scale : 1.0));
        }
        grid.rows.push_back(std::move(cells));
        grid.highlighted.push_back(i == best);
      }
      s.grids.push_back(std::move(grid));
    }
    s.tables.push_back(results);
    if (r.spec->charts) r.spec->charts(j, s);
    for (const auto& [flag, content] : r.files) {
      if (flag == "--svg") s.drawings_svg.push_back(content);
    }
    report.sections.push_back(std::move(s));
  }
  return report;
}

io::CaseFile load(const std::string& path) {
  if (path.empty())
    return io::parse_case(default_case_toml(), "built-in:000_thesis_rolling_hinge.toml");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError({{"CASE", path, "a readable TOML case file"}});
  std::stringstream text;
  text << in.rdbuf();
  return io::parse_case(text.str(), path);
}

struct CaseFlags {
  std::string path, output, format = "html";
};

}  // namespace

std::map<std::string, std::function<int()>> register_analyses(CLI::App& app) {
  return {{"pocketwheel", add_pocketwheel(app)},
          {"hinge", add_hinge(app)},
          {"contact", add_contact(app)},
          {"fretting", add_fretting(app)},
          {"warp", add_warp(app)},
          {"engagement", add_engagement(app)},
          {"ring", add_ring(app)},
          {"loop", add_loop(app)},
          {"strength", add_strength(app)}};
}

std::function<int()> add_run(CLI::App& app) {
  auto f = std::make_shared<CaseFlags>();
  CLI::App* c = app.add_subcommand(
      "run", "Run every analysis of a case file; print the JSON result tree (SI, with units)");
  c->add_option("CASE", f->path, "TOML case file (docs/case_files.md)")->required();
  c->add_option("-o,--output", f->output, "write the JSON to FILE instead of stdout");
  return [f]() {
    const CaseRun run = run_case(load(f->path));
    const std::string text = result_tree(run).dump(2) + "\n";
    write_text_output(f->output, text);
    return 0;
  };
}

std::function<int()> add_report(CLI::App& app) {
  auto f = std::make_shared<CaseFlags>();
  CLI::App* c = app.add_subcommand(
      "report",
      "Run a case file and write one self-contained HTML report (no CASE: the built-in thesis "
      "rolling-hinge conveyor chain)");
  c->add_option("CASE", f->path, "TOML case file (docs/case_files.md); default: built-in case");
  c->add_option("-o,--output", f->output, "the report file (default report.html; json: stdout)");
  c->add_option("--format", f->format, "html (default) or json (the whole result tree)")
      ->check(CLI::IsMember({"html", "json"}));
  return [f]() {
    const CaseRun run = run_case(load(f->path));
    Outputs outputs;
    if (f->format == "json") {
      const std::string text = result_tree(run).dump(2) + "\n";
      if (!f->output.empty()) outputs.add("--output", f->output, text);
      outputs.commit(f->output.empty() ? text : "");
      return 0;
    }
    const std::string path = f->output.empty() ? "report.html" : f->output;
    outputs.add("--output", path, io::to_html(build_report(run), plotly_js()));
    outputs.commit();
    std::cerr << "catena: wrote " << path << " (" << run.runs.size()
              << (run.runs.size() == 1 ? " analysis)\n" : " analyses)\n");
    return 0;
  };
}

}  // namespace catena::cli
