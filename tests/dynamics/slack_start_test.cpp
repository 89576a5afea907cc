// The start with slack (dynamics/layout.hpp, place_slack_loop): a chain longer than the belt path
// laid with its slack span sagging as a circular arc. Tested: every link of the start exactly one
// pitch (the chain's length N p to 1e-9), the sag in the span that faces down, and the loop
// settled under gravity against the catenary through the span's settled ends (the closed form of
// validation (2), tests/validation/dynamics_validation_test.cpp, with ends at unequal heights).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "catena/dynamics/chain.hpp"
#include "catena/dynamics/integrator.hpp"
#include "catena/dynamics/layout.hpp"
#include "catenary_closed_form.hpp"
#include "slack_start_checks.hpp"

namespace catena::dynamics {
namespace {

// the slack start's shared checks and the 12B pitch and roller diameter (slack_start_checks.hpp)
using namespace catena::dynamics::testing;  // NOLINT(google-build-using-namespace)

constexpr double kPi = std::numbers::pi;
// 12B (ISO 606): inner width, mass per metre
constexpr double kWidth = 0.01168, kMass = 1.25;
constexpr double kG = 9.81;

// Two wheels z = 17 on a horizontal line 0.6 m apart (the second `rise` higher); the chain
// `extra` links longer than the taut path (rounded up to whole links).
struct Slack {
  std::vector<Circle> circles{{0.0, 0.0, pitch_radius(17)}, {0.6, 0.0, pitch_radius(17)}};
  std::vector<int> teeth{17, 17};
  BeltPath path, laid;
  LoopPlacement place;
  int links = 0;
};
Slack slack_loop(double fraction, double rise = 0.0) {
  Slack s;
  s.circles[1].y = rise;
  s.path = belt_path(s.circles, 0);
  s.links = static_cast<int>(std::ceil(s.path.length * (1 + fraction) / kPitch));
  s.place = place_slack_loop(s.path, s.circles, s.teeth, s.links, kPitch, s.laid);
  return s;
}

TEST(DynamicsSlackStart, EveryLinkIsOnePitchAndTheLowerSpanSags) {
  for (const double fraction : {0.001, 0.01, 0.03}) {
    const Slack s = slack_loop(fraction);
    ASSERT_EQ(s.place.s.size(), static_cast<std::size_t>(s.links)) << fraction;
    EXPECT_NEAR(s.place.spacing, kPitch, 1e-12 * kPitch);
    const State st = loop_state(s.laid, s.circles, s.place, 0.0);
    expect_every_link_one_pitch(st, s.links, std::to_string(fraction));
    double lowest = 0.0;
    for (std::size_t i = 0; i < st.nodes(); ++i) lowest = std::min(lowest, st.y[i]);
    // the sag is in the lower span (its outward normal points down): the circular arc of the
    // chord c and length c + e between the tangent points, sagitta ρ (1 − cos φ)
    const std::size_t k = slack_span(s.path);
    ASSERT_LT(k, s.path.pieces.size());
    const PathPiece& taut = s.path.pieces[k];
    EXPECT_LT(taut.y0, 0.0);
    const PathPiece& sag = s.laid.pieces[k];
    EXPECT_TRUE(sag.sag);
    EXPECT_NEAR(s.laid.length - s.path.length, sag.length - taut.length, 1e-12);
    const double phi = 0.5 * std::abs(sag.to - sag.from);
    EXPECT_NEAR(2 * sag.radius * std::sin(phi), taut.length, 1e-12);
    const double sagitta = sag.radius * (1 - std::cos(phi));
    // the lowest node is within a pitch's sagitta of the arc's lowest point
    EXPECT_NEAR(-lowest, pitch_radius(17) + sagitta, 0.01 * sagitta + 1e-4) << fraction;
    // the extra length is what the links need: about N p − the taut path (the chords of the arcs)
    EXPECT_GT(s.laid.length, s.path.length);
  }
  // no slack: nothing to sag
  Slack s;
  s.path = belt_path(s.circles, 0);
  const int taut = static_cast<int>(std::floor(s.path.length / kPitch));
  EXPECT_TRUE(place_slack_loop(s.path, s.circles, s.teeth, taut, kPitch, s.laid).s.empty());
}

// Slack beyond the 3 % the start once took, up to the half circle the sagging arc can make:
// 5, 10 and 20 % of the path on the two wheels (the lower span's chord c = 0.6 m takes at most
// (π/2 − 1) c = 342 mm, 22 % of the 1.53 m path). Every link one pitch (1e-11), the chain's length
// N p (1e-9 relative), no link inside a wheel's pitch circle but the chords of its own wrap, the
// sagging arc clear (`sag_obstacle`); 25 % is more than a half circle: laid as the catenary
// (before: no placement), and with nothing under the span `sag_limit` is the longest catenary's
// extra, 10 c (before: the half circle's).
TEST(DynamicsSlackStart, LargeSlackSagsUpToAHalfCircleWithEveryLinkOnePitch) {
  const double r1 = pitch_radius(17);
  for (const double fraction : {0.05, 0.1, 0.2}) {
    const Slack s = slack_loop(fraction);
    ASSERT_EQ(s.place.s.size(), static_cast<std::size_t>(s.links)) << fraction;
    const State st = loop_state(s.laid, s.circles, s.place, 0.0);
    expect_every_link_one_pitch(st, s.links, std::to_string(fraction));
    const std::size_t n = st.nodes();
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t j = (i + 1) % n;
      const double l = std::hypot(st.x[j] - st.x[i], st.y[j] - st.y[i]);
      for (const Circle& c : s.circles) {
        const double di = std::hypot(st.x[i] - c.x, st.y[i] - c.y);
        const double dj = std::hypot(st.x[j] - c.x, st.y[j] - c.y);
        EXPECT_GT(di, c.radius - 1e-12) << fraction << " node " << i;
        // a link with a node on the circle: wrapped, or articulating off the wheel (its chord
        // cuts the circle as a wrapped one does)
        if (std::abs(di - c.radius) < 1e-9 || std::abs(dj - c.radius) < 1e-9) continue;
        // the link's nearest point to the centre
        const double ux = st.x[j] - st.x[i], uy = st.y[j] - st.y[i];
        const double t =
            std::clamp(((c.x - st.x[i]) * ux + (c.y - st.y[i]) * uy) / (l * l), 0.0, 1.0);
        EXPECT_GT(std::hypot(st.x[i] + t * ux - c.x, st.y[i] + t * uy - c.y), c.radius - 1e-9)
            << fraction << " link " << i;
      }
    }
    EXPECT_EQ(sag_obstacle(s.laid, slack_span(s.path), s.circles, {r1 + 0.01, r1 + 0.01}, {},
                           kRoller, kPitch),
              "");
  }
  const Slack over = slack_loop(0.25);
  EXPECT_EQ(over.place.s.size(), static_cast<std::size_t>(over.links));
  const std::size_t k = slack_span(over.path);
  ASSERT_FALSE(over.laid.pieces.empty());
  EXPECT_TRUE(over.laid.pieces[k].catenary);
  EXPECT_NEAR(sag_limit(over.path, k, over.circles, {r1 + 0.01, r1 + 0.01}, {}, kRoller, kPitch),
              kCatenaryMostExtra * 0.6, 1e-6);
}

// The slack shared by every span that can sag (`sagging_spans`, `sag_spans`): on the two wheels
// both spans, of equal length, sag by equal extras (1e-12), each a circular arc of its chord;
// every link one pitch (1e-11) and the chain N p long (1e-9 relative), 2 and 20 % of the path.
TEST(DynamicsSlackStart, SlackSharedByEverySpanInProportionToItsLength) {
  for (const double fraction : {0.02, 0.2}) {
    Slack s;
    s.path = belt_path(s.circles, 0);
    s.links = static_cast<int>(std::ceil(s.path.length * (1 + fraction) / kPitch));
    const std::vector<std::size_t> spans = sagging_spans(s.path);
    ASSERT_EQ(spans.size(), 2u);
    s.place = place_slack_loop(s.path, s.circles, s.teeth, s.links, kPitch, s.laid, spans);
    ASSERT_EQ(s.place.s.size(), static_cast<std::size_t>(s.links)) << fraction;
    const PathPiece &a = s.laid.pieces[spans[0]], &b = s.laid.pieces[spans[1]];
    EXPECT_TRUE(a.sag && b.sag);
    const double ea = a.length - s.path.pieces[spans[0]].length;
    const double eb = b.length - s.path.pieces[spans[1]].length;
    EXPECT_GT(ea, 0.0);
    EXPECT_NEAR(ea, eb, 1e-12) << fraction;
    EXPECT_NEAR(s.laid.length - s.path.length, ea + eb, 1e-12);
    const State st = loop_state(s.laid, s.circles, s.place, 0.0);
    expect_every_link_one_pitch(st, s.links, std::to_string(fraction));
  }
}

// The same on spans of clearly different lengths: three wheels of different sizes (z = 17, 25, 12)
// at the corners of a triangle (0, 0), (0.6, 0), (0.2, 0.35) m — the hull's three spans are about
// 0.60, 0.51 and 0.39 m long, all sagging. The claim of `sag_spans`: each span's extra over its
// chord (the straight span's length) in proportion to that length, e_i / L_i the same for every
// span (1e-6 relative); the extras sum to the laid path's extra (1e-12); every link one pitch
// (1e-11) and the chain N p long (1e-9 relative); 2 and 10 % of the path.
TEST(DynamicsSlackStart, SlackSharedByUnequalSpansInProportionToTheirLengths) {
  const std::vector<Circle> circles{
      {0.0, 0.0, pitch_radius(17)}, {0.6, 0.0, pitch_radius(25)}, {0.2, 0.35, pitch_radius(12)}};
  const std::vector<int> teeth{17, 25, 12};
  const BeltPath path = belt_path(circles, 0);
  ASSERT_FALSE(path.pieces.empty());
  const std::vector<std::size_t> spans = sagging_spans(path);
  ASSERT_EQ(spans.size(), 3u);
  double shortest = INFINITY, longest = 0.0;
  for (const std::size_t k : spans) {
    shortest = std::min(shortest, path.pieces[k].length);
    longest = std::max(longest, path.pieces[k].length);
  }
  ASSERT_GT(longest, 1.3 * shortest);  // the spans' lengths clearly differ
  for (const double fraction : {0.02, 0.1}) {
    const int links = static_cast<int>(std::ceil(path.length * (1 + fraction) / kPitch));
    BeltPath laid;
    const LoopPlacement place = place_slack_loop(path, circles, teeth, links, kPitch, laid, spans);
    ASSERT_EQ(place.s.size(), static_cast<std::size_t>(links)) << fraction;
    double total = 0.0;
    const double share0 = (laid.pieces[spans[0]].length - path.pieces[spans[0]].length) /
                          path.pieces[spans[0]].length;
    EXPECT_GT(share0, 0.0);
    for (const std::size_t k : spans) {
      EXPECT_TRUE(laid.pieces[k].sag) << fraction << " span " << k;
      const double extra = laid.pieces[k].length - path.pieces[k].length;
      std::printf("%.2f: span %zu, length %.5f m, extra %.6f m, extra / length %.8f\n", fraction, k,
                  path.pieces[k].length, extra, extra / path.pieces[k].length);
      EXPECT_NEAR(extra / path.pieces[k].length / share0, 1.0, 1e-6) << fraction << " span " << k;
      total += extra;
    }
    EXPECT_NEAR(laid.length - path.length, total, 1e-12) << fraction;
    const State st = loop_state(laid, circles, place, 0.0);
    expect_every_link_one_pitch(st, links, std::to_string(fraction));
  }
}

// A guide under the lower span: a rail 100 mm below it from x = 0.1 to 0.5 m (the rollers on
// top). A chain one link longer than the taut path sags less than that and passes it, every node
// more than a roller radius from the rail; the half circle would pass below the whole rail,
// enclosing it between the chain's runs, and is named; the limit `sag_limit` is the sag whose
// lowest point (at x = 0.3 m, over the rail) is a roller radius above the rail: ρ (1 − cos φ) =
// 100 mm − d1/2, within 1e-5 m.
TEST(DynamicsSlackStart, SagIsCheckedAgainstTheGuides) {
  const double r1 = pitch_radius(17), depth = 0.1;
  Guide rail;
  rail.x0 = 0.1;
  rail.x1 = 0.5;
  rail.y0 = rail.y1 = -r1 - depth;
  rail.roller_radius = 0.5 * kRoller;
  const std::vector<double> tip{r1 + 0.01, r1 + 0.01};
  auto sagitta = [](const PathPiece& q) {
    return q.radius * (1 - std::cos(0.5 * std::abs(q.to - q.from)));
  };
  const Slack small = slack_loop(0.0);
  ASSERT_FALSE(small.place.s.empty());
  const std::size_t k = slack_span(small.path);
  ASSERT_LT(sagitta(small.laid.pieces[k]), depth - 0.5 * kRoller);
  EXPECT_EQ(sag_obstacle(small.laid, k, small.circles, tip, {rail}, kRoller, kPitch), "");
  const State st = loop_state(small.laid, small.circles, small.place, 0.0);
  for (std::size_t i = 0; i < st.nodes(); ++i) {
    const double gap = st.x[i] < rail.x0   ? std::hypot(st.x[i] - rail.x0, st.y[i] - rail.y0)
                       : st.x[i] > rail.x1 ? std::hypot(st.x[i] - rail.x1, st.y[i] - rail.y0)
                                           : std::abs(st.y[i] - rail.y0);
    EXPECT_GT(gap, 0.5 * kRoller) << i;
  }
  const BeltPath half = sag_span(small.path, k, (kPi / 2 - 1) * 0.6 * (1 - 1e-6));
  ASSERT_FALSE(half.pieces.empty());
  EXPECT_EQ(sag_obstacle(half, k, small.circles, tip, {rail}, kRoller, kPitch), "guide[0]");
  EXPECT_EQ(sag_obstacle(half, k, small.circles, tip, {}, kRoller, kPitch), "");
  const double most = sag_limit(small.path, k, small.circles, tip, {rail}, kRoller, kPitch);
  const BeltPath limit = sag_span(small.path, k, most);
  ASSERT_FALSE(limit.pieces.empty());
  EXPECT_NEAR(sagitta(limit.pieces[k]), depth - 0.5 * kRoller, 1e-5);
}

// Two sagging spans facing each other (as the two walls of a notch in a serpentine path would,
// each bulging into it): the sag of one is checked against the other's arc, not only against the
// straight spans (`sag_obstacle`). Two vertical spans 0.3 m long, `gap` apart, travelling down
// and up, so each bulges towards the other. Apart by 0.2 m their half circles (0.15 m each) would
// cross: the joint limit (`sag_spans_limit`) is where the arcs come within a roller diameter, the
// sagittae (gap − d1)/2 each, and a little more runs into the other span, named. Apart by 0.5 m
// the half circles pass (0.2 m between them): the limit is the half circle's.
BeltPath facing_spans(double gap) {
  BeltPath path;
  PathPiece down;  // from wheel 0 to wheel 1, down x = gap/2: bulges to −x
  down.wheel = 0;
  down.next = 1;
  down.x0 = down.x1 = 0.5 * gap;
  down.y0 = 0.3;
  down.y1 = 0.0;
  down.length = 0.3;
  PathPiece up = down;  // from wheel 2 to wheel 3, up x = −gap/2: bulges to +x
  up.wheel = 2;
  up.next = 3;
  up.x0 = up.x1 = -0.5 * gap;
  up.y0 = 0.0;
  up.y1 = 0.3;
  up.start = 0.3;
  path.pieces = {down, up};
  path.length = 0.6;
  return path;
}

// the sagitta of a sagging piece: its arc's farthest point from the chord
double sagitta(const PathPiece& q) {
  const double phi = 0.5 * (q.to - q.from);
  return q.radius * (1.0 - std::cos(phi));
}

TEST(DynamicsSlackStart, TwoSaggingSpansAreCheckedAgainstEachOther) {
  const std::vector<std::size_t> both{0, 1};
  const BeltPath near = facing_spans(0.2);
  // a half circle each would cross the other: refused, naming the other span
  const BeltPath crossing = sag_spans(near, both, (0.5 * kPi - 1.0) * 0.6 * (1 - 1e-6));
  ASSERT_EQ(crossing.pieces.size(), 2u);
  EXPECT_EQ(sag_obstacle(crossing, 0, {}, {}, {}, kRoller, kPitch),
            "the span sprocket[2] -> sprocket[3]");
  EXPECT_EQ(sag_obstacle(crossing, 1, {}, {}, {}, kRoller, kPitch),
            "the span sprocket[0] -> sprocket[1]");
  // each alone (the other straight) is clear up to its half circle: the crossing is the arcs'
  const double alone = sag_limit(near, 0, {}, {}, {}, kRoller, kPitch);
  EXPECT_NEAR(alone, (0.5 * kPi - 1.0) * 0.3, 1e-6 * 0.3);
  const double most = sag_spans_limit(near, both, {}, {}, {}, kRoller, kPitch);
  const BeltPath limit = sag_spans(near, both, most);
  ASSERT_EQ(limit.pieces.size(), 2u);
  // both sag alike; the arcs' gap at the limit is a roller diameter (the bisection's 1e-6 of the
  // spans' 0.6 m in extra length moves the sagittae by less than 1 um here)
  EXPECT_NEAR(sagitta(limit.pieces[0]), 0.5 * (0.2 - kRoller), 2e-6);
  EXPECT_NEAR(sagitta(limit.pieces[1]), 0.5 * (0.2 - kRoller), 2e-6);
  EXPECT_EQ(sag_obstacle(limit, 0, {}, {}, {}, kRoller, kPitch), "");
  const BeltPath beyond = sag_spans(near, both, most + 1e-4);
  EXPECT_EQ(sag_obstacle(beyond, 0, {}, {}, {}, kRoller, kPitch),
            "the span sprocket[2] -> sprocket[3]");

  // apart by 0.5 m: the half circles pass each other, the limit is theirs
  const BeltPath far = facing_spans(0.5);
  const double half = sag_spans_limit(far, both, {}, {}, {}, kRoller, kPitch);
  EXPECT_NEAR(half, (0.5 * kPi - 1.0) * 0.6, 1e-8);
  const BeltPath passing = sag_spans(far, both, half);
  ASSERT_EQ(passing.pieces.size(), 2u);
  EXPECT_NEAR(sagitta(passing.pieces[0]), 0.15, 1e-6);
  EXPECT_EQ(sag_obstacle(passing, 0, {}, {}, {}, kRoller, kPitch), "");
  EXPECT_EQ(sag_obstacle(passing, 1, {}, {}, {}, kRoller, kPitch), "");
}

// The notched loop of DynamicsLayoutCli.TwoSaggingWallsOfANotchAreCheckedAgainstEachOther (four
// corner wheels z 20, a notch from the top: mouth wheels z 20, inside wheels z 30 kinking its
// walls, a back-side wheel z 34 at its bottom), every span between two wheels inside sagging.
// With 344, 360, 364 and 368 links the secant on e cycled (the walk's miss is continuous and
// falls with e, but its slope swings from -0.2 to -20 where a node passes a sag's kink at a
// wheel: for 344 the iterates went round e - (N p - L) = 34.9, 41.4, 71.4, 48.0 mm), so those
// counts were not laid while the others of 274-370 were; the miss changes sign between N p - L
// and the half circle, and the bisection there finds e (344: 44.197 mm beyond N p - L). Every
// count 343-368 is now laid, every link one pitch (the sags' checks against the wheels and each
// other are not made here: through the command 365 and above run into the other wall).
TEST(DynamicsSlackStart, EveryCountOnTheNotchedPathIsLaid) {
  std::vector<Circle> circles{
      {-0.5, -0.3, pitch_radius(20)},    {0.5, -0.3, pitch_radius(20)},
      {0.5, 0.6, pitch_radius(20)},      {0.25, 0.6, pitch_radius(20)},
      {0.1412, 0.35, pitch_radius(30)},  {0.0, 0.15, pitch_radius(34), true},
      {-0.1412, 0.35, pitch_radius(30)}, {-0.25, 0.6, pitch_radius(20)},
      {-0.5, 0.6, pitch_radius(20)}};
  const std::vector<int> teeth{20, 20, 20, 20, 30, 34, 30, 20, 20};
  const BeltPath path = belt_path(circles, 0);
  ASSERT_TRUE(path.faults.empty());
  const std::vector<std::size_t> pieces = sagging_spans(path);
  ASSERT_EQ(pieces.size(), 7u);
  for (int links = 343; links <= 368; ++links) {
    const std::string what = std::to_string(links) + " links";
    const double e = slack_extra(path, pieces, links, kPitch);
    ASSERT_TRUE(std::isfinite(e)) << what;
    // a chord spans at least its own length of the path: e is not below N p - L
    EXPECT_GE(e, links * kPitch - path.length) << what;
    BeltPath laid;
    const LoopPlacement place = place_slack_loop(path, circles, teeth, links, kPitch, laid, pieces);
    ASSERT_EQ(place.s.size(), static_cast<std::size_t>(links)) << what;
    EXPECT_NEAR(laid.length, path.length + e, 1e-12) << what;
    // the closing link within the solve's tolerance on the walk's end, 1e-11 of the chain
    expect_every_link_one_pitch(loop_state(laid, circles, place, 0.0), links, what,
                                1e-11 * links * kPitch);
  }
  // beyond every span's half circle the walk still overshoots: no e, and no start
  double spans = 0.0;
  for (const std::size_t k : pieces) spans += path.pieces[k].length;
  const double half = (0.5 * kPi - 1.0) * spans;
  const int beyond = static_cast<int>(std::ceil((path.length + half) / kPitch));
  EXPECT_EQ(slack_extra(path, pieces, beyond, kPitch), INFINITY);
}

// The search for the most links that start (longest_count): tried downwards one by one; after
// `scan` counts without a start the rest is bisected, and the phrase says a larger count may start.
// Here the counts 1..250 start: from 400 down, 400..301 fail (100 counts), and the bisection over
// 1..300 finds 250, which starts, with at most 100 + 10 tries in all.
TEST(DynamicsSlackStart, MostLinksFoundByBisectionAfterTheScanFails) {
  int tries = 0;
  auto starts = [&tries](int n) {
    ++tries;
    return n <= 250;
  };
  const LongestCount bisected = longest_count(0, 400, starts);
  EXPECT_FALSE(bisected.scanned);
  EXPECT_EQ(bisected.links, 250);
  EXPECT_TRUE(starts(bisected.links));
  EXPECT_LE(tries, 100 + 10 + 1);
  EXPECT_EQ(links_that_start_phrase(bisected, 0),
            "250 links start so (found by bisection after the 100 counts below the limit "
            "failed; a larger count may start)");
  // within the scan: the first that starts, named as the most
  const LongestCount scanned = longest_count(0, 400, [](int n) { return n <= 350; });
  EXPECT_TRUE(scanned.scanned);
  EXPECT_EQ(scanned.links, 350);
  EXPECT_EQ(links_that_start_phrase(scanned, 0), "at most 350 links start so");
  // a count given below the most that does not start itself is named so
  EXPECT_NE(links_that_start_phrase(scanned, 340).find("; no start was found at exactly 340 links"),
            std::string::npos);
  // none starts: the bisection's first try fails
  const LongestCount none = longest_count(0, 400, [](int) { return false; });
  EXPECT_EQ(none.links, 0);
  EXPECT_EQ(links_that_start_phrase(none, 0), "no count starts so");
}

// The catenary through the span's ends: closed_form (catenary_closed_form.hpp).

// The slack loop at rest under gravity: the driver held, the driven wheel free, drag settling the
// chain. The lower span between the last roller seated on each wheel hangs as the catenary of its
// links' length through those two points: y = a cosh((x − x0)/a) + c with √(s² − h²) =
// 2a sinh(d/2a), x0 = (xA + xB)/2 − a atanh(h/s). Every free node within 1 % of the sag, the sag
// within 0.5 % (validation (2)); with `tensions`, the span's end links' tensions q g (a + y − y0)
// (y their middles' height, y0 the catenary's lowest point) and the lowest link's horizontal
// tension a q g within 0.5 % too.
void expect_settled_catenary(double fraction, bool tensions, int steps) {
  Slack s = slack_loop(fraction);
  ASSERT_FALSE(s.place.s.empty());
  Model m = uniform_chain(s.place.s.size(), true, kPitch, kMass * kPitch, 5e6, 20.0, false);
  for (std::size_t w = 0; w < 2; ++w)
    m.sprockets.push_back(
        iso606_sprocket(kPitch, kRoller, kWidth, 17, s.circles[w].x, s.circles[w].y, 2e8, 800.0));
  m.sprockets[0].driver = true;
  m.sprockets[0].speed = 0.0;
  m.sprockets[1].inertia = 0.02;
  m.gravity_y = -kG;
  m.drag = 20.0;
  State st = loop_state(s.laid, s.circles, s.place, 0.0);
  Integrator integ(m, {.step = 2e-4, .theta = 0.6});
  for (int k = 0; k < steps; ++k) ASSERT_TRUE(integ.step(m, st).converged) << k;
  // settled: the kinetic energy below 1e-6 of the chain's weight over 0.1 m (what is left is the
  // free wheel's slow creep under the drag on the nodes)
  EXPECT_LT(energy(m, st).kinetic,
            1e-6 * kMass * kPitch * static_cast<double>(st.nodes()) * kG * 0.1);
  // the seated nodes (on a pitch circle within 0.2 mm) below the centres' line; the span's ends:
  // the driver's seated node farthest round (largest x), the driven wheel's smallest x
  const std::size_t n = st.nodes();
  auto seated = [&](std::size_t i, std::size_t w) {
    return std::abs(std::hypot(st.x[i] - s.circles[w].x, st.y[i] - s.circles[w].y) -
                    s.circles[w].radius) < 2e-4;
  };
  std::size_t a = n, b = n;
  for (std::size_t i = 0; i < n; ++i) {
    if (st.y[i] >= 0.0) continue;
    if (seated(i, 0) && (a == n || st.x[i] > st.x[a])) a = i;
    if (seated(i, 1) && (b == n || st.x[i] < st.x[b])) b = i;
  }
  ASSERT_LT(a, n);
  ASSERT_LT(b, n);
  // the links from a forward to b (the loop runs from the driver's bottom to the driven wheel)
  const std::size_t count = (b + n - a) % n;
  ASSERT_GT(count, 20u);
  ASSERT_LT(count, n);
  const double sl = static_cast<double>(count) * kPitch;  // the links' rest length; stretch < 1e-6
  const double xa = st.x[a], ya = st.y[a], xb = st.x[b], yb = st.y[b];
  const double d = xb - xa, h = yb - ya;
  const ClosedForm form = closed_form(xa, ya, xb, yb, sl);
  const double ca = form.a, x0 = form.x0;
  auto catenary = [&](double x) { return form.y(x, xa, ya); };
  double sag = 0.0;
  for (std::size_t k = 1; k < count; ++k) {
    const std::size_t i = (a + k) % n;
    sag = std::max(sag, ya + (st.x[i] - xa) * h / d - catenary(st.x[i]));
  }
  ASSERT_GT(sag, 0.02);  // a real sag: tens of millimetres
  double sim_sag = 0.0;
  for (std::size_t k = 1; k < count; ++k) {
    const std::size_t i = (a + k) % n;
    EXPECT_NEAR(st.y[i], catenary(st.x[i]), 0.01 * sag) << "node " << k << " of the span";
    sim_sag = std::max(sim_sag, ya + (st.x[i] - xa) * h / d - st.y[i]);
  }
  EXPECT_NEAR(sim_sag / sag, 1.0, 0.005) << sim_sag << " vs " << sag;
  std::printf("slack span: %zu links, sag %.6f m (catenary %.6f m, ratio %.5f)\n", count, sim_sag,
              sag, sim_sag / sag);
  if (!tensions) return;
  std::vector<double> tension(m.links());
  link_tensions(m, st, tension);
  const double w = kMass * kG, lowest = catenary(x0) - ca;  // the directrix: T = w (y − lowest)
  for (const std::size_t j : {a, (b + n - 1) % n}) {
    const double ym = 0.5 * (st.y[j] + st.y[(j + 1) % n]);
    EXPECT_NEAR(tension[j] / (w * (ym - lowest)), 1.0, 0.005) << "end link " << j;
    std::printf("end link %zu: tension %.4f N (catenary %.4f N)\n", j, tension[j],
                w * (ym - lowest));
  }
  std::size_t low = a;
  for (std::size_t k = 0; k < count; ++k)
    if (st.y[(a + k) % n] + st.y[(a + k + 1) % n] < st.y[low] + st.y[(low + 1) % n])
      low = (a + k) % n;
  const double dx = st.x[(low + 1) % n] - st.x[low], dy = st.y[(low + 1) % n] - st.y[low];
  EXPECT_NEAR(tension[low] * dx / std::hypot(dx, dy) / (ca * w), 1.0, 0.005);
  std::printf("lowest link: horizontal tension %.4f N (a q g %.4f N)\n",
              tension[low] * dx / std::hypot(dx, dy), ca * w);
}

// measured: sag +0.15 %
TEST(DynamicsSlackStart, SettledSlackSpanIsTheCatenary) {
  expect_settled_catenary(0.02, false, 10000);
}

// 30 % of slack: beyond the half circle (22.5 % of this path), laid as the catenary of the span's
// length and settled with its sag, its end tensions and its lowest tension the catenary's
TEST(DynamicsSlackStart, SettledSlackBeyondTheHalfCircleIsTheCatenary) {
  expect_settled_catenary(0.30, true, 20000);
}

// Slack beyond a half circle of its span (before the catenary: refused) is laid as the catenary
// of its length tangent to both wheels (`tangent_span`: a hanging chain meets its wheels
// tangentially, its rest shape; before, between the span's tangent points, with a kink at each
// wheel): on two wheels 0.6 m apart, the second 0.15 m higher, 30 % of slack. Tangent by plain
// geometry (tangent_fit), the path turning by under 1e-9 rad at every joint, the wraps cut short;
// the laid curve against the closed form through its own ends with its length (the test's own
// solve) at 1000 points to 1e-9 m, its lowest point, its end slopes sinh((x − x0)/a) and its
// length (the sum of 10⁵ chords) to 1e-9; a and the lowest point against the tangent catenary of
// the laid e (the test's own solve of the tangency conditions) to 1e-9; every link one pitch.
TEST(DynamicsSlackStart, SlackBeyondTheHalfCircleIsLaidAsTheCatenary) {
  const Slack s = slack_loop(0.30, 0.15);
  ASSERT_EQ(s.place.s.size(), static_cast<std::size_t>(s.links));
  const std::size_t k = slack_span(s.path);
  ASSERT_LT(k, s.path.pieces.size());
  ASSERT_GT(k, 0u);
  const PathPiece& taut = s.path.pieces[k];
  const PathPiece& q = s.laid.pieces[k];
  ASSERT_TRUE(q.sag && q.catenary);
  // beyond the half circle: the path's extra more than (π/2 − 1) c
  const double extra = s.laid.length - s.path.length;
  EXPECT_GT(extra, (0.5 * kPi - 1.0) * taut.length);
  // tangent to both wheels: their wraps cut short, no turn where the span meets them
  EXPECT_LT(s.laid.pieces[k - 1].length, s.path.pieces[k - 1].length);
  EXPECT_LT(s.laid.pieces[(k + 1) % s.laid.pieces.size()].length,
            s.path.pieces[(k + 1) % s.path.pieces.size()].length);
  expect_tangent_fit(s.laid, k, s.circles, "30 %");
  const double turn = largest_joint_turn(s.laid);
  EXPECT_LT(turn, 1e-9);
  const ClosedForm c = closed_form(q.x0, q.y0, q.x1, q.y1, q.length);
  const double d = q.x1 - q.x0, h = q.y1 - q.y0;
  double worst = 0.0, length = 0.0, lowest = INFINITY;
  PathPoint before = path_point(s.laid, q.start);
  for (int j = 1; j <= 100000; ++j) {
    const PathPoint p = path_point(s.laid, q.start + q.length * j / 100000.0);
    length += std::hypot(p.x - before.x, p.y - before.y);
    if (j % 100 == 0) worst = std::max(worst, std::abs(p.y - c.y(p.x, q.x0, q.y0)));
    lowest = std::min(lowest, p.y);
    before = p;
  }
  EXPECT_LT(worst, 1e-9);
  EXPECT_NEAR(length, q.length, 1e-9);
  // the lowest point: the closed form's vertex (sampled every 1e-5 of the curve: within its
  // curvature's (Δs)²/2a of it)
  const double vertex = c.y(c.x0, q.x0, q.y0);
  EXPECT_NEAR(lowest, vertex, 1e-9);
  // the tangent catenary of the laid e, solved by the test (equal wheels)
  const double r = s.circles[0].radius;
  const TangentCatenary own = tangent_catenary(
      s.circles[1].x - s.circles[0].x, s.circles[1].y - s.circles[0].y, r, taut.length, extra);
  EXPECT_NEAR(c.a / own.a, 1.0, 1e-9);
  EXPECT_NEAR(vertex, s.circles[0].y - tangent_catenary_depth(own, r), 1e-9);
  std::printf("catenary: a %.6f m, e %.6f m, sag below the chord's lower end %.6f m\n", c.a, extra,
              std::min(taut.y0, taut.y1) - vertex);
  // the end slopes
  const PathPoint first = sag_point(q, 0.0);
  const PathPoint last = sag_point(q, q.length);
  EXPECT_NEAR(first.ty / first.tx, std::sinh((q.x0 - c.x0) / c.a), 1e-9);
  EXPECT_NEAR(last.ty / last.tx, std::sinh((q.x1 - c.x0) / c.a), 1e-9);
  EXPECT_GT(d, 0.0);
  EXPECT_GT(h, 0.0);
  // the nodes: every link one pitch (the solve's tolerance on the closing link)
  expect_every_link_one_pitch(loop_state(s.laid, s.circles, s.place, 0.0), s.links, "30 %",
                              1e-11 * s.links * kPitch);
}

// The catenary is checked as the arc is (sag_obstacle): a wheel under the span, within the sag's
// reach, is named; well below it, the sag is clear. The limit (`sag_limit`) is that of the lay a
// start lays beyond the half circle, tangent to both wheels: that lay is clear at the limit and
// runs into the wheel 1e-4 c beyond it. The upper run (its outward side up) cannot
// hang beyond its half circle: refused (no pieces), as before.
TEST(DynamicsSlackStart, ACatenaryIntoAWheelIsRefused) {
  const Slack s = slack_loop(0.30);
  const std::size_t k = slack_span(s.path);
  const double c = s.path.pieces[k].length;
  const BeltPath laid = sag_span(s.path, k, 0.8 * c);  // beyond the half circle's 0.571 c
  ASSERT_FALSE(laid.pieces.empty());
  ASSERT_TRUE(laid.pieces[k].catenary);
  std::vector<Circle> circles = s.circles;
  circles.push_back({0.3, -0.5, pitch_radius(17)});
  const std::vector<double> tip(3, pitch_radius(17) + 0.01);
  EXPECT_EQ(sag_obstacle(laid, k, circles, tip, {}, kRoller, kPitch), "sprocket[2]'s teeth");
  circles.back().y = -1.0;
  EXPECT_EQ(sag_obstacle(laid, k, circles, tip, {}, kRoller, kPitch), "");
  // the limit: the wheel 0.5 m below (clear of the half circle) stops the catenary short of 0.8 c,
  // beyond the half circle
  circles.back().y = -0.5;
  const double most = sag_limit(s.path, k, circles, tip, {}, kRoller, kPitch);
  EXPECT_GT(most, (0.5 * kPi - 1.0) * c);
  EXPECT_LT(most, 0.8 * c);
  // the limit is the lay a start lays there: tangent to both wheels (`tangent_span`), clear at
  // the limit and named a step beyond it
  const BeltPath at = tangent_span(s.path, k, most);
  ASSERT_FALSE(at.pieces.empty());
  EXPECT_EQ(sag_obstacle(at, k, circles, tip, {}, kRoller, kPitch), "");
  const BeltPath beyond = tangent_span(s.path, k, most + 1e-4 * c);
  ASSERT_FALSE(beyond.pieces.empty());
  EXPECT_EQ(sag_obstacle(beyond, k, circles, tip, {}, kRoller, kPitch), "sprocket[2]'s teeth");
  std::printf("catenary into a wheel: the limit %.6f c\n", most / c);
  // the upper run: no catenary bulging up
  for (std::size_t u = 0; u < s.path.pieces.size(); ++u)
    if (!s.path.pieces[u].arc && u != k) {
      EXPECT_TRUE(sag_span(s.path, u, 0.8 * c).pieces.empty());
    }
}

// A count laid tangent at an e just below the half circle: z 17 both, level 0.6 m apart, 98 links.
// Between the tangent points its lay would pass the half circle (the chord solve's e 346.531 mm
// against (π/2 − 1) c = 342.478 mm), so it is laid tangent, where it closes at e = 342.414 mm,
// below the half circle. A rail under the span between the half circle's lowest roller and the
// tangent lay's at that e: the arc is clear all the way up to the half circle, the tangent lay
// laid is not. The limit (`sag_limit`) checks the lay laid there: both the arc and the tangent
// lay within a pitch below the half circle, so here 323.427 mm, that pitch's low end, below the
// 98 links' e (before, it checked the arc alone there and named the half circle's 342.478 mm,
// above the e of a count whose start runs into the rail).
TEST(DynamicsSlackStart, TheLimitJustBelowTheHalfCircleChecksTheTangentLay) {
  const Slack s = slack_loop(0.0);
  const std::size_t k = slack_span(s.path);
  const double c = s.path.pieces[k].length, r = pitch_radius(17);
  const double half = (0.5 * kPi - 1.0) * c;
  const int links = 98;
  BeltPath laid;
  const LoopPlacement place = place_slack_loop(s.path, s.circles, s.teeth, links, kPitch, laid);
  ASSERT_EQ(place.s.size(), static_cast<std::size_t>(links));
  ASSERT_TRUE(laid.pieces[k].catenary);
  EXPECT_LT(largest_joint_turn(laid), 1e-9);
  const double e = laid.length - s.path.length;
  EXPECT_LT(e, half);
  EXPECT_GT(e, half - kPitch);
  // the rail midway between the half circle's lowest point (c/2 below the tangent line) and the
  // tangent lay's (the test's own solve), each a roller radius off it
  const double arc_low = 0.5 * c,
               hang_low = tangent_catenary_depth(tangent_catenary(c, 0.0, r, c, e), r) - r;
  ASSERT_GT(hang_low - arc_low, 2.0 * kRoller);
  Guide rail;
  rail.x0 = 0.2;
  rail.x1 = 0.4;
  rail.y0 = rail.y1 = -r - 0.5 * (arc_low + hang_low);
  rail.roller_radius = 0.5 * kRoller;
  const std::vector<double> tip{r + 0.01, r + 0.01};
  EXPECT_EQ(sag_obstacle(sag_span(s.path, k, half * (1.0 - 1e-9)), k, s.circles, tip, {rail},
                         kRoller, kPitch),
            "");
  EXPECT_EQ(sag_obstacle(laid, k, s.circles, tip, {rail}, kRoller, kPitch), "guide[0]");
  // the tangent lay runs into the rail across the whole pitch below the half circle (at its low
  // end too), the arc below it is clear: the limit is that pitch's low end, below the 98 links' e
  const BeltPath low = tangent_span(s.path, k, half - kPitch);
  ASSERT_FALSE(low.pieces.empty());
  EXPECT_EQ(sag_obstacle(low, k, s.circles, tip, {rail}, kRoller, kPitch), "guide[0]");
  const double most = sag_limit(s.path, k, s.circles, tip, {rail}, kRoller, kPitch);
  EXPECT_LT(most, e);
  EXPECT_NEAR(most, half - kPitch, 1e-6 * c);
  EXPECT_EQ(sag_obstacle(sag_span(s.path, k, most), k, s.circles, tip, {rail}, kRoller, kPitch),
            "");
  std::printf(
      "98 links: e %.6f mm, half circle %.6f mm, limit %.6f mm; lowest arc %.3f, "
      "tangent %.3f mm\n",
      e * 1e3, half * 1e3, most * 1e3, arc_low * 1e3, hang_low * 1e3);
}

// A tight catenary (a under 0.7 p, where a circle of radius a would turn the chord over 1.6 p of
// the curve short of p; the catenary is that tight only at its lowest point): wheels z 6 50 mm
// apart, 36 links, laid tangent to both (the path turning by under 1e-9 rad at every joint),
// a = 11.1 mm = 0.59 p: every link still one pitch. (Before the tangent lay: z 8 70 mm apart, 46
// links, laid between the tangent points with a = 7.9 mm and a kink at each wheel; tangent to
// them that start's a is 15.6 mm, 0.82 p, no longer tight.) z 6 is a case of the walker alone:
// the command takes 8 to 150 teeth, and its level two-wheel starts laid tangent do not get this
// tight (z 8 at 62, 65 and 70 mm, every count up to the longest catenary: a at least 14.0 mm,
// 0.735 p).
TEST(DynamicsSlackStart, ATightCatenaryIsWalkedAtOnePitch) {
  const std::vector<Circle> circles{{0.0, 0.0, pitch_radius(6)}, {0.05, 0.0, pitch_radius(6)}};
  const BeltPath path = belt_path(circles, 0);
  BeltPath laid;
  const int links = 36;
  const LoopPlacement place = place_slack_loop(path, circles, {6, 6}, links, kPitch, laid);
  ASSERT_EQ(place.s.size(), static_cast<std::size_t>(links));
  const std::size_t k = slack_span(path);
  ASSERT_TRUE(laid.pieces[k].catenary);
  EXPECT_LT(laid.pieces[k].hang_a, 0.7 * kPitch);
  const double turn = largest_joint_turn(laid);
  EXPECT_LT(turn, 1e-9);
  std::printf("tight catenary: a %.6f m, e / c %.4f\n", laid.pieces[k].hang_a,
              (laid.pieces[k].length - path.pieces[k].length) / path.pieces[k].length);
  expect_every_link_one_pitch(loop_state(laid, circles, place, 0.0), links, "tight",
                              1e-11 * links * kPitch);
}

}  // namespace
}  // namespace catena::dynamics

