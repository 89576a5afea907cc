// A regression check, not an external reference: the closed forms against golden data of the
// paper's example produced by Catena's own numerical solver (`--method numeric`;
// data/reference/pocketwheel_paper/README.md says how). The external reference, sharing no code
// with Catena, is tested in pocketwheel_independent_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "../read_text.hpp"
#include "catena/pocketwheel/run_on.hpp"

namespace catena::pocketwheel {
namespace {

constexpr double kPositionTol = 1e-11;  // [m]
constexpr double kVelocityTol = 1e-9;   // [m/s]
constexpr double kAccelTol = 1e-6;      // [m/s²]
constexpr double kEventGap = 1e-9;      // [rad]

std::map<std::string, std::vector<double>> read_csv(const std::string& path) {
  std::istringstream in(read_text(path));
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  std::stringstream header(line);
  for (std::string name; std::getline(header, name, ',');) names.push_back(name);
  std::map<std::string, std::vector<double>> columns;
  while (std::getline(in, line)) {
    std::stringstream row(line);
    std::string cell;
    for (std::size_t c = 0; std::getline(row, cell, ','); ++c)
      columns[names.at(c)].push_back(std::stod(cell));
  }
  return columns;
}

TEST(PocketwheelReference, ClosedFormsReproduceTheNumericalGoldenData) {
  const auto data =
      read_csv(std::string(CATENA_REFERENCE_DIR) + "/pocketwheel_paper/example_numeric.csv");
  ASSERT_EQ(data.at("phi").size(), 33u);
  const PocketWheel wheel{0.064, 0.018, 8};
  const double omega = 5.0;
  for (auto [kind, name] :
       {std::pair{GuideKind::kNone, "none"}, std::pair{GuideKind::kChordal, "chordal"},
        std::pair{GuideKind::kTangential, "tangential"}}) {
    const RunOnPlan plan = plan_run_on(wheel, Guide{kind, 0.0, 0.256, SpanModel::kSlider});
    const std::string s = std::string("_") + name;
    int compared = 0;
    for (std::size_t i = 0; i < data.at("phi").size(); ++i) {
      const double phi = data.at("phi")[i];
      bool at_event = false;
      for (const Phase& p : plan.phases)
        at_event |= std::abs(phi - p.end) < kEventGap || std::abs(phi - p.begin) < kEventGap;
      if (at_event) continue;
      const PointKinematics k = evaluate(plan, phi);
      EXPECT_NEAR(k.x, data.at("x" + s)[i], kPositionTol) << name << " phi " << phi;
      EXPECT_NEAR(omega * k.dx, data.at("vx" + s)[i], kVelocityTol) << name << " phi " << phi;
      EXPECT_NEAR(omega * omega * k.d2x, data.at("ax" + s)[i], kAccelTol) << name << " phi " << phi;
      ++compared;
    }
    EXPECT_GE(compared, 30) << name;
  }
}

}  // namespace
}  // namespace catena::pocketwheel
