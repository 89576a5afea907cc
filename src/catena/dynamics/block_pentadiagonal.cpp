// Band LU with partial pivoting and a rank-4 Sherman–Morrison–Woodbury closure
// (include/catena/dynamics/block_pentadiagonal.hpp; docs/models/dynamics.md, "Solver").
#include "catena/dynamics/block_pentadiagonal.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace catena::dynamics {
namespace {

bool usable_pivot(double p) { return std::isfinite(p) && std::abs(p) > 1e-300; }

}  // namespace

BlockPentadiagonalSolver::BlockPentadiagonalSolver(std::size_t n, bool cyclic)
    : rhs(n),
      n_(n),
      m_(2 * n),
      cyclic_(cyclic),
      closure_(cyclic && n >= 4),  // at n = 3 every pair of nodes lies within the band
      lu_(2 * n * kWidth),
      inv_diag_(2 * n),
      piv_(2 * n),
      q_(cyclic && n >= 4 ? 2 * n * 4 : 0),
      y_(2 * n),
      y2_(2 * n) {
  if (cyclic && n < 3) throw std::invalid_argument("a cyclic block system needs n >= 3");
  if (n < 1) throw std::invalid_argument("a block system needs n >= 1");
  for (auto& b : band) b.resize(n);
  for (auto& b : t_) b.resize(n);
  for (auto& b : f_) b.resize(n);
}

SolveStatus BlockPentadiagonalSolver::solve(std::span<Vec2> x) {
  if (x.size() != n_) throw std::invalid_argument("solution span has the wrong size");
  const SolveStatus status = factor();
  if (status == SolveStatus::kSolved) substitute(rhs, x);
  return status;
}

