// Parameter sweeps over one analysis: a grid (the Cartesian product of lists of values) or an
// explicit list of input sets, each point run through `catena::run` on a pool of threads. The
// results come back in input order and are the same, bit for bit, whatever the number of
// threads. A point whose inputs do not bind keeps its error and the others run; keys that can
// never bind (not parameters of the analysis) are refused before anything runs. The command line
// (`catena sweep`) and the Python module are front ends of this.
#pragma once

#include <atomic>
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "catena/analysis/parameter.hpp"
#include "catena/analysis/record.hpp"
#include "catena/core/error.hpp"
#include "catena/core/progress.hpp"

namespace catena {

/// The size of one sweep: every point is held until the end (~2.4 kB of scalars each, ~2.7 kB
/// with its CSV row: 10⁵ hinge points took 267 MB resident through `catena sweep`), so 10⁶
/// points are ~2.7 GB. Split a bigger study into several sweeps (or Dask chunks).
inline constexpr std::size_t kMaxSweepPoints = 1'000'000;
/// The total work of one sweep of an analysis that estimates its runs' work
/// (analysis::Analysis::work_of: dynamics), in per-run caps: at most 40 runs' worth at the cap
/// (dynamics: 40 × 5·10⁷ = 2·10⁹ link-steps, about 1000 s of CPU). Above it the sweep is
/// refused before anything runs unless every point allows large (allow_large = true).
inline constexpr double kSweepWorkCaps = 40.0;
/// Threads of one sweep: more than any machine's cores, few enough that creating them cannot
/// fail for want of resources.
inline constexpr unsigned kMaxSweepThreads = 1024;

/// Inputs as `catena::run` takes them: key → text ("40 mm", "8", "true"), in order.
using InputSet = std::vector<std::pair<std::string, std::string>>;

/// A table parameter's value as a case file gives it ([dynamics] with its [[dynamics.sprocket]],
/// [loop] with its segments): every value with its case path ("dynamics.sprocket[1].load_torque"),
/// every table's path, the file's name. io::table_input makes one from a case file.
struct TableValue {
  std::string key;  ///< the table parameter ("dynamics", "loop")
  std::vector<analysis::InputValue::Entry> entries;
  std::vector<std::string> tables;  ///< every table's path in the file, empty ones too
  std::string source;               ///< the file
};

/// One swept input: its key and the texts it takes, in order.
struct SweepAxis {
  std::string key;
  std::vector<std::string> values;
};

struct SweepRequest {
  std::string analysis;  ///< registry name ("hinge", "engagement")
  InputSet base;         ///< values every point shares; a point's own value replaces the base's
  /// Table parameters every point shares, as values (a table parameter in `base` is the path of a
  /// file holding it, read by each point). A key of a point or an axis may then be a path inside
  /// one of these tables ("dynamics.duration", "dynamics.sprocket[1].load_torque"): the point runs
  /// with that value in place of the table's (or added, when the table lacks it), read as a
  /// TOML value (true/false a boolean, a bare number a number, anything else a string). The path's
  /// table must exist in `tables` (a row such as sprocket[1] must be in the file); a key the table
  /// does not take is the point's error, as the analysis reports it.
  std::vector<TableValue> tables;
  /// A grid: the Cartesian product of the axes, the first axis varying slowest. Or, when the grid
  /// is empty, `points`: each set is one point (its keys are the swept inputs). Not both.
  std::vector<SweepAxis> grid;
  std::vector<InputSet> points;
};

struct SweepOptions {
  unsigned threads = 0;  ///< worker threads; 0: every hardware thread; at most 1024
  /// Called on the calling thread while the sweep runs (at most about every 50 ms, and once at
  /// the end with done == total), never from a worker.
  std::function<void(std::size_t done, std::size_t total)> progress;
  /// When set (from any thread, or a signal handler), the workers take no new point and the
  /// running points stop at their next poll (catena/core/progress.hpp); `sweep` then throws
  /// Cancelled once every thread has stopped, and returns no result.
  const std::atomic<bool>* cancel = nullptr;
  /// Keep each point's whole Record; false keeps only its scalars and worst diagnostic (what
  /// the table needs: a 10⁵-point sweep then holds megabytes, not gigabytes).
  bool keep_records = true;
};

/// The name and SI unit of a scalar result ("hertz.stress", "Pa"); unit "" when it has none.
struct ScalarName {
  std::string path;
  std::string unit;
  bool operator==(const ScalarName&) const = default;
};

/// Every scalar number of a Record's data, in document order: nested objects give dotted paths
/// ("step1.R1_max"), arrays (series) and text are left out, `units`/`diagnostics` skipped; a
/// null (an absent optional value) is a NaN here. The unit is the `units` entry of the whole
/// path, else of the last key (the convention of every analysis' `units` object).
struct Scalars {
  std::shared_ptr<const std::vector<ScalarName>> names;  ///< shared by points of one layout
  std::vector<double> values;                            ///< one per name
};
Scalars scalars_of(const analysis::Value& data);

/// The worst diagnostic: the highest severity (error > infeasible > warning > info), the first
/// of that severity; nothing when there is none.
std::optional<Diagnostic> worst_diagnostic(const std::vector<Diagnostic>& diagnostics);

struct SweepPoint {
  InputSet inputs;  ///< this point's own values (the swept keys); run with the base under them
  std::optional<analysis::Record> record;  ///< when it ran and `keep_records`
  Scalars scalars;                         ///< when it ran
  std::optional<Diagnostic> worst;         ///< when it ran and has diagnostics
  std::string error;                       ///< the InputError's message when it did not run
  std::vector<Issue> issues;               ///< the InputError's issues when it did not run
  bool ok() const { return error.empty(); }
};

struct SweepResult {
  std::string analysis;
  std::vector<std::string> keys;   ///< the swept keys: grid axes, or every key of the points
  std::vector<SweepPoint> points;  ///< in input order
};

/// The points of a request, each the point's own values, in order (grid: first axis slowest).
/// Throws InputError listing every problem: an unknown analysis, keys that are not parameters
/// of it (with did-you-mean), a shared value that no point replaces and that does not read on
/// its own (a wrong unit: every point would fail), an empty or repeated axis, both a grid and
/// points, or none. A swept value that does not read is its point's error, not the request's.
/// For an analysis that estimates its work (Analysis::work_of), also a total over kSweepWorkCaps
/// per-run caps (named "grid", with the limit and the estimate) unless every point allows large.
std::vector<InputSet> sweep_points(const SweepRequest& request);

/// For a request of explicit points whose table parameter is given as the path of its file (a
/// point's "dynamics" = "drive.toml", as Python's catena.sweep gives it): when a point or the base
/// also names a value inside that table ("dynamics.sprocket[1].load_torque"), the file is read
/// once into `tables` and its key dropped from the base and the points, so that each point runs
/// with its value in place of the file's, as `catena sweep` does for a case file. Every point must
/// then name the same file (an issue names the key otherwise, and a file that does not read is
/// one); a table no point looks inside is left as it is. Appends its problems to `issues`.
void share_table_files(SweepRequest& request, std::vector<Issue>& issues);

/// Runs every point (sweep_points, then `catena::run` with `base` overlaid by the point) on
/// `options.threads` threads. Throws InputError for the problems of sweep_points and a thread
/// count over 1024, all at once; a point's own
/// InputError is its `error`. Any other exception of a point (an internal error) is rethrown,
/// the first point's first, after every thread has stopped.
SweepResult sweep(const SweepRequest& request, const SweepOptions& options = {});

/// Appends an Issue naming `field` when `threads` is over kMaxSweepThreads (front ends check their
/// flag with it, so that it is listed with their other problems).
void check_threads(unsigned threads, std::string_view field, std::vector<Issue>& issues);

/// A sweep as columns, one row per point: the swept inputs (as typed), then every scalar result
/// of any point (the order of first appearance, points in order; NaN where a point lacks it or
/// did not run), then the worst diagnostic's severity and code, then the input error (its problems
/// on one line, "; " between; "" when the point ran).
struct SweepTable {
  struct Text {
    std::string name;
    std::vector<std::string> values;
  };
  struct Number {
    std::string name, unit;
    std::vector<double> values;
  };
  std::vector<Text> inputs;
  std::vector<Number> results;
  Text severity{"worst_severity", {}};
  Text code{"worst_code", {}};
  Text error{"error", {}};
  std::size_t rows() const { return severity.values.size(); }
};
SweepTable sweep_table(const SweepResult& result);

/// The table as CSV: a header of names, results as "name [unit]" ("name" when it has no unit);
/// numbers in the shortest text that reads back exactly, NaN as an empty cell; texts quoted
/// when they hold a comma, a quote or a line break.
std::string sweep_csv(const SweepTable& table);

/// One axis from its text, as `catena sweep --grid` takes it: "key=a:b" (whole numbers a to b
/// inclusive), "key=a:b:step" (step > 0), or "key=v1,v2,..." (texts, units allowed: "30mm,40 mm").
/// Appends an Issue naming `field` (e.g. "--grid") for a malformed text; returns nothing then.
std::optional<SweepAxis> parse_axis(std::string_view text, std::string_view field,
                                    std::vector<Issue>& issues);

}  // namespace catena
