// Progress and cancellation of a long run, for every analysis alike. A front end that listens
// hands a Progress to the run (Inputs::listen, catena::run, SweepOptions::cancel); the analysis'
// long loops poll it through a ProgressLoop — a step reports how far the loop has come and, when
// the Progress was cancelled (a flag set from another thread or a signal handler), throws
// Cancelled, so that a cancelled run never returns a partial result. With nobody listening a
// loop costs one thread-local load when it starts and one branch per step.
#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace catena {

/// Thrown at the poll after the Progress' cancel flag was set. Not an InputError: the input was
/// fine, the run was stopped.
class Cancelled : public std::runtime_error {
 public:
  Cancelled() : std::runtime_error("cancelled") {}
};

/// One report of a loop: the analysis it belongs to, what the loop counts ("nodes",
/// "harmonics", "points"), and how many of `total` are done (0 ≤ done ≤ total).
struct ProgressReport {
  std::string_view analysis;
  std::string_view unit;
  std::size_t done = 0;
  std::size_t total = 0;
};

/// What a listening front end gives a run. Both members are optional.
struct Progress {
  /// Set to true (from any thread, or a signal handler: a lock-free atomic) to stop the run at
  /// its next poll with Cancelled.
  const std::atomic<bool>* cancel = nullptr;
  /// Called on the running thread from the outermost loop of the run: at most every
  /// `interval` and once when the loop ends (done == total), with done never decreasing within a
  /// loop. Not called from the loops nested in it.
  std::function<void(const ProgressReport&)> report;
  std::chrono::steady_clock::duration interval = std::chrono::milliseconds(50);

  bool cancelled() const noexcept {
    return cancel != nullptr && cancel->load(std::memory_order_relaxed);
  }
  /// Throws Cancelled when cancelled().
  void throw_if_cancelled() const {
    if (cancelled()) throw Cancelled();
  }
};

/// Makes `progress` the one the loops of this thread poll, on behalf of `analysis`, until the
/// scope ends (Analysis::evaluate opens one; scopes nest and restore the previous one).
class ProgressScope {
 public:
  ProgressScope(const Progress* progress, std::string_view analysis);
  ~ProgressScope();
  ProgressScope(const ProgressScope&) = delete;
  ProgressScope& operator=(const ProgressScope&) = delete;

 private:
  const Progress* previous_;
  std::string_view previous_analysis_;
  int previous_depth_;
};

/// A long loop of an analysis: `total` steps counted in `unit` (a literal: "nodes"). Checks for
/// cancellation when it starts and at every step; the outermost loop of a run also reports.
class ProgressLoop {
 public:
  ProgressLoop(std::size_t total, std::string_view unit);
  ~ProgressLoop();
  ProgressLoop(const ProgressLoop&) = delete;
  ProgressLoop& operator=(const ProgressLoop&) = delete;

  /// `done` of the total steps are done (call with i + 1 after step i). Throws Cancelled.
  void step(std::size_t done) {
    if (progress_ != nullptr) poll(done);
  }

 private:
  void poll(std::size_t done);
  const Progress* progress_;
  std::size_t total_;
  std::string_view unit_;
  bool reports_ = false;
  std::size_t reported_ = 0;
  std::chrono::steady_clock::time_point last_{};
};

/// Throws Cancelled when the thread's current Progress was cancelled (a poll outside a loop).
void check_cancelled();

/// The progress line that the command line draws on a terminal, without its leading carriage
/// return: "catena sweep [####....] 120/400 points, 3 s" — `label` ("sweep", "ring"), a bar of
/// `width` characters filled done/total ('#' done, '.' to do), the counts, the unit and the whole
/// seconds since the run started. done > total is drawn as total.
std::string progress_line(std::string_view label, std::size_t done, std::size_t total,
                          std::string_view unit, double seconds, int width = 40);

}  // namespace catena
