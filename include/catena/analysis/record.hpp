// What an analysis' `describe` returns: the result as named fields with SI units (the Value tree
// that `--format json` prints, its `units` object inside), and everything else a front end shows
// of it — the text table, CSV columns, drawings, the report's charts and grids, and the
// diagnostics. Writers in io/ turn a Record into files; no front end writes a model's fields.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "catena/analysis/value.hpp"
#include "catena/core/drawing.hpp"
#include "catena/core/error.hpp"

namespace catena::analysis {

/// One curve of a chart (x and y of equal length; non-finite values are drawn as gaps), in the
/// display units of the chart's axis labels.
struct Trace {
  std::string name;
  std::vector<double> x, y;
};

/// A vertical line across a chart at x, with its label written beside it (a frequency of
/// interest on a spectrum).
struct Marker {
  double x = 0.0;
  std::string label;
};

/// One frame of an animated chart: its name (shown on the slider) and its curves, which replace
/// the chart's last `traces.size()` curves while the frame is shown.
struct Frame {
  std::string name;
  std::vector<Trace> traces;
};

/// A chart of the report.
struct Chart {
  std::string title, x_label, y_label;
  std::vector<Trace> traces;
  bool equal_axes = false;      ///< same scale on x and y (paths, outlines)
  bool integer_x = false;       ///< x counts things (a roller index): ticks at whole numbers only
  std::vector<Marker> markers;  ///< vertical lines with labels; may be empty
  /// Frames of an animation (a slider and a play button); empty: a still chart. The chart's own
  /// traces are what is shown before the first frame is played (normally the first frame).
  std::vector<Frame> frames;
};

/// A table with columns (a sweep: one row per design; safety checks). Headers carry units.
struct Grid {
  std::string title;
  std::vector<std::string> columns;
  std::vector<std::vector<std::string>> rows;
  std::vector<bool> highlighted;  ///< per row (e.g. the best design); may be empty
  bool numbered = false;          ///< the report adds a column "#" counting rows from 1
  std::string note;               ///< a line under the table (what the highlighted row is)
};

/// A named column of numbers, for CSV (`--format csv`, `--csv FILE`). A column shorter than the
/// first leaves its remaining cells empty (a quantity the run does not have).
struct Column {
  std::string name;
  std::vector<double> values;
  int digits = 12;         ///< significant digits written
  bool blank_nan = false;  ///< NaN written as an empty cell (an optional value that is absent)
};

/// A person's name for a result field in the report, instead of its path in the data.
/// `path` is matched against the end of the field's dotted path ("plate_force.lower_outer"
/// names layouts.layout_1.plate_force.lower_outer and the same field of every layout; the
/// longest match wins); `text` is the label with its symbol ("Plate force, lower outer F21");
/// `unit` is the display unit when it is not display()'s ("kN" for N, "m" for m; empty:
/// display()'s); it must be one display_scale converts to.
struct Label {
  std::string path, text, unit;
};

struct Record {
  Value data;  ///< the JSON tree (an object, or a list of objects for several runs)
  std::vector<Diagnostic> diagnostics;  ///< findings about the design (also inside `data`)
  std::string table;                    ///< the text table (`--format table`)
  std::vector<Column> columns;          ///< CSV columns; empty: the analysis has no CSV
  std::string csv;  ///< a CSV the analysis wrote itself (text columns); used instead of `columns`
  std::vector<Drawing> drawings;    ///< for --svg / --dxf and the report
  std::string drawing_unavailable;  ///< why there is no drawing (for the --svg message)
  std::vector<Chart> charts;        ///< the report's charts
  std::vector<Grid> grids;          ///< the report's tables with columns
  std::vector<Label> labels;        ///< the report's names for result fields (optional)
  /// For a result with sweep `rows`: the row keys that name a design ("R1", "R2"), so that the
  /// report names the best row by them; empty: by its number only.
  std::vector<std::string> design_keys;
};

/// `v` with `digits` significant digits (printf's %g): numbers in tables and messages.
std::string format_g(double v, int digits = 6);

/// A multiple in words, "more than ... the": 2 → "twice", else m's shortest exact %g + " times"
/// ("1.5 times", "2.0000001 times"). Domain: finite m > 1 (outside it: "1 times", "nan times").
std::string times_text(double m);

/// A unit people read for an SI unit: "m" → mm (×1000), "Pa" → MPa, "rad" → °.
struct Display {
  std::string unit;
  double scale = 1.0;
};
Display display(const std::string& si_unit);

/// The factor from `si_unit` to the display unit `unit` ("N" → "kN": 1e-3; "m" → "m": 1);
/// NaN when the pair is not one it knows.
double display_scale(const std::string& si_unit, const std::string& unit);

/// The SI unit of `key` in the `units` object of `result` ("" when it has none).
std::string unit_of(const Value& result, const std::string& key);

/// A chart of y(x) for arrays inside `object` (`x` and each of `ys` are its keys), in display
/// units taken from `result`'s `units`; a missing y is left out.
Chart series_chart(const Value& result, const Value& object, const std::string& title,
                   const std::string& x, const std::vector<std::string>& ys,
                   const std::string& y_label = "");

/// A result field whose numbers are not all finite: its path in the data ("series.ax",
/// "layouts.layout_1.safety_factor"), how many of its numbers are ±inf or NaN, and the first.
struct NonFinite {
  std::string path;
  std::size_t count = 0, total = 0;
  double first = 0.0;
};
/// Every real number of `data` that is ±inf or NaN, grouped by field (an array is one field),
/// in document order; `units` and `diagnostics` are not results and are skipped. Absent values
/// are null Values, not NaN, so they are not listed.
std::vector<NonFinite> non_finite_fields(const Value& data);

/// Adds to `record` one error diagnostic `result.non_finite` per field of non_finite_fields,
/// to `diagnostics` and to the data's own `diagnostics` array where it has one.
void diagnose_non_finite(Record& record);

/// Diagnostics as the JSON array every analysis prints: {severity, code, message, value, limit}.
Value diagnostics_value(const std::vector<Diagnostic>& diagnostics);

/// The `units` object from (key, unit) pairs, in order.
Value units_value(const std::vector<std::pair<const char*, const char*>>& units);

}  // namespace catena::analysis
