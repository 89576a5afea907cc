#include "catena/hinge/sweep.hpp"

#include <gtest/gtest.h>

#include "examples.hpp"

namespace catena::hinge {
namespace {

TEST(HingeSweep, R2GrowsWithoutBoundTowardsR1maxAndTheBestRowIsFeasible) {
  Hinge h = testing::example_hinge();
  Loads loads;
  loads.tension = 29.4e3;
  loads.contact_length = 0.024;
  loads.friction = 0.15;
  const Sweep s = sweep(h, loads, 25);
  ASSERT_EQ(s.rows.size(), 25u);
  for (std::size_t i = 1; i < s.rows.size(); ++i) {
    EXPECT_GT(s.rows[i].r1, s.rows[i - 1].r1);
    EXPECT_GT(s.rows[i].r2, s.rows[i - 1].r2);
    EXPECT_GT(s.rows[i].rolling_limit.value(), s.rows[i - 1].rolling_limit.value());
  }
  EXPECT_GT(s.rows.back().r2, 100 * s.rows.back().r1);
  ASSERT_TRUE(s.best.has_value());
  const SweepRow& best = s.rows[*s.best];
  EXPECT_TRUE(best.feasible);
  for (const SweepRow& row : s.rows) {
    if (row.feasible) {
      EXPECT_LE(best.contact_stress.value(), row.contact_stress.value());
    }
  }
  h.face = Face::kFlat;
  EXPECT_THROW(sweep(h, loads, 5), InputError);
}

}  // namespace
}  // namespace catena::hinge