SolveStatus BlockPentadiagonalSolver::factor() {
  const std::size_t n = n_, m = m_;
  // Once n ≥ 5 (or on an open system) each of T's places takes at most one block, so each is
  // written once: a block as the zero the place starts at plus the block (0 + b, which keeps the
  // sum's sign of a zero), a place no block reaches as zero. At n = 3, 4 a closed loop's wrapped
  // block can land on a place within the band too: there the places start at zero and add up.
  const bool once = !cyclic_ || n >= 5;
  if (!once) {
    for (auto& b : t_) std::fill(b.begin(), b.end(), Mat2{});
  }
  for (auto& row : ctr_) std::fill(row, row + 4, 0.0);
  for (auto& row : cbl_) std::fill(row, row + 4, 0.0);
  // Gather the blocks: within the band (|i − j| ≤ 2 as plain indices) into T's bands t_, else (a
  // closed loop's wrap-around) into the corners.
  for (int o = -2; o <= 2; ++o) {
    const std::vector<Mat2>& blocks = band[static_cast<std::size_t>(o + 2)];
    Mat2* const within = t_[static_cast<std::size_t>(o + 2)].data();
    const long nl = static_cast<long>(n);
    for (std::size_t i = 0; i < n; ++i) {
      const long jl = static_cast<long>(i) + o;
      const Mat2& b = blocks[i];
      if (jl >= 0 && jl < nl) {  // within the band: the gap is o
        Mat2& t = within[i];
        t = once ? Mat2{0.0 + b.a, 0.0 + b.b, 0.0 + b.c, 0.0 + b.d}
                 : Mat2{t.a + b.a, t.b + b.b, t.c + b.c, t.d + b.d};
        continue;
      }
      if (once) within[i] = Mat2{};  // outside the band: a corner's block, or none
      if (!cyclic_) continue;
      const std::size_t j = static_cast<std::size_t>(jl < 0 ? jl + nl : jl - nl);
      const long gap = static_cast<long>(j) - static_cast<long>(i);
      if (gap >= -2 && gap <= 2) {
        Mat2& t = t_[static_cast<std::size_t>(gap + 2)][i];
        t = {t.a + b.a, t.b + b.b, t.c + b.c, t.d + b.d};
        continue;
      }
      const double v[2][2] = {{b.a, b.b}, {b.c, b.d}};
      for (std::size_t r = 0; r < 2; ++r) {
        for (std::size_t c = 0; c < 2; ++c) {
          const std::size_t row = 2 * i + r, col = 2 * j + c;
          if (i < j) {  // rows of nodes 0, 1; columns of nodes n − 2, n − 1
            ctr_[row][col - (m - 4)] += v[r][c];
          } else {
            cbl_[row - (m - 4)][col] += v[r][c];
          }
        }
      }
    }
  }
  SmallLu a_tl;        // A_tl's LU
  double a_top[4][4];  // A_tl itself (G = −A_tl is W's top)
  if (closure_) {
    // T = A − W Zᵀ: T_tl = A_tl − G = 2 A_tl, T_br = A_br − C_bl G⁻¹ C_tr = A_br + C_bl A_tl⁻¹
    // C_tr; H = G⁻¹ C_tr = −A_tl⁻¹ C_tr.
    for (std::size_t r = 0; r < 4; ++r) {
      for (std::size_t c = 0; c < 4; ++c) a_tl.lu[r][c] = a_top[r][c] = element(r, c);
    }
    if (!a_tl.factor(4, usable_pivot)) return SolveStatus::kSingularPivot;
    for (int c = 0; c < 4; ++c) {
      double col[4] = {ctr_[0][c], ctr_[1][c], ctr_[2][c], ctr_[3][c]};
      a_tl.solve(col);
      for (int r = 0; r < 4; ++r) h_[r][c] = -col[r];
    }
    for (std::size_t r = 0; r < 4; ++r) {
      for (std::size_t c = 0; c < 4; ++c) element(r, c) += a_top[r][c];
    }
    for (std::size_t r = 0; r < 4; ++r) {
      for (std::size_t c = 0; c < 4; ++c) {
        double s = 0.0;  // (C_bl A_tl⁻¹ C_tr)_rc = −(C_bl H)_rc
        for (int k = 0; k < 4; ++k) s -= cbl_[r][k] * h_[k][c];
        element(m - 4 + r, m - 4 + c) += s;
      }
    }
  }
  // T's factors: block LU without pivoting when every 2×2 pivot block is well conditioned (as
  // for the chain's matrices, whose symmetric part is positive definite: mass, links in tension,
  // the rate term c g gᵀ; Golub & Van Loan §4.2 on LU without pivoting of such systems), else
  // the scalar band elimination with partial pivoting.
  blocked_ = block_factor();
  if (!blocked_) {
    const SolveStatus status = pivoted_factor();
    if (status != SolveStatus::kSolved) return status;
  }
  if (!closure_) return SolveStatus::kSolved;
  // Q = T⁻¹ W, W = [G; 0; C_bl], G = −A_tl
  std::fill(q_.begin(), q_.end(), 0.0);
  for (std::size_t r = 0; r < 4; ++r) {
    for (std::size_t c = 0; c < 4; ++c) {
      q_[4 * r + c] = -a_top[r][c];
      q_[4 * (m - 4 + r) + c] += cbl_[r][c];
    }
  }
  if (blocked_) {
    block_solve4(q_.data());  // the four columns side by side
  } else {
    for (std::size_t c = 0; c < 4; ++c) {
      for (std::size_t r = 0; r < m; ++r) y_[r] = q_[4 * r + c];
      band_solve(y_.data());
      for (std::size_t r = 0; r < m; ++r) q_[4 * r + c] = y_[r];
    }
  }
  // capacitance I + Zᵀ Q, Zᵀ v = v_top + H v_bottom
  for (std::size_t r = 0; r < 4; ++r) {
    for (std::size_t c = 0; c < 4; ++c) {
      double s = (r == c ? 1.0 : 0.0) + q_[4 * r + c];
      for (std::size_t k = 0; k < 4; ++k) s += h_[r][k] * q_[4 * (m - 4 + k) + c];
      cap_.lu[r][c] = s;
    }
  }
  if (!cap_.factor(4, usable_pivot)) return SolveStatus::kSingularPivot;
  return SolveStatus::kSolved;
}

double& BlockPentadiagonalSolver::element(std::size_t r, std::size_t c) {
  Mat2& b = t_[c / 2 + 2 - r / 2][r / 2];
  return r % 2 == 0 ? (c % 2 == 0 ? b.a : b.b) : (c % 2 == 0 ? b.c : b.d);
}

