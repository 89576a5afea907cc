#include "cli_support.hpp"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <system_error>

#include "catena/io/atomic_file.hpp"

namespace catena::cli {

namespace fs = std::filesystem;

namespace {

std::atomic<bool> interrupted{false};
static_assert(std::atomic<bool>::is_always_lock_free,
              "a signal handler may only set a lock-free atomic");

extern "C" void on_interrupt(int /*signal*/) { interrupted.store(true, std::memory_order_relaxed); }

}  // namespace

InterruptGuard::InterruptGuard() {
  interrupted.store(false);
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  // SA_RESETHAND: the first Ctrl-C asks the run to stop; a second one is the default action
  action.sa_flags = SA_RESTART | SA_RESETHAND;
  installed_ = ::sigaction(SIGINT, &action, &previous_) == 0;
}

InterruptGuard::~InterruptGuard() {
  if (installed_) ::sigaction(SIGINT, &previous_, nullptr);
}

const std::atomic<bool>* interrupt_flag() { return &interrupted; }

void throw_if_interrupted() {
  if (interrupted.load(std::memory_order_relaxed)) throw Cancelled();
}

ProgressBar::ProgressBar() : terminal_(::isatty(STDERR_FILENO) == 1), start_(Clock::now()) {}

void ProgressBar::draw(std::string_view label, std::size_t done, std::size_t total,
                       std::string_view unit) {
  if (!terminal_) return;
  const double seconds = std::chrono::duration<double>(Clock::now() - start_).count();
  if (seconds < 1.0 && !drawn_) return;
  std::string line = progress_line(label, done, total, unit, seconds);
  const std::size_t length = line.size();
  if (length < length_) line.append(length_ - length, ' ');
  std::fprintf(stderr, "\r%s", line.c_str());
  std::fflush(stderr);
  length_ = length;
  drawn_ = true;
}

void ProgressBar::finish() {
  if (drawn_) std::fputs("\n", stderr);
  drawn_ = false;
  length_ = 0;
}

Progress listen(ProgressBar& bar, std::string label, bool name_analysis) {
  Progress progress;
  progress.cancel = interrupt_flag();
  if (bar.terminal()) {
    progress.report = [&bar, label = std::move(label), name_analysis](const ProgressReport& r) {
      if (name_analysis) {
        bar.draw(label + " " + std::string(r.analysis), r.done, r.total, r.unit);
      } else {
        bar.draw(label, r.done, r.total, r.unit);
      }
    };
  }
  return progress;
}

void write_text_output(const std::string& output, const std::string& text,
                       const std::string& case_path) {
  Outputs outputs;
  if (!case_path.empty()) outputs.keep("CASE", case_path);
  if (!output.empty()) outputs.add("--output", output, text);
  outputs.commit(output.empty() ? text : "");
}

void Outputs::keep(std::string flag, std::string path) {
  kept_.push_back({std::move(flag), std::move(path), {}});
}

void Outputs::add(std::string flag, std::string path, std::string content) {
  // Two outputs to one file would leave only the last one there, while both are reported
  // written: refuse them, whatever the spelling of the path (links followed, hard links too).
  // An output onto the command's own input would replace what the user wrote.
  for (const File& f : kept_) {
    if (io::same_file(f.path, path))
      throw InputError({{flag, path,
                         "a file other than " + f.flag + " " + f.path +
                             " (the input read; writing it would replace it)"}});
  }
  // A character device (/dev/null) holds no content to be wrong: it takes any number.
  std::error_code error;
  const bool device = fs::is_character_file(io::output_target(path), error);
  for (const File& f : files_) {
    if (device || !io::same_file(f.path, path)) continue;
    const std::string target = io::output_target(path), other = io::output_target(f.path);
    const std::string both =
        target == other ? "both name " + target : other + " and " + target + " are one file";
    throw InputError(
        {{flag, path,
          "a file other than " + f.flag + "'s (" + both + "): each output needs its own file"}});
  }
  files_.push_back({std::move(flag), std::move(path), std::move(content)});
}

void Outputs::commit(const std::string& stdout_text) {
  // Open every file first (a path that cannot be written is the user's input: nothing is
  // written then), write them, and only when all are written rename them into place.
  std::vector<io::StagedFile> staged;
  staged.reserve(files_.size());
  for (const File& f : files_) {
    try {
      staged.emplace_back(f.path);
    } catch (const io::WriteError& error) {
      throw InputError(
          {{f.flag, f.path, "a writable file path (" + error.reason() + "); nothing was written"}});
    }
  }
  for (std::size_t i = 0; i < files_.size(); ++i) staged[i].write(files_[i].content);
  // Ctrl-C until now: the temporaries are removed (~StagedFile) and nothing is written
  throw_if_interrupted();
  for (io::StagedFile& file : staged) file.commit();
  if (!stdout_text.empty()) io::write_stdout(stdout_text);
}

void report_errors(const std::vector<Diagnostic>& diagnostics, const std::string& where) {
  for (const Diagnostic& d : diagnostics) {
    if (d.severity != Diagnostic::Severity::kError) continue;
    std::cerr << "catena: error: " << (where.empty() ? "" : where + ": ") << d.message << "\n";
  }
}

}  // namespace catena::cli
