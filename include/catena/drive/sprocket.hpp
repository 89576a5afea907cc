// The ISO 606 sprocket tooth form: pitch, root, seat and tip diameters, the seating curve, the
// roller seating angle and the tooth flank of the minimum and the maximum tooth-gap form, the tooth
// width, and the closed tooth outline of the whole sprocket (docs/models/sprocket.md).
//
// ISO 606 writes the radii in millimetres (ri,max has a cube root of d1 in mm); this interface is
// in SI metres and radians like the rest of the library, and converts inside.
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "catena/core/error.hpp"

namespace catena::drive {

struct SprocketInput {
  double pitch = 0.0;                      ///< [m] p
  double roller_diameter = 0.0;            ///< [m] d1 (max)
  double inner_width = 0.0;                ///< [m] b1 (min)
  int teeth = 0;                           ///< z
  int strands = 1;                         ///< k
  std::optional<double> transverse_pitch;  ///< [m] pt, multi-strand chains
  std::optional<double> tooth_width;       ///< [m] bf1 given by the user (overrides the factor)
};

/// One tooth-gap form: its three radii and where its tooth ends.
struct GapForm {
  double seating_radius = 0.0;  ///< [m] ri
  double seating_angle = 0.0;   ///< [rad] α
  double flank_radius = 0.0;    ///< [m] re
  /// [m] the diameter at which the two flanks of one tooth meet (on the tooth's centre line)
  double flank_meeting_diameter = 0.0;
  /// [m] where the outline's tooth ends: min(flank meeting diameter, da,max)
  double outline_tip_diameter = 0.0;
  bool flanks_meet_below_tip = false;  ///< the meeting point lies below da,max
};

struct Sprocket {
  SprocketInput input;
  double pitch_diameter = 0.0;      ///< [m] d = p / sin(180°/z)
  double root_diameter = 0.0;       ///< [m] df = d − d1
  double seat_diameter_min = 0.0;   ///< [m] d − 2 ri,max
  double seat_diameter_max = 0.0;   ///< [m] d − 2 ri,min
  double tip_diameter_min = 0.0;    ///< [m] da,min = d + p (1 − 1.6/z) − d1
  double tip_diameter_max = 0.0;    ///< [m] da,max = d + 1.25 p − d1
  double seating_radius_min = 0.0;  ///< [m] ri,min = 0.505 d1
  double seating_radius_max = 0.0;  ///< [m] ri,max = 0.505 d1 + 0.069 ∛d1 (mm)
  double seating_angle_min = 0.0;   ///< [rad] α,min = 120° − 90°/z
  double seating_angle_max = 0.0;   ///< [rad] α,max = 140° − 90°/z
  double flank_radius_min = 0.0;    ///< [m] re,min = 0.12 d1 (z + 2)
  double flank_radius_max = 0.0;    ///< [m] re,max = 0.008 d1 (z² + 180)
  /// [m] bf1: 0.95 b1 for one strand and p > 12.7 mm, or as given; empty otherwise (no source)
  std::optional<double> tooth_width;
  std::optional<double> strand_width;  ///< [m] bf(k) = pt (k − 1) + bf1, several strands
  double side_radius = 0.0;            ///< [m] rx = p
  double side_relief_min = 0.0;        ///< [m] ba = 0.10 p
  double side_relief_max = 0.0;        ///< [m] ba = 0.15 p
  double measurement_over_pins = 0.0;  ///< [m] MR over pins of diameter d1
  GapForm min_gap;                     ///< ri,min with α,max and re,max
  GapForm max_gap;                     ///< ri,max with α,min and re,min
};

/// Every problem with the input, fields named "pitch", "roller_diameter", "inner_width",
/// "teeth", "strands", "transverse_pitch", "tooth_width".
std::vector<Issue> validate(const SprocketInput& in);

/// The tooth form; throws InputError for invalid input.
Sprocket sprocket(const SprocketInput& in);

/// The closed tooth outline of the whole sprocket for one gap form, centred on the origin with
/// the first roller seat on the +x axis, counter-clockwise; [m]. `points_per_arc` samples each of
/// the seating arc, the flank and the tip arc (per half tooth), both ends included.
std::vector<std::pair<double, double>> tooth_outline(const Sprocket& s, const GapForm& form,
                                                     int points_per_arc = 24);

}  // namespace catena::drive
