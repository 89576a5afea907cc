// Helpers shared by the subcommands: unit-tagged flags, output destinations.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/io/quantity.hpp"

namespace catena::cli {

/// `v` with `digits` significant digits (printf's %g): numbers in tables and messages.
std::string format_g(double v, int digits = 6);
/// The comma-separated parts of a list flag ("30kN,35kN"), empty parts kept.
std::vector<std::string> split_commas(const std::string& text);
/// A model's diagnostics as the commands' JSON array: {severity, code, message, value, limit}.
nlohmann::ordered_json diagnostics_json(const std::vector<Diagnostic>& diagnostics);

/// Parses flags into SI values, collecting every problem so that all are reported at once.
class FlagReader {
 public:
  /// A unit-tagged flag; `text` empty means "not given" and yields nothing without an issue.
  std::optional<double> quantity(const std::string& flag, const std::string& text,
                                 io::QuantityKind kind);
  /// A unit-tagged flag that must be given: empty adds "(missing): expected `what`". NaN when
  /// missing or unreadable (the problem is recorded either way).
  double required_quantity(const std::string& flag, const std::string& text, io::QuantityKind kind,
                           const std::string& what);
  /// A plain number that must be given (a ratio, an exponent, a factor in SI): empty adds
  /// "(missing)", text that is not a finite number adds "'text'", each with `what`; NaN then.
  double required_number(const std::string& flag, const std::string& text, const std::string& what);
  /// A whole number ≥ `min`.
  std::optional<int> integer(const std::string& flag, const std::string& text, int min);
  void add(Issue issue) { issues_.push_back(std::move(issue)); }
  /// Renames model field names (e.g. "guide_end") to flags ("--guide-end") in `model_issues`
  /// and adds them.
  void add_model_issues(const std::vector<Issue>& model_issues);
  /// Throws InputError listing everything found so far.
  void throw_if_any() const { catena::throw_if_any(issues_); }

 private:
  std::vector<Issue> issues_;
};

/// The outputs of one command, written all or nothing: every file goes to a temporary beside its
/// target first; only when all are written are they renamed into place. Then the text meant for
/// stdout is printed (when no --output file took it). An unwritable path is invalid input.
class Outputs {
 public:
  /// `flag` names the option the path came from, for the error message.
  void add(std::string flag, std::string path, std::string content);
  /// Writes everything; `stdout_text` goes to stdout unless empty.
  void commit(const std::string& stdout_text = "");

 private:
  struct File {
    std::string flag, path, content, temporary;
  };
  std::vector<File> files_;
};

/// A command's text output: to the --output FILE when one is given, else to stdout.
void write_text_output(const std::string& output, const std::string& text);

/// While a Capture exists, Outputs::commit hands its files and stdout text to it instead of
/// writing them: the case runner runs a subcommand in-process and keeps what it produced.
/// (The program is single-threaded; captures do not nest.)
class Capture {
 public:
  Capture();
  ~Capture();
  Capture(const Capture&) = delete;
  Capture& operator=(const Capture&) = delete;
  std::string stdout_text;
  /// (flag, content) of every file the command would have written
  std::vector<std::pair<std::string, std::string>> files;
};

}  // namespace catena::cli
