#include "cli_support.hpp"

#include <cctype>
#include <cstdlib>
#include <iostream>

#include "catena/io/atomic_file.hpp"

namespace catena::cli {

std::optional<double> FlagReader::quantity(const std::string& flag, const std::string& text,
                                           io::QuantityKind kind) {
  if (text.empty()) return std::nullopt;
  return io::parse_quantity(text, kind, flag, issues_);
}

std::optional<int> FlagReader::integer(const std::string& flag, const std::string& text, int min) {
  char* end = nullptr;
  const long value = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || value < min || value > 1000000000L) {
    issues_.push_back({flag, "'" + text + "'", "a whole number ≥ " + std::to_string(min)});
    return std::nullopt;
  }
  return static_cast<int>(value);
}

void FlagReader::add_model_issues(const std::vector<Issue>& model_issues) {
  for (Issue issue : model_issues) {
    std::string flag = "--" + issue.field;
    for (char& c : flag) c = c == '_' ? '-' : c;
    issue.field = flag;
    issues_.push_back(std::move(issue));
  }
}

void emit(const std::string& path, const std::string& content) {
  if (path.empty()) {
    std::cout << content << std::flush;
  } else {
    io::write_file_atomic(path, content);
  }
}

}  // namespace catena::cli
