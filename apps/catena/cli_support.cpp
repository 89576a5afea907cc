#include "cli_support.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>

namespace catena::cli {

std::string format_g(double v, int digits) {
  char b[64];
  std::snprintf(b, sizeof b, "%.*g", digits, v);
  return b;
}

std::vector<std::string> split_commas(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream ss(text);
  std::string part;
  while (std::getline(ss, part, ',')) out.push_back(part);
  return out;
}

std::optional<double> FlagReader::quantity(const std::string& flag, const std::string& text,
                                           io::QuantityKind kind) {
  if (text.empty()) return std::nullopt;
  return io::parse_quantity(text, kind, flag, issues_);
}

double FlagReader::required_quantity(const std::string& flag, const std::string& text,
                                     io::QuantityKind kind, const std::string& what) {
  if (text.empty()) {
    add({flag, "(missing)", what});
    return NAN;
  }
  return quantity(flag, text, kind).value_or(NAN);
}

double FlagReader::required_number(const std::string& flag, const std::string& text,
                                   const std::string& what) {
  if (text.empty()) {
    add({flag, "(missing)", what});
    return NAN;
  }
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (*end != '\0' || !std::isfinite(v)) {
    add({flag, "'" + text + "'", what});
    return NAN;
  }
  return v;
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

nlohmann::ordered_json diagnostics_json(const std::vector<Diagnostic>& diagnostics) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const Diagnostic& d : diagnostics)
    out.push_back({{"severity", to_string(d.severity)},
                   {"code", d.code},
                   {"message", d.message},
                   {"value", d.value},
                   {"limit", d.limit}});
  return out;
}

void write_text_output(const std::string& output, const std::string& text) {
  Outputs outputs;
  if (!output.empty()) outputs.add("--output", output, text);
  outputs.commit(output.empty() ? text : "");
}

void Outputs::add(std::string flag, std::string path, std::string content) {
  files_.push_back({std::move(flag), std::move(path), std::move(content), {}});
}

namespace {
Capture* active_capture = nullptr;
}  // namespace

Capture::Capture() { active_capture = this; }
Capture::~Capture() { active_capture = nullptr; }

void Outputs::commit(const std::string& stdout_text) {
  namespace fs = std::filesystem;
  if (active_capture) {
    for (File& f : files_) active_capture->files.emplace_back(f.flag, std::move(f.content));
    active_capture->stdout_text += stdout_text;
    return;
  }
  auto discard = [&] {
    for (File& f : files_) {
      std::error_code ignored;
      if (!f.temporary.empty()) fs::remove(f.temporary, ignored);
    }
  };
  std::random_device random;
  for (File& f : files_) {
    f.temporary = f.path + ".tmp" + std::to_string(random());
    std::ofstream out(f.temporary, std::ios::binary | std::ios::trunc);
    out.write(f.content.data(), static_cast<std::streamsize>(f.content.size()));
    out.close();
    if (!out) {
      const std::string reason = std::strerror(errno);
      discard();
      throw InputError(
          {{f.flag, f.path, "a writable file path (" + reason + "); nothing was written"}});
    }
  }
  for (File& f : files_) {
    std::error_code error;
    fs::rename(f.temporary, f.path, error);
    if (error) {
      discard();
      throw InputError({{f.flag, f.path, "a writable file path (" + error.message() + ")"}});
    }
    f.temporary.clear();
  }
  if (!stdout_text.empty()) std::cout << stdout_text << std::flush;
}

}  // namespace catena::cli
