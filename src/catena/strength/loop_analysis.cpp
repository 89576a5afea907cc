// `loop` — conveyor loop tensions by the contour method (seed 000 §1.5, fig. 19) — as an
// analysis. Its input is the [loop] table with [[loop.segment]] elements: the schema of case
// files, so `catena loop case.toml` reads a case file's loop and ignores the rest.
#include "catena/strength/loop_analysis.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "catena/io/bind.hpp"
#include "catena/io/case_file.hpp"
#include "catena/io/quantity.hpp"

namespace catena::strength {
namespace {

using analysis::format_g;
using analysis::InputValue;
using analysis::Parameter;
using analysis::ParameterType;
using analysis::Record;
using analysis::Value;
using Entry = analysis::InputValue::Entry;
using K = QuantityKind;

// The keys of [loop] and of each [[loop.segment]], with the unit a bare number takes.
std::vector<Parameter> loop_fields() {
  using analysis::number;
  using analysis::quantity;
  using analysis::text;
  return {quantity("speed", K::kSpeed, "chain speed v"),
          number("efficiency", "drive efficiency eta in (0, 1]"),
          quantity("min_tension", K::kForce, "smallest tension the chain must keep"),
          quantity("allowable_tension", K::kForce, "largest tension the chain may carry"),
          text("name", "the loop's name")};
}

std::vector<Parameter> segment_fields() {
  using analysis::number;
  using analysis::quantity;
  using analysis::text;
  Parameter length = quantity("length", K::kLength, "the run's length L along its slope");
  length.bare_unit = "m";  // conveyor runs are metres long, not the mm of chain geometry
  return {text("kind", "straight, turn, takeup or drive"),
          text("name", "the segment's name"),
          length,
          quantity("incline", K::kAngle, "the run's incline beta (rising in the travel direction)"),
          quantity("chain_weight", K::kForcePerLength, "the chain's weight per metre q0"),
          quantity("load_weight", K::kForcePerLength, "the load's weight per metre q"),
          number("resistance", "running resistance factor w of a straight run"),
          number("factor", "turn: tension ratio k = S_out/S_in >= 1"),
          quantity("wrap", K::kAngle, "turn: wrap angle alpha (with friction, k = exp(f alpha))"),
          number("friction", "turn: friction coefficient f"),
          quantity("pretension", K::kForce, "take-up: pretension S0"),
          number("loss", "drive: tension lost over the drive sprocket, as a share")};
}

const analysis::Parameter& table_parameter() { return loop_table_parameter(); }

std::map<std::string, const Parameter*> keys_of(const std::vector<Parameter>& fields) {
  std::map<std::string, const Parameter*> keys;
  for (const Parameter& p : fields) keys[p.name] = &p;
  return keys;
}

const std::map<std::string, const Parameter*>& loop_keys() {
  static const auto keys = keys_of(table_parameter().fields);
  return keys;
}

const std::map<std::string, const Parameter*>& segment_keys() {
  static const auto keys = keys_of(table_parameter().row_fields);
  return keys;
}

// The keys each kind takes (besides kind and name).
const std::map<std::string, std::vector<std::string>>& kind_keys() {
  static const std::map<std::string, std::vector<std::string>> keys = {
      {"straight", {"length", "incline", "chain_weight", "load_weight", "resistance"}},
      {"turn", {"factor", "wrap", "friction"}},
      {"takeup", {"pretension"}},
      {"drive", {"loss"}},
  };
  return keys;
}

std::string where(const Entry& v) { return v.path + " (line " + std::to_string(v.line) + ")"; }

// Reads one value as SI; appends an issue naming the path and line on failure.
std::optional<double> read(const Entry& v, const Parameter& key, std::vector<Issue>& issues) {
  if (!v.is_string && !v.is_number) {
    issues.push_back({where(v), v.text, "a number or a string"});
    return std::nullopt;
  }
  if (key.type == ParameterType::kNumber) {
    std::vector<Issue> found;
    const auto x = io::parse_number(v.text, where(v), "a plain (dimensionless) number", found);
    issues.insert(issues.end(), found.begin(), found.end());
    return x;
  }
  // a bare number (a TOML number, or a string holding only a number: "20") takes the key's
  // documented unit, which for lengths (m) is not the kind's default (mm)
  const std::string bare_unit = io::bare_unit(key);
  const bool bare = v.is_number || io::is_bare_number(v.text);
  const std::string text = bare ? v.text + " " + bare_unit : v.text;
  std::vector<Issue> found;
  const auto x = io::parse_quantity(text, key.kind, where(v), found);
  for (Issue& i : found) {
    i.value = "'" + v.text + "'";
    if (bare_unit != io::default_unit(key.kind))
      i.expected += "; here a bare number is in " + bare_unit;
    issues.push_back(std::move(i));
  }
  return x;
}

struct Parsed {
  Loop loop;
  std::string name;
  bool has_name = false;
  std::vector<int> segment_lines;    ///< line of each segment's first value (0: none)
  std::map<std::string, int> lines;  ///< loop-relative field ("segment[2].length") → line
};

Parsed parse_loop(const InputValue& file) {
  Parsed out;
  std::vector<Issue> issues;
  const bool has_loop =
      std::find(file.tables.begin(), file.tables.end(), "loop") != file.tables.end();
  if (!has_loop) {
    throw InputError({{"loop", "(missing)",
                       "a [loop] table (speed, efficiency) and its segments as [[loop.segment]] "
                       "tables (docs/models/loop.md)"}});
  }
  // the segments: tables loop.segment[i]
  std::size_t count = 0;
  static const std::regex element(R"(^loop\.segment\[(\d+)\]$)");
  for (const std::string& t : file.tables) {
    std::smatch m;
    if (std::regex_match(t, m, element)) count = std::max<std::size_t>(count, std::stoul(m[1]) + 1);
  }
  out.loop.segments.resize(count);
  out.segment_lines.assign(count, 0);
  std::vector<const Entry*> kinds(count, nullptr);
  std::vector<bool> kind_ok(count, false);  // the segment's kind was read
  std::vector<std::map<std::string, const Entry*>> given(count);

  std::vector<std::string> loop_names, segment_names;
  for (const auto& [k, key] : loop_keys()) loop_names.push_back(k);
  loop_names.push_back("segment");
  for (const auto& [k, key] : segment_keys()) segment_names.push_back(k);
  auto suggest = [](const std::string& word, const std::vector<std::string>& candidates) {
    const auto m = io::did_you_mean(word, candidates);
    return m ? " (did you mean '" + *m + "'?)" : std::string();
  };

  static const std::regex segment_value(R"(^loop\.segment\[(\d+)\]\.([^.]+)$)");
  for (const Entry& v : file.table) {
    if (v.path.rfind("loop.", 0) != 0) continue;  // the rest of a case file is not ours
    std::smatch m;
    if (std::regex_match(v.path, m, segment_value)) {
      const std::size_t i = std::stoul(m[1]);
      const std::string key = m[2];
      if (out.segment_lines[i] == 0) out.segment_lines[i] = v.line;
      out.lines["segment[" + std::to_string(i) + "]." + key] = v.line;
      if (!segment_keys().count(key)) {
        issues.push_back({where(v), v.text,
                          "a key of a loop segment" + suggest(key, segment_names) +
                              ": kind, name, length, incline, chain_weight, load_weight, "
                              "resistance, factor, wrap, friction, pretension, loss"});
        continue;
      }
      if (key == "kind") kinds[i] = &v;
      given[i][key] = &v;
      continue;
    }
    const std::string key = v.path.substr(5);
    if (key.rfind("segment", 0) == 0) {
      issues.push_back({where(v), v.text,
                        "segments as an array of tables: [[loop.segment]] (double brackets), one "
                        "per segment"});
      continue;
    }
    const auto k = loop_keys().find(key);
    if (k == loop_keys().end()) {
      issues.push_back({where(v), v.text,
                        "a key of [loop]" + suggest(key, loop_names) +
                            ": speed, efficiency, min_tension, allowable_tension, name, and "
                            "[[loop.segment]] tables"});
      continue;
    }
    out.lines[key] = v.line;
    if (key == "name") {
      out.name = v.text;
      out.has_name = true;
      continue;
    }
    const auto x = read(v, *k->second, issues);
    if (!x) continue;
    if (key == "speed") out.loop.speed = *x;
    if (key == "efficiency") out.loop.efficiency = *x;
    if (key == "min_tension") out.loop.min_tension = *x;
    if (key == "allowable_tension") out.loop.allowable_tension = *x;
  }
  if (!out.lines.count("speed"))
    issues.push_back({"loop.speed", "(missing)", "the chain speed v, e.g. \"0.5 m/s\""});
  if (!out.lines.count("efficiency"))
    issues.push_back(
        {"loop.efficiency", "(missing)", "the drive efficiency η in (0, 1], e.g. 0.85"});

  std::vector<std::string> kind_names;
  for (const auto& [k, keys] : kind_keys()) kind_names.push_back(k);
  for (std::size_t i = 0; i < count; ++i) {
    Segment& s = out.loop.segments[i];
    const std::string base = "loop.segment[" + std::to_string(i) + "]";
    const std::string at =
        out.segment_lines[i] ? " (line " + std::to_string(out.segment_lines[i]) + ")" : "";
    if (!kinds[i]) {
      issues.push_back({base + ".kind" + at, "(missing)",
                        "the segment's kind: straight, turn, takeup or drive"});
      continue;
    }
    const std::string kind = kinds[i]->text;
    const auto kk = kind_keys().find(kind);
    if (!kinds[i]->is_string || kk == kind_keys().end()) {
      issues.push_back({where(*kinds[i]), "'" + kind + "'",
                        "straight, turn, takeup or drive" + suggest(kind, kind_names)});
      continue;
    }
    kind_ok[i] = true;
    s.kind = kind == "straight" ? SegmentKind::kStraight
             : kind == "turn"   ? SegmentKind::kTurn
             : kind == "takeup" ? SegmentKind::kTakeup
                                : SegmentKind::kDrive;
    const std::vector<std::string>& allowed = kk->second;
    for (const auto& [key, v] : given[i]) {
      if (key == "kind") continue;
      if (key == "name") {
        s.name = v->text;
        continue;
      }
      if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
        std::string list;
        for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
        issues.push_back({where(*v), v->text, "a key of a " + kind + " segment: " + list});
        continue;
      }
      const auto x = read(*v, *segment_keys().at(key), issues);
      if (!x) continue;
      if (key == "length") s.length = *x;
      if (key == "incline") s.incline = *x;
      if (key == "chain_weight") s.chain_weight = *x;
      if (key == "load_weight") s.load_weight = *x;
      if (key == "resistance") s.resistance = *x;
      if (key == "factor") s.factor = *x;
      if (key == "wrap") s.wrap = *x;
      if (key == "friction") s.friction = *x;
      if (key == "pretension") s.pretension = *x;
      if (key == "loss") s.loss = *x;
    }
    // required keys (no default that would hide an omission; incline 0, load 0, loss 0 default)
    auto require = [&](const char* key, const char* what) {
      if (!given[i].count(key)) issues.push_back({base + "." + key + at, "(missing)", what});
    };
    if (s.kind == SegmentKind::kStraight) {
      require("length", "the run's length L along its slope, e.g. \"30 m\" (bare: m)");
      require("chain_weight", "the chain's weight per metre q0, e.g. \"150 N/m\" (bare: N/m)");
      require("resistance", "the running resistance factor w of the run, e.g. 0.1");
    }
    if (s.kind == SegmentKind::kTakeup)
      require("pretension", "the take-up's pretension S0, e.g. \"2 kN\" (bare: N)");
  }

