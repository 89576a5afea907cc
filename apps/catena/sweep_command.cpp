// catena sweep CASE --grid KEY=VALUES ...: one analysis of a case file over a grid of values, on
// the library's thread pool (catena/sweep.hpp), written as CSV — one row per point: the swept
// inputs, the scalar results, the worst diagnostic. The case gives the analysis and the values
// every point shares exactly as `catena run` binds them, the tables it reads ([dynamics], [loop])
// included; the grid keys are case paths (analyses.hinge.teeth, or a value inside the analysis'
// table: dynamics.sprocket[1].load_torque) or, when the case has one analysis table, bare keys
// (teeth).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>

#include "catena/catena.hpp"
#include "catena/io/case_file.hpp"
#include "catena/io/case_run.hpp"
#include "catena/sweep.hpp"
#include "cli_support.hpp"
#include "commands.hpp"

namespace catena::cli {
namespace {

struct SweepFlags {
  std::string path, output;
  std::vector<std::string> grid;
  unsigned threads = 0;
};

// One --grid as the user typed it, and what it sweeps.
struct GridFlag {
  std::string flag;   ///< "--grid analyses.hinge.teeth": how problems name it
  std::string table;  ///< the analysis table it names ("" for a bare key)
  SweepAxis axis;     ///< key: the parameter key, or a case path inside an analysis' table
  std::string text;   ///< the --grid text of a case path outside [analyses] (dynamics.duration)
};

std::vector<GridFlag> read_grid(const std::vector<std::string>& texts, std::vector<Issue>& issues) {
  std::vector<GridFlag> out;
  const std::string prefix = "analyses.";
  for (const std::string& text : texts) {
    std::optional<SweepAxis> axis = parse_axis(text, "--grid", issues);
    if (!axis) continue;
    GridFlag g{"--grid " + axis->key, "", *axis};
    if (axis->key.rfind(prefix, 0) == 0) {
      const std::string rest = axis->key.substr(prefix.size());
      const std::size_t dot = rest.find('.');
      if (dot == std::string::npos || dot == 0 || dot + 1 == rest.size()) {
        issues.push_back({"--grid", "'" + text + "'",
                          "analyses.<name>.<key>=values (e.g. analyses.hinge.teeth=6:20)"});
        continue;
      }
      g.table = rest.substr(0, dot);
      g.axis.key = rest.substr(dot + 1);
    } else if (axis->key.find('.') != std::string::npos) {
      g.text = text;  // a value in a table of the case (dynamics.duration), or refused below
    }
    out.push_back(std::move(g));
  }
  return out;
}

// The analysis table the grid sweeps: the one its keys name, or the case's only one.
std::string table_of(const std::vector<GridFlag>& grid, const io::CaseFile& file,
                     std::vector<Issue>& issues) {
  std::string table;
  for (const GridFlag& g : grid) {
    if (g.table.empty()) continue;
    if (table.empty()) {
      table = g.table;
    } else if (g.table != table) {
      issues.push_back({g.flag, "(grid)",
                        "keys of one analysis: the grid also sweeps analyses." + table +
                            " (one sweep runs one analysis)"});
    }
  }
  if (!table.empty()) return table;
  const std::vector<std::string> tables = io::analysis_tables(file);
  if (tables.size() == 1) return tables.front();
  std::string names;
  for (const std::string& t : tables) names += (names.empty() ? "" : ", ") + t;
  issues.push_back(
      {"--grid", "(no analysis named)",
       tables.empty()
           ? std::string("analyses.<name>.<key>=values: the case has no analysis table")
           : "analyses.<name>.<key>=values naming one of the case's analyses (" + names + ")"});
  return "";
}

}  // namespace

std::function<int()> add_sweep(CLI::App& app) {
  auto f = std::make_shared<SweepFlags>();
  CLI::App* c = app.add_subcommand(
      "sweep",
      "Run one analysis of a case file over a grid of values; write CSV, one row per point "
      "(swept inputs, scalar results in SI, worst diagnostic)");
  c->add_option("CASE", f->path,
                "TOML case file (docs/case_files.md): the analysis and the values "
                "every point shares")
      ->required();
  c->add_option("--grid", f->grid,
                "KEY=a:b (whole numbers, inclusive), KEY=a:b:step or KEY=v1,v2,... (texts with "
                "units: 30mm,40mm); KEY is analyses.<name>.<key>, or <key> when the case has one "
                "analysis, or a value in the table the analysis reads "
                "(dynamics.sprocket[1].load_torque); repeat for more axes (the first varies "
                "slowest)")
      ->required();
  c->add_option("--threads", f->threads, "worker threads (default 0: every hardware thread)");
  c->add_option("-o,--output", f->output, "write the CSV to FILE instead of stdout");
  return [f]() {
    std::vector<Issue> issues;
    std::optional<io::CaseFile> file;
    try {
      file = io::read_case(f->path);
    } catch (const InputError& e) {  // listed with the grid's problems
      issues.insert(issues.end(), e.issues().begin(), e.issues().end());
    }
    const std::vector<GridFlag> grid = read_grid(f->grid, issues);
    const std::string table = file ? table_of(grid, *file, issues) : "";
    io::CaseInputs inputs;
    if (!table.empty()) inputs = io::case_inputs(*file, table, issues);

    SweepRequest request;
    std::map<std::string, std::string> flag_of;  // parameter key → the --grid that sweeps it
    if (inputs.analysis != nullptr) {
      // the analysis' tables ([dynamics], wear's [loop]) go to every point as the case has them
      for (const io::RawInput& raw : inputs.raw) {
        if (raw.type == io::RawInput::Type::kTable)
          request.tables.push_back({raw.key, raw.table, raw.tables, raw.source});
      }
      for (const analysis::Parameter& p : inputs.analysis->parameters) {
        const bool given = std::any_of(request.tables.begin(), request.tables.end(),
                                       [&p](const TableValue& t) { return t.key == p.name; });
        if (p.type == analysis::ParameterType::kTable && p.required && !given)
          issues.push_back({p.name, "(missing)", p.expected.empty() ? "a table" : p.expected});
      }
    }
    for (const GridFlag& g : grid) {
      if (!g.table.empty() && g.table != table) continue;  // refused above
      if (!g.text.empty()) {  // a case path outside [analyses]: inside one of the tables passed
        const std::string head = g.axis.key.substr(0, g.axis.key.find('.'));
        const bool in_table = std::any_of(request.tables.begin(), request.tables.end(),
                                          [&head](const TableValue& t) { return t.key == head; });
        if (!in_table) {
          issues.push_back({"--grid", "'" + g.text + "'",
                            request.tables.empty()
                                ? "an input of the analysis: a key (teeth) or analyses.<name>.<key>"
                                : "an input of the analysis: a key, analyses.<name>.<key> or a "
                                  "value of its table (" +
                                      request.tables.front().key + ".<key>)"});
          continue;
        }
      }
      request.grid.push_back(g.axis);
      flag_of.emplace(g.axis.key, g.flag);
    }
    if (inputs.analysis != nullptr) {
      request.analysis = inputs.analysis->name;
      for (const io::RawInput& raw : inputs.raw) {
        if (raw.type == io::RawInput::Type::kTable) continue;
        // a value no point replaces must read as `catena run` reads it (its TOML type too)
        const analysis::Parameter* p = inputs.analysis->parameter(raw.key);
        if (p != nullptr && !flag_of.count(raw.key)) {
          for (Issue issue : io::value_issues(*p, raw)) {
            const auto path = inputs.path_of.find(issue.field);
            if (path != inputs.path_of.end()) issue.field = path->second;
            issues.push_back(std::move(issue));
          }
        }
        request.base.emplace_back(raw.key, raw.text);
      }
      try {
        sweep_points(request);
      } catch (const InputError& e) {
        for (Issue issue : e.issues()) {
          const auto path = inputs.path_of.find(issue.field);
          const auto swept = flag_of.find(issue.field);
          if (swept != flag_of.end()) {
            issue.field = swept->second;
          } else if (issue.field == "grid") {
            issue.field = "--grid";  // the number of points
          } else if (path != inputs.path_of.end()) {
            continue;  // a shared value's problem: reported above, by its path
          }
          issues.push_back(std::move(issue));
        }
      }
    }
    check_threads(f->threads, "--threads", issues);
    throw_if_any(issues);

    ProgressBar bar;
    SweepOptions options;
    options.threads = f->threads;
    options.keep_records = false;
    options.cancel = interrupt_flag();
    if (bar.terminal()) {
      options.progress = [&bar](std::size_t done, std::size_t total) {
        bar.draw("sweep", done, total, "points");
      };
    }
    const SweepResult result = sweep(request, options);
    bar.finish();
    std::size_t failed = 0;
    for (const SweepPoint& p : result.points) failed += p.ok() ? 0 : 1;
    write_text_output(f->output, sweep_csv(sweep_table(result)), f->path);
    if (failed > 0) {
      std::cerr << "catena: " << failed << " of " << result.points.size()
                << " points did not run (the error column says why)\n";
    }
    if (!f->output.empty()) {
      std::cerr << "catena: wrote " << result.points.size() << " points to " << f->output << "\n";
    }
    return 0;
  };
}

}  // namespace catena::cli
