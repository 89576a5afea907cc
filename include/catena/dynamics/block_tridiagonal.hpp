// Linear systems with the chain's structure: block tridiagonal with 2×2 blocks, cyclic for a
// closed loop (docs/models/dynamics.md, "Solver").
//
// Row i of the matrix holds lower[i] (column i − 1), diag[i] (column i) and upper[i] (column
// i + 1). A cyclic system also has the two corner blocks lower[0] (row 0, column n − 1) and
// upper[n − 1] (row n − 1, column 0); an open one ignores them.
//
// Open: block Thomas (block LU without pivoting), O(n). Cyclic: the corners are split off as a
// rank-2 update A = T + W Zᵀ chosen so that T stays symmetric positive definite when A is
// (the block form of the cyclic tridiagonal algorithm, Press et al., Numerical Recipes §2.7), T is
// solved by block Thomas for the right-hand side and for W's two columns at once, and the
// Sherman–Morrison–Woodbury formula (Sherman & Morrison 1950; Woodbury 1950)
//   A⁻¹b = y − Q (I + Zᵀ Q)⁻¹ Zᵀ y,   y = T⁻¹ b,  Q = T⁻¹ W
// closes the loop: O(n) too. Using the structure of the chain's equations to reach linear time is
// the idea of Baraff (1996), "Linear-time dynamics using Lagrange multipliers", SIGGRAPH '96.
//
// Nothing is allocated by solve(): the workspace is sized by the constructor.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace catena::dynamics {

struct Vec2 {
  double x = 0.0, y = 0.0;
};

/// A 2×2 matrix [[a, b], [c, d]].
struct Mat2 {
  double a = 0.0, b = 0.0, c = 0.0, d = 0.0;
};

// The block solvers' 2×2 arithmetic (block_tridiagonal.cpp, block_pentadiagonal.cpp).
inline Mat2 operator*(const Mat2& p, const Mat2& q) {
  return {p.a * q.a + p.b * q.c, p.a * q.b + p.b * q.d, p.c * q.a + p.d * q.c,
          p.c * q.b + p.d * q.d};
}
inline Vec2 operator*(const Mat2& p, Vec2 v) {
  return {p.a * v.x + p.b * v.y, p.c * v.x + p.d * v.y};
}
inline Mat2 operator-(const Mat2& p, const Mat2& q) {
  return {p.a - q.a, p.b - q.b, p.c - q.c, p.d - q.d};
}
inline Mat2 operator+(const Mat2& p, const Mat2& q) {
  return {p.a + q.a, p.b + q.b, p.c + q.c, p.d + q.d};
}
inline Vec2 operator-(Vec2 p, Vec2 q) { return {p.x - q.x, p.y - q.y}; }
inline Vec2 operator+(Vec2 p, Vec2 q) { return {p.x + q.x, p.y + q.y}; }

/// Why a solve stopped.
enum class SolveStatus {
  kSolved,
  kSingularPivot,  ///< a 2×2 pivot block (of T or of the closure's capacitance) was singular
};

class BlockTridiagonalSolver {
 public:
  /// A system of `n` block rows; cyclic needs n ≥ 3, open n ≥ 1 (throws std::invalid_argument).
  BlockTridiagonalSolver(std::size_t n, bool cyclic);

  std::size_t size() const { return n_; }
  bool cyclic() const { return cyclic_; }

  std::vector<Mat2> lower, diag, upper;  ///< the blocks, filled by the caller
  std::vector<Vec2> rhs;                 ///< the right-hand side, filled by the caller

  /// Solves the system into x (size n): factor() then substitute(rhs, x). The blocks and rhs
  /// are left unchanged.
  SolveStatus solve(std::span<Vec2> x);

  /// Factors the blocks (and, for a cyclic system, solves for the closure's two columns).
  SolveStatus factor();
  /// Solves for another right-hand side b with the last successful factor(); b may alias rhs.
  void substitute(std::span<const Vec2> b, std::span<Vec2> x);
  /// Two right-hand sides in one pass over the factors: the same arithmetic as two calls of
  /// substitute (bit for bit), but the two recurrences run side by side (each row's chain of
  /// dependent 2×2 products is latency-bound; two independent ones fill the pipeline).
  void substitute(std::span<const Vec2> b, std::span<Vec2> x, std::span<const Vec2> b2,
                  std::span<Vec2> x2);

  /// factor() with the forward sweeps (and, for a cyclic system, the closure's back sweep) of
  /// the substitution for b, and for b2 unless it is empty, in the same passes over the blocks;
  /// finish() then completes the solve. The same arithmetic as factor() followed by
  /// substitute(b, x) or substitute(b, x, b2, x2), bit for bit, with one pass over the factors
  /// fewer in each direction. Leaves the factors for substitute() as factor() does.
  SolveStatus factor_forward(std::span<const Vec2> b, std::span<const Vec2> b2);
  /// The rest of the solve begun by the last successful factor_forward(): x (and x2 when that
  /// call had a second right-hand side; x2 is ignored otherwise). Throws std::logic_error when
  /// there is no such solve to finish: no factor_forward() yet, the last one failed, or a
  /// factor() or substitute() has run since (they overwrite the workspace finish() reads).
  void finish(std::span<Vec2> x, std::span<Vec2> x2);

 private:
  template <bool kTwo>
  SolveStatus factor_forward(const Vec2* b, const Vec2* b2);

  std::size_t n_;
  bool cyclic_;
  // the factors: S_i⁻¹ and C'_i = S_i⁻¹ U_i; for a cyclic system Q = T⁻¹ W, (I + Zᵀ Q)⁻¹ and
  // G⁻¹ L_0; y_ is the substitution's workspace
  std::vector<Mat2> s_inv_, c_prime_, w_;
  std::vector<Vec2> y_, y2_;
  Mat2 cap_inv_, h_;
  bool two_ = false;      // the last factor_forward() had a second right-hand side
  bool pending_ = false;  // a successful factor_forward()'s solve is left for finish()
};

}  // namespace catena::dynamics