namespace catena::dynamics {
namespace {

// A sloped lower run (the second wheel below and to the right of the first, z 17 both, 80 links):
// its catenary meets the lower wheel at a kink, where the path nearly folds back (about 146° on
// the 45° span), and on a steep span its lowest point is tight. The start is laid with every link
// one pitch, or not laid (refused) — never with a link cut short (16.9 mm at 45°, 5.4 mm at
// (60, -400) mm before the walk marched to the first point a pitch on). Below a = d1/2 the sag
// check names the catenary laid between the span's tangent points its own other strand. Every
// one of them folds so (the turn at its far wheel over 90°) and is laid tangent to its wheels
// instead (AKinkedSlopedCatenaryIsLaidTangentToItsWheels): the path turning by less than 1e-9 rad
// at every joint of its pieces, a roller on each wheel. Laid: (300, -300) and (200, -400) (before
// at its node 0's phase, refused before that). Tangent to its wheels (a = 22.4 and 17.0 mm)
// (60, -400) and (30, -400) leave the driven wheel 0.62 and 0.37 of a pitch of wrap and no roller
// on it, not a start: they are laid between the tangent points as before the tangent lay, across
// the fold. (60, -400) is laid so (a = 6.3 mm, above the roller's 6.035 mm), a roller on each
// wheel; (30, -400) is not (refused before too: that catenary tighter than a roller, a = 2.7 mm).
// The e a refusal names (`laid_slack_extra`) is the laid path's: at (60, -400) not the tangent
// lay's `slack_extra`.
TEST(DynamicsSlackStart, ASlopedCatenaryIsLaidAtOnePitchOrRefused) {
  struct Case {
    double x, y;   // [m] the second wheel's centre
    bool tangent;  // laid tangent to its wheels (else, when laid, between the tangent points)
  };
  int laid_count = 0;
  for (const Case c : {Case{0.3, -0.3, true}, Case{0.2, -0.4, true}, Case{0.06, -0.4, false},
                       Case{0.03, -0.4, false}}) {
    const std::string what = std::to_string(c.x) + ", " + std::to_string(c.y);
    const std::vector<Circle> circles{{0.0, 0.0, pitch_radius(17)}, {c.x, c.y, pitch_radius(17)}};
    const std::vector<double> tip(2, pitch_radius(17) + 0.01);
    const BeltPath path = belt_path(circles, 0);
    const std::size_t k = slack_span(path);
    BeltPath laid;
    const int links = 80;
    const LoopPlacement place = place_slack_loop(path, circles, {17, 17}, links, kPitch, laid);
    // the e the command names for the count (`laid_slack_extra`): the laid path's extra over the
    // taut path where laid (between the tangent points: not the tangent lay's `slack_extra`),
    // else the solve's
    const double named = laid_slack_extra(path, circles, {17, 17}, links, kPitch, {k});
    const double solved = slack_extra(path, {k}, links, kPitch);
    if (place.s.empty()) {
      EXPECT_EQ(named, solved) << what;
    } else {
      EXPECT_NEAR(named, laid.length - path.length, 1e-12) << what;
      EXPECT_EQ(std::abs(named - solved) > 1e-3, !c.tangent) << what << ": " << named;
    }
    std::printf("sloped (%s): e named %.6f mm, the solve's %.6f mm\n", what.c_str(), named * 1e3,
                solved * 1e3);
    // the catenary of the chain's own extra (about the e a start needs): below a = d1/2 the sag
    // check names its other strand
    const BeltPath hang = sag_span(path, k, links * kPitch - path.length);
    ASSERT_TRUE(hang.pieces[k].catenary) << what;
    const std::string strand = sag_obstacle(hang, k, circles, tip, {}, kRoller, kPitch);
    const double fold = std::max(std::abs(joint_turn(hang, k - 1)), std::abs(joint_turn(hang, k)));
    EXPECT_GT(fold, 0.5 * kPi) << what;
    std::printf(
        "sloped (%s): %s, between the tangent points a %.3f mm at e = N p - L, fold %.1f deg, "
        "sag check \"%s\"\n",
        what.c_str(), place.s.empty() ? "not laid" : "laid", hang.pieces[k].hang_a * 1e3,
        fold * 180.0 / kPi, strand.c_str());
    EXPECT_EQ(hang.pieces[k].hang_a < 0.5 * kRoller, strand.rfind("its own other strand", 0) == 0)
        << what << ": " << strand;
    if (place.s.empty() || !c.tangent) {
      EXPECT_TRUE(place.s.empty() == laid.pieces.empty()) << what;
      // the tangent lay that closes: less than a pitch of wrap left on the driven wheel
      const BeltPath tangent = tangent_span(path, k, solved);
      ASSERT_FALSE(tangent.pieces.empty()) << what;
      const PathPiece& w1 = tangent.pieces[(k + 1) % tangent.pieces.size()];
      EXPECT_LT(w1.to - w1.from, 2.0 * kPi / 17) << what;
      std::printf(
          "sloped (%s): tangent to its wheels a %.3f mm, the driven wheel's wrap %.3f of "
          "a pitch\n",
          what.c_str(), tangent.pieces[k].hang_a * 1e3, (w1.to - w1.from) / (2.0 * kPi / 17));
      if (place.s.empty()) continue;
    }
    ++laid_count;
    ASSERT_EQ(place.s.size(), static_cast<std::size_t>(links)) << what;
    EXPECT_GT(place.wrapped[0], 0) << what;
    EXPECT_GT(place.wrapped[1], 0) << what;
    EXPECT_TRUE(laid.pieces[k].catenary) << what;
    const double turn = largest_joint_turn(laid);
    if (c.tangent) {
      EXPECT_LT(turn, 1e-9) << what;
    } else {
      // between the tangent points: the span's ends on the taut path's, across the fold
      EXPECT_GT(turn, 0.5 * kPi) << what;
      EXPECT_LT(
          std::hypot(laid.pieces[k].x0 - path.pieces[k].x0, laid.pieces[k].y0 - path.pieces[k].y0),
          1e-12)
          << what;
      EXPECT_GT(laid.pieces[k].hang_a, 0.5 * kRoller) << what;
    }
    std::printf("sloped (%s): %s a %.3f mm, largest turn at a joint %.3g rad\n", what.c_str(),
                c.tangent ? "tangent to its wheels" : "between the tangent points",
                laid.pieces[k].hang_a * 1e3, turn);
    expect_every_link_one_pitch(loop_state(laid, circles, place, 0.0), links, what,
                                1e-11 * links * kPitch);
  }
  EXPECT_EQ(laid_count, 3);  // (0.3, -0.3) and (0.2, -0.4) m tangent, (0.06, -0.4) m between
}

// The sloped catenary that folded at its far wheel (the driven wheel at (200, −400) mm, z 17
// both, 80 links): laid between the span's tangent points the catenary climbs into the wheel at
// 143° to the wrap, a link jumped across the fold and node 0's phase was searched for a closing
// start. Now laid tangent to both wheels (tangent_span): the path turns at each tangent point by
// less than 1e-9 rad (against the fold's 143°); by plain geometry (tangent_fit) the catenary's
// ends on the wraps' ends and on the circles within 1e-12 m, along the circles' tangents within
// 1e-9 rad; the laid catenary against the test's own solve of the two tangency conditions and
// the length condition (tangent_catenary, the same equations for equal wheels: it checks the
// root chosen and the solve, the geometry the equations): a and both tangent points within 1e-9;
// the curve clear of both wheels' pitch circles, touching them at its ends;
// node 0 at the path's start; every link one pitch (1e-11), no two links crossing, none nearer a
// wheel's centre than a wrapped link's chord, no two links turning by more than a wrap's 2π/z
// (before: the link across the fold). Started under gravity (the model of validation (2)) every
// step converges and it settles within 4 s (the time it first stays settled, sampled every 0.1 s,
// printed).
TEST(DynamicsSlackStart, AKinkedSlopedCatenaryIsLaidTangentToItsWheels) {
  const std::vector<Circle> circles{{0.0, 0.0, pitch_radius(17)}, {0.2, -0.4, pitch_radius(17)}};
  const double r = pitch_radius(17);
  const BeltPath path = belt_path(circles, 0);
  const std::size_t k = slack_span(path);
  const int links = 80;
  // the fold of the lay between the tangent points, at the chain's own extra
  const BeltPath chord_end = sag_span(path, k, links * kPitch - path.length);
  ASSERT_TRUE(chord_end.pieces[k].catenary);
  const double fold = std::abs(joint_turn(chord_end, k));
  EXPECT_GT(fold, 0.5 * kPi);
  BeltPath laid;
  const LoopPlacement place = place_slack_loop(path, circles, {17, 17}, links, kPitch, laid);
  ASSERT_EQ(place.s.size(), static_cast<std::size_t>(links));
  const PathPiece& q = laid.pieces[k];
  ASSERT_TRUE(q.catenary);
  const double into = joint_turn(laid, k - 1), out = joint_turn(laid, k);
  EXPECT_LT(std::abs(into), 1e-9);
  EXPECT_LT(std::abs(out), 1e-9);
  expect_tangent_fit(laid, k, circles, "kinked");
  const double extra = laid.length - path.length;
  const TangentCatenary own = tangent_catenary(
      circles[1].x - circles[0].x, circles[1].y - circles[0].y, r, path.pieces[k].length, extra);
  EXPECT_NEAR(q.hang_a / own.a, 1.0, 1e-9);
  EXPECT_NEAR(q.x0, circles[0].x + r * std::tanh(own.t0), 1e-9);
  EXPECT_NEAR(q.y0, circles[0].y - r / std::cosh(own.t0), 1e-9);
  EXPECT_NEAR(q.x1, circles[1].x + r * std::tanh(own.t1), 1e-9);
  EXPECT_NEAR(q.y1, circles[1].y - r / std::cosh(own.t1), 1e-9);
  double closest = INFINITY;
  for (int j = 1; j < 10000; ++j) {
    const PathPoint p = sag_point(q, q.length * j / 10000.0);
    for (const Circle& c : circles) closest = std::min(closest, std::hypot(p.x - c.x, p.y - c.y));
  }
  EXPECT_GT(closest, r * (1.0 - 1e-12));
  EXPECT_EQ(place.s[0], 0.0);
  std::printf(
      "kinked: fold between the tangent points %.1f deg; tangent lay: turns %.3g and %.3g rad, e "
      "%.9f m (N p - L %.9f m), a %.6f mm (own solve %.6f mm), leaving at %.2f deg, arriving at "
      "%.2f deg\n",
      fold * 180.0 / kPi, into, out, extra, links * kPitch - path.length, q.hang_a * 1e3,
      own.a * 1e3, std::atan(std::sinh(own.t0)) * 180.0 / kPi,
      std::atan(std::sinh(own.t1)) * 180.0 / kPi);
  State st = loop_state(laid, circles, place, 0.0);
  const double worst = expect_every_link_one_pitch(st, links, "kinked", 1e-11 * links * kPitch);
  std::printf("kinked: the links' largest miss of the pitch %.3g of it\n", worst / kPitch);
  // no two links cross (neighbours share a node), none cuts into a wheel: no nearer its centre
  // than a wrapped link's chord, r cos(π/z); no two neighbours turning by more than a wrap's
  const std::size_t n = st.nodes();
  const double inset = r * std::cos(kPi / 17);
  double nearest = INFINITY, sharpest = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t i1 = (i + 1) % n, i2 = (i + 2) % n;
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // neighbours across the closing link
      const std::size_t j1 = (j + 1) % n;
      EXPECT_FALSE(segments_cross(st.x[i], st.y[i], st.x[i1], st.y[i1], st.x[j], st.y[j], st.x[j1],
                                  st.y[j1]))
          << "links " << i << " and " << j;
    }
    for (const Circle& c : circles) {
      const double d = segment_distance(c.x, c.y, st.x[i], st.y[i], st.x[i1], st.y[i1]);
      EXPECT_GE(d, inset * (1.0 - 1e-9)) << "link " << i;
      nearest = std::min(nearest, d);
    }
    const double ux = st.x[i1] - st.x[i], uy = st.y[i1] - st.y[i];
    const double vx = st.x[i2] - st.x[i1], vy = st.y[i2] - st.y[i1];
    sharpest = std::max(sharpest, std::abs(std::atan2(ux * vy - uy * vx, ux * vx + uy * vy)));
  }
  EXPECT_LT(sharpest, 2.0 * kPi / 17 * (1.0 + 1e-9));
  std::printf(
      "kinked: the links' nearest approach to a wheel's centre %.6f mm (chord's %.6f mm), their "
      "sharpest turn %.3f deg\n",
      nearest * 1e3, inset * 1e3, sharpest * 180.0 / kPi);
  Model m = uniform_chain(st.nodes(), true, kPitch, kMass * kPitch, 5e6, 20.0, false);
  for (std::size_t w = 0; w < 2; ++w)
    m.sprockets.push_back(
        iso606_sprocket(kPitch, kRoller, kWidth, 17, circles[w].x, circles[w].y, 2e8, 800.0));
  m.sprockets[0].driver = true;
  m.sprockets[0].speed = 0.0;
  m.sprockets[1].inertia = 0.02;
  m.gravity_y = -kG;
  m.drag = 20.0;
  Integrator integ(m, {.step = 2e-4, .theta = 0.6});
  // settled (as expect_settled_catenary): the kinetic energy below 1e-6 of the chain's weight over
  // 0.1 m; the time from which it stays so, sampled every 0.1 s
  const double settled = 1e-6 * kMass * kPitch * links * kG * 0.1;
  double since = NAN;
  for (int step = 1; step <= 20000; ++step) {
    ASSERT_TRUE(integ.step(m, st).converged) << step;
    if (step % 500 != 0) continue;
    const double kinetic = energy(m, st).kinetic;
    if (!(kinetic < settled))
      since = NAN;
    else if (std::isnan(since))
      since = step * 2e-4;
  }
  for (std::size_t i = 0; i < st.nodes(); ++i) {
    const std::size_t j = (i + 1) % st.nodes();
    EXPECT_NEAR(std::hypot(st.x[j] - st.x[i], st.y[j] - st.y[i]), kPitch, 1e-4 * kPitch) << i;
  }
  const double kinetic = energy(m, st).kinetic;
  EXPECT_LT(kinetic, settled);
  std::printf("kinked: after 4 s, kinetic energy %.3g J; settled (below %.3g J) from %.1f s on\n",
              kinetic, settled, since);
}

