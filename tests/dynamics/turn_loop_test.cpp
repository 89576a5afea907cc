// The inclined conveyor of validation (6b) (tests/dynamics/two_wheel_loops.hpp: the level loop
// turned by −β about the driver's centre, gravity vertical) against the level loop under gravity
// turned by +β: the same motion seen in two frames. Checks that turn_loop turns everything the
// model places (wheels and their seats, rails, lead-ins, the chain's positions and velocities) and
// that the dynamics do not depend on the frame. Over 10 ms: the two runs start 2e-16 m apart
// (rounding) and part at Newton's tolerance (1e-10 pitches, 2e-12 m) a step, growing ×10 every
// 2–3 ms as rollers meet seats and rails at slightly different times (measured at +15°: 1.5e-11 m
// at 10 ms, 3.7e-9 m at 15 ms, 3e-5 m at 50 ms — the loop's sensitivity behind the scatter of
// validation (6b)'s short-window means).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "two_wheel_loops.hpp"

namespace catena::dynamics {
namespace {

TEST(DynamicsTurnLoop, InclinedConveyorMovesAsTheLevelOneUnderTurnedGravity) {
  constexpr double kPi = std::numbers::pi;
  for (const double degrees : {15.0, -25.0}) {
    testing::Conveyor level;
    testing::Conveyor inclined;
    inclined.incline = degrees * kPi / 180.0;
    const double beta = inclined.incline;
    testing::Loop a = testing::conveyor_loop(level);
    testing::Loop b = testing::conveyor_loop(inclined);
    a.model.gravity_x = level.gravity * std::sin(beta);  // world's −y seen in the level frame
    a.model.gravity_y = -level.gravity * std::cos(beta);
    ASSERT_NEAR(b.model.sprockets[1].centre_y, -std::sin(beta) * level.span_links * level.pitch,
                1e-12);
    Integrator ia(a.model, {.step = 1e-4, .theta = 0.6});
    Integrator ib(b.model, {.step = 1e-4, .theta = 0.6});
    const double c = std::cos(beta), s = std::sin(beta);
    std::vector<double> ta(a.model.links()), tb(b.model.links());
    for (int step = 0; step < 100; ++step) {  // 10 ms: the chain moves 2.4 mm
      ASSERT_TRUE(ia.step(a.model, a.state).converged) << degrees << " step " << step;
      ASSERT_TRUE(ib.step(b.model, b.state).converged) << degrees << " step " << step;
    }
    double gap = 0.0, speed_gap = 0.0, tension_gap = 0.0;
    for (std::size_t i = 0; i < a.model.nodes(); ++i) {
      // b's node turned back by +β into the level frame
      const double x = c * b.state.x[i] - s * b.state.y[i], y = s * b.state.x[i] + c * b.state.y[i];
      const double vx = c * b.state.vx[i] - s * b.state.vy[i];
      const double vy = s * b.state.vx[i] + c * b.state.vy[i];
      gap = std::max(gap, std::hypot(x - a.state.x[i], y - a.state.y[i]));
      speed_gap = std::max(speed_gap, std::hypot(vx - a.state.vx[i], vy - a.state.vy[i]));
    }
    link_tensions(a.model, a.state, ta);
    link_tensions(b.model, b.state, tb);
    for (std::size_t j = 0; j < ta.size(); ++j)
      tension_gap = std::max(tension_gap, std::abs(ta[j] - tb[j]));
    EXPECT_LT(gap, 1e-8) << degrees;
    EXPECT_LT(speed_gap, 1e-5) << degrees;
    EXPECT_LT(tension_gap, 0.01) << degrees;  // of tensions of 3–20 N
    EXPECT_NEAR(b.state.angle[1] - a.state.angle[1], -beta, 1e-8) << degrees;
    EXPECT_NEAR(b.state.speed[1], a.state.speed[1], 1e-5) << degrees;
    EXPECT_NEAR(b.state.friction_work / a.state.friction_work, 1.0, 1e-6) << degrees;
    EXPECT_LT(a.state.friction_work, -1e-5) << degrees;  // the rails carried the chain
    std::printf("beta %+.0f deg: position %.2e m, speed %.2e m/s, tension %.2e N\n", degrees, gap,
                speed_gap, tension_gap);
  }
}

}  // namespace
}  // namespace catena::dynamics
