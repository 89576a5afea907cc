// Orthotropic ring contact problem (seed 002 eqs. (1)–(8)); see docs/models/composite.md.
#include "catena/composite/ring.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <numbers>
#include <utility>

#include "catena/core/progress.hpp"

namespace catena::composite {
namespace {

using cplx = std::complex<double>;
constexpr double kPi = std::numbers::pi;
constexpr double kRepeatTol = 1e-6;       // [-] relative exponent separation below which λ repeat
constexpr double kCornerFraction = 0.05;  // [-] singular zone r < r1 + 0.05(r2 − r1)

/// Plane-stress stiffnesses divided by E_φ (seed 002 constants D of eq. (1), derived):
/// σ_r = c11 ε_r + c12 ε_φ, σ_φ = c12 ε_r + c22 ε_φ, τ = g γ.
struct Stiffness {
  double c11, c12, c22, g;
};

Stiffness stiffness(const Ring& ring) {
  const double er = ring.E_r / ring.E_phi;
  const double nu_rphi = ring.nu_phi_r * er;  // Maxwell–Betti: ν_rφ/E_r = ν_φr/E_φ
  const double det = 1.0 - ring.nu_phi_r * nu_rphi;
  return {er / det, ring.nu_phi_r * er / det, 1.0 / det, ring.G / ring.E_phi};
}

/// Small dense complex solve (partial pivoting), in place; returns x.
template <std::size_t N>
std::array<cplx, N> solve_dense(std::array<std::array<cplx, N>, N> a, std::array<cplx, N> b) {
  for (std::size_t k = 0; k < N; ++k) {
    std::size_t p = k;
    for (std::size_t i = k + 1; i < N; ++i)
      if (std::abs(a[i][k]) > std::abs(a[p][k])) p = i;
    std::swap(a[k], a[p]);
    std::swap(b[k], b[p]);
    for (std::size_t i = k + 1; i < N; ++i) {
      const cplx f = a[i][k] / a[k][k];
      for (std::size_t j = k; j < N; ++j) a[i][j] -= f * a[k][j];
      b[i] -= f * b[k];
    }
  }
  std::array<cplx, N> x{};
  for (std::size_t k = N; k-- > 0;) {
    cplx s = b[k];
    for (std::size_t j = k + 1; j < N; ++j) s -= a[k][j] * x[j];
    x[k] = s / a[k][k];
  }
  return x;
}

// 2x2 real blocks for the sweep (8)
struct M2 {
  double a, b, c, d;
};
struct V2 {
  double x, y;
};
M2 mul(const M2& p, const M2& q) {
  return {p.a * q.a + p.b * q.c, p.a * q.b + p.b * q.d, p.c * q.a + p.d * q.c,
          p.c * q.b + p.d * q.d};
}
V2 mul(const M2& p, const V2& v) { return {p.a * v.x + p.b * v.y, p.c * v.x + p.d * v.y}; }
M2 add(const M2& p, const M2& q) { return {p.a + q.a, p.b + q.b, p.c + q.c, p.d + q.d}; }
M2 sub(const M2& p, const M2& q) { return {p.a - q.a, p.b - q.b, p.c - q.c, p.d - q.d}; }
V2 sub(const V2& p, const V2& q) { return {p.x - q.x, p.y - q.y}; }
M2 inv(const M2& p) {
  const double det = p.a * p.d - p.b * p.c;
  return {p.d / det, -p.b / det, -p.c / det, p.a / det};
}
M2 neg(const M2& p) { return {-p.a, -p.b, -p.c, -p.d}; }

/// Dense real solve with partial pivoting (row-major n×n `a`); false if singular.
bool solve_real(std::vector<double> a, std::vector<double>& b) {
  const std::size_t n = b.size();
  for (std::size_t k = 0; k < n; ++k) {
    check_cancelled();  // n² work a column: one poll each
    std::size_t p = k;
    for (std::size_t i = k + 1; i < n; ++i)
      if (std::abs(a[i * n + k]) > std::abs(a[p * n + k])) p = i;
    if (!(std::abs(a[p * n + k]) > 0.0)) return false;
    if (p != k) {
      for (std::size_t j = 0; j < n; ++j) std::swap(a[k * n + j], a[p * n + j]);
      std::swap(b[k], b[p]);
    }
    const double piv = a[k * n + k];
    for (std::size_t i = k + 1; i < n; ++i) {
      const double f = a[i * n + k] / piv;
      if (f == 0.0) continue;
      for (std::size_t j = k; j < n; ++j) a[i * n + j] -= f * a[k * n + j];
      b[i] -= f * b[k];
    }
  }
  for (std::size_t k = n; k-- > 0;) {
    double s = b[k];
    for (std::size_t j = k + 1; j < n; ++j) s -= a[k * n + j] * b[j];
    b[k] = s / a[k * n + k];
  }
  return true;
}

/// Unilateral contact (seed 002 extended): each harmonic's solution for the inner displacement
/// Δc_n is rescaled by s_n so that, at collocation angles φ_j = j(π/2)/(K − 1), either the ring
/// follows the half-disc (Σ s_n Δc_n cos nφ_j = Δ cos φ_j, contact) or is free (pressure
/// −Σ s_n σ_r,n(α) cos nφ_j = 0, separated). Active set: contact points with tension leave,
/// separated points that would penetrate (u < Δ cos φ) return. Returns the scales; sets the
/// contact angle and the pass count.
std::vector<double> unilateral_scales(const std::vector<Harmonic>& hs, double delta,
                                      double& contact_angle, int& passes) {
  const std::size_t k = hs.size();
  std::vector<double> phi(k), u0(k), scale(k, 1.0);
  for (std::size_t j = 0; j < k; ++j) {
    phi[j] = 0.5 * kPi * static_cast<double>(j) / static_cast<double>(k - 1);
    u0[j] = delta * std::cos(phi[j]);
  }
  // the two kinds of collocation row, built once: u(φ_j) = Σ D_jn s_n and p(φ_j) = Σ Q_jn s_n
  std::vector<double> disp_row(k * k), pres_row(k * k);
  for (std::size_t j = 0; j < k; ++j)
    for (std::size_t n = 0; n < k; ++n) {
      const double c = std::cos(hs[n].n * phi[j]);
      disp_row[j * k + n] = delta * inner_coefficient(hs[n].n) * c;
      pres_row[j * k + n] = -hs[n].inner_sigma_r * c;
    }
  auto dot = [&](const std::vector<double>& rows, std::size_t j, const std::vector<double>& s) {
    double v = 0;
    for (std::size_t n = 0; n < k; ++n) v += rows[j * k + n] * s[n];
    return v;
  };
  std::vector<char> contact(k, 1);
  std::vector<double> p(k);
  constexpr int kMaxPasses = 100;
  for (passes = 1; passes <= kMaxPasses; ++passes) {
    std::vector<double> a(k * k), b(k);
    for (std::size_t j = 0; j < k; ++j) {
      const std::vector<double>& rows = contact[j] ? disp_row : pres_row;
      std::copy_n(rows.begin() + static_cast<std::ptrdiff_t>(j * k), k,
                  a.begin() + static_cast<std::ptrdiff_t>(j * k));
      b[j] = contact[j] ? u0[j] : 0.0;
    }
    if (!solve_real(a, b)) break;
    scale = b;
    bool changed = false;
    double pscale = 0;
    for (std::size_t j = 0; j < k; ++j) {
      p[j] = dot(pres_row, j, scale);
      pscale = std::max(pscale, std::abs(p[j]));
    }
    for (std::size_t j = 0; j < k; ++j) {
      if (contact[j] && p[j] < -1e-12 * pscale) {
        contact[j] = 0;
        changed = true;
      } else if (!contact[j] && dot(disp_row, j, scale) < u0[j] - 1e-12 * delta) {
        contact[j] = 1;
        changed = true;
      }
    }
    if (!changed) break;
  }
  contact_angle = 0.5 * kPi;
  for (std::size_t j = 0; j < k; ++j)
    if (!contact[j]) {
      contact_angle = j == 0 ? 0.0 : 0.5 * (phi[j - 1] + phi[j]);
      break;
    }
  return scale;
}

double simpson(const std::vector<double>& f, double h) {
  const std::size_t m = f.size() - 1;
  double s = f.front() + f.back();
  for (std::size_t i = 1; i < m; ++i) s += (i % 2 == 1 ? 4.0 : 2.0) * f[i];
  return s * h / 3.0;
}

}  // namespace

std::vector<Issue> validate(const Ring& ring) {
  std::vector<Issue> out;
  check::finite_positive(out, "inner_radius", ring.inner_radius, "m");
  check::finite_positive(out, "outer_radius", ring.outer_radius, "m");
  check::finite_positive(out, "thickness", ring.thickness, "m");
  check::finite_positive(out, "E_r", ring.E_r, "Pa");
  check::finite_positive(out, "E_phi", ring.E_phi, "Pa");
  check::finite_positive(out, "G", ring.G, "Pa");
  check::finite_positive(out, "gap", ring.gap, "m");
  if (std::isfinite(ring.inner_radius) && std::isfinite(ring.outer_radius) &&
      ring.inner_radius > 0 && ring.outer_radius > 0) {
    const double a = ring.inner_radius / ring.outer_radius;
    if (!(a < 0.995) || a < 0.05)
      out.push_back(
          {"inner_radius", check::format_si(ring.inner_radius, "m"),
           "0.05 ≤ r1/r2 ≤ 0.995 (r2 = " + check::format_si(ring.outer_radius, "m") + ")"});
  }
  if (!std::isfinite(ring.nu_phi_r) || ring.nu_phi_r < 0.0) {
    out.push_back({"nu_phi_r", check::format_si(ring.nu_phi_r, ""), "a ratio ≥ 0"});
  } else if (ring.E_r > 0 && ring.E_phi > 0 &&
             !(ring.nu_phi_r * ring.nu_phi_r * ring.E_r / ring.E_phi < 1.0)) {
    out.push_back({"nu_phi_r", check::format_si(ring.nu_phi_r, ""),
                   "ν_φr² E_r/E_φ < 1 (positive-definite stiffness)"});
  }
  if (std::isfinite(ring.gap) && ring.gap > 0 && ring.gap >= 0.1 * ring.inner_radius)
    out.push_back(
        {"gap", check::format_si(ring.gap, "m"), "a small opening 2δ < 0.1 r1 (linear theory)"});
  return out;
}

std::vector<Issue> validate(const Options& o) {
  std::vector<Issue> out;
  if (o.harmonics != 0 && (o.harmonics < 2 || o.harmonics > 200000))
    out.push_back({"harmonics", std::to_string(o.harmonics), "0 (default) or 2..200000"});
  if (o.nodes != 0 && (o.nodes < 20 || o.nodes > 2000000))
    out.push_back({"nodes", std::to_string(o.nodes), "0 (default) or 20..2000000"});
  if (o.points < 21 || o.points > 2001 || o.points % 2 == 0)
    out.push_back({"points", std::to_string(o.points), "an odd number 21..2001"});
  return out;
}

int default_harmonics(const Ring& ring) {
  const double a = ring.inner_radius / ring.outer_radius;
  const int half = static_cast<int>(std::ceil(5.0 / (kCornerFraction * (1.0 - a))));
  return std::max(40, 2 * half);
}

int default_nodes(const Ring& ring, int harmonics, int points) {
  const double a = ring.inner_radius / ring.outer_radius;
  const double want = std::max(200.0, 10.0 * harmonics * (1.0 - a) / a);
  const int step = points - 1;
  const int m = static_cast<int>(std::ceil(want / step)) * step;
  return m % 2 == 0 ? m : m + step;
}

double inner_coefficient(int n) {
  if (n == 0) return 2.0 / kPi;  // seed 002 eq. (5): G0 = 2/π
  const double sign = (n / 2) % 2 == 0 ? 1.0 : -1.0;
  return -(4.0 / kPi) * sign / (static_cast<double>(n) * n - 1.0);
}

Harmonic solve_exact(const Ring& ring, int n, const std::vector<double>& rho) {
  const Stiffness c = stiffness(ring);
  const double alpha = ring.inner_radius / ring.outer_radius;
  const double delta = 0.5 * ring.gap / ring.outer_radius;  // Δ = δ/r2
  const double s0 = std::log(alpha);
  const double dn = n;
  Harmonic h;
  h.n = n;
  const std::size_t k = rho.size();
  h.sigma_r.assign(k, 0.0);
  h.sigma_phi.assign(k, 0.0);
  h.tau.assign(k, 0.0);
  if (n == 0) {
    // axisymmetric: c11(ρ²V'' + ρV') − c22 V = 0, V = ρ^{±κ}, κ = √(c22/c11)
    const double kappa = std::sqrt(c.c22 / c.c11);
    // modes scaled to 1 where they are largest: ρ^κ at ρ = 1, ρ^{−κ} at ρ = α
    const double lam[2] = {kappa, -kappa};
    const double ref[2] = {0.0, s0};
    std::array<std::array<cplx, 2>, 2> a{};
    for (int j = 0; j < 2; ++j) {
      a[0][static_cast<std::size_t>(j)] = std::exp(lam[j] * (s0 - ref[j]));  // V(α)
      a[1][static_cast<std::size_t>(j)] =
          (c.c11 * lam[j] + c.c12) * std::exp(lam[j] * (0.0 - ref[j]));  // ρσ_r(1)
    }
    const auto x = solve_dense<2>(a, {cplx(delta * inner_coefficient(0)), cplx(0.0)});
    auto at = [&](double s, std::size_t i) {
      double sr = 0, sp = 0;
      for (std::size_t j = 0; j < 2; ++j) {
        const double e = x[j].real() * std::exp(lam[j] * (s - ref[j]));
        sr += (c.c11 * lam[j] + c.c12) * e;
        sp += (c.c12 * lam[j] + c.c22) * e;
      }
      return i == 0 ? sr : sp;
    };
    for (std::size_t i = 0; i < k; ++i) {
      const double s = std::log(rho[i]);
      h.sigma_r[i] = at(s, 0) / rho[i] * ring.E_phi;
      h.sigma_phi[i] = at(s, 1) / rho[i] * ring.E_phi;
    }
    h.inner_sigma_r = at(s0, 0) / alpha * ring.E_phi;
    double integral = 0;
    for (std::size_t j = 0; j < 2; ++j)
      integral += x[j].real() * (c.c12 * lam[j] + c.c22) *
                  (std::exp(lam[j] * (0.0 - ref[j])) - std::exp(lam[j] * (s0 - ref[j]))) / lam[j];
    h.section_integral = integral * ring.E_phi;
    return h;
  }
  // n ≥ 2: V = a ρ^λ, W = b ρ^λ in (4); det = 0 is biquadratic, a4 μ² + a2 μ + a0 = 0, μ = λ²
  const double n2 = dn * dn;
  const double a4 = c.c11 * c.g;
  const double a2 =
      -c.c11 * (c.g + n2 * c.c22) - c.g * (c.c22 + n2 * c.g) + n2 * (c.c12 + c.g) * (c.c12 + c.g);
  const double a0 = (c.c22 + n2 * c.g) * (c.g + n2 * c.c22) - n2 * (c.g + c.c22) * (c.g + c.c22);
  const cplx disc = std::sqrt(cplx(a2 * a2 - 4.0 * a4 * a0));
  // stable quadratic roots
  const cplx q = -0.5 * (cplx(a2) + (a2 >= 0 ? disc : -disc));
  const cplx mu1 = q / a4;
  const cplx mu2 = cplx(a0) / q;
  std::array<cplx, 4> lam = {std::sqrt(mu1), -std::sqrt(mu1), std::sqrt(mu2), -std::sqrt(mu2)};
  double scale = 0;
  for (const cplx& l : lam) scale = std::max(scale, std::abs(l));
  double sep = 1e300;
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = i + 1; j < 4; ++j) sep = std::min(sep, std::abs(lam[i] - lam[j]));
  if (!(sep > kRepeatTol * scale) || !std::isfinite(scale)) {
    // (nearly) repeated exponents: the power basis degenerates; use a fine sweep instead
    h.fallback = true;
    return h;  // caller replaces by the sweep
  }
  struct Mode {
    cplx lambda, v, w, sr, tr, sp;
    double ref;
  };
  std::array<Mode, 4> mode{};
  for (std::size_t j = 0; j < 4; ++j) {
    const cplx l = lam[j];
    // null vector of [[p1, q1], [p2, q2]] from the better-conditioned row
    const cplx p1 = c.c11 * l * l - (c.c22 + n2 * c.g);
    const cplx q1 = dn * ((c.c12 + c.g) * l - (c.g + c.c22));
    const cplx p2 = -dn * ((c.g + c.c12) * l + (c.g + c.c22));
    const cplx q2 = c.g * l * l - (c.g + n2 * c.c22);
    cplx v, w;
    if (std::abs(p1) + std::abs(q1) >= std::abs(p2) + std::abs(q2)) {
      v = q1;
      w = -p1;
    } else {
      v = q2;
      w = -p2;
    }
    const cplx sr = c.c11 * l * v + c.c12 * (v + dn * w);  // ρσ_r
    const cplx tr = c.g * (l * w - w - dn * v);            // ρτ
    const cplx sp = c.c12 * l * v + c.c22 * (v + dn * w);  // ρσ_φ
    const double norm = std::max({std::abs(v), std::abs(w), std::abs(sr), std::abs(tr)});
    mode[j] = {l, v / norm, w / norm, sr / norm, tr / norm, sp / norm, l.real() >= 0 ? 0.0 : s0};
  }
  std::array<std::array<cplx, 4>, 4> m{};
  for (std::size_t j = 0; j < 4; ++j) {
    const cplx ein = std::exp(mode[j].lambda * (s0 - mode[j].ref));
    const cplx eout = std::exp(mode[j].lambda * (0.0 - mode[j].ref));
    m[0][j] = mode[j].v * ein;    // V(α) = Δ c_n         (2)
    m[1][j] = mode[j].tr * ein;   // τ(α) = 0             (2)
    m[2][j] = mode[j].sr * eout;  // σ_r(1) = 0           (2)
    m[3][j] = mode[j].tr * eout;  // τ(1) = 0             (2)
  }
  const auto x = solve_dense<4>(m, {cplx(delta * inner_coefficient(n)), 0.0, 0.0, 0.0});
  auto eval = [&](double s, double r, std::size_t i) {
    cplx sr = 0, sp = 0, tr = 0;
    for (std::size_t j = 0; j < 4; ++j) {
      const cplx e = x[j] * std::exp(mode[j].lambda * (s - mode[j].ref));
      sr += mode[j].sr * e;
      sp += mode[j].sp * e;
      tr += mode[j].tr * e;
    }
    h.sigma_r[i] = sr.real() / r * ring.E_phi;
    h.sigma_phi[i] = sp.real() / r * ring.E_phi;
    h.tau[i] = tr.real() / r * ring.E_phi;
  };
  for (std::size_t i = 0; i < k; ++i) eval(std::log(rho[i]), rho[i], i);
  cplx sr_in = 0, integral = 0;
  for (std::size_t j = 0; j < 4; ++j) {
    const cplx ein = std::exp(mode[j].lambda * (s0 - mode[j].ref));
    const cplx eout = std::exp(mode[j].lambda * (0.0 - mode[j].ref));
    sr_in += x[j] * mode[j].sr * ein;
    integral += x[j] * mode[j].sp * (eout - ein) / mode[j].lambda;  // ∫ρσ_φ ds = ∫σ_φ dρ
  }
  h.inner_sigma_r = sr_in.real() / alpha * ring.E_phi;
  h.section_integral = integral.real() * ring.E_phi;
  return h;
}