// The counts that start on the kinked slope ((200, −400) mm, z 17 both): every count from 77 (the
// first beyond the half circle's arc) to 298 (the bound N p ≤ L + 10 c) is laid tangent to its
// wheels (measured one by one: all 222, node 0 at the path's start; before, every one folded and
// was laid at its node 0's phase), sampled here at 77, 150 and 298: the path turning by less than
// 1e-9 rad at every joint, every link one pitch. 76 is laid as before, a circular arc (its kink
// 87.5°: within its half circle, where the arc is kept), and 299 is not laid.
TEST(DynamicsSlackStart, EveryCountOnTheKinkedSlopeIsLaidTangent) {
  const std::vector<Circle> circles{{0.0, 0.0, pitch_radius(17)}, {0.2, -0.4, pitch_radius(17)}};
  const BeltPath path = belt_path(circles, 0);
  const std::size_t k = slack_span(path);
  for (const int links : {76, 77, 150, 298, 299}) {
    BeltPath laid;
    const LoopPlacement place = place_slack_loop(path, circles, {17, 17}, links, kPitch, laid);
    if (links == 299) {
      EXPECT_TRUE(place.s.empty());
      continue;
    }
    ASSERT_EQ(place.s.size(), static_cast<std::size_t>(links)) << links;
    EXPECT_EQ(place.s[0], 0.0) << links;
    const double turn = largest_joint_turn(laid);
    if (links == 76) {
      EXPECT_FALSE(laid.pieces[k].catenary);
      EXPECT_NEAR(laid.pieces[k - 1].length, path.pieces[k - 1].length, 1e-15);  // wrap kept
      EXPECT_LT(turn, 0.5 * kPi);
    } else {
      EXPECT_TRUE(laid.pieces[k].catenary) << links;
      EXPECT_LT(turn, 1e-9) << links;
    }
    std::printf("kinked slope, %d links: %s, largest turn at a joint %.3g deg\n", links,
                laid.pieces[k].catenary ? "catenary" : "arc", turn * 180.0 / kPi);
    expect_every_link_one_pitch(loop_state(laid, circles, place, 0.0), links, std::to_string(links),
                                1e-11 * links * kPitch);
  }
}

