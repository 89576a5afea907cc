#include "catena/contact/chain_catalog.hpp"

#include <gtest/gtest.h>

namespace catena::contact {
namespace {

TEST(ChainCatalog, CoversTheIssuesChainsInSiUnits) {
  for (const char* name : {"06B", "08B", "10B", "12B", "16B", "08A", "10A", "12A", "16A"}) {
    const auto c = iso606_chain(name);
    ASSERT_TRUE(c.has_value()) << name;
    EXPECT_GT(c->pitch, 5e-3) << name;
    EXPECT_LT(c->pitch, 40e-3) << name;
    ASSERT_TRUE(c->roller_diameter.has_value()) << name;
    EXPECT_LT(*c->roller_diameter, c->pitch) << name;
    EXPECT_FALSE(c->source.empty()) << name;
  }
  const auto b12 = iso606_chain("12b");  // case-insensitive
  ASSERT_TRUE(b12.has_value());
  EXPECT_DOUBLE_EQ(b12->pitch, 19.05e-3);
  EXPECT_DOUBLE_EQ(*b12->roller_diameter, 12.07e-3);
  EXPECT_DOUBLE_EQ(*b12->inner_width, 11.68e-3);
  EXPECT_DOUBLE_EQ(*b12->tensile_strength, 28.94e3);
  // a value no source stated stays absent
  EXPECT_FALSE(iso606_chain("06B")->pin_diameter.has_value());
  EXPECT_FALSE(iso606_chain("99X").has_value());
}

}  // namespace
}  // namespace catena::contact
