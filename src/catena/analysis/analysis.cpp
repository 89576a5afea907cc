#include "catena/analysis/analysis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <numbers>
#include <stdexcept>

namespace catena::analysis {

// ---- parameters

const InputValue& Inputs::at(std::string_view key) const {
  const auto it = values_.find(key);
  if (it != values_.end()) return it->second;
  if (parameters_) {
    for (const Parameter& p : *parameters_) {
      if (p.name == key) {
        static const InputValue absent;
        return absent;
      }
    }
  }
  throw std::logic_error("analysis input '" + std::string(key) + "' is not in its table");
}

InputValue& Inputs::set(std::string_view key) {
  const auto it = values_.find(key);
  if (it != values_.end()) return it->second;
  return values_.emplace(std::string(key), InputValue{}).first->second;
}

std::optional<double> Inputs::optional(std::string_view key) const {
  const InputValue& v = at(key);
  if (!v.present) return std::nullopt;
  return v.number;
}

namespace {
Parameter make(std::string name, ParameterType type, std::string doc) {
  Parameter p;
  p.name = std::move(name);
  p.type = type;
  p.doc = std::move(doc);
  return p;
}
}  // namespace

Parameter quantity(std::string name, QuantityKind kind, std::string doc) {
  Parameter p = make(std::move(name), ParameterType::kQuantity, std::move(doc));
  p.kind = kind;
  return p;
}
Parameter number(std::string name, std::string doc) {
  return make(std::move(name), ParameterType::kNumber, std::move(doc));
}
Parameter integer(std::string name, int min, std::string doc) {
  Parameter p = make(std::move(name), ParameterType::kInteger, std::move(doc));
  p.min_integer = min;
  return p;
}
Parameter choice(std::string name, std::vector<std::string> choices, std::string doc) {
  Parameter p = make(std::move(name), ParameterType::kChoice, std::move(doc));
  p.choices = std::move(choices);
  return p;
}
Parameter flag(std::string name, std::string doc) {
  return make(std::move(name), ParameterType::kFlag, std::move(doc));
}
Parameter text(std::string name, std::string doc) {
  return make(std::move(name), ParameterType::kText, std::move(doc));
}

Parameter operator|(Parameter p, const Required& r) {
  p.required = true;
  p.expected = r.expected;
  return p;
}
Parameter operator|(Parameter p, const Default& d) {
  p.default_text = d.text;
  return p;
}
Parameter operator|(Parameter p, const Example& e) {
  p.example = e.text;
  return p;
}
Parameter operator|(Parameter p, ListOf) {
  p.list = true;
  return p;
}
Parameter operator|(Parameter p, NotShared) {
  p.not_shared = true;
  return p;
}
Parameter operator|(Parameter p, const Expects& e) {
  p.expected = e.text;
  return p;
}
Parameter operator|(Parameter p, Positional) {
  p.positional = true;
  return p;
}

Parameter operator|(Parameter p, CliOnly) {
  p.cli_only = true;
  return p;
}
Parameter operator|(Parameter p, const Alias& a) {
  p.aliases.push_back(a.name);
  return p;
}
Parameter operator|(Parameter p, const Work& w) {
  p.work = w;
  return p;
}

// ---- records

namespace {

// Collects the non-finite reals below `v` (path `path`); an array of numbers is one field.
void collect_non_finite(const Value& v, const std::string& path, std::vector<NonFinite>& out) {
  if (v.is_real()) {
    const double x = v.as_number();
    if (!std::isfinite(x)) out.push_back({path, 1, 1, x});
  } else if (v.is_array()) {
    const Value::Array& items = v.as_array();
    const bool numbers = std::all_of(items.begin(), items.end(),
                                     [](const Value& e) { return e.is_number() || e.is_null(); });
    if (numbers && !items.empty()) {
      NonFinite f{path, 0, items.size(), 0.0};
      for (const Value& e : items) {
        if (e.is_real() && !std::isfinite(e.as_number()) && f.count++ == 0) f.first = e.as_number();
      }
      if (f.count > 0) out.push_back(f);
      return;
    }
    for (std::size_t i = 0; i < items.size(); ++i)
      collect_non_finite(items[i], path + "[" + std::to_string(i) + "]", out);
  } else if (v.is_object()) {
    for (const auto& [key, member] : v.as_object()) {
      if (key == "units" || key == "diagnostics") continue;
      collect_non_finite(member, path.empty() ? key : path + "." + key, out);
    }
  }
}

}  // namespace

std::vector<NonFinite> non_finite_fields(const Value& data) {
  std::vector<NonFinite> out;
  collect_non_finite(data, "", out);
  return out;
}

void diagnose_non_finite(Record& record) {
  const std::vector<NonFinite> fields = non_finite_fields(record.data);
  if (fields.empty()) return;
  Value* listed = record.data.is_object() && record.data.contains("diagnostics") &&
                          record.data.at("diagnostics").is_array()
                      ? &record.data["diagnostics"]
                      : nullptr;
  for (const NonFinite& f : fields) {
    const char* what = std::isnan(f.first) ? "NaN" : (f.first > 0 ? "+inf" : "-inf");
    Diagnostic d;
    d.severity = Diagnostic::Severity::kError;
    d.code = "result.non_finite";
    d.message =
        "the result '" + (f.path.empty() ? std::string("(value)") : f.path) + "' is not finite (" +
        what +
        (f.total > 1 ? ", " + std::to_string(f.count) + " of " + std::to_string(f.total) + " values"
                     : std::string()) +
        "): an input lies outside the range the model can compute in double precision";
    d.value = static_cast<double>(f.count);
    d.limit = 0.0;
    record.diagnostics.push_back(d);
    if (listed) listed->push_back(diagnostics_value({d}).as_array().front());
  }
}

Value diagnostics_value(const std::vector<Diagnostic>& diagnostics) {
  Value out = Value::array();
  for (const Diagnostic& d : diagnostics) {
    out.push_back(Value::object({{"severity", to_string(d.severity)},
                                 {"code", d.code},
                                 {"message", d.message},
                                 {"value", d.value},
                                 {"limit", d.limit}}));
  }
  return out;
}

Value units_value(const std::vector<std::pair<const char*, const char*>>& units) {
  Value out = Value::object();
  for (const auto& [key, unit] : units) out[key] = unit;
  return out;
}

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

double display_scale(const std::string& si_unit, const std::string& unit) {
  if (unit == si_unit) return 1.0;
  const Display d = display(si_unit);
  if (unit == d.unit) return d.scale;
  static const std::map<std::pair<std::string, std::string>, double> table = {
      {{"N", "kN"}, 1e-3},
      {{"Pa", "GPa"}, 1e-9},
      {{"W", "kW"}, 1e-3},
      {{"N*m", "kN·m"}, 1e-3},
      {{"N*m", "N·m"}, 1.0}};
  const auto it = table.find({si_unit, unit});
  return it == table.end() ? std::numeric_limits<double>::quiet_NaN() : it->second;
}

std::string format_g(double v, int digits) {
  char b[64];
  std::snprintf(b, sizeof b, "%.*g", digits, v);
  return b;
}

std::string times_text(double m) {
  if (m == 2.0) return "twice";
  // the shortest of 6 to 17 digits that reads back as m: 2.0000001 is not "2 times"
  std::string g = format_g(m);
  for (int digits = 7; digits <= 17 && std::strtod(g.c_str(), nullptr) != m; ++digits)
    g = format_g(m, digits);
  return g + " times";
}

std::string unit_of(const Value& result, const std::string& key) {
  const Value& u = result.at("units").at(key);
  return u.is_string() ? u.as_string() : "";
}

Chart series_chart(const Value& result, const Value& object, const std::string& title,
                   const std::string& x, const std::vector<std::string>& ys,
                   const std::string& y_label) {
  Chart chart;
  chart.title = title;
  const Display dx = display(unit_of(result, x));
  chart.x_label = x + (dx.unit.empty() ? "" : " [" + dx.unit + "]");
  std::string common_unit;
  for (const std::string& y : ys) {
    if (!object.contains(y)) continue;
    const Display dy = display(unit_of(result, y));
    common_unit = dy.unit;
    chart.traces.push_back({y, object.at(x).numbers(dx.scale), object.at(y).numbers(dy.scale)});
  }
  chart.y_label = (y_label.empty() ? (ys.size() == 1 ? ys[0] : std::string("value")) : y_label) +
                  (common_unit.empty() ? "" : " [" + common_unit + "]");
  return chart;
}

// ---- analyses

std::vector<Issue> in_read_order(const std::vector<Issue>& bound, const std::vector<Issue>& added,
                                 const std::vector<std::string>& order,
                                 const std::function<bool(const std::string&)>& read) {
  std::vector<Issue> out;
  for (const Issue& issue : bound) {  // not an input of the table (an unknown key)
    if (std::find(order.begin(), order.end(), issue.field) == order.end()) out.push_back(issue);
  }
  for (const std::string& key : order) {
    if (read(key)) {
      for (const Issue& issue : bound) {
        if (issue.field == key) out.push_back(issue);
      }
    }
    for (const Issue& issue : added) {
      if (issue.field == key) out.push_back(issue);
    }
  }
  return out;
}

const Parameter* Analysis::parameter(std::string_view key) const {
  for (const Parameter& p : parameters) {
    if (p.name == key) return &p;
  }
  return nullptr;
}

bool Analysis::renames(const std::string& field) const {
  if (field.find('.') != std::string::npos) return false;  // a path of a table's reader
  const Parameter* p = parameter(field);
  return !(p && p->type == ParameterType::kTable);
}

const Parameter* Analysis::table_field(const std::string& path) const {
  const std::string head = path.substr(0, path.find('.'));
  const Parameter* table = parameter(head);
  if (!table || table->type != ParameterType::kTable || head.size() == path.size()) return nullptr;
  const std::string key = path.substr(path.rfind('.') + 1);
  const bool in_row =
      !table->rows_name.empty() && path.rfind(head + "." + table->rows_name + "[", 0) == 0;
  for (const Parameter& f : in_row ? table->row_fields : table->fields) {
    if (f.name == key) return &f;
  }
  return nullptr;
}

namespace {
// "0.42", "8.5", "260", "65000", "2.6e+07": two digits below 100, whole numbers to a million.
std::string estimate_number(double v) {
  if (v < 100.0 || v >= 1e6) return format_g(v, 2);
  char b[32];
  std::snprintf(b, sizeof b, "%.0f", v);
  return b;
}
std::string estimate_text(double seconds, double bytes) {
  return estimate_number(seconds) + " s and " + estimate_number(bytes / 1e6) + " MB";
}
}  // namespace

std::vector<Issue> Analysis::size_issues(const Inputs& inputs) const {
  std::vector<Issue> issues;
  if (inputs.large_allowed()) return issues;
  for (const Parameter& p : parameters) {
    if (p.type != ParameterType::kInteger || p.work.cap <= 0) continue;
    const InputValue& v = inputs.at(p.name);
    if (!v.present || v.integer <= p.work.cap) continue;
    const double n = static_cast<double>(v.integer);
    const double cap = static_cast<double>(p.work.cap);
    issues.push_back(
        {p.name, "'" + v.text + "'",
         "at most " + std::to_string(p.work.cap) + " (estimated " +
             estimate_text(p.work.estimated_seconds(n), p.work.estimated_bytes(n)) +
             "; at the cap " +
             estimate_text(p.work.estimated_seconds(cap), p.work.estimated_bytes(cap)) +
             "); allow_large (--allow-large) runs it anyway"});
  }
  return issues;
}

bool Analysis::has_size_caps() const {
  // a table parameter with a cap: a size that follows from several of its values, refused by
  // the run itself (dynamics: duration/step × links)
  return std::any_of(parameters.begin(), parameters.end(), [](const Parameter& p) {
    return (p.type == ParameterType::kInteger || p.type == ParameterType::kTable) && p.work.cap > 0;
  });
}

Record Analysis::evaluate(const Inputs& inputs) const {
  throw_if_any(size_issues(inputs));
  // the loops of the run poll inputs.progress(); a cancelled run throws Cancelled from one
  const ProgressScope scope(inputs.progress(), name);
  check_cancelled();
  Record record = describe(run(inputs), inputs);
  diagnose_non_finite(record);
  return record;
}

}  // namespace catena::analysis
