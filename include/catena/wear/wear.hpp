// Hinge wear and elongation life of a conveyor chain, sliding versus rolling hinges (seed 000 §2,
// conclusions 8, 10, 11; docs/models/wear.md).
//
// Archard's law per surface, V = k·F·s/H, with the sliding distance s of every articulation taken
// from Catena's own kinematics: the engagement model's criteria (24)/(25) say on which pair of
// surfaces a sliding hinge slides; the hinge model's pose and rolling limit (eq. 21) say how far a
// rolling hinge rolls and where it slides; micro-slip of the rolling contact follows Carter's
// creep law. Wear depths of each part give the pitch extension and the elongation ε(t); the life
// to each retirement limit follows from block extrapolation (geometry re-solved every ΔN passes).
//
// Parts are named after the thesis' chain: its "rollers" (Latvian asītes) are the hinge pivots
// and the plates carry the bores (sliding) or the convex working arcs (rolling). That chain has no
// pin and no bush; those parts are reported as absent.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/core/hertz.hpp"
#include "catena/hinge/hinge.hpp"

namespace catena::wear {

enum class HingeKind { kSliding, kRolling };

/// How far a rolling hinge rolls before it slides.
enum class RollingLimit {
  kFriction,  ///< friction alone: rolling up to eq. (21), the rest of the turn slides
  kGuided,    ///< the figured aperture keeps it rolling over the whole turn (conclusion 4)
};

/// Micro-slip of the rolling contact.
enum class Creep {
  kCarter,  ///< Carter's 2-D creep law (Johnson, Contact Mechanics, §8.2)
  kNone,    ///< none (for checks: a hinge that only rolls then does not wear)
};

struct Input {
  HingeKind hinge = HingeKind::kRolling;
  double pitch = 0.0;     ///< [m] t
  int teeth = 0;          ///< [-] z
  int strokes = 1;        ///< [-] m; mutual turn per articulation 360°·m/z
  int articulations = 4;  ///< [-] articulations per pass of the loop (2 per sprocket)
  double tension = 0.0;   ///< [N] chain tension at the articulations
  /// [N] tension at each articulation of a pass (the loop's tensions at the sprockets); empty:
  /// `tension` at every one; otherwise one value (≥ 0) per articulation.
  std::vector<double> tensions;
  double speed = 0.0;             ///< [m/s] chain speed
  double loop_length = 0.0;       ///< [m] chain length of the loop (one pass = loop_length / speed)
  double wear_coefficient = 0.0;  ///< [-] Archard k of the pivot–plate pair
  double plate_hardness = 0.0;    ///< [Pa] H of the plates
  double roller_hardness = 0.0;   ///< [Pa] H of the pivots (the thesis' "rollers")
  double contact_length = 0.0;    ///< [m] L, bearing length of one pivot–plate interface
  double friction = 0.15;         ///< [-] f, pivot–plate friction
  // Sliding hinge (engagement model §1.6.1).
  double journal_diameter = 0.0;  ///< [m] d1, the pivot neck in the plate bore
  double tooth_diameter = 0.0;    ///< [m] d2, the pivot on the tooth
  double tooth_friction = -1.0;   ///< [-] < 0: = friction
  double flank_angle = 0.0;       ///< [rad] ψ
  // Rolling hinge (hinge model §1.2–1.3).
  hinge::Hinge geometry;  ///< d, a, R1, R2 (0 = eq. 6); teeth/strokes copied in
  RollingLimit limit = RollingLimit::kFriction;
  Creep creep = Creep::kCarter;
  Elastic plate_elastic, roller_elastic;
  // Life.
  std::vector<double> limits = {0.015, 0.02, 0.03};  ///< [-] retirement elongations
  double block_passes = 0.0;  ///< ΔN [passes]; 0 = automatic (about 400 blocks to the last limit)
  int samples = 181;          ///< samples of an articulation (numerical integration)
};

/// Every problem at once, fields named by parameter key.
std::vector<Issue> validate(const Input& in);

/// Current state of the worn parts (depths in the loaded direction).
struct Worn {
  double roller = 0.0;  ///< [m] pivot (neck or working face), per interface
  double plate = 0.0;   ///< [m] plate (bore or working arc), per interface
};

/// The sliding of one articulation (mutual turn Δφ at one hinge) and where it lands.
struct Articulation {
  double mutual_turn = 0.0;  ///< [rad] Δφ = 360°·m/z
  // Sliding hinge.
  double turned = 0.0;       ///< [rad] part of Δφ over which the pivot turns against the
                             ///< tooth (criterion 25): the sliding moves to link 2's bore
  double slide_link1 = 0.0;  ///< [m] neck against link 1's bores: r·(Δφ − turned)
  double slide_link2 = 0.0;  ///< [m] neck against link 2's bores: r·turned
  double slide_tooth = 0.0;  ///< [m] pivot on the tooth: (d2/2)·turned
  double neck_spread = 1.0;  ///< [-] 1: wear on the projected neck; 1/π: spread round it
  // Rolling hinge (per interface: each plate turns Δφ/2 against the pivot, eq. 3).
  double plate_turn = 0.0;     ///< [rad] θ per interface
  double rolling_limit = 0.0;  ///< [rad] eq. (21)
  double rolled_turn = 0.0;    ///< [rad] min(θ, limit) (guided: θ)
  double gross_slide = 0.0;    ///< [m] per interface: R1·(θ − limit)
  double micro_slip = 0.0;     ///< [m] per interface: ∫ creep · d(rolled arc)
  double rolled_arc = 0.0;     ///< [m] contact travel on the plate arc R1·ψ1(θ)
  double half_width = 0.0;     ///< [m] Hertz half-width b
  // Both.
  double slide_pivot_plate = 0.0;  ///< [m] all pivot–plate sliding of the articulation
  double band = 0.0;               ///< [m] width over which a part's wear volume spreads
  double roller_depth = 0.0;       ///< [m] pivot wear depth per articulation (all interfaces)
  double plate_depth = 0.0;        ///< [m] plate wear depth per articulation (all interfaces)
  std::vector<Diagnostic> diagnostics;
};

/// One articulation under `in.tension` at the current wear state (the engagement and hinge models
/// re-solved on the worn geometry). Throws InputError for invalid input.
Articulation articulate(const Input& in, const Worn& worn);

/// [m³] Archard: V = k·F·s/H.
double archard_volume(double k, double force, double sliding, double hardness);

/// [-] Carter's creep ratio of a 2-D rolling contact: (μ·b/R*)·(1 − √(1 − Q/(μN))), Q/(μN) ≤ 1.
double carter_creep(double friction, double half_width, double radius, double traction_ratio);

struct Point {
  double hours = 0.0;       ///< [h]
  double elongation = 0.0;  ///< [-] Δt/t
  double roller = 0.0;      ///< [m] pivot wear depth (sum over its interfaces)
  double plate = 0.0;       ///< [m] plate wear depth (sum over interfaces)
};

struct Result {
  double mutual_turn = 0.0;      ///< [rad]
  double passes_per_hour = 0.0;  ///< [1/h]
  double block_passes = 0.0;     ///< ΔN used
  Articulation first;            ///< the new chain's articulation
  Articulation pass;  ///< the new chain's whole pass: slides and depths summed over articulations
  std::vector<Point> series;                      ///< at each block end, from 0 to the last limit
  std::vector<std::optional<double>> life_hours;  ///< per limit; empty: never reached
  Point at_end;                                   ///< wear at the end of the series
  std::vector<Diagnostic> diagnostics;
};

/// The whole life. Throws InputError for invalid input.
Result run(const Input& in);

}  // namespace catena::wear
