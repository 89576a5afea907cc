#include "catena/core/error.hpp"

#include <cmath>
#include <cstdio>

namespace catena {
namespace {
std::string join(const std::vector<Issue>& issues) {
  std::string text = issues.size() == 1
                         ? "invalid input:"
                         : "invalid input (" + std::to_string(issues.size()) + " problems):";
  for (const Issue& issue : issues) text += "\n  " + to_string(issue);
  return text;
}
}  // namespace

InputError::InputError(std::vector<Issue> issues)
    : std::runtime_error(join(issues)), issues_(std::move(issues)) {}

std::string to_string(const Issue& issue) {
  return issue.field + " = " + issue.value + ": expected " + issue.expected;
}

void throw_if_any(const std::vector<Issue>& issues) {
  if (!issues.empty()) throw InputError(issues);
}

const char* to_string(Diagnostic::Severity severity) {
  switch (severity) {
    case Diagnostic::Severity::kInfo:
      return "info";
    case Diagnostic::Severity::kWarning:
      return "warning";
    case Diagnostic::Severity::kInfeasible:
      return "infeasible";
    case Diagnostic::Severity::kError:
      return "error";
  }
  return "unknown";
}

namespace check {
std::string format_si(double value, const char* unit) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, unit[0] == '\0' ? "%.6g%s" : "%.6g %s", value, unit);
  return buffer;
}

void finite(std::vector<Issue>& out, const char* field, double value, const char* unit) {
  if (!std::isfinite(value)) out.push_back({field, format_si(value, unit), "a finite value"});
}

void finite_positive(std::vector<Issue>& out, const char* field, double value, const char* unit) {
  if (!std::isfinite(value) || value <= 0.0) {
    out.push_back({field, format_si(value, unit), std::string("a finite value > 0 ") + unit});
  }
}
}  // namespace check

}  // namespace catena
