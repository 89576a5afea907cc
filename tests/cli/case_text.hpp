// Case texts edited for a test: whole lines added to a table of a case's TOML text.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <utility>

// `lines` (a key, or several lines; the last one's newline added if missing) added after the
// n-th line (0: the first) of `text` holding `header`; a header not found fails the test and
// leaves `text` as it is.
inline std::string with_lines_after(std::string text, const std::string& header, int n,
                                    const std::string& lines) {
  std::size_t at = 0;
  for (int k = 0; k <= n; ++k) {
    at = text.find(header, k == 0 ? 0 : at + 1);
    EXPECT_NE(at, std::string::npos) << header << " #" << n;
    if (at == std::string::npos) return text;
  }
  const std::string whole = lines.empty() || lines.back() == '\n' ? lines : lines + "\n";
  const std::size_t end = text.find('\n', at);
  if (end == std::string::npos) return text + "\n" + whole;
  return text.insert(end + 1, whole);
}

// `key` (or several lines) added to the [dynamics] table, right after its header.
inline std::string with_dynamics_key(std::string text, const std::string& key) {
  return with_lines_after(std::move(text), "[dynamics]\n", 0, key);
}

// `key` (or several lines) added to the n-th [[dynamics.guide]] table (0: the first).
inline std::string with_guide_key(std::string text, int n, const std::string& key) {
  return with_lines_after(std::move(text), "[[dynamics.guide]]", n, key);
}
