// The hinges' friction couple (include/catena/dynamics/hinge_friction.hpp; docs/models/dynamics.md,
// "Hinges"): its forces against finite differences of the relative angle it is defined by, the
// couple's resultant and moment, its work, and the work balance of a chain with hinge friction.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <random>

#include "catena/dynamics/integrator.hpp"
#include "catena/hinge/kinematics.hpp"

namespace catena::dynamics {
namespace {

// A closed loop of n nodes a pitch p apart on its polygon's circle, spinning at omega, each node
// with a radial speed of ±wobble alternately (0: a rigid spin).
State spinning_ring(std::size_t n, double p, double omega, double wobble) {
  const double radius = p / (2 * std::sin(M_PI / static_cast<double>(n)));
  State s(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = 2 * M_PI * static_cast<double>(i) / static_cast<double>(n);
    s.x[i] = radius * std::cos(a);
    s.y[i] = radius * std::sin(a);
    const double radial = (i % 2 ? wobble : -wobble);  // [m/s]
    s.vx[i] = -omega * s.y[i] + radial * std::cos(a);
    s.vy[i] = omega * s.x[i] + radial * std::sin(a);
  }
  return s;
}

// β: the angle of link (1 → 2) less the angle of link (0 → 1), in (−π, π].
double relative_angle(const double x[3], const double y[3]) {
  const double ax = x[1] - x[0], ay = y[1] - y[0], bx = x[2] - x[1], by = y[2] - y[1];
  return std::atan2(ax * by - ay * bx, ax * bx + ay * by);
}

struct Pose {
  double x0[3], y0[3], x1[3], y1[3];
};

// Three nodes about a pitch apart at random angles, and a small random step.
// Links of 82 and 46 mm (directions 0.3 and 0.9 rad) from the origin, the hinge turning a little
// over the step (the last node moves by 1 µm).
Pose round_link_pose() {
  const double a = 0.3, b = 0.9;  // the links' directions
  Pose p{};
  p.x0[1] = 0.082 * std::cos(a);
  p.y0[1] = 0.082 * std::sin(a);
  p.x0[2] = p.x0[1] + 0.046 * std::cos(b);
  p.y0[2] = p.y0[1] + 0.046 * std::sin(b);
  for (int k = 0; k < 3; ++k) p.x1[k] = p.x0[k], p.y1[k] = p.y0[k];
  p.x1[2] += 1e-6;
  return p;
}

Pose random_pose(std::mt19937& rng, double pitch, double move) {
  std::uniform_real_distribution<double> angle(-3.0, 3.0), turn(-0.6, 0.6), stretch(0.995, 1.005),
      d(-move, move);
  Pose p{};
  const double a = angle(rng), b = a + turn(rng);
  p.x0[0] = d(rng);
  p.y0[0] = d(rng);
  p.x0[1] = p.x0[0] + pitch * stretch(rng) * std::cos(a);
  p.y0[1] = p.y0[0] + pitch * stretch(rng) * std::sin(a);
  p.x0[2] = p.x0[1] + pitch * stretch(rng) * std::cos(b);
  p.y0[2] = p.y0[1] + pitch * stretch(rng) * std::sin(b);
  for (int k = 0; k < 3; ++k) {
    p.x1[k] = p.x0[k] + d(rng);
    p.y1[k] = p.y0[k] + d(rng);
  }
  return p;
}

constexpr double kPitch = 0.01905, kStiffness = 5e7;

// Link j's (j → j + 1) length at the nodes (x, y), as the integrator takes it (sqrt, not hypot).
double link_length(const double x[3], const double y[3], int j) {
  const double dx = x[j + 1] - x[j], dy = y[j + 1] - y[j];
  return std::sqrt(dx * dx + dy * dy);
}

// The pin load is the mean of the two links' elastic tensions, each from its own rest length
// (an alternating round-link chain has links of p + a and p − a): links of 82 and 46 mm at rest
// on rest lengths 82 and 46 mm carry nothing; on 80 and 45 mm, k (2 mm + 1 mm)/2; on one pitch
// of 64 mm for both, the stretch of one and the shortening of the other cancel.
TEST(HingeFriction, PinLoadTakesEachLinksOwnRestLength) {
  const HingeFriction hinge{.arm = 2.86e-4, .rate_band = 5.0};
  const Pose p = round_link_pose();
  const double own[2] = {0.082, 0.046}, shorter[2] = {0.080, 0.045};
  auto load = [&](const double rest[2]) {
    return hinge_couple(hinge, kStiffness, rest, p.x0, p.y0, p.x1, p.y1, 0.0, 1e-4, 0, 0.0).load;
  };
  EXPECT_NEAR(load(own), 0.0, 1e-6);
  EXPECT_NEAR(load(shorter), 0.5 * kStiffness * (0.002 + 0.001), 1e-6 * kStiffness * 0.003);
  EXPECT_NEAR(
      hinge_couple(hinge, kStiffness, 0.064, p.x0, p.y0, p.x1, p.y1, 0.0, 1e-4, 0, 0.0).load, 0.0,
      1e-6);
  EXPECT_NE(
      hinge_couple(hinge, kStiffness, shorter, p.x0, p.y0, p.x1, p.y1, 0.0, 1e-4, 0, 0.0).torque,
      0.0);
}

// With PinLoad::kPinLink the load is the outer link's tension alone: links alternate along the
// chain, link 0 outer, so at an even node the hinge's second link (node → node + 1) holds the pin,
// at an odd node its first. The same pose as above on rest lengths 80 and 45 mm: k 1 mm at an
// even node, k 2 mm at an odd one, where the mean takes k 1.5 mm at both.
TEST(HingeFriction, PinLinkLoadIsTheOuterLinksTension) {
  HingeFriction hinge{.arm = 2.86e-4, .rate_band = 5.0, .pin_load = PinLoad::kPinLink};
  const Pose p = round_link_pose();
  const double rest[2] = {0.080, 0.045};
  auto couple = [&](std::size_t node) {
    return hinge_couple(hinge, kStiffness, rest, p.x0, p.y0, p.x1, p.y1, 0.0, 1e-4, node, 0.0);
  };
  EXPECT_EQ(pin_link_side(hinge, 0), 1);
  EXPECT_EQ(pin_link_side(hinge, 7), 0);
  for (std::size_t node : {0u, 2u, 36u})
    EXPECT_NEAR(couple(node).load, kStiffness * 0.001, 1e-6 * kStiffness * 0.001) << node;
  for (std::size_t node : {1u, 3u, 37u})
    EXPECT_NEAR(couple(node).load, kStiffness * 0.002, 1e-6 * kStiffness * 0.002) << node;
  // the torque scales with the load: twice as much at an odd node as at an even one
  EXPECT_NEAR(couple(1).torque, 2.0 * couple(0).torque, 1e-9 * std::abs(couple(0).torque));
  // the mean ignores the node's parity: at node 0 bit for bit what it is at node 1
  hinge.pin_load = PinLoad::kMean;
  EXPECT_EQ(pin_link_side(hinge, 1), -1);
  const HingeCouple mean =
      hinge_couple(hinge, kStiffness, rest, p.x0, p.y0, p.x1, p.y1, 0.0, 1e-4, 0, 0.0);
  EXPECT_EQ(couple(1).load, mean.load);
  EXPECT_EQ(couple(0).torque, mean.torque);
  EXPECT_NEAR(mean.load, 0.5 * kStiffness * 0.003, 1e-6 * kStiffness * 0.003);
}

// An odd closed loop has no alternation of inner and outer links all round: refused with the pin
// link's load (field "links"), whether the law or the model is validated; an open chain of any
// count, an even loop, the mean or a frictionless hinge are not.
TEST(HingeFriction, PinLinkLoadRefusesAnOddLoop) {
  const HingeFriction pin{.arm = 2.86e-4, .rate_band = 5.0, .pin_load = PinLoad::kPinLink};
  const std::vector<Issue> odd = validate_pin_links(pin, 25, true);
  ASSERT_EQ(odd.size(), 1u);
  EXPECT_EQ(odd[0].field, "links");
  EXPECT_EQ(odd[0].value, "25");
  EXPECT_NE(odd[0].expected.find("an even count"), std::string::npos) << odd[0].expected;
  EXPECT_TRUE(validate_pin_links(pin, 24, true).empty());
  EXPECT_TRUE(validate_pin_links(pin, 25, false).empty());
  EXPECT_TRUE(validate_pin_links({.arm = 2.86e-4, .rate_band = 5.0}, 25, true).empty());
  EXPECT_TRUE(validate_pin_links({.arm = 0.0, .pin_load = PinLoad::kPinLink}, 25, true).empty());
  Model model = uniform_chain(25, true, 0.01905, 0.02, 5e7, 0.0, false);
  model.hinge = pin;
  bool named = false;
  for (const Issue& i : validate(model)) named = named || i.field == "links";
  EXPECT_TRUE(named);
  model = uniform_chain(26, true, 0.01905, 0.02, 5e7, 0.0, false);
  model.hinge = pin;
  EXPECT_TRUE(validate(model).empty());
}

TEST(HingeFriction, ForceIsTheTorqueTimesTheGradientOfTheRelativeAngle) {
  std::mt19937 rng(21);
  const HingeFriction hinge{.arm = 2.86e-4, .rate_band = 5.0};
  for (int trial = 0; trial < 200; ++trial) {
    const Pose p = random_pose(rng, kPitch, 2e-4);
    for (double theta : {0.5, 0.6, 1.0}) {
      const HingeCouple hc =
          hinge_couple(hinge, kStiffness, kPitch, p.x0, p.y0, p.x1, p.y1, theta, 1e-4, 0, 0.0);
      // g = ∂β/∂x at the θ point, by central differences of β
      double xt[3], yt[3];
      for (int k = 0; k < 3; ++k) {
        xt[k] = (1 - theta) * p.x0[k] + theta * p.x1[k];
        yt[k] = (1 - theta) * p.y0[k] + theta * p.y1[k];
      }
      const double e = 1e-7;
      for (int k = 0; k < 3; ++k) {
        double xp[3] = {xt[0], xt[1], xt[2]}, xm[3] = {xt[0], xt[1], xt[2]};
        xp[k] += e;
        xm[k] -= e;
        const double gx = (relative_angle(xp, yt) - relative_angle(xm, yt)) / (2 * e);
        double yp[3] = {yt[0], yt[1], yt[2]}, ym[3] = {yt[0], yt[1], yt[2]};
        yp[k] += e;
        ym[k] -= e;
        const double gy = (relative_angle(xt, yp) - relative_angle(xt, ym)) / (2 * e);
        const double scale = 1.0 / kPitch;
        EXPECT_NEAR(hc.gx[k], gx, 1e-6 * scale) << trial << " node " << k;
        EXPECT_NEAR(hc.gy[k], gy, 1e-6 * scale) << trial << " node " << k;
        // the couple's nodal forces are the torque times ∂β/∂x — the finite difference's, not
        // hc.gx (f = torque · hc.gx restated the code's own line)
        const double force_tol = 1e-6 * scale * std::abs(hc.torque) + 1e-300;
        EXPECT_NEAR(hc.fx[k], hc.torque * gx, force_tol) << trial << " node " << k;
        EXPECT_NEAR(hc.fy[k], hc.torque * gy, force_tol) << trial << " node " << k;
      }
      // the torque: −e F s(ω), F the mean elastic tension at the θ point (≥ 0)
      double tension = 0.0;
      for (int j = 0; j < 2; ++j) {
        const double l0 = std::hypot(p.x0[j + 1] - p.x0[j], p.y0[j + 1] - p.y0[j]);
        const double l1 = std::hypot(p.x1[j + 1] - p.x1[j], p.y1[j + 1] - p.y1[j]);
        tension += 0.5 * kStiffness * ((1 - theta) * l0 + theta * l1 - kPitch);
      }
      EXPECT_NEAR(hc.load, std::max(0.0, tension), 1e-9 * kStiffness * kPitch);
      const double w = hc.rate;
      EXPECT_NEAR(hc.torque, -hinge.arm * hc.load * w / std::sqrt(w * w + 25.0),
                  1e-12 * hinge.arm * kStiffness * kPitch);
    }
  }
}

// The integrator's chord iterations take the couple without its Jacobian, into one HingeCouple
// kept across hinges: every other field must be the full evaluation's, bit for bit, and the
// Jacobian must be left as it was (here: a marker), or written in full when asked for.
TEST(HingeFriction, CoupleWithoutJacobianIsTheFullOnesBitForBitAndLeavesTheJacobian) {
  std::mt19937 rng(11);
  const HingeFriction hinge{.arm = 2.86e-4, .rate_band = 5.0};
  for (int trial = 0; trial < 200; ++trial) {
    const Pose p = random_pose(rng, kPitch, 5e-5);
    const double theta = trial % 2 ? 0.5 : 0.6, h = 1e-4;
    const double rest[2] = {kPitch, kPitch * (1.0 + 1e-3)};
    double l0[2], l1[2];
    for (int j = 0; j < 2; ++j) {
      l0[j] = link_length(p.x0, p.y0, j);
      l1[j] = link_length(p.x1, p.y1, j);
    }
    const HingeCouple full = hinge_couple(hinge, kStiffness, rest, p.x0, p.y0, p.x1, p.y1, theta, h,
                                          l0, l1, true, 0, 0.0);
    HingeCouple lean;
    for (auto& row : lean.jacobian) {
      for (double& v : row) v = 12345.0;
    }
    hinge_couple(hinge, kStiffness, rest, p.x0, p.y0, p.x1, p.y1, theta, h, l0, l1, lean, false, 0,
                 0.0);
    EXPECT_EQ(lean.load, full.load);
    EXPECT_EQ(lean.rate, full.rate);
    EXPECT_EQ(lean.torque, full.torque);
    EXPECT_EQ(lean.turn, full.turn);
    EXPECT_EQ(lean.work, full.work);
    EXPECT_EQ(lean.rate_stiffness, full.rate_stiffness);
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(lean.gx[k], full.gx[k]);
      EXPECT_EQ(lean.gy[k], full.gy[k]);
      EXPECT_EQ(lean.fx[k], full.fx[k]);
      EXPECT_EQ(lean.fy[k], full.fy[k]);
    }
    for (const auto& row : lean.jacobian) {
      for (const double v : row) EXPECT_EQ(v, 12345.0);
    }
    hinge_couple(hinge, kStiffness, rest, p.x0, p.y0, p.x1, p.y1, theta, h, l0, l1, lean, true, 0,
                 0.0);
    for (int r = 0; r < 6; ++r) {
      for (int c = 0; c < 6; ++c) EXPECT_EQ(lean.jacobian[r][c], full.jacobian[r][c]);
    }
  }
}

// The integrator's hinge loop takes the couple's Jacobian block by block (hinge_couple_blocks),
// adding −h × each block into its band: the nine blocks, each once, in row-major order, each the
// stored Jacobian's bit for bit (both links' terms from hinge_link, as the integrator has them);
// none without the Jacobian, the other fields the same either way. hinge_couple fills its stored
// Jacobian through hinge_couple_blocks, so this checks the blocks' indices and order, not the
// formula: the formula is checked against finite differences in
// JacobianIsTheForcesDerivativeByTheEndOfStepPositions (a block's sign flipped fails it).
TEST(HingeFriction, CoupleBlocksAreTheStoredJacobiansNineBlocksInOrderBitForBit) {
  std::mt19937 rng(13);
  const HingeFriction hinge{.arm = 2.86e-4, .rate_band = 5.0};
  for (int trial = 0; trial < 200; ++trial) {
    const Pose p = random_pose(rng, kPitch, 5e-5);
    const double theta = trial % 2 ? 0.5 : 0.6, h = 1e-4;
    const double rest[2] = {kPitch, kPitch * (1.0 - 1e-3)};
    HingeLink link[2];
    for (int j = 0; j < 2; ++j) {
      const double d0x = p.x0[j + 1] - p.x0[j], d0y = p.y0[j + 1] - p.y0[j];
      const double d1x = p.x1[j + 1] - p.x1[j], d1y = p.y1[j + 1] - p.y1[j];
      hinge_link(d0x, d0y, d1x, d1y, link_length(p.x0, p.y0, j), link_length(p.x1, p.y1, j),
                 rest[j], kStiffness, theta, link[j]);
    }
    HingeCouple stored;
    hinge_couple(hinge, link[0], link[1], h, stored, true, 0, theta, 0.0);
    HingeCouple blocks;
    int calls = 0;
    hinge_couple_blocks(
        hinge, link[0], link[1], h, blocks, true,
        [&](int k, int q, double a, double b, double c, double d) {
          EXPECT_EQ(3 * k + q, calls);
          ++calls;
          EXPECT_EQ(a, stored.jacobian[2 * k][2 * q]);
          EXPECT_EQ(b, stored.jacobian[2 * k][2 * q + 1]);
          EXPECT_EQ(c, stored.jacobian[2 * k + 1][2 * q]);
          EXPECT_EQ(d, stored.jacobian[2 * k + 1][2 * q + 1]);
        },
        0, theta, 0.0);
    EXPECT_EQ(calls, 9);
    HingeCouple lean;
    hinge_couple_blocks(
        hinge, link[0], link[1], h, lean, false,
        [&](int, int, double, double, double, double) { ++calls; }, 0, theta, 0.0);
    EXPECT_EQ(calls, 9);
    for (const HingeCouple* hc : {&blocks, &lean}) {
      EXPECT_EQ(hc->torque, stored.torque);
      EXPECT_EQ(hc->work, stored.work);
      EXPECT_EQ(hc->rate_stiffness, stored.rate_stiffness);
      for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(hc->fx[k], stored.fx[k]);
        EXPECT_EQ(hc->fy[k], stored.fy[k]);
      }
      for (const auto& row : hc->jacobian) {
        for (const double v : row) EXPECT_EQ(v, 0.0);  // not written
      }
    }
  }
}

