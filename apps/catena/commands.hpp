// Subcommands of the catena program. Each registers its flags and returns the action to run.
#pragma once

#include <functional>

namespace CLI {
class App;
}

namespace catena::cli {

/// Registers `catena pocketwheel` on `app`; the returned action runs it and returns the exit code.
std::function<int()> add_pocketwheel(CLI::App& app);
/// Registers `catena hinge` (and `catena hinge sweep`).
std::function<int()> add_hinge(CLI::App& app);
/// Registers `catena contact` and `catena fretting`.
std::function<int()> add_contact(CLI::App& app);
std::function<int()> add_fretting(CLI::App& app);

}  // namespace catena::cli
