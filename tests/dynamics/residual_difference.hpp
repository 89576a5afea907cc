// Central differences of the step's Newton residual (Integrator::newton_system): the tests that
// check its Newton matrix column by column against them.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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

// What `expect_columns_match_differences` found: the worst |J − FD| over a column's largest
// difference, the largest |J − other| (another law's matrix at the same iterate) and the largest
// difference of any column.
struct ColumnsAgainstDifferences {
  double worst = 0.0, differs = 0.0, scale = 0.0;
};

// Every column of the Newton matrix `jac` (size × size, row-major) at the unknowns `u` against
// central differences of the residual (column c's step eps(c)), each entry within `tolerance` of
// its column's largest difference; `other` (the same size, or empty) is the matrix of another law
// at the same iterate, whose largest departure from `jac` is reported.
template <class Eps>
ColumnsAgainstDifferences expect_columns_match_differences(
    Integrator& integ, const Model& model, const State& state, const std::vector<double>& u,
    const std::vector<double>& jac, const std::vector<double>& other, Eps eps, double tolerance) {
  ColumnsAgainstDifferences out;
  const std::size_t size = u.size();
  for (std::size_t c = 0; c < size; ++c) {
    const std::vector<double> fd = residual_difference(integ, model, state, u, c, eps(c));
    double scale = 0.0;
    for (std::size_t r = 0; r < size; ++r) scale = std::max(scale, std::abs(fd[r]));
    out.scale = std::max(out.scale, scale);
    for (std::size_t r = 0; r < size; ++r) {
      out.worst = std::max(out.worst, std::abs(jac[r * size + c] - fd[r]) / scale);
      EXPECT_NEAR(jac[r * size + c], fd[r], tolerance * scale) << "row " << r << " column " << c;
      if (!other.empty())
        out.differs = std::max(out.differs, std::abs(jac[r * size + c] - other[r * size + c]));
    }
  }
  return out;
}

}  // namespace catena::dynamics::testing