TEST(HingeFriction, CoupleHasNoResultantItsMomentIsTheTorqueAndItsWorkIsMTimesTheTurn) {
  std::mt19937 rng(6);
  const HingeFriction hinge{.arm = 2.86e-4, .rate_band = 5.0};
  for (int trial = 0; trial < 200; ++trial) {
    const Pose p = random_pose(rng, kPitch, 5e-5);  // a step: turns of up to 0.3°
    const double theta = trial % 2 ? 0.5 : 0.6, h = 1e-4;
    const HingeCouple hc =
        hinge_couple(hinge, kStiffness, kPitch, p.x0, p.y0, p.x1, p.y1, theta, h, 0, 0.0);
    const double scale = std::abs(hc.torque) / kPitch + 1e-300;
    EXPECT_NEAR(hc.fx[0] + hc.fx[1] + hc.fx[2], 0.0, 1e-12 * scale);
    EXPECT_NEAR(hc.fy[0] + hc.fy[1] + hc.fy[2], 0.0, 1e-12 * scale);
    // the moment about the origin of all three forces is zero; the second link's share (the
    // force on node 2 and its reaction on node 1) is the torque M
    double xt[3], yt[3];
    for (int k = 0; k < 3; ++k) {
      xt[k] = (1 - theta) * p.x0[k] + theta * p.x1[k];
      yt[k] = (1 - theta) * p.y0[k] + theta * p.y1[k];
    }
    double moment = 0.0;
    for (int k = 0; k < 3; ++k) moment += xt[k] * hc.fy[k] - yt[k] * hc.fx[k];
    EXPECT_NEAR(moment, 0.0, 1e-12 * std::abs(hc.torque) + 1e-300);
    const double second = (xt[2] - xt[1]) * hc.fy[2] - (yt[2] - yt[1]) * hc.fx[2];
    EXPECT_NEAR(second, hc.torque, 1e-12 * std::abs(hc.torque) + 1e-300);
    // work: the forces times the step's displacements is M Δβ ≤ 0, and Δβ is the true change of
    // the relative angle to third order in the links' turns (and to first order in their length
    // changes at θ ≠ ½: l₀ l₁/l_θ², within 0.1 % here)
    double work = 0.0;
    for (int k = 0; k < 3; ++k)
      work += hc.fx[k] * (p.x1[k] - p.x0[k]) + hc.fy[k] * (p.y1[k] - p.y0[k]);
    EXPECT_NEAR(work, hc.work, 1e-9 * std::abs(hc.work) + 1e-300);  // rounding: Δx ≪ x
    EXPECT_LE(hc.work, 0.0);
    const double turn = relative_angle(p.x1, p.y1) - relative_angle(p.x0, p.y0);
    auto link_turn = [&](int j) {
      const double ax = p.x0[j + 1] - p.x0[j], ay = p.y0[j + 1] - p.y0[j];
      const double bx = p.x1[j + 1] - p.x1[j], by = p.y1[j + 1] - p.y1[j];
      return std::abs(std::atan2(ax * by - ay * bx, ax * bx + ay * by));
    };
    const double tol = 2e-3 * (link_turn(0) + link_turn(1)) + 1e-15;  // each link's turn's error
    EXPECT_NEAR(hc.turn, turn, tol) << trial;
    EXPECT_NEAR(hc.work, hc.torque * turn, std::abs(hc.torque) * tol) << trial;
  }
}

