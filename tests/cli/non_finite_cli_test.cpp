// Results that are not finite never reach the user as a silent null (issue 18). The issue's
// reproducers overflowed through inputs far outside any design; those inputs are now refused at
// the boundary (exit 2, the flag and its range named, nothing run). The diagnostic that a
// non-finite result still gets is tested on Records directly (analysis_test.cpp: NonFinite.*)
// and on every fuzzed input (tests/fuzz).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "cli_run.hpp"

namespace {

struct Case {
  const char* name;
  const char* args;
  const char* message;  ///< the refusal: the flag and its range
};

class OverflowingInputCli : public testing::TestWithParam<Case> {};

TEST_P(OverflowingInputCli, IsRefusedAtTheBoundaryWithItsRange) {
  const Case& c = GetParam();
  const CliRun r = run(std::string(c.args) + " --format json");
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
}

INSTANTIATE_TEST_SUITE_P(
    Issue18, OverflowingInputCli,
    testing::Values(
        Case{"omega", "pocketwheel --pitch 64 --wire 18 --teeth 8 --omega 1e200",
             "expected a wheel speed 0 < omega <= 10000 rad/s"},
        Case{"gamma",
             "contact --chain 12B --tooth-radius 15.56 --load 1kN --skew 0.7 --gamma 1e300",
             "--gamma = 1e300: expected γ ≤ 1 per arcmin²"},
        Case{"friction",
             "engagement --hinge sliding --pitch 125 --teeth 8 --tension 29.4kN --friction 1e300",
             "expected a friction factor 0 <= f <= 1"},
        Case{"heights",
             "strength --heights 1e13 --widths 8 --pin-diameter 40 --plate-width 80 "
             "--end-distance 40 --tension 29.4kN --roller-yield 600 --plate-yield 355 "
             "--allowable-pressure 60",
             "--heights = (over 10 m): expected plate mid-plane heights |h| ≤ 10 m"}),
    [](const testing::TestParamInfo<Case>& p) { return std::string(p.param.name); });

// At the edge of each range the analyses run and every result is finite (no diagnostic).
TEST(OverflowingInputCli, AtTheEdgeOfTheRangesTheResultsAreFinite) {
  for (const char* args :
       {"pocketwheel --pitch 64 --wire 18 --teeth 8 --omega 10000",
        "contact --chain 12B --tooth-radius 15.56 --load 1kN --skew 0.7 --gamma 1",
        "engagement --hinge sliding --pitch 125 --teeth 8 --tension 29.4kN --friction 1"}) {
    const CliRun r = run(std::string(args) + " --format json");
    ASSERT_EQ(r.status, 0) << args << "\n" << r.err;
    EXPECT_EQ(r.out.find("result.non_finite"), std::string::npos) << args;
  }
}

}  // namespace
