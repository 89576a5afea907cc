// Chain tension around a conveyor loop by the contour (point-by-point) method (seed 000 §1.5,
// fig. 19).
//
// The thesis shows the tension distribution of fig. 19 in words only (greatest on the branch that
// runs onto the drive sprocket, falling over the sprocket to a minimum where the links leave it)
// and gives no numbers. We use the standard traction calculation of conveyor textbooks
// (Spivakovsky & Dyachkov, "Conveyors and related equipment", the chain-conveyor chapters; the
// same bookkeeping as ISO 5048 / DIN 22101 for belts): walk the loop in the direction of travel
// from the slack side of the drive sprocket and add each segment's resistance,
//   straight run      S_out = S_in + (q0 + q)·L·(w·cosβ + sinβ)
//   turn (not drive)  S_out = k·S_in            or  S_out = S_in·exp(f·α)   (Euler)
//   take-up           S_out = S_in, and S there is the pretension S0
//   drive             F = S_tight − S_slack + ξ·(S_tight + S_slack)
// Every segment maps the tension affinely, S_out = a·S_in + b, so the take-up condition is solved
// exactly. docs/models/loop.md states the conventions and assumptions.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "catena/core/error.hpp"

namespace catena::strength {

enum class SegmentKind { kStraight, kTurn, kTakeup, kDrive };

/// "straight", "turn", "takeup", "drive".
const char* to_string(SegmentKind kind);

/// One piece of the loop, in the direction of travel. Only the fields of its kind are read.
struct Segment {
  SegmentKind kind = SegmentKind::kStraight;
  std::string name;  ///< optional label for the output

  // straight
  double length = 0.0;        ///< [m] L, along the run (> 0)
  double incline = 0.0;       ///< [rad] β, positive when the run rises in the travel direction
  double chain_weight = 0.0;  ///< [N/m] q0, weight of the chain (all strands) per metre (≥ 0)
  double load_weight = 0.0;   ///< [N/m] q, weight of the load per metre (0 on the return run)
  double resistance = 0.0;    ///< [-] w, running resistance factor of the run (0 ≤ w ≤ 1)

  // turn: exactly one of `factor` or (`wrap` and `friction`)
  std::optional<double> factor;    ///< [-] k ≥ 1, S_out = k·S_in
  std::optional<double> wrap;      ///< [rad] α, wrap angle of a curved guide (0 ≤ α ≤ 2π)
  std::optional<double> friction;  ///< [-] f, friction on the guide (0 ≤ f ≤ 1)

  // take-up
  double pretension = 0.0;  ///< [N] S0, the tension the take-up sets at its point (≥ 0)

  // drive
  double loss = 0.0;  ///< [-] ξ, drive sprocket loss: F += ξ·(S_tight + S_slack) (0 ≤ ξ ≤ 0.5)
};

struct Loop {
  std::vector<Segment> segments;      ///< travel order, from the drive's slack side; the drive last
  double speed = 0.0;                 ///< [m/s] chain speed v (> 0)
  double efficiency = 1.0;            ///< [-] η of the drive train (0 < η ≤ 1)
  std::optional<double> min_tension;  ///< [N] a diagnostic fires below it (≥ 0)
  std::optional<double> allowable_tension;  ///< [N] breaking force / safety factor (> 0)
};

/// Every problem with the inputs at once; fields are named "segment[i].length" (0-based index),
/// "speed", etc.
std::vector<Issue> validate(const Loop& loop);

/// The affine map of one (non-drive) segment: S_out = a·S_in + b.
struct Affine {
  double a = 1.0;  ///< [-]
  double b = 0.0;  ///< [N]
};
Affine affine(const Segment& segment);

struct SegmentTension {
  double s_start = 0.0;      ///< [m] path length from the drive's slack side at the segment start
  double s_end = 0.0;        ///< [m] … at its end (turns, take-up and drive have no length)
  double tension_in = 0.0;   ///< [N] S at the start
  double tension_out = 0.0;  ///< [N] S at the end (for the drive: S_slack, the loop's start)
  double resistance = 0.0;   ///< [N] S_out − S_in (for the drive: the force it supplies, −F)
};

struct Extremum {
  double tension = 0.0;     ///< [N]
  std::size_t segment = 0;  ///< index of the segment
  bool at_end = false;      ///< at the segment's end (else its start)
  double s = 0.0;           ///< [m] path length
};

struct LoopResult {
  std::vector<SegmentTension> segments;  ///< one per input segment
  double slack_tension = 0.0;            ///< [N] S leaving the drive sprocket (start of the walk)
  double tight_tension = 0.0;            ///< [N] S arriving at the drive sprocket
  double drive_force = 0.0;              ///< [N] peripheral force F = S_t − S_s + ξ(S_t + S_s)
  double power = 0.0;   ///< [W] F·v/η (F ≥ 0); F·v·η when the drive brakes (F < 0)
  double length = 0.0;  ///< [m] path length of the loop
  Extremum max;         ///< greatest tension over the points
  Extremum min;         ///< least tension over the points
  std::vector<Diagnostic> diagnostics;
};

/// Solves the loop: throws InputError when validate() finds problems.
LoopResult solve(const Loop& loop);

}  // namespace catena::strength