TEST(HingeFriction, RateStiffnessIsTheTorquesSlopeInTheRate) {
  // −∂M/∂ω at fixed load = e F s'(ω): turn the last link about node 1 between two iterates
  const HingeFriction hinge{.arm = 2.86e-4, .rate_band = 5.0};
  const double h = 1e-4;
  for (double rate : {0.0, 1.0, 5.0, 40.0}) {
    auto at = [&](double r) {
      const double turn = r * h;
      Pose p{{0, kPitch, 2 * kPitch}, {0, 0, 0}, {0, kPitch, 0}, {0, 0, 0}};
      const double l = 1.002 * kPitch;  // in tension
      p.x0[2] = p.x0[1] + l;
      p.x1[2] = p.x1[1] + l * std::cos(turn);
      p.y1[2] = l * std::sin(turn);
      p.x0[0] = p.x1[0] = p.x0[1] - l;
      return hinge_couple(hinge, kStiffness, kPitch, p.x0, p.y0, p.x1, p.y1, 0.5, h, 0, 0.0);
    };
    const double dr = 1e-4;
    const HingeCouple mid = at(rate);
    const double slope = -(at(rate + dr).torque - at(rate - dr).torque) / (2 * dr);
    // the load changes with the turn only to second order; the rate is Δβ/h to third order
    EXPECT_NEAR(mid.rate_stiffness, slope, 1e-4 * mid.rate_stiffness + 1e-9) << rate;
    EXPECT_GT(mid.rate_stiffness, 0.0);
  }
}

