// The O(N) block pentadiagonal solver (cyclic or open) against a dense Gaussian elimination with
// partial pivoting written here, on random systems with the structure of a chain with hinge
// friction: nonsymmetric and diagonally dominant, nonsymmetric and indefinite with zero diagonal
// entries (pivoting needed), and mass + link stiffness + hinge couples (three-node rank-one terms
// g tᵀ with t ≠ g, as the exact hinge Jacobian has); N even and odd, down to 3, 4 and 5.
#include "catena/dynamics/block_pentadiagonal.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "dense_solve.hpp"

namespace catena::dynamics {
namespace {

using testing::Dense;
using testing::dense_solve;

// The dense matrix the bands describe, built from the header's definition (column i + o, taken
// modulo n on a cyclic system; blocks naming the same column add up).
Dense to_dense(const BlockPentadiagonalSolver& s) {
  const long n = static_cast<long>(s.size());
  Dense a(2 * s.size(), std::vector<double>(2 * s.size(), 0.0));
  for (long o = -2; o <= 2; ++o) {
    for (long i = 0; i < n; ++i) {
      long j = i + o;
      if (!s.cyclic() && (j < 0 || j >= n)) continue;
      j = (j + n) % n;
      const Mat2& m = s.band[static_cast<std::size_t>(o + 2)][static_cast<std::size_t>(i)];
      a[2 * i][2 * j] += m.a;
      a[2 * i][2 * j + 1] += m.b;
      a[2 * i + 1][2 * j] += m.c;
      a[2 * i + 1][2 * j + 1] += m.d;
    }
  }
  return a;
}

double relative_error(const BlockPentadiagonalSolver& s, const std::vector<Vec2>& x) {
  std::vector<double> b(2 * s.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    b[2 * i] = s.rhs[i].x;
    b[2 * i + 1] = s.rhs[i].y;
  }
  const std::vector<double> ref = dense_solve(to_dense(s), b);
  double err = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    err = std::max({err, std::abs(x[i].x - ref[2 * i]), std::abs(x[i].y - ref[2 * i + 1])});
    scale = std::max({scale, std::abs(ref[2 * i]), std::abs(ref[2 * i + 1])});
  }
  return err / scale;
}

Mat2 random_block(std::mt19937& rng, double spread) {
  std::uniform_real_distribution<double> u(-spread, spread);
  return {u(rng), u(rng), u(rng), u(rng)};
}

void fill_rhs(BlockPentadiagonalSolver& s, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (Vec2& v : s.rhs) v = {u(rng), u(rng)};
}

// Nonsymmetric, block diagonally dominant.
void fill_dominant(BlockPentadiagonalSolver& s, std::mt19937& rng) {
  for (std::size_t o = 0; o < 5; ++o) {
    for (Mat2& m : s.band[o]) m = random_block(rng, 1.0);
  }
  for (Mat2& m : s.band[2]) m = {m.a + 10.0, m.b, m.c, m.d + 10.0};
  fill_rhs(s, rng);
}

// Nonsymmetric and indefinite, with zero diagonal entries: no factorisation without pivoting.
void fill_indefinite(BlockPentadiagonalSolver& s, std::mt19937& rng) {
  for (std::size_t o = 0; o < 5; ++o) {
    for (Mat2& m : s.band[o]) m = random_block(rng, 1.0);
  }
  for (Mat2& m : s.band[2]) m = {0.0, 3.0 + m.b, -3.0 + m.c, 0.0};
  fill_rhs(s, rng);
}

// A chain's Newton matrix with hinge friction: mass (m I), per link a symmetric stiffness
// [K −K; −K K], per hinge the three-node term c g tᵀ (g, t random with zero sum, t ≠ g: the
// exact hinge Jacobian's shape) added to blocks (i − 1..i + 1) × (i − 1..i + 1).
void fill_chain(BlockPentadiagonalSolver& s, std::mt19937& rng, double mass, double hinge) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const std::size_t n = s.size();
  for (std::size_t o = 0; o < 5; ++o) {
    for (Mat2& m : s.band[o]) m = {};
  }
  for (Mat2& m : s.band[2]) m = {mass, 0.0, 0.0, mass};
  auto add = [&](std::size_t i, long o, const Mat2& d) {
    Mat2& m = s.band[static_cast<std::size_t>(o + 2)][i];
    m = {m.a + d.a, m.b + d.b, m.c + d.c, m.d + d.d};
  };
  const std::size_t links = s.cyclic() ? n : n - 1;
  for (std::size_t j = 0; j < links; ++j) {
    const double p = u(rng), q = u(rng), r = u(rng);
    const Mat2 k{p * p + 0.1, p * q, p * q, q * q + r * r + 0.1};
    add(j, 0, k);
    add((j + 1) % n, 0, k);
    add(j, 1, {-k.a, -k.b, -k.c, -k.d});
    add((j + 1) % n, -1, {-k.a, -k.b, -k.c, -k.d});
  }
  const std::size_t first = s.cyclic() ? 0 : 1, last = s.cyclic() ? n : n - 1;
  for (std::size_t i = first; i < last; ++i) {
    double gx[3], gy[3], tx[3], ty[3];
    gx[0] = u(rng), gy[0] = u(rng), gx[2] = u(rng), gy[2] = u(rng);
    gx[1] = -gx[0] - gx[2], gy[1] = -gy[0] - gy[2];
    tx[0] = gx[0] + 0.3 * u(rng), ty[0] = gy[0] + 0.3 * u(rng);
    tx[2] = gx[2] + 0.3 * u(rng), ty[2] = gy[2] + 0.3 * u(rng);
    tx[1] = -tx[0] - tx[2], ty[1] = -ty[0] - ty[2];
    const std::size_t node[3] = {(i + n - 1) % n, i, (i + 1) % n};
    for (int a = 0; a < 3; ++a) {
      for (int b = 0; b < 3; ++b) {
        add(node[a], b - a,
            {hinge * gx[a] * tx[b], hinge * gx[a] * ty[b], hinge * gy[a] * tx[b],
             hinge * gy[a] * ty[b]});
      }
    }
  }
  fill_rhs(s, rng);
}

