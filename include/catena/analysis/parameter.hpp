// The inputs of an analysis, described once: name (= CLI flag with '-' for '_' = case-file key),
// what kind of value it takes, the unit of a bare number, required or default, list or not,
// choices, a one-line doc. Every front end — the command line, case files, the report's inputs
// table, the Python module, sweeps — is built from these tables; none declares inputs of its own.
#pragma once

#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "catena/core/progress.hpp"
#include "catena/core/quantity_kind.hpp"

namespace catena::analysis {

/// The key that lets a run exceed the caps of its size parameters: `--allow-large` on the
/// command line, `allow_large = true` in an [analyses.<name>] table, `allow_large="true"` in
/// the Python module. Not a parameter of any table: the binder reads it for every analysis.
inline constexpr std::string_view kAllowLarge = "allow_large";

/// The cost of a size parameter (points, harmonics, nodes, count, slices): a run's time and
/// memory estimated as `seconds`·n^`time_power` and `bytes`·n^`memory_power` (the constants
/// measured on the reference machine, docs/reliability.md), and the cap on n beyond which the
/// binder refuses the value unless allow_large is given. `cap == 0`: not a size parameter.
struct Work {
  std::int64_t cap = 0;
  double seconds = 0.0;
  double time_power = 1.0;
  double bytes = 0.0;
  double memory_power = 1.0;
  double estimated_seconds(double n) const { return seconds * std::pow(n, time_power); }
  double estimated_bytes(double n) const { return bytes * std::pow(n, memory_power); }
};

enum class ParameterType {
  kQuantity,  ///< a dimensional value with a unit ("64mm"); bare number: the kind's default unit
  kNumber,    ///< a plain real (a ratio, an exponent, a factor)
  kInteger,   ///< a whole number ≥ `min_integer`
  kChoice,    ///< one of `choices`
  kFlag,      ///< on or off (a CLI flag without a value; true/false in a case file)
  kText,      ///< free text (a chain designation such as "12B")
  kTable,     ///< a table of the case file (with arrays of tables), e.g. [loop] with
              ///< [[loop.segment]]; on the command line the path of a TOML file holding it
};

struct Parameter {
  std::string name;  ///< snake_case key; the flag is "--" + name with '-' for '_'
  ParameterType type = ParameterType::kQuantity;
  QuantityKind kind = QuantityKind::kLength;  ///< for kQuantity
  std::string doc;                            ///< one line: what it is, its symbol, its range
  bool required = false;
  /// What the value would be when absent, as the user would type it ("256mm", "721", "table").
  std::string default_text;
  /// Comma-separated values allowed ("30kN,35kN"): a list, each part parsed alike.
  bool list = false;
  std::vector<std::string> choices;  ///< for kChoice
  int min_integer = 0;               ///< for kInteger
  /// The "expected" text of the message when it is required and missing (default "a value").
  std::string expected;
  /// The paper's example value, used when the value is absent and the analysis' `--example` is
  /// given (only analyses that have an example set these).
  std::string example;
  /// Shown on the command line only (a per-command option such as --method); still a key in
  /// case files unless `cli_only`.
  bool cli_only = false;
  /// On the command line the value may also be given without its flag, as the command's first
  /// word (`catena catalog 12B` = `catena catalog --chain 12B`).
  bool positional = false;
  /// Not taken from the case file's shared tables ([chain], [loads], ...): only from the
  /// analysis' own table.
  bool not_shared = false;
  /// The unit a bare number takes when it is not the kind's default (a conveyor run's length in
  /// m, not the mm of chain geometry); empty: the kind's default.
  std::string bare_unit;
  /// kTable: the keys of the table itself ([loop]: speed, efficiency, …) and, when it holds an
  /// array of tables, that array's name ("segment") and the keys of each element.
  std::vector<Parameter> fields;
  std::string rows_name;
  std::vector<Parameter> row_fields;
  /// Other names of its flag on the command line ("r1" → --r1), kept for scripts that used
  /// them; not keys of case files.
  std::vector<std::string> aliases;
  /// kInteger size parameters: the estimated work of a value and its cap.
  Work work;
};

/// One bound input: what the user gave (or the default) and its value in SI.
struct InputValue {
  bool given = false;              ///< the user gave it (defaults and examples are not "given")
  bool present = false;            ///< given, defaulted, or filled from the example
  std::string text;                ///< as typed (or the default text)
  double number = NAN;             ///< [SI] kQuantity / kNumber; NaN when absent or unreadable
  std::int64_t integer = 0;        ///< kInteger
  bool flag = false;               ///< kFlag
  std::vector<double> list;        ///< [SI] list parameters, part by part
  std::vector<std::string> parts;  ///< list parameters: the parts as typed
  /// kTable: the table's values, each (path, text, line), path relative to the case file root
  /// ("loop.segment[2].length"), and the file they came from.
  struct Entry {
    std::string path, text;
    int line = 0;
    bool is_string = false;   ///< a TOML string (a number in quotes still is)
    bool is_number = false;   ///< a TOML number
    bool is_boolean = false;  ///< a TOML boolean
  };
  std::vector<Entry> table;
  std::vector<std::string> tables;  ///< kTable: every table's path, empty ones too
  std::string source;               ///< kTable: the file the table came from
};

/// The inputs of one run, bound to a parameter table (io::bind makes them from text).
class Inputs {
 public:
  Inputs() = default;
  explicit Inputs(const std::vector<Parameter>* parameters) : parameters_(parameters) {}

