// Subcommands of the catena program. Each registers its flags and returns the action to run.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

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

}  // namespace catena::cli
