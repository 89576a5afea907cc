// `wear`: hinge wear and elongation life, sliding versus rolling hinges (seed 000 §2,
// conclusions 8, 10, 11) as the analysis interface describes it.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "catena/analysis/analysis.hpp"
#include "catena/wear/wear.hpp"

namespace catena::wear {

/// One articulation's load taken from the loop: where the chain enters or leaves a sprocket.
struct LoopLoad {
  std::size_t segment = 0;  ///< the loop segment (a drive, or a turn given by a factor)
  std::string name;         ///< its name
  bool entry = true;        ///< entering the sprocket (its tension_in), else leaving (tension_out)
  double tension = 0.0;     ///< [N]
};

/// Where the loads came from.
struct Loads {
  bool from_loop = false;        ///< tension_source = loop
  std::vector<LoopLoad> points;  ///< from_loop: one per articulation, in travel order
  bool speed_from_loop = false;
  bool loop_length_from_loop = false;
};

/// The other hinge type on the same chain, sprocket and loads (compare_wear_coefficient).
struct Other {
  Input input;
  Result result;
};

/// What `wear` computed: the inputs as the model took them and the life.
struct WearAnalysis {
  Input input;
  Loads loads;
  Result result;
  std::optional<Other> other;  ///< compare_wear_coefficient given
};

/// The analysis description (registered as "wear").
const analysis::Analysis& wear_analysis();

/// Runs it on bound inputs (throws InputError, fields named by parameter key).
WearAnalysis wear_analysis_run(const analysis::Inputs& inputs);

}  // namespace catena::wear
