// The layout functions' input checks (include/catena/drive/layout.hpp, "Valid input"): each bad
// argument alone is refused with its name and valid range, several at once in one message, the
// ranges' ends are accepted, and random valid input never throws and gives finite output.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "catena/drive/layout.hpp"

namespace catena::drive {
namespace {

constexpr double kP = 0.01905;  // [m] 12B pitch
const double kNan = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

// The message of the std::invalid_argument `call` throws; empty if it returned.
std::string refusal(const std::function<void()>& call) {
  try {
    call();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// `text` refuses exactly one argument, `field`, naming `range`, from `function`.
void expect_one(const std::string& text, const std::string& function, const std::string& field,
                const std::string& range, const std::string& what) {
  EXPECT_TRUE(contains(text, function + ": 1 invalid argument(s):")) << what << ": " << text;
  EXPECT_TRUE(contains(text, "\n  " + field + " = ")) << what << ": " << text;
  EXPECT_TRUE(contains(text, ": expected " + range)) << what << ": " << text;
}

// `text` names every one of `fields`, in that order, and says how many.
void expect_all(const std::string& text, const std::string& function,
                const std::vector<std::string>& fields) {
  EXPECT_TRUE(
      contains(text, function + ": " + std::to_string(fields.size()) + " invalid argument(s):"))
      << text;
  std::size_t at = 0;
  for (const std::string& field : fields) {
    const std::size_t next = text.find("\n  " + field + " = ", at);
    EXPECT_NE(next, std::string::npos) << field << ": " << text;
    if (next != std::string::npos) at = next + 1;
  }
}

// Every function that takes a pitch and two tooth counts, called with these and otherwise valid
// arguments (a centre distance of 40 pitches, 100 links).
struct Sprockets {
  const char* function;
  std::function<void(double, int, int)> call;
};
const std::vector<Sprockets>& two_sprocket_functions() {
  static const std::vector<Sprockets> all = {
      {"links_for", [](double p, int z1, int z2) { (void)links_for(p, z1, z2, 40 * kP); }},
      {"center_distance_formula",
       [](double p, int z1, int z2) { (void)center_distance_formula(p, z1, z2, 100); }},
      {"polygon_hull",
       [](double p, int z1, int z2) { (void)polygon_hull(p, z1, z2, 40 * kP, 0.1, 0.2); }},
      {"polygon_wrap", [](double p, int z1, int z2) { (void)polygon_wrap(p, z1, z2, 100, 0.1); }},
      {"exact_center_distance",
       [](double p, int z1, int z2) { (void)exact_center_distance(p, z1, z2, 100); }},
      {"shaft_loads",
       [](double p, int z1, int z2) { (void)shaft_loads(p, z1, z2, 40 * kP, 5000, 400, 300); }},
      {"span_angle", [](double p, int z1, int z2) { (void)span_angle(p, z1, z2, 40 * kP); }},
      {"wrap_pins",
       [](double p, int z1, int z2) {
         PolygonWrap w;
         w.center_distance = 40 * kP;
         w.wrap1 = 1;
         w.seat1_out = 1;
         w.span_lower = w.span_upper = 40;
         (void)wrap_pins(w, p, z1, z2);
       }},
  };
  return all;
}

const std::vector<double> kBadPitches = {kNan, kInf, -kInf, 0.0, -0.01, 1e-91, 1e91};
const std::vector<int> kBadTeeth = {
    0, -1, 2, 1001, std::numeric_limits<int>::min(), std::numeric_limits<int>::max()};

TEST(DriveLayoutInput, RefusesABadPitchOrToothCount) {
  int refused = 0;
  for (double p : kBadPitches) {
    const std::string what = "pitch " + std::to_string(p);
    const std::string text = refusal([&] { (void)pitch_radius(p, 17); });
    expect_one(text, "pitch_radius", "pitch", "1e-90 m to 1e+90 m", what);
    refused += !text.empty();
    for (const Sprockets& f : two_sprocket_functions()) {
      const std::string t = refusal([&] { f.call(p, 17, 34); });
      expect_one(t, f.function, "pitch", "1e-90 m to 1e+90 m", what);
      refused += !t.empty();
    }
  }
  for (int z : kBadTeeth) {
    const std::string what = "teeth " + std::to_string(z);
    const std::string text = refusal([&] { (void)pitch_radius(kP, z); });
    expect_one(text, "pitch_radius", "teeth", "3 to 1000 teeth", what);
    refused += !text.empty();
    for (const Sprockets& f : two_sprocket_functions()) {
      const std::string t1 = refusal([&] { f.call(kP, z, 34); });
      expect_one(t1, f.function, "z1", "3 to 1000 teeth", what);
      const std::string t2 = refusal([&] { f.call(kP, 17, z); });
      expect_one(t2, f.function, "z2", "3 to 1000 teeth", what);
      refused += !t1.empty() + !t2.empty();
    }
  }
  EXPECT_EQ(refused, 7 * 9 + 6 * 17);
}

// The centre distance: links_for takes any 1e-9 p ≤ a ≤ 1e100 m (below, Δ²p/a grows to
// infinity: 1e-320 m gave inf); the others need the pitch circles apart (12B, 17/34 teeth:
// r1 + r2 = 155.1 mm).
TEST(DriveLayoutInput, RefusesABadCentreDistance) {
  const double touch = pitch_radius(kP, 17) + pitch_radius(kP, 34);
  for (double a : {kNan, kInf, -kInf, 0.0, -0.5, 2e100, 1e-320, 1e-12, 0.999e-9 * kP}) {
    expect_one(refusal([&] { (void)links_for(kP, 17, 34, a); }), "links_for", "center_distance",
               "at least 1e-9 pitch = 1.905e-11 m, at most 1e+100 m", std::to_string(a));
  }
  EXPECT_TRUE(std::isfinite(links_for(kP, 17, 34, 1e-9 * kP)));
  EXPECT_TRUE(std::isfinite(links_for(kMaxPitch, 3, kMaxTeeth, 1e-9 * kMaxPitch)));
  const std::string apart =
      "more than r1 + r2 = 0.155068 m (the pitch circles apart), at most "
      "1e+100 m";
  for (double a : {kNan, kInf, -kInf, 0.0, -0.5, 0.5 * touch, touch, 2e100}) {
    const std::string what = "a " + std::to_string(a);
    expect_one(refusal([&] { (void)polygon_hull(kP, 17, 34, a, 0.1, 0.2); }), "polygon_hull",
               "center_distance", apart, what);
    expect_one(refusal([&] { (void)span_angle(kP, 17, 34, a); }), "span_angle", "center_distance",
               apart, what);
    expect_one(refusal([&] { (void)shaft_loads(kP, 17, 34, a, 5000, 400, 300); }), "shaft_loads",
               "center_distance", apart, what);
  }
  // touching or overlapping pitch circles still have a textbook link count
  EXPECT_TRUE(std::isfinite(links_for(kP, 17, 34, touch)));
  EXPECT_TRUE(std::isfinite(links_for(kP, 17, 34, 0.1 * touch)));
}

TEST(DriveLayoutInput, RefusesABadLinkCount) {
  for (double x : {kNan, kInf, -kInf, 0.0, 1e-300, 1e-9, -3.0, 2147483647.0, 1e300}) {
    expect_one(refusal([&] { (void)round_up_even(x); }), "round_up_even", "links",
               "more than 1e-9, at most 2147483646", std::to_string(x));
  }
  for (double x : {kNan, kInf, -kInf, 0.0, -5.0, 2e100}) {
    expect_one(refusal([&] { (void)center_distance_formula(kP, 17, 34, x); }),
               "center_distance_formula", "links", "more than 0, at most 1e+100",
               std::to_string(x));
  }
  for (int x : {0, 1, -2, 100001, std::numeric_limits<int>::min()}) {
    const std::string what = "links " + std::to_string(x);
    expect_one(refusal([&] { (void)polygon_wrap(kP, 17, 34, x, 0.1); }), "polygon_wrap", "links",
               "2 to 100000 links", what);
    expect_one(refusal([&] { (void)exact_center_distance(kP, 17, 34, x); }),
               "exact_center_distance", "links", "2 to 100000 links", what);
  }
  // too few links for a real root: NaN, as documented (valid input, an impossible design)
  EXPECT_TRUE(std::isnan(center_distance_formula(kP, 17, 34, 20)));
  // too short a chain, within the range: still std::domain_error
  EXPECT_THROW((void)polygon_wrap(kP, 17, 34, 20, 0.1), std::domain_error);
}

TEST(DriveLayoutInput, RefusesABadPhaseOrForce) {
  for (double v : {kNan, kInf, -kInf}) {
    const std::string what = std::to_string(v);
    expect_one(refusal([&] { (void)polygon_hull(kP, 17, 34, 0.6, v, 0.2); }), "polygon_hull",
               "phase1", "a finite value", what);
    expect_one(refusal([&] { (void)polygon_hull(kP, 17, 34, 0.6, 0.1, v); }), "polygon_hull",
               "phase2", "a finite value", what);
    expect_one(refusal([&] { (void)polygon_wrap(kP, 17, 34, 100, v); }), "polygon_wrap", "phase1",
               "a finite value", what);
  }
  const std::string range = "a finite value within ±1e+307 N";
  for (double v : {kNan, kInf, -kInf, 2e307, -2e307}) {
    const std::string what = std::to_string(v);
    expect_one(refusal([&] { (void)shaft_loads(kP, 17, 34, 0.6, v, 400, 300); }), "shaft_loads",
               "tight", range, what);
    expect_one(refusal([&] { (void)shaft_loads(kP, 17, 34, 0.6, 5000, v, 300); }), "shaft_loads",
               "slack", range, what);
    expect_one(refusal([&] { (void)shaft_loads(kP, 17, 34, 0.6, 5000, 400, v); }), "shaft_loads",
               "centrifugal", range, what);
  }
}

// wrap_pins: a wrap as polygon_wrap solved it passes; each field spoiled alone is named.
TEST(DriveLayoutInput, WrapPinsRefusesAWrapItCannotDraw) {
  const int z1 = 17, z2 = 34, links = 100;
  const PolygonWrap good = polygon_wrap(kP, z1, z2, links, 0.1);
  EXPECT_EQ(wrap_pins(good, kP, z1, z2).size(), static_cast<std::size_t>(links + 1));
  struct Case {
    const char* field;
    const char* range;
    std::function<void(PolygonWrap&)> spoil;
  };
  const std::vector<Case> cases = {
      {"w.center_distance", "more than r1 + r2 = 0.155068 m",
       [](PolygonWrap& w) { w.center_distance = 0.1; }},
      {"w.center_distance", "more than r1 + r2", [](PolygonWrap& w) { w.center_distance = kNan; }},
      {"w.phase1", "a finite value", [](PolygonWrap& w) { w.phase1 = kInf; }},
      {"w.phase2", "a finite value", [](PolygonWrap& w) { w.phase2 = kNan; }},
      {"w.seat1_in", "0 to 16", [](PolygonWrap& w) { w.seat1_in = -1; }},
      {"w.seat2_in", "0 to 33", [](PolygonWrap& w) { w.seat2_in = 34; }},
      {"w.seat1_out", "0 to 16", [](PolygonWrap& w) { w.seat1_out = 17; }},
      {"w.wrap2", "0 to 33", [](PolygonWrap& w) { w.wrap2 = 40; }},
      {"w.seat1_out", "(w.seat1_in + w.wrap1) mod z1 = ",
       [](PolygonWrap& w) { w.seat1_out = (w.seat1_out + 1) % 17; }},
      {"w.seat2_out",
       "(w.seat2_in + w.wrap2) mod z2 = ", [](PolygonWrap& w) { w.wrap2 = (w.wrap2 + 1) % 34; }},
      {"w.span_lower", "1 to 100000 links", [](PolygonWrap& w) { w.span_lower = 0; }},
      {"w.span_upper", "1 to 100000 links", [](PolygonWrap& w) { w.span_upper = -5; }},
      {"w.span_upper", "1 to 100000 links", [](PolygonWrap& w) { w.span_upper = 100001; }},
      {"w.wrap1 + w.wrap2 + w.span_lower + w.span_upper", "at most 100000 links",
       [](PolygonWrap& w) { w.span_lower = 99990; }},
  };
  for (const Case& c : cases) {
    PolygonWrap w = good;
    c.spoil(w);
    expect_one(refusal([&] { (void)wrap_pins(w, kP, z1, z2); }), "wrap_pins", c.field, c.range,
               c.field);
  }
}

// Every problem at once, one message, in the arguments' order.
TEST(DriveLayoutInput, RefusesEveryBadArgumentAtOnce) {
  expect_all(refusal([] { (void)pitch_radius(kNan, 2); }), "pitch_radius", {"pitch", "teeth"});
  expect_all(refusal([] { (void)links_for(-1, 0, 1001, kInf); }), "links_for",
             {"pitch", "z1", "z2", "center_distance"});
  expect_all(refusal([] { (void)center_distance_formula(0, 2, 2, kNan); }),
             "center_distance_formula", {"pitch", "z1", "z2", "links"});
  expect_all(refusal([] { (void)polygon_hull(kInf, -3, 17, kNan, kInf, kNan); }), "polygon_hull",
             {"pitch", "z1", "center_distance", "phase1", "phase2"});
  expect_all(refusal([] { (void)polygon_wrap(kP, 17, 0, 1, kNan); }), "polygon_wrap",
             {"z2", "links", "phase1"});
  expect_all(refusal([] { (void)exact_center_distance(1e91, 1, 1, 0); }), "exact_center_distance",
             {"pitch", "z1", "z2", "links"});
  expect_all(refusal([] { (void)shaft_loads(kP, 17, 34, 0.1, kNan, kInf, -kInf); }), "shaft_loads",
             {"center_distance", "tight", "slack", "centrifugal"});
  expect_all(refusal([] { (void)span_angle(kNan, 17, 2000, -1); }), "span_angle",
             {"pitch", "z2", "center_distance"});
  PolygonWrap w;  // all zero: the centres coincide, no spans
  w.phase2 = kNan;
  expect_all(refusal([&] { (void)wrap_pins(w, kP, 17, 1); }), "wrap_pins",
             {"z2", "w.center_distance", "w.phase2", "w.span_lower", "w.span_upper"});
}

// The ranges' ends are valid: finite results, no exception.
TEST(DriveLayoutInput, AcceptsTheRangesEnds) {
  for (double p : {kMinPitch, kMaxPitch}) {
    for (int z : {kMinTeeth, kMaxTeeth}) {
      const double r = pitch_radius(p, z);
      EXPECT_TRUE(std::isfinite(r) && r > 0) << p << " " << z;
      const double a = 2.5 * r;
      EXPECT_TRUE(std::isfinite(links_for(p, z, z, a)));
      EXPECT_TRUE(std::isfinite(span_angle(p, z, z, a)));
      const PolygonWrap h = polygon_hull(p, z, z, a, 0.3, -0.2);
      EXPECT_TRUE(std::isfinite(h.upper_length) && std::isfinite(h.lower_length));
      const ShaftLoads l = shaft_loads(p, z, z, a, kMaxTension, -kMaxTension, kMaxTension);
      EXPECT_TRUE(std::isfinite(l.driver_x) && std::isfinite(l.driver_y));
    }
  }
  EXPECT_TRUE(std::isfinite(links_for(kP, 17, 34, kMaxCenterDistance)));
  EXPECT_TRUE(std::isfinite(center_distance_formula(kP, 17, 34, 1e100)));
  EXPECT_EQ(round_up_even(2147483646.0), 2147483646);
  EXPECT_EQ(round_up_even(2e-9), 2);
  const double touch = pitch_radius(kP, 17) + pitch_radius(kP, 34);
  EXPECT_TRUE(std::isfinite(span_angle(kP, 17, 34, std::nextafter(touch, 1.0))));
  EXPECT_TRUE(std::isfinite(polygon_hull(kP, 17, 34, kMaxCenterDistance, 0, 0).upper_length));
}

// Random valid input: no exception, every output finite. The pitch anywhere in its range
// (log-uniform), teeth 3–1000, centre distances from just apart to 10⁴ pitches, phases in
// ±100 rad; the polygon wrap (a few ms each) on fewer draws, links from the shortest chain that
// passes round both sprockets to 300 more.
TEST(DriveLayoutInput, RandomValidInputGivesFiniteOutput) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> unit(0, 1), phase(-100, 100);
  std::uniform_int_distribution<int> teeth(kMinTeeth, kMaxTeeth), small(kMinTeeth, 60);
  auto pitch = [&] { return std::pow(10.0, -90 + 180 * unit(rng)); };
  for (int trial = 0; trial < 3000; ++trial) {
    const double p = pitch();
    const int z1 = teeth(rng), z2 = teeth(rng);
    const double touch = pitch_radius(p, z1) + pitch_radius(p, z2);
    const double a = touch * (1 + 1e-9) + 1e4 * p * unit(rng) * unit(rng);
    const std::string what = std::to_string(trial);
    ASSERT_NO_THROW({
      const double x = links_for(p, z1, z2, a);
      EXPECT_TRUE(std::isfinite(x)) << what;
      const int even = round_up_even(x);
      EXPECT_TRUE(even % 2 == 0 && even >= x - 1e-6) << what;
      EXPECT_TRUE(std::isfinite(center_distance_formula(p, z1, z2, even))) << what;
      EXPECT_TRUE(std::isfinite(span_angle(p, z1, z2, a))) << what;
      const ShaftLoads l = shaft_loads(p, z1, z2, a, 1e4 * unit(rng), 1e3 * unit(rng), 100);
      EXPECT_TRUE(std::isfinite(l.driver_x + l.driver_y + l.driven_x + l.driven_y)) << what;
      const PolygonWrap h = polygon_hull(p, z1, z2, a, phase(rng), phase(rng));
      EXPECT_TRUE(std::isfinite(h.upper_length + h.lower_length)) << what;
    }) << what;
  }
  for (int trial = 0; trial < 12; ++trial) {
    const double p = pitch();
    const int z1 = small(rng), z2 = small(rng);
    const double touch = pitch_radius(p, z1) + pitch_radius(p, z2);
    const int links = static_cast<int>(std::ceil(links_for(p, z1, z2, touch))) + 2 +
                      static_cast<int>(300 * unit(rng));
    const std::string what = std::to_string(trial) + ": " + std::to_string(z1) + "/" +
                             std::to_string(z2) + ", " + std::to_string(links) + " links";
    ASSERT_NO_THROW({
      const PolygonWrap w = polygon_wrap(p, z1, z2, links, phase(rng));
      EXPECT_TRUE(std::isfinite(w.center_distance) && w.center_distance > touch) << what;
      for (const auto& [x, y] : wrap_pins(w, p, z1, z2))
        EXPECT_TRUE(std::isfinite(x) && std::isfinite(y)) << what;
    }) << what;
  }
}

}  // namespace
}  // namespace catena::drive
