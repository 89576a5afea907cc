// The README's library example (kept identical to it; built with the project).
#include <catena/pocketwheel/run_on.hpp>
#include <cstdio>

int main() {
  using namespace catena::pocketwheel;
  const PocketWheel wheel{.pitch = 0.064, .wire = 0.018, .teeth = 8};  // SI: m
  const Guide guide{.kind = GuideKind::kTangential, .end_distance = 0.256};
  const RunOnResult r = run_on(wheel, guide, Sampling{.omega = 5.0, .points = 721});
  std::printf("R = %.4f m, period %.4f s\n", r.plan.geometry.pitch_radius, r.period);
  std::printf("a_x from %.3f to %.3f m/s^2\n", r.extremes.ax_min, r.extremes.ax_max);
  for (double phi : r.plan.seating_angles) std::printf("joint seats at %.4f rad\n", phi);
}
