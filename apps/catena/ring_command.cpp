// STUB of `catena ring` from branch issue7-capacity (helper): it exists only so that
// `catena ring capacity` and `catena ring design` can be run and tested before the lead's real
// ring_command.cpp (the contact analysis) lands. The lead replaces this whole file and keeps the
// hook: the two add_ring_* calls and the two `if (...->parsed())` dispatch lines below.
#include <CLI/CLI.hpp>
#include <iostream>

#include "commands.hpp"

namespace catena::cli {

std::function<int()> add_ring(CLI::App& app) {
  CLI::App* ring_app = app.add_subcommand(
      "ring", "Orthotropic ring link (seed 002); this branch: the capacity and design parts");
  // --- hook (keep) ---
  auto cap = add_ring_capacity(*ring_app);
  auto des = add_ring_design(*ring_app);
  CLI::App* cap_app = ring_app->get_subcommand("capacity");
  CLI::App* des_app = ring_app->get_subcommand("design");
  // --- end hook ---
  return [=]() {
    if (cap_app->parsed()) return cap();  // hook (keep)
    if (des_app->parsed()) return des();  // hook (keep)
    std::cerr << "catena ring: the contact analysis is not in this branch (stub); use "
                 "`catena ring capacity` or `catena ring design`\n";
    return 2;
  };
}

}  // namespace catena::cli
