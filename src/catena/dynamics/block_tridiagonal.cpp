// Block Thomas with a Sherman–Morrison–Woodbury closure (include/catena/dynamics/
// block_tridiagonal.hpp; the derivation is in docs/models/dynamics.md, "Solver").
#include "catena/dynamics/block_tridiagonal.hpp"

#include <cmath>
#include <stdexcept>

namespace catena::dynamics {
namespace {

// The inverse of a 2×2 block; false when it is singular relative to its own size. Inline: it is
// called once per block row of every factorisation, on the recurrence's critical path.
inline bool invert(const Mat2& m, Mat2& inv) {
  const double det = m.a * m.d - m.b * m.c;
  const double scale = std::max(std::abs(m.a) + std::abs(m.b), std::abs(m.c) + std::abs(m.d));
  if (!std::isfinite(det) || !(std::abs(det) > 1e-300) || std::abs(det) <= 1e-14 * scale * scale) {
    return false;
  }
  inv = {m.d / det, -m.b / det, -m.c / det, m.a / det};
  return true;
}

}  // namespace

BlockTridiagonalSolver::BlockTridiagonalSolver(std::size_t n, bool cyclic)
    : lower(n),
      diag(n),
      upper(n),
      rhs(n),
      n_(n),
      cyclic_(cyclic),
      s_inv_(n),
      c_prime_(n),
      w_(n),
      y_(n),
      y2_(n) {
  if (cyclic && n < 3) throw std::invalid_argument("a cyclic block system needs n >= 3");
  if (n < 1) throw std::invalid_argument("a block system needs n >= 1");
}

SolveStatus BlockTridiagonalSolver::solve(std::span<Vec2> x) {
  if (x.size() != n_) throw std::invalid_argument("solution span has the wrong size");
  const SolveStatus status = factor();
  if (status == SolveStatus::kSolved) substitute(rhs, x);
  return status;
}

SolveStatus BlockTridiagonalSolver::factor() {
  pending_ = false;  // the factors and the workspace are no longer factor_forward()'s
  const std::size_t n = n_;
  const std::size_t last = n - 1;

  // The closure, for a cyclic system: A = T + W Zᵀ with W = [G; 0; …; U_{n−1}] and
  // Zᵀ = [I, 0, …, G⁻¹ L_0], G = −D_0. Then T differs from A only in two diagonal blocks:
  // T_00 = D_0 − G = 2 D_0 and T_{n−1,n−1} = D_{n−1} − U_{n−1} G⁻¹ L_0 = D_{n−1} + U_{n−1} D_0⁻¹
  // L_0. For symmetric A, W Zᵀ = −[I; −L_0ᵀ D_0⁻¹] D_0 [I, −D_0⁻¹ L_0] is negative semidefinite, so
  // T = A − W Zᵀ is positive definite whenever A is: its block LU needs no pivoting.
  Mat2 d0_inv;
  if (cyclic_) {
    if (!invert(diag[0], d0_inv)) return SolveStatus::kSingularPivot;
    const Mat2 m = d0_inv * lower[0];
    h_ = {-m.a, -m.b, -m.c, -m.d};  // G⁻¹ L_0 = −D_0⁻¹ L_0
  }
  // Block LU of T; for a cyclic system the forward sweep of T Q = W rides along. T's diagonal is
  // A's but for T_00 and T_{n−1,n−1}; W is −D_0 in row 0, U_{n−1} in row n−1 and zero between.
  if (!cyclic_) {
    if (!invert(diag[0], s_inv_[0])) return SolveStatus::kSingularPivot;
    if (n > 1) c_prime_[0] = s_inv_[0] * upper[0];
    for (std::size_t i = 1; i < n; ++i) {
      if (!invert(diag[i] - lower[i] * c_prime_[i - 1], s_inv_[i])) {
        return SolveStatus::kSingularPivot;
      }
      if (i < last) c_prime_[i] = s_inv_[i] * upper[i];
    }
    return SolveStatus::kSolved;
  }
  if (!invert(diag[0] + diag[0], s_inv_[0])) return SolveStatus::kSingularPivot;
  c_prime_[0] = s_inv_[0] * upper[0];
  w_[0] = s_inv_[0] * Mat2{-diag[0].a, -diag[0].b, -diag[0].c, -diag[0].d};
  for (std::size_t i = 1; i < last; ++i) {
    if (!invert(diag[i] - lower[i] * c_prime_[i - 1], s_inv_[i])) {
      return SolveStatus::kSingularPivot;
    }
    c_prime_[i] = s_inv_[i] * upper[i];
    w_[i] = s_inv_[i] * (Mat2{} - lower[i] * w_[i - 1]);
  }
  const Mat2 t_last = diag[last] + upper[last] * d0_inv * lower[0];
  if (!invert(t_last - lower[last] * c_prime_[last - 1], s_inv_[last])) {
    return SolveStatus::kSingularPivot;
  }
  w_[last] = s_inv_[last] * (upper[last] - lower[last] * w_[last - 1]);
  for (std::size_t k = n - 1; k-- > 0;) w_[k] = w_[k] - c_prime_[k] * w_[k + 1];
  // Sherman–Morrison–Woodbury: x = y − Q (I + Zᵀ Q)⁻¹ Zᵀ y, Zᵀ v = v_0 + G⁻¹ L_0 v_{n−1}.
  const Mat2 capacitance = Mat2{1.0, 0.0, 0.0, 1.0} + w_[0] + h_ * w_[last];
  if (!invert(capacitance, cap_inv_)) return SolveStatus::kSingularPivot;
  return SolveStatus::kSolved;
}

void BlockTridiagonalSolver::substitute(std::span<const Vec2> b, std::span<Vec2> x) {
  pending_ = false;  // y_ is overwritten
  if (x.size() != n_ || b.size() != n_) throw std::invalid_argument("span of the wrong size");
  const std::size_t n = n_;
  y_[0] = s_inv_[0] * b[0];
  for (std::size_t i = 1; i < n; ++i) y_[i] = s_inv_[i] * (b[i] - lower[i] * y_[i - 1]);
  for (std::size_t k = n - 1; k-- > 0;) y_[k] = y_[k] - c_prime_[k] * y_[k + 1];
  if (!cyclic_) {
    for (std::size_t i = 0; i < n; ++i) x[i] = y_[i];
    return;
  }
  const Vec2 z = cap_inv_ * (y_[0] + h_ * y_[n - 1]);
  for (std::size_t i = 0; i < n; ++i) x[i] = y_[i] - w_[i] * z;
}

void BlockTridiagonalSolver::substitute(std::span<const Vec2> b, std::span<Vec2> x,
                                        std::span<const Vec2> b2, std::span<Vec2> x2) {
  pending_ = false;  // y_ and y2_ are overwritten
  if (x.size() != n_ || b.size() != n_ || x2.size() != n_ || b2.size() != n_) {
    throw std::invalid_argument("span of the wrong size");
  }
  const std::size_t n = n_;
  y_[0] = s_inv_[0] * b[0];
  y2_[0] = s_inv_[0] * b2[0];
  for (std::size_t i = 1; i < n; ++i) {
    y_[i] = s_inv_[i] * (b[i] - lower[i] * y_[i - 1]);
    y2_[i] = s_inv_[i] * (b2[i] - lower[i] * y2_[i - 1]);
  }
  for (std::size_t k = n - 1; k-- > 0;) {
    y_[k] = y_[k] - c_prime_[k] * y_[k + 1];
    y2_[k] = y2_[k] - c_prime_[k] * y2_[k + 1];
  }
  if (!cyclic_) {
    for (std::size_t i = 0; i < n; ++i) {
      x[i] = y_[i];
      x2[i] = y2_[i];
    }
    return;
  }
  const Vec2 z = cap_inv_ * (y_[0] + h_ * y_[n - 1]);
  const Vec2 z2 = cap_inv_ * (y2_[0] + h_ * y2_[n - 1]);
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = y_[i] - w_[i] * z;
    x2[i] = y2_[i] - w_[i] * z2;
  }
}

}  // namespace catena::dynamics

