// `drive` — a two-sprocket roller-chain drive: layout (links, textbook and exact polygon-wrap
// centre distance, wrap, spans), loads (tensions, shaft loads, sag) and the ANSI rating where a
// public formula exists — and `drive select` — every catalogued chain and strand count that
// carries a design power (issue 16 §3).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "catena/analysis/analysis.hpp"
#include "catena/contact/chain_catalog.hpp"
#include "catena/drive/layout.hpp"
#include "catena/drive/rating.hpp"

namespace catena::drive {

/// What `drive` computed (SI).
struct DriveResult {
  contact::ChainDimensions chain;
  int z1 = 0, z2 = 0, strands = 1;
  double speed = 0.0;                           ///< [rad/s] driver
  double power = 0.0;                           ///< [W] transmitted
  std::optional<double> given_center_distance;  ///< [m]
  std::optional<double> links_exact;            ///< X for the given centre distance, unrounded
  int links = 0;
  double center_distance_formula = 0.0;         ///< [m] textbook, from X
  ExactCenterDistance exact;                    ///< polygon wrap over one driver pitch
  double chain_length = 0.0;                    ///< [m] X p
  double speed_ratio = 0.0;                     ///< z2 / z1
  double chain_speed = 0.0;                     ///< [m/s]
  double chordal_variation = 0.0;               ///< (vmax − vmin)/vmax
  double wrap_driver = 0.0, wrap_driven = 0.0;  ///< [rad] on the pitch circles
  double span_length = 0.0;                     ///< [m] common tangent of the pitch circles
  double mass_per_metre = 0.0;                  ///< [kg/m] of the chain (all strands)
  double effective_tension = 0.0;               ///< [N] P / v
  double centrifugal_tension = 0.0;             ///< [N] q v²
  double slack_tension = 0.0;                   ///< [N] q v² + H
  double tight_tension = 0.0;                   ///< [N] P / v + q v² + H
  std::optional<double> horizontal_tension;     ///< [N] H given
  std::optional<double> slack;                  ///< [m] ΔL given
  std::optional<double> sag_from_tension, sag_from_slack;  ///< [m]
  ShaftLoads shaft;
  std::optional<double> service_factor;
  std::optional<Rating> rating;
  std::vector<Diagnostic> diagnostics;
};

/// One candidate of `drive select`.
struct Candidate {
  std::string chain;
  double pitch = 0.0;  ///< [m]
  int strands = 1;
  Rating rating;
};

/// What `drive select` computed.
struct SelectResult {
  double power = 0.0, speed = 0.0, ratio = 0.0, service_factor = 0.0;
  int driver_teeth = 0, driven_teeth = 0, max_strands = 0;
  double design_power = 0.0;
  std::vector<Candidate> candidates;  ///< smallest pitch first, then fewest strands
  std::vector<Diagnostic> diagnostics;
};

const analysis::Analysis& drive_analysis();
const analysis::Analysis& drive_select_analysis();

DriveResult drive_run(const analysis::Inputs& inputs);
SelectResult drive_select_run(const analysis::Inputs& inputs);

}  // namespace catena::drive
