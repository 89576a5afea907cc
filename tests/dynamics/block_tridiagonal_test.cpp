// The O(N) block solver against a dense Gaussian elimination with partial pivoting written here,
// on random systems with the chain's structure: symmetric positive definite (mass + assembled
// link stiffnesses, as the integrator builds them) and nonsymmetric diagonally dominant, open
// and cyclic, down to the smallest sizes.
#include "catena/dynamics/block_tridiagonal.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "dense_solve.hpp"

namespace catena::dynamics {
namespace {

constexpr double kRelativeTol = 1e-10;  // max |x − x_dense| / max |x_dense|

using testing::Dense;
using testing::dense_solve;

void put(Dense& a, std::size_t bi, std::size_t bj, const Mat2& m) {
  a[2 * bi][2 * bj] += m.a;
  a[2 * bi][2 * bj + 1] += m.b;
  a[2 * bi + 1][2 * bj] += m.c;
  a[2 * bi + 1][2 * bj + 1] += m.d;
}

Dense to_dense(const BlockTridiagonalSolver& s) {
  const std::size_t n = s.size();
  Dense a(2 * n, std::vector<double>(2 * n, 0.0));
  for (std::size_t i = 0; i < n; ++i) {
    put(a, i, i, s.diag[i]);
    if (i > 0) put(a, i, i - 1, s.lower[i]);
    if (i + 1 < n) put(a, i, i + 1, s.upper[i]);
  }
  if (s.cyclic()) {
    put(a, 0, n - 1, s.lower[0]);
    put(a, n - 1, 0, s.upper[n - 1]);
  }
  return a;
}

// SPD: node masses m_i I (small: stiffness dominated, as at large steps) plus, per link, a random
// SPD 2×2 stiffness K assembled as [K −K; −K K].
void fill_spd(BlockTridiagonalSolver& s, std::mt19937& rng, double mass) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const std::size_t n = s.size();
  for (std::size_t i = 0; i < n; ++i) {
    s.diag[i] = {mass, 0.0, 0.0, mass};
    s.lower[i] = s.upper[i] = {};
  }
  const std::size_t links = s.cyclic() ? n : n - 1;
  for (std::size_t j = 0; j < links; ++j) {
    const double p = u(rng), q = u(rng), r = u(rng);
    const Mat2 k{p * p + 0.1, p * q, p * q, q * q + r * r + 0.1};  // LLᵀ + 0.1 I
    const std::size_t a = j, b = (j + 1) % n;
    for (std::size_t i : {a, b}) {
      s.diag[i] = {s.diag[i].a + k.a, s.diag[i].b + k.b, s.diag[i].c + k.c, s.diag[i].d + k.d};
    }
    s.upper[a] = {-k.a, -k.b, -k.c, -k.d};
    s.lower[b] = {-k.a, -k.b, -k.c, -k.d};
  }
  for (Vec2& v : s.rhs) v = {u(rng), u(rng)};
}

// Nonsymmetric, block diagonally dominant.
void fill_general(BlockTridiagonalSolver& s, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::size_t i = 0; i < s.size(); ++i) {
    s.lower[i] = {u(rng), u(rng), u(rng), u(rng)};
    s.upper[i] = {u(rng), u(rng), u(rng), u(rng)};
    s.diag[i] = {6.0 + u(rng), u(rng), u(rng), 6.0 + u(rng)};
    s.rhs[i] = {u(rng), u(rng)};
  }
}

