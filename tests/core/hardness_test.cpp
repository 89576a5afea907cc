// The hardness conversion against ASTM E140 Table 1 (non-austenitic steels) at its own points,
// and the wear model's defaults (the thesis' 42 and 30 HRC) against it.
#include "catena/core/hardness.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "catena/catena.hpp"
#include "catena/core/error.hpp"
#include "catena/io/quantity.hpp"

namespace catena {
namespace {

// Table 1 rows, read from the table (docs/bibliography.md): HRC → HV.
TEST(Hardness, RockwellCToVickersAtTheTablesPoints) {
  EXPECT_EQ(vickers_from_rockwell_c(42.0), 412.0);  // the thesis' plates (conclusion 10)
  EXPECT_EQ(vickers_from_rockwell_c(30.0), 302.0);  // the thesis' pivots
  EXPECT_EQ(vickers_from_rockwell_c(60.0), 697.0);
  EXPECT_EQ(vickers_from_rockwell_c(20.0), 238.0);  // the table's ends
  EXPECT_EQ(vickers_from_rockwell_c(68.0), 940.0);
  // between whole numbers: linear (E140: converted values are approximate)
  EXPECT_DOUBLE_EQ(vickers_from_rockwell_c(42.5), 0.5 * (412.0 + 423.0));
  // monotone over the whole table
  for (double h = 20.0; h < 68.0; h += 0.25)
    EXPECT_LT(vickers_from_rockwell_c(h), vickers_from_rockwell_c(h + 0.25)) << h;
}

TEST(Hardness, VickersAsAPressure) {
  // HV is kgf/mm²: 1 HV = 9.80665 MPa
  EXPECT_DOUBLE_EQ(vickers_to_pascal(1.0), 9.80665e6);
  EXPECT_NEAR(vickers_to_pascal(412.0), 4040.34e6, 0.01e6);
  EXPECT_NEAR(vickers_to_pascal(302.0), 2961.61e6, 0.01e6);
}

TEST(Hardness, OutsideTheTableIsRefused) {
  for (double h : {19.9, 68.1, -1.0, std::numeric_limits<double>::quiet_NaN()}) {
    try {
      vickers_from_rockwell_c(h);
      ADD_FAILURE() << h;
    } catch (const InputError& e) {
      ASSERT_EQ(e.issues().size(), 1u);
      EXPECT_EQ(e.issues()[0].field, "hardness");
    }
  }
}

// The wear analysis' defaults are the thesis' 42 HRC (plates) and 30 HRC (pivots) by this
// conversion, rounded to the whole MPa they are written with.
TEST(Hardness, WearDefaultsAreTheThesisHardnessConverted) {
  const analysis::Analysis* wear = find_analysis("wear");
  ASSERT_NE(wear, nullptr);
  const auto pressure = [&](const char* key) {
    std::vector<Issue> issues;
    const auto x =
        io::parse_quantity(wear->parameter(key)->default_text, QuantityKind::kStress, key, issues);
    EXPECT_TRUE(issues.empty());
    return x.value_or(0.0);
  };
  const double plate = vickers_to_pascal(vickers_from_rockwell_c(42.0));
  const double pivot = vickers_to_pascal(vickers_from_rockwell_c(30.0));
  EXPECT_EQ(pressure("plate_hardness"), std::round(plate / 1e6) * 1e6);   // 4040.34 → 4040 MPa
  EXPECT_EQ(pressure("roller_hardness"), std::round(pivot / 1e6) * 1e6);  // 2961.61 → 2962 MPa
}

}  // namespace
}  // namespace catena
