// Roller warp in the vertical plane (seed 000 §1.4): beam on four unilateral joints.
// The thesis prints no formula for this section; every relation below is our reconstruction
// (docs/models/warp.md), cited to the textbook it comes from.
#include "catena/warp/warp.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "catena/core/hertz.hpp"

namespace catena::warp {
namespace {

constexpr const char* kJointName[4] = {"F21", "F11", "F12", "F22"};
constexpr double kJacobianFloor = 1e-9;  // [-] of the secant joint stiffness, for open joints

double second_moment(double d) { return std::numbers::pi * d * d * d * d / 64.0; }

double cube_plus(double x) { return x > 0 ? x * x * x : 0.0; }

// Joint law R = k·g^n for g > 0, else 0 (Levina & Reshetov power law, n = 1/m).
double law(double k, double n, double g) { return g > 0 ? k * std::pow(g, n) : 0.0; }
double law_slope(double k, double n, double g) {
  return g > 0 ? k * n * std::pow(g, n - 1.0) : 0.0;
}
// Secant stiffness of a joint carrying the whole load: scale for the Jacobian floor.
double secant(double k, double n, double force) {
  return k * n * std::pow(force / k, (n - 1.0) / n);
}

// Dense Gaussian elimination with partial pivoting; false if singular.
bool solve_dense(std::vector<double>& a, std::vector<double>& x, int n) {
  for (int c = 0; c < n; ++c) {
    int p = c;
    for (int r = c + 1; r < n; ++r)
      if (std::abs(a[static_cast<std::size_t>(r * n + c)]) >
          std::abs(a[static_cast<std::size_t>(p * n + c)]))
        p = r;
    if (!(std::abs(a[static_cast<std::size_t>(p * n + c)]) > 0)) return false;
    if (p != c) {
      for (int k = 0; k < n; ++k)
        std::swap(a[static_cast<std::size_t>(p * n + k)], a[static_cast<std::size_t>(c * n + k)]);
      std::swap(x[static_cast<std::size_t>(p)], x[static_cast<std::size_t>(c)]);
    }
    const double piv = a[static_cast<std::size_t>(c * n + c)];
    for (int r = c + 1; r < n; ++r) {
      const double f = a[static_cast<std::size_t>(r * n + c)] / piv;
      if (f == 0.0) continue;
      for (int k = c; k < n; ++k)
        a[static_cast<std::size_t>(r * n + k)] -= f * a[static_cast<std::size_t>(c * n + k)];
      x[static_cast<std::size_t>(r)] -= f * x[static_cast<std::size_t>(c)];
    }
  }
  for (int r = n - 1; r >= 0; --r) {
    double s = x[static_cast<std::size_t>(r)];
    for (int k = r + 1; k < n; ++k)
      s -= a[static_cast<std::size_t>(r * n + k)] * x[static_cast<std::size_t>(k)];
    x[static_cast<std::size_t>(r)] = s / a[static_cast<std::size_t>(r * n + r)];
  }
  return true;
}

struct State {
  double a = 0, b = 0;
  std::array<double, 4> r{};
};

// w(z) of the free–free beam by Macaulay's method (Timoshenko & Gere, Mechanics of Materials,
// §9.5): EI w'' = Σ_j P_j <z − z_j>, loads P = +F at L1 and −R_i at z_i, so
// w(z) = a + b z + Σ_j P_j <z − z_j>³ / (6 EI).
double deflection(const Warp& w, const Load& load, const State& s, double z) {
  const double ei = w.modulus * second_moment(w.roller_diameter);
  double bend = load.force * cube_plus(z - load.height);
  for (int j = 0; j < 4; ++j)
    bend -= s.r[static_cast<std::size_t>(j)] *
            cube_plus(z - w.supports[static_cast<std::size_t>(j)].height);
  return s.a + s.b * z + bend / (6.0 * ei);
}

// Bending moment at z from the forces below it: M(z) = Σ_{z_j < z} P_j (z − z_j).
double moment_at(const Warp& w, const Load& load, const std::array<double, 4>& r, double z) {
  double m = load.height < z ? load.force * (z - load.height) : 0.0;
  for (int j = 0; j < 4; ++j) {
    const double zj = w.supports[static_cast<std::size_t>(j)].height;
    if (zj < z) m -= r[static_cast<std::size_t>(j)] * (z - zj);
  }
  return m;
}

// Scaled residual: joint laws (÷F) and equilibrium (÷F, ÷F·span).
std::array<double, 6> residual(const Warp& w, const Load& load, const State& s) {
  std::array<double, 6> res{};
  const double f = load.force;
  const double span = w.supports[3].height - w.supports[0].height;
  double sum = 0, mom = 0;
  for (std::size_t i = 0; i < 4; ++i) {
    const Support& sp = w.supports[i];
    const double g = deflection(w, load, s, sp.height) - sp.clearance;
    res[i] = (s.r[i] - law(sp.stiffness, w.exponent, g)) / f;
    sum += s.r[i];
    mom += s.r[i] * sp.height;
  }
  res[4] = (sum - f) / f;                         // ΣF = 0
  res[5] = (mom - f * load.height) / (f * span);  // ΣM = 0 about z = 0
  return res;
}

double norm_inf(const std::array<double, 6>& r) {
  double m = 0;
  for (double v : r) m = std::max(m, std::abs(v));
  return m;
}

}  // namespace

std::vector<Issue> validate(const Warp& w, const Load& load) {
  std::vector<Issue> out;
  for (std::size_t i = 0; i < 4; ++i) {
    const Support& s = w.supports[i];
    const std::string name = std::string("joint ") + kJointName[i];
    check::finite(out, (name + " height").c_str(), s.height, "m");
    if (!(std::isfinite(s.clearance) && s.clearance >= 0))
      out.push_back({name + " clearance", check::format_si(s.clearance, "m"), "a clearance ≥ 0 m"});
    check::finite_positive(out, (name + " stiffness").c_str(), s.stiffness, "N/m^n");
    check::finite_positive(out, (name + " width").c_str(), s.width, "m");
    if (i > 0 && std::isfinite(s.height) && std::isfinite(w.supports[i - 1].height) &&
        !(s.height > w.supports[i - 1].height))
      out.push_back({name + " height", check::format_si(s.height, "m"),
                     std::string("above joint ") + kJointName[i - 1] + " (" +
                         check::format_si(w.supports[i - 1].height, "m") +
                         "): order lower outer < lower inner < upper inner < upper outer"});
  }
  if (!(w.exponent >= 1 && w.exponent <= 3))
    out.push_back({"exponent", check::format_si(w.exponent, ""), "n of R = k·g^n in [1, 3]"});
  check::finite_positive(out, "roller_diameter", w.roller_diameter, "m");
  check::finite_positive(out, "modulus", w.modulus, "Pa");
  if (!(w.poisson >= 0 && w.poisson < 0.5))
    out.push_back({"poisson", check::format_si(w.poisson, ""), "0 ≤ ν < 0.5"});
  if (w.kind == HingeKind::kRolling) {
    check::finite_positive(out, "r1", w.r1, "m");
    if (!(std::isfinite(w.r2) && w.r2 > w.r1))
      out.push_back({"r2", check::format_si(w.r2, "m"), "R2 > R1 (the roller's concave face)"});
  }
  check::finite_positive(out, "force", load.force, "N");
  const double lo = w.supports[0].height, hi = w.supports[3].height;
  if (!std::isfinite(load.height)) {
    out.push_back({"load_height", check::format_si(load.height, "m"), "a finite height L1"});
  } else if (std::isfinite(lo) && std::isfinite(hi) && !(load.height >= lo && load.height <= hi)) {
    out.push_back({"load_height", check::format_si(load.height, "m"),
                   "L1 between the outer joints [" + check::format_si(lo, "m") + ", " +
                       check::format_si(hi, "m") +
                       "] (outside, unilateral joints cannot balance the moment)"});
  }
  return out;
}

double contact_stress(const Warp& w, int joint, double force) {
  const Support& s = w.supports[static_cast<std::size_t>(joint)];
  if (w.kind == HingeKind::kSliding)  // specific pressure on the projected area, cf. 000 eq. (23)
    return force / (w.roller_diameter * s.width);
  const Elastic e{w.modulus, w.poisson};
  // Johnson (1985) §4.2, R1 convex in R2 concave (fig. 12c), load per length R/B.
  return line_contact(force / s.width, conformal_radius(w.r1, w.r2), contact_modulus(e, e))
      .peak_pressure;
}

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

namespace {
// Joint forces, deflections, moments, stresses and diagnostics of a solved state.
WarpResult build_result(const Warp& w, const Load& load, const State& s,
                        const SolverSummary& summary, const SolveOptions& options) {
  const double f = load.force;
  const double n = w.exponent;
  WarpResult out;
  out.summary = summary;
  // Results.
  out.offset = s.a;
  out.rotation = s.b;
  double sum = 0, mom = 0;
  for (std::size_t i = 0; i < 4; ++i) {
    const Support& sp = w.supports[i];
    out.deflection[i] = deflection(w, load, s, sp.height);
    out.deformation[i] = std::max(0.0, out.deflection[i] - sp.clearance);
    // The joint law evaluated at the converged deflection (never a tension); the residuals
    // below then measure how well these forces balance F.
    out.force[i] = law(sp.stiffness, n, out.deflection[i] - sp.clearance);
    sum += out.force[i];
    mom += out.force[i] * sp.height;
  }
  for (std::size_t i = 0; i < 4; ++i) {
    out.moment[i] = moment_at(w, load, out.force, w.supports[i].height);
    out.contact_stress[i] = contact_stress(w, static_cast<int>(i), std::max(0.0, out.force[i]));
  }
  // |M| is piecewise linear: its maximum is at a load point.
  out.moment_max = std::abs(moment_at(w, load, out.force, load.height));
  for (double m : out.moment) out.moment_max = std::max(out.moment_max, std::abs(m));
  out.bending_stress = out.moment_max * 0.5 * w.roller_diameter / second_moment(w.roller_diameter);
  out.tilt = std::atan((out.deflection[3] - out.deflection[0]) /
                       (w.supports[3].height - w.supports[0].height));
  const double lower = out.force[kF11] + out.force[kF21];
  out.upper_share = lower > 0 ? (out.force[kF12] + out.force[kF22]) / lower - 1.0 : INFINITY;
  out.force_residual = std::abs(f - sum);
  out.moment_residual = std::abs(f * load.height - mom);
  // Diagnostics.
  if (!out.summary.converged)
    out.diagnostics.push_back({Diagnostic::Severity::kInfeasible, "warp.not_converged",
                               "the joint-force solver did not converge (" +
                                   out.summary.termination + "); results are not valid",
                               out.summary.residual, options.tolerance * f});
  for (std::size_t i = 0; i < 4; ++i) {
    if (out.force[i] <= 0.0)
      out.diagnostics.push_back(
          {Diagnostic::Severity::kInfo, std::string("warp.joint_open.") + kJointName[i],
           std::string("joint ") + kJointName[i] +
               " carries no load: its clearance is not closed (approach ≤ clearance)",
           out.deflection[i], w.supports[i].clearance});
    if (w.kind == HingeKind::kRolling && out.force[i] > 0) {
      const Elastic e{w.modulus, w.poisson};
      const double b = line_contact(out.force[i] / w.supports[i].width,
                                    conformal_radius(w.r1, w.r2), contact_modulus(e, e))
                           .half_width;
      constexpr double kHertzWidthLimit = 0.1;  // [-] b/R1 beyond which conformal Hertz is rough
      if (b > kHertzWidthLimit * w.r1)
        out.diagnostics.push_back(
            {Diagnostic::Severity::kWarning, std::string("warp.hertz_conformal.") + kJointName[i],
             std::string("joint ") + kJointName[i] +
                 ": Hertz half-width exceeds 0.1·R1, the conformal contact is outside Hertz' "
                 "small-contact assumption (Persson's conformal theory would apply)",
             b, kHertzWidthLimit * w.r1});
    }
  }
  return out;
}
}  // namespace

namespace {
WarpResult flexibility_impl(const Warp& w, const Load& load, const SolveOptions& options,
                            const State* initial) {
  const double f = load.force;
  const double n = w.exponent;
  const double ei = w.modulus * second_moment(w.roller_diameter);
  WarpResult out;
  // Damped Newton on the scaled residual, from state `s`, for the load `ld`; returns the final
  // max |scaled residual| and counts iterations into `it`.
  auto newton = [&](State& s, const Load& ld, int& it, int max_it) {
    const double fl = ld.force;
    auto res = residual(w, ld, s);
    double rn = norm_inf(res);
    for (int k0 = 0; k0 < max_it && rn > options.tolerance; ++k0, ++it) {
      // Jacobian of the scaled residual in the unknowns (a, b, R_0..R_3).
      std::vector<double> jac(36, 0.0);
      std::vector<double> rhs(6);
      const double span = w.supports[3].height - w.supports[0].height;
      for (std::size_t i = 0; i < 4; ++i) {
        const Support& sp = w.supports[i];
        const double g = deflection(w, ld, s, sp.height) - sp.clearance;
        const double kt =
            std::max(law_slope(sp.stiffness, n, g), kJacobianFloor * secant(sp.stiffness, n, fl));
        jac[i * 6 + 0] = -kt / fl;
        jac[i * 6 + 1] = -kt * sp.height / fl;
        for (std::size_t j = 0; j < 4; ++j) {
          const double dw = -cube_plus(sp.height - w.supports[j].height) / (6.0 * ei);
          jac[i * 6 + 2 + j] = ((i == j ? 1.0 : 0.0) - kt * dw) / fl;
        }
      }
      for (std::size_t j = 0; j < 4; ++j) {
        jac[4 * 6 + 2 + j] = 1.0 / fl;
        jac[5 * 6 + 2 + j] = w.supports[j].height / (fl * span);
      }
      for (std::size_t i = 0; i < 6; ++i) rhs[i] = -res[i];
      if (!solve_dense(jac, rhs, 6)) break;  // reported as not converged
      // Backtracking on the max-norm of the residual.
      double step = 1.0;
      State trial;
      std::array<double, 6> tres{};
      double tn = rn;
      for (int k = 0; k < 40; ++k, step *= 0.5) {
        trial.a = s.a + step * rhs[0];
        trial.b = s.b + step * rhs[1];
        for (std::size_t j = 0; j < 4; ++j) trial.r[j] = s.r[j] + step * rhs[2 + j];
        tres = residual(w, ld, trial);
        tn = norm_inf(tres);
        if (tn < rn * (1 - 1e-4 * step)) break;
      }
      s = trial;
      res = tres;
      rn = tn;
    }
    return rn;
  };
  // Start: every joint closed and sharing F equally, no tilt.
  double cmax = 0;
  for (const Support& sp : w.supports) cmax = std::max(cmax, sp.clearance);
  double kmin = w.supports[0].stiffness;
  for (const Support& sp : w.supports) kmin = std::min(kmin, sp.stiffness);
  auto start = [&](double force) {
    State st;
    st.a = cmax + std::pow(0.25 * force / kmin, 1.0 / n);
    st.r.fill(0.25 * force);
    return st;
  };
  int it = 0;
  State s = initial ? *initial : start(f);
  double rn = newton(s, load, it, options.max_iterations);
  // Fallback when the active set chatters (a flexible roller, joints far apart): load
  // continuation, each increment started from the previous converged state.
  for (int steps : {8, 64}) {
    if (rn <= options.tolerance) break;
    s = start(f / steps);
    for (int k = 1; k <= steps; ++k) {
      const Load part{f * k / steps, load.height};
      rn = newton(s, part, it, options.max_iterations);
      if (rn > options.tolerance) break;
      if (k < steps) {  // scale the forces to the next increment
        for (double& r : s.r) r *= static_cast<double>(k + 1) / k;
      }
    }
  }
  out.summary.converged = rn <= options.tolerance;
  out.summary.termination = out.summary.converged ? "max |scaled residual| ≤ tolerance"
                                                  : "iteration limit (after load continuation)";
  out.summary.iterations = it;
  out.summary.residual = rn * f;
  return build_result(w, load, s, out.summary, options);
}
}  // namespace

WarpResult solve_flexibility(const Warp& w, const Load& load, const SolveOptions& options) {
  throw_if_any(validate(w, load));
  return flexibility_impl(w, load, options, nullptr);
}

namespace {
struct FeSolution {
  std::vector<double> z, u;  // node heights, (w, θ) per node
  std::array<int, 4> joint_node{};
  int iterations = 0;
  double residual = 0;  // [N] max |nodal force residual|
  bool converged = false;
};

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
  sol.converged = rn <= tolerance * f + floor_of(u);
  return sol;
}
}  // namespace

