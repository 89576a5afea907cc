// Central differences of the step's Newton residual (Integrator::newton_system): the tests that
// check its Newton matrix column by column against them.
#pragma once

#include <cstddef>
#include <vector>

#include "catena/dynamics/integrator.hpp"

namespace catena::dynamics::testing {

// Column `c` of the residual's derivative at the unknowns `u` by central differences of step
// `eps`: (R(u + eps e_c) − R(u − eps e_c)) / (2 eps), every row.
inline std::vector<double> residual_difference(Integrator& integ, const Model& model,
                                               const State& state, const std::vector<double>& u,
                                               std::size_t c, double eps) {
  std::vector<double> up = u, um = u, rp, rm;
  up[c] += eps;
  um[c] -= eps;
  integ.newton_system(model, state, up, rp, nullptr);
  integ.newton_system(model, state, um, rm, nullptr);
  std::vector<double> fd(rp.size());
  for (std::size_t r = 0; r < fd.size(); ++r) fd[r] = (rp[r] - rm[r]) / (2 * eps);
  return fd;
}

}  // namespace catena::dynamics::testing
