// The ISO 606 tooth form: the check vector, the drawing measured back (the seating arc fitted,
// the roller seated without interference, the outline closed and simple), the flanks' meeting
// point solved another way, and properties over every catalogued chain and many tooth counts.
#include "catena/drive/sprocket.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "catena/catena.hpp"
#include "catena/contact/chain_catalog.hpp"
#include "catena/drive/analysis.hpp"

namespace catena::drive {
namespace {

using Point = std::pair<double, double>;
constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180;

// Tolerances.
constexpr double kPrintedTol = 0.5e-6;   // [m] a value printed to 0.001 mm: half its last digit
constexpr double kPrinted4Tol = 0.5e-7;  // [m] a value printed to 0.0001 mm
constexpr double kIssueTol = 0.05e-3;    // [m] the issue's "≈ 110.2 mm"
constexpr double kFitTol = 1e-9;         // [m] a circle fitted to exact arc samples (~1e-2 m)
constexpr double kFitAngleTol = 1e-9;    // [rad] the angle the fitted arc subtends
constexpr double kSameTol = 1e-12;       // [m] one point computed two ways (~5e-2 m)

SprocketInput chain_input(const std::string& name, int z) {
  const auto c = contact::iso606_chain(name);
  EXPECT_TRUE(c.has_value()) << name;
  return {c->pitch, *c->roller_diameter, *c->inner_width, z};
}

Sprocket b12_z17() { return sprocket(chain_input("12B", 17)); }

// --- the check vector ----------------------------------------------------------------------

// Bhandari, Design of Machine Elements, Ex. 14.5: 12B (p 19.05, d1 12.07, b1 11.68), z 17,
// d 103.674 mm and "Df 91.3248". The root diameter by the ISO definition is d − d1 = 91.604; the
// book's number is reproduced by d − 2 ri with ri the mean of ri,min and ri,max — derived below
// from the computed limits, not fitted.
TEST(Sprocket, BhandariCheckVector) {
  const Sprocket s = b12_z17();
  EXPECT_NEAR(s.pitch_diameter, 103.674e-3, kPrintedTol);
  EXPECT_NEAR(s.root_diameter, 103.674e-3 - 12.07e-3, kPrintedTol);  // 91.604, not the book's
  const double ri_mean = (s.seating_radius_min + s.seating_radius_max) / 2;
  EXPECT_NEAR(s.pitch_diameter - 2 * ri_mean, 91.3248e-3, kPrinted4Tol);
  // the same number is the middle of the reported seat diameters
  EXPECT_NEAR((s.seat_diameter_min + s.seat_diameter_max) / 2, 91.3248e-3, kPrinted4Tol);
  // and it is not d − d1: the two differ by more than the book's rounding
  EXPECT_GT(std::abs(s.root_diameter - 91.3248e-3), 100 * kPrinted4Tol);
}

// The formulas of the issue, each written out once more with 12B's numbers in mm.
TEST(Sprocket, FormulasFor12BZ17) {
  const Sprocket s = b12_z17();
  const double d = 19.05 / std::sin(kPi / 17);
  EXPECT_NEAR(s.seating_radius_min, 0.505 * 12.07e-3, 1e-15);
  EXPECT_NEAR(s.seating_radius_max, (0.505 * 12.07 + 0.069 * std::cbrt(12.07)) * 1e-3, 1e-15);
  EXPECT_NEAR(s.seating_angle_min, (120 - 90.0 / 17) * kDeg, 1e-15);
  EXPECT_NEAR(s.seating_angle_max, (140 - 90.0 / 17) * kDeg, 1e-15);
  EXPECT_NEAR(s.flank_radius_min, 0.12 * 12.07 * 19 * 1e-3, 1e-15);
  EXPECT_NEAR(s.flank_radius_max, 0.008 * 12.07 * (289 + 180) * 1e-3, 1e-15);
  EXPECT_NEAR(s.tip_diameter_max, (d + 1.25 * 19.05 - 12.07) * 1e-3, 1e-15);
  EXPECT_NEAR(s.tip_diameter_min, (d + 19.05 * (1 - 1.6 / 17) - 12.07) * 1e-3, 1e-15);
  EXPECT_NEAR(s.tip_diameter_max, 115.416e-3, kPrintedTol);  // the issue's 115.4
  // z odd: MR = d cos(90°/z) + d1
  EXPECT_NEAR(s.measurement_over_pins, (d * std::cos(90.0 / 17 * kDeg) + 12.07) * 1e-3, 1e-15);
  ASSERT_TRUE(s.tooth_width.has_value());
  EXPECT_NEAR(*s.tooth_width, 0.95 * 11.68e-3, 1e-15);
  EXPECT_DOUBLE_EQ(s.side_radius, 19.05e-3);
  EXPECT_NEAR(s.side_relief_min, 1.905e-3, 1e-15);
  EXPECT_NEAR(s.side_relief_max, 2.8575e-3, 1e-15);
  // z even: MR = d + d1
  const Sprocket e = sprocket(chain_input("12B", 18));
  EXPECT_NEAR(e.measurement_over_pins, e.pitch_diameter + 12.07e-3, 1e-15);
}

// --- the flanks' meeting point ------------------------------------------------------------

// Solved another way: the flank of gap 0 and the flank of gap 1 on the same tooth are two circles
// of radius re; their centres are mirror images about the tooth's centre line, and the flanks
// meet where the circles intersect (the outer of the two points). The centre of the flank is
// found here from the tangency alone: on the line from the roller centre through the end of the
// seating arc, re beyond it.
double meeting_by_circles(const Sprocket& s, double ri, double alpha, double re) {
  const int z = s.input.teeth;
  const double rp = s.pitch_diameter / 2;
  // end of the seating arc of gap 0, on the side of the tooth towards gap 1
  const double jx = rp - ri * std::cos(alpha / 2), jy = ri * std::sin(alpha / 2);
  const double ux = (jx - rp) / ri, uy = jy / ri;  // from the roller centre through it
  const double ex = jx + re * ux, ey = jy + re * uy;
  // gap 1's flank centre: the mirror image about the line at π/z
  const double b = 2 * kPi / z;
  const double fx = std::cos(b) * ex + std::sin(b) * ey, fy = std::sin(b) * ex - std::cos(b) * ey;
  const double mx = (ex + fx) / 2, my = (ey + fy) / 2;
  const double half = std::hypot(fx - ex, fy - ey) / 2;
  const double h = std::sqrt(re * re - half * half);
  const double nx = -(fy - ey) / (2 * half), ny = (fx - ex) / (2 * half);
  const double r1 = std::hypot(mx + h * nx, my + h * ny), r2 = std::hypot(mx - h * nx, my - h * ny);
  return 2 * std::max(r1, r2);
}

TEST(Sprocket, FlanksMeetingPointSolvedIndependently) {
  const Sprocket s = b12_z17();
  const double meet =
      meeting_by_circles(s, s.seating_radius_max, s.seating_angle_min, s.flank_radius_min);
  EXPECT_NEAR(s.max_gap.flank_meeting_diameter, meet, kSameTol);
  EXPECT_NEAR(meet, 110.2e-3, kIssueTol);  // the issue's ≈ 110.2 mm against da,max 115.4
  EXPECT_TRUE(s.max_gap.flanks_meet_below_tip);
  EXPECT_DOUBLE_EQ(s.max_gap.outline_tip_diameter, s.max_gap.flank_meeting_diameter);
  // the minimum gap form's flanks meet above da,max: its outline ends on the tip circle
  const double meet_min =
      meeting_by_circles(s, s.seating_radius_min, s.seating_angle_max, s.flank_radius_max);
  EXPECT_NEAR(s.min_gap.flank_meeting_diameter, meet_min, kSameTol);
  EXPECT_GT(meet_min, s.tip_diameter_max);
  EXPECT_FALSE(s.min_gap.flanks_meet_below_tip);
  EXPECT_DOUBLE_EQ(s.min_gap.outline_tip_diameter, s.tip_diameter_max);
}

// The issue: likewise for z 9–40 of 08A, 08B, 12B, 16B.
TEST(Sprocket, MaxGapFlanksMeetBelowTipForTheIssuesChains) {
  for (const char* name : {"08A", "08B", "12B", "16B"}) {
    for (int z = 9; z <= 40; ++z) {
      const Sprocket s = sprocket(chain_input(name, z));
      EXPECT_TRUE(s.max_gap.flanks_meet_below_tip) << name << " z " << z;
      EXPECT_NEAR(
          s.max_gap.flank_meeting_diameter,
          meeting_by_circles(s, s.seating_radius_max, s.seating_angle_min, s.flank_radius_min),
          kSameTol)
          << name << " z " << z;
    }
  }
}

// --- the drawing measured back ----------------------------------------------------------------

const Polyline& layer(const Drawing& d, const std::string& name) {
  for (const Polyline& p : d.polylines)
    if (p.layer == name) return p;
  throw std::runtime_error("no layer " + name);
}

// The circle through three points: centre and radius (radius inf for collinear points).
struct Circle {
  double x = 0, y = 0, r = INFINITY;
};
Circle through(Point a, Point b, Point c) {
  const double d = 2 * (a.first * (b.second - c.second) + b.first * (c.second - a.second) +
                        c.first * (a.second - b.second));
  if (d == 0) return {};
  const double a2 = a.first * a.first + a.second * a.second;
  const double b2 = b.first * b.first + b.second * b.second;
  const double c2 = c.first * c.first + c.second * c.second;
  Circle o;
  o.x = (a2 * (b.second - c.second) + b2 * (c.second - a.second) + c2 * (a.second - b.second)) / d;
  o.y = (a2 * (c.first - b.first) + b2 * (a.first - c.first) + c2 * (b.first - a.first)) / d;
  o.r = std::hypot(a.first - o.x, a.second - o.y);
  return o;
}

// Least-squares circle (Kåsa): minimises Σ (x² + y² + D x + E y + F)², normal equations 3×3.
Circle fit(const std::vector<Point>& pts) {
  double m[3][4] = {};
  for (const auto& [x, y] : pts) {
    const double row[3] = {x, y, 1.0}, rhs = -(x * x + y * y);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) m[i][j] += row[i] * row[j];
      m[i][3] += row[i] * rhs;
    }
  }
  for (int c = 0; c < 3; ++c) {  // Gauss–Jordan with partial pivoting
    int piv = c;
    for (int r = c + 1; r < 3; ++r)
      if (std::abs(m[r][c]) > std::abs(m[piv][c])) piv = r;
    for (int k = 0; k < 4; ++k) std::swap(m[c][k], m[piv][k]);
    for (int r = 0; r < 3; ++r) {
      if (r == c) continue;
      const double f = m[r][c] / m[c][c];
      for (int k = 0; k < 4; ++k) m[r][k] -= f * m[c][k];
    }
  }
  const double dd = m[0][3] / m[0][0], ee = m[1][3] / m[1][1], ff = m[2][3] / m[2][2];
  Circle o;
  o.x = -dd / 2;
  o.y = -ee / 2;
  o.r = std::sqrt(o.x * o.x + o.y * o.y - ff);
  return o;
}