  /// The bound value of `key`; std::logic_error for a key the table does not have.
  const InputValue& at(std::string_view key) const;
  InputValue& set(std::string_view key);

  bool given(std::string_view key) const { return at(key).given; }
  bool present(std::string_view key) const { return at(key).present; }
  double number(std::string_view key) const { return at(key).number; }
  /// The value when present; NaN inside when present but unreadable; empty when absent.
  std::optional<double> optional(std::string_view key) const;
  int integer(std::string_view key) const { return static_cast<int>(at(key).integer); }
  bool flag(std::string_view key) const { return at(key).flag; }
  const std::string& text(std::string_view key) const { return at(key).text; }
  const std::vector<double>& list(std::string_view key) const { return at(key).list; }
  const std::vector<Parameter>* parameters() const { return parameters_; }
  /// The front end writes the record's drawing (--svg/--dxf given; a case run, whose report
  /// shows it). An analysis whose drawing needs work of its own (the hinge's aperture) does that
  /// work, and reports its results, only then.
  bool drawing_wanted() const { return drawing_wanted_; }
  void want_drawing(bool wanted = true) { drawing_wanted_ = wanted; }
  /// The user allowed size parameters beyond their caps (kAllowLarge).
  bool large_allowed() const { return allow_large_; }
  void allow_large(bool allowed = true) { allow_large_ = allowed; }
  /// The Progress the run reports to and stops on (catena/core/progress.hpp); nullptr: nobody
  /// listens. Not owned: it must outlive the run.
  const Progress* progress() const { return progress_; }
  void listen(const Progress* progress) { progress_ = progress; }

 private:
  const std::vector<Parameter>* parameters_ = nullptr;
  const Progress* progress_ = nullptr;
  bool drawing_wanted_ = false;
  bool allow_large_ = false;
  std::map<std::string, InputValue, std::less<>> values_;
};

/// Helpers to write parameter tables compactly.
Parameter quantity(std::string name, QuantityKind kind, std::string doc);
Parameter number(std::string name, std::string doc);
Parameter integer(std::string name, int min, std::string doc);
Parameter choice(std::string name, std::vector<std::string> choices, std::string doc);
Parameter flag(std::string name, std::string doc);
Parameter text(std::string name, std::string doc);

/// Fluent modifiers: `quantity(...) | required()` etc.
struct Required {
  std::string expected;
};
struct Default {
  std::string text;
};
struct Example {
  std::string text;
};
struct ListOf {};
struct NotShared {};
/// The "expected" text of messages about the value (unreadable, or missing when required).
struct Expects {
  std::string text;
};
/// A flag of the command line only (not a case-file key).
struct CliOnly {};
/// The value may be given on the command line without its flag (at most one per analysis).
struct Positional {};
struct Alias {
  std::string name;  ///< snake_case, as `Parameter::name`
};
Parameter operator|(Parameter p, const Required& r);
Parameter operator|(Parameter p, const Default& d);
Parameter operator|(Parameter p, const Example& e);
Parameter operator|(Parameter p, ListOf);
Parameter operator|(Parameter p, NotShared);
Parameter operator|(Parameter p, const Expects& e);
Parameter operator|(Parameter p, CliOnly);
Parameter operator|(Parameter p, Positional);
Parameter operator|(Parameter p, const Alias& a);
Parameter operator|(Parameter p, const Work& w);

}  // namespace catena::analysis