TEST(HingeFriction, JacobianIsTheForcesDerivativeByTheEndOfStepPositions) {
  // central differences of f = M g in each of the six end-of-step coordinates, on random poses
  // in tension, at rates inside and beyond the band, at θ = ½ and 0.6; the exact Jacobian is
  // not symmetric, and the rate term alone (rate_stiffness × g gᵀ / h) misses part of it. For
  // each pin load: the mean, and the pin link's at an even node (the second link's tension: the
  // load term on nodes b and c alone) and at an odd one (the first link's: nodes a and b).
  const double h = 1e-4;
  for (int rule = 0; rule < 3; ++rule) {
    std::mt19937 rng(2105);
    const PinLoad pin_load = rule == 0 ? PinLoad::kMean : PinLoad::kPinLink;
    const std::size_t node = rule == 2 ? 1 : 0;
    int asymmetric = 0, beyond_rate_term = 0, poses = 0;
    for (double band : {2.0, 5.0}) {
      const HingeFriction hinge{.arm = 2.86e-4, .rate_band = band, .pin_load = pin_load};
      for (double theta : {0.5, 0.6}) {
        for (int trial = 0; trial < 40; ++trial) {
          Pose p = random_pose(rng, kPitch, (trial % 2 == 0 ? 2e-6 : 2e-4));
          // stretch: loaded (the pin link's load is one link's tension: every link stretched)
          const double stretch = rule == 0 ? 1.002 : 1.006;
          for (int k = 0; k < 3; ++k) p.x0[k] *= stretch, p.x1[k] *= stretch;
          const HingeCouple hc =
              hinge_couple(hinge, kStiffness, kPitch, p.x0, p.y0, p.x1, p.y1, theta, h, node, 0.0);
          if (!(hc.load > 0.0)) continue;
          ++poses;
          double scale = 0.0;
          for (const auto& row : hc.jacobian) {
            for (double v : row) scale = std::max(scale, std::abs(v));
          }
          double worst = 0.0, asym = 0.0, miss = 0.0;
          for (int q = 0; q < 6; ++q) {
            const double du = 1e-10;
            Pose plus = p, minus = p;
            (q % 2 == 0 ? plus.x1 : plus.y1)[q / 2] += du;
            (q % 2 == 0 ? minus.x1 : minus.y1)[q / 2] -= du;
            const HingeCouple a = hinge_couple(hinge, kStiffness, kPitch, plus.x0, plus.y0, plus.x1,
                                               plus.y1, theta, h, node, 0.0);
            const HingeCouple b = hinge_couple(hinge, kStiffness, kPitch, minus.x0, minus.y0,
                                               minus.x1, minus.y1, theta, h, node, 0.0);
            for (int r = 0; r < 6; ++r) {
              const double fa = r % 2 == 0 ? a.fx[r / 2] : a.fy[r / 2];
              const double fb = r % 2 == 0 ? b.fx[r / 2] : b.fy[r / 2];
              const double fd = (fa - fb) / (2 * du);
              worst = std::max(worst, std::abs(hc.jacobian[r][q] - fd));
              const double gr = r % 2 == 0 ? hc.gx[r / 2] : hc.gy[r / 2];
              const double gq = q % 2 == 0 ? hc.gx[q / 2] : hc.gy[q / 2];
              miss = std::max(miss, std::abs(fd + hc.rate_stiffness * gr * gq / h));
              asym = std::max(asym, std::abs(hc.jacobian[r][q] - hc.jacobian[q][r]));
            }
          }
          EXPECT_LT(worst, 1e-5 * scale)
              << "rule " << rule << " band " << band << " theta " << theta << " " << trial;
          if (asym > 1e-3 * scale) ++asymmetric;
          if (miss > 1e-3 * scale) ++beyond_rate_term;
        }
      }
    }
    EXPECT_GT(poses, 100) << rule;
    EXPECT_GT(asymmetric, poses / 2) << rule;
    EXPECT_GT(beyond_rate_term, poses / 2) << rule;
  }
}

