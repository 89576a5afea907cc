// Roller warp (seed 000 §1.4): what the sources of src/catena/warp/ share; private, not installed.
// The thesis prints no formula for this section; every relation in these sources is our
// reconstruction (docs/models/warp.md), cited to the textbook it comes from.
#pragma once

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "catena/warp/warp.hpp"

namespace catena::warp::detail {

inline constexpr const char* kJointName[4] = {"F21", "F11", "F12", "F22"};
// [-] of the secant joint stiffness, for open joints
inline constexpr double kJacobianFloor = 1e-9;

inline double second_moment(double d) { return std::numbers::pi * d * d * d * d / 64.0; }

inline double cube_plus(double x) { return x > 0 ? x * x * x : 0.0; }

// Joint law R = k·g^n for g > 0, else 0 (Levina & Reshetov power law, n = 1/m).
inline double law(double k, double n, double g) { return g > 0 ? k * std::pow(g, n) : 0.0; }
inline double law_slope(double k, double n, double g) {
  return g > 0 ? k * n * std::pow(g, n - 1.0) : 0.0;
}
// Secant stiffness of a joint carrying the whole load: scale for the Jacobian floor.
inline double secant(double k, double n, double force) {
  return k * n * std::pow(force / k, (n - 1.0) / n);
}

// Dense Gaussian elimination with partial pivoting; false if singular (dense_solve.cpp).
bool solve_dense(std::vector<double>& a, std::vector<double>& x, int n);

// Unknowns of the force method: w = a + b z + bending, and the joint forces.
struct State {
  double a = 0, b = 0;
  std::array<double, 4> r{};
};

// w(z) of the free–free roller by Macaulay's method (force_method.cpp).
double deflection(const Warp& w, const Load& load, const State& s, double z);

// Joint forces, deflections, moments, stresses and diagnostics of a solved state (result.cpp).
WarpResult build_result(const Warp& w, const Load& load, const State& s,
                        const SolverSummary& summary, const SolveOptions& options);

// Force method from `initial` (or from every joint closed and sharing F equally when null), with
// load continuation as the fallback (force_method.cpp).
WarpResult flexibility_impl(const Warp& w, const Load& load, const SolveOptions& options,
                            const State* initial);

struct FeSolution {
  std::vector<double> z, u;  // node heights, (w, θ) per node
  std::array<int, 4> joint_node{};
  int iterations = 0;
  double residual = 0;   // [N] max |nodal force residual|
  double tolerance = 0;  // [N] tolerance·F + the round-off floor the residual was tested against
  bool converged = false;
};

// Displacement method: `elements` Hermite beam elements between consecutive feature points
// (displacement_method.cpp).
FeSolution fe_solve(const Warp& w, const Load& load, int elements, double tolerance,
                    int max_iterations);

}  // namespace catena::warp::detail