// The start is continuous as the slope turns through where the lay between the span's tangent
// points folds (a turn over 90° at the far wheel, between −19° and −20° here): z 17 both, centres
// 447.214 mm apart (the kinked slope's), 80 links, the slope from −17° to −22° in steps of 1/4°.
// Every start is laid tangent to its wheels (the path turning by under 1e-9 rad at every joint),
// and a, the lowest point and e change from one step to the next by about the slope's own change:
// a and the lowest point by at most 1.5 times the mean step's change (measured: 0.340 against
// 0.308 mm, 1.157 against 1.147 mm), e by under 0.01 mm (measured 1.4 µm; it stays 305.13–305.14
// mm). Before, the lay switched at the fold: a jumped by 29 % (109.0 to 140.4 mm), the lowest
// point by 8.8 mm and e by −4.2 mm between −19° and −20°.
TEST(DynamicsSlackStart, TheStartIsContinuousAsTheSlopeTurnsThroughAFold) {
  const double centres = std::hypot(0.2, 0.4);
  const int links = 80;
  std::vector<double> as, lows, extras;
  for (int q = 0; q <= 20; ++q) {
    const double slope = -(17.0 + 0.25 * q) * kPi / 180.0;
    const std::string what = std::to_string(-(17.0 + 0.25 * q)) + " deg";
    const std::vector<Circle> circles{
        {0.0, 0.0, pitch_radius(17)},
        {centres * std::cos(slope), centres * std::sin(slope), pitch_radius(17)}};
    const BeltPath path = belt_path(circles, 0);
    const std::size_t k = slack_span(path);
    BeltPath laid;
    const LoopPlacement place = place_slack_loop(path, circles, {17, 17}, links, kPitch, laid);
    ASSERT_EQ(place.s.size(), static_cast<std::size_t>(links)) << what;
    const PathPiece& span = laid.pieces[k];
    ASSERT_TRUE(span.catenary) << what;
    const double turn = largest_joint_turn(laid);
    EXPECT_LT(turn, 1e-9) << what;
    double low = INFINITY;
    for (int j = 0; j <= 10000; ++j) low = std::min(low, sag_point(span, span.length * j / 1e4).y);
    as.push_back(span.hang_a);
    lows.push_back(low);
    extras.push_back(laid.length - path.length);
    std::printf("slope %s: a %.3f mm, lowest point %.3f mm, e %.3f mm, turn %.3g rad\n",
                what.c_str(), span.hang_a * 1e3, low * 1e3, (laid.length - path.length) * 1e3,
                turn);
  }
  // a and the lowest point: no step's change over 1.5 times the mean step's; e (nearly constant:
  // the chain's N p less the path's length and what the links' chords cut off the curve) by
  // under 0.01 mm a step
  const std::pair<const char*, const std::vector<double>&> series[] = {
      {"a", as}, {"lowest point", lows}, {"e", extras}};
  for (const auto& [name, v] : series) {
    const auto [mean, most] = step_changes(v);
    if (name == std::string("e"))
      EXPECT_LT(most, 1e-5) << name;
    else
      EXPECT_LT(most, 1.5 * mean) << name;
    std::printf("%s: the largest step's change %.4g mm, the mean step's %.4g mm\n", name,
                most * 1e3, mean * 1e3);
  }
}

