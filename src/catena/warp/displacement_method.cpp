// Roller warp (seed 000 §1.4), displacement method: Hermite beam elements between the joints and
// the load point, energy-descent Newton on the convex total potential. One element per segment
// is solve()'s primary solver; solve_fe() refines the mesh as an independent check.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include "catena/warp/warp.hpp"
#include "internal.hpp"

namespace catena::warp {
namespace detail {

// Displacement method: minimises the convex total potential energy
// Π(u) = ½ uᵀK u − F w(L1) + Σ k_i/(n+1) · max(0, w_i − c_i)^(n+1)
// by Newton with Armijo backtracking on Π (globally convergent for a convex Π).
FeSolution fe_solve(const Warp& w, const Load& load, int elements, double tolerance,
                    int max_iterations) {
  // Nodes: the joints, the load point and `elements` subdivisions of every segment between them.
  std::vector<double> key = {w.supports[0].height, w.supports[1].height, w.supports[2].height,
                             w.supports[3].height, load.height};
  std::sort(key.begin(), key.end());
  key.erase(std::unique(key.begin(), key.end()), key.end());
  std::vector<double> z;
  for (std::size_t s = 0; s + 1 < key.size(); ++s)
    for (int e = 0; e < elements; ++e) z.push_back(key[s] + (key[s + 1] - key[s]) * e / elements);
  z.push_back(key.back());
  const int nodes = static_cast<int>(z.size());
  const int dof = 2 * nodes;
  auto node_of = [&](double h) {
    int best = 0;
    for (int i = 0; i < nodes; ++i)
      if (std::abs(z[static_cast<std::size_t>(i)] - h) <
          std::abs(z[static_cast<std::size_t>(best)] - h))
        best = i;
    return best;
  };
  const double ei = w.modulus * second_moment(w.roller_diameter);
  // Hermite cubic beam element (Przemieniecki, Theory of Matrix Structural Analysis, §5.3).
  std::vector<double> kb(static_cast<std::size_t>(dof * dof), 0.0);
  for (int e = 0; e + 1 < nodes; ++e) {
    const double h = z[static_cast<std::size_t>(e + 1)] - z[static_cast<std::size_t>(e)];
    const double c = ei / (h * h * h);
    const double ke[4][4] = {{12 * c, 6 * h * c, -12 * c, 6 * h * c},
                             {6 * h * c, 4 * h * h * c, -6 * h * c, 2 * h * h * c},
                             {-12 * c, -6 * h * c, 12 * c, -6 * h * c},
                             {6 * h * c, 2 * h * h * c, -6 * h * c, 4 * h * h * c}};
    for (int r = 0; r < 4; ++r)
      for (int q = 0; q < 4; ++q)
        kb[static_cast<std::size_t>((2 * e + r) * dof + 2 * e + q)] += ke[r][q];
  }
  std::array<int, 4> sn{};
  for (std::size_t i = 0; i < 4; ++i) sn[i] = node_of(w.supports[i].height);
  const int ln = node_of(load.height);
  const double f = load.force, n = w.exponent;
  std::vector<double> u(static_cast<std::size_t>(dof), 0.0);
  double cmax = 0;
  for (const Support& sp : w.supports) cmax = std::max(cmax, sp.clearance);
  for (int i = 0; i < nodes; ++i) u[static_cast<std::size_t>(2 * i)] = cmax;
  auto resid = [&](const std::vector<double>& v) {
    std::vector<double> r(static_cast<std::size_t>(dof), 0.0);
    for (int i = 0; i < dof; ++i)
      for (int j = 0; j < dof; ++j)
        r[static_cast<std::size_t>(i)] +=
            kb[static_cast<std::size_t>(i * dof + j)] * v[static_cast<std::size_t>(j)];
    r[static_cast<std::size_t>(2 * ln)] -= f;
    for (std::size_t i = 0; i < 4; ++i) {
      const Support& sp = w.supports[i];
      r[static_cast<std::size_t>(2 * sn[i])] +=
          law(sp.stiffness, n, v[static_cast<std::size_t>(2 * sn[i])] - sp.clearance);
    }
    return r;
  };
  auto energy = [&](const std::vector<double>& v) {
    double e = 0;
    for (int i = 0; i < dof; ++i)
      for (int j = 0; j < dof; ++j)
        e += 0.5 * v[static_cast<std::size_t>(i)] * kb[static_cast<std::size_t>(i * dof + j)] *
             v[static_cast<std::size_t>(j)];
    e -= f * v[static_cast<std::size_t>(2 * ln)];
    for (std::size_t i = 0; i < 4; ++i) {
      const Support& sp = w.supports[i];
      const double gap = v[static_cast<std::size_t>(2 * sn[i])] - sp.clearance;
      e += gap > 0 ? law(sp.stiffness, n, gap) * gap / (n + 1) : 0.0;
    }
    return e;
  };
  auto rnorm = [&](const std::vector<double>& r) {
    double m = 0;
    for (double v : r) m = std::max(m, std::abs(v));
    return m;
  };
  std::vector<double> r = resid(u);
  double rn = rnorm(r);
  // Round-off floor of the nodal residual: a stiff roller makes K·u large terms that cancel.
  constexpr double kRoundoff = 1e-13;  // [-]
  auto floor_of = [&](const std::vector<double>& v) {
    double m = 0;
    for (int i = 0; i < dof; ++i) {
      double row = 0;
      for (int j = 0; j < dof; ++j)
        row += std::abs(kb[static_cast<std::size_t>(i * dof + j)] * v[static_cast<std::size_t>(j)]);
      m = std::max(m, row);
    }
    return kRoundoff * m;
  };
  double en = energy(u);
  FeSolution sol;
  for (int it = 0; it < max_iterations && rn > tolerance * f + floor_of(u);
       ++it, ++sol.iterations) {
    std::vector<double> jac = kb;
    for (std::size_t i = 0; i < 4; ++i) {
      const Support& sp = w.supports[i];
      const double g = u[static_cast<std::size_t>(2 * sn[i])] - sp.clearance;
      jac[static_cast<std::size_t>(2 * sn[i] * dof + 2 * sn[i])] +=
          std::max(law_slope(sp.stiffness, n, g), kJacobianFloor * secant(sp.stiffness, n, f));
    }
    std::vector<double> du(static_cast<std::size_t>(dof));
    for (int i = 0; i < dof; ++i) du[static_cast<std::size_t>(i)] = -r[static_cast<std::size_t>(i)];
    if (!solve_dense(jac, du, dof)) break;
    double step = 1.0;
    std::vector<double> trial(u.size());
    double slope = 0;  // dΠ/dstep at 0 = r·du < 0 (the modified Hessian is positive definite)
    for (std::size_t i = 0; i < u.size(); ++i) slope += r[i] * du[i];
    double te = en;
    for (int k = 0; k < 60; ++k, step *= 0.5) {
      for (std::size_t i = 0; i < u.size(); ++i) trial[i] = u[i] + step * du[i];
      te = energy(trial);
      if (te <= en + 1e-4 * step * slope) break;
    }
    u = trial;
    en = te;
    r = resid(u);
    rn = rnorm(r);
  }
  sol.z = z;
  sol.u = u;
  sol.joint_node = sn;
  sol.residual = rn;
  sol.tolerance = tolerance * f + floor_of(u);
  sol.converged = rn <= sol.tolerance;
  return sol;
}

}  // namespace detail

using detail::fe_solve;
using detail::FeSolution;
using detail::law;

std::array<double, 4> solve_fe(const Warp& w, const Load& load, int elements) {
  throw_if_any(validate(w, load));
  const FeSolution sol = fe_solve(w, load, elements, 1e-11, 500);
  std::array<double, 4> out{};
  for (std::size_t i = 0; i < 4; ++i)
    out[i] = law(w.supports[i].stiffness, w.exponent,
                 sol.u[static_cast<std::size_t>(2 * sol.joint_node[i])] - w.supports[i].clearance);
  return out;
}

}  // namespace catena::warp
