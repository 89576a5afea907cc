// `loop`: conveyor loop tensions by the contour method (seed 000 §1.5 fig. 19) as an analysis.
// Its one input is a table, [loop] with [[loop.segment]] elements (a case file's, or a TOML file
// named on the command line); the keys and their bare units are the table parameter's fields.
#pragma once

#include <string>

#include "catena/analysis/analysis.hpp"
#include "catena/strength/loop.hpp"

namespace catena::strength {

struct LoopAnalysis {
  Loop loop;
  std::string name;  ///< loop.name, when given
  bool has_name = false;
  LoopResult result;
};

/// The analysis description (registered as "loop").
const analysis::Analysis& loop_analysis();

/// The `loop` table parameter ([loop] with [[loop.segment]]): its keys and their bare units. Other
/// analyses that read a case's loop (wear: the tensions at the sprockets) take a copy.
const analysis::Parameter& loop_table_parameter();

/// Reads a bound [loop] table and solves it, exactly as `catena loop` does. Throws InputError
/// naming the table's paths and lines ("loop.segment[2].length (line 27)", "loop").
LoopAnalysis loop_from_table(const analysis::InputValue& table);

}  // namespace catena::strength