// The seating arc of the gap whose bottom is nearest to polar angle `angle`: the contiguous run
// of vertices whose three-point circle has the bottom vertex's radius, and one more vertex at
// each end (the arc's end points, shared with the flanks).
std::vector<Point> seat_run(const std::vector<Point>& pts, double angle) {
  const std::size_t n = pts.size();
  auto at = [&](std::ptrdiff_t i) {
    return pts[static_cast<std::size_t>(
        (i % static_cast<std::ptrdiff_t>(n) + static_cast<std::ptrdiff_t>(n)) %
        static_cast<std::ptrdiff_t>(n))];
  };
  // the bottom: the vertex nearest the centre among those within half a pitch of `angle`
  std::ptrdiff_t bottom = -1;
  double best = INFINITY;
  for (std::size_t i = 0; i < n; ++i) {
    double da = std::atan2(pts[i].second, pts[i].first) - angle;
    da = std::remainder(da, 2 * kPi);
    if (std::abs(da) > 0.2) continue;
    const double r = std::hypot(pts[i].first, pts[i].second);
    if (r < best) best = r, bottom = static_cast<std::ptrdiff_t>(i);
  }
  auto radius = [&](std::ptrdiff_t i) { return through(at(i - 1), at(i), at(i + 1)).r; };
  const double r0 = radius(bottom);
  std::ptrdiff_t lo = bottom, hi = bottom;
  while (std::abs(radius(lo - 1) - r0) < 1e-9 * r0) --lo;
  while (std::abs(radius(hi + 1) - r0) < 1e-9 * r0) ++hi;
  std::vector<Point> run;
  for (std::ptrdiff_t i = lo - 1; i <= hi + 1; ++i) run.push_back(at(i));
  return run;
}

