// Results that are not finite never reach the user as a silent null (issue 18): each reproducer
// of the issue exits 0 (the analysis ran) with an error diagnostic naming the field, in JSON and
// on stderr.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "cli_run.hpp"

namespace {

struct Case {
  const char* name;
  const char* args;
  const char* field;  ///< a field the diagnostic must name
};

class NonFiniteCli : public testing::TestWithParam<Case> {};

TEST_P(NonFiniteCli, IsAnErrorDiagnosticNamingTheField) {
  const Case& c = GetParam();
  const CliRun r = run(std::string(c.args) + " --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  bool named = false;
  for (const auto& d : j.at("diagnostics")) {
    if (d.at("code") != "result.non_finite") continue;
    EXPECT_EQ(d.at("severity"), "error");
    if (d.at("message").get<std::string>().find(std::string("'") + c.field + "'") !=
        std::string::npos)
      named = true;
  }
  EXPECT_TRUE(named) << c.field << " not named in\n" << j.at("diagnostics").dump(1);
  EXPECT_NE(r.err.find(std::string("catena: error: the result '") + c.field), std::string::npos)
      << r.err;
}

INSTANTIATE_TEST_SUITE_P(
    Issue18, NonFiniteCli,
    testing::Values(
        Case{"omega", "pocketwheel --pitch 64 --wire 18 --teeth 8 --omega 1e200", "series.ax"},
        Case{"gamma",
             "contact --chain 12B --tooth-radius 15.56 --load 1kN --skew 0.7 --gamma 1e300",
             "hertz_stress"},
        Case{"friction",
             "engagement --hinge sliding --pitch 125 --teeth 8 --tension 29.4kN --friction 1e300",
             "wrap.torque"},
        Case{"heights",
             "strength --heights 1e13 --widths 8 --pin-diameter 40 --plate-width 80 "
             "--end-distance 40 --tension 29.4kN --roller-yield 600 --plate-yield 355 "
             "--allowable-pressure 60",
             "layouts.layout_1.plate_force.lower_inner"}),
    [](const testing::TestParamInfo<Case>& p) { return std::string(p.param.name); });

}  // namespace
