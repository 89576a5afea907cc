// Subcommands of the catena program. Each registers its flags and returns the action to run.
#pragma once

#include <functional>
#include <map>
#include <string>

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
/// Registers `catena ring` (seed 002 composite link).
std::function<int()> add_ring(CLI::App& app);

/// Register `capacity` (eq. (9), mass comparison) and `design` (sizing) as subcommands of the
/// given `catena ring` App; the ring action runs the returned action when its subcommand parsed.
std::function<int()> add_ring_capacity(CLI::App& ring);
std::function<int()> add_ring_design(CLI::App& ring);

/// Registers every analysis subcommand above on `app`; returns their actions by name. The case
/// runner uses it too: a model added here (and described in case_command.cpp's registry) is
/// reachable from case files and reports.
std::map<std::string, std::function<int()>> register_analyses(CLI::App& app);
/// Registers `catena run CASE` (JSON result tree) and `catena report [CASE]` (HTML report).
std::function<int()> add_run(CLI::App& app);
std::function<int()> add_report(CLI::App& app);

}  // namespace catena::cli
