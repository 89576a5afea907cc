// `warp`: roller warp in the vertical plane (seed 000 §1.4) as the analysis interface describes
// it — its parameters (the four joints, the roller, the hinge, the load sweep), run (one solution
// per load F and height L1) and describe (JSON fields, table, CSV, report chart).
#pragma once

#include <vector>

#include "catena/analysis/analysis.hpp"
#include "catena/warp/warp.hpp"

namespace catena::warp {

/// What `warp` computed: the roller on its joints and one solution per sweep point.
struct WarpAnalysis {
  Warp warp;
  struct Point {
    Load load;
    WarpResult result;
  };
  std::vector<Point> points;  ///< for each force, each load height
  /// One diagnostic per code over the whole sweep: the point where it is worst (largest
  /// value/limit), with the number of sweep points at which it fired.
  struct Finding {
    Diagnostic diagnostic;  ///< its message as first found; value and limit at the worst point
    Load load;              ///< the worst point
    int points = 0;
  };
  std::vector<Finding> findings;
};

/// The analysis description (registered as "warp").
const analysis::Analysis& warp_analysis();

/// Runs it on bound inputs (throws InputError, fields named by parameter key).
WarpAnalysis warp_analysis_run(const analysis::Inputs& inputs);

}  // namespace catena::warp
