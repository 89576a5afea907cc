// The whole text of a file, for every test program: a file that cannot be opened fails the
// calling test (at the caller's line, naming the path) instead of reading as an empty text.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <source_location>
#include <sstream>
#include <string>

inline std::string read_text(const std::filesystem::path& path,
                             const std::source_location at = std::source_location::current()) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    ADD_FAILURE_AT(at.file_name(), static_cast<int>(at.line()))
        << "read_text: cannot open " << path.string();
    return {};
  }
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}
