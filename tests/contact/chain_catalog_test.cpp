#include "catena/contact/chain_catalog.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

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

// The link's axial stiffness (issue 21), a transcription check: the source's stretch factor k
// per ANSI size, `elongation_factor_in` of the single-strand rows 40-1 … 160-1 in
// jordanrobot/Calculators, xml/ansi_chain_specs.xml at commit
// b6f5c7e53719d495feab40e06c26b2e1c65b1a26 (lbf per in of stretch per ft of chain; its
// formulas/chain_ansi.md: l = (L/12) T/k), so EA = 12 k lbf and one link's k = EA/p. Every other
// row has none (no source found: data/catalog/iso606/README.md).
TEST(ChainCatalog, AxialStiffnessOfTheARowsFromTheSourcesStretchFactor) {
  const std::vector<std::pair<std::string, double>> source = {
      {"08A", 17889.01714}, {"10A", 29022.23096}, {"12A", 38794.33465}, {"16A", 79685.84238},
      {"20A", 106981.5296}, {"24A", 165746.0851}, {"28A", 193680.1803}, {"32A", 245243.8539}};
  const double inch = 25.4e-3, lbf = 4.4482216152605;  // [m], [N] (exact)
  const std::vector<double> pitch_in = {0.5, 0.625, 0.75, 1.0, 1.25, 1.5, 1.75, 2.0};
  for (std::size_t i = 0; i < source.size(); ++i) {
    const auto& [name, k] = source[i];
    const auto c = iso606_chain(name);
    ASSERT_TRUE(c && c->axial_stiffness) << name;
    const double expected = 12 * k * lbf / (pitch_in[i] * inch);
    EXPECT_NEAR(*c->axial_stiffness, expected, 1e-12 * expected) << name;
    EXPECT_NE(c->source.find("CALCULATORS_K"), std::string::npos) << name;
  }
  // the order of magnitude the research derived: 12A 1.09e8 N/m, 32A 2.58e8 N/m
  EXPECT_NEAR(*iso606_chain("12A")->axial_stiffness, 1.09e8, 0.01e8);
  EXPECT_NEAR(*iso606_chain("32A")->axial_stiffness, 2.58e8, 0.01e8);
  for (const std::string& name : iso606_names()) {
    const bool sourced = std::any_of(source.begin(), source.end(),
                                     [&](const auto& row) { return row.first == name; });
    if (!sourced) {
      EXPECT_FALSE(iso606_chain(name)->axial_stiffness.has_value()) << name;
      EXPECT_EQ(iso606_chain(name)->source.find("CALCULATORS_K"), std::string::npos) << name;
    }
  }
}

}  // namespace
}  // namespace catena::contact