double distance_to_segment(Point p, Point a, Point b) {
  const double vx = b.first - a.first, vy = b.second - a.second;
  const double t = std::clamp(
      ((p.first - a.first) * vx + (p.second - a.second) * vy) / (vx * vx + vy * vy), 0.0, 1.0);
  return std::hypot(p.first - a.first - t * vx, p.second - a.second - t * vy);
}

double distance_to_outline(Point p, const std::vector<Point>& pts) {
  double best = INFINITY;
  for (std::size_t i = 0; i < pts.size(); ++i)
    best = std::min(best, distance_to_segment(p, pts[i], pts[(i + 1) % pts.size()]));
  return best;
}

bool segments_cross(Point a, Point b, Point c, Point d) {
  auto orient = [](Point p, Point q, Point r) {
    const double v =
        (q.first - p.first) * (r.second - p.second) - (q.second - p.second) * (r.first - p.first);
    return (v > 0) - (v < 0);
  };
  return orient(a, b, c) * orient(a, b, d) <= 0 && orient(c, d, a) * orient(c, d, b) <= 0;
}

// Simple: no two segments that do not share a vertex touch or cross (brute force).
bool simple(const std::vector<Point>& pts) {
  const std::size_t n = pts.size();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // neighbours across the closing segment
      if (segments_cross(pts[i], pts[i + 1], pts[j], pts[(j + 1) % n])) return false;
    }
  }
  return true;
}

