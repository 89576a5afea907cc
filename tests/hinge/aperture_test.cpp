#include "catena/hinge/aperture.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <numbers>

#include "catena/hinge/synthesis.hpp"
#include "catena/io/drawing.hpp"
#include "examples.hpp"

namespace catena::hinge {
namespace {

Hinge example() { return testing::example_hinge(); }

constexpr double kArcTol = 1e-9;  // [m] distances to the plate's arc, radii ~1e-2 m: round-off
// [m] where the roller rolls on the plate's arc, the polygonal contour may cut the arc's chords
constexpr double kChordTol = 2e-6;
constexpr double kClearanceShare = 0.9;  // [1] share of the clearance the polygonal contour keeps
constexpr double kRelTol = 1e-12;        // [1] relative, radii: round-off

// Signed distance from p to the closed polygon (positive inside), by edges and crossings.
double inside_distance(const std::vector<Point>& poly, Point p) {
  bool inside = false;
  double best = 1e300;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const Point a = poly[j], b = poly[i];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x)
      inside = !inside;
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double t =
        std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
    best = std::min(best, std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy));
  }
  return inside ? best : -best;
}

class ApertureCase : public ::testing::TestWithParam<int> {};

TEST_P(ApertureCase, HoldsTheRollerInEveryPositionWithTheClearance) {
  Hinge h = example();
  if (GetParam() == 1) {  // flat faces with an offset contact
    h.face = Face::kFlat;
    h.face_half_length = 0.015;
    h.loaded_length = 0.012;
  } else if (GetParam() == 2) {  // a 12-tooth sprocket, thinner roller
    h.teeth = 12;
    h.half_thickness = 0.005;
    h.pin_diameter = 0.030;
    h.plate_radius = 0.012;
  }
  const double r2 = h.face == Face::kFlat
                        ? std::numeric_limits<double>::infinity()
                        : *r2_eq6(h.pin_diameter, h.half_thickness, h.plate_radius, gamma_max(h));
  const double c = 0.5e-3;
  const Aperture ap = aperture(h, r2, ApertureOptions{c, 1440, 361});
  ASSERT_GE(ap.contour.size(), 1440u);
  EXPECT_GT(ap.working_points, 10);
  const std::vector<Point> body = roller_outline(h, r2, 90);
  const double r1 = h.plate_radius;
  const Point o1{h.half_thickness + r1, h.face == Face::kFlat ? flat_contact_offset(h) : 0.0};
  // at turns between the construction's poses, too
  for (int k = 0; k <= 37; ++k) {
    const Pose p = pose(h, r2, 2 * gamma_max(h) * k / 37.0);
    for (const Point& q : body) {
      const Point w = roller_point(p, q);
      const double dist = inside_distance(ap.contour, w);
      const double to_arc = std::hypot(w.x - o1.x, w.y - o1.y) - r1;  // ≥ 0: not in the plate's arc
      EXPECT_GE(to_arc, -kArcTol);
      // inside with the clearance, except where the roller rolls on the plate's arc
      if (to_arc > c) {
        EXPECT_GE(dist, kClearanceShare * c)
            << "k " << k << " at " << w.x << ", " << w.y << " to_arc " << to_arc;
      } else {
        EXPECT_GE(dist, -kChordTol)
            << "k " << k << " at " << w.x << ", " << w.y << " to_arc " << to_arc;
      }
    }
  }
  // the hole does not cut into the plate's working arc (Ψ from −90° to the contact at φmax)
  const double psi_end = pose(h, r2, 2 * gamma_max(h)).psi1;
  for (const Point& q : ap.contour) {
    const double psi = std::atan2(q.y - o1.y, o1.x - q.x);
    if (psi >= -0.5 * std::numbers::pi && psi <= psi_end) {
      EXPECT_GE(std::hypot(q.x - o1.x, q.y - o1.y), r1 * (1 - kRelTol)) << psi;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Hinges, ApertureCase, ::testing::Values(0, 1, 2));

TEST(HingeAperture, DxfRoundTripKeepsTheClosedContourAndItsExtent) {
  const Hinge h = example();
  const double r2 = *r2_eq6(h.pin_diameter, h.half_thickness, h.plate_radius, gamma_max(h));
  const Aperture ap = aperture(h, r2);
  io::Drawing d;
  io::Polyline line{"APERTURE", {}, true};
  for (const Point& q : ap.contour) line.points.push_back({q.x, q.y});
  d.polylines.push_back(line);
  d.polylines.push_back({"OPEN", {{0.0, 0.0}, {0.001, 0.002}}, false});
  const auto path = std::filesystem::temp_directory_path() / "catena_aperture_test.dxf";
  io::write_dxf(path.string(), d);
  const std::vector<io::Polyline> back = io::read_dxf_polylines(path.string());
  std::filesystem::remove(path);
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[0].layer, "APERTURE");
  EXPECT_TRUE(back[0].closed);
  EXPECT_FALSE(back[1].closed);
  ASSERT_EQ(back[0].points.size(), ap.contour.size());
  double xmin = 1, xmax = -1, ymin = 1, ymax = -1, bxmin = 1, bxmax = -1, bymin = 1, bymax = -1;
  for (std::size_t i = 0; i < ap.contour.size(); ++i) {
    xmin = std::min(xmin, ap.contour[i].x), xmax = std::max(xmax, ap.contour[i].x);
    ymin = std::min(ymin, ap.contour[i].y), ymax = std::max(ymax, ap.contour[i].y);
    bxmin = std::min(bxmin, back[0].points[i].first),
    bxmax = std::max(bxmax, back[0].points[i].first);
    bymin = std::min(bymin, back[0].points[i].second),
    bymax = std::max(bymax, back[0].points[i].second);
  }
  constexpr double kDxfTol = 1e-9;  // [m] DXF keeps ~1e-6 mm
  EXPECT_NEAR(bxmin, xmin, kDxfTol);
  EXPECT_NEAR(bxmax, xmax, kDxfTol);
  EXPECT_NEAR(bymin, ymin, kDxfTol);
  EXPECT_NEAR(bymax, ymax, kDxfTol);
  // extent: the roller circle plus clearance bounds it below; the arc and the swept corners above
  constexpr double kExtentTol = 1e-6;  // [m] the contour's lowest vertex against the circle
  EXPECT_NEAR(ymin, -(0.5 * h.pin_diameter + 0.5e-3), kExtentTol);
  EXPECT_LE(xmax, h.half_thickness + h.plate_radius);
  EXPECT_GT(xmax, h.half_thickness);
}

TEST(HingeAperture, SvgIsAValidDocumentInMillimetres) {
  io::Drawing d;  // 10 mm × 20 mm, plus 5 mm margins: 20 mm × 30 mm
  d.polylines.push_back({"A", {{0.0, 0.0}, {0.01, 0.0}, {0.01, 0.02}}, true});
  const std::string svg = io::to_svg(d);
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_NE(svg.find("width=\"20mm\""), std::string::npos) << svg.substr(0, 400);
  EXPECT_NE(svg.find("height=\"30mm\""), std::string::npos) << svg.substr(0, 400);
  EXPECT_NE(svg.find("viewBox=\"0 0 20 30\""), std::string::npos) << svg.substr(0, 400);
}

}  // namespace
}  // namespace catena::hinge
