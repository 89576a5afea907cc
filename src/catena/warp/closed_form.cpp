// Roller warp (seed 000 §1.4): the closed form for a rigid roller on linear joints, the tests'
// reference for the solvers.
#include <array>
#include <cstddef>

#include "catena/warp/warp.hpp"

namespace catena::warp {

std::array<double, 4> rigid_linear(const Warp& w, const Load& load) {
  double k = 0, kz = 0, kzz = 0;
  for (const Support& s : w.supports) {
    k += s.stiffness;
    kz += s.stiffness * s.height;
    kzz += s.stiffness * s.height * s.height;
  }
  // a Σk + b Σkz = F;  a Σkz + b Σkz² = F L1
  const double det = k * kzz - kz * kz;
  const double a = (load.force * kzz - kz * load.force * load.height) / det;
  const double b = (k * load.force * load.height - kz * load.force) / det;
  std::array<double, 4> r{};
  for (std::size_t i = 0; i < 4; ++i)
    r[i] = w.supports[i].stiffness * (a + b * w.supports[i].height);
  return r;
}

}  // namespace catena::warp