// Unequal wheels (z 17 and, below and to its right, z 34 at (200, −400) mm): the tangent lay of
// e = 0.1, 1 and 3 chords by plain geometry (tangent_fit: the catenary's ends on the wraps' ends
// and on both circles within 1e-12 m, along their tangents within 1e-9 rad), its length the taut
// path's plus e (1e-12 relative): with the two radii swapped in the code's tangency conditions
// the lay is refused, in its length condition the length misses e. And a start of 112 links laid
// so (the lay between the tangent points folds), a roller on each wheel, every link one pitch.
TEST(DynamicsSlackStart, AnUnequalPairIsLaidTangentToBothWheels) {
  const std::vector<Circle> circles{{0.0, 0.0, pitch_radius(17)}, {0.2, -0.4, pitch_radius(34)}};
  const BeltPath path = belt_path(circles, 0);
  const std::size_t k = slack_span(path);
  const double chord = path.pieces[k].length;
  for (const double share : {0.1, 1.0, 3.0}) {
    const std::string what = "z 17/34, e " + std::to_string(share) + " c";
    const BeltPath laid = tangent_span(path, k, share * chord);
    ASSERT_FALSE(laid.pieces.empty()) << what;
    ASSERT_TRUE(laid.pieces[k].catenary) << what;
    expect_tangent_fit(laid, k, circles, what);
    EXPECT_NEAR(laid.length, path.length + share * chord, 1e-12 * laid.length) << what;
  }
  const int links = 112;
  BeltPath laid;
  const LoopPlacement place = place_slack_loop(path, circles, {17, 34}, links, kPitch, laid);
  ASSERT_EQ(place.s.size(), static_cast<std::size_t>(links));
  ASSERT_TRUE(laid.pieces[k].catenary);
  EXPECT_LT(laid.pieces[k - 1].length, path.pieces[k - 1].length);  // laid tangent: wrap shortened
  EXPECT_GT(place.wrapped[0], 0);
  EXPECT_GT(place.wrapped[1], 0);
  expect_tangent_fit(laid, k, circles, "z 17/34, 112 links");
  expect_every_link_one_pitch(loop_state(laid, circles, place, 0.0), links, "z 17/34",
                              1e-11 * links * kPitch);
}

