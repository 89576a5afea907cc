#include "catena/sweep.hpp"

#include <algorithm>
#include <atomic>
#include <charconv>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <limits>
#include <map>
#include <mutex>
#include <optional>
#include <thread>

#include "catena/catena.hpp"
#include "catena/io/bind.hpp"
#include "catena/io/case_file.hpp"
#include "catena/io/quantity.hpp"

namespace catena {
namespace {

using analysis::Value;

constexpr std::size_t kMaxPoints = kMaxSweepPoints;

std::string quoted(std::string_view text) { return "'" + std::string(text) + "'"; }

void scalar_walk(const Value& root, const Value& object, const std::string& prefix,
                 std::vector<ScalarName>& names, std::vector<double>& values) {
  for (const auto& [key, v] : object.as_object()) {
    if (prefix.empty() && (key == "units" || key == "diagnostics")) continue;
    const std::string path = prefix + key;
    if (v.is_object()) {
      scalar_walk(root, v, path + ".", names, values);
    } else if (v.is_number() || v.is_null()) {
      const Value& units = root.at("units");
      std::string unit;
      if (units.is_object()) {
        const Value& whole = units.at(path);
        const Value& leaf = units.at(key);
        if (whole.is_string()) {
          unit = whole.as_string();
        } else if (leaf.is_string()) {
          unit = leaf.as_string();
        }
      }
      names.push_back({path, unit});
      values.push_back(v.is_null() ? NAN : v.as_number());
    }
  }
}

// The point's inputs for catena::run: the base with the point's values in place of the base's,
// then the point's other keys.
InputSet merged(const InputSet& base, const InputSet& point) {
  InputSet out;
  out.reserve(base.size() + point.size());
  for (const auto& [key, text] : base) {
    const auto own = std::find_if(point.begin(), point.end(),
                                  [&key = key](const auto& kv) { return kv.first == key; });
    out.emplace_back(key, own == point.end() ? text : own->second);
  }
  for (const auto& kv : point) {
    const bool in_base =
        std::any_of(base.begin(), base.end(), [&kv](const auto& b) { return b.first == kv.first; });
    if (!in_base) out.push_back(kv);
  }
  return out;
}

// The shared table `key` is a path inside ("dynamics.duration" → [dynamics]), or nullptr.
const TableValue* table_of_path(const std::vector<TableValue>& tables, const std::string& key) {
  for (const TableValue& t : tables) {
    if (key.size() > t.key.size() + 1 && key.compare(0, t.key.size(), t.key) == 0 &&
        key[t.key.size()] == '.')
      return &t;
  }
  return nullptr;
}

// A path inside a shared table names a value of a table the file has: its parent is the table
// itself or one of its sub-tables or rows ("dynamics.sprocket[1]").
void check_table_path(const TableValue& t, const std::string& key, const std::string& text,
                      std::vector<Issue>& issues) {
  const std::string parent = key.substr(0, key.rfind('.'));
  const std::string leaf = key.substr(key.rfind('.') + 1);
  // an array of tables ("dynamics.sprocket") holds rows, not values: its rows are parents
  const bool array = std::find(t.tables.begin(), t.tables.end(), parent + "[0]") != t.tables.end();
  const bool known_parent =
      !array &&
      (parent == t.key || std::find(t.tables.begin(), t.tables.end(), parent) != t.tables.end());
  if (known_parent && !leaf.empty() && leaf.find('[') == std::string::npos) return;
  std::string rows;  // the rows and sub-tables the file has, as the user would name them
  for (const std::string& table : t.tables) {
    if (table.rfind(t.key + ".", 0) == 0 && table.back() == ']')
      rows += (rows.empty() ? "" : ", ") + table;
  }
  issues.push_back({key, text,
                    "a value of the [" + t.key + "] table: " + t.key + ".<key>" +
                        (rows.empty() ? std::string()
                                      : " or <row>.<key> with a row of the file (" + rows + ")")});
}

void check_key(const analysis::Analysis& a, const std::vector<std::string>& known,
               const std::string& key, const std::string& text, std::vector<Issue>& issues,
               const std::vector<TableValue>* tables = nullptr) {
  // allow_large is no parameter, but every analysis reads it (the binder does)
  if (a.parameter(key) != nullptr || key == analysis::kAllowLarge) return;
  if (tables != nullptr) {
    if (const TableValue* t = table_of_path(*tables, key)) {
      check_table_path(*t, key, text, issues);
      return;
    }
  }
  const auto near = io::did_you_mean(key, known);
  issues.push_back({key, text,
                    "an input of '" + a.name + "'" +
                        (near ? " (did you mean '" + *near + "'?)" : std::string())});
}

// The point's raw inputs with the shared tables as values: the point's table paths go into its
// own copy of them, its other inputs read as catena::run reads them.
std::vector<io::RawInput> point_raw(const analysis::Analysis& a, const InputSet& inputs,
                                    const std::vector<TableValue>& tables,
                                    std::vector<Issue>& issues, std::vector<std::string>& unread) {
  std::vector<TableValue> own = tables;
  InputSet plain;
  for (const auto& [key, text] : inputs) {
    const TableValue* shared = table_of_path(tables, key);
    if (shared == nullptr) {
      plain.emplace_back(key, text);
      continue;
    }
    TableValue& t = own[static_cast<std::size_t>(shared - tables.data())];
    // the value read as a TOML value typed in the file would be
    analysis::InputValue::Entry entry{key, text, 0, false, false, false};
    if (text == "true" || text == "false") {
      entry.is_boolean = true;
    } else if (io::is_bare_number(text)) {
      entry.is_number = true;
    } else {
      entry.is_string = true;
    }
    const auto at = std::find_if(t.entries.begin(), t.entries.end(),
                                 [&key = key](const auto& e) { return e.path == key; });
    if (at != t.entries.end()) {
      entry.line = at->line;
      *at = std::move(entry);
    } else {
      t.entries.push_back(std::move(entry));
    }
  }
  std::vector<io::RawInput> raw = io::raw_inputs(a, plain, issues, unread);
  for (TableValue& t : own) {
    io::RawInput r;
    r.key = t.key;
    r.type = io::RawInput::Type::kTable;
    r.text = "[" + t.key + "]";
    r.table = std::move(t.entries);
    r.tables = std::move(t.tables);
    r.source = std::move(t.source);
    raw.push_back(std::move(r));
  }
  return raw;
}

// catena::run with the shared tables as values (point_raw), bound as catena::run binds.
analysis::Record run_with_tables(const std::string& name, const InputSet& inputs,
                                 const std::vector<TableValue>& tables, const Progress* progress) {
  const analysis::Analysis* a = find_analysis(name);
  std::vector<Issue> issues;
  std::vector<std::string> unread;  // table parameters whose file could not be read
  const std::vector<io::RawInput> raw = point_raw(*a, inputs, tables, issues, unread);
  return io::bind_and_evaluate(*a, raw, std::move(issues), unread, progress);
}

// A point's estimated work (Analysis::work_of) and whether it allows large; no work for a point
// whose inputs do not bind (it fails on its own, before any work).
std::pair<double, bool> point_work(const analysis::Analysis& a, const SweepRequest& request,
                                   const InputSet& point) {
  std::vector<Issue> issues;
  std::vector<std::string> unread;
  const std::vector<io::RawInput> raw =
      point_raw(a, merged(request.base, point), request.tables, issues, unread);
  std::vector<Issue> bound;
  const analysis::Inputs in = io::bind(a, raw, bound);
  if (!issues.empty() || !bound.empty()) return {0.0, false};
  return {a.work_of(in), in.large_allowed()};
}

// The request's total work against kSweepWorkCaps per-run caps: an issue naming the limit and
// the estimate, unless every point that works allows large.
void check_total_work(const analysis::Analysis& a, const SweepRequest& request,
                      const std::vector<InputSet>& points, std::vector<Issue>& issues) {
  const analysis::Parameter* capped = nullptr;
  for (const analysis::Parameter& p : a.parameters)
    if (p.work.cap > 0) capped = &p;
  if (!a.work_of || capped == nullptr) return;
  double total = 0.0;
  bool allowed = true;
  for (const InputSet& point : points) {
    const auto [work, large] = point_work(a, request, point);
    total += work;
    if (work > 0.0) allowed = allowed && large;
  }
  const double cap = kSweepWorkCaps * static_cast<double>(capped->work.cap);
  if (total <= cap || allowed) return;
  const auto g = [](double x) { return analysis::format_g(x, 4); };
  issues.push_back(
      {"grid",
       std::to_string(points.size()) + " points, " + g(total) + " " + a.work_unit + " in all",
       "at most " + g(cap) + " " + a.work_unit + " in one sweep (" + g(kSweepWorkCaps) +
           " runs at the per-run cap of " + g(static_cast<double>(capped->work.cap)) + ", about " +
           g(capped->work.estimated_seconds(cap)) + " s of CPU; this one about " +
           g(capped->work.estimated_seconds(total)) + " s); allow_large = true in [analyses." +
           a.name + "] (or on every point) runs it anyway, or split the sweep"});
}

// Runs one point into its slot. Only InputError is the point's own: anything else is kept for
// the caller to rethrow.
// `layout` is the worker's last list of scalar names: points with the same names share it, so a
// long sweep holds its names once, not once per point.
void run_point(const SweepRequest& request, SweepPoint& point, bool keep,
               std::shared_ptr<const std::vector<ScalarName>>& layout, std::exception_ptr& failure,
               const Progress* progress) {
  try {
    const InputSet inputs = merged(request.base, point.inputs);
    analysis::Record record = request.tables.empty() ? run(request.analysis, inputs, progress)
                                                     : run_with_tables(request.analysis, inputs,
                                                                       request.tables, progress);
    point.scalars = scalars_of(record.data);
    if (layout && *layout == *point.scalars.names) {
      point.scalars.names = layout;
    } else {
      layout = point.scalars.names;
    }
    point.worst = worst_diagnostic(record.diagnostics);
    if (keep) point.record = std::move(record);
  } catch (const InputError& e) {
    point.error = e.what();
    point.issues = e.issues();
  } catch (...) {
    failure = std::current_exception();
  }
}

int rank(Diagnostic::Severity s) {
  switch (s) {
    case Diagnostic::Severity::kInfo:
      return 0;
    case Diagnostic::Severity::kWarning:
      return 1;
    case Diagnostic::Severity::kInfeasible:
      return 2;
    case Diagnostic::Severity::kError:
      return 3;
  }
  return 0;
}

std::string number_text(double v) {
  if (std::isnan(v)) return "";
  char buffer[64];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
  return ec == std::errc() ? std::string(buffer, end) : std::string();
}

std::string csv_cell(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

bool whole_number(std::string_view text, long long& out) {
  if (text.empty()) return false;
  const char* first = text.data();
  if (*first == '+') ++first;
  const auto [end, ec] = std::from_chars(first, text.data() + text.size(), out);
  return ec == std::errc() && end == text.data() + text.size();
}

std::string trimmed(std::string_view text) {
  const auto blank = [](char c) { return c == ' ' || c == '\t'; };
  while (!text.empty() && blank(text.front())) text.remove_prefix(1);
  while (!text.empty() && blank(text.back())) text.remove_suffix(1);
  return std::string(text);
}

}  // namespace

Scalars scalars_of(const Value& data) {
  std::vector<ScalarName> names;
  Scalars out;
  if (data.is_object()) scalar_walk(data, data, "", names, out.values);
  out.names = std::make_shared<const std::vector<ScalarName>>(std::move(names));
  return out;
}

std::optional<Diagnostic> worst_diagnostic(const std::vector<Diagnostic>& diagnostics) {
  const Diagnostic* worst = nullptr;
  for (const Diagnostic& d : diagnostics) {
    if (worst == nullptr || rank(d.severity) > rank(worst->severity)) worst = &d;
  }
  if (worst == nullptr) return std::nullopt;
  return *worst;
}

void share_table_files(SweepRequest& request, std::vector<Issue>& issues) {
  const analysis::Analysis* a = find_analysis(request.analysis);
  if (a == nullptr) return;  // sweep_points names it
  for (const analysis::Parameter& p : a->parameters) {
    if (p.type != analysis::ParameterType::kTable) continue;
    const std::string inside = p.name + ".";
    const auto names_inside = [&inside](const InputSet& set) {
      return std::any_of(set.begin(), set.end(),
                         [&inside](const auto& kv) { return kv.first.rfind(inside, 0) == 0; });
    };
    const bool looked_into =
        names_inside(request.base) ||
        std::any_of(request.points.begin(), request.points.end(), names_inside) ||
        std::any_of(request.grid.begin(), request.grid.end(),
                    [&inside](const SweepAxis& axis) { return axis.key.rfind(inside, 0) == 0; });
    const bool shared = std::any_of(request.tables.begin(), request.tables.end(),
                                    [&p](const TableValue& t) { return t.key == p.name; });
    if (!looked_into || shared) continue;
    const auto file_of = [&p](const InputSet& set) -> const std::string* {
      for (const auto& [key, text] : set)
        if (key == p.name) return &text;
      return nullptr;
    };
    const std::string* base_file = file_of(request.base);
    std::optional<std::string> file;
    bool one_file = true, everywhere = true;
    const auto take = [&](const std::string* text) {
      if (text == nullptr) {
        everywhere = false;
      } else if (!file) {
        file = *text;
      } else if (*file != *text) {
        one_file = false;
      }
    };
    if (request.points.empty()) take(base_file);
    for (const InputSet& point : request.points) {
      const std::string* own = file_of(point);
      take(own != nullptr ? own : base_file);
    }
    const std::string expected = "the path of one TOML file with a [" + p.name +
                                 "] table, the same for every point (a point names " + inside +
                                 "<key>); sweep each file on its own";
    if (!everywhere || !one_file) {
      issues.push_back(
          {p.name, !everywhere ? "(missing)" : "a different file in some points", expected});
      continue;
    }
    try {
      io::RawInput raw = io::table_input(io::read_case(*file), p);
      request.tables.push_back(
          {p.name, std::move(raw.table), std::move(raw.tables), std::move(raw.source)});
    } catch (const InputError& e) {
      for (const Issue& issue : e.issues())
        issues.push_back({p.name, *file,
                          "a readable TOML file with a [" + p.name + "] table (" + issue.field +
                              " = " + issue.value + ": " + issue.expected + ")"});
      continue;
    }
    const auto drop = [&p](InputSet& set) {
      std::erase_if(set, [&p](const auto& kv) { return kv.first == p.name; });
    };
    drop(request.base);
    for (InputSet& point : request.points) drop(point);
  }
}

std::vector<InputSet> sweep_points(const SweepRequest& request) {
  const analysis::Analysis* a = find_analysis(request.analysis);
  if (a == nullptr) {
    std::vector<std::string> names;
    for (const analysis::Analysis* each : analyses()) names.push_back(each->name);
    const auto near = io::did_you_mean(request.analysis, names);
    throw InputError(
        {{"analysis", quoted(request.analysis),
          "an analysis Catena has" + (near ? " (did you mean '" + *near + "'?)" : std::string())}});
  }
  std::vector<std::string> known;
  for (const analysis::Parameter& p : a->parameters) known.push_back(p.name);
  std::vector<Issue> issues;
  for (const auto& [key, text] : request.base) check_key(*a, known, key, text, issues);
  for (std::size_t i = 0; i < request.tables.size(); ++i) {
    const TableValue& t = request.tables[i];
    const analysis::Parameter* p = a->parameter(t.key);
    if (p == nullptr || p->type != analysis::ParameterType::kTable) {
      std::string names;
      for (const analysis::Parameter& each : a->parameters) {
        if (each.type == analysis::ParameterType::kTable)
          names += (names.empty() ? "" : ", ") + each.name;
      }
      issues.push_back({t.key, "(table)",
                        names.empty() ? "no table: '" + a->name + "' takes none"
                                      : "a table parameter of '" + a->name + "' (" + names + ")"});
    }
    const bool twice =
        std::any_of(request.tables.begin(), request.tables.begin() + static_cast<std::ptrdiff_t>(i),
                    [&t](const TableValue& o) { return o.key == t.key; }) ||
        std::any_of(request.base.begin(), request.base.end(),
                    [&t](const auto& kv) { return kv.first == t.key; });
    if (twice) issues.push_back({t.key, "(table)", "one value of the table (it is given twice)"});
  }
  if (!request.grid.empty() && !request.points.empty())
    issues.push_back({"points", "given with a grid", "a grid or a list of points, not both"});
  if (request.grid.empty() && request.points.empty())
    issues.push_back({"grid", "(missing)", "a grid or a list of points"});
  std::size_t total = 1;
  bool too_many = false;
  for (std::size_t i = 0; i < request.grid.size(); ++i) {
    const SweepAxis& axis = request.grid[i];
    check_key(*a, known, axis.key, "(grid)", issues, &request.tables);
    for (std::size_t j = 0; j < i; ++j) {
      if (request.grid[j].key == axis.key) {
        issues.push_back({axis.key, "(grid)", "one axis per input (it is swept twice)"});
        break;
      }
    }
    if (axis.values.empty()) issues.push_back({axis.key, "(grid)", "at least one value"});
    if (!axis.values.empty()) {
      // the product, or "more than the cap" once it could overflow
      if (too_many || total > std::numeric_limits<std::size_t>::max() / axis.values.size())
        too_many = true;
      else
        total *= axis.values.size();
    }
  }
  if (request.grid.empty()) total = request.points.size();
  if (too_many || total > kMaxPoints)
    issues.push_back({"grid",
                      too_many ? "more than " + std::to_string(kMaxPoints) + " points"
                               : std::to_string(total) + " points",
                      "at most " + std::to_string(kMaxPoints) +
                          " points in one sweep (~2.7 kB of memory each: 10^6 points ~2.7 GB); "
                          "split the study into several sweeps"});
  std::vector<std::string> unknown;  // each unknown key of the points once
  for (const InputSet& point : request.points) {
    for (const auto& [key, text] : point) {
      if (a->parameter(key) != nullptr || key == analysis::kAllowLarge ||
          std::find(unknown.begin(), unknown.end(), key) != unknown.end())
        continue;
      unknown.push_back(key);
      check_key(*a, known, key, text, issues, &request.tables);
    }
  }
  // A shared value that no point replaces and that does not read (a unit, a number) would fail
  // every point alike: it is the request's problem.
  for (const auto& [key, text] : request.base) {
    const analysis::Parameter* p = a->parameter(key);
    const bool swept =
        std::any_of(request.grid.begin(), request.grid.end(),
                    [&key = key](const SweepAxis& axis) { return axis.key == key; }) ||
        std::any_of(request.points.begin(), request.points.end(), [&key = key](const InputSet& s) {
          return std::any_of(s.begin(), s.end(), [&](const auto& kv) { return kv.first == key; });
        });
    if (p == nullptr || swept) continue;
    const bool is_flag = p->type == analysis::ParameterType::kFlag;
    for (Issue& issue :
         io::value_issues(*p, {key,
                               text,
                               is_flag ? io::RawInput::Type::kBoolean : io::RawInput::Type::kText,
                               {},
                               {},
                               {}}))
      issues.push_back(std::move(issue));
  }
  throw_if_any(issues);

  if (request.grid.empty()) {
    check_total_work(*a, request, request.points, issues);
    throw_if_any(issues);
    return request.points;
  }
  std::vector<InputSet> out;
  out.reserve(total);
  std::vector<std::size_t> index(request.grid.size(), 0);
  for (std::size_t n = 0; n < total; ++n) {
    InputSet point;
    point.reserve(request.grid.size());
    for (std::size_t k = 0; k < request.grid.size(); ++k)
      point.emplace_back(request.grid[k].key, request.grid[k].values[index[k]]);
    out.push_back(std::move(point));
    // the last axis varies fastest
    for (std::size_t k = request.grid.size(); k-- > 0;) {
      if (++index[k] < request.grid[k].values.size()) break;
      index[k] = 0;
    }
  }
  check_total_work(*a, request, out, issues);
  throw_if_any(issues);
  return out;
}

void check_threads(unsigned threads, std::string_view field, std::vector<Issue>& issues) {
  if (threads > kMaxSweepThreads)
    issues.push_back({std::string(field), std::to_string(threads),
                      "0 (every hardware thread) to " + std::to_string(kMaxSweepThreads)});
}

SweepResult sweep(const SweepRequest& request, const SweepOptions& options) {
  std::vector<Issue> issues;
  check_threads(options.threads, "threads", issues);
  std::vector<InputSet> points;
  try {
    points = sweep_points(request);
  } catch (const InputError& e) {
    issues.insert(issues.begin(), e.issues().begin(), e.issues().end());
  }
  if (!issues.empty()) throw InputError(std::move(issues));
  SweepResult result;
  result.analysis = request.analysis;
  if (!request.grid.empty()) {
    for (const SweepAxis& axis : request.grid) result.keys.push_back(axis.key);
  } else {
    for (const InputSet& point : points) {
      for (const auto& kv : point) {
        if (std::find(result.keys.begin(), result.keys.end(), kv.first) == result.keys.end())
          result.keys.push_back(kv.first);
      }
    }
  }
  const std::size_t total = points.size();
  result.points.resize(total);
  for (std::size_t i = 0; i < total; ++i) result.points[i].inputs = std::move(points[i]);

  unsigned threads = options.threads != 0 ? options.threads : std::thread::hardware_concurrency();
  threads = std::max(1u, threads);
  if (threads > total) threads = static_cast<unsigned>(std::max<std::size_t>(total, 1));

  // Each point has its own slot; workers take the next index from one counter, so which thread
  // runs a point changes nothing in its slot.
  std::vector<std::exception_ptr> failures(total);
  std::atomic<std::size_t> next{0};
  std::atomic<std::size_t> done{0};
  std::mutex mutex;
  std::condition_variable finished;
  const bool keep = options.keep_records;
  // each point's run polls the cancel flag too (the points report no progress of their own)
  Progress point_progress;
  point_progress.cancel = options.cancel;
  const Progress* listen = options.cancel != nullptr ? &point_progress : nullptr;
  auto work = [&] {
    std::shared_ptr<const std::vector<ScalarName>> layout;
    for (;;) {
      if (point_progress.cancelled()) break;
      const std::size_t i = next.fetch_add(1, std::memory_order_relaxed);
      if (i >= total) break;
      run_point(request, result.points[i], keep, layout, failures[i], listen);
      // a point the cancel stopped is not done (its run threw Cancelled into its slot): it is
      // neither counted nor reported
      if (point_progress.cancelled()) break;
      if (done.fetch_add(1, std::memory_order_acq_rel) + 1 == total) {
        const std::lock_guard<std::mutex> lock(mutex);
        finished.notify_all();
      }
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(threads);
  try {
    for (unsigned t = 0; t < threads; ++t) pool.emplace_back(work);
  } catch (...) {
    next.store(total);  // no more points for the threads that did start
    for (std::thread& t : pool) t.join();
    throw;
  }
  {
    std::unique_lock<std::mutex> lock(mutex);
    std::size_t reported = std::numeric_limits<std::size_t>::max();
    for (;;) {
      if (point_progress.cancelled()) break;  // no report after the cancel
      const std::size_t now = done.load(std::memory_order_acquire);
      if (options.progress && now != reported) {
        lock.unlock();
        options.progress(now, total);
        lock.lock();
        reported = now;
      }
      if (now == total || point_progress.cancelled()) break;
      finished.wait_for(lock, std::chrono::milliseconds(50));
    }
  }
  for (std::thread& t : pool) t.join();
  // a cancelled sweep returns nothing, though some points may have run
  point_progress.throw_if_cancelled();
  for (const std::exception_ptr& failure : failures) {
    if (failure) std::rethrow_exception(failure);
  }
  return result;
}

SweepTable sweep_table(const SweepResult& result) {
  SweepTable table;
  const std::size_t rows = result.points.size();
  for (const std::string& key : result.keys) table.inputs.push_back({key, {}});
  // result columns: the union of every layout's names, in order of first appearance
  std::map<std::string, std::size_t> column_of;
  const std::vector<ScalarName>* last_layout = nullptr;
  for (const SweepPoint& p : result.points) {
    if (!p.ok() || !p.scalars.names || p.scalars.names.get() == last_layout) continue;
    last_layout = p.scalars.names.get();
    for (const ScalarName& n : *p.scalars.names) {
      if (column_of.emplace(n.path, table.results.size()).second)
        table.results.push_back({n.path, n.unit, {}});
    }
  }
  for (auto& column : table.results) column.values.assign(rows, NAN);
  for (auto* text : {&table.severity, &table.code, &table.error}) text->values.resize(rows);
  for (auto& column : table.inputs) column.values.resize(rows);
  std::vector<std::size_t> map;  // layout index → column, for the current layout
  last_layout = nullptr;
  for (std::size_t r = 0; r < rows; ++r) {
    const SweepPoint& p = result.points[r];
    for (std::size_t k = 0; k < result.keys.size(); ++k) {
      for (const auto& [key, text] : p.inputs) {
        if (key == result.keys[k]) table.inputs[k].values[r] = text;
      }
    }
    if (!p.ok()) {
      std::string line;  // the problems on one line: one cell, one CSV row
      for (const Issue& issue : p.issues) line += (line.empty() ? "" : "; ") + to_string(issue);
      table.error.values[r] = line.empty() ? p.error : line;
      continue;
    }
    if (p.scalars.names && p.scalars.names.get() != last_layout) {
      last_layout = p.scalars.names.get();
      map.clear();
      for (const ScalarName& n : *last_layout) map.push_back(column_of.at(n.path));
    }
    for (std::size_t i = 0; i < p.scalars.values.size() && i < map.size(); ++i)
      table.results[map[i]].values[r] = p.scalars.values[i];
    if (p.worst) {
      table.severity.values[r] = to_string(p.worst->severity);
      table.code.values[r] = p.worst->code;
    }
  }
  return table;
}

std::string sweep_csv(const SweepTable& table) {
  std::string out;
  bool first = true;
  const auto cell = [&](const std::string& text) {
    if (!first) out += ',';
    first = false;
    out += csv_cell(text);
  };
  for (const auto& c : table.inputs) cell(c.name);
  for (const auto& c : table.results) cell(c.unit.empty() ? c.name : c.name + " [" + c.unit + "]");
  for (const auto* c : {&table.severity, &table.code, &table.error}) cell(c->name);
  out += '\n';
  for (std::size_t r = 0; r < table.rows(); ++r) {
    first = true;
    for (const auto& c : table.inputs) cell(c.values[r]);
    for (const auto& c : table.results) cell(number_text(c.values[r]));
    for (const auto* c : {&table.severity, &table.code, &table.error}) cell(c->values[r]);
    out += '\n';
  }
  return out;
}

std::optional<SweepAxis> parse_axis(std::string_view text, std::string_view field,
                                    std::vector<Issue>& issues) {
  const auto fail = [&](const std::string& expected) -> std::optional<SweepAxis> {
    issues.push_back({std::string(field), quoted(text), expected});
    return std::nullopt;
  };
  const std::size_t equals = text.find('=');
  if (equals == std::string_view::npos || trimmed(text.substr(0, equals)).empty())
    return fail("key=a:b, key=a:b:step or key=v1,v2,... (e.g. teeth=6:20, pin_diameter=30mm,40mm)");
  SweepAxis axis;
  axis.key = trimmed(text.substr(0, equals));
  const std::string_view values = text.substr(equals + 1);
  if (values.find(':') != std::string_view::npos) {
    std::vector<std::string_view> parts;
    std::size_t start = 0;
    for (std::size_t i = 0; i <= values.size(); ++i) {
      if (i == values.size() || values[i] == ':') {
        parts.push_back(values.substr(start, i - start));
        start = i + 1;
      }
    }
    long long from = 0, to = 0, step = 1;
    const bool ok = (parts.size() == 2 || parts.size() == 3) &&
                    whole_number(trimmed(parts[0]), from) && whole_number(trimmed(parts[1]), to) &&
                    (parts.size() == 2 || whole_number(trimmed(parts[2]), step));
    if (!ok) return fail("a range of whole numbers a:b or a:b:step (e.g. 6:20, 6:20:2)");
    if (step <= 0) return fail("a step > 0 in a:b:step");
    if (to < from) return fail("a range a:b with a ≤ b");
    const unsigned long long count =
        (static_cast<unsigned long long>(to - from)) / static_cast<unsigned long long>(step) + 1;
    if (count > kMaxPoints)
      return fail("at most " + std::to_string(kMaxPoints) + " values in a range");
    for (long long v = from; v <= to; v += step) {
      axis.values.push_back(std::to_string(v));
      if (to - v < step) break;  // no overflow past `to`
    }
    return axis;
  }
  std::size_t start = 0;
  for (std::size_t i = 0; i <= values.size(); ++i) {
    if (i == values.size() || values[i] == ',') {
      axis.values.push_back(trimmed(values.substr(start, i - start)));
      start = i + 1;
    }
  }
  for (const std::string& v : axis.values) {
    if (v.empty())
      return fail("a comma-separated list of values without empty ones (e.g. 30mm,40mm,50mm)");
  }
  return axis;
}

}  // namespace catena