constexpr std::size_t kSizes[] = {3, 4, 5, 6, 7, 8, 9, 17, 64, 151, 200};

TEST(BlockPentadiagonal, DominantMatchesDenseEliminationCyclicAndOpen) {
  std::mt19937 rng(2101);
  for (bool cyclic : {true, false}) {
    for (std::size_t n : kSizes) {
      for (int trial = 0; trial < 4; ++trial) {
        BlockPentadiagonalSolver s(n, cyclic);
        fill_dominant(s, rng);
        std::vector<Vec2> x(n);
        ASSERT_EQ(s.solve(x), SolveStatus::kSolved) << "n " << n;
        EXPECT_LT(relative_error(s, x), 1e-12) << "n " << n << " cyclic " << cyclic;
      }
    }
  }
  for (std::size_t n : {1u, 2u}) {  // open systems below the band's width
    BlockPentadiagonalSolver s(n, false);
    fill_dominant(s, rng);
    std::vector<Vec2> x(n);
    ASSERT_EQ(s.solve(x), SolveStatus::kSolved);
    EXPECT_LT(relative_error(s, x), 1e-12) << "n " << n;
  }
}

TEST(BlockPentadiagonal, IndefiniteWithZeroDiagonalNeedsAndGetsPivoting) {
  std::mt19937 rng(2102);
  for (bool cyclic : {true, false}) {
    for (std::size_t n : kSizes) {
      for (int trial = 0; trial < 4; ++trial) {
        BlockPentadiagonalSolver s(n, cyclic);
        fill_indefinite(s, rng);
        std::vector<Vec2> x(n);
        ASSERT_EQ(s.solve(x), SolveStatus::kSolved) << "n " << n;
        EXPECT_LT(relative_error(s, x), 1e-9) << "n " << n << " cyclic " << cyclic;
      }
    }
  }
}

TEST(BlockPentadiagonal, ZeroPivotBlocksFallBackToPivotedElimination) {
  // every third diagonal block zero (and the rest of the matrix random): the block LU's pivot
  // block at node 0 is singular, so the pivoted elimination takes over
  std::mt19937 rng(2106);
  for (bool cyclic : {true, false}) {
    for (std::size_t n : kSizes) {
      for (int trial = 0; trial < 4; ++trial) {
        BlockPentadiagonalSolver s(n, cyclic);
        fill_indefinite(s, rng);
        for (std::size_t i = 0; i < n; i += 3) s.band[2][i] = {};
        std::vector<Vec2> x(n);
        ASSERT_EQ(s.solve(x), SolveStatus::kSolved) << "n " << n;
        EXPECT_TRUE(s.pivoted()) << "n " << n;
        EXPECT_LT(relative_error(s, x), 1e-9) << "n " << n << " cyclic " << cyclic;
      }
    }
  }
}

TEST(BlockPentadiagonal, ChainWithHingeTermsMatchesDenseElimination) {
  std::mt19937 rng(2103);
  for (bool cyclic : {true, false}) {
    for (std::size_t n : kSizes) {
      for (double mass : {1e-2, 1.0, 100.0}) {
        for (double hinge : {0.5, 5.0}) {
          BlockPentadiagonalSolver s(n, cyclic);
          fill_chain(s, rng, mass, hinge);
          std::vector<Vec2> x(n);
          ASSERT_EQ(s.solve(x), SolveStatus::kSolved) << "n " << n;
          EXPECT_FALSE(s.pivoted()) << "n " << n;
          EXPECT_LT(relative_error(s, x), 1e-10)
              << "n " << n << " cyclic " << cyclic << " mass " << mass << " hinge " << hinge;
        }
      }
    }
  }
}