// Star-shaped about the centre with the polar angle strictly increasing once around: a closed
// polygon that is simple (the cheap test for the property sweep).
bool star_shaped(const std::vector<Point>& pts) {
  double total = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Point a = pts[i], b = pts[(i + 1) % pts.size()];
    const double step = std::atan2(a.first * b.second - a.second * b.first,
                                   a.first * b.first + a.second * b.second);
    if (!(step > 0)) return false;
    total += step;
  }
  return std::abs(total - 2 * kPi) < 1e-9;
}

TEST(SprocketDrawing, SeatingArcFittedBackHasTheComputedRadiusAndAngle) {
  const Sprocket s = b12_z17();
  const Drawing d = sprocket_drawing(s);
  for (const auto& [name, form] :
       {std::pair{"OUTLINE_MIN_GAP", &s.min_gap}, std::pair{"OUTLINE_MAX_GAP", &s.max_gap}}) {
    const Polyline& p = layer(d, name);
    EXPECT_TRUE(p.closed) << name;
    for (int gap : {0, 5, 16}) {
      const double angle = 2 * kPi * gap / 17;
      const std::vector<Point> run = seat_run(p.points, angle);
      const Circle c = fit(run);
      EXPECT_NEAR(c.r, form->seating_radius, kFitTol) << name << " gap " << gap;
      // its centre is the roller's seat on the pitch circle
      EXPECT_NEAR(c.x, s.pitch_diameter / 2 * std::cos(angle), kFitTol) << name;
      EXPECT_NEAR(c.y, s.pitch_diameter / 2 * std::sin(angle), kFitTol) << name;
      // the angle the arc subtends at its centre, end to end
      const Point a = run.front(), b = run.back();
      const double subtended = std::acos(
          ((a.first - c.x) * (b.first - c.x) + (a.second - c.y) * (b.second - c.y)) / (c.r * c.r));
      EXPECT_NEAR(subtended, form->seating_angle, kFitAngleTol) << name << " gap " << gap;
    }
    // the seat bottom lies at d − 2 ri; the outline's outermost point is the reported tip
    double rmin = INFINITY, rmax = 0;
    for (const auto& [x, y] : p.points) {
      rmin = std::min(rmin, std::hypot(x, y));
      rmax = std::max(rmax, std::hypot(x, y));
    }
    EXPECT_NEAR(2 * rmin, s.pitch_diameter - 2 * form->seating_radius, kFitTol) << name;
    EXPECT_NEAR(2 * rmax, form->outline_tip_diameter, kFitTol) << name;
  }
  // the circles drawn are the pitch and the root circle
  const Polyline& pitch = layer(d, "PITCH_CIRCLE");
  const Polyline& root = layer(d, "ROOT_CIRCLE");
  EXPECT_NEAR(2 * std::hypot(pitch.points[7].first, pitch.points[7].second), s.pitch_diameter,
              kSameTol);
  EXPECT_NEAR(2 * std::hypot(root.points[7].first, root.points[7].second), s.root_diameter,
              kSameTol);
}

