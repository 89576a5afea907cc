// The lead-in tests' case (tests/cli/dynamics_*_cli_test.cpp): a 12B two-wheel loop of 32 links
// under gravity, two z = 12 wheels (the driver at 13 rad/s, a driven wheel of inertia 0.01), run
// for 2 ms (20 steps of 0.1 ms), and the straight rails its guides are written as. Some tests
// assert the line numbers of the messages on these files: the text must stay as it is.
#pragma once

#include <cmath>
#include <string>

// The case's [dynamics] table and its two [[dynamics.sprocket]] tables (18 lines): the guides
// follow it.
inline const std::string kLeadInLoopHead = R"([dynamics]
chain = "12B"
links = 32
axial_stiffness = "5e7 N/m"
contact_stiffness = "2e8 N/m"
contact_damping = 800
duration = "0.002 s"
step = "0.1 ms"
gravity = true
[[dynamics.sprocket]]
teeth = 12
role = "driver"
speed = "13 rad/s"
[[dynamics.sprocket]]
teeth = 12
role = "driven"
inertia = 0.01
)";

// A straight [[dynamics.guide]] from (30 mm, y) to (150 mm, y), then `keys` (whole lines).
inline std::string lead_in_rail(const std::string& y, const std::string& keys) {
  return "[[dynamics.guide]]\nkind = \"straight\"\nx0 = \"30 mm\"\ny0 = \"" + y +
         "\"\nx1 = \"150 mm\"\ny1 = \"" + y + "\"\n" + keys;
}

// The number written after `before` in a refusal (the radius "0 < R <= " or the sweep
// "lead_in_angle <= " a lead-in's refusal names); NaN when `before` is not in it.
inline double named_after(const std::string& err, const std::string& before) {
  const auto at = err.find(before);
  return at == std::string::npos ? NAN : std::stod(err.substr(at + before.size()));
}
