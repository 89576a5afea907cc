// Errors and diagnostics shared by every model.
//
// Invalid input (a negative pitch, a non-finite value) is an InputError listing every problem at
// once. A valid input that describes an infeasible design is not an error: analyses report it as
// a Diagnostic with the reason and the limit that was crossed.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace catena {

/// One problem with one input field.
struct Issue {
  std::string field;     ///< name of the field or flag, e.g. "pitch" or "--pitch"
  std::string value;     ///< the offending value as the user gave it (or formatted, in SI)
  std::string expected;  ///< what would have been valid, e.g. "a length > 0 m"
};

/// Thrown by entry points when validate() found problems. what() lists them all, one a line.
class InputError : public std::runtime_error {
 public:
  explicit InputError(std::vector<Issue> issues);
  const std::vector<Issue>& issues() const noexcept { return issues_; }

 private:
  std::vector<Issue> issues_;
};

/// Formats one issue as "field = value: expected ...".
std::string to_string(const Issue& issue);

/// Throws InputError if `issues` is not empty.
void throw_if_any(const std::vector<Issue>& issues);

/// A finding about a valid design: infeasible, or outside a model's range of validity.
struct Diagnostic {
  /// kError: the result itself is unusable (a field that is not finite), not a finding about
  /// the design.
  enum class Severity { kInfo, kWarning, kInfeasible, kError };
  Severity severity = Severity::kWarning;
  std::string code;     ///< stable identifier, e.g. "pocketwheel.guide_end_too_close"
  std::string message;  ///< sentence naming the reason and the limit
  double value = 0.0;   ///< [SI] the value that was checked
  double limit = 0.0;   ///< [SI] the limit it was checked against
  /// The SI unit of `value` and `limit` ("m", "Pa", "rad"; empty: a pure number), so that the
  /// report shows the limit in the display units of the tables beside it. Not in the JSON.
  std::string unit;
};

const char* to_string(Diagnostic::Severity severity);

/// Small helpers that build Issues; each appends when the check fails.
namespace check {
std::string format_si(double value, const char* unit);
void finite_positive(std::vector<Issue>& out, const char* field, double value, const char* unit);
void finite(std::vector<Issue>& out, const char* field, double value, const char* unit);
}  // namespace check

}  // namespace catena