TEST(HingeFriction, RollingArmIsTheRollingCoefficientTimesTheReducedRadius) {
  // R* = R1 R2/(R2 − R1); flat face: R1; and the flat face is the limit of large R2
  EXPECT_DOUBLE_EQ(rolling_hinge_arm(0.001, 0.015, 0.06276), 0.001 * 0.015 * 0.06276 / 0.04776);
  EXPECT_DOUBLE_EQ(rolling_hinge_arm(0.001, 0.015, INFINITY), 0.001 * 0.015);
  EXPECT_NEAR(rolling_hinge_arm(0.001, 0.015, 1e6), 0.001 * 0.015, 1e-12);
  // against the hinge model's rolling geometry (hinge::pose, eqs. 1–3 of seed 000): over a turn
  // φ each of the two contacts runs R1 Ψ1(φ) along its plate's arc, so c_r F · 2 R1 Ψ1(φ) = e F φ
  hinge::Hinge h{.pin_diameter = 0.040, .half_thickness = 0.008, .plate_radius = 0.015, .teeth = 8};
  for (double phi : {0.05, 0.3, 0.7}) {
    const hinge::Pose concave = hinge::pose(h, 0.06276, phi);
    EXPECT_NEAR(rolling_hinge_arm(0.001, 0.015, 0.06276), 0.001 * 2 * 0.015 * concave.psi1 / phi,
                1e-12)
        << phi;
    h.face = hinge::Face::kFlat;
    h.face_half_length = 0.015;
    h.loaded_length = 0.012;
    const hinge::Pose flat = hinge::pose(h, INFINITY, phi);
    EXPECT_NEAR(rolling_hinge_arm(0.001, 0.015, INFINITY), 0.001 * 2 * 0.015 * flat.psi1 / phi,
                1e-12)
        << phi;
    h.face = hinge::Face::kConcave;
  }
}

