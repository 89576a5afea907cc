#include <catena/catena.hpp>
#include <catena/io/record.hpp>
#include <catena/pocketwheel/run_on.hpp>
#include <cmath>
#include <cstdio>

int main() {
  const catena::pocketwheel::PocketWheel wheel{0.064, 0.018, 8};
  const auto g = catena::pocketwheel::wheel_geometry(wheel);
  std::printf("consumer: pitch radius R = %.6f m\n", g.pitch_radius);
  // the same through the analysis interface, by name, with units as a user types them
  const catena::analysis::Record r = catena::run(
      "pocketwheel", {{"pitch", "64 mm"}, {"wire", "18"}, {"teeth", "8"}, {"omega", "5 1/s"}});
  const double by_name = r.data.at("pitch_radius").as_number();
  const bool json = catena::io::to_json(r.data).find("\"pitch_radius\"") != std::string::npos;
  std::printf("consumer: %zu analyses; by name R = %.6f m\n", catena::analyses().size(), by_name);
  return std::abs(g.pitch_radius - 0.164283) < 1e-6 && by_name == g.pitch_radius && json ? 0 : 1;
}
