#include <catena/pocketwheel/run_on.hpp>
#include <cmath>
#include <cstdio>

int main() {
  const catena::pocketwheel::PocketWheel wheel{0.064, 0.018, 8};
  const auto g = catena::pocketwheel::wheel_geometry(wheel);
  std::printf("consumer: pitch radius R = %.6f m\n", g.pitch_radius);
  return std::abs(g.pitch_radius - 0.164283) < 1e-6 ? 0 : 1;
}
