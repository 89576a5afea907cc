// Catena's closed forms of the pocket-wheel run-on (003) against an EXTERNAL reference that shares
// no code and no formula with Catena: data/reference/pocketwheel_independent/, produced by
// generate.py (Python standard library) from a link-by-link closure of the chain on the wheel —
// R as the root of the chords' closure, joints fixed to the wheel where they land, the guided
// point and the seating events by bisection, velocity and acceleration by fourth-order finite
// differences in time. Its README states how it was produced and its accuracy.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "../read_text.hpp"
#include "catena/pocketwheel/run_on.hpp"

namespace catena::pocketwheel {
namespace {

// Tolerances from the generator's error budget (README): positions are bisected to the last
// bit (~3e-17 m) and written with 17 digits; the differences use a time step of 0.8 ms, whose
// truncation and round-off the generator estimates (|h − 2h|/15) at 2.5e-11 m/s and
// 2.3e-10 m/s² for the example.
constexpr double kPositionTol = 1e-15;  // [m] bisection to round-off on lengths of ~0.3 m
constexpr double kVelocityTol = 2e-10;  // [m/s] 8× the estimated finite-difference error
constexpr double kAccelTol = 2e-9;      // [m/s²] 8× the estimated finite-difference error
constexpr double kAngleTol = 1e-13;     // [rad] seating events bisected to round-off
constexpr double kEventGap = 1e-9;      // [rad] a sample this close to an event is skipped

const std::string kDir = std::string(CATENA_REFERENCE_DIR) + "/pocketwheel_independent/";
const PocketWheel kWheel{0.064, 0.018, 8};  // 003: chain Ø18×64, z = 8
constexpr double kOmega = 5.0;              // [rad/s]
constexpr double kGuideEnd = 0.256;         // [m] l

std::vector<std::vector<std::string>> read_rows(const std::string& path) {
  std::istringstream in(read_text(path));
  std::vector<std::vector<std::string>> rows;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cells;
    std::stringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

std::map<std::string, std::vector<double>> read_columns(const std::string& path) {
  const auto rows = read_rows(path);
  std::map<std::string, std::vector<double>> columns;
  for (std::size_t r = 1; r < rows.size(); ++r)
    for (std::size_t c = 0; c < rows[r].size(); ++c)
      columns[rows[0].at(c)].push_back(std::stod(rows[r][c]));
  return columns;
}

std::map<std::string, double> read_events() {
  std::map<std::string, double> events;
  const auto rows = read_rows(kDir + "events.csv");
  for (std::size_t r = 1; r < rows.size(); ++r)
    events[rows[r].at(0) + "." + rows[r].at(1)] = std::stod(rows[r].at(2));
  return events;
}

RunOnPlan plan_for(GuideKind kind) {
  return plan_run_on(kWheel, Guide{kind, 0.0, kGuideEnd, SpanModel::kSlider});
}

TEST(PocketwheelIndependent, PitchRadiusGuideHeightAndSeatingsMatchTheClosedForms) {
  const auto e = read_events();
  const WheelGeometry g = wheel_geometry(kWheel);
  EXPECT_NEAR(e.at("all.pitch_radius_m"), g.pitch_radius, kPositionTol);  // 003 eq. (6)
  const RunOnPlan chordal = plan_for(GuideKind::kChordal);
  const RunOnPlan tangential = plan_for(GuideKind::kTangential);
  const RunOnPlan free = plan_for(GuideKind::kNone);
  EXPECT_NEAR(e.at("chordal.guide_height_m"), chordal.guide_height, kPositionTol);  // R cos(δ1/2)
  EXPECT_NEAR(e.at("tangential.guide_height_m"), tangential.guide_height, kPositionTol);  // R
  // The generator's events lie in (0, 2π/z); Catena also lists a chordal seating at φ = 0.
  ASSERT_EQ(free.seating_angles.size(), 2u);  // 0 and π/z
  EXPECT_NEAR(e.at("none.seating_rad_1"), free.seating_angles[1], kAngleTol);
  ASSERT_EQ(chordal.seating_angles.size(), 2u);  // 0 and 21.44°
  EXPECT_NEAR(e.at("chordal.seating_rad_1"), chordal.seating_angles[1], kAngleTol);
  ASSERT_EQ(tangential.seating_angles.size(), 2u);  // 15.85° and 37.57°
  EXPECT_NEAR(e.at("tangential.seating_rad_1"), tangential.seating_angles[0], kAngleTol);
  EXPECT_NEAR(e.at("tangential.seating_rad_2"), tangential.seating_angles[1], kAngleTol);
  EXPECT_EQ(e.count("tangential.seating_rad_3"), 0u);
  EXPECT_EQ(e.count("chordal.seating_rad_2"), 0u);
  // a check of the reference itself: its strand advances two pitches per period
  for (const char* name : {"none", "chordal", "tangential"})
    EXPECT_NEAR(e.at(std::string(name) + ".x_end_of_period_m"), 2 * kWheel.pitch, kPositionTol);
}

TEST(PocketwheelIndependent, ClosedFormsMatchTheLinkByLinkClosureOverThePeriod) {
  const auto data = read_columns(kDir + "run_on.csv");
  const std::vector<double>& phi = data.at("phi");
  ASSERT_EQ(phi.size(), 65u);
  const double period = 2 * std::numbers::pi / kWheel.teeth;
  for (auto [kind, name] :
       {std::pair{GuideKind::kNone, "none"}, std::pair{GuideKind::kChordal, "chordal"},
        std::pair{GuideKind::kTangential, "tangential"}}) {
    const RunOnPlan plan = plan_for(kind);
    const std::string s = std::string("_") + name;
    int compared = 0;
    for (std::size_t i = 0; i < phi.size(); ++i) {
      bool at_event = false;
      for (double event : plan.seating_angles) at_event |= std::abs(phi[i] - event) < kEventGap;
      if (at_event && phi[i] > 0) continue;  // φ = 0: both sides hold the right-hand limit
      // the generator's last sample is the left-hand limit at 2π/z (the end of the period)
      const PointKinematics k = i + 1 == phi.size()
                                    ? evaluate_phase(plan, plan.phases.size() - 1, period)
                                    : evaluate(plan, phi[i]);
      EXPECT_NEAR(k.x, data.at("x" + s)[i], kPositionTol) << name << " phi " << phi[i];
      EXPECT_NEAR(kOmega * k.dx, data.at("vx" + s)[i], kVelocityTol) << name << " phi " << phi[i];
      EXPECT_NEAR(kOmega * kOmega * k.d2x, data.at("ax" + s)[i], kAccelTol)
          << name << " phi " << phi[i];
      if (kind == GuideKind::kNone) {
        EXPECT_NEAR(kOmega * k.dy, data.at("vy_none")[i], kVelocityTol) << "phi " << phi[i];
        EXPECT_NEAR(kOmega * kOmega * k.d2y, data.at("ay_none")[i], kAccelTol) << "phi " << phi[i];
      }
      ++compared;
    }
    EXPECT_GE(compared, 63) << name;
  }
}

}  // namespace
}  // namespace catena::pocketwheel