  // the model's own checks, renamed to the file's paths and lines; only those not already found
  // while reading (a value that failed to parse is left at its default)
  std::set<std::string> reported;
  for (const Issue& i : issues) reported.insert(i.field.substr(0, i.field.find(' ')));
  for (Issue i : validate(out.loop)) {
    if (i.field == "segments") {
      i.field = "loop.segment";
    } else {
      const auto line = out.lines.find(i.field);
      const std::string path = "loop." + i.field;
      if (reported.count(path)) continue;
      if (line != out.lines.end()) {
        i.field = path + " (line " + std::to_string(line->second) + ")";
      } else {
        // a missing value: the segment's line
        static const std::regex index(R"(^segment\[(\d+)\])");
        std::smatch m;
        int l = 0;
        if (std::regex_search(i.field, m, index)) l = out.segment_lines.at(std::stoul(m[1]));
        i.field = path + (l ? " (line " + std::to_string(l) + ")" : "");
      }
    }
    // a segment whose kind could not be read already has its issue, and the counts of drives
    // and take-ups are not known then
    bool skip = false;
    for (std::size_t k = 0; k < count; ++k)
      if (!kind_ok[k] && (i.field == "loop.segment" ||
                          i.field.rfind("loop.segment[" + std::to_string(k) + "]", 0) == 0))
        skip = true;
    if (!skip) issues.push_back(std::move(i));
  }
  throw_if_any(issues);
  return out;
}

// At most `width` bytes of `text`, never cutting a UTF-8 sequence, padded to `width` bytes.
std::string column(const std::string& text, std::size_t width) {
  std::size_t n = std::min(text.size(), width);
  while (n > 0 && n < text.size() && (static_cast<unsigned char>(text[n]) & 0xC0) == 0x80) --n;
  return text.substr(0, n) + std::string(width - n, ' ');
}

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

LoopAnalysis run(const analysis::Inputs& in) { return loop_from_table(in.at("loop")); }

Record describe(const LoopAnalysis& a, const analysis::Inputs&) {
  const Loop& loop = a.loop;
  const LoopResult& r = a.result;
  Record rec;
  rec.diagnostics = r.diagnostics;
  auto name_of = [&](std::size_t i) { return loop.segments[i].name; };
  auto at = [&](const Extremum& e) {
    return Value::object({{"segment", e.segment},
                          {"name", name_of(e.segment)},
                          {"at", e.at_end ? "end" : "start"},
                          {"s", e.s}});
  };

  {
    Value j = Value::object();
    j["model"] = "strength.loop_contour";
    j["source"] =
        "000 §1.5 fig. 19 (qualitative); contour (point-by-point) traction method of conveyor "
        "textbooks (Spivakovsky & Dyachkov, Conveyors and related equipment)";
    if (a.has_name) j["name"] = a.name;
    j["speed"] = loop.speed;
    j["efficiency"] = loop.efficiency;
    Value points = Value::array(), segments = Value::array();
    for (std::size_t i = 0; i < r.segments.size(); ++i) {
      const SegmentTension& t = r.segments[i];
      const char* kind = to_string(loop.segments[i].kind);
      points.push_back(Value::object({{"segment", i},
                                      {"name", name_of(i)},
                                      {"kind", kind},
                                      {"at", "start"},
                                      {"s", t.s_start},
                                      {"tension", t.tension_in}}));
      points.push_back(Value::object({{"segment", i},
                                      {"name", name_of(i)},
                                      {"kind", kind},
                                      {"at", "end"},
                                      {"s", t.s_end},
                                      {"tension", t.tension_out}}));
      segments.push_back(Value::object({{"segment", i},
                                        {"name", name_of(i)},
                                        {"kind", kind},
                                        {"s_start", t.s_start},
                                        {"s_end", t.s_end},
                                        {"tension_in", t.tension_in},
                                        {"tension_out", t.tension_out},
                                        {"resistance", t.resistance}}));
    }
    j["points"] = points;
    j["segments"] = segments;
    j["max_tension"] = r.max.tension;
    j["max_tension_at"] = at(r.max);
    j["min_tension"] = r.min.tension;
    j["min_tension_at"] = at(r.min);
    j["slack_tension"] = r.slack_tension;
    j["tight_tension"] = r.tight_tension;
    j["drive_force"] = r.drive_force;
    j["power"] = r.power;
    j["length"] = r.length;
    j["diagnostics"] = analysis::diagnostics_value(r.diagnostics);
    j["units"] = analysis::units_value({{"speed", "m/s"},
                                        {"efficiency", "1"},
                                        {"s", "m"},
                                        {"s_start", "m"},
                                        {"s_end", "m"},
                                        {"tension", "N"},
                                        {"tension_in", "N"},
                                        {"tension_out", "N"},
                                        {"resistance", "N"},
                                        {"max_tension", "N"},
                                        {"min_tension", "N"},
                                        {"slack_tension", "N"},
                                        {"tight_tension", "N"},
                                        {"drive_force", "N"},
                                        {"power", "W"},
                                        {"length", "m"},
                                        {"value", "SI"},
                                        {"limit", "SI"}});
    rec.data = std::move(j);
  }
  {
    std::ostringstream csv;
    csv << "segment,name,kind,at,s,tension\n";
    for (std::size_t i = 0; i < r.segments.size(); ++i) {
      const SegmentTension& t = r.segments[i];
      const std::string head =
          std::to_string(i) + "," + csv_field(name_of(i)) + "," + to_string(loop.segments[i].kind);
      csv << head << ",start," << format_g(t.s_start, 12) << "," << format_g(t.tension_in, 12)
          << "\n";
      csv << head << ",end," << format_g(t.s_end, 12) << "," << format_g(t.tension_out, 12) << "\n";
    }
    rec.csv = csv.str();
  }
  {
    std::ostringstream table;
    table << "Catena loop: chain tensions by the contour method (seed 000 §1.5, fig. 19)\n\n"
          << "   #  segment               kind        s start [m]  s end [m]   S in [kN]  "
             "S out [kN]  dS [kN]\n";
    for (std::size_t i = 0; i < r.segments.size(); ++i) {
      const SegmentTension& t = r.segments[i];
      char line[256];
      std::snprintf(line, sizeof line, "  %2zu  %s  %-10s %11.3f %10.3f %11.4g %11.4g %8.4g\n", i,
                    column(name_of(i), 20).c_str(), to_string(loop.segments[i].kind), t.s_start,
                    t.s_end, t.tension_in / 1e3, t.tension_out / 1e3, t.resistance / 1e3);
      table << line;
    }
    auto place = [&](const Extremum& e) {
      return "segment " + std::to_string(e.segment) +
             (name_of(e.segment).empty() ? "" : " '" + name_of(e.segment) + "'") +
             (e.at_end ? " end" : " start") + ", s = " + format_g(e.s, 5) + " m";
    };
    table << "\n  tight side S_t " << format_g(r.tight_tension / 1e3, 5) << " kN, slack side S_s "
          << format_g(r.slack_tension / 1e3, 5) << " kN\n"
          << "  max tension  " << format_g(r.max.tension / 1e3, 5) << " kN at " << place(r.max)
          << "\n"
          << "  min tension  " << format_g(r.min.tension / 1e3, 5) << " kN at " << place(r.min)
          << "\n"
          << "  drive force  " << format_g(r.drive_force / 1e3, 5) << " kN; power "
          << format_g(r.power / 1e3, 5) << " kW at v = " << format_g(loop.speed, 4)
          << " m/s, eta = " << format_g(loop.efficiency, 4) << "\n";
    for (const Diagnostic& d : r.diagnostics)
      table << "  " << to_string(d.severity) << ": " << d.message << "\n";
    rec.table = table.str();
  }
  // the report: tension along the path (a vertical step at each turn and over the drive
  // sprocket) and the segments
  analysis::Chart c;
  c.title = "Chain tension along the loop (from the drive sprocket's slack side)";
  c.x_label = "path length s [m]";
  c.y_label = "tension [kN]";
  std::vector<double> x, y;
  for (const Value& p : rec.data.at("points").as_array()) {
    x.push_back(p.at("s").as_number());
    y.push_back(p.at("tension").as_number() * 1e-3);
  }
  c.traces.push_back({"tension", x, y});
  rec.charts.push_back(c);
  analysis::Grid grid{
      "Segments",
      {"#", "name", "kind", "s start [m]", "s end [m]", "S in [kN]", "S out [kN]", "ΔS [kN]"},
      {},
      {}};
  auto f = [](const Value& v, double scale) { return format_g(v.as_number() * scale, 5); };
  for (const Value& g : rec.data.at("segments").as_array())
    grid.rows.push_back({std::to_string(g.at("segment").as_integer()), g.at("name").as_string(),
                         g.at("kind").as_string(), f(g.at("s_start"), 1.0), f(g.at("s_end"), 1.0),
                         f(g.at("tension_in"), 1e-3), f(g.at("tension_out"), 1e-3),
                         f(g.at("resistance"), 1e-3)});
  rec.grids.push_back(std::move(grid));
  // the results in the units of the segment table and the chart: path lengths in m, forces in
  // kN (the default display would give mm beside m)
  rec.labels = {{"max_tension", "Greatest tension S max", "kN"},
                {"max_tension_at.segment", "… in segment #", ""},
                {"max_tension_at.name", "… named", ""},
                {"max_tension_at.at", "… at its", ""},
                {"max_tension_at.s", "… at path length s", "m"},
                {"min_tension", "Least tension S min", "kN"},
                {"min_tension_at.segment", "… in segment #", ""},
                {"min_tension_at.name", "… named", ""},
                {"min_tension_at.at", "… at its", ""},
                {"min_tension_at.s", "… at path length s", "m"},
                {"slack_tension", "Slack-side tension at the drive", "kN"},
                {"tight_tension", "Tight-side tension at the drive", "kN"},
                {"drive_force", "Drive force", "kN"},
                {"power", "Drive power P", "kW"},
                {"length", "Loop length L", "m"}};
  return rec;
}

}  // namespace

