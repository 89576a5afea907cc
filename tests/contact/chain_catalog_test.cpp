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

// The cells added for issue 16 §2, as the README records them (mm, kg/m).
TEST(ChainCatalog, TransversePitchAndMassWhereSourced) {
  const auto b12 = iso606_chain("12B");
  ASSERT_TRUE(b12->transverse_pitch.has_value());
  EXPECT_DOUBLE_EQ(*b12->transverse_pitch, 19.46e-3);
  EXPECT_DOUBLE_EQ(*b12->mass_per_metre, 1.244);
  EXPECT_DOUBLE_EQ(*iso606_chain("16A")->transverse_pitch, 29.29e-3);
  EXPECT_DOUBLE_EQ(*iso606_chain("32B")->tensile_strength, 250.60e3);
  // no source: empty, not guessed
  EXPECT_FALSE(iso606_chain("08A")->transverse_pitch.has_value());
  EXPECT_FALSE(iso606_chain("05B")->mass_per_metre.has_value());
  // every row: p > d1 > 0, b1 > 0, a source; pt (where given) wider than b1
  for (const std::string& name : iso606_names()) {
    const auto c = iso606_chain(name);
    ASSERT_TRUE(c->roller_diameter && c->inner_width) << name;
    EXPECT_LT(*c->roller_diameter, c->pitch) << name;
    EXPECT_GT(*c->inner_width, 0) << name;
    EXPECT_FALSE(c->source.empty()) << name;
    if (c->transverse_pitch) {
      EXPECT_GT(*c->transverse_pitch, *c->inner_width) << name;
    }
  }
}

}  // namespace
}  // namespace catena::contact