// Where the longest catenary (e = 10 c) cannot be laid tangent but the one that closes can: z 11 at
// the origin, z 41 at 671 mm and 82.9° above it (c 664.9 mm). At 10 c the tangent lay leaves a
// wheel more curved than the wheel or uses a wrap up; the solve's bracket now ends at the longest
// e it lays (stepped down from 10 c). Before, the solve gave up there and the lay between the
// tangent points was kept, folding at the far wheel by 162–164° at 137, 177 and 217 links. Now
// each is laid tangent: the path turning by less than 1e-9 rad at every joint, tangent by plain
// geometry (tangent_fit), a roller on each wheel (one on z 11, whose wrap is cut to a sliver),
// node 0 at the path's start, every link one pitch.
TEST(DynamicsSlackStart, AFoldIsLaidTangentWhereTheLongestCatenaryIsNot) {
  const double slope = 82.9 * kPi / 180.0, d = 0.671;
  const std::vector<Circle> circles{{0.0, 0.0, pitch_radius(11)},
                                    {d * std::cos(slope), d * std::sin(slope), pitch_radius(41)}};
  const BeltPath path = belt_path(circles, 0);
  const std::size_t k = slack_span(path);
  EXPECT_TRUE(tangent_span(path, k, kCatenaryMostExtra * path.pieces[k].length * (1.0 - 1e-9))
                  .pieces.empty());
  for (const int links : {137, 217}) {
    const std::string what = "z 11/41, " + std::to_string(links) + " links";
    BeltPath laid;
    const LoopPlacement place = place_slack_loop(path, circles, {11, 41}, links, kPitch, laid);
    ASSERT_EQ(place.s.size(), static_cast<std::size_t>(links)) << what;
    ASSERT_TRUE(laid.pieces[k].catenary) << what;
    EXPECT_EQ(place.s[0], 0.0) << what;
    const double turn = largest_joint_turn(laid);
    EXPECT_LT(turn, 1e-9) << what;
    expect_tangent_fit(laid, k, circles, what);
    EXPECT_GT(place.wrapped[0], 0) << what;
    EXPECT_GT(place.wrapped[1], 0) << what;
    std::printf("%s: a %.3f mm, e %.3f mm, largest turn at a joint %.3g rad, wrapped %d and %d\n",
                what.c_str(), laid.pieces[k].hang_a * 1e3, (laid.length - path.length) * 1e3, turn,
                place.wrapped[0], place.wrapped[1]);
    expect_every_link_one_pitch(loop_state(laid, circles, place, 0.0), links, what,
                                1e-11 * links * kPitch);
  }
}