double relative_error(const BlockTridiagonalSolver& s, const std::vector<Vec2>& x) {
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

TEST(BlockTridiagonal, CyclicSpdMatchesDenseElimination) {
  std::mt19937 rng(21);
  for (std::size_t n : {3u, 4u, 5u, 8u, 17u, 64u, 150u}) {
    for (double mass : {1e-3, 1.0, 100.0}) {
      for (int trial = 0; trial < 5; ++trial) {
        BlockTridiagonalSolver s(n, true);
        fill_spd(s, rng, mass);
        std::vector<Vec2> x(n);
        ASSERT_EQ(s.solve(x), SolveStatus::kSolved) << "n " << n;
        EXPECT_LT(relative_error(s, x), kRelativeTol * (mass < 1e-2 ? 1e3 : 1.0))
            << "n " << n << " mass " << mass;
      }
    }
  }
}

TEST(BlockTridiagonal, OpenSpdMatchesDenseElimination) {
  std::mt19937 rng(7);
  for (std::size_t n : {1u, 2u, 3u, 10u, 101u}) {
    for (int trial = 0; trial < 5; ++trial) {
      BlockTridiagonalSolver s(n, false);
      fill_spd(s, rng, 0.5);
      std::vector<Vec2> x(n);
      ASSERT_EQ(s.solve(x), SolveStatus::kSolved);
      EXPECT_LT(relative_error(s, x), kRelativeTol) << "n " << n;
    }
  }
}

TEST(BlockTridiagonal, NonsymmetricCyclicAndOpenMatchDenseElimination) {
  std::mt19937 rng(3);
  for (bool cyclic : {false, true}) {
    for (std::size_t n : {3u, 6u, 40u}) {
      BlockTridiagonalSolver s(n, cyclic);
      fill_general(s, rng);
      std::vector<Vec2> x(n);
      ASSERT_EQ(s.solve(x), SolveStatus::kSolved);
      EXPECT_LT(relative_error(s, x), kRelativeTol) << "n " << n << " cyclic " << cyclic;
    }
  }
}

// One factorisation, several right-hand sides (what the integrator does for driven wheels).
TEST(BlockTridiagonal, FactorOnceSubstituteMany) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (bool cyclic : {false, true}) {
    BlockTridiagonalSolver s(20, cyclic);
    fill_spd(s, rng, 0.3);
    ASSERT_EQ(s.factor(), SolveStatus::kSolved);
    for (int k = 0; k < 3; ++k) {
      std::vector<Vec2> b(20), x(20);
      for (Vec2& v : b) v = {u(rng), u(rng)};
      s.substitute(b, x);
      s.rhs = b;  // relative_error reads the right-hand side from the solver
      EXPECT_LT(relative_error(s, x), kRelativeTol) << "cyclic " << cyclic << " rhs " << k;
    }
  }
}

// Two right-hand sides in one pass give bit for bit what two single substitutions give.
TEST(BlockTridiagonal, PairedSubstitutionEqualsTwoSingleOnes) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (bool cyclic : {false, true}) {
    for (std::size_t n : {3u, 4u, 31u}) {
      BlockTridiagonalSolver s(n, cyclic);
      fill_general(s, rng);
      ASSERT_EQ(s.factor(), SolveStatus::kSolved);
      std::vector<Vec2> b2(n), x1(n), x2(n), p1(n), p2(n);
      for (Vec2& v : b2) v = {u(rng), u(rng)};
      s.substitute(s.rhs, x1);
      s.substitute(b2, x2);
      s.substitute(s.rhs, p1, b2, p2);
      for (std::size_t i = 0; i < n; ++i) {
        EXPECT_EQ(p1[i].x, x1[i].x) << "n " << n << " cyclic " << cyclic << " row " << i;
        EXPECT_EQ(p1[i].y, x1[i].y) << "n " << n << " cyclic " << cyclic << " row " << i;
        EXPECT_EQ(p2[i].x, x2[i].x) << "n " << n << " cyclic " << cyclic << " row " << i;
        EXPECT_EQ(p2[i].y, x2[i].y) << "n " << n << " cyclic " << cyclic << " row " << i;
      }
      s.rhs = b2;  // and the second is a solution of its own system
      EXPECT_LT(relative_error(s, p2), kRelativeTol) << "n " << n << " cyclic " << cyclic;
    }
  }
}

