// Subcommands of the catena program. Each registers its flags and returns the action to run.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/io/bind.hpp"

namespace CLI {
class App;
}

namespace catena::analysis {
struct Analysis;
}

namespace catena::cli {

/// Registers the subcommand of an analysis of the registry (its path `analysis.command` under
/// `root`), with a flag per parameter and the output options it offers; the returned action
/// binds, runs, describes and writes, and returns the exit code.
std::function<int()> add_analysis(CLI::App& root, const analysis::Analysis& analysis);

/// Registers the subcommand of every analysis of the registry on `app`; returns their actions by
/// top-level name (a sub-command's action runs from its parent's when its own name was parsed).
std::map<std::string, std::function<int()>> register_analyses(CLI::App& app);
/// Registers `catena run CASE` (JSON result tree) and `catena report [CASE]` (HTML report).
std::function<int()> add_run(CLI::App& app);
std::function<int()> add_report(CLI::App& app);
/// Registers `catena sweep CASE --grid KEY=VALUES ...` (CSV, one row per point).
std::function<int()> add_sweep(CLI::App& app);

/// One analysis' inputs as a case file gives them to `catena run`: its [analyses.<name>] table,
/// the shared tables, what the chain type implies; each value with the case path it came from.
struct CaseInputs {
  const analysis::Analysis* analysis = nullptr;  ///< nullptr when `name` names none
  std::vector<io::RawInput> raw;
  std::map<std::string, std::string> path_of;  ///< parameter key → case-file path
};
/// The inputs of the analysis table `name` ("hinge", "pocketwheel-free"; the table may be absent:
/// the shared tables still apply). Problems of the file's structure, its chain type and the
/// table's keys are appended, named by case-file path.
CaseInputs case_inputs(const io::CaseFile& file, const std::string& name,
                       std::vector<Issue>& issues);
/// The [analyses.<name>] tables of `file`, in file order.
std::vector<std::string> analysis_tables(const io::CaseFile& file);

}  // namespace catena::cli
