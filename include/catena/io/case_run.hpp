// The case runner: a parsed case file (io/case_file.hpp) bound onto the registry's parameter
// tables, every analysis it names run, and the result as one JSON tree or one HTML report. The
// analysis-independent schema (chain types, shared tables [chain] [sprocket] [loads] [material],
// descriptive keys) lives here; everything about an analysis comes from the registry. Used by
// `catena run`, `catena report` and the Python module; docs/case_files.md describes the schema.
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "catena/analysis/analysis.hpp"
#include "catena/core/error.hpp"
#include "catena/io/bind.hpp"
#include "catena/io/case_file.hpp"
#include "catena/io/report.hpp"

namespace catena::io {

/// One analysis of a case, run.
struct AnalysisRun {
  const analysis::Analysis* analysis = nullptr;
  std::string name;  ///< the table's name: the analysis', or "<name>-<label>"
  analysis::Record record;
  std::string note;  ///< the table's `note`: what this run shows, for the report's reader
};

/// A case file and its runs, in the file's order of [analyses.<name>] tables.
struct CaseRun {
  CaseFile file;
  std::string hash;  ///< SHA-256 of the file's bytes, hex
  std::vector<AnalysisRun> runs;
};

/// One analysis' inputs as a case file gives them to `catena run`: its [analyses.<name>] table,
/// the shared tables, what the chain type implies; each value with the case path it came from.
/// Used by `catena sweep` to bind a case's values for one analysis.
struct CaseInputs {
  const analysis::Analysis* analysis = nullptr;  ///< nullptr when `name` names none
  std::vector<RawInput> raw;
  std::map<std::string, std::string> path_of;  ///< parameter key → case-file path
};
/// The inputs of the analysis table `name` ("hinge", "pocketwheel-free"; the table may be absent:
/// the shared tables still apply). Problems of the file's structure, its chain type and the
/// table's keys are appended, named by case-file path.
CaseInputs case_inputs(const CaseFile& file, const std::string& name, std::vector<Issue>& issues);
/// The [analyses.<name>] tables of `file`, in file order.
std::vector<std::string> analysis_tables(const CaseFile& file);

/// Binds every [analyses.<name>] table of `file` (with the shared tables and what chain.type
/// implies) and runs it. Throws InputError listing every problem of the whole file at once,
/// each named by its case-file path. Each run reports to and stops on `progress` (when given):
/// a cancelled case throws Cancelled (catena/core/progress.hpp) and returns no runs.
CaseRun run_case(const CaseFile& file, const Progress* progress = nullptr);

/// The JSON result tree of `catena run`: catena_version, case, case_sha256, title, analyses.
analysis::Value result_tree(const CaseRun& run, std::string_view version);

/// The report sections of analysis runs, in order.
std::vector<ReportSection> report_sections(const std::vector<AnalysisRun>& runs);

/// The HTML report's content for a case: its title, hash, inputs as typed, one section per run.
Report build_report(const CaseRun& run, std::string_view version);

}  // namespace catena::io
