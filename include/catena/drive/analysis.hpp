// `sprocket`: the ISO 606 tooth form as an analysis (docs/models/sprocket.md).
#pragma once

#include <optional>
#include <string>

#include "catena/analysis/analysis.hpp"
#include "catena/drive/sprocket.hpp"

namespace catena::drive {

/// What `sprocket` computed: the chain it was given (name empty for --pitch …) and the form.
struct SprocketAnalysis {
  std::string chain;
  Sprocket sprocket;
  std::vector<Diagnostic> diagnostics;
};

/// The analysis description (registered as "sprocket").
const analysis::Analysis& sprocket_analysis();

/// Runs it on bound inputs (throws InputError, fields named by parameter key).
SprocketAnalysis sprocket_analysis_run(const analysis::Inputs& inputs);

/// The drawing: both gap forms' closed outlines, the pitch and the root circle.
Drawing sprocket_drawing(const Sprocket& s);

}  // namespace catena::drive
