// Output destinations shared by the subcommands: files written all or nothing, stdout last.
#pragma once

#include <atomic>
#include <chrono>
#include <csignal>
#include <string>
#include <string_view>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/core/progress.hpp"

namespace catena::cli {

/// The outputs of one command, written all or nothing: every file goes to a temporary beside its
/// target first; only when all are written are they renamed into place. Then the text meant for
/// stdout is printed (when no --output file took it). An unwritable path, or two outputs to one
/// file, is invalid input; a write that fails once started (disk full) throws io::WriteError.
class Outputs {
 public:
  /// `flag` names the option the path came from, for the error message.
  void add(std::string flag, std::string path, std::string content);
  /// An input of the command (the case file) that no output may replace; `flag` names it.
  void keep(std::string flag, std::string path);
  /// Writes everything; `stdout_text` goes to stdout unless empty.
  void commit(const std::string& stdout_text = "");

 private:
  struct File {
    std::string flag, path, content;
  };
  std::vector<File> files_, kept_;
};

/// While one is alive, Ctrl-C (SIGINT) only sets a flag — the handler does nothing else, so it
/// is async-signal-safe — and restores the default action, so that a second Ctrl-C ends the
/// process at once. The run polls the flag (interrupt_flag()) and stops with catena::Cancelled;
/// main() then exits 130 and nothing has been written.
class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

 private:
  struct sigaction previous_ {};
  bool installed_ = false;
};

/// The flag that SIGINT sets while an InterruptGuard is alive (false otherwise).
const std::atomic<bool>* interrupt_flag();

/// Throws catena::Cancelled when Ctrl-C was pressed (Outputs::commit asks before the renames).
void throw_if_interrupted();

/// The progress bar of long runs on stderr: drawn only when stderr is a terminal and the run has
/// taken a second, as catena::progress_line ("catena sweep [####....] 120/400 points, 3 s"),
/// redrawn in place; the line ends when the run does.
class ProgressBar {
 public:
  ProgressBar();
  /// False when stderr is not a terminal: nothing will ever be drawn (do not listen at all).
  bool terminal() const { return terminal_; }
  void draw(std::string_view label, std::size_t done, std::size_t total, std::string_view unit);
  /// Ends the bar's line, so that later messages start on their own.
  void finish();
  ~ProgressBar() { finish(); }
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

 private:
  using Clock = std::chrono::steady_clock;
  bool terminal_;
  bool drawn_ = false;
  std::size_t length_ = 0;  ///< of the line drawn last (a shorter one is padded over it)
  Clock::time_point start_;
};

/// What a command gives the library to listen to its run: the interrupt flag, and, on a
/// terminal, reports drawn on `bar` labelled `label` ("ring"; "run <analysis>" for case runs,
/// where `label` is "run" and the analysis' name is added).
Progress listen(ProgressBar& bar, std::string label, bool name_analysis = false);

/// A command's text output: to the --output FILE when one is given, else to stdout. A
/// `case_path` (the file the command read) is kept: an --output onto it is refused.
void write_text_output(const std::string& output, const std::string& text,
                       const std::string& case_path = "");

/// Names each error diagnostic of a run on stderr (`catena: error: <where>: message`, `where`
/// the case run's analysis, or nothing for a subcommand): the text table and CSV carry no
/// diagnostics. The exit status stays 0 (issue 2's contract: 0 whenever the analysis ran, its
/// diagnostics part of the output).
void report_errors(const std::vector<Diagnostic>& diagnostics, const std::string& where);

}  // namespace catena::cli