TEST(HingeFriction, InvalidLawListsEveryProblem) {
  const std::vector<Issue> issues = validate(HingeFriction{.arm = -1.0, .rate_band = 0.0}, 0.01905);
  ASSERT_EQ(issues.size(), 2u);
  EXPECT_EQ(issues[0].field, "hinge.arm");
  EXPECT_EQ(issues[1].field, "hinge.rate_band");
  EXPECT_EQ(validate(HingeFriction{.arm = 0.01, .rate_band = 5.0}, 0.01905).size(), 1u);  // ≥ p/2
  EXPECT_TRUE(validate(HingeFriction{.arm = 2.86e-4, .rate_band = 5.0}, 0.01905).empty());
  Model model = uniform_chain(8, true, 0.01905, 0.02, 5e7, 0.0, false);
  model.hinge.arm = NAN;
  bool named = false;
  for (const Issue& i : validate(model)) named = named || i.field == "hinge.arm";
  EXPECT_TRUE(named);
}

// A free loop of 24 links spinning and wobbling (a transverse velocity on every other node), no
// contact, no damping, at θ = ½: the energy changes by exactly the hinges' friction work (the
// springs' discrete gradient and the midpoint rule's kinetic energy are exact), to the Newton
// tolerance. Leaving the hinge work out breaks the balance by that work (a few % of the energy).
// With either pin load: the mean, or the pin link's tension.
TEST(HingeFriction, WorkBalanceClosesWithHingeFriction) {
  constexpr std::size_t n = 24;
  constexpr double p = 0.01905, omega = 20.0;
  for (PinLoad pin_load : {PinLoad::kMean, PinLoad::kPinLink}) {
    Model model = uniform_chain(n, true, p * (1 - 1e-3), 0.0238, 5e7, 0.0, false);
    model.hinge = {.arm = 0.1 * 0.00286, .rate_band = 5.0, .pin_load = pin_load};
    State s = spinning_ring(n, p, omega, 0.3);
    Integrator integ(model, {.step = 1e-4, .theta = 0.5});
    const double e0 = energy(model, s).total();
    for (int k = 0; k < 2000; ++k) ASSERT_TRUE(integ.step(model, s).converged) << k;
    const double e1 = energy(model, s).total();
    EXPECT_LT(s.hinge_work, -0.01 * e0);  // the hinges took a few % of the energy
    EXPECT_NEAR(e1 - e0, s.hinge_work, 1e-6 * e0);
    EXPECT_GT(std::abs(e1 - e0), 1e-3 * e0);  // so the balance without the hinge work fails
  }
}

