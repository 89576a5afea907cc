// The library's entry point: every analysis Catena has, their parameter tables, and running one
// by name with values as a user types them ("64 mm", "29.4kN", a bare number in the parameter's
// default unit). The command line, case files, the report, the Python module and sweeps all go
// through here.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "catena/analysis/analysis.hpp"

namespace catena {

/// Every analysis, in registry order.
const std::vector<const analysis::Analysis*>& analyses();

/// The analysis called `name` ("pocketwheel", "hinge_sweep"), or nullptr.
const analysis::Analysis* find_analysis(std::string_view name);

/// Binds `inputs` (key → text) to the analysis' parameters, runs it and describes the result.
/// A table parameter's text is the path of a TOML file holding the table (as on the command line).
/// Throws InputError listing every problem at once, fields named by parameter key. Safe to call
/// from several threads at once (sweeps do): the registry is built once and only read, analyses
/// keep no state between runs, and UDUNITS-2 (not thread-safe) is used under one mutex in
/// io/quantity.cpp; tests/analysis/sweep_test.cpp runs it on 8 threads. The run reports to and
/// stops on `progress` when given (catena/core/progress.hpp): cancelled, it throws Cancelled.
analysis::Record run(std::string_view name,
                     const std::vector<std::pair<std::string, std::string>>& inputs,
                     const Progress* progress = nullptr);

}  // namespace catena
