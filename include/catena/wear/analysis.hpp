// `wear`: hinge wear and elongation life, sliding versus rolling hinges (seed 000 §2,
// conclusions 8, 10, 11) as the analysis interface describes it.
#pragma once

#include "catena/analysis/analysis.hpp"
#include "catena/wear/wear.hpp"

namespace catena::wear {

/// What `wear` computed: the inputs as the model took them and the life.
struct WearAnalysis {
  Input input;
  Result result;
};

/// The analysis description (registered as "wear").
const analysis::Analysis& wear_analysis();

/// Runs it on bound inputs (throws InputError, fields named by parameter key).
WearAnalysis wear_analysis_run(const analysis::Inputs& inputs);

}  // namespace catena::wear
