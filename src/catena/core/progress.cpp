#include "catena/core/progress.hpp"

#include <algorithm>
#include <cstdio>

namespace catena {
namespace {

// The Progress the loops of this thread poll (none: nobody listens), the analysis it runs, and
// how many loops are open inside the current scope (only the outermost reports).
struct Current {
  const Progress* progress = nullptr;
  std::string_view analysis;
  int depth = 0;
};
thread_local Current current;

}  // namespace

ProgressScope::ProgressScope(const Progress* progress, std::string_view analysis)
    : previous_(current.progress),
      previous_analysis_(current.analysis),
      previous_depth_(current.depth) {
  current = {progress, analysis, 0};
}

ProgressScope::~ProgressScope() { current = {previous_, previous_analysis_, previous_depth_}; }

ProgressLoop::ProgressLoop(std::size_t total, std::string_view unit)
    : progress_(current.progress), total_(total), unit_(unit) {
  if (progress_ == nullptr) return;
  reports_ = current.depth == 0 && static_cast<bool>(progress_->report);
  ++current.depth;
  try {
    progress_->throw_if_cancelled();
    if (reports_) {
      progress_->report({current.analysis, unit_, 0, total_});
      last_ = std::chrono::steady_clock::now();
    }
  } catch (...) {
    --current.depth;
    throw;
  }
}

ProgressLoop::~ProgressLoop() {
  if (progress_ != nullptr) --current.depth;
}

void ProgressLoop::poll(std::size_t done) {
  progress_->throw_if_cancelled();
  if (!reports_) return;
  done = std::min(done, total_);
  if (done < reported_) return;  // never backwards
  const auto now = std::chrono::steady_clock::now();
  if (done != total_ && now - last_ < progress_->interval) return;
  if (done == total_ && reported_ == total_ && total_ != 0) return;  // the end once
  reported_ = done;
  last_ = now;
  progress_->report({current.analysis, unit_, done, total_});
}

void check_cancelled() {
  if (current.progress != nullptr) current.progress->throw_if_cancelled();
}

std::string progress_line(std::string_view label, std::size_t done, std::size_t total,
                          std::string_view unit, double seconds, int width) {
  done = std::min(done, total);
  const int filled = total == 0 ? width : static_cast<int>(width * done / total);
  std::string line = "catena " + std::string(label) + " [";
  line.append(static_cast<std::size_t>(filled), '#');
  line.append(static_cast<std::size_t>(width - filled), '.');
  char counts[96];
  std::snprintf(counts, sizeof counts, "] %zu/%zu ", done, total);
  line += counts;
  line += unit;
  std::snprintf(counts, sizeof counts, ", %.0f s", seconds);
  line += counts;
  return line;
}

}  // namespace catena
