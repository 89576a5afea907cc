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

#include "catena/catena.hpp"
#include "catena/io/bind.hpp"
#include "catena/io/case_file.hpp"
#include "catena/io/record.hpp"
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
  const AnalysisSpec* spec;  ///< a subcommand not yet on the analysis interface, or nullptr
  std::string name;  ///< the table's name: the spec's, or "<spec>-<label>" for one of several
  ordered_json result;
  std::vector<std::pair<std::string, std::string>> files;  // captured (flag, content)
  const analysis::Analysis* analysis = nullptr;            ///< an analysis of the registry
  analysis::Record record;                                 ///< its record
};

// The registry analysis a case table names ("pocketwheel" or "pocketwheel-<label>").
const analysis::Analysis* registry_analysis(const std::string& name) {
  for (const analysis::Analysis* a : catena::analyses()) {
    if (a->name == name || name.rfind(a->name + "-", 0) == 0) return a;
  }
  return nullptr;
}

io::RawInput::Type raw_type(io::CaseValue::Type type) {
  switch (type) {
    case io::CaseValue::Type::kString:
      return io::RawInput::Type::kText;
    case io::CaseValue::Type::kNumber:
      return io::RawInput::Type::kNumber;
    case io::CaseValue::Type::kBoolean:
      return io::RawInput::Type::kBoolean;
    case io::CaseValue::Type::kOther:
      break;
  }
  return io::RawInput::Type::kOther;
}

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
  for (const analysis::Analysis* a : catena::analyses()) {
    for (const analysis::Parameter& p : a->parameters) {
      if (!p.cli_only) any_key.insert(p.name);
    }
  }
  std::vector<std::string> spec_names;
  for (const analysis::Analysis* a : catena::analyses()) spec_names.push_back(a->name);
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
    const analysis::Analysis* analysis = nullptr;
    std::vector<io::RawInput> raw;
  };
  std::vector<Planned> planned;
  for (const std::string& name : wanted) {
    if (const analysis::Analysis* a = registry_analysis(name)) {
      if (!chain_type.empty() && std::find(a->chain_types.begin(), a->chain_types.end(),
                                           chain_type) == a->chain_types.end()) {
        std::string types;
        for (const auto& t : a->chain_types) types += (types.empty() ? "" : ", ") + t;
        issues.push_back({"analyses." + name, "(table)",
                          "an analysis for chain.type = " + chain_type + "; '" + name +
                              "' applies to " + types});
        continue;
      }
      std::vector<std::string> key_names;
      for (const analysis::Parameter& p : a->parameters) {
        if (!p.cli_only && !kOutputFlags.count(p.name)) key_names.push_back(p.name);
      }
      Planned p{nullptr, name, {}, {}, a, {}};
      std::map<std::string, const io::CaseValue*> given;
      const std::string prefix = "analyses." + name + ".";
      for (const io::CaseValue& v : file.values) {
        if (v.path.rfind(prefix, 0) != 0) continue;
        const std::string key = v.path.substr(prefix.size());
        const analysis::Parameter* param = a->parameter(key);
        if (kOutputFlags.count(key)) {
          issues.push_back({v.path, v.text,
                            "no output option in a case file: 'catena report' and "
                            "'catena run' choose the outputs"});
        } else if (!param || param->cli_only) {
          issues.push_back({v.path, v.text,
                            "an option of '" + name + "'" + suggest(key, key_names) +
                                " (docs/cli.md lists them; '_' for '-')"});
        } else {
          given[key] = &v;
        }
      }
      const analysis::Analysis::Variant* variant = nullptr;
      for (const auto& [variant_type, v] : a->variants) {
        if (variant_type == chain_type) variant = &v;
      }
      for (const auto& [key, v] : shared) {
        const analysis::Parameter* param = a->parameter(key);
        const bool excluded =
            variant && std::find(variant->not_shared.begin(), variant->not_shared.end(), key) !=
                           variant->not_shared.end();
        if (param && !param->cli_only && !param->not_shared && !given.count(key) && !excluded)
          given[key] = v;
      }
      for (const auto& [key, v] : given) {
        p.flag_to_path[key] = v->path;
        p.raw.push_back({key, v->text, raw_type(v->type), {}, {}});
      }
      if (variant) {
        for (const auto& [key, value] : variant->set) {
          const analysis::Parameter* param = a->parameter(key);
          const bool is_flag = param && param->type == analysis::ParameterType::kFlag;
          p.raw.push_back({key,
                           value,
                           is_flag ? io::RawInput::Type::kBoolean : io::RawInput::Type::kText,
                           {},
                           {}});
        }
      }
      planned.push_back(std::move(p));
      continue;
    }
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
    if (p.analysis) {
      const std::string where = "analyses." + p.name;
      std::vector<Issue> found;
      const analysis::Inputs inputs = io::bind(*p.analysis, p.raw, found);
      AnalysisRun run{nullptr, p.name, {}, {}, p.analysis, {}};
      if (found.empty()) {
        try {
          run.record = p.analysis->evaluate(inputs);
          run.result = ordered_json::parse(io::to_json(run.record.data, -1));
          out.runs.push_back(std::move(run));
        } catch (const InputError& e) {
          found = e.issues();
        }
      }
      for (Issue issue : found) {
        // name the case-file path the value came from, or where a missing one belongs
        const auto path = p.flag_to_path.find(issue.field);
        if (path != p.flag_to_path.end()) {
          issue.field = path->second;
        } else if (p.analysis->parameter(issue.field)) {
          issue.field = where + "." + issue.field;
        } else {
          issue.field = where + " (" + issue.field + ")";
        }
        issues.push_back(std::move(issue));
      }
      continue;
    }
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
      const auto alias_key = kAliases.find(v.path);
      const std::string parameter_key = alias_key != kAliases.end() ? alias_key->second : key;
      for (const analysis::Analysis* a : catena::analyses()) {
        const analysis::Parameter* p = a->parameter(parameter_key);
        if (p && unit.empty()) unit = io::bare_unit(*p);
      }
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
    const std::string& base = r.analysis ? r.analysis->name : r.spec->name;
    std::string section_title = r.analysis ? r.analysis->title : r.spec->title;
    if (r.name != base) section_title += " — " + r.name.substr(base.size() + 1);
    const std::string& docs = r.analysis ? r.analysis->docs : r.spec->docs;
    if (r.analysis) {
      report.sections.push_back(io::report_section(r.record, r.name, section_title, docs));
      continue;
    }
    // a subcommand not yet on the analysis interface: its JSON, charts and captured drawing
    analysis::Record record;
    record.data = io::parse_json(r.result.dump());
    for (const analysis::Value& d : record.data.at("diagnostics").is_array()
                                        ? record.data.at("diagnostics").as_array()
                                        : analysis::Value::Array{}) {
      Diagnostic diagnostic;
      const std::string severity =
          d.at("severity").is_string() ? d.at("severity").as_string() : "warning";
      diagnostic.severity = severity == "infeasible" ? Diagnostic::Severity::kInfeasible
                            : severity == "info"     ? Diagnostic::Severity::kInfo
                                                     : Diagnostic::Severity::kWarning;
      diagnostic.message = d.at("message").is_string() ? d.at("message").as_string() : "";
      diagnostic.limit = d.at("limit").is_number() ? d.at("limit").as_number() : NAN;
      record.diagnostics.push_back(diagnostic);
    }
    io::ReportSection s = io::report_section(record, r.name, section_title, docs);
    if (r.spec->charts) r.spec->charts(r.result, s);
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
  std::map<std::string, std::function<int()>> actions = {
      {"hinge", add_hinge(app)},           {"contact", add_contact(app)},
      {"fretting", add_fretting(app)},     {"warp", add_warp(app)},
      {"engagement", add_engagement(app)}, {"loop", add_loop(app)},
      {"strength", add_strength(app)}};
  // the analyses of the registry; one below another (hinge sweep) runs when its own name was
  // parsed, else its parent's action
  std::map<std::string, std::vector<std::pair<CLI::App*, std::function<int()>>>> children;
  for (const analysis::Analysis* a : catena::analyses()) {
    if (a->command.size() == 1) {
      actions[a->command.front()] = add_analysis(app, *a);
    } else {
      std::function<int()> action = add_analysis(app, *a);
      CLI::App* sub = app.get_subcommand(a->command.front());
      for (std::size_t i = 1; i < a->command.size(); ++i) sub = sub->get_subcommand(a->command[i]);
      children[a->command.front()].push_back({sub, std::move(action)});
    }
  }
  for (auto& [name, subs] : children) {
    actions[name] = [own = actions[name], subs = subs]() {
      for (const auto& [sub, action] : subs) {
        if (sub->parsed()) return action();
      }
      return own();
    };
  }
  return actions;
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