// Newton on the exact hinge Jacobian converges quadratically: the spinning, wobbling loop of the
// test above (no contacts: every term of its Jacobian is exact), one step after 5 ms repeated
// with a cap of 1, 2, 3, … iterations; |δ_(k+1)| ≤ C |δ_k|² down to round-off, at the default
// rate band and at 2 rad/s (most hinges of the loop turn slower than that: in the stick band).
TEST(HingeFriction, NewtonConvergesQuadraticallyOnTheExactJacobian) {
  constexpr std::size_t n = 24;
  constexpr double p = 0.01905, omega = 20.0;
  // the default band and 2 rad/s with the mean pin load, the default band with the pin link's
  for (int run_case = 0; run_case < 3; ++run_case) {
    const double band = run_case == 1 ? 2.0 : 5.0;
    Model model = uniform_chain(n, true, p * (1 - 1e-3), 0.0238, 5e7, 0.0, false);
    model.hinge = {.arm = 0.1 * 0.00286,
                   .rate_band = band,
                   .pin_load = run_case == 2 ? PinLoad::kPinLink : PinLoad::kMean};
    State s = spinning_ring(n, p, omega, 0.3);
    Integrator run(model, {.step = 1e-4, .theta = 0.5});
    for (int k = 0; k < 50; ++k) ASSERT_TRUE(run.step(model, s).converged);
    std::vector<double> c;  // |δ_k| / p
    for (int cap = 1; cap <= 10; ++cap) {
      Integrator probe(model, {.step = 1e-4, .max_iterations = cap, .tolerance = 1e-15});
      State copy = s;
      const StepReport rep = probe.step(model, copy);
      ASSERT_EQ(rep.solve, SolveStatus::kSolved);
      c.push_back(rep.last_correction / p);
      if (rep.converged || c.back() < 1e-13) break;
    }
    std::printf("band %.0f rad/s%s: |dx|/p per iteration:", band,
                run_case == 2 ? " (pin link's load)" : "");
    for (double v : c) std::printf(" %.2e", v);
    std::printf("\n");
    int quadratic = 0;
    for (std::size_t k = 0; k + 1 < c.size() && c[k] > 1e-10; ++k) {
      EXPECT_LT(c[k + 1], 100.0 * c[k] * c[k]) << band << " " << k;
      ++quadratic;
    }
    EXPECT_GE(quadratic, 2) << band;
  }
}

// An open chain of 16 links pinned at both ends, released as an inverted V under gravity: it
// falls through and swings on its hinges, and at θ = ½ without dampers its energy (gravity's
// included) changes by the hinges' work alone. The end hinges (next to the pinned nodes) take part;
// an open chain has no hinge at its two end nodes. With either pin load.
TEST(HingeFriction, OpenPinnedChainSwingingBalancesItsHingeWork) {
  for (PinLoad pin_load : {PinLoad::kMean, PinLoad::kPinLink}) {
    constexpr std::size_t n = 17;
    constexpr double p = 0.01905;
    Model model = uniform_chain(n, false, p, 0.0238, 5e6, 0.0, true);
    model.gravity_y = -9.81;
    model.hinge = {.arm = 0.1 * 0.00286, .rate_band = 5.0, .pin_load = pin_load};
    State s(n, 0);
    // an inverted V of links at rest length, 30° up to the middle and down again
    const double c30 = std::cos(M_PI / 6), s30 = std::sin(M_PI / 6);
    for (std::size_t i = 1; i < n; ++i) {
      const bool up = i <= n / 2;
      s.x[i] = s.x[i - 1] + p * c30;
      s.y[i] = s.y[i - 1] + (up ? p : -p) * s30;
    }
    Integrator integ(model, {.step = 1e-4, .theta = 0.5});
    const double e0 = energy(model, s).total();
    for (int k = 0; k < 2000; ++k) ASSERT_TRUE(integ.step(model, s).converged) << k;
    const Energy e1 = energy(model, s);
    EXPECT_LT(s.y[n / 2], -0.01);  // it swung down
    EXPECT_LT(s.hinge_work, 0.0);
    EXPECT_GT(-s.hinge_work, 1e-3 * e1.kinetic);  // not negligible against the motion
    std::printf("hinge work %.6g J, kinetic %.6g J, balance error %.3g J\n", s.hinge_work,
                e1.kinetic, e1.total() - e0 - s.hinge_work);
    EXPECT_NEAR(e1.total() - e0, s.hinge_work, 1e-6 * std::abs(e0 - e1.potential) + 1e-9);
    EXPECT_EQ(s.x[0], 0.0);  // pinned ends stay
    EXPECT_DOUBLE_EQ(s.x[n - 1], 16 * p * c30);
  }
}

// The integrator takes each hinge's pin link by its node: on the swinging chain above with the
// pin link's load, once it swings in tension (after 0.15 s), a step's hinge work is the sum of
// hinge_couple's at each node i (the couple of nodes i − 1, i, i + 1 over the step, with node i's
// parity), and not the sum with the parities swapped (each hinge loaded by its inner link): the
// report is 100 times closer to the first than the two sums are to each other.
TEST(HingeFriction, IntegratorLoadsEachHingeByItsOwnPinLink) {
  constexpr std::size_t n = 17;
  constexpr double p = 0.01905, c30 = 0.8660254037844386, h = 1e-4;
  Model model = uniform_chain(n, false, p, 0.0238, 5e6, 0.0, true);
  model.gravity_y = -9.81;
  model.hinge = {.arm = 0.1 * 0.00286, .rate_band = 5.0, .pin_load = PinLoad::kPinLink};
  State s(n, 0);
  for (std::size_t i = 1; i < n; ++i) {
    s.x[i] = s.x[i - 1] + p * c30;
    s.y[i] = s.y[i - 1] + (i <= n / 2 ? p : -p) * 0.5;
  }
  Integrator integ(model, {.step = h, .tolerance = 1e-13, .theta = 0.5});
  for (int k = 0; k < 1500; ++k) ASSERT_TRUE(integ.step(model, s).converged) << k;
  const State before = s;
  const StepReport rep = integ.step(model, s);
  ASSERT_TRUE(rep.converged);
  double own = 0.0, swapped = 0.0;
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double x0[3] = {before.x[i - 1], before.x[i], before.x[i + 1]};
    const double y0[3] = {before.y[i - 1], before.y[i], before.y[i + 1]};
    const double x1[3] = {s.x[i - 1], s.x[i], s.x[i + 1]}, y1[3] = {s.y[i - 1], s.y[i], s.y[i + 1]};
    own += hinge_couple(model.hinge, model.axial_stiffness, p, x0, y0, x1, y1, 0.5, h, i, 0.0).work;
    swapped +=
        hinge_couple(model.hinge, model.axial_stiffness, p, x0, y0, x1, y1, 0.5, h, i + 1, 0.0)
            .work;
  }
  std::printf("step's hinge work %.12g J, its pin links' %.12g J, swapped %.12g J\n",
              rep.hinge_work, own, swapped);
  EXPECT_LT(own, 0.0);
  EXPECT_LT(std::abs(rep.hinge_work - own), 0.01 * std::abs(swapped - own));
}