bool BlockPentadiagonalSolver::block_factor() {
  // f_[o + 2][i]: U's blocks (i, i + o), o = 0..2 (the diagonal ones inverted), and L's
  // multipliers (i, i + o), o = −2, −1
  const std::size_t n = n_;
  for (std::size_t o = 0; o < 5; ++o) f_[o] = t_[o];
  double scale = 0.0;
  for (const Mat2& d : t_[2]) {
    scale = std::max({scale, std::abs(d.a) + std::abs(d.b), std::abs(d.c) + std::abs(d.d)});
  }
  Mat2 *const f0 = f_[0].data(), *const f1 = f_[1].data(), *const f2 = f_[2].data();
  Mat2* const f3 = f_[3].data();
  const Mat2* const f4 = f_[4].data();  // U's (k, k + 2): the elimination leaves them as they are
  for (std::size_t k = 0; k < n; ++k) {
    const Mat2 d = f2[k];
    const double det = d.a * d.d - d.b * d.c;
    const double size = std::max(std::abs(d.a) + std::abs(d.b), std::abs(d.c) + std::abs(d.d));
    // a pivot block small against the matrix or ill conditioned in itself: pivot instead
    if (!std::isfinite(det) || !(size > 1e-8 * scale) || !(std::abs(det) > 1e-8 * size * size)) {
      return false;
    }
    const Mat2 inv{d.d / det, -d.b / det, -d.c / det, d.a / det};
    f2[k] = inv;
    // rows k + 1 and k + 2: L's multiplier (r, k) = A(r, k) S_k⁻¹, then the blocks (r, k + 1)
    // and (r, k + 2) less it times U's (k, k + 1) and (k, k + 2), in that order
    const Mat2 u1 = f3[k], u2 = f4[k];
    if (k + 1 < n) {
      const Mat2 l = f1[k + 1] * inv;
      f1[k + 1] = l;
      f2[k + 1] = f2[k + 1] - l * u1;
      if (k + 2 < n) f3[k + 1] = f3[k + 1] - l * u2;
    }
    if (k + 2 < n) {
      const Mat2 l = f0[k + 2] * inv;
      f0[k + 2] = l;
      f1[k + 2] = f1[k + 2] - l * u1;
      f2[k + 2] = f2[k + 2] - l * u2;
    }
  }
  return true;
}

SolveStatus BlockPentadiagonalSolver::pivoted_factor() {
  const std::size_t n = n_, m = m_;
  std::fill(lu_.begin(), lu_.end(), 0.0);
  for (std::size_t o = 0; o < 5; ++o) {
    for (std::size_t i = 0; i < n; ++i) {
      if (i + o < 2 || i + o - 2 >= n) continue;
      const std::size_t j = i + o - 2;
      const Mat2& b = t_[o][i];
      at(2 * i, 2 * j) = b.a;
      at(2 * i, 2 * j + 1) = b.b;
      at(2 * i + 1, 2 * j) = b.c;
      at(2 * i + 1, 2 * j + 1) = b.d;
    }
  }
  // Band elimination with partial pivoting, column by column.
  for (std::size_t k = 0; k < m; ++k) {
    const std::size_t rmax = std::min(m - 1, k + kLower);
    const std::size_t cmax = std::min(m - 1, k + kLower + kUpper);
    std::size_t p = k;
    for (std::size_t r = k + 1; r <= rmax; ++r) {
      if (std::abs(at(r, k)) > std::abs(at(p, k))) p = r;
    }
    piv_[k] = p;
    if (!usable_pivot(at(p, k))) return SolveStatus::kSingularPivot;
    if (p != k) {
      for (std::size_t c = k; c <= cmax; ++c) std::swap(at(k, c), at(p, c));
    }
    const double inv = 1.0 / at(k, k);
    inv_diag_[k] = inv;
    const double* pivot_row = &at(k, k);
    for (std::size_t r = k + 1; r <= rmax; ++r) {
      double* row = &at(r, k);
      const double l = row[0] * inv;
      row[0] = l;
      if (l == 0.0) continue;
      for (std::size_t c = 1; c <= cmax - k; ++c) row[c] -= l * pivot_row[c];
    }
  }
  return SolveStatus::kSolved;
}

