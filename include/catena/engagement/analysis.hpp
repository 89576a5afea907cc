// `engagement`: chain–sprocket engagement forces for sliding and rolling hinges (seed 000
// §1.6.1–1.6.2) as the analysis interface describes it — its parameters (hinge, pitch, teeth,
// tension, and each hinge's own), run (one engagement and the whole wrap) and describe (JSON
// fields, table, CSV series, report charts).
#pragma once

#include "catena/analysis/analysis.hpp"
#include "catena/engagement/engagement.hpp"

namespace catena::engagement {

/// What `engagement` computed: the inputs as the model took them, one engagement, the wrap.
struct EngagementAnalysis {
  bool rolling = false;
  double pitch = 0.0;       ///< [m] t
  double tension = 0.0;     ///< [N] F1
  double wrap_angle = 0.0;  ///< [rad]
  SlidingInput sliding;     ///< when !rolling
  RollingInput rolling_in;  ///< when rolling
  Result result;
  Wrap wrap;
};

/// The analysis description (registered as "engagement").
const analysis::Analysis& engagement_analysis();

/// Runs it on bound inputs (throws InputError, fields named by parameter key).
EngagementAnalysis engagement_analysis_run(const analysis::Inputs& inputs);

}  // namespace catena::engagement