// A step that does not converge from the first starting point (the predictor, with hinge
// friction the last step's factors) runs Newton again from constant velocity with fresh factors:
// its report counts the iterations of both runs and says so (starts = 2), and the message's text
// names the count for what it is rather than as iterations of one run past max_iterations.
TEST(HingeFriction, StepThatFailsTwiceCountsBothStartsAndSaysSo) {
  constexpr std::size_t n = 24;
  constexpr double p = 0.01905, omega = 20.0;
  constexpr int cap = 3;
  Model model = uniform_chain(n, true, p * (1 - 1e-3), 0.0238, 5e7, 0.0, false);
  model.hinge = {.arm = 0.1 * 0.00286, .rate_band = 5.0};
  State s = spinning_ring(n, p, omega, 0.0);
  const double radius = p / (2 * std::sin(M_PI / n));  // the ring's, for the blow below
  Integrator run(model, {.step = 1e-4, .max_iterations = cap, .theta = 0.5});
  for (int k = 0; k < 3; ++k) {
    const StepReport rep = run.step(model, s);
    ASSERT_TRUE(rep.converged) << k;
    EXPECT_EQ(rep.starts, 1) << k;
    EXPECT_LE(rep.iterations, cap) << k;
  }
  // a blow: every other node moved out by half a pitch and kicked outward at 3000 m/s, the
  // state's time unchanged
  for (std::size_t i = 0; i < n; i += 2) {
    const double ux = s.x[i] / radius, uy = s.y[i] / radius;
    s.x[i] += 0.5 * p * ux;
    s.y[i] += 0.5 * p * uy;
    s.vx[i] += 3000.0 * ux;
    s.vy[i] += 3000.0 * uy;
  }
  const StepReport rep = run.step(model, s);
  ASSERT_FALSE(rep.converged);
  EXPECT_EQ(rep.starts, 2);
  EXPECT_GT(rep.iterations, cap);
  EXPECT_LE(rep.iterations, 2 * cap);
  EXPECT_EQ(newton_iterations_text(rep, cap),
            std::to_string(rep.iterations) +
                " Newton iterations in all, from 2 starting points with at most 3 from each");
  StepReport once;
  once.iterations = 5;
  EXPECT_EQ(newton_iterations_text(once, cap), "5 Newton iterations");
}

// A state whose time is reset after a sequence of steps (a grid step taken as sub-steps, whose
// summed time differs from the grid's by rounding: docs/models/dynamics.md, "Integrator: the
// sub-step size kept") keeps the predictor's history when the integrator is re-timed to it: the
// next step is bit-identical to the one from the state left at its own time. Without the
// re-timing the step restarts from constant velocity and ends elsewhere within the tolerance
// (the control: the predictor matters here).
TEST(HingeFriction, RetimedHistoryKeepsThePredictor) {
  constexpr std::size_t n = 24;
  constexpr double p = 0.01905, omega = 20.0;
  Model model = uniform_chain(n, true, p * (1 - 1e-3), 0.0238, 5e7, 0.0, false);
  model.hinge = {.arm = 0.1 * 0.00286, .rate_band = 5.0};
  std::vector<State> s(3, spinning_ring(n, p, omega, 0.0));
  std::array<std::optional<Integrator>, 3> run;
  for (std::size_t r = 0; r < 3; ++r) {
    run[r].emplace(model, IntegratorOptions{.step = 1e-4, .theta = 0.5});
    for (int k = 0; k < 3; ++k) ASSERT_TRUE(run[r]->step(model, s[r]).converged) << r << " " << k;
  }
  const double summed = s[0].time, grid = std::nextafter(summed, 1.0);  // one rounding away
  s[1].time = s[2].time = grid;
  run[1]->retime(summed, grid);
  for (std::size_t r = 0; r < 3; ++r) ASSERT_TRUE(run[r]->step(model, s[r]).converged) << r;
  int kept = 0, lost = 0;
  for (std::size_t i = 0; i < n; ++i) {
    kept += s[1].x[i] != s[0].x[i] || s[1].y[i] != s[0].y[i] || s[1].vx[i] != s[0].vx[i];
    lost += s[2].x[i] != s[0].x[i] || s[2].y[i] != s[0].y[i] || s[2].vx[i] != s[0].vx[i];
  }
  EXPECT_EQ(kept, 0);
  EXPECT_GT(lost, 0);  // the control
}

}  // namespace
}  // namespace catena::dynamics
