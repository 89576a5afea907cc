// catena run CASE / catena report [CASE]: the command-line front of the library's case runner
// (catena/io/case_run.hpp): which file, which output. Nothing here knows a model or the schema.
#include <CLI/CLI.hpp>
#include <iostream>

#include "catena/io/case_file.hpp"
#include "catena/io/case_run.hpp"
#include "catena/io/record.hpp"
#include "catena/io/report.hpp"
#include "cli_support.hpp"
#include "commands.hpp"

namespace catena::cli {

std::string_view plotly_js();          // embedded web/node_modules/plotly.js-dist-min/plotly.min.js
std::string_view default_case_toml();  // embedded examples/000_thesis_rolling_hinge.toml

namespace {

struct CaseFlags {
  std::string path, output, format = "html";
  CLI::Option* case_option = nullptr;  ///< given at all: `catena run ""` names no file
};

io::CaseFile load(const CaseFlags& f) {
  if (f.case_option->count() == 0)
    return io::parse_case(default_case_toml(), "built-in:000_thesis_rolling_hinge.toml");
  return io::read_case(f.path);
}

// Runs the case with the bar on a terminal naming the analysis that runs ("catena run ring
// [###...]"), and Ctrl-C.
io::CaseRun run_listening(const CaseFlags& f, const std::string& command) {
  const io::CaseFile file = load(f);
  ProgressBar bar;
  const Progress progress = listen(bar, command, true);
  return io::run_case(file, &progress);
}

// Each analysis' error diagnostics on stderr, named by its table (the exit status stays 0).
void report_case_errors(const io::CaseRun& run) {
  for (const io::AnalysisRun& each : run.runs)
    report_errors(each.record.diagnostics, "analyses." + each.name);
}

}  // namespace

std::function<int()> add_run(CLI::App& app) {
  auto f = std::make_shared<CaseFlags>();
  CLI::App* c = app.add_subcommand(
      "run", "Run every analysis of a case file; print the JSON result tree (SI, with units)");
  f->case_option =
      c->add_option("CASE", f->path, "TOML case file (docs/case_files.md)")->required();
  c->add_option("-o,--output", f->output, "write the JSON to FILE instead of stdout");
  return [f]() {
    const io::CaseRun run = run_listening(*f, "run");
    write_text_output(f->output, io::to_json(io::result_tree(run, CATENA_VERSION)), f->path);
    report_case_errors(run);
    return 0;
  };
}

std::function<int()> add_report(CLI::App& app) {
  auto f = std::make_shared<CaseFlags>();
  CLI::App* c = app.add_subcommand(
      "report",
      "Run a case file and write one self-contained HTML report (no CASE: the built-in thesis "
      "rolling-hinge conveyor chain)");
  f->case_option =
      c->add_option("CASE", f->path, "TOML case file (docs/case_files.md); default: built-in case");
  c->add_option("-o,--output", f->output, "the report file (default report.html; json: stdout)");
  c->add_option("--format", f->format, "html (default) or json (the whole result tree)")
      ->check(CLI::IsMember({"html", "json"}));
  return [f]() {
    const io::CaseRun run = run_listening(*f, "report");
    if (f->format == "json") {
      write_text_output(f->output, io::to_json(io::result_tree(run, CATENA_VERSION)), f->path);
      report_case_errors(run);
      return 0;
    }
    const std::string path = f->output.empty() ? "report.html" : f->output;
    Outputs outputs;
    if (!f->path.empty()) outputs.keep("CASE", f->path);
    outputs.add("--output", path, io::to_html(io::build_report(run, CATENA_VERSION), plotly_js()));
    outputs.commit();
    std::cerr << "catena: wrote " << path << " (" << run.runs.size()
              << (run.runs.size() == 1 ? " analysis)\n" : " analyses)\n");
    report_case_errors(run);
    return 0;
  };
}

}  // namespace catena::cli
