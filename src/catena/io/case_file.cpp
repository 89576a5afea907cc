#include "catena/io/case_file.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <utility>

namespace catena::io {
namespace {

std::string number_text(const toml::node& node) {
  // toml++ keeps no source spelling; integers print exactly, floats with round-trip precision.
  if (const auto* i = node.as_integer()) return std::to_string(i->get());
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.17g", node.as_floating_point()->get());
  // shortest spelling that reads back to the same double
  for (int digits = 1; digits <= 17; ++digits) {
    char shorter[64];
    std::snprintf(shorter, sizeof shorter, "%.*g", digits, node.as_floating_point()->get());
    if (std::strtod(shorter, nullptr) == node.as_floating_point()->get()) return shorter;
  }
  return buffer;
}

void flatten(const toml::table& table, const std::string& prefix, CaseFile& out,
             std::vector<std::pair<int, std::string>>& tables) {
  for (const auto& [key, node] : table) {
    const std::string path =
        prefix.empty() ? std::string(key.str()) : prefix + "." + std::string(key.str());
    const int line = static_cast<int>(node.source().begin.line);
    if (const auto* sub = node.as_table()) {
      tables.emplace_back(line, path);
      flatten(*sub, path, out, tables);
    } else if (node.is_string()) {
      out.values.push_back(
          {path, std::string(node.as_string()->get()), CaseValue::Type::kString, line});
    } else if (node.is_integer() || node.is_floating_point()) {
      out.values.push_back({path, number_text(node), CaseValue::Type::kNumber, line});
    } else if (node.is_boolean()) {
      out.values.push_back(
          {path, node.as_boolean()->get() ? "true" : "false", CaseValue::Type::kBoolean, line});
    } else if (const auto* array = node.as_array();
               array != nullptr && !array->empty() && array->is_array_of_tables()) {
      // [[loop.segment]]: each element is a table "loop.segment[0]", "loop.segment[1]", …
      tables.emplace_back(line, path);
      std::size_t index = 0;
      for (const toml::node& element : *array) {
        const std::string element_path = path + "[" + std::to_string(index++) + "]";
        tables.emplace_back(static_cast<int>(element.source().begin.line), element_path);
        flatten(*element.as_table(), element_path, out, tables);
      }
    } else {
      out.values.push_back({path, "(an array or date)", CaseValue::Type::kOther, line});
    }
  }
}

}  // namespace

const CaseValue* CaseFile::find(std::string_view path) const {
  for (const CaseValue& v : values) {
    if (v.path == path) return &v;
  }
  return nullptr;
}

std::vector<std::string> CaseFile::children(std::string_view parent) const {
  std::vector<std::string> out;
  const std::string prefix = std::string(parent) + ".";
  for (const std::string& t : tables) {
    if (t.rfind(prefix, 0) == 0 && t.find('.', prefix.size()) == std::string::npos)
      out.push_back(t.substr(prefix.size()));
  }
  return out;
}

CaseFile parse_case(std::string_view text, std::string name) {
  CaseFile out;
  out.name = std::move(name);
  out.text = std::string(text);
  toml::table parsed;
  try {
    parsed = toml::parse(out.text, out.name);
  } catch (const toml::parse_error& error) {
    throw InputError({{out.name + ":" + std::to_string(error.source().begin.line) + ":" +
                           std::to_string(error.source().begin.column),
                       "(TOML syntax)", "valid TOML: " + std::string(error.description())}});
  }
  // toml++ iterates a table's keys in sorted order; put the values back in file order
  std::vector<std::pair<int, std::string>> tables;
  flatten(parsed, "", out, tables);
  std::stable_sort(tables.begin(), tables.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  for (auto& [line, path] : tables) out.tables.push_back(std::move(path));
  std::stable_sort(out.values.begin(), out.values.end(),
                   [](const CaseValue& a, const CaseValue& b) { return a.line < b.line; });
  return out;
}

std::optional<std::string> did_you_mean(std::string_view word,
                                        const std::vector<std::string>& candidates) {
  auto distance = [](std::string_view a, std::string_view b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
      std::size_t diagonal = row[0];
      row[0] = i;
      for (std::size_t j = 1; j <= b.size(); ++j) {
        const std::size_t above = row[j];
        row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
        diagonal = above;
      }
    }
    return row[b.size()];
  };
  std::optional<std::string> best;
  std::size_t best_distance = std::max<std::size_t>(2, word.size() / 3) + 1;
  for (const std::string& c : candidates) {
    const std::size_t d = distance(word, c);
    if (d < best_distance) {
      best_distance = d;
      best = c;
    }
  }
  return best;
}

CaseFile read_case(const std::string& path) {
  const char* kExpected = "a readable TOML case file";
  if (path.empty()) throw InputError({{"CASE", "''", "a path (an empty path names no file)"}});
  const std::string cap = std::to_string(kMaxCaseFileBytes >> 20) + " MiB (" +
                          std::to_string(kMaxCaseFileBytes) + " bytes)";
  auto too_large = [&](const std::string& size) {
    return InputError({{"CASE", path,
                        "a case file of at most " + cap + "; this one has " + size +
                            " (a case is a few kilobytes)"}});
  };
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (std::filesystem::is_directory(status))
    throw InputError({{"CASE", path, "a TOML case file, not a folder"}});
  if (std::filesystem::is_regular_file(status)) {
    const auto size = std::filesystem::file_size(path, error);
    if (!error && size > kMaxCaseFileBytes) throw too_large(std::to_string(size) + " bytes");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError({{"CASE", path, kExpected}});
  // Read in pieces, no further than one byte past the cap: a device or a pipe has no size to
  // ask for beforehand, and /dev/zero has no end.
  std::string text;
  std::vector<char> piece(std::size_t{1} << 16);
  while (text.size() <= kMaxCaseFileBytes && in) {
    const std::size_t want = std::min(piece.size(), kMaxCaseFileBytes + 1 - text.size());
    in.read(piece.data(), static_cast<std::streamsize>(want));
    text.append(piece.data(), static_cast<std::size_t>(in.gcount()));
  }
  if (in.bad()) throw InputError({{"CASE", path, kExpected}});
  if (text.size() > kMaxCaseFileBytes) throw too_large("more (reading stopped at the cap)");
  return parse_case(text, path);
}

}  // namespace catena::io