TEST(BlockPentadiagonal, SecondRightHandSideReusesTheFactorsAndAliasingIsAllowed) {
  std::mt19937 rng(2104);
  for (std::size_t n : {4u, 5u, 30u}) {
    BlockPentadiagonalSolver s(n, true);
    fill_chain(s, rng, 1.0, 2.0);
    ASSERT_EQ(s.factor(), SolveStatus::kSolved);
    std::vector<Vec2> x(n), x2(n), other(n);
    for (Vec2& v : other) v = {0.5, -0.25};
    s.substitute(s.rhs, x, other, x2);
    EXPECT_LT(relative_error(s, x), 1e-10);
    s.rhs = other;
    EXPECT_LT(relative_error(s, x2), 1e-10);
    s.substitute(s.rhs, s.rhs);  // in place
    for (std::size_t i = 0; i < n; ++i) {
      EXPECT_EQ(s.rhs[i].x, x2[i].x);
      EXPECT_EQ(s.rhs[i].y, x2[i].y);
    }
  }
}

TEST(BlockPentadiagonal, TwoRightHandSidesInOnePassEqualTwoSingleSolvesBitForBit) {
  // the fused two-right-hand-side substitution does per column the single one's arithmetic in
  // the same order: the results must be equal bit for bit, on the block LU and on the pivoted path
  std::mt19937 rng(77);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (bool cyclic : {true, false}) {
    for (std::size_t n : {3u, 4u, 5u, 9u, 40u}) {
      for (int pivot = 0; pivot < 2; ++pivot) {
        BlockPentadiagonalSolver s(n, cyclic);
        if (pivot == 0) {
          fill_chain(s, rng, 1.0, 2.0);
        } else {  // zero pivot blocks: the pivoted elimination
          fill_indefinite(s, rng);
          for (std::size_t i = 0; i < n; i += 3) s.band[2][i] = {};
        }
        ASSERT_EQ(s.factor(), SolveStatus::kSolved);
        EXPECT_EQ(s.pivoted(), pivot == 1);
        std::vector<Vec2> b(n), b2(n), x(n), x2(n), y(n), y2(n);
        for (std::size_t i = 0; i < n; ++i) {
          b[i] = {u(rng), u(rng)};
          b2[i] = {u(rng), u(rng)};
        }
        s.substitute(b, x, b2, x2);
        s.substitute(b, y);
        s.substitute(b2, y2);
        for (std::size_t i = 0; i < n; ++i) {
          EXPECT_EQ(x[i].x, y[i].x);
          EXPECT_EQ(x[i].y, y[i].y);
          EXPECT_EQ(x2[i].x, y2[i].x);
          EXPECT_EQ(x2[i].y, y2[i].y);
        }
      }
    }
  }
}

TEST(BlockPentadiagonal, RefactoringTheSameSolverWithNewBlocksMatchesDenseElimination) {
  // the integrator refactors one solver every step: the second factor() must not keep anything
  // of the first one's blocks (a closed loop of 3 or 4 nodes adds wrapped blocks onto places of
  // the band, so those start from zero again; from n = 5 on each place is written once). Every
  // kind of fill follows every kind: dominant, indefinite, and zero pivot blocks (pivoted)
  enum class Fill { kDominant, kIndefinite, kZeroPivots };
  std::mt19937 rng(2107);
  auto fill = [&rng](BlockPentadiagonalSolver& s, Fill kind) {
    if (kind == Fill::kDominant) {
      fill_dominant(s, rng);
      return;
    }
    fill_indefinite(s, rng);
    if (kind == Fill::kZeroPivots) {
      for (std::size_t i = 0; i < s.size(); i += 3) s.band[2][i] = {};
    }
  };
  const Fill kinds[] = {Fill::kDominant, Fill::kIndefinite, Fill::kZeroPivots};
  for (bool cyclic : {true, false}) {
    for (std::size_t n = 3; n <= 12; ++n) {
      for (Fill first : kinds) {
        for (Fill second : kinds) {
          BlockPentadiagonalSolver s(n, cyclic);
          std::vector<Vec2> x(n);
          fill(s, first);
          ASSERT_EQ(s.solve(x), SolveStatus::kSolved) << "n " << n;
          fill(s, second);
          ASSERT_EQ(s.solve(x), SolveStatus::kSolved) << "n " << n;
          if (second == Fill::kZeroPivots) {
            EXPECT_TRUE(s.pivoted()) << "n " << n;
          }
          EXPECT_LT(relative_error(s, x), second == Fill::kDominant ? 1e-12 : 1e-9)
              << "n " << n << " cyclic " << cyclic << " fills " << static_cast<int>(first)
              << " then " << static_cast<int>(second);
        }
      }
    }
  }
}

TEST(BlockPentadiagonal, SingularSystemIsReportedNotSolved) {
  BlockPentadiagonalSolver open(6, false);  // all zero
  std::vector<Vec2> x(6);
  EXPECT_EQ(open.solve(x), SolveStatus::kSingularPivot);
  BlockPentadiagonalSolver cyclic(6, true);
  EXPECT_EQ(cyclic.solve(x), SolveStatus::kSingularPivot);
  EXPECT_THROW(BlockPentadiagonalSolver(2, true), std::invalid_argument);
  EXPECT_THROW(BlockPentadiagonalSolver(0, false), std::invalid_argument);
}

}  // namespace
}  // namespace catena::dynamics