// factor_forward + finish is factor + substitute, bit for bit (one and two right-hand sides, open
// and cyclic, SPD and nonsymmetric), and the factors it leaves serve substitute() as factor()'s do.
TEST(BlockTridiagonal, FusedFactorAndForwardSweepEqualsFactorThenSubstitute) {
  std::mt19937 rng(29);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto expect_same = [](const std::vector<Vec2>& p, const std::vector<Vec2>& q,
                        const std::string& what) {
    for (std::size_t i = 0; i < p.size(); ++i) {
      EXPECT_EQ(p[i].x, q[i].x) << what << " row " << i;
      EXPECT_EQ(p[i].y, q[i].y) << what << " row " << i;
    }
  };
  for (bool cyclic : {false, true}) {
    for (bool spd : {false, true}) {
      for (std::size_t n : {1u, 2u, 3u, 4u, 31u, 200u}) {
        if (cyclic && n < 3) continue;
        const std::string what = "n " + std::to_string(n) + " cyclic " + std::to_string(cyclic) +
                                 " spd " + std::to_string(spd);
        BlockTridiagonalSolver s(n, cyclic), f(n, cyclic);
        if (spd) {
          fill_spd(s, rng, 0.01);
        } else {
          fill_general(s, rng);
        }
        f.lower = s.lower;
        f.diag = s.diag;
        f.upper = s.upper;
        f.rhs = s.rhs;
        std::vector<Vec2> b2(n), b3(n), x1(n), x2(n), x3(n), p1(n), p2(n), q1(n), q3(n);
        for (Vec2& v : b2) v = {u(rng), u(rng)};
        for (Vec2& v : b3) v = {u(rng), u(rng)};
        ASSERT_EQ(s.factor(), SolveStatus::kSolved) << what;
        s.substitute(s.rhs, x1, b2, x2);
        s.substitute(b3, x3);
        ASSERT_EQ(f.factor_forward(f.rhs, b2), SolveStatus::kSolved) << what;
        f.finish(p1, p2);
        expect_same(p1, x1, what + " first");
        expect_same(p2, x2, what + " second");
        f.substitute(b3, q3);  // the factors left behind
        expect_same(q3, x3, what + " factors");
        ASSERT_EQ(f.factor_forward(b3, {}), SolveStatus::kSolved) << what;
        f.finish(q1, {});
        expect_same(q1, x3, what + " one right-hand side");
        EXPECT_LT(relative_error(f, p1), kRelativeTol) << what;
      }
    }
  }
  BlockTridiagonalSolver z(5, true);  // all blocks zero: reported, as by factor()
  EXPECT_EQ(z.factor_forward(z.rhs, {}), SolveStatus::kSingularPivot);
  std::vector<Vec2> wrong(4);
  EXPECT_THROW(z.factor_forward(wrong, {}), std::invalid_argument);
  EXPECT_THROW(z.factor_forward(z.rhs, wrong), std::invalid_argument);
  std::vector<Vec2> x5(5);
  EXPECT_THROW(z.finish(x5, {}), std::logic_error);  // the failed call left nothing to finish
  // a solve begun by factor_forward() is finished only while its workspace is its own
  std::mt19937 rng_g(5);
  BlockTridiagonalSolver g(6, true);
  fill_spd(g, rng_g, 1.0);
  std::vector<Vec2> x6(6), other(6);
  EXPECT_THROW(g.finish(x6, {}), std::logic_error);  // none begun
  ASSERT_EQ(g.factor_forward(g.rhs, {}), SolveStatus::kSolved);
  g.finish(x6, {});
  g.substitute(g.rhs, other);
  EXPECT_THROW(g.finish(x6, {}), std::logic_error);  // substitute() overwrote the workspace
  ASSERT_EQ(g.factor_forward(g.rhs, {}), SolveStatus::kSolved);
  ASSERT_EQ(g.factor(), SolveStatus::kSolved);
  EXPECT_THROW(g.finish(x6, {}), std::logic_error);  // so did factor()
}

// The corner blocks matter: a cyclic solve differs from the open solve of the same blocks.
TEST(BlockTridiagonal, ClosureChangesTheSolution) {
  std::mt19937 rng(11);
  BlockTridiagonalSolver cyc(12, true), open(12, false);
  fill_spd(cyc, rng, 1.0);
  open.lower = cyc.lower;
  open.diag = cyc.diag;
  open.upper = cyc.upper;
  open.rhs = cyc.rhs;
  std::vector<Vec2> xc(12), xo(12);
  ASSERT_EQ(cyc.solve(xc), SolveStatus::kSolved);
  ASSERT_EQ(open.solve(xo), SolveStatus::kSolved);
  double diff = 0.0;
  for (std::size_t i = 0; i < 12; ++i) diff = std::max(diff, std::abs(xc[i].x - xo[i].x));
  EXPECT_GT(diff, 1e-3);
}

TEST(BlockTridiagonal, SingularSystemIsReportedNotSolved) {
  BlockTridiagonalSolver s(5, true);  // all blocks zero
  std::vector<Vec2> x(5);
  EXPECT_EQ(s.solve(x), SolveStatus::kSingularPivot);
  BlockTridiagonalSolver o(4, false);
  std::vector<Vec2> y(4);
  EXPECT_EQ(o.solve(y), SolveStatus::kSingularPivot);
}

TEST(BlockTridiagonal, RejectsTooSmallCyclicSystems) {
  EXPECT_THROW(BlockTridiagonalSolver(2, true), std::invalid_argument);
  EXPECT_THROW(BlockTridiagonalSolver(0, false), std::invalid_argument);
}

}  // namespace
}  // namespace catena::dynamics
