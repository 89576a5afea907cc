// What every fuzz harness asserts besides the sanitizers: a Record never holds a number that is
// not finite without an error diagnostic naming it, and the size parameters are kept small so
// that the fuzzer spends its time on the models, not on one huge run (docs/reliability.md).
#pragma once

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <string_view>
#include <vector>

#include "catena/analysis/record.hpp"
#include "catena/analysis/value.hpp"
#include "catena/core/error.hpp"

namespace catena::fuzz {

/// A broken invariant: the message on stderr, then abort (libFuzzer saves the input as a crash).
[[noreturn]] inline void fail(const std::string& what) {
  std::fprintf(stderr, "catena fuzz: invariant broken: %s\n", what.c_str());
  std::fflush(stderr);
  std::abort();
}

namespace detail {

// The path of every real below `v` that is ±inf or NaN ("series.ax[3]"), `units` and
// `diagnostics` skipped (they describe the results, they are none).
inline void non_finite_paths(const analysis::Value& v, const std::string& path,
                             std::vector<std::string>& out) {
  if (v.is_real()) {
    if (!std::isfinite(v.as_number())) out.push_back(path);
  } else if (v.is_array()) {
    const analysis::Value::Array& items = v.as_array();
    for (std::size_t i = 0; i < items.size(); ++i)
      non_finite_paths(items[i], path + "[" + std::to_string(i) + "]", out);
  } else if (v.is_object()) {
    for (const auto& [key, member] : v.as_object()) {
      if (key == "units" || key == "diagnostics") continue;
      non_finite_paths(member, path.empty() ? key : path + "." + key, out);
    }
  }
}

// True when an error diagnostic names `path` or the array that holds it.
inline bool diagnosed(const std::vector<Diagnostic>& diagnostics, const std::string& path) {
  for (const Diagnostic& d : diagnostics) {
    if (d.severity != Diagnostic::Severity::kError) continue;
    const std::size_t open = d.message.find('\'');
    const std::size_t close =
        open == std::string::npos ? std::string::npos : d.message.find('\'', open + 1);
    if (close == std::string::npos) continue;
    const std::string named = d.message.substr(open + 1, close - open - 1);
    if (named == path || named == "(value)") return true;
    if (path.size() > named.size() && path.compare(0, named.size(), named) == 0 &&
        path[named.size()] == '[')
      return true;
  }
  return false;
}

}  // namespace detail

/// Every non-finite number of the record's data is named by an error diagnostic, and a CSV
/// column with one (other than the blank cells of an absent value) comes with an error diagnostic.
inline void check_record(const analysis::Record& record, std::string_view who) {
  std::vector<std::string> paths;
  detail::non_finite_paths(record.data, "", paths);
  for (const std::string& path : paths) {
    if (!detail::diagnosed(record.diagnostics, path))
      fail(std::string(who) + ": the result '" + path +
           "' is not finite and no error diagnostic names it");
  }
  bool any_error = false;
  for (const Diagnostic& d : record.diagnostics)
    any_error = any_error || d.severity == Diagnostic::Severity::kError;
  for (const analysis::Column& column : record.columns) {
    for (const double x : column.values) {
      if (std::isfinite(x) || (column.blank_nan && std::isnan(x)) || any_error) continue;
      fail(std::string(who) + ": CSV column '" + column.name +
           "' holds a number that is not finite and there is no error diagnostic");
    }
  }
}

/// Defects the fuzzer found that are known and reported (issue 18) and are fixed outside the
/// harnesses: an exception whose what() starts with `what`, thrown by `analysis`. While one is
/// listed the harnesses let it pass, so that fuzzing goes on past it and CI fails on anything new;
/// its reproducer in tests/fuzz/regressions/ runs strict (CATENA_FUZZ_STRICT=1) as a test that
/// expects the failure: when the defect is fixed that test fails, and its entry here goes.
struct KnownDefect {
  const char* analysis;
  const char* what;
};
// None open: the contact roller of 1e150 m (TOMS 748 "do not bracket the root") is an input error
// since issue 18's range checks; its reproducer is regressions/analysis/contact-roller-1e150m.
inline constexpr std::array<KnownDefect, 0> kKnownDefects{};

/// True when `e`, thrown by `analysis`, is a listed known defect and CATENA_FUZZ_STRICT is unset.
inline bool known_defect(std::string_view analysis, const std::exception& e) {
  if (std::getenv("CATENA_FUZZ_STRICT") != nullptr) return false;
  const std::string_view what = e.what();
  for (const KnownDefect& k : kKnownDefects) {
    if (analysis == k.analysis && what.substr(0, std::string_view(k.what).size()) == k.what)
      return true;
  }
  return false;
}

/// The largest value the harnesses pass to a size parameter. The analyses' own caps (issue 18's
/// work model) still allow runs of seconds, which would spend the fuzzing budget on a few inputs.
/// Larger values are replaced by the cap, so the value's parsing is still exercised.
inline long size_cap(std::string_view key) {
  if (key == "points") return 200;
  if (key == "count") return 50;
  if (key == "nodes") return 400;
  if (key == "harmonics") return 40;  // the least the ring solver's own default takes
  if (key == "slices") return 100;
  return 0;  // not a size parameter
}

/// `text` with a whole number above the cap of `key` replaced by the cap; other texts unchanged.
inline std::string clamp_size(std::string_view key, const std::string& text) {
  const long cap = size_cap(key);
  if (cap == 0) return text;
  char* end = nullptr;
  const long value = std::strtol(text.c_str(), &end, 10);
  if (end == text.c_str() || value <= cap) return text;
  return std::to_string(cap);
}

}  // namespace catena::fuzz
