// The case runner: a parsed case file (io/case_file.hpp) bound onto the registry's parameter
// tables, every analysis it names run, and the result as one JSON tree or one HTML report. The
// analysis-independent schema (chain types, shared tables [chain] [sprocket] [loads] [material],
// descriptive keys) lives here; everything about an analysis comes from the registry. Used by
// `catena run`, `catena report` and the Python module; docs/case_files.md describes the schema.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "catena/analysis/analysis.hpp"
#include "catena/io/case_file.hpp"
#include "catena/io/report.hpp"

namespace catena::io {

/// One analysis of a case, run.
struct AnalysisRun {
  const analysis::Analysis* analysis = nullptr;
  std::string name;  ///< the table's name: the analysis', or "<name>-<label>"
  analysis::Record record;
};

/// A case file and its runs, in the file's order of [analyses.<name>] tables.
struct CaseRun {
  CaseFile file;
  std::string hash;  ///< SHA-256 of the file's bytes, hex
  std::vector<AnalysisRun> runs;
};

/// Binds every [analyses.<name>] table of `file` (with the shared tables and what chain.type
/// implies) and runs it. Throws InputError listing every problem of the whole file at once,
/// each named by its case-file path.
CaseRun run_case(const CaseFile& file);

/// The JSON result tree of `catena run`: catena_version, case, case_sha256, title, analyses.
analysis::Value result_tree(const CaseRun& run, std::string_view version);

/// The report sections of analysis runs, in order.
std::vector<ReportSection> report_sections(const std::vector<AnalysisRun>& runs);

/// The HTML report's content for a case: its title, hash, inputs as typed, one section per run.
Report build_report(const CaseRun& run, std::string_view version);

}  // namespace catena::io
