#include "catena/io/record.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "catena/io/drawing.hpp"

namespace catena::io {

using analysis::Value;
using nlohmann::ordered_json;

namespace {

ordered_json to_nlohmann(const Value& v) {
  if (v.is_null()) return ordered_json();
  if (v.is_bool()) return ordered_json(v.as_bool());
  if (v.is_integer()) return ordered_json(v.as_integer());
  if (v.is_real()) return ordered_json(v.as_number());
  if (v.is_string()) return ordered_json(v.as_string());
  if (v.is_array()) {
    ordered_json a = ordered_json::array();
    for (const Value& e : v.as_array()) a.push_back(to_nlohmann(e));
    return a;
  }
  ordered_json o = ordered_json::object();
  for (const auto& [key, e] : v.as_object()) o[key] = to_nlohmann(e);
  return o;
}

Value from_nlohmann(const ordered_json& j) {
  if (j.is_null()) return Value();
  if (j.is_boolean()) return Value(j.get<bool>());
  if (j.is_number_integer()) return Value(j.get<long long>());
  if (j.is_number()) return Value(j.get<double>());
  if (j.is_string()) return Value(j.get<std::string>());
  if (j.is_array()) {
    Value a = Value::array();
    for (const ordered_json& e : j) a.push_back(from_nlohmann(e));
    return a;
  }
  Value o = Value::object();
  for (auto it = j.begin(); it != j.end(); ++it) o[it.key()] = from_nlohmann(it.value());
  return o;
}

using analysis::format_g;
using analysis::unit_of;

// The label of the field at `path` (dotted): the longest of `labels` whose path ends `path`
// at a dot boundary; null when none does.
const analysis::Label* label_of(const std::vector<analysis::Label>& labels,
                                const std::string& path) {
  const analysis::Label* best = nullptr;
  for (const analysis::Label& l : labels) {
    if (l.path.empty() || l.path.size() > path.size()) continue;
    const std::size_t at = path.size() - l.path.size();
    if (path.compare(at, std::string::npos, l.path) != 0) continue;
    if (at > 0 && path[at - 1] != '.') continue;
    if (!best || l.path.size() > best->path.size()) best = &l;
  }
  return best;
}

// The row name and display of a result field: its label (the uncovered part of the path in
// front, "layout 1 › Plate force, lower outer F21"), or its path; the label's unit when it names
// one that display_scale knows.
struct Named {
  std::string name;
  Display display;
};
Named named(const std::vector<analysis::Label>& labels, const std::string& path,
            const std::string& si_unit) {
  Named n{path, display(si_unit)};
  const analysis::Label* l = label_of(labels, path);
  if (!l) return n;
  n.name.clear();
  if (l->path.size() < path.size()) {
    // the containers in front: each by its own label when it has one, else by its key
    std::string prefix = path.substr(0, path.size() - l->path.size() - 1), walked;
    for (std::size_t from = 0; from <= prefix.size();) {
      std::size_t dot = prefix.find('.', from);
      if (dot == std::string::npos) dot = prefix.size();
      const std::string key = prefix.substr(from, dot - from);
      walked += (walked.empty() ? "" : ".") + key;
      const analysis::Label* own = label_of(labels, walked);
      std::string text = own ? own->text : key;  // a label of the container itself
      for (char& c : text)
        if (c == '_') c = ' ';
      if (!text.empty()) n.name += text + " › ";  // a container labelled "" is left out
      from = dot + 1;
    }
  }
  n.name += l->text;
  if (!l->unit.empty()) {
    const double scale = analysis::display_scale(si_unit, l->unit);
    if (std::isfinite(scale)) n.display = {l->unit, scale};
  }
  return n;
}

// The scalars of a result (nested objects with dotted names), in display units. A member
// without a unit of its own takes its enclosing object's (`tension.tight`: the unit of
// `tension`), so that objects such as {driver, driven} need no unit per member name.
void scalar_rows(const Value& result, const Value& object, const std::string& prefix,
                 const std::vector<analysis::Label>& labels, std::vector<ReportRow>& rows,
                 const std::string& inherited = "") {
  static const std::set<std::string> skip = {"model", "source", "units", "diagnostics"};
  for (const auto& [key, v] : object.as_object()) {
    if (skip.count(key)) continue;
    const std::string own = unit_of(result, key);
    const std::string unit = own.empty() ? inherited : own;
    if (v.is_object()) {
      scalar_rows(result, v, prefix + key + ".", labels, rows, unit);
    } else if (!v.is_array()) {
      const Named n = named(labels, prefix + key, unit);
      rows.push_back(
          {n.name, format_cell(v, v.is_number() ? n.display.scale : 1.0), n.display.unit});
    } else if (v.size() <= 4 && v.size() > 0 && v.as_array()[0].is_number()) {
      const Named n = named(labels, prefix + key, unit);
      std::string text;
      for (const Value& e : v.as_array())
        text += (text.empty() ? "" : ", ") + format_cell(e, n.display.scale);
      rows.push_back({n.name, text, n.display.unit});
    }
  }
}

// `d` with a scale bar under its lower-left corner: a round length (1, 2 or 5 × 10^k mm) near a
// fifth of the drawing's width, with end ticks, on layer "scale bar"; `length_mm` is set to it.
Drawing with_scale_bar(const Drawing& d, double& length_mm) {
  double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
  for (const Polyline& p : d.polylines) {
    for (auto [x, y] : p.points) {
      xmin = std::min(xmin, x), xmax = std::max(xmax, x);
      ymin = std::min(ymin, y), ymax = std::max(ymax, y);
    }
  }
  length_mm = 0.0;
  if (!(xmax > xmin) || !std::isfinite(xmax - xmin)) return d;
  const double target = (xmax - xmin) * 1e3 / 5.0;
  const double decade = std::pow(10.0, std::floor(std::log10(target)));
  const double step = target / decade >= 5 ? 5 : target / decade >= 2 ? 2 : 1;
  length_mm = step * decade;
  const double l = length_mm * 1e-3, tick = std::max(l / 10, (ymax - ymin) / 60);
  const double y = ymin - 2 * tick;
  Drawing out = d;
  out.polylines.push_back({"scale bar",
                           {{xmin, y + tick}, {xmin, y}, {xmin + l, y}, {xmin + l, y + tick}},
                           false,
                           0.6,
                           0x000000});
  return out;
}

// "12.5 mm", "0.15": a value of a diagnostic in the display unit of its SI unit.
std::string with_unit(double si_value, const std::string& si_unit) {
  const Display d = display(si_unit);
  std::string text = format_g(si_value * d.scale, 6);
  if (text == "-0") text = "0";
  if (d.unit.empty()) return text;
  return text + (d.unit == "°" ? "" : " ") + d.unit;
}

}  // namespace

std::string to_json(const Value& value, int indent) {
  return to_nlohmann(value).dump(indent) + (indent >= 0 ? "\n" : "");
}

Value parse_json(const std::string& text) { return from_nlohmann(ordered_json::parse(text)); }

std::string to_csv(const std::vector<analysis::Column>& columns) {
  std::ostringstream out;
  for (std::size_t c = 0; c < columns.size(); ++c) out << (c ? "," : "") << columns[c].name;
  out << "\n";
  const std::size_t n = columns.empty() ? 0 : columns.front().values.size();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t c = 0; c < columns.size(); ++c) {
      const double v = i < columns[c].values.size() ? columns[c].values[i] : NAN;
      out << (c ? "," : "");
      if (i < columns[c].values.size() && !(columns[c].blank_nan && std::isnan(v)))
        out << format_g(v, columns[c].digits);
    }
    out << "\n";
  }
  return out.str();
}

