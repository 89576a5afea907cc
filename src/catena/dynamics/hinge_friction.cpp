// The hinges' friction couple (include/catena/dynamics/hinge_friction.hpp; docs/models/dynamics.md,
// "Hinges").
#include "catena/dynamics/hinge_friction.hpp"

#include <algorithm>
#include <cmath>

namespace catena::dynamics {

std::vector<Issue> validate(const HingeFriction& hinge, double pitch) {
  std::vector<Issue> out;
  // the arm is a fraction of a pin radius or a rolling lever: far below the pitch
  if (!std::isfinite(hinge.arm) || hinge.arm < 0.0 ||
      (std::isfinite(pitch) && pitch > 0.0 && hinge.arm >= 0.5 * pitch)) {
    out.push_back({"hinge.arm", check::format_si(hinge.arm, "m"),
                   "a finite value in [0, p/2) m (mu r or c_r R*)"});
  }
  if (!std::isfinite(hinge.rate_band) || !(hinge.rate_band > 0.0) || hinge.rate_band > 100.0) {
    out.push_back({"hinge.rate_band", check::format_si(hinge.rate_band, "rad/s"),
                   "a value in (0, 100] rad/s"});
  }
  return out;
}

double rolling_hinge_arm(double rolling_coefficient, double plate_radius, double face_radius) {
  const double reduced = std::isinf(face_radius)
                             ? plate_radius
                             : plate_radius * face_radius / (face_radius - plate_radius);
  return rolling_coefficient * reduced;
}

HingeCouple hinge_couple(const HingeFriction& hinge, double axial_stiffness, const double rest[2],
                         const double x0[3], const double y0[3], const double x1[3],
                         const double y1[3], double theta, double step) {
  double length0[2], length1[2];
  for (int j = 0; j < 2; ++j) {
    const double d0x = x0[j + 1] - x0[j], d0y = y0[j + 1] - y0[j];
    const double d1x = x1[j + 1] - x1[j], d1y = y1[j + 1] - y1[j];
    length0[j] = std::sqrt(d0x * d0x + d0y * d0y);
    length1[j] = std::sqrt(d1x * d1x + d1y * d1y);
  }
  return hinge_couple(hinge, axial_stiffness, rest, x0, y0, x1, y1, theta, step, length0, length1);
}

HingeCouple hinge_couple(const HingeFriction& hinge, double axial_stiffness, const double rest[2],
                         const double x0[3], const double y0[3], const double x1[3],
                         const double y1[3], double theta, double step, const double length0[2],
                         const double length1[2], bool jacobian) {
  HingeCouple hc;
  hinge_couple(hinge, axial_stiffness, rest, x0, y0, x1, y1, theta, step, length0, length1, hc,
               jacobian);
  return hc;
}

void hinge_couple(const HingeFriction& hinge, double axial_stiffness, const double rest[2],
                  const double x0[3], const double y0[3], const double x1[3], const double y1[3],
                  double theta, double step, const double length0[2], const double length1[2],
                  HingeCouple& hc, bool jacobian) {
  HingeLink link[2];
  for (int j = 0; j < 2; ++j) {
    hinge_link(x0[j + 1] - x0[j], y0[j + 1] - y0[j], x1[j + 1] - x1[j], y1[j + 1] - y1[j],
               length0[j], length1[j], rest[j], axial_stiffness, theta, link[j], jacobian);
  }
  hinge_couple(hinge, link[0], link[1], step, hc, jacobian);
}

void hinge_couple(const HingeFriction& hinge, const HingeLink& l0, const HingeLink& l1, double step,
                  HingeCouple& hc, bool jacobian) {
  const double tension_sum = l0.tension + l1.tension;
  hc.load = std::max(0.0, 0.5 * tension_sum);
  hc.turn = l1.turn - l0.turn;
  hc.rate = hc.turn / step;
  // g = ∂β/∂x: (+P₀, −P₀ − P₁, +P₁), P = perp(d_θ)/|d_θ|²
  hc.gx[0] = l0.px;
  hc.gy[0] = l0.py;
  hc.gx[1] = -l0.px - l1.px;
  hc.gy[1] = -l0.py - l1.py;
  hc.gx[2] = l1.px;
  hc.gy[2] = l1.py;
  const double band = hinge.rate_band;
  const double root = std::sqrt(hc.rate * hc.rate + band * band);
  const double limit = hinge.arm * hc.load;  // e F
  hc.torque = -limit * hc.rate / root;
  hc.work = hc.torque * hc.turn;
  for (int k = 0; k < 3; ++k) {
    hc.fx[k] = hc.torque * hc.gx[k];
    hc.fy[k] = hc.torque * hc.gy[k];
  }
  hc.rate_stiffness = limit * band * band / (root * root * root);
  if (!jacobian) return;
  // The exact ∂f/∂x₁. Node gradients of a per-link quantity q(d₁) of links 0 (a → b) and 1
  // (b → c): the turn Δβ = turn₁ − turn₀ gives (T₀, −T₀ − T₁, T₁) (as g); the load F = Σ ½ k
  // (l_θ − rest) gives (−E₀, E₀ − E₁, E₁) (zero where the load is clamped at 0).
  const double loaded = 0.5 * tension_sum > 0.0 ? 1.0 : 0.0;
  const double load_factor = -hinge.arm * (hc.rate / root) * loaded;  // ∂M/∂F = −e s(ω)
  const double rate_factor = -hc.rate_stiffness / step;               // ∂M/∂Δβ = −e F s'/h
  const double nturn_x[3] = {l0.tx, -l0.tx - l1.tx, l1.tx};
  const double nturn_y[3] = {l0.ty, -l0.ty - l1.ty, l1.ty};
  const double nload_x[3] = {-l0.ex, l0.ex - l1.ex, l1.ex};
  const double nload_y[3] = {-l0.ey, l0.ey - l1.ey, l1.ey};
  double dmx[3], dmy[3];  // ∂M/∂x₁ per node
  for (int q = 0; q < 3; ++q) {
    dmx[q] = load_factor * nload_x[q] + rate_factor * nturn_x[q];
    dmy[q] = load_factor * nload_y[q] + rate_factor * nturn_y[q];
  }
  // The load and rate terms: g_k ⊗ ∂M/∂x_q on every block.
  for (int k = 0; k < 3; ++k) {
    for (int q = 0; q < 3; ++q) {
      hc.jacobian[2 * k][2 * q] = hc.gx[k] * dmx[q];
      hc.jacobian[2 * k][2 * q + 1] = hc.gx[k] * dmy[q];
      hc.jacobian[2 * k + 1][2 * q] = hc.gy[k] * dmx[q];
      hc.jacobian[2 * k + 1][2 * q + 1] = hc.gy[k] * dmy[q];
    }
  }
  // The direction term M ∂g_k/∂x_q: g = (P₀, −P₀ − P₁, P₁), ∂P_j/∂x of its link's end node is
  // DP_j, of its start node −DP_j, so (blocks k, q) −DP₀ +DP₀ 0 / +DP₀ −DP₀+DP₁ −DP₁ / 0 −DP₁ +DP₁
  // (the blocks (0, 2) and (2, 0) have no direction term).
  const double m = hc.torque;
  for (int e = 0; e < 4; ++e) {
    const int r = e / 2, c = e % 2;
    const double p0 = m * l0.dp[e], p1 = m * l1.dp[e], p01 = m * (-l0.dp[e] + l1.dp[e]);
    hc.jacobian[r][c] -= p0;
    hc.jacobian[r][2 + c] += p0;
    hc.jacobian[2 + r][c] += p0;
    hc.jacobian[2 + r][2 + c] += p01;
    hc.jacobian[2 + r][4 + c] -= p1;
    hc.jacobian[4 + r][2 + c] -= p1;
    hc.jacobian[4 + r][4 + c] += p1;
  }
}

}  // namespace catena::dynamics