Harmonic solve_sweep(const Ring& ring, int n, int m, const std::vector<double>& rho) {
  const Stiffness c = stiffness(ring);
  const double alpha = ring.inner_radius / ring.outer_radius;
  const double delta = 0.5 * ring.gap / ring.outer_radius;
  const double h = (1.0 - alpha) / m;
  const double dn = n;
  const auto mm = static_cast<std::size_t>(m);
  std::vector<M2> A(mm + 1), B(mm + 1), C(mm + 1);
  std::vector<V2> F(mm + 1, {0.0, 0.0});
  auto r_at = [&](std::size_t i) { return alpha + static_cast<double>(i) * h; };
  // interior rows: (4) with the central differences (6)
  for (std::size_t i = 1; i < mm; ++i) {
    const double r = r_at(i);
    const double pv = c.c11 * r * r, qv = c.c11 * r;  // eq. 1, V
    const double qw1 = dn * (c.c12 + c.g) * r, zv1 = -(c.c22 + dn * dn * c.g),
                 zw1 = -dn * (c.g + c.c22);
    const double pw = c.g * r * r, qw = c.g * r;  // eq. 2, W
    const double qv2 = -dn * (c.g + c.c12) * r, zw2 = -(c.g + dn * dn * c.c22),
                 zv2 = -dn * (c.g + c.c22);
    A[i] = {pv / (h * h) - qv / (2 * h), -qw1 / (2 * h), -qv2 / (2 * h),
            pw / (h * h) - qw / (2 * h)};
    B[i] = {-2 * pv / (h * h) + zv1, zw1, zv2, -2 * pw / (h * h) + zw2};
    C[i] = {pv / (h * h) + qv / (2 * h), qw1 / (2 * h), qv2 / (2 * h), pw / (h * h) + qw / (2 * h)};
    if (n == 0) {  // W decoupled (rigid rotation): W ≡ 0
      A[i].b = A[i].c = A[i].d = 0;
      B[i].b = B[i].c = 0;
      B[i].d = 1;
      C[i].b = C[i].c = C[i].d = 0;
    }
  }
  // boundary ρ = α: V = Δ c_n; ρW' − W − nV = 0 with the one-sided (7)
  {
    const double r = alpha;
    M2 b0 = {1.0, 0.0, -dn, -1.0 - 3.0 * r / (2 * h)};
    M2 c0 = {0.0, 0.0, 0.0, 4.0 * r / (2 * h)};
    M2 e0 = {0.0, 0.0, 0.0, -r / (2 * h)};
    if (n == 0) {
      // W ≡ 0 and V(α) given: no derivative, nothing to eliminate (C[1] is singular here)
      B[0] = {1.0, 0.0, 0.0, 1.0};
      C[0] = {0.0, 0.0, 0.0, 0.0};
    } else {
      const M2 t = mul(e0, inv(C[1]));  // eliminate y2 with row 1
      B[0] = sub(b0, mul(t, A[1]));
      C[0] = sub(c0, mul(t, B[1]));
    }
    F[0] = {delta * inner_coefficient(n), 0.0};
  }
  // boundary ρ = 1: c11 V' + c12(V + nW) = 0; W' − W − nV = 0 with (7)
  {
    const M2 bm = {c.c11 * 3.0 / (2 * h) + c.c12, c.c12 * dn, -dn, 3.0 / (2 * h) - 1.0};
    const M2 am = {c.c11 * -4.0 / (2 * h), 0.0, 0.0, -4.0 / (2 * h)};
    const M2 fm = {c.c11 * 1.0 / (2 * h), 0.0, 0.0, 1.0 / (2 * h)};
    if (n == 0) {
      // W ≡ 0: only the first row, a scalar elimination of V_{m−2} with row m−1's V part
      const double t = fm.a / A[mm - 1].a;
      A[mm] = {am.a - t * B[mm - 1].a, 0.0, 0.0, 0.0};
      B[mm] = {bm.a - t * C[mm - 1].a, 0.0, 0.0, 1.0};
    } else {
      const M2 t = mul(fm, inv(A[mm - 1]));  // eliminate y_{m−2} with row m−1
      A[mm] = sub(am, mul(t, B[mm - 1]));
      B[mm] = sub(bm, mul(t, C[mm - 1]));
    }
  }
  // forward elimination (8): y_i = P_i y_{i+1} + g_i
  std::vector<M2> P(mm + 1);
  std::vector<V2> g(mm + 1);
  {
    const M2 bi = inv(B[0]);
    P[0] = neg(mul(bi, C[0]));
    g[0] = mul(bi, F[0]);
  }
  for (std::size_t i = 1; i <= mm; ++i) {
    if (i % 4096 == 0) check_cancelled();  // millions of nodes with allow_large
    const M2 den = inv(add(B[i], mul(A[i], P[i - 1])));
    const V2 rhs = sub(F[i], mul(A[i], g[i - 1]));
    if (i < mm) P[i] = neg(mul(den, C[i]));
    g[i] = mul(den, rhs);
  }
  std::vector<double> V(mm + 1), W(mm + 1);
  V[mm] = g[mm].x;
  W[mm] = g[mm].y;
  for (std::size_t i = mm; i-- > 0;) {
    const V2 y = mul(P[i], V2{V[i + 1], W[i + 1]});
    V[i] = y.x + g[i].x;
    W[i] = y.y + g[i].y;
  }
  // derivatives (6), (7) and stresses
  std::vector<double> sr(mm + 1), sp(mm + 1), tu(mm + 1);
  for (std::size_t i = 0; i <= mm; ++i) {
    double dv, dw;
    if (i == 0) {
      dv = (-3 * V[0] + 4 * V[1] - V[2]) / (2 * h);
      dw = (-3 * W[0] + 4 * W[1] - W[2]) / (2 * h);
    } else if (i == mm) {
      dv = (V[mm - 2] - 4 * V[mm - 1] + 3 * V[mm]) / (2 * h);
      dw = (W[mm - 2] - 4 * W[mm - 1] + 3 * W[mm]) / (2 * h);
    } else {
      dv = (V[i + 1] - V[i - 1]) / (2 * h);
      dw = (W[i + 1] - W[i - 1]) / (2 * h);
    }
    const double r = r_at(i);
    sr[i] = (c.c11 * dv + c.c12 * (V[i] + dn * W[i]) / r) * ring.E_phi;
    sp[i] = (c.c12 * dv + c.c22 * (V[i] + dn * W[i]) / r) * ring.E_phi;
    tu[i] = c.g * (dw - (W[i] + dn * V[i]) / r) * ring.E_phi;
  }
  Harmonic out;
  out.n = n;
  for (double q : rho) {
    const auto i = static_cast<std::size_t>(std::lround((q - alpha) / h));
    const std::size_t j = std::min(i, mm);
    out.sigma_r.push_back(sr[j]);
    out.sigma_phi.push_back(sp[j]);
    out.tau.push_back(tu[j]);
  }
  out.inner_sigma_r = sr[0];
  out.section_integral = simpson(sp, h);
  return out;
}

