// Linear systems with the structure of a chain whose hinges carry friction: block pentadiagonal
// with 2×2 node blocks, cyclic for a closed loop (docs/models/dynamics.md, "Solver").
//
// A hinge couple acts on three nodes (i − 1, i, i + 1), so its exact Jacobian couples nodes two
// apart; with the rate, load and direction terms it is not symmetric, and it need not be
// definite. So this solver does not rely on either:
//
// - the band (A without the cyclic corners) is factored by block LU without pivoting (2×2 pivot
//   blocks, no fill outside the band) as long as every pivot block is well conditioned and not
//   small against the matrix — the chain's Newton matrices, whose symmetric part is positive
//   definite (mass, links in tension, the hinges' rate term c g gᵀ; the nonsymmetric load and
//   direction terms are small against it), for which LU without pivoting exists and is stable
//   (Golub & Van Loan, Matrix Computations, 4th ed., §4.2, positive definite systems, incl. the
//   unsymmetric case); otherwise by band Gaussian elimination with partial pivoting over the 2n
//   scalar unknowns, lower and upper bandwidth 5 (U's grows to 10 by the row interchanges), in
//   O(n) too (Golub & Van Loan §4.3, band Gaussian elimination with pivoting; the storage and the
//   interleaved application of the interchanges are LAPACK's dgbtrf/dgbtrs);
// - a closed loop's corners (nodes 0, 1 against n − 2, n − 1: a 4×4 scalar block each way) are
//   split off as a rank-4 update A = T + W Zᵀ, W = [G; 0; C_bl], Zᵀ = [I, 0, G⁻¹ C_tr], with
//   G = −A_tl (the top-left 4×4 of A): the four-column form of the block tridiagonal solver's
//   closure (block_tridiagonal.hpp; Press et al., Numerical Recipes §2.7), and the
//   Sherman–Morrison–Woodbury formula (Golub & Van Loan, §2.1)
//     A⁻¹b = y − Q (I + Zᵀ Q)⁻¹ Zᵀ y,   y = T⁻¹ b,  Q = T⁻¹ W,
//   with the 4×4 capacitance I + Zᵀ Q and A_tl factored by Gaussian elimination with partial
//   pivoting.
//
// Nothing is allocated by factor() or substitute(): the workspace is sized by the constructor.
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "catena/dynamics/block_tridiagonal.hpp"
#include "catena/dynamics/small_lu.hpp"

namespace catena::dynamics {

class BlockPentadiagonalSolver {
 public:
  /// A system of `n` block rows; cyclic needs n ≥ 3, open n ≥ 1 (throws std::invalid_argument).
  BlockPentadiagonalSolver(std::size_t n, bool cyclic);

  std::size_t size() const { return n_; }
  bool cyclic() const { return cyclic_; }

  /// band[o + 2][i] is the block (i, i + o), o in −2..2; on a cyclic system the column is taken
  /// modulo n (where two offsets name the same column, at n = 3 or 4, the blocks add up); on an
  /// open one blocks whose column falls outside 0..n − 1 are ignored. Filled by the caller.
  std::array<std::vector<Mat2>, 5> band;
  std::vector<Vec2> rhs;  ///< the right-hand side, filled by the caller

  /// Factors the blocks (and, for a cyclic system, solves for the closure's four columns). The
  /// blocks are left unchanged.
  SolveStatus factor();
  /// Solves for a right-hand side b with the last successful factor(); b may alias rhs.
  void substitute(std::span<const Vec2> b, std::span<Vec2> x);
  /// Two right-hand sides (the same arithmetic as two calls of substitute).
  void substitute(std::span<const Vec2> b, std::span<Vec2> x, std::span<const Vec2> b2,
                  std::span<Vec2> x2);
  /// Whether the last factor() took the pivoted scalar elimination (a 2×2 pivot block of the
  /// block LU was too small or ill conditioned) rather than the block LU.
  bool pivoted() const { return !blocked_; }
  /// factor() then substitute(rhs, x).
  SolveStatus solve(std::span<Vec2> x);

 private:
  static constexpr int kLower = 5, kUpper = 5;            // scalar bandwidths of A's band
  static constexpr int kWidth = 2 * kLower + kUpper + 1;  // stored columns per row (with fill)
  double& at(std::size_t r, std::size_t c) { return lu_[r * kWidth + (c + kLower - r)]; }
  double& element(std::size_t r, std::size_t c);  // T's scalar entry (r, c), |r/2 − c/2| ≤ 2
  bool block_factor();                            // false: a pivot block too small, pivot
  SolveStatus pivoted_factor();
  void band_solve(double* y) const;    // y ← T⁻¹ y with the band factors
  void block_solve4(double* q) const;  // q ← T⁻¹ q, four columns, with the block factors

  std::size_t n_, m_;  // block rows, scalar rows (2 n)
  bool cyclic_, closure_, blocked_ = true;
  // T = A − W Zᵀ without its corners, in blocks: t_[o + 2][i] = (i, i + o) with 0 ≤ i + o < n;
  // f_ its block LU factors (no pivoting)
  std::array<std::vector<Mat2>, 5> t_, f_;
  std::vector<double> lu_, inv_diag_;
  std::vector<std::size_t> piv_;
  // the closure: corners C_tr (rows 0..3, columns m − 4..m − 1) and C_bl (rows m − 4..m − 1,
  // columns 0..3), H = G⁻¹ C_tr = −A_tl⁻¹ C_tr, Q = T⁻¹ W (m × 4, row-major), the capacitance's
  // LU and pivots
  double ctr_[4][4] = {}, cbl_[4][4] = {}, h_[4][4] = {};
  SmallLu cap_;
  std::vector<double> q_, y_, y2_;
};

}  // namespace catena::dynamics
