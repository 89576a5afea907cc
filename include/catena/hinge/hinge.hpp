// The rolling-friction hinge of a dismountable plate conveyor chain (seed 000 §1.1–1.3).
//
// A plate with a figured aperture carries a convex working arc of radius R1 that rolls on a
// working face of the roller (pin): concave with radius R2 > R1, or flat. The roller's section
// is a circle of diameter d cut by two working faces, symmetric about its centre.
//
// Frame (the plate's): origin at the roller centre O2 at φ = 0 (chain straight), x along the
// plate axis towards the plate's working arc (away from the plate's other hinge), y completing a
// right-handed frame so that the contact point moves to +y as the links turn. The arc's centre
// is O1 = (a + R1, 0) (concave faces; the flat case adds the contact offset e to y).
#pragma once

#include <vector>

#include "catena/core/error.hpp"

namespace catena::hinge {

enum class Face {
  kConcave,  ///< working faces are arcs of radius R2 (given, or from eq. 6)
  kFlat,     ///< working faces are planes (§1.3.1, figs. 8–10)
};

/// The hinge geometry (constant model). Lengths in m.
struct Hinge {
  Face face = Face::kConcave;
  double pin_diameter = 0.0;    ///< [m] d, diameter of the roller's cylindrical part
  double half_thickness = 0.0;  ///< [m] a: centre to working face (flat: b of fig. 8)
  double plate_radius = 0.0;    ///< [m] R1, the plate's convex working arc
  int teeth = 0;                ///< [-] z, sprocket teeth
  int strokes = 1;              ///< [-] m, sprocket strokes (eq. 12)
  double roller_radius = 0.0;   ///< [m] R2 of concave faces; 0 = from eq. (6)
  // Flat faces only (fig. 8b/10): the face spans ±face_half_length about the foot of the
  // perpendicular from the roller centre; at φ = 0 the load is taken at e = loaded_length −
  // face_half_length along the face (the thesis' c − a).
  double face_half_length = 0.0;  ///< [m] a of fig. 8 (half the face length L)
  double loaded_length = 0.0;     ///< [m] c of fig. 8
};

/// Every problem at once: positive finite lengths, 2a < d, z ≥ 3, 1 ≤ m < z/2 … Feasibility of
/// the design (R1 < R1max) is a diagnostic of the synthesis, not an input error.
std::vector<Issue> validate(const Hinge& hinge);

/// [rad] γmax = 180°·m/z, the largest turn of the roller relative to one plate, eqs. (3), (12).
double gamma_max(const Hinge& hinge);

/// [m] contact offset e along a flat face at φ = 0 (loaded_length − face_half_length).
double flat_contact_offset(const Hinge& hinge);

}  // namespace catena::hinge
