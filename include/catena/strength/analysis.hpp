// `strength`: the strength checks of seed 000 §1.5 as the analysis interface describes them —
// their parameters (plate heights and widths, pin, plate section, hinge kind, loads, material),
// run (the inputs as the model takes them, then assess) and describe (JSON fields, table, CSV of
// the M and Q diagrams, the report's safety-factor grid and diagrams).
#pragma once

#include "catena/analysis/analysis.hpp"
#include "catena/strength/strength.hpp"

namespace catena::strength {

/// What `strength` computed: the inputs as the model took them and its result.
struct StrengthAnalysis {
  Input input;
  Result result;
};

/// The analysis description (registered as "strength").
const analysis::Analysis& strength_analysis();

/// Runs it on bound inputs (throws InputError, fields named by parameter key).
StrengthAnalysis strength_analysis_run(const analysis::Inputs& inputs);

}  // namespace catena::strength
