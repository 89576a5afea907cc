// `dynamics`: a roller-chain loop over two ISO 606 sprockets stepped in time (issue 21,
// docs/models/dynamics.md) as an analysis. Its input is the [dynamics] table with
// [[dynamics.sprocket]] elements (a case file's, or a TOML file named on the command line);
// --duration and --step override the table's.
#pragma once

#include "catena/analysis/analysis.hpp"

namespace catena::dynamics {

/// The analysis description (registered as "dynamics").
const analysis::Analysis& dynamics_analysis();

}  // namespace catena::dynamics
