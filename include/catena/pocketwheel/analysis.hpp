// `pocketwheel`: the run-on analysis of seed 003 as the analysis interface describes it — its
// parameters (pitch, wire, teeth, omega, guide, …), run (one run-on, or the paper's three with
// --example) and describe (JSON fields, table, CSV series, drawing, report charts).
#pragma once

#include <vector>

#include "catena/analysis/analysis.hpp"
#include "catena/pocketwheel/run_on.hpp"

namespace catena::pocketwheel {

/// What `pocketwheel` computed: the inputs as the model took them and one result per guide.
struct RunOnAnalysis {
  PocketWheel wheel;
  std::vector<Guide> guides;  ///< one, or the paper's three with --example and no --guide
  Sampling sampling;
  bool numeric = false;              ///< --method numeric: the independent geometric solver
  std::vector<RunOnResult> results;  ///< per guide
};

/// The analysis description (registered as "pocketwheel").
const analysis::Analysis& run_on_analysis();

/// Runs it on bound inputs (throws InputError, fields named by parameter key).
RunOnAnalysis run_on_analysis_run(const analysis::Inputs& inputs);

}  // namespace catena::pocketwheel
