// Wheels on the back of the chain (a serpentine belt path; dynamics/layout.hpp): the path against
// independent computations (a dense polygon of its points: its length, its winding round each
// wheel's centre, its tangents), the loop placed on it (chords, closure, seats), the layout's
// faults, the start pressing no roller into a tooth, and the running loop's tensions either side
// of a back-side idler on a take-up against the static force balance on the idler.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "catena/dynamics/chain.hpp"
#include "catena/dynamics/integrator.hpp"
#include "catena/dynamics/layout.hpp"

namespace catena::dynamics {
namespace {

constexpr double kPi = std::numbers::pi;
// 12B (ISO 606): pitch, roller diameter, inner width, mass per metre
constexpr double kPitch = 0.01905, kRoller = 0.01207, kWidth = 0.01168, kMass = 1.25;

double pitch_radius(int z) { return 0.5 * kPitch / std::sin(kPi / z); }

// examples/dynamics_serpentine.toml's wheels, counter-clockwise round the loop: the driver z = 12
// at the origin, the idler z = 18 on the back of the slack span at (275, −27) mm, the driven z = 18
// at (400, 0) mm.
struct Wheels {
  std::vector<Circle> circles;
  std::vector<int> teeth;
};
Wheels example_wheels(double idler_y = -0.027) {
  return {{{0.0, 0.0, pitch_radius(12)},
           {0.275, idler_y, pitch_radius(18), true},
           {0.4, 0.0, pitch_radius(18)}},
          {12, 18, 18}};
}

// The winding number of the closed polygon round (x, y) (sum of the turned angles over 2π).
int winding(const std::vector<double>& px, const std::vector<double>& py, double x, double y) {
  double sum = 0.0;
  for (std::size_t i = 0; i < px.size(); ++i) {
    const std::size_t j = (i + 1) % px.size();
    const double a = std::atan2(py[i] - y, px[i] - x), b = std::atan2(py[j] - y, px[j] - x);
    sum += std::remainder(b - a, 2 * kPi);
  }
  return static_cast<int>(std::lround(sum / (2 * kPi)));
}

// Random serpentine layouts: three to five wheels inside on a ring, and one on the back pushed
// into the middle of a span between two of them; those whose path is usable.
std::vector<Wheels> random_layouts(int count) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Wheels> out;
  for (int trial = 0; trial < count; ++trial) {
    const std::size_t n = 3 + static_cast<std::size_t>(trial) % 3;
    std::vector<Circle> ring;
    std::vector<int> teeth;
    for (std::size_t i = 0; i < n; ++i) {
      const int z = 10 + static_cast<int>(u(rng) * 25);
      const double a = 2 * kPi * (static_cast<double>(i) + 0.2 * u(rng)) / static_cast<double>(n);
      const double d = 0.3 + 0.15 * u(rng);
      ring.push_back({d * std::cos(a), d * std::sin(a), pitch_radius(z)});
      teeth.push_back(z);
    }
    // the back wheel between ring wheels 0 and 1, at 60-85 % of the way, its centre pushed in
    // from the outer tangent by 0.5-3 radii (the span's deflection)
    const int z = 10 + static_cast<int>(u(rng) * 15);
    const double r = pitch_radius(z);
    const double f = 0.6 + 0.25 * u(rng);
    const double mx = (1 - f) * ring[0].x + f * ring[1].x, my = (1 - f) * ring[0].y + f * ring[1].y;
    const double dm = std::hypot(mx, my);
    const double depth = (0.5 + 2.5 * u(rng)) * r;
    const double out_by = r - depth + (1 - f) * ring[0].radius + f * ring[1].radius;
    Wheels w;
    w.circles = {ring[0], {mx + out_by * mx / dm, my + out_by * my / dm, r, true}};
    w.teeth = {teeth[0], z};
    for (std::size_t i = 1; i < n; ++i) {
      w.circles.push_back(ring[i]);
      w.teeth.push_back(teeth[i]);
    }
    // usable: no fault, every wheel wrapped over at least 1.5 teeth (a roller on each)
    const BeltPath path = belt_path(w.circles, 0);
    bool usable = path.faults.empty();
    for (const PathPiece& q : path.pieces)
      if (q.arc && std::abs(q.to - q.from) < 1.5 * 2 * kPi / w.teeth[q.wheel]) usable = false;
    if (usable) out.push_back(w);
  }
  return out;
}

// The path's length against the polygon of 40 000 of its points (the chords fall short of the
// arcs by L h²/(24 R²)) and its Richardson extrapolation from 20 000, its pieces joined end to end
// with the spans tangent to both wheels, the loop turning once counter-clockwise round every wheel
// inside it and not round the back-side wheels.
TEST(DynamicsSerpentine, PathMatchesADensePolygonOfItsPoints) {
  std::vector<Wheels> layouts = random_layouts(60);
  ASSERT_GT(layouts.size(), 15u);
  layouts.push_back(example_wheels());
  for (const Wheels& w : layouts) {
    const BeltPath path = belt_path(w.circles, 0);
    ASSERT_TRUE(path.faults.empty());
    ASSERT_EQ(path.pieces.size(), 2 * w.circles.size());
    // the polygons of m and 2m points, extrapolated (Richardson: the chords' shortfall is h² times
    // a constant over the arcs, so (4 P(2m) − P(m))/3 leaves O(h⁴))
    auto polygon = [&](int m, std::vector<double>& px, std::vector<double>& py) {
      px.assign(m, 0.0);
      py.assign(m, 0.0);
      double sum = 0.0;
      for (int k = 0; k < m; ++k) {
        const PathPoint p = path_point(path, path.length * k / m);
        px[k] = p.x;
        py[k] = p.y;
        if (k > 0) sum += std::hypot(px[k] - px[k - 1], py[k] - py[k - 1]);
      }
      return sum + std::hypot(px[0] - px[m - 1], py[0] - py[m - 1]);
    };
    std::vector<double> px, py;
    const double coarse = polygon(20000, px, py), fine = polygon(40000, px, py);
    EXPECT_NEAR(fine, path.length, 1e-7 * path.length);
    EXPECT_NEAR((4 * fine - coarse) / 3, path.length, 1e-11 * path.length);
    for (std::size_t i = 0; i < w.circles.size(); ++i)
      EXPECT_EQ(winding(px, py, w.circles[i].x, w.circles[i].y), w.circles[i].back ? 0 : 1)
          << "wheel " << i;
    for (std::size_t k = 0; k < path.pieces.size(); ++k) {
      const PathPiece& q = path.pieces[k];
      const PathPiece& next = path.pieces[(k + 1) % path.pieces.size()];
      EXPECT_NEAR(q.x1, next.x0, 1e-14);
      EXPECT_NEAR(q.y1, next.y0, 1e-14);
      if (q.arc) {
        EXPECT_EQ(q.sense, w.circles[q.wheel].back ? -1.0 : 1.0);
        EXPECT_GT(q.sense * (q.to - q.from), 0.0);
        continue;
      }
      // a span touches both wheels: its ends at their radius, its direction across their radii
      const double tx = (q.x1 - q.x0) / q.length, ty = (q.y1 - q.y0) / q.length;
      for (const auto& [wheel, x, y] :
           {std::tuple{q.wheel, q.x0, q.y0}, std::tuple{q.next, q.x1, q.y1}}) {
        const Circle& c = w.circles[wheel];
        EXPECT_NEAR(std::hypot(x - c.x, y - c.y), c.radius, 1e-14);
        EXPECT_NEAR((x - c.x) * tx + (y - c.y) * ty, 0.0, 1e-14);
        // the wheel on the travel's left inside the loop, on its right on the back
        const double left = tx * (c.y - y) - ty * (c.x - x);
        EXPECT_GT(c.back ? -left : left, 0.0);
      }
    }
  }
}

// The loop placed on a serpentine path closes at one chord, the back-side wheel's rollers sit on
// its pitch circle within the seats' straddle the placement reports, and it turns clockwise at the
// chain's speed over its radius.
TEST(DynamicsSerpentine, PlacementClosesTheLoopOnTheBackSideWheel) {
  std::vector<Wheels> layouts = random_layouts(30);
  layouts.push_back(example_wheels());
  int placed = 0;
  for (const Wheels& w : layouts) {
    const BeltPath path = belt_path(w.circles, 0);
    const double f = path_links(path, kPitch);
    const int count = static_cast<int>(std::lround(f));
    const LoopPlacement place = place_loop(path, w.circles, w.teeth, count, kPitch);
    ASSERT_EQ(place.s.size(), static_cast<std::size_t>(count));
    ++placed;
    EXPECT_LT(std::abs(place.spacing - kPitch), kPitch * std::abs(f - count) / count * 1.5 + 1e-15);
    const State st = loop_state(path, w.circles, place, 1.5);
    for (std::size_t i = 0; i < st.nodes(); ++i) {
      const std::size_t j = (i + 1) % st.nodes();
      EXPECT_NEAR(std::hypot(st.x[j] - st.x[i], st.y[j] - st.y[i]), place.spacing, 1e-11);
    }
    for (std::size_t k = 0; k < w.circles.size(); ++k) {
      const Circle& c = w.circles[k];
      EXPECT_NEAR(st.speed[k], (c.back ? -1.5 : 1.5) / c.radius, 1e-12);
      const double tau = 2 * kPi / w.teeth[k];
      double worst = 0.0;
      int on = 0;
      for (std::size_t i = 0; i < st.nodes(); ++i) {
        const double dx = st.x[i] - c.x, dy = st.y[i] - c.y;
        if (std::abs(std::hypot(dx, dy) - c.radius) > 1e-12) continue;
        ++on;
        // a wrapped node moves along the wheel's pitch circle the way the wheel turns
        EXPECT_NEAR((dx * st.vy[i] - dy * st.vx[i]) / c.radius, c.radius * st.speed[k], 1e-9);
        const double off = std::remainder(std::atan2(dy, dx) - st.angle[k], tau);
        worst = std::max(worst, 2 * c.radius * std::sin(0.5 * std::abs(off)));
      }
      EXPECT_EQ(on, place.wrapped[k]);
      EXPECT_GT(on, 0);
      EXPECT_NEAR(worst, place.seat_offset[k], 1e-12);
    }
  }
  EXPECT_GT(placed, 10);
}

// The faults, each naming its wheel: a back-side wheel the chain only touches, spans that cross,
// a span through a wheel, and wheels listed clockwise.
TEST(DynamicsSerpentine, FaultsNameTheWheelAndSayWhy) {
  auto has = [](const BeltPath& p, std::size_t wheel, const std::string& word) {
    for (const BeltPath::Fault& f : p.faults)
      if (f.wheel == wheel && f.why.find(word) != std::string::npos) return true;
    return false;
  };
  // the idler below the straight span (it does not reach the chain): not wrapped
  {
    Wheels w = example_wheels(-0.2);
    const BeltPath p = belt_path(w.circles, 0);
    EXPECT_TRUE(p.pieces.empty());
    EXPECT_FALSE(p.faults.empty());
  }
  // the idler pushed up through the tight span: the spans cross / run through a wheel
  {
    Wheels w = example_wheels(0.04);
    const BeltPath p = belt_path(w.circles, 0);
    EXPECT_TRUE(p.pieces.empty());
    EXPECT_TRUE(has(p, 1, "runs through") || has(p, 0, "crosses")) << p.faults.size();
  }
  // the same wheels listed clockwise: the loop turns −360 deg
  {
    Wheels w = example_wheels();
    std::swap(w.circles[0], w.circles[2]);
    const BeltPath p = belt_path(w.circles, 0);
    EXPECT_TRUE(p.pieces.empty());
    EXPECT_FALSE(p.faults.empty());
  }
  // a wheel inside the loop on the wrong side: a back-side wheel at the hull's corner
  {
    Wheels w = example_wheels();
    w.circles[0].back = true;
    w.circles[1].back = false;
    const BeltPath p = belt_path(w.circles, 0);
    EXPECT_TRUE(p.pieces.empty());
    EXPECT_FALSE(p.faults.empty());
  }
  // without a back-side wheel: the hull path as before, no faults
  {
    Wheels w = example_wheels();
    w.circles[1].back = false;
    const BeltPath p = belt_path(w.circles, 0);
    EXPECT_TRUE(p.faults.empty());
  }
}

// Two spans on one line that do not overlap do not cross (on a common line the side tests are all
// zero, which the crossing test took for a touch): a loop whose lower run is broken by a notch up
// over a back-side wheel, the runs either side of the notch both exactly on y = −R. The path is
// accepted (it was refused as crossing itself), its two collinear spans apart along the line.
TEST(DynamicsSerpentine, CollinearSpansThatDoNotOverlapDoNotCross) {
  const double r = pitch_radius(18);
  // counter-clockwise: A, B (the notch's left), E (on the back, the notch's top), C (its right),
  // D, F, G
  const std::vector<Circle> circles = {{0.0, 0.0, r},  {0.15, 0.0, r}, {0.3, 0.3, r, true},
                                       {0.45, 0.0, r}, {0.8, 0.0, r},  {0.8, 0.6, r},
                                       {0.0, 0.6, r}};
  const BeltPath p = belt_path(circles, 0);
  for (const BeltPath::Fault& f : p.faults) ADD_FAILURE() << f.wheel << ": " << f.why;
  ASSERT_FALSE(p.pieces.empty());
  std::vector<const PathPiece*> low;  // the spans on y = −R
  for (const PathPiece& q : p.pieces)
    if (!q.arc && q.y0 == -r && q.y1 == -r) low.push_back(&q);
  ASSERT_EQ(low.size(), 2u);  // A -> B and C -> D, exactly on one line
  EXPECT_EQ(low[0]->wheel, 0u);
  EXPECT_EQ(low[1]->wheel, 3u);
  EXPECT_LT(std::max(low[0]->x0, low[0]->x1), std::min(low[1]->x0, low[1]->x1));
  // the path turns once round and has the notch: its polygon winds 1 round every inside wheel
  std::vector<double> px, py;
  for (int k = 0; k < 20000; ++k) {
    const PathPoint q = path_point(p, p.length * k / 20000.0);
    px.push_back(q.x);
    py.push_back(q.y);
  }
  for (std::size_t w = 0; w < circles.size(); ++w)
    EXPECT_EQ(winding(px, py, circles[w].x, circles[w].y), circles[w].back ? 0 : 1) << w;
}

// The start on the example's serpentine loop presses no roller into a tooth: every roller within
// reach of a wheel is clear of its tooth surfaces (the seats straddle the wrapped rollers) — the
// contact is the same on a back-side wheel (the roller pressed towards its centre by the chain).
TEST(DynamicsSerpentine, StartPressesNoRollerIntoATooth) {
  const Wheels w = example_wheels();
  const BeltPath path = belt_path(w.circles, 0);
  const int count = static_cast<int>(std::lround(path_links(path, kPitch)));
  const LoopPlacement place = place_loop(path, w.circles, w.teeth, count, kPitch);
  ASSERT_FALSE(place.s.empty());
  const State st = loop_state(path, w.circles, place, 0.5);
  for (std::size_t k = 0; k < w.circles.size(); ++k) {
    const Sprocket s = iso606_sprocket(kPitch, kRoller, kWidth, w.teeth[k], w.circles[k].x,
                                       w.circles[k].y, 2e8, 0.0);
    for (std::size_t i = 0; i < st.nodes(); ++i) {
      const SeatContact c =
          seat_contact(s, st.x[i], st.y[i], st.vx[i], st.vy[i], st.angle[k], st.speed[k]);
      EXPECT_LE(c.penetration, 1e-9) << "wheel " << k << " node " << i;
    }
  }
}

// The example's loop as a model: the driver at `omega`, the driven wheel with J = 0.02 kg m² and
// `load`, the back-side idler (J = 0.002 kg m²) on a slide along +y (into the loop) pushed by
// `force` through a damper.
struct Loop {
  Model model;
  State state;
  Wheels wheels = example_wheels();
};
Loop serpentine_loop(double omega, double load, double force, double damping) {
  Loop l;
  const BeltPath path = belt_path(l.wheels.circles, 0);
  const int count = static_cast<int>(std::lround(path_links(path, kPitch)));
  const LoopPlacement place = place_loop(path, l.wheels.circles, l.wheels.teeth, count, kPitch);
  EXPECT_FALSE(place.s.empty());
  l.model = uniform_chain(place.s.size(), true, place.spacing, kMass * kPitch, 5e7, 100.0, false);
  for (std::size_t w = 0; w < 3; ++w) {
    const Circle& c = l.wheels.circles[w];
    l.model.sprockets.push_back(
        iso606_sprocket(kPitch, kRoller, kWidth, l.wheels.teeth[w], c.x, c.y, 2e8, 800.0));
  }
  l.model.sprockets[0].driver = true;
  l.model.sprockets[0].speed = omega;
  Sprocket& idler = l.model.sprockets[1];
  idler.inertia = 0.002;
  idler.takeup = true;
  idler.takeup_dx = 0.0;
  idler.takeup_dy = 1.0;
  idler.takeup_force = force;
  idler.takeup_damping = damping;
  idler.takeup_mass = 1.0;
  l.model.sprockets[2].inertia = 0.02;
  l.model.sprockets[2].load_torque = load;
  l.state = loop_state(path, l.wheels.circles, place, omega * l.wheels.circles[0].radius);
  l.state.speed[0] = omega;
  return l;
}

// The force balance on the idler along its slide e = +y with the idler at `idler_y`: the chain
// pulls the wrapped arc's ends along the leaving and the arriving span, so on the wheel it acts
// with T (d_out − d_in), and F e + T (d_out − d_in) = 0 along e: T = −F / (e·(d_out − d_in)).
// Also the two spans either side of the idler (the path's straight pieces 0 -> 1 and 1 -> 2).
double balance_tension(double force, double idler_y, PathPiece& before, PathPiece& after) {
  const Wheels w = example_wheels(idler_y);
  const BeltPath path = belt_path(w.circles, 0);
  for (std::size_t k = 0; k < path.pieces.size(); ++k) {
    const PathPiece& arc = path.pieces[k];
    if (!arc.arc || arc.wheel != 1) continue;
    before = path.pieces[(k + path.pieces.size() - 1) % path.pieces.size()];
    after = path.pieces[k + 1];
    const double din_y = (before.y1 - before.y0) / before.length;
    const double dout_y = (after.y1 - after.y0) / after.length;
    return -force / (dout_y - din_y);
  }
  return NAN;
}

// The mean tension of the links on a straight span (their middles within 2 mm of it), away from
// its ends by half a pitch.
double span_tension(const Model& m, const State& s, const PathPiece& span) {
  std::vector<double> t(m.links());
  link_tensions(m, s, t);
  const double ux = (span.x1 - span.x0) / span.length, uy = (span.y1 - span.y0) / span.length;
  double sum = 0.0;
  int count = 0;
  for (std::size_t j = 0; j < s.nodes(); ++j) {
    const std::size_t b = (j + 1) % s.nodes();
    const double mx = 0.5 * (s.x[j] + s.x[b]) - span.x0, my = 0.5 * (s.y[j] + s.y[b]) - span.y0;
    const double along = mx * ux + my * uy, off = std::abs(mx * uy - my * ux);
    if (off > 0.002 || along < 0.5 * kPitch || along > span.length - 0.5 * kPitch) continue;
    sum += t[j];
    ++count;
  }
  EXPECT_GE(count, 2);
  return sum / count;
}

// At rest: the take-up pushes the back-side idler into the slack side until the chain's pull on
// it balances the force; both spans either side carry the balance's tension (1 %).
TEST(DynamicsSerpentine, StaticTensionBalancesTheTakeupOnTheBackSideIdler) {
  const double force = 600.0;
  Loop l = serpentine_loop(0.0, 0.0, force, 2000.0);
  l.model.drag = 20.0;  // settle the chain's transverse motion too
  Integrator integ(l.model, {.step = 2e-4, .theta = 1.0});
  for (int k = 0; k < 2500; ++k) ASSERT_TRUE(integ.step(l.model, l.state).converged) << k;
  EXPECT_LT(std::abs(l.state.slide_speed[1]), 1e-6);
  EXPECT_GT(l.state.slide[1], 0.0);  // the idler moved into the loop, taking up the stretch
  PathPiece before, after;
  const double closed =
      balance_tension(force, l.wheels.circles[1].y + l.state.slide[1], before, after);
  // 1 %, plus the wrapped polygon's effect on the span's line: its ends lie on the chords of the
  // wheels' polygons, up to R (1 − cos(π/z)) off the pitch circle's tangent, which turns a span
  // of length L by up to 2 R (1 − cos(π/z)) / L and changes the balance's T by ½ cot(β/2) per
  // radian (β the idler's wrap): 0.6 % on the long span before the idler, 2.2 % on the 66 mm one
  // after it
  const double r = l.wheels.circles[1].radius, sag = r * (1 - std::cos(kPi / 18));
  const double beta =
      std::acos((before.x1 - before.x0) * (after.x1 - after.x0) / (before.length * after.length) +
                (before.y1 - before.y0) * (after.y1 - after.y0) / (before.length * after.length));
  for (const PathPiece* span : {&before, &after}) {
    const double tol = 0.01 + 0.5 / std::tan(0.5 * beta) * 2 * sag / span->length;
    EXPECT_NEAR(span_tension(l.model, l.state, *span), closed, tol * closed)
        << "span " << span->wheel << " -> " << span->next;
  }
  EXPECT_NEAR(-integ.applied_slide_force()[1], force, 1e-3 * force);
  // deflecting the slack span raises its tension above the force's half: the wrap is < 180 deg
  EXPECT_GT(closed, 0.5 * force);
}

// Running: the driver at 13 rad/s against 10 N m; over the last 0.2 s of 0.6 s the spans either
// side of the back-side idler carry the balance's tension plus q v² (1 %), the idler turns
// clockwise at the chain's speed over its radius (1 %) and no roller goes deeper than 20 um.
TEST(DynamicsSerpentine, RunningLoopIsStableAndTheSlackSpansCarryTheBalance) {
  const double force = 600.0, omega = 13.0;
  Loop l = serpentine_loop(omega, 10.0, force, 500.0);
  l.model.axial_damping = 200.0;
  Integrator integ(l.model, {.step = 1e-4, .theta = 0.6});
  double a = 0.0, b = 0.0, slide = 0.0, speed = 0.0, deepest = 0.0;
  int samples = 0;
  const int steps = 6000, window = 2000;
  PathPiece before, after;
  balance_tension(force, l.wheels.circles[1].y, before, after);
  for (int k = 0; k < steps; ++k) {
    const StepReport r = integ.step(l.model, l.state);
    ASSERT_TRUE(r.converged) << k;
    deepest = std::max(deepest, r.max_penetration);
    if (k < steps - window) continue;
    a += span_tension(l.model, l.state, before);
    b += span_tension(l.model, l.state, after);
    slide += l.state.slide[1];
    speed += l.state.speed[1];
    ++samples;
  }
  a /= samples;
  b /= samples;
  slide /= samples;
  speed /= samples;
  const double v = omega * l.wheels.circles[0].radius;
  const double closed =
      balance_tension(force, l.wheels.circles[1].y + slide, before, after) + kMass * v * v;
  EXPECT_NEAR(a, closed, 0.01 * closed);
  EXPECT_NEAR(b, closed, 0.01 * closed);
  EXPECT_NEAR(speed, -v / l.wheels.circles[1].radius, 0.01 * v / l.wheels.circles[1].radius);
  EXPECT_LT(deepest, 20e-6);
}

}  // namespace
}  // namespace catena::dynamics