std::array<double, 4> solve_fe(const Warp& w, const Load& load, int elements) {
  throw_if_any(validate(w, load));
  const FeSolution sol = fe_solve(w, load, elements, 1e-11, 500);
  std::array<double, 4> out{};
  for (std::size_t i = 0; i < 4; ++i)
    out[i] = law(w.supports[i].stiffness, w.exponent,
                 sol.u[static_cast<std::size_t>(2 * sol.joint_node[i])] - w.supports[i].clearance);
  return out;
}

WarpResult solve(const Warp& w, const Load& load, const SolveOptions& options) {
  throw_if_any(validate(w, load));
  // One element per segment between joints and load point: exact for the Euler–Bernoulli
  // beam under point loads (cubic between them).
  const FeSolution sol = fe_solve(w, load, 1, options.tolerance, options.max_iterations);
  State s;
  for (std::size_t i = 0; i < 4; ++i)
    s.r[i] = law(w.supports[i].stiffness, w.exponent,
                 sol.u[static_cast<std::size_t>(2 * sol.joint_node[i])] - w.supports[i].clearance);
  // Below every load w = a + b z: b is the slope, a the intercept at the lowest node.
  s.b = sol.u[1];
  s.a = sol.u[0] - s.b * sol.z[0];
  // Polish: the force method started from this state (active set known) restores equilibrium
  // to round-off of F rather than of K·u; kept only if it converges.
  SolveOptions polish = options;
  polish.max_iterations = 20;
  WarpResult polished = flexibility_impl(w, load, polish, &s);
  if (polished.summary.converged) {
    polished.summary.iterations += sol.iterations;
    polished.summary.termination =
        "energy-descent Newton (displacement method), polished by the force method: " +
        polished.summary.termination;
    return polished;
  }
  SolverSummary summary;
  summary.iterations = sol.iterations;
  summary.residual = sol.residual;
  summary.converged = sol.converged;
  summary.termination =
      summary.converged
          ? "max |nodal force residual| ≤ tolerance·F + round-off floor (energy-descent Newton)"
          : "iteration limit";
  return build_result(w, load, s, summary, options);
}

}  // namespace catena::warp