TEST(SprocketDrawing, RollerSeatsInBothFormsWithoutInterference) {
  const Sprocket s = b12_z17();
  const Drawing d = sprocket_drawing(s);
  const double r1 = s.input.roller_diameter / 2;
  for (const auto& [name, form] :
       {std::pair{"OUTLINE_MIN_GAP", &s.min_gap}, std::pair{"OUTLINE_MAX_GAP", &s.max_gap}}) {
    const Polyline& p = layer(d, name);
    for (int gap = 0; gap < 17; ++gap) {
      const double a = 2 * kPi * gap / 17;
      const Point centre{s.pitch_diameter / 2 * std::cos(a), s.pitch_diameter / 2 * std::sin(a)};
      const double gap_to_outline = distance_to_outline(centre, p.points);
      EXPECT_GE(gap_to_outline, r1) << name << " gap " << gap;  // no interference
      // and it sits in its seat: the outline nearest to the roller's centre is the seating arc,
      // ri away (its chords a little nearer: sag 1 − cos(1.4°) < 1e-3), not a flank or a tooth
      EXPECT_LE(gap_to_outline, form->seating_radius) << name << " gap " << gap;
      EXPECT_GT(gap_to_outline, (1 - 1e-3) * form->seating_radius) << name << " gap " << gap;
    }
  }
}

TEST(SprocketDrawing, OutlineIsClosedAndSimple) {
  for (int z : {6, 17, 40}) {
    const Sprocket s = sprocket(chain_input("12B", z));
    const Drawing d = sprocket_drawing(s);
    for (const char* name : {"OUTLINE_MIN_GAP", "OUTLINE_MAX_GAP"}) {
      const Polyline& p = layer(d, name);
      ASSERT_TRUE(p.closed);
      EXPECT_TRUE(simple(p.points)) << name << " z " << z;
      EXPECT_TRUE(star_shaped(p.points)) << name << " z " << z;
      // the closing segment is as short as the others: the outline returns to its start
      const double close = std::hypot(p.points.back().first - p.points.front().first,
                                      p.points.back().second - p.points.front().second);
      double longest = 0;
      for (std::size_t i = 0; i + 1 < p.points.size(); ++i)
        longest = std::max(longest, std::hypot(p.points[i + 1].first - p.points[i].first,
                                               p.points[i + 1].second - p.points[i].second));
      EXPECT_LE(close, longest) << name;
      EXPECT_GT(close, 0) << name;  // no repeated point
    }
  }
}

