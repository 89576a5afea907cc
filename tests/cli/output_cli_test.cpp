// Output that cannot lose data or lie about it, and the case file's boundary: a full disk, two
// outputs to one file, an output through a symbolic link, control characters in the report, and
// case paths that are no case file (issue 18).
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "../read_text.hpp"
#include "cli_run.hpp"

namespace {

namespace fs = std::filesystem;

const std::string kWheel = "pocketwheel --pitch 64 --wire 18 --teeth 8 --omega 5 ";

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("catena_output_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir / name;
}

bool has_full_device() { return fs::is_character_file("/dev/full"); }

TEST(OutputCli, AFullDiskIsAnErrorNamingThePath) {
  if (!has_full_device()) GTEST_SKIP() << "no /dev/full on this system";
  const CliRun file = run(kWheel + "--output /dev/full");
  EXPECT_EQ(file.status, 1) << file.err;
  EXPECT_NE(file.err.find("cannot write '/dev/full'"), std::string::npos) << file.err;
  EXPECT_NE(file.err.find("No space left"), std::string::npos) << file.err;
  EXPECT_TRUE(fs::is_character_file("/dev/full"));  // written to, never replaced

  const CliRun report = run("report -o /dev/full");
  EXPECT_EQ(report.status, 1) << report.err;
  EXPECT_NE(report.err.find("cannot write '/dev/full'"), std::string::npos) << report.err;
  EXPECT_EQ(report.err.find("catena: wrote"), std::string::npos) << report.err;
}

TEST(OutputCli, AStdoutThatCannotBeWrittenIsAnError) {
  if (!has_full_device()) GTEST_SKIP() << "no /dev/full on this system";
  // `run` reads stdout through a pipe; this command sends it to /dev/full instead.
  const CliRun r = run(kWheel + "--format json >/dev/full");
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("cannot write 'stdout'"), std::string::npos) << r.err;
}

TEST(OutputCli, ADeviceIsWrittenDirectly) {
  const CliRun r = run(kWheel + "--output /dev/null");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(r.out.empty());
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
  // a device holds no content to be wrong: two outputs may both be discarded there
  const CliRun both = run(kWheel + "--output /dev/null --csv /dev/null");
  EXPECT_EQ(both.status, 0) << both.err;
}

TEST(OutputCli, TwoOutputsToOneFileAreRefusedNamingBothFlags) {
  const fs::path same = scratch("same.txt");
  fs::remove(same);
  const CliRun table = run(kWheel + "--output " + same.string() + " --csv " + same.string());
  EXPECT_EQ(table.status, 2);
  EXPECT_NE(table.err.find("--output"), std::string::npos) << table.err;
  EXPECT_NE(table.err.find("--csv"), std::string::npos) << table.err;
  EXPECT_FALSE(fs::exists(same));  // nothing written

  // the same file under another spelling
  const fs::path drawing = scratch("wheel.svg");
  const std::string other = (drawing.parent_path() / "." / drawing.filename()).string();
  const CliRun svg = run(kWheel + "--svg " + drawing.string() + " --dxf " + other);
  EXPECT_EQ(svg.status, 2);
  EXPECT_NE(svg.err.find("--svg"), std::string::npos) << svg.err;
  EXPECT_NE(svg.err.find("--dxf"), std::string::npos) << svg.err;
  EXPECT_FALSE(fs::exists(drawing));
}

TEST(OutputCli, AnOutputThroughASymbolicLinkWritesItsTargetAndKeepsTheLink) {
  const fs::path target = scratch("target.json");
  const fs::path link = scratch("link.json");
  fs::remove(link);
  std::ofstream(target) << "old";
  fs::create_symlink(target.filename(), link);  // relative, as people make them
  const CliRun r = run(kWheel + "--format json --output " + link.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::is_symlink(link));
  const std::string written = read_text(target);
  EXPECT_EQ(written.rfind("{", 0), 0u) << written.substr(0, 40);
  // a dangling link: its target is created, the link kept
  fs::remove(target);
  const CliRun again = run(kWheel + "--format json --output " + link.string());
  ASSERT_EQ(again.status, 0) << again.err;
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_TRUE(fs::is_regular_file(target));
}

TEST(OutputCli, AFolderOrAMissingFolderIsInvalidInput) {
  const CliRun folder = run(kWheel + "--output " + fs::temp_directory_path().string());
  EXPECT_EQ(folder.status, 2);
  EXPECT_NE(folder.err.find("--output"), std::string::npos) << folder.err;
  const CliRun missing = run(kWheel + "--output /nonexistent-catena-dir/out.txt");
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("nothing was written"), std::string::npos) << missing.err;
}