// A span index beyond the path's pieces is refused (NAN, nothing laid), not read: the tangent
// solve, tried where the lay between the tangent points does not close, looked up the span's
// length before any check (a read past the pieces, seen by valgrind's memcheck).
TEST(DynamicsSlackStart, ASpanBeyondThePathIsRefused) {
  const std::vector<Circle> circles{{0.0, 0.0, pitch_radius(17)}, {0.2, -0.4, pitch_radius(17)}};
  const BeltPath path = belt_path(circles, 0);
  for (const std::size_t k : {path.pieces.size(), path.pieces.size() + 7}) {
    EXPECT_TRUE(std::isnan(slack_extra(path, {k}, 80, kPitch))) << k;
    BeltPath laid;
    EXPECT_TRUE(place_slack_loop(path, circles, {17, 17}, 80, kPitch, laid, {k}).s.empty()) << k;
    EXPECT_TRUE(laid.pieces.empty()) << k;
  }
}

// `slack_spans = "all"` beyond the half circle (every share passes it at one e, the shares in
// proportion to the chords): each lower run laid as the catenary tangent to its two wheels with
// its share (`tangent_spans`), the path turning by under 1e-9 rad at every joint, every link one
// pitch, a roller on every wheel: 180 links (the first count laid so; its e, 522.703 mm, closes
// 0.83 p below the half circle's 538.488 mm, within the pitch a span that the limit checks both
// lays in) and 199 (183 and 215 too before the slow tier took the rest of the range:
// tests/validation/dynamics_multispan_slow_test.cpp). Before, every catenary of more than one span
// was laid between its tangent points, kinked at the wheels (107.7° at 199 links), and 180 links
// were not laid.
TEST(DynamicsSlackStart, TwoSlackSpansAreEachLaidTangentToTheirWheels) {
  const TwoRuns t = two_lower_runs();
  ASSERT_TRUE(t.path.faults.empty());
  ASSERT_EQ(t.spans.size(), 2u);
  const double half = (0.5 * kPi - 1.0) * t.chords;
  for (const int links : {180, 199}) {
    const std::string what = std::to_string(links) + " links";
    BeltPath laid;
    const LoopPlacement place =
        place_slack_loop(t.path, t.circles, t.teeth, links, kPitch, laid, t.spans);
    ASSERT_EQ(place.s.size(), static_cast<std::size_t>(links)) << what;
    const double e = laid.length - t.path.length;
    EXPECT_EQ(e > half, links != 180) << what;
    EXPECT_GT(e, half - 2.0 * kPitch) << what;
    EXPECT_LT(largest_joint_turn(laid), 1e-9) << what;
    for (const int w : place.wrapped) EXPECT_GT(w, 0) << what;
    expect_both_runs_tangent(t, laid, what);
    expect_every_link_one_pitch(loop_state(laid, t.circles, place, 0.0), links, what,
                                1e-11 * links * kPitch);
  }
}

// The first obstacle any of the two runs of `laid` runs into with the guides `guides`
// (`sag_obstacle`, z 17 tips), empty when both are clear.
std::string first_obstacle(const TwoRuns& t, const BeltPath& laid,
                           const std::vector<Guide>& guides) {
  const std::vector<double> tip(t.circles.size(), pitch_radius(17) + 0.0066);
  std::string out;
  for (const std::size_t k : t.spans)
    if (out.empty()) out = sag_obstacle(laid, k, t.circles, tip, guides, kRoller, kPitch);
  return out;
}

// The limit of more than one span (`sag_spans_limit`) follows the lay a start lays beyond the half
// circle, both spans tangent (`tangent_spans`): a rail under the first run, 1 mm below where the
// tangent lay of 1.5 half circles would bring a roller onto it; the limit lies beyond the half
// circle, that lay is clear at the limit, and 1e-4 of the chords beyond it runs into the rail.
TEST(DynamicsSlackStart, TheLimitOfTwoSpansFollowsTheirTangentLay) {
  const TwoRuns t = two_lower_runs();
  const double half = (0.5 * kPi - 1.0) * t.chords;
  const BeltPath deep = tangent_spans(t.path, t.spans, 1.5 * half);
  ASSERT_FALSE(deep.pieces.empty());
  const PathPiece& run = deep.pieces[t.spans[0]];
  const ClosedForm c = closed_form(run.x0, run.y0, run.x1, run.y1, run.length);
  ASSERT_GT(c.x0, run.x0);
  ASSERT_LT(c.x0, run.x1);
  Guide rail;
  rail.x0 = c.x0 - 0.05;
  rail.x1 = c.x0 + 0.05;
  rail.y0 = rail.y1 = catenary_lowest(run) - 0.5 * kRoller - 0.001;
  rail.roller_radius = 0.5 * kRoller;
  const std::vector<double> tip(t.circles.size(), pitch_radius(17) + 0.0066);
  auto named = [&](const BeltPath& laid) { return first_obstacle(t, laid, {rail}); };
  EXPECT_EQ(named(deep), "");
  const double most = sag_spans_limit(t.path, t.spans, t.circles, tip, {rail}, kRoller, kPitch);
  EXPECT_GT(most, 1.5 * half);
  EXPECT_LT(most, 2.0 * half);
  const BeltPath at = tangent_spans(t.path, t.spans, most);
  ASSERT_FALSE(at.pieces.empty());
  EXPECT_EQ(named(at), "");
  const BeltPath beyond = tangent_spans(t.path, t.spans, most + 1e-4 * t.chords);
  ASSERT_FALSE(beyond.pieces.empty());
  EXPECT_EQ(named(beyond), "guide[0]");
  std::printf("two runs, a rail under the first: the limit %.6f mm (half circle %.6f mm)\n",
              most * 1e3, half * 1e3);
}

// The lowest point [m] of a sagging piece, sampled at 10⁴ points along it.
double sampled_lowest(const PathPiece& q) {
  double low = INFINITY;
  for (int j = 0; j <= 10000; ++j) low = std::min(low, sag_point(q, q.length * j / 1e4).y);
  return low;
}

// A link whose chord p spans a kink of the path turning by φ (two straight legs from the kink K,
// directions u1 in and u2 out, u1·u2 = cos φ): its end A = K − a u1 a before K, its other end B =
// K + b u2 on the out leg where |A − B| = p (b = −a cos φ + √(p² − a² sin² φ)), taking a + b of
// the path. Walked over a in [0, p] in 2·10⁵ steps (the last joint before K lies within a pitch of
// it): the most it takes beyond its chord, and the a it takes it at.
struct KinkWalk {
  double most = 0.0, at = 0.0;
};
KinkWalk walk_kink(double phi, double p) {
  KinkWalk w;
  for (int j = 0; j <= 200000; ++j) {
    const double a = p * j / 200000.0;
    const double b = -a * std::cos(phi) + std::sqrt(p * p - a * a * std::sin(phi) * std::sin(phi));
    if (b < 0.0) continue;
    if (a + b - p > w.most) {
      w.most = a + b - p;
      w.at = a;
    }
  }
  return w;
}