// The test can fail: a figure-eight is not simple, a repeated loop is not star-shaped once.
TEST(SprocketDrawing, TheSimplicityChecksRejectBadOutlines) {
  EXPECT_FALSE(simple({{0, 0}, {1, 1}, {1, 0}, {0, 1}}));
  EXPECT_TRUE(simple({{0, 0}, {1, 0}, {1, 1}, {0, 1}}));
  EXPECT_FALSE(star_shaped({{1, 0}, {0, 1}, {-1, 0}, {0, -1}, {1, 0.1}, {0, 1}, {-1, 0}, {0, -1}}));
}

// --- properties -----------------------------------------------------------------------------

TEST(SprocketProperties, EveryCataloguedChainAndRandomToothCounts) {
  std::mt19937 rng(606);
  std::uniform_int_distribution<int> teeth(6, 150);
  int cases = 0;
  for (const std::string& name : contact::iso606_names()) {
    std::vector<int> zs = {6, 7, 150};
    for (int i = 0; i < 12; ++i) zs.push_back(teeth(rng));
    for (int z : zs) {
      SCOPED_TRACE(name + " z " + std::to_string(z));
      const Sprocket s = sprocket(chain_input(name, z));
      for (double v : {s.pitch_diameter, s.root_diameter, s.seat_diameter_min, s.seat_diameter_max,
                       s.tip_diameter_min, s.tip_diameter_max, s.seating_radius_min,
                       s.seating_radius_max, s.seating_angle_min, s.seating_angle_max,
                       s.flank_radius_min, s.flank_radius_max, s.measurement_over_pins,
                       s.min_gap.flank_meeting_diameter, s.max_gap.flank_meeting_diameter})
        ASSERT_TRUE(std::isfinite(v) && v > 0);
      EXPECT_LT(s.seat_diameter_min, s.seat_diameter_max);
      EXPECT_LT(s.seat_diameter_max, s.root_diameter);  // ri > d1/2
      EXPECT_LT(s.root_diameter, s.pitch_diameter);
      EXPECT_LT(s.tip_diameter_min, s.tip_diameter_max);
      EXPECT_LT(s.seating_radius_min, s.seating_radius_max);
      EXPECT_LT(s.seating_angle_min, s.seating_angle_max);
      EXPECT_LT(s.flank_radius_min, s.flank_radius_max);
      EXPECT_GT(s.measurement_over_pins, s.pitch_diameter);
      // the maximum gap is the larger gap: it ends lower than the minimum gap form
      EXPECT_LE(s.max_gap.outline_tip_diameter, s.min_gap.outline_tip_diameter);
      for (const GapForm* f : {&s.min_gap, &s.max_gap}) {
        EXPECT_LE(f->outline_tip_diameter, s.tip_diameter_max);
        EXPECT_GT(f->outline_tip_diameter, s.pitch_diameter);
        const std::vector<Point> pts = tooth_outline(s, *f, 8);
        EXPECT_TRUE(star_shaped(pts));
        // the first roller: seated, no interference
        const double gap = distance_to_outline({s.pitch_diameter / 2, 0.0}, pts);
        EXPECT_GE(gap, s.input.roller_diameter / 2);
      }
      ++cases;
    }
  }
  EXPECT_EQ(cases, 15 * static_cast<int>(contact::iso606_names().size()));
}

