// Hinges shared by the hinge tests.
#pragma once

#include "catena/hinge/hinge.hpp"

namespace catena::hinge::testing {

/// d = 40 mm, a = 8 mm, R1 = 20 mm, z = 8, m = 1, concave faces with R2 from eq. (6).
inline Hinge example_hinge() {
  Hinge h;
  h.pin_diameter = 0.040;
  h.half_thickness = 0.008;
  h.plate_radius = 0.020;
  h.teeth = 8;
  return h;
}

}  // namespace catena::hinge::testing
