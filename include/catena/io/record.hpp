// Writers from an analysis Record: JSON (the field names, nesting and `units` of every command's
// contract), CSV, and the report section. No model-specific output code lives here: whatever an
// analysis shows, its `describe` put into the Record.
#pragma once

#include <string>
#include <vector>

#include "catena/analysis/analysis.hpp"
#include "catena/io/report.hpp"

namespace catena::io {

/// The value as JSON text, indented by `indent` spaces (-1: one line), with a final newline when
/// indented. Reals print as the shortest text that reads back exactly; non-finite reals as null.
std::string to_json(const analysis::Value& value, int indent = 2);

/// Parses JSON text into a Value (numbers with a fraction or exponent become reals).
analysis::Value parse_json(const std::string& text);

/// CSV: a header of column names, then one row per sample, each number with 12 significant
/// digits. Columns must have equal lengths.
std::string to_csv(const std::vector<analysis::Column>& columns);

using analysis::Display;
using analysis::display;

/// The report section of one analysis run: results table (every scalar of `record.data` in
/// display units, named by its path), sweep grid (`rows`/`best`), the record's grids, charts and
/// drawings, its diagnostics.
ReportSection report_section(const analysis::Record& record, const std::string& id,
                             const std::string& title, const std::string& docs);

/// `value` with the formatting of report cells: %.6g for numbers (times `scale`), yes/no, —
/// for null.
std::string format_cell(const analysis::Value& value, double scale = 1.0);

}  // namespace catena::io