TEST(OutputCli, ControlCharactersInACaseReachTheReportAsVisibleSymbols) {
  const fs::path case_path = scratch("control.toml");
  // TOML's \u0000 and \u0007 escapes put a NUL and a BEL into the title.
  std::ofstream(case_path)
      << "title = \"Wheel\\u0000A\\u0007B\"\n"
         "[chain]\ntype = \"round-link\"\npitch = \"64 mm\"\nwire = \"18 mm\"\n"
         "[sprocket]\nteeth = 8\n[analyses.pocketwheel]\nomega = \"5 1/s\"\n";
  const fs::path html = scratch("control.html");
  const CliRun r = run("report " + case_path.string() + " -o " + html.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string page = read_text(html);
  EXPECT_EQ(page.find('\0'), std::string::npos);
  EXPECT_EQ(page.find('\a'), std::string::npos);
  EXPECT_NE(page.find("Wheel\u2400A\u2407B"), std::string::npos);
}

TEST(OutputCli, CasePathsThatAreNoCaseFileAreRefused) {
  const CliRun endless = run("run /dev/zero");
  EXPECT_EQ(endless.status, 2) << endless.err;
  EXPECT_NE(endless.err.find("at most 16 MiB"), std::string::npos) << endless.err;

  const CliRun folder = run("run " + fs::temp_directory_path().string());
  EXPECT_EQ(folder.status, 2);
  EXPECT_NE(folder.err.find("not a folder"), std::string::npos) << folder.err;

  for (const char* command : {"run ''", "report ''"}) {
    const CliRun empty = run(command);
    EXPECT_EQ(empty.status, 2) << command;
    EXPECT_NE(empty.err.find("empty path"), std::string::npos) << empty.err;
  }
}

const char* kCase =
    "title = \"Wheel\"\n"
    "[chain]\ntype = \"round-link\"\npitch = \"64 mm\"\nwire = \"18 mm\"\n"
    "[sprocket]\nteeth = 8\n[analyses.pocketwheel]\nomega = \"5 1/s\"\n";

TEST(OutputCli, AStdoutThatCannotTakeHelpOrVersionIsAnError) {
  if (!has_full_device()) GTEST_SKIP() << "no /dev/full on this system";
  for (const char* command : {"--help >/dev/full", "--version >/dev/full"}) {
    const CliRun r = run(command);
    EXPECT_EQ(r.status, 1) << command;
    EXPECT_NE(r.err.find("cannot write 'stdout': No space left"), std::string::npos) << r.err;
  }
  EXPECT_EQ(run("--version").status, 0);  // a stdout that takes it: as before
}

TEST(OutputCli, ASymbolicLinkLoopIsRefusedAndTheLinksKept) {
  const fs::path one = scratch("loop1.txt"), two = scratch("loop2.txt");
  fs::remove(one);
  fs::remove(two);
  fs::create_symlink(two.filename(), one);
  fs::create_symlink(one.filename(), two);
  const CliRun r = run(kWheel + "--output " + one.string());
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("--output"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("loop"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_symlink(one));  // not replaced by a regular file
  EXPECT_TRUE(fs::is_symlink(two));
}

TEST(OutputCli, TwoOutputsToHardLinksOfOneFileAreRefused) {
  const fs::path first = scratch("hard1.txt"), second = scratch("hard2.txt");
  fs::remove(first);
  fs::remove(second);
  std::ofstream(first) << "old";
  fs::create_hard_link(first, second);
  const CliRun r = run(kWheel + "--output " + first.string() + " --csv " + second.string());
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("--output"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--csv"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("are one file"), std::string::npos) << r.err;
  EXPECT_EQ(read_text(first), "old");  // nothing written, the links not split apart
  EXPECT_TRUE(fs::equivalent(first, second));
}

TEST(OutputCli, AnOutputOntoTheCaseFileIsRefused) {
  const fs::path case_path = scratch("own.toml");
  std::ofstream(case_path) << kCase;
  const fs::path link = scratch("own-link.toml");
  fs::remove(link);
  fs::create_symlink(case_path.filename(), link);
  const std::string other_spelling =
      (case_path.parent_path() / "." / case_path.filename()).string();
  for (const std::string& command :
       {"run " + case_path.string() + " -o " + other_spelling,
        "report " + case_path.string() + " -o " + case_path.string(),
        "report --format json " + link.string() + " -o " + case_path.string()}) {
    const CliRun r = run(command);
    EXPECT_EQ(r.status, 2) << command << "\n" << r.err;
    EXPECT_NE(r.err.find("--output"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("CASE"), std::string::npos) << r.err;
    EXPECT_EQ(read_text(case_path), kCase) << command;  // the case is still the case
  }
  const fs::path result = scratch("own.json");
  const CliRun elsewhere = run("run " + case_path.string() + " -o " + result.string());
  EXPECT_EQ(elsewhere.status, 0) << elsewhere.err;
  EXPECT_EQ(read_text(result).rfind("{", 0), 0u);
}

TEST(OutputCli, ACaseFileOverTheCapNamesItsSizeAndTheCap) {
  constexpr std::uintmax_t kCap = std::uintmax_t{16} << 20;  // [bytes] io::kMaxCaseFileBytes
  const fs::path big = scratch("big.toml");
  fs::remove(big);
  std::ofstream(big) << kCase;
  fs::resize_file(big, kCap + 1);  // sparse: no disk used
  const CliRun over = run("run " + big.string());
  EXPECT_EQ(over.status, 2) << over.err;
  EXPECT_NE(over.err.find(big.string()), std::string::npos) << over.err;
  EXPECT_NE(over.err.find("at most 16 MiB (16777216 bytes)"), std::string::npos) << over.err;
  EXPECT_NE(over.err.find("has 16777217 bytes"), std::string::npos) << over.err;

  // exactly the cap: read and run (the padding is one TOML comment)
  const fs::path at_cap = scratch("at_cap.toml");
  {
    std::ofstream out(at_cap, std::ios::binary);
    const std::string head = std::string(kCase) + "#";
    out << head << std::string(static_cast<std::size_t>(kCap) - head.size(), 'x');
  }
  ASSERT_EQ(fs::file_size(at_cap), kCap);
  const CliRun fits = run("run " + at_cap.string());
  EXPECT_EQ(fits.status, 0) << fits.err.substr(0, 400);
  fs::remove(at_cap);
  fs::remove(big);

  const CliRun endless = run("run /dev/zero");
  EXPECT_EQ(endless.status, 2) << endless.err;
  EXPECT_NE(endless.err.find("/dev/zero"), std::string::npos) << endless.err;
  EXPECT_NE(endless.err.find("reading stopped at the cap"), std::string::npos) << endless.err;
}

}  // namespace
