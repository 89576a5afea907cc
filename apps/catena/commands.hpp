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
/// Registers `catena hinge` (and `catena hinge sweep`).
std::function<int()> add_hinge(CLI::App& app);
/// Registers `catena contact` and `catena fretting`.
std::function<int()> add_contact(CLI::App& app);
std::function<int()> add_fretting(CLI::App& app);
/// Registers `catena warp` (roller warp, seed 000 §1.4).
std::function<int()> add_warp(CLI::App& app);
/// Registers `catena strength` (roller and plate strength checks, seed 000 §1.5).
std::function<int()> add_strength(CLI::App& app);
/// Registers `catena engagement`.
std::function<int()> add_engagement(CLI::App& app);
/// Registers `catena loop FILE` (conveyor loop tensions, seed 000 §1.5 fig. 19). It reads the
/// [loop] table of a TOML file, so the case runner hands it the case file's path.
std::function<int()> add_loop(CLI::App& app);
/// The unit a bare number takes at a [loop] path ("loop.segment[2].length" → "m"), for reports.
std::string loop_bare_unit(const std::string& path);

/// Registers every analysis subcommand above on `app`; returns their actions by name. The case
/// runner uses it too: a model added here (and described in case_command.cpp's registry) is
/// reachable from case files and reports.
std::map<std::string, std::function<int()>> register_analyses(CLI::App& app);
/// Registers `catena run CASE` (JSON result tree) and `catena report [CASE]` (HTML report).
std::function<int()> add_run(CLI::App& app);
std::function<int()> add_report(CLI::App& app);

}  // namespace catena::cli
