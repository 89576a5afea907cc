// tests/read_text.hpp, the test programs' file reader: the whole file byte for byte, and a path
// that cannot be read (not opened, a directory, a read error) fails the calling test, naming the
// path at the caller's line.
#include "read_text.hpp"

#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <source_location>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using namespace std::string_literals;

fs::path scratch() {
  const fs::path dir =
      fs::temp_directory_path() / ("catena_read_text_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}

TEST(ReadText, ReadsTheWholeFileByteForByte) {
  const fs::path path = scratch() / "bytes.txt";
  const std::string bytes = "line\r\nzero \0 byte, no newline at the end"s;
  std::ofstream(path, std::ios::binary) << bytes;
  EXPECT_EQ(read_text(path), bytes);
  std::ofstream(path, std::ios::binary | std::ios::trunc).close();
  EXPECT_EQ(read_text(path), "");  // an empty file reads empty, without a failure
  fs::remove_all(path.parent_path());
}

TEST(ReadText, AFileThatCannotBeOpenedFailsTheCallerNamingThePath) {
  const fs::path missing = scratch() / "missing.txt";
  fs::remove(missing);
  ::testing::TestPartResultArray failures;
  std::string text = "not read";
  int line = 0;
  {
    ::testing::ScopedFakeTestPartResultReporter reporter(
        ::testing::ScopedFakeTestPartResultReporter::INTERCEPT_ONLY_CURRENT_THREAD, &failures);
    line = __LINE__, text = read_text(missing);
  }
  EXPECT_EQ(text, "");
  ASSERT_EQ(failures.size(), 1);
  const ::testing::TestPartResult& failure = failures.GetTestPartResult(0);
  EXPECT_TRUE(failure.nonfatally_failed());
  EXPECT_NE(std::string(failure.message()).find(missing.string()), std::string::npos)
      << failure.message();
  ASSERT_NE(failure.file_name(), nullptr);
  EXPECT_EQ(std::string(failure.file_name()), std::source_location::current().file_name());
  EXPECT_EQ(failure.line_number(), line);
  fs::remove_all(missing.parent_path());
}

// read_text on `path` with its failures caught: the text and the failures' messages
struct Caught {
  std::string text;
  std::vector<std::string> messages;
};
Caught read_caught(const fs::path& path) {
  ::testing::TestPartResultArray failures;
  Caught out;
  {
    ::testing::ScopedFakeTestPartResultReporter reporter(
        ::testing::ScopedFakeTestPartResultReporter::INTERCEPT_ONLY_CURRENT_THREAD, &failures);
    out.text = read_text(path);
  }
  for (int i = 0; i < failures.size(); ++i)
    out.messages.emplace_back(failures.GetTestPartResult(i).message());
  return out;
}

TEST(ReadText, ADirectoryFailsTheCallerInsteadOfReadingEmpty) {
  // a directory opens as a file stream on Linux and reads as nothing
  const fs::path dir = scratch();
  const Caught c = read_caught(dir);
  EXPECT_EQ(c.text, "");
  ASSERT_EQ(c.messages.size(), 1u);
  EXPECT_NE(c.messages[0].find("directory"), std::string::npos) << c.messages[0];
  EXPECT_NE(c.messages[0].find(dir.string()), std::string::npos) << c.messages[0];
  fs::remove_all(dir);
}

TEST(ReadText, AReadErrorAfterOpeningFailsTheCaller) {
  // /proc/self/mem opens for reading, and reading at offset 0 (never mapped) fails with EIO
  const fs::path mem = "/proc/self/mem";
  if (!fs::exists(mem)) GTEST_SKIP() << "no " << mem << " here";
  ASSERT_TRUE(std::ifstream(mem, std::ios::binary).is_open());
  const Caught c = read_caught(mem);
  EXPECT_EQ(c.text, "");
  ASSERT_EQ(c.messages.size(), 1u);
  EXPECT_NE(c.messages[0].find("read error in " + mem.string()), std::string::npos)
      << c.messages[0];
}

}  // namespace