void BlockPentadiagonalSolver::block_solve4(double* q) const {
  // q is 2n × 4, row-major: node k's rows are q[8k..8k+3] (x) and q[8k+4..8k+7] (y). Each node's
  // eight entries are gathered into a local, its updates applied there (row r's from rows r − 2
  // then r − 1 forward, from rows k + 1 then k + 2 backward: the order of a sweep that subtracts
  // each finished row from the rows after it) and stored once, so the four columns run without
  // reloads through q (which the compiler must otherwise assume each store may change).
  const std::size_t n = n_;
  const auto less = [](double* v, const Mat2& a, const double* qk) {  // v −= a q_k
    const double x0 = qk[0], x1 = qk[1], x2 = qk[2], x3 = qk[3];
    const double y0 = qk[4], y1 = qk[5], y2 = qk[6], y3 = qk[7];
    v[0] -= a.a * x0 + a.b * y0;
    v[1] -= a.a * x1 + a.b * y1;
    v[2] -= a.a * x2 + a.b * y2;
    v[3] -= a.a * x3 + a.b * y3;
    v[4] -= a.c * x0 + a.d * y0;
    v[5] -= a.c * x1 + a.d * y1;
    v[6] -= a.c * x2 + a.d * y2;
    v[7] -= a.c * x3 + a.d * y3;
  };
  for (std::size_t r = 1; r < n; ++r) {
    double v[8];
    std::copy(q + 8 * r, q + 8 * r + 8, v);
    if (r >= 2) less(v, f_[0][r], q + 8 * (r - 2));  // block (r, r − 2)
    less(v, f_[1][r], q + 8 * (r - 1));              // block (r, r − 1)
    std::copy(v, v + 8, q + 8 * r);
  }
  for (std::size_t k = n; k-- > 0;) {
    double v[8];
    double* qk = q + 8 * k;
    std::copy(qk, qk + 8, v);
    if (k + 1 < n) less(v, f_[3][k], q + 8 * (k + 1));  // block (k, k + 1)
    if (k + 2 < n) less(v, f_[4][k], q + 8 * (k + 2));  // block (k, k + 2)
    const Mat2& d = f_[2][k];
    for (std::size_t c = 0; c < 4; ++c) {
      qk[c] = d.a * v[c] + d.b * v[4 + c];
      qk[4 + c] = d.c * v[c] + d.d * v[4 + c];
    }
  }
}

void BlockPentadiagonalSolver::band_solve(double* y) const {
  if (blocked_) {
    // Row by row, each row's updates in the order of the sweep that subtracts each finished row
    // from the rows after it (forward: from rows r − 2 then r − 1; backward: from k + 1 then
    // k + 2), the two rows before carried in locals: the same operations, stored once a row.
    const std::size_t n = n_;
    Vec2 before2{}, before1{y[0], y[1]};  // rows r − 2 and r − 1, finished
    for (std::size_t r = 1; r < n; ++r) {
      Vec2 s{y[2 * r], y[2 * r + 1]};
      if (r >= 2) s = s - f_[0][r] * before2;
      s = s - f_[1][r] * before1;
      y[2 * r] = s.x;
      y[2 * r + 1] = s.y;
      before2 = before1;
      before1 = s;
    }
    Vec2 after1{}, after2{};  // rows k + 1 and k + 2, finished
    for (std::size_t k = n; k-- > 0;) {
      Vec2 s{y[2 * k], y[2 * k + 1]};
      if (k + 1 < n) s = s - f_[3][k] * after1;
      if (k + 2 < n) s = s - f_[4][k] * after2;
      const Vec2 x = f_[2][k] * s;
      y[2 * k] = x.x;
      y[2 * k + 1] = x.y;
      after2 = after1;
      after1 = x;
    }
    return;
  }
  const std::size_t m = m_;
  for (std::size_t k = 0; k < m; ++k) {
    const std::size_t p = piv_[k];
    if (p != k) std::swap(y[k], y[p]);
    const double yk = y[k];
    if (yk == 0.0) continue;
    const std::size_t rmax = std::min(m - 1, k + kLower);
    for (std::size_t r = k + 1; r <= rmax; ++r) y[r] -= lu_[r * kWidth + (k + kLower - r)] * yk;
  }
  for (std::size_t k = m; k-- > 0;) {
    const std::size_t cmax = std::min(m - 1, k + kLower + kUpper);
    const double* row = &lu_[k * kWidth + kLower];  // row[c − k] = U(k, c)
    double s = y[k];
    for (std::size_t c = k + 1; c <= cmax; ++c) s -= row[c - k] * y[c];
    y[k] = s * inv_diag_[k];
  }
}

void BlockPentadiagonalSolver::substitute(std::span<const Vec2> b, std::span<Vec2> x) {
  if (x.size() != n_ || b.size() != n_) throw std::invalid_argument("span of the wrong size");
  const std::size_t n = n_, m = m_;
  for (std::size_t i = 0; i < n; ++i) {
    y_[2 * i] = b[i].x;
    y_[2 * i + 1] = b[i].y;
  }
  band_solve(y_.data());
  if (closure_) {
    double z[4];
    for (std::size_t r = 0; r < 4; ++r) {
      double s = y_[r];
      for (std::size_t k = 0; k < 4; ++k) s += h_[r][k] * y_[m - 4 + k];
      z[r] = s;
    }
    cap_.solve(z);
    // y − Q z, written straight into x
    for (std::size_t i = 0; i < n; ++i) {
      const double* q = &q_[8 * i];
      x[i] = {y_[2 * i] - (q[0] * z[0] + q[1] * z[1] + q[2] * z[2] + q[3] * z[3]),
              y_[2 * i + 1] - (q[4] * z[0] + q[5] * z[1] + q[6] * z[2] + q[7] * z[3])};
    }
    return;
  }
  for (std::size_t i = 0; i < n; ++i) x[i] = {y_[2 * i], y_[2 * i + 1]};
}