const analysis::Parameter& loop_table_parameter() {
  static const Parameter p = [] {
    Parameter t;
    t.name = "loop";
    t.type = ParameterType::kTable;
    t.doc =
        "TOML file with a [loop] table and [[loop.segment]] tables (a case file works); in a case "
        "file, its own [loop] table";
    t.required = true;
    t.expected =
        "a [loop] table (speed, efficiency) and its segments as [[loop.segment]] tables "
        "(docs/models/loop.md)";
    t.fields = loop_fields();
    t.rows_name = "segment";
    t.row_fields = segment_fields();
    return t;
  }();
  return p;
}

LoopAnalysis loop_from_table(const analysis::InputValue& table) {
  const Parsed p = parse_loop(table);
  return LoopAnalysis{p.loop, p.name, p.has_name, solve(p.loop)};
}

namespace {

analysis::Analysis make() {
  analysis::Analysis a;
  a.name = "loop";
  a.command = {"loop"};
  a.title =
      "Conveyor loop: chain tension at every point by the contour method (seed 000 §1.5 fig. 19)";
  a.help =
      "Chain tensions around a conveyor loop by the contour method: every point, maximum, drive "
      "force and power (seed 000 §1.5 fig. 19)";
  a.seed = "000 §1.5";
  a.docs = "docs/models/loop.md";
  a.chain_types = {"rolling-hinge", "sliding-hinge", "roller-iso606", "round-link",
                   "composite-link"};
  a.formats = {.table = true, .csv = true, .drawing = false};
  a.parameters = {table_parameter()};
  analysis::set_functions<LoopAnalysis>(a, run, describe);
  return a;
}

}  // namespace

const analysis::Analysis& loop_analysis() {
  static const analysis::Analysis a = make();
  return a;
}

}  // namespace catena::strength
