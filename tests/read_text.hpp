// The whole text of a file, for every test program: a path that cannot be read fails the calling
// test (at the caller's line, naming the path) instead of reading as an empty or a cut text — a
// file that cannot be opened, a directory (which opens, and reads as nothing) and a read error
// after the file opened.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <source_location>
#include <sstream>
#include <string>

inline std::string read_text(const std::filesystem::path& path,
                             const std::source_location at = std::source_location::current()) {
  const auto fail = [&](const char* why) {
    ADD_FAILURE_AT(at.file_name(), static_cast<int>(at.line()))
        << "read_text: " << why << " " << path.string();
    return std::string();
  };
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) return fail("is a directory, not a file:");
  std::ifstream in(path, std::ios::binary);
  if (!in) return fail("cannot open");
  std::ostringstream text;
  // peek first: an empty file inserts nothing, which alone would set the text's failbit; a read
  // error sets the file's badbit here (peek) or the text's failbit (the copy stops at it)
  if (in.peek() != std::ifstream::traits_type::eof()) text << in.rdbuf();
  if (in.bad() || text.fail()) return fail("read error in");
  return text.str();
}