// --- inputs and the analysis ----------------------------------------------------------------

TEST(Sprocket, InvalidInputNamesTheFieldAndTheRange) {
  SprocketInput in = chain_input("12B", 5);
  in.roller_diameter = 20e-3;
  in.strands = 0;
  try {
    (void)sprocket(in);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    ASSERT_EQ(e.issues().size(), 3u);
    EXPECT_EQ(e.issues()[0].field, "roller_diameter");
    EXPECT_NE(e.issues()[0].expected.find("d1 < p"), std::string::npos);
    EXPECT_EQ(e.issues()[1].field, "teeth");
    EXPECT_EQ(e.issues()[1].expected, "a tooth count z from 6 to 500");
    EXPECT_EQ(e.issues()[2].field, "strands");
  }
}

TEST(SprocketAnalysis, ThroughTheRegistry) {
  const analysis::Record r = catena::run("sprocket", {{"chain", "12B"}, {"teeth", "17"}});
  const analysis::Value& j = r.data;
  EXPECT_NEAR(j.at("pitch_diameter").as_number(), 103.674e-3, kPrintedTol);
  for (const char* key :
       {"seat_diameter", "tip_diameter", "seating_radius", "seating_angle", "flank_radius"}) {
    EXPECT_LT(j.at(key).at("min").as_number(), j.at(key).at("max").as_number()) << key;
  }
  EXPECT_NEAR(j.at("tooth_width").as_number(), 0.95 * 11.68e-3, 1e-15);
  EXPECT_EQ(unit_of(j, "seating_angle"), "rad");
  ASSERT_EQ(r.drawings.size(), 1u);
  bool meets = false;
  for (const Diagnostic& d : r.diagnostics)
    meets = meets || d.code == "sprocket.flanks_meet_below_tip";
  EXPECT_TRUE(meets);
}

TEST(SprocketAnalysis, ToothWidthOutsideTheSourcedCaseIsAbsentWithAReason) {
  // p = 12.7 mm: the 0.95 factor does not apply and no other factor is sourced
  const analysis::Record r = catena::run("sprocket", {{"chain", "08B"}, {"teeth", "20"}});
  EXPECT_TRUE(r.data.at("tooth_width").is_null());
  bool said = false;
  for (const Diagnostic& d : r.diagnostics)
    said = said || d.code == "sprocket.tooth_width_unsourced";
  EXPECT_TRUE(said);
  // two strands: neither bf1 nor the width over the strands without a sourced factor and pt
  const analysis::Record two =
      catena::run("sprocket", {{"chain", "12B"}, {"teeth", "20"}, {"strands", "2"}});
  EXPECT_TRUE(two.data.at("tooth_width").is_null());
  EXPECT_TRUE(two.data.at("strand_width").is_null());
  // given bf1 and pt: bf(k) = pt (k − 1) + bf1
  const analysis::Record given = catena::run("sprocket", {{"chain", "12B"},
                                                          {"teeth", "20"},
                                                          {"strands", "3"},
                                                          {"tooth_width", "10.8mm"},
                                                          {"transverse_pitch", "19.46mm"}});
  EXPECT_NEAR(given.data.at("strand_width").as_number(), 19.46e-3 * 2 + 10.8e-3, 1e-15);
}

TEST(SprocketAnalysis, UnknownChainAndMissingLengthsAreRefused) {
  EXPECT_THROW((void)catena::run("sprocket", {{"chain", "99X"}, {"teeth", "17"}}), InputError);
  try {
    (void)catena::run("sprocket", {{"pitch", "19.05mm"}, {"teeth", "17"}});
    FAIL();
  } catch (const InputError& e) {
    ASSERT_EQ(e.issues().size(), 2u);
    EXPECT_EQ(e.issues()[0].field, "roller_diameter");
    EXPECT_EQ(e.issues()[1].field, "inner_width");
  }
}

}  // namespace
}  // namespace catena::drive
