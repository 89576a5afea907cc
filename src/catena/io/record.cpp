#include "catena/io/record.hpp"

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

// The scalars of a result (nested objects with dotted names), in display units. A member
// without a unit of its own takes its enclosing object's (`tension.tight`: the unit of
// `tension`), so that objects such as {driver, driven} need no unit per member name.
void scalar_rows(const Value& result, const Value& object, const std::string& prefix,
                 std::vector<ReportRow>& rows, const std::string& inherited = "") {
  static const std::set<std::string> skip = {"model", "source", "units", "diagnostics"};
  for (const auto& [key, v] : object.as_object()) {
    if (skip.count(key)) continue;
    const std::string own = unit_of(result, key);
    const std::string unit = own.empty() ? inherited : own;
    if (v.is_object()) {
      scalar_rows(result, v, prefix + key + ".", rows, unit);
    } else if (!v.is_array()) {
      const Display d = display(unit);
      rows.push_back({prefix + key, format_cell(v, v.is_number() ? d.scale : 1.0), d.unit});
    } else if (v.size() <= 4 && v.size() > 0 && v.as_array()[0].is_number()) {
      const Display d = display(unit);
      std::string text;
      for (const Value& e : v.as_array())
        text += (text.empty() ? "" : ", ") + format_cell(e, d.scale);
      rows.push_back({prefix + key, text, d.unit});
    }
  }
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
  if (v.is_number()) return format_g(v.as_number() * scale, 6);
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
    if (std::isfinite(d.limit)) rd.limit = format_g(d.limit, 6) + " in SI units (m, rad, Pa, N)";
    s.diagnostics.push_back(rd);
  }
  ReportTable results{"Results", {}};
  if (j.is_object()) scalar_rows(j, j, "", results.rows);
  const Value& rows = j.at("rows");
  if (rows.is_array() && rows.size() > 0) {
    // a sweep: one grid row per design, the best one highlighted
    ReportGrid grid{"Designs", {}, {}, {}};
    for (const auto& [key, v] : rows.as_array()[0].as_object()) {
      const Display d = display(unit_of(j, key));
      grid.columns.push_back(key + (d.unit.empty() ? "" : " [" + d.unit + "]"));
    }
    const Value& best = j.at("best");
    const std::size_t best_row = best.is_integer() && best.as_integer() >= 0
                                     ? static_cast<std::size_t>(best.as_integer())
                                     : rows.size();
    for (std::size_t i = 0; i < rows.size(); ++i) {
      std::vector<std::string> cells;
      for (const auto& [key, v] : rows.as_array()[i].as_object()) {
        const Display d = display(unit_of(j, key));
        cells.push_back(format_cell(v, v.is_number() ? d.scale : 1.0));
      }
      grid.rows.push_back(std::move(cells));
      grid.highlighted.push_back(i == best_row);
    }
    s.grids.push_back(std::move(grid));
  }
  for (const ReportGrid& g : record.grids) s.grids.push_back(g);
  s.tables.push_back(results);
  s.charts = record.charts;
  for (const Drawing& d : record.drawings) s.drawings_svg.push_back(to_svg(d));
  return s;
}

}  // namespace catena::io