void BlockPentadiagonalSolver::substitute(std::span<const Vec2> b, std::span<Vec2> x,
                                          std::span<const Vec2> b2, std::span<Vec2> x2) {
  if (!blocked_) {  // the pivoted band solve: one right-hand side at a time
    substitute(b, x);
    substitute(b2, x2);
    return;
  }
  if (x.size() != n_ || b.size() != n_ || x2.size() != n_ || b2.size() != n_) {
    throw std::invalid_argument("span of the wrong size");
  }
  // Both right-hand sides in one pass over the block factors; per column the same operations in
  // the same order as substitute(b, x), so the results are bit-identical to two calls.
  const std::size_t n = n_, m = m_;
  double* y = y_.data();
  double* w = y2_.data();
  for (std::size_t i = 0; i < n; ++i) {
    y[2 * i] = b[i].x;
    y[2 * i + 1] = b[i].y;
    w[2 * i] = b2[i].x;
    w[2 * i + 1] = b2[i].y;
  }
  Vec2 ybefore2{}, ybefore1{y[0], y[1]}, wbefore2{}, wbefore1{w[0], w[1]};
  for (std::size_t r = 1; r < n; ++r) {
    Vec2 s{y[2 * r], y[2 * r + 1]}, t{w[2 * r], w[2 * r + 1]};
    if (r >= 2) {
      const Mat2& l = f_[0][r];
      s = s - l * ybefore2;
      t = t - l * wbefore2;
    }
    const Mat2& l = f_[1][r];
    s = s - l * ybefore1;
    t = t - l * wbefore1;
    y[2 * r] = s.x;
    y[2 * r + 1] = s.y;
    w[2 * r] = t.x;
    w[2 * r + 1] = t.y;
    ybefore2 = ybefore1;
    ybefore1 = s;
    wbefore2 = wbefore1;
    wbefore1 = t;
  }
  Vec2 yafter1{}, yafter2{}, wafter1{}, wafter2{};
  for (std::size_t k = n; k-- > 0;) {
    Vec2 s{y[2 * k], y[2 * k + 1]}, t{w[2 * k], w[2 * k + 1]};
    if (k + 1 < n) {
      const Mat2& u = f_[3][k];
      s = s - u * yafter1;
      t = t - u * wafter1;
    }
    if (k + 2 < n) {
      const Mat2& u = f_[4][k];
      s = s - u * yafter2;
      t = t - u * wafter2;
    }
    const Vec2 xs = f_[2][k] * s, xt = f_[2][k] * t;
    y[2 * k] = xs.x;
    y[2 * k + 1] = xs.y;
    w[2 * k] = xt.x;
    w[2 * k + 1] = xt.y;
    yafter2 = yafter1;
    yafter1 = xs;
    wafter2 = wafter1;
    wafter1 = xt;
  }
  if (closure_) {
    double z[4], z2[4];
    for (std::size_t r = 0; r < 4; ++r) {
      double s = y[r], t = w[r];
      for (std::size_t k = 0; k < 4; ++k) {
        s += h_[r][k] * y[m - 4 + k];
        t += h_[r][k] * w[m - 4 + k];
      }
      z[r] = s;
      z2[r] = t;
    }
    cap_.solve(z);
    cap_.solve(z2);
    // y − Q z and w − Q z₂, written straight into x and x₂
    for (std::size_t i = 0; i < n; ++i) {
      const double* q = &q_[8 * i];
      x[i] = {y[2 * i] - (q[0] * z[0] + q[1] * z[1] + q[2] * z[2] + q[3] * z[3]),
              y[2 * i + 1] - (q[4] * z[0] + q[5] * z[1] + q[6] * z[2] + q[7] * z[3])};
      x2[i] = {w[2 * i] - (q[0] * z2[0] + q[1] * z2[1] + q[2] * z2[2] + q[3] * z2[3]),
               w[2 * i + 1] - (q[4] * z2[0] + q[5] * z2[1] + q[6] * z2[2] + q[7] * z2[3])};
    }
    return;
  }
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = {y[2 * i], y[2 * i + 1]};
    x2[i] = {w[2 * i], w[2 * i + 1]};
  }
}

}  // namespace catena::dynamics
