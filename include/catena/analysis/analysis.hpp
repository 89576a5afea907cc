// One analysis, described once: who it is (name, title, seed and section, docs), its inputs (the
// parameter table), and what it does — `run(inputs) → Result` (everything the analysis computes,
// every diagnostic) and `describe(result) → Record` (the result as named fields with SI units,
// and what front ends show of it). Each model folder defines its analyses in analysis.hpp/.cpp;
// the registry (catena/catena.hpp) lists them; every front end is generic over this type.
#pragma once

#include <any>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "catena/analysis/parameter.hpp"
#include "catena/analysis/record.hpp"
#include "catena/core/error.hpp"

namespace catena::analysis {

/// Output formats an analysis offers on the command line besides JSON.
struct Formats {
  bool table = true;     ///< --format table (the default when offered)
  bool csv = false;      ///< --format csv and --csv FILE
  bool drawing = false;  ///< --svg FILE and --dxf FILE
};

struct Analysis {
  std::string name;                  ///< registry and case-file name ("pocketwheel", "hinge_sweep")
  std::vector<std::string> command;  ///< the CLI path: {"hinge", "sweep"}
  std::string title;                 ///< one line for people and reports
  std::string help;                  ///< the command's description in --help
  std::string seed;                  ///< "003", "000 §1.2–1.3"
  std::string docs;                  ///< "docs/models/pocketwheel.md"
  std::vector<std::string> chain_types;  ///< case files: chain.type values it applies to
  std::vector<Parameter> parameters;
  Formats formats;
  /// Fills missing values from each parameter's `example` when `--example` is given.
  std::string example_doc;  ///< non-empty: the analysis has an example; the --example help
  /// Cross-field input rules beyond one parameter (a value only with a given choice, a flag that
  /// a mode refuses): appends issues, named by parameter key. Called after every value is bound.
  std::function<void(const Inputs&, std::vector<Issue>&)> check;
  /// Runs the analysis; throws InputError (fields named by parameter key) for invalid input.
  std::function<std::any(const Inputs&)> run;
  /// The result as a Record.
  std::function<Record(const std::any&, const Inputs&)> describe;
  /// Per chain type (case files): values the type implies (engagement: hinge = rolling) and
  /// shared keys that do not apply to it.
  struct Variant {
    std::vector<std::pair<std::string, std::string>> set;
    std::vector<std::string> not_shared;
  };
  std::vector<std::pair<std::string, Variant>> variants;
  /// The work of one run from its bound inputs, without running it, in `work_unit`s — the
  /// measure of its table parameter's `work` cap (dynamics: link-steps, duration/step × links);
  /// 0 for inputs the run refuses (it does no work). Set by an analysis whose size follows from
  /// several values; a sweep sums it over its points and refuses a total over
  /// kSweepWorkCaps × the per-run cap (catena/sweep.hpp) unless every point allows large.
  std::function<double(const Inputs&)> work_of;
  std::string work_unit;  ///< "link-steps"

  /// The problems of the size parameters of `inputs` whose value is above its cap (unless
  /// `inputs.large_allowed()`), each naming the value, the estimated time and memory and the
  /// cap; named by parameter key. The binder appends them; `evaluate` throws them.
  std::vector<Issue> size_issues(const Inputs& inputs) const;
  /// True when some parameter has a cap (the command line then offers --allow-large).
  bool has_size_caps() const;
  /// Refuses sizes above their caps (size_issues), then run, then describe; then every result field
  /// that is not finite becomes an error diagnostic (diagnose_non_finite), so no front end shows a
  /// silent null. The run's loops poll `inputs.progress()` (catena/core/progress.hpp): they
  /// report to it, and when it is cancelled the run throws Cancelled, never a partial Record.
  Record evaluate(const Inputs& inputs) const;
  const Parameter* parameter(std::string_view key) const;
  /// True when an issue's field is a parameter key or a model field ("joint F21 stiffness") that a
  /// front end names in its own spelling (--flag, analyses.x.key); false for paths that a table
  /// parameter's reader already wrote as the user's ("loop.segment[2].length (line 27)", "loop").
  bool renames(const std::string& field) const;
  /// The parameter of a value inside a table parameter ("loop.segment[2].length" → length),
  /// or nullptr.
  const Parameter* table_field(const std::string& path) const;
};

/// The problems of one binding in the order a command reads its inputs, for a `check`: first
/// the binder's problems about keys outside `order` (as found), then for each key of `order` the
/// binder's problems about it — unless `read(key)` is false (a value the chosen mode does not
/// read) — followed by the check's own (`added`) about it.
std::vector<Issue> in_read_order(const std::vector<Issue>& bound, const std::vector<Issue>& added,
                                 const std::vector<std::string>& order,
                                 const std::function<bool(const std::string&)>& read);

/// Wraps typed run/describe functions into an Analysis' type-erased ones.
template <class Result>
void set_functions(Analysis& a, std::function<Result(const Inputs&)> run,
                   std::function<Record(const Result&, const Inputs&)> describe) {
  a.run = [run = std::move(run)](const Inputs& in) -> std::any { return run(in); };
  a.describe = [describe = std::move(describe)](const std::any& r, const Inputs& in) {
    return describe(std::any_cast<const Result&>(r), in);
  };
}

}  // namespace catena::analysis