std::string format_cell(const Value& v, double scale) {
  if (v.is_number()) {
    // a negative value that rounds to zero (or -0 itself) prints as 0, never as "-0"
    const std::string text = format_g(v.as_number() * scale, 6);
    return text == "-0" ? "0" : text;
  }
  if (v.is_bool()) return v.as_bool() ? "yes" : "no";
  if (v.is_null()) return "—";
  if (v.is_string()) return v.as_string();
  return to_json(v, -1);
}

ReportSection report_section(const analysis::Record& record, const std::string& id,
                             const std::string& title, const std::string& docs) {
  ReportSection s;
  s.id = id;
  s.title = title;
  s.docs = docs;
  const Value& j = record.data;
  const Value& source = j.at("source");
  s.source = source.is_string() ? source.as_string() : "see " + docs;
  for (const Diagnostic& d : record.diagnostics) {
    ReportDiagnostic rd;
    rd.severity = d.severity == Diagnostic::Severity::kInfeasible ? "error" : to_string(d.severity);
    rd.message = d.message;
    // the checked value and its limit in the display units of the tables beside them; a
    // diagnostic that names no unit is a pure number (a ratio, a safety factor) or says its
    // limit in its message only
    // (a note's value and limit are context, not a check: left to its message)
    if (d.severity != Diagnostic::Severity::kInfo && std::isfinite(d.limit) &&
        (!d.unit.empty() || d.limit != 0.0 || d.value != 0.0)) {
      rd.limit = with_unit(d.limit, d.unit);
      if (std::isfinite(d.value) && d.value != d.limit)
        rd.limit = "value " + with_unit(d.value, d.unit) + ", limit " + rd.limit;
    }
    s.diagnostics.push_back(rd);
  }
  ReportTable results{"Results", {}};
  const Value& rows = j.at("rows");
  const bool sweep = rows.is_array() && rows.size() > 0;
  if (j.is_object()) scalar_rows(j, j, "", record.labels, results.rows);
  if (sweep) {
    // a sweep: one grid row per design, numbered from 1, the best one highlighted and named
    ReportGrid grid{"Designs", {}, {}, {}, true, ""};
    for (const auto& [key, v] : rows.as_array()[0].as_object()) {
      const Named n = named(record.labels, key, unit_of(j, key));
      grid.columns.push_back(n.name + (n.display.unit.empty() ? "" : " [" + n.display.unit + "]"));
    }
    const Value& best = j.at("best");
    const std::size_t best_row = best.is_integer() && best.as_integer() >= 0
                                     ? static_cast<std::size_t>(best.as_integer())
                                     : rows.size();
    for (std::size_t i = 0; i < rows.size(); ++i) {
      std::vector<std::string> cells;
      for (const auto& [key, v] : rows.as_array()[i].as_object()) {
        const Named n = named(record.labels, key, unit_of(j, key));
        cells.push_back(format_cell(v, v.is_number() ? n.display.scale : 1.0));
      }
      grid.rows.push_back(std::move(cells));
      grid.highlighted.push_back(i == best_row);
    }
    std::string best_name = "none: no row qualifies";
    if (best_row < rows.size()) {
      best_name = "#" + std::to_string(best_row + 1);
      std::string inputs;
      for (const std::string& key : record.design_keys) {
        const Value& v = rows.as_array()[best_row].at(key);
        if (v.is_null()) continue;
        const Named n = named(record.labels, key, unit_of(j, key));
        inputs += (inputs.empty() ? "" : ", ") + key + " = " +
                  format_cell(v, v.is_number() ? n.display.scale : 1.0) +
                  (n.display.unit.empty() ? "" : " " + n.display.unit);
      }
      if (!inputs.empty()) best_name += " (" + inputs + ")";
    }
    const Value& criterion = j.at("criterion");
    grid.note = "Best design, highlighted: " + best_name +
                (criterion.is_string() ? "; " + criterion.as_string() : std::string()) + ".";
    // the Results table names the best row as the note does, not by its 0-based index
    for (ReportRow& r : results.rows) {
      if (r.name == "best") r = {"best design", best_name, ""};
    }
    s.grids.push_back(std::move(grid));
  }
  for (const ReportGrid& g : record.grids) s.grids.push_back(g);
  s.tables.push_back(results);
  s.charts = record.charts;
  for (const Drawing& d : record.drawings) {
    ReportDrawingKey key;
    Drawing shown = with_scale_bar(d, key.scale_bar_mm);
    key.caption = d.title.empty() ? title : d.title;
    for (const Polyline& p : d.polylines) {
      const bool listed = std::any_of(d.polylines.data(), &p,
                                      [&](const Polyline& q) { return q.layer == p.layer; });
      if (listed || p.layer.empty()) continue;
      // DXF layer names read as words in the legend: "ROLLER_PHI0" → "roller phi0"
      std::string name = p.layer;
      for (char& c : name)
        c = c == '_' ? ' ' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      key.legend.push_back({name, p.rgb});
    }
    s.drawings_svg.push_back(to_svg(shown));
    s.drawing_keys.push_back(std::move(key));
  }
  return s;
}

}  // namespace catena::io