// The walk's most is p (sec(φ/2) − 1) (to 1e-9 p), at a = b = p / (2 cos (φ/2)), up to φ = 120°,
// where a = b = p; beyond, a = p and it takes −2 p cos φ, below the sec bound (1.0539 against
// 1.0562 p at 121.8°, 1.4426 against 1.6771 p at 136.2°): `kink_link_extra` is the walk's most
// (to 1e-9 p) at 30°, the half circle's 90°, the catenaries' 69.7°, 98.6°, 121.8° and 136.2°, and
// near the half turn (179.9°, 2 p less 1e-8 p; the sec bound there is 1145 p), and at most 2 p.
TEST(DynamicsSlackStart, ALinkAcrossAKinkTakesAtMostSecHalfItsTurnOfThePath) {
  for (const double deg : {30.0, 69.7, 90.0, 98.6, 121.8, 136.2, 179.9}) {
    const double phi = deg * kPi / 180.0, p = kPitch;
    const KinkWalk w = walk_kink(phi, p);
    const double bound = p * (1.0 / std::cos(0.5 * phi) - 1.0);
    EXPECT_LE(w.most, bound + 1e-12 * p) << deg;
    EXPECT_NEAR(kink_link_extra(phi, p), w.most, 1e-9 * p) << deg;
    EXPECT_LE(kink_link_extra(phi, p), 2.0 * p) << deg;
    if (deg <= 120.0) {
      EXPECT_NEAR(w.most, bound, 1e-9 * p) << deg;
      EXPECT_NEAR(w.at, p / (2.0 * std::cos(0.5 * phi)), 1e-4 * p) << deg;
    } else {  // a = b would lie beyond a pitch: the last joint before K is a pitch from it
      EXPECT_EQ(w.at, p) << deg;
      EXPECT_NEAR(w.most, -2.0 * p * std::cos(phi), 1e-9 * p) << deg;
    }
    std::printf("kink %.1f deg: most extra %.6f p (sec bound %.6f p)\n", deg, w.most / p,
                bound / p);
  }
}

// The band below the half circle from the spans' kinks (`sag_spans_band`) against the kinks
// measured on the lays themselves and links walked across them (not the band's formula): each
// span's sag a hair beyond the half circle (`sag_spans`), its direction at both ends from two of
// its points 1e-7 m apart (`sag_point`'s positions, not its tangent) against its chord's, each kink
// at least the half circle's 90°, the most a link of a pitch walked across it takes (`walk_kink`):
// on the two lower runs at slopes of 32°, 51° and 61° (the high wheels 0.25, 0.5 and 0.72 m up; the
// widest kinks 98.6°, 122.2° and 136.1°, the last two past the 120° where a = b = p). The printed
// bands 1.8959, 2.9622 and 3.7120 p (the sec bound's 2.9693 and 4.1822 p at 51° and 61°).
TEST(DynamicsSlackStart, TheBandBelowTheHalfCircleIsTheSpansKinksExtraPath) {
  for (const double high : {0.25, 0.5, 0.72}) {
    const TwoRuns t = two_lower_runs(high);
    ASSERT_EQ(t.spans.size(), 2u);
    const double half = (0.5 * kPi - 1.0) * t.chords;
    const BeltPath beyond = sag_spans(t.path, t.spans, half * (1.0 + 1e-9));
    ASSERT_FALSE(beyond.pieces.empty());
    double walked = 0.0, widest = 0.0;
    for (const std::size_t k : t.spans) {
      const PathPiece& q = beyond.pieces[k];
      const double cx = q.x1 - q.x0, cy = q.y1 - q.y0, c = std::hypot(cx, cy);
      for (const auto& [from, to] : {std::pair{0.0, 1e-7}, std::pair{q.length - 1e-7, q.length}}) {
        const PathPoint u = sag_point(q, from), v = sag_point(q, to);
        const double dx = v.x - u.x, dy = v.y - u.y;
        const double turn =
            std::acos(std::clamp((dx * cx + dy * cy) / (std::hypot(dx, dy) * c), -1.0, 1.0));
        widest = std::max(widest, turn);
        walked += walk_kink(std::max(turn, 0.5 * kPi), kPitch).most;
      }
    }
    const double derived = sag_spans_band(t.path, t.spans, kPitch);
    EXPECT_NEAR(derived, walked, 1e-5 * kPitch) << high;
    if (high > 0.25) {
      EXPECT_GT(widest, 2.0 * kPi / 3.0) << high;  // the case past 120° is reached
    }
    std::printf("high wheels %.2f m: the band %.4f p, walked %.4f p, widest kink %.1f deg\n", high,
                derived / kPitch, walked / kPitch, widest * 180.0 / kPi);
  }
}

// Below the half circle, within the band from the spans' kinks (here 1.896 p, narrower than the
// two pitches of the rule before): 180 links close laid tangent at an e 0.829 p below the half
// circle (TwoSlackSpansAreEachLaidTangentToTheirWheels). A rail under the first run midway between
// its half circle's lowest point and that tangent lay's: the arcs are clear up to the half circle,
// the 180 links' lay is not; the limit (`sag_spans_limit`) checks both lays within the band, so
// here it lies below the 180 links' 522.703 mm and below the half circle, the arcs clear there,
// at the band's low end, not below it (502.371 mm; with a pitch a span, 500.388 mm, a count laid as
// arcs a pitch tenth above it refused for a tangent lay no count there takes; before the tangent
// lay was checked, the half circle's 538.488 mm, above the e of a count whose start runs into the
// rail); the tangent lay just above the limit runs into the rail; the arcs' own limit
// (`sag_spans_arcs_limit`) is the half circle's.
TEST(DynamicsSlackStart, TheLimitOfTwoSpansJustBelowTheHalfCircleChecksTheTangentLay) {
  const TwoRuns t = two_lower_runs();
  const double half = (0.5 * kPi - 1.0) * t.chords;
  BeltPath laid;
  const LoopPlacement place =
      place_slack_loop(t.path, t.circles, t.teeth, 180, kPitch, laid, t.spans);
  ASSERT_EQ(place.s.size(), 180u);
  const double e = laid.length - t.path.length;
  ASSERT_LT(e, half);
  const BeltPath arcs = sag_spans(t.path, t.spans, half * (1.0 - 1e-9));
  ASSERT_FALSE(arcs.pieces.empty());
  const PathPiece &arc = arcs.pieces[t.spans[0]], &hang = laid.pieces[t.spans[0]];
  const double arc_low = sampled_lowest(arc), hang_low = sampled_lowest(hang);
  ASSERT_GT(arc_low - hang_low, 2.0 * kRoller);
  const ClosedForm c = closed_form(hang.x0, hang.y0, hang.x1, hang.y1, hang.length);
  Guide rail;
  rail.x0 = c.x0 - 0.03;
  rail.x1 = c.x0 + 0.03;
  rail.y0 = rail.y1 = 0.5 * (arc_low + hang_low);
  rail.roller_radius = 0.5 * kRoller;
  const std::vector<double> tip(t.circles.size(), pitch_radius(17) + 0.0066);
  auto named = [&](const BeltPath& lay) { return first_obstacle(t, lay, {rail}); };
  EXPECT_EQ(named(arcs), "");
  EXPECT_EQ(named(laid), "guide[0]");
  const double most = sag_spans_limit(t.path, t.spans, t.circles, tip, {rail}, kRoller, kPitch);
  EXPECT_LT(most, e);
  EXPECT_LT(most, half);
  EXPECT_EQ(named(sag_spans(t.path, t.spans, most)), "");
  const double band = sag_spans_band(t.path, t.spans, kPitch);
  EXPECT_GE(most, half - band - 1e-6 * t.chords);
  // a pin on this case's band (1.8959 p, between it and the two pitches of the rule before): the
  // tangent lay fails over the whole band here, so the limit sits at its low end, not two pitches'
  EXPECT_GT(most, half - 2.0 * kPitch + 0.1 * kPitch);
  EXPECT_EQ(named(tangent_spans(t.path, t.spans, most + 1e-3 * kPitch)), "guide[0]");
  // the arcs alone are clear up to the half circle: what a count laid as arcs may take
  const double arcs_most =
      sag_spans_arcs_limit(t.path, t.spans, t.circles, tip, {rail}, kRoller, kPitch);
  EXPECT_NEAR(arcs_most, half, 1e-6 * t.chords);
  std::printf(
      "two runs, 180 links: e %.6f mm, half circle %.6f mm, limit %.6f mm; lowest arc %.3f, "
      "tangent %.3f mm\n",
      e * 1e3, half * 1e3, most * 1e3, arc_low * 1e3, hang_low * 1e3);
}

// Two slack spans meeting on one wheel (a V: z 17 at (0, 0) and (0.6, 0) m, z 60 at (0.3, −0.3) m,
// a back-side wheel z 17 at (0.3, 0) m over the return run): their tangent lays cut that wheel's
// wrap at both ends, each cut the span's own (the pair's pieces those of each span's lay alone,
// exactly). Where the two cuts together use the wrap up (each alone fits: e = 0.1 half circle,
// 103.7° each of a 125.7° wrap; the chain would leave the wheel, hanging as one curve, not
// modelled) the pair is refused, and a start there is laid between the tangent points as before.
TEST(DynamicsSlackStart, TwoTangentSpansOnOneWheelCutItsWrapAtBothEnds) {
  const std::vector<Circle> circles{{0.0, 0.0, pitch_radius(17)},
                                    {0.3, -0.3, pitch_radius(60)},
                                    {0.6, 0.0, pitch_radius(17)},
                                    {0.3, 0.0, pitch_radius(17), true}};
  const BeltPath path = belt_path(circles, 0);
  ASSERT_TRUE(path.faults.empty());
  const std::vector<std::size_t> spans = sagging_spans(path);
  ASSERT_EQ(spans.size(), 2u);
  ASSERT_EQ(spans[1], spans[0] + 2);  // the wrap between them: the shared wheel's
  const std::size_t wrap = spans[0] + 1;
  double chords = 0.0;
  for (const std::size_t k : spans) chords += path.pieces[k].length;
  const double half = (0.5 * kPi - 1.0) * chords;
  const double small = 0.03 * half;
  const BeltPath both = tangent_spans(path, spans, small);
  ASSERT_FALSE(both.pieces.empty());
  double cuts = 0.0;
  for (const std::size_t k : spans) {
    const BeltPath alone = tangent_span(path, k, small * path.pieces[k].length / chords);
    ASSERT_FALSE(alone.pieces.empty()) << k;
    EXPECT_EQ(both.pieces[k].hang_a, alone.pieces[k].hang_a) << k;
    EXPECT_EQ(both.pieces[k].length, alone.pieces[k].length) << k;
    cuts += path.pieces[wrap].length - alone.pieces[wrap].length;
    expect_tangent_fit(both, k, circles, "on one wheel, span " + std::to_string(k));
  }
  EXPECT_GT(both.pieces[wrap].from, path.pieces[wrap].from);
  EXPECT_LT(both.pieces[wrap].to, path.pieces[wrap].to);
  EXPECT_NEAR(path.pieces[wrap].length - both.pieces[wrap].length, cuts, 1e-15);
  EXPECT_NEAR(both.length, path.length + small, 1e-12);
  const double more = 0.1 * half;
  for (const std::size_t k : spans)
    EXPECT_FALSE(tangent_span(path, k, more * path.pieces[k].length / chords).pieces.empty()) << k;
  EXPECT_TRUE(tangent_spans(path, spans, more).pieces.empty());
}

}  // namespace
}  // namespace catena::dynamics