namespace catena::dynamics {

// factor() and substitute() interleaved: each row's forward substitution y_i = S_i⁻¹ (b_i − L_i
// y_{i−1}) as soon as S_i⁻¹ is known, and the back sweeps of y and of the closure's columns Q in
// one pass (the statements, and so the roundings, of the two functions).
template <bool kTwo>
SolveStatus BlockTridiagonalSolver::factor_forward(const Vec2* b, const Vec2* b2) {
  const std::size_t n = n_;
  const std::size_t last = n - 1;
  const Mat2* lo = lower.data();
  const Mat2* di = diag.data();
  const Mat2* up = upper.data();
  Mat2* s_inv = s_inv_.data();
  Mat2* c_prime = c_prime_.data();
  Mat2* w = w_.data();
  Vec2* y = y_.data();
  Vec2* y2 = y2_.data();
  two_ = kTwo;
  if (!cyclic_) {
    if (!invert(di[0], s_inv[0])) return SolveStatus::kSingularPivot;
    if (n > 1) c_prime[0] = s_inv[0] * up[0];
    y[0] = s_inv[0] * b[0];
    if constexpr (kTwo) y2[0] = s_inv[0] * b2[0];
    for (std::size_t i = 1; i < n; ++i) {
      if (!invert(di[i] - lo[i] * c_prime[i - 1], s_inv[i])) return SolveStatus::kSingularPivot;
      if (i < last) c_prime[i] = s_inv[i] * up[i];
      y[i] = s_inv[i] * (b[i] - lo[i] * y[i - 1]);
      if constexpr (kTwo) y2[i] = s_inv[i] * (b2[i] - lo[i] * y2[i - 1]);
    }
    for (std::size_t k = n - 1; k-- > 0;) {
      y[k] = y[k] - c_prime[k] * y[k + 1];
      if constexpr (kTwo) y2[k] = y2[k] - c_prime[k] * y2[k + 1];
    }
    return SolveStatus::kSolved;
  }
  Mat2 d0_inv;
  if (!invert(di[0], d0_inv)) return SolveStatus::kSingularPivot;
  const Mat2 m = d0_inv * lo[0];
  h_ = {-m.a, -m.b, -m.c, -m.d};
  if (!invert(di[0] + di[0], s_inv[0])) return SolveStatus::kSingularPivot;
  c_prime[0] = s_inv[0] * up[0];
  w[0] = s_inv[0] * Mat2{-di[0].a, -di[0].b, -di[0].c, -di[0].d};
  y[0] = s_inv[0] * b[0];
  if constexpr (kTwo) y2[0] = s_inv[0] * b2[0];
  for (std::size_t i = 1; i < last; ++i) {
    if (!invert(di[i] - lo[i] * c_prime[i - 1], s_inv[i])) return SolveStatus::kSingularPivot;
    c_prime[i] = s_inv[i] * up[i];
    w[i] = s_inv[i] * (Mat2{} - lo[i] * w[i - 1]);
    y[i] = s_inv[i] * (b[i] - lo[i] * y[i - 1]);
    if constexpr (kTwo) y2[i] = s_inv[i] * (b2[i] - lo[i] * y2[i - 1]);
  }
  const Mat2 t_last = di[last] + up[last] * d0_inv * lo[0];
  if (!invert(t_last - lo[last] * c_prime[last - 1], s_inv[last])) {
    return SolveStatus::kSingularPivot;
  }
  w[last] = s_inv[last] * (up[last] - lo[last] * w[last - 1]);
  y[last] = s_inv[last] * (b[last] - lo[last] * y[last - 1]);
  if constexpr (kTwo) y2[last] = s_inv[last] * (b2[last] - lo[last] * y2[last - 1]);
  for (std::size_t k = n - 1; k-- > 0;) {
    const Mat2 c = c_prime[k];
    w[k] = w[k] - c * w[k + 1];
    y[k] = y[k] - c * y[k + 1];
    if constexpr (kTwo) y2[k] = y2[k] - c * y2[k + 1];
  }
  const Mat2 capacitance = Mat2{1.0, 0.0, 0.0, 1.0} + w[0] + h_ * w[last];
  if (!invert(capacitance, cap_inv_)) return SolveStatus::kSingularPivot;
  return SolveStatus::kSolved;
}

SolveStatus BlockTridiagonalSolver::factor_forward(std::span<const Vec2> b,
                                                   std::span<const Vec2> b2) {
  if (b.size() != n_ || (!b2.empty() && b2.size() != n_)) {
    throw std::invalid_argument("span of the wrong size");
  }
  pending_ = false;
  const SolveStatus status = b2.empty() ? factor_forward<false>(b.data(), nullptr)
                                        : factor_forward<true>(b.data(), b2.data());
  pending_ = status == SolveStatus::kSolved;
  return status;
}

void BlockTridiagonalSolver::finish(std::span<Vec2> x, std::span<Vec2> x2) {
  if (!pending_) {
    throw std::logic_error(
        "finish() without a successful factor_forward() since the last factor() or substitute()");
  }
  if (x.size() != n_ || (two_ && x2.size() != n_)) {
    throw std::invalid_argument("span of the wrong size");
  }
  const std::size_t n = n_;
  if (!cyclic_) {
    for (std::size_t i = 0; i < n; ++i) x[i] = y_[i];
    if (two_) {
      for (std::size_t i = 0; i < n; ++i) x2[i] = y2_[i];
    }
    return;
  }
  const Vec2 z = cap_inv_ * (y_[0] + h_ * y_[n - 1]);
  if (!two_) {
    for (std::size_t i = 0; i < n; ++i) x[i] = y_[i] - w_[i] * z;
    return;
  }
  const Vec2 z2 = cap_inv_ * (y2_[0] + h_ * y2_[n - 1]);
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = y_[i] - w_[i] * z;
    x2[i] = y2_[i] - w_[i] * z2;
  }
}

}  // namespace catena::dynamics
