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
  double turn[2], tension_sum = 0.0;
  double px[2], py[2];  // perp(d_θ)/|d_θ|² per link
  // per link, the derivatives by its end-of-step chord d₁: of its turn (tx, ty), of its share of
  // the pin load (ex, ey) and of perp(d_θ)/|d_θ|² (dp, row-major 2×2)
  double tx[2], ty[2], ex[2], ey[2], dp[2][4];
  for (int j = 0; j < 2; ++j) {
    const double d0x = x0[j + 1] - x0[j], d0y = y0[j + 1] - y0[j];
    const double d1x = x1[j + 1] - x1[j], d1y = y1[j + 1] - y1[j];
    const double mx = (1.0 - theta) * d0x + theta * d1x, my = (1.0 - theta) * d0y + theta * d1y;
    const double m2 = mx * mx + my * my, im2 = 1.0 / m2;
    turn[j] = (d0x * d1y - d0y * d1x) * im2;  // d_θ × (d₁ − d₀) = d₀ × d₁
    px[j] = -my * im2;
    py[j] = mx * im2;
    // the elastic tension at the θ point, with the integrator's interpolated length
    const double l1 = length1[j];
    const double lt = (1.0 - theta) * length0[j] + theta * l1;
    tension_sum += axial_stiffness * (lt - rest[j]);
    // ∂turn/∂d₁ = perp(d₀)/|d_θ|² − turn 2θ d_θ/|d_θ|²
    tx[j] = (-d0y - 2.0 * theta * turn[j] * mx) * im2;
    ty[j] = (d0x - 2.0 * theta * turn[j] * my) * im2;
    // ∂(½ k l_θ)/∂d₁ = ½ k θ d₁/l₁
    const double e = l1 > 0.0 ? 0.5 * axial_stiffness * theta / l1 : 0.0;
    ex[j] = e * d1x;
    ey[j] = e * d1y;
    // ∂(perp(m)/|m|²)/∂d₁ = θ (R/|m|² − 2 perp(m) mᵀ/|m|⁴), R = [[0, −1], [1, 0]]
    const double s2 = theta * im2, s4 = 2.0 * s2 * im2;
    dp[j][0] = s4 * my * mx;
    dp[j][1] = -s2 + s4 * my * my;
    dp[j][2] = s2 - s4 * mx * mx;
    dp[j][3] = -s4 * mx * my;
  }
  hc.load = std::max(0.0, 0.5 * tension_sum);
  hc.turn = turn[1] - turn[0];
  hc.rate = hc.turn / step;
  // g = ∂β/∂x: (+P₀, −P₀ − P₁, +P₁), P = perp(d_θ)/|d_θ|²
  hc.gx[0] = px[0];
  hc.gy[0] = py[0];
  hc.gx[1] = -px[0] - px[1];
  hc.gy[1] = -py[0] - py[1];
  hc.gx[2] = px[1];
  hc.gy[2] = py[1];
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
  const double nturn_x[3] = {tx[0], -tx[0] - tx[1], tx[1]};
  const double nturn_y[3] = {ty[0], -ty[0] - ty[1], ty[1]};
  const double nload_x[3] = {-ex[0], ex[0] - ex[1], ex[1]};
  const double nload_y[3] = {-ey[0], ey[0] - ey[1], ey[1]};
  double dmx[3], dmy[3];  // ∂M/∂x₁ per node
  for (int q = 0; q < 3; ++q) {
    dmx[q] = load_factor * nload_x[q] + rate_factor * nturn_x[q];
    dmy[q] = load_factor * nload_y[q] + rate_factor * nturn_y[q];
  }
  // ∂g_k/∂x_q: g = (P₀, −P₀ − P₁, P₁), ∂P_j/∂x of its link's end node = DP_j, of its start −DP_j
  const double sgn0[3][3] = {{-1, 1, 0}, {1, -1, 0}, {0, 0, 0}};  // ∂g_k/∂x_q's share of DP₀
  const double sgn1[3][3] = {{0, 0, 0}, {0, 1, -1}, {0, -1, 1}};  // and of DP₁
  for (int k = 0; k < 3; ++k) {
    for (int q = 0; q < 3; ++q) {
      for (int r = 0; r < 2; ++r) {
        const double gk = r == 0 ? hc.gx[k] : hc.gy[k];
        for (int c = 0; c < 2; ++c) {
          const double dg = sgn0[k][q] * dp[0][2 * r + c] + sgn1[k][q] * dp[1][2 * r + c];
          hc.jacobian[2 * k + r][2 * q + c] = gk * (c == 0 ? dmx[q] : dmy[q]) + hc.torque * dg;
        }
      }
    }
  }
}

}  // namespace catena::dynamics
