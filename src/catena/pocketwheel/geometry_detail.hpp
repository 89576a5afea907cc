// Library-internal: the wheel's derived geometry without validating the wheel again, for entry
// points that have validated it already (plan_run_on validates once and derives once).
#pragma once

#include "catena/pocketwheel/geometry.hpp"

namespace catena::pocketwheel::detail {

/// wheel_geometry() for a wheel that validate() has accepted; the same arithmetic.
WheelGeometry geometry_of_valid(const PocketWheel& wheel);

}  // namespace catena::pocketwheel::detail
