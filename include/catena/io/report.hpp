// The engineering report: one self-contained HTML file (inputs, results tables, interactive
// charts, drawings, diagnostics, sources) that opens offline. The charting library's script is
// passed in by the caller and written into the file, so the file needs no network.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "catena/analysis/record.hpp"

namespace catena::io {

/// A row of a results or inputs table: what, value (already formatted), unit.
struct ReportRow {
  std::string name, value, unit;
};

struct ReportTable {
  std::string title;
  std::vector<ReportRow> rows;
};

/// Tables with columns, charts and their curves: the analysis Record's types.
using ReportGrid = analysis::Grid;
using ReportTrace = analysis::Trace;
using ReportChart = analysis::Chart;

/// A finding about the design: severity ("error", "warning", "note"), message, limit.
struct ReportDiagnostic {
  std::string severity, message, limit;
};

/// What a drawing of the report shows: caption, legend (layer name and colour 0xRRGGBB) and
/// the length of its scale bar in mm (0: none).
struct ReportDrawingKey {
  std::string caption;
  std::vector<std::pair<std::string, unsigned>> legend;
  double scale_bar_mm = 0.0;
};

/// One analysis of the case.
struct ReportSection {
  std::string id;      ///< HTML anchor, [a-z0-9_-]
  std::string title;   ///< "Rolling-friction hinge (seed 000 §1.2–1.3)"
  std::string source;  ///< where the equations come from
  std::string docs;    ///< documentation page, relative to the repository ("docs/models/hinge.md")
  std::string note;    ///< the case's words on this run (its table's `note`); may be empty
  std::vector<ReportDiagnostic> diagnostics;
  std::vector<ReportTable> tables;
  std::vector<ReportGrid> grids;
  std::vector<ReportChart> charts;
  std::vector<std::string> drawings_svg;  ///< complete SVG documents, inlined
  /// Per drawing (same order; may be shorter): its caption, its layers with their colours and
  /// the length of the scale bar drawn into it.
  std::vector<ReportDrawingKey> drawing_keys;
  std::string failure;  ///< the analysis could not run: why (then the rest is empty)
};

struct Report {
  std::string title;              ///< the case's title
  std::string case_name;          ///< file name or "built-in"
  std::string case_hash;          ///< SHA-256 of the case file's bytes
  std::string version;            ///< Catena version
  std::string description;        ///< the case's `description`: paragraphs split at blank lines
  std::vector<ReportRow> inputs;  ///< the case's values as typed, path = name
  std::vector<ReportSection> sections;
};

/// The report as one HTML document. `chart_script` is the charting library (Plotly) source,
/// written into the document; each chart is drawn by Plotly.newPlot into its own element.
std::string to_html(const Report& report, std::string_view chart_script);

/// Escapes text for HTML element content and attribute values.
std::string html_escape(std::string_view text);

}  // namespace catena::io