Result analyse(const Ring& ring, const Options& options) {
  std::vector<Issue> issues = validate(ring);
  const auto more = validate(options);
  issues.insert(issues.end(), more.begin(), more.end());
  throw_if_any(issues);
  const double alpha = ring.inner_radius / ring.outer_radius;
  const int N =
      options.harmonics > 0 ? options.harmonics - options.harmonics % 2 : default_harmonics(ring);
  const bool sweep = options.method == Method::kSweep;
  int m = options.nodes > 0 ? options.nodes : default_nodes(ring, N, options.points);
  const int step = options.points - 1;
  // m a multiple of 2·step: the output radii are nodes of both m and m/2 (Richardson), and m/2
  // is even (Simpson); step is even because points is odd
  if (m % (2 * step) != 0) m = (m / (2 * step) + 1) * (2 * step);
  const auto np = static_cast<std::size_t>(options.points);
  std::vector<double> rho(np);
  for (std::size_t i = 0; i < np; ++i)
    rho[i] = alpha + (1.0 - alpha) * static_cast<double>(i) / static_cast<double>(step);
  rho.back() = 1.0;

  Result res;
  res.summary.method = sweep ? "sweep" : "exact";
  res.summary.harmonics = N;
  res.summary.nodes = sweep ? m : 0;
  std::vector<Harmonic> hs;
  std::vector<Harmonic> coarse;  // sweep with m/2 for Richardson
  int fallback_m = std::max(2 * step, default_nodes(ring, N, options.points) * 2);
  fallback_m += (2 * step - fallback_m % (2 * step)) % (2 * step);
  ProgressLoop harmonics(static_cast<std::size_t>(N / 2 + 1), "harmonics");
  for (int n = 0; n <= N; n += 2) {
    harmonics.step(static_cast<std::size_t>(n / 2));
    Harmonic hm = sweep ? solve_sweep(ring, n, m, rho) : solve_exact(ring, n, rho);
    if (hm.fallback) {
      hm = solve_sweep(ring, n, fallback_m, rho);
      hm.fallback = true;
      ++res.summary.fallbacks;
    }
    hs.push_back(std::move(hm));
    if (sweep) coarse.push_back(solve_sweep(ring, n, m / 2, rho));
    harmonics.step(static_cast<std::size_t>(n / 2 + 1));
  }
  res.contact_angle = 0.5 * kPi;
  if (options.unilateral) {
    const double delta = 0.5 * ring.gap / ring.outer_radius;
    auto rescale = [](std::vector<Harmonic>& list, const std::vector<double>& sc) {
      for (std::size_t k = 0; k < list.size(); ++k) {
        Harmonic& hm = list[k];
        for (auto* v : {&hm.sigma_r, &hm.sigma_phi, &hm.tau})
          for (double& x : *v) x *= sc[k];
        hm.section_integral *= sc[k];
        hm.inner_sigma_r *= sc[k];
      }
    };
    rescale(hs, unilateral_scales(hs, delta, res.contact_angle, res.contact_iterations));
    if (!coarse.empty()) {  // the coarse sweep finds its own contact zone (Richardson)
      double angle = 0;
      int passes = 0;
      rescale(coarse, unilateral_scales(coarse, delta, angle, passes));
    }
  }
  // sums at φ = 0 (cos nφ = 1) and φ = π/2 (cos nφ = (−1)^{n/2}); τ vanishes on both sections
  const double r2 = ring.outer_radius;
  auto sum_sections = [&](const std::vector<Harmonic>& list, std::size_t upto,
                          std::vector<double>& s0, std::vector<double>& s90,
                          std::vector<double>* r0 = nullptr, std::vector<double>* r90 = nullptr) {
    s0.assign(np, 0.0);
    s90.assign(np, 0.0);
    if (r0) r0->assign(np, 0.0);
    if (r90) r90->assign(np, 0.0);
    for (std::size_t k = 0; k < upto; ++k) {
      const double sgn = (list[k].n / 2) % 2 == 0 ? 1.0 : -1.0;
      for (std::size_t i = 0; i < np; ++i) {
        s0[i] += list[k].sigma_phi[i];
        s90[i] += sgn * list[k].sigma_phi[i];
        if (r0) (*r0)[i] += list[k].sigma_r[i];
        if (r90) (*r90)[i] += sgn * list[k].sigma_r[i];
      }
    }
  };
  sum_sections(hs, hs.size(), res.sigma_phi_0, res.sigma_phi_90, &res.sigma_r_0, &res.sigma_r_90);
  res.tau_0.assign(np, 0.0);
  res.tau_90.assign(np, 0.0);
  for (std::size_t i = 0; i < np; ++i) res.r.push_back(rho[i] * r2);
  // load P: seed 002 — two φ = π/2 sections; and from the contact pressure (equilibrium)
  double sec = 0, con = 0;
  for (const Harmonic& hm : hs) {
    const int k = hm.n / 2;
    const double sgn = k % 2 == 0 ? 1.0 : -1.0;
    sec += sgn * hm.section_integral;
    // ∫_0^{π/2} cos nφ cos φ dφ = 1 (n = 0), (−1)^{k+1}/(n² − 1)
    const double w = hm.n == 0 ? 1.0 : -sgn / (static_cast<double>(hm.n) * hm.n - 1.0);
    con += -hm.inner_sigma_r * w;
  }
  res.load = 2.0 * ring.thickness * r2 * sec;
  res.load_contact = 2.0 * ring.inner_radius * ring.thickness * con;
  res.mean_stress = res.load / (2.0 * (ring.outer_radius - ring.inner_radius) * ring.thickness);
  res.sum_sigma_r = con / res.mean_stress;
  // contact pressure and the quarter-ring shear
  const int nphi = 91;
  std::vector<double> cos_n(hs.size()), sin_n(hs.size());  // per angle, not per radius
  for (int j = 0; j < nphi; ++j) {
    check_cancelled();  // harmonics × points a row
    const double phi = 0.5 * kPi * j / (nphi - 1);
    double p = 0;
    for (std::size_t k = 0; k < hs.size(); ++k) {
      cos_n[k] = std::cos(hs[k].n * phi);
      sin_n[k] = std::sin(hs[k].n * phi);
      p -= hs[k].inner_sigma_r * cos_n[k];
    }
    res.contact_phi.push_back(phi);
    res.contact_pressure.push_back(p);
    std::vector<double> fr(np), fp(np), ft(np);
    for (std::size_t i = 0; i < np; ++i) {
      double t = 0, sr = 0, sp = 0;
      for (std::size_t k = 0; k < hs.size(); ++k) {
        t += hs[k].tau[i] * sin_n[k];
        sr += hs[k].sigma_r[i] * cos_n[k];
        sp += hs[k].sigma_phi[i] * cos_n[k];
      }
      fr[i] = sr;
      fp[i] = sp;
      ft[i] = t;
      if (std::abs(t) > std::abs(res.max_shear)) {
        res.max_shear = t;
        res.max_shear_r = res.r[i];
        res.max_shear_phi = phi;
      }
    }
    res.field_sigma_r.push_back(std::move(fr));
    res.field_sigma_phi.push_back(std::move(fp));
    res.field_tau.push_back(std::move(ft));
  }
  const double cutoff = alpha + kCornerFraction * (1.0 - alpha) - 1e-12;
  double smax = -1e300;
  for (std::size_t i = 0; i < np; ++i)
    if (rho[i] >= cutoff) smax = std::max(smax, res.sigma_phi_90[i]);
  res.stress_concentration = smax / res.mean_stress;
  res.corner_sigma_phi = res.sigma_phi_90.front();
  // truncation: change of the checked σ_φ between N/2 and N, relative to the largest checked
  {
    std::vector<double> h0, h90;
    sum_sections(hs, hs.size() / 2 + 1, h0, h90);
    double big = 0, d = 0;
    for (std::size_t i = 0; i < np; ++i) {
      big = std::max({big, std::abs(res.sigma_phi_0[i])});
      d = std::max(d, std::abs(res.sigma_phi_0[i] - h0[i]));
      if (rho[i] >= cutoff) {
        big = std::max(big, std::abs(res.sigma_phi_90[i]));
        d = std::max(d, std::abs(res.sigma_phi_90[i] - h90[i]));
      }
    }
    res.summary.truncation_change = d / big;
  }
  if (!coarse.empty()) {
    std::vector<double> c0, c90;
    sum_sections(coarse, coarse.size(), c0, c90);
    double d = 0;
    for (std::size_t i = 0; i < np; ++i) {
      d = std::max(d, std::abs(res.sigma_phi_0[i] - c0[i]));
      if (rho[i] >= cutoff) d = std::max(d, std::abs(res.sigma_phi_90[i] - c90[i]));
    }
    res.summary.richardson_error = d / 3.0 / std::abs(res.mean_stress);
  }
  // diagnostics: tension in the contact, corner singularity
  double pmin = 0;
  for (double p : res.contact_pressure) pmin = std::min(pmin, p);
  if (pmin < 0 && !options.unilateral) {
    double at = 0;
    for (std::size_t j = 0; j < res.contact_pressure.size(); ++j)
      if (res.contact_pressure[j] < 0) {
        at = res.contact_phi[j];
        break;
      }
    res.diagnostics.push_back(
        {Diagnostic::Severity::kWarning, "composite.contact_tension",
         "the half-disc pulls on the ring (negative contact pressure, value: the least, Pa) from "
         "phi = " +
             std::to_string(at * 180.0 / kPi).substr(0, 5) +
             " deg: eq. (2) assumes bilateral contact; --unilateral lets the ring separate there",
         pmin, 0.0, "Pa"});
  }
  if (options.unilateral && res.contact_iterations > 100)
    res.diagnostics.push_back({Diagnostic::Severity::kWarning, "composite.unilateral_not_settled",
                               "the contact zone did not settle in 100 active-set passes",
                               static_cast<double>(res.contact_iterations), 100.0});
  res.diagnostics.push_back(
      {Diagnostic::Severity::kInfo, "composite.corner_singularity",
       "sigma_phi at (r1, pi/2), where the half-discs meet, grows without bound with the number "
       "of harmonics; it is reported for N = " +
           std::to_string(N) + " only",
       res.corner_sigma_phi, 0.0, "Pa"});
  if (res.summary.fallbacks > 0)
    res.diagnostics.push_back({Diagnostic::Severity::kInfo, "composite.repeated_exponents",
                               "some harmonics had (nearly) repeated exponents, where the power "
                               "basis degenerates; the paper's sweep solved them with " +
                                   std::to_string(fallback_m) + " intervals (value: how many)",
                               static_cast<double>(res.summary.fallbacks), 0.0});
  return res;
}

}  // namespace catena::composite
