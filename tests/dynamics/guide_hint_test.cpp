// The guides' node hint (docs/models/dynamics.md, "Guides: O(N) a step"): on random guides and
// random node motions (small moves that keep the lists, large ones that rebuild them, jumps, guides
// replaced), every node inside a guide's bounding box is on that guide's list, the lists are in
// increasing node order and hold only nodes near the box; and the integrator gives bit-identical
// states and works with the hint and with every node tried against every guide, on a conveyor loop
// with 26 guides run far enough for the lists to be rebuilt many times.
#include "catena/dynamics/guide_hint.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <random>
#include <vector>

#include "catena/dynamics/integrator.hpp"
#include "random_guides.hpp"
#include "two_wheel_loops.hpp"

namespace catena::dynamics {
namespace {

constexpr double kPi = std::numbers::pi;

// Guides within ±2 m of the origin, rollers of 2–15 mm, rails up to 1.5 m, arcs of 0.02–0.6 m
// radius spanning 0.1 rad to a whole turn (tests/dynamics/random_guides.hpp).
Guide random_guide(std::mt19937_64& rng, int kind) {
  const testing::GuideRanges ranges{.roller_lo = 2e-3,
                                    .roller_hi = 1.5e-2,
                                    .centre = 2.0,
                                    .length_lo = 1e-3,
                                    .length_hi = 1.5,
                                    .radius_lo = 0.02,
                                    .radius_over_roller = 0.0,
                                    .radius_hi = 0.6,
                                    .span_lo = 0.1};
  return testing::random_guide(rng, kind, ranges);
}

// A point on or near a guide's surface (within ±2 roller radii of it), near an edge of a guide's
// box (where a node crosses into it), or anywhere at random.
void place(std::mt19937_64& rng, const std::vector<Guide>& guides, double margin, double& x,
           double& y) {
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  auto uni = [&](double a, double b) { return a + (b - a) * u01(rng); };
  const double pick = u01(rng);
  if (pick < 0.2) {
    x = uni(-2.5, 2.5);
    y = uni(-2.5, 2.5);
    return;
  }
  if (pick < 0.5) {  // near an edge of a guide's box, within ±1.5 margins of it
    const GuideBounds b = guide_bounds(
        guides[std::min(guides.size() - 1,
                        static_cast<std::size_t>(u01(rng) * static_cast<double>(guides.size())))]);
    const double off = uni(-1.5, 1.5) * margin;
    const int edge = static_cast<int>(4.0 * u01(rng));
    x = edge == 0 ? b.x_lo + off : edge == 1 ? b.x_hi + off : uni(b.x_lo, b.x_hi);
    y = edge == 2 ? b.y_lo + off : edge == 3 ? b.y_hi + off : uni(b.y_lo, b.y_hi);
    return;
  }
  const Guide& g = guides[std::min(
      guides.size() - 1, static_cast<std::size_t>(u01(rng) * static_cast<double>(guides.size())))];
  const double off = uni(-2.0, 2.0) * g.roller_radius;
  const double along = uni(-0.05, 1.05);
  testing::point_near(g, along, off, x, y);
}

TEST(DynamicsGuideHint, ListsEveryNodeInsideAGuidesBoxOnRandomMotions) {
  std::mt19937_64 rng(2611);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  constexpr double kMargin = 0.005;
  constexpr std::size_t kGuides = 50, kNodes = 600;
  std::vector<Guide> guides;
  for (std::size_t g = 0; g < kGuides; ++g)
    guides.push_back(random_guide(rng, static_cast<int>(g)));
  std::vector<double> x(kNodes), y(kNodes);
  for (std::size_t i = 0; i < kNodes; ++i) place(rng, guides, kMargin, x[i], y[i]);
  std::vector<double> vx(kNodes), vy(kNodes);
  for (std::size_t i = 0; i < kNodes; ++i) {
    const double a = 2.0 * kPi * u01(rng), speed = 0.2 * kMargin * u01(rng);
    vx[i] = speed * std::cos(a);
    vy[i] = speed * std::sin(a);
  }
  GuideHint hint(kMargin);
  long inside = 0, listed = 0, kept = 0;
  std::vector<std::uint8_t> on_list(kNodes);
  for (int round = 0; round < 400; ++round) {
    if (round > 0) {
      const double mode = u01(rng);
      if (mode < 0.05) {  // a guide replaced: its box changes
        guides[static_cast<std::size_t>(u01(rng) * kGuides) % kGuides] = random_guide(rng, round);
      } else if (mode < 0.1) {  // a few nodes jump far
        for (int k = 0; k < 5; ++k) {
          const auto i = static_cast<std::size_t>(u01(rng) * kNodes) % kNodes;
          place(rng, guides, kMargin, x[i], y[i]);
        }
      } else if (mode < 0.3) {  // every node moves by up to 10^[-6, -1.7] m, in any direction
        const double size = std::pow(10.0, -6.0 + 4.3 * u01(rng) * u01(rng));
        for (std::size_t i = 0; i < kNodes; ++i) {
          const double a = 2.0 * kPi * u01(rng), r = size * u01(rng);
          x[i] += r * std::cos(a);
          y[i] += r * std::sin(a);
        }
      } else {  // every node drifts on at its own velocity (up to a fifth of a margin a round)
        const double dt = u01(rng);
        for (std::size_t i = 0; i < kNodes; ++i) {
          x[i] += dt * vx[i];
          y[i] += dt * vy[i];
        }
      }
    }
    if (!hint.update(guides, x, y)) ++kept;
    ASSERT_EQ(hint.bounds().size(), kGuides);
    for (std::size_t g = 0; g < kGuides; ++g) {
      const GuideBounds b = guide_bounds(guides[g]);
      ASSERT_EQ(hint.bounds()[g].x_lo, b.x_lo);
      ASSERT_EQ(hint.bounds()[g].y_hi, b.y_hi);
      const auto nodes = hint.nodes(g);
      std::fill(on_list.begin(), on_list.end(), 0);
      for (std::size_t k = 0; k < nodes.size(); ++k) {
        if (k > 0) {
          ASSERT_LT(nodes[k - 1], nodes[k]) << "guide " << g << " round " << round;
        }
        const std::uint32_t i = nodes[k];
        ASSERT_LT(i, kNodes);
        on_list[i] = 1;
        // listed at the build within 1.25 margins of the box, moved at most a margin since
        const double reach = 2.25 * kMargin + 1e-12;
        ASSERT_TRUE(x[i] >= b.x_lo - reach && x[i] <= b.x_hi + reach && y[i] >= b.y_lo - reach &&
                    y[i] <= b.y_hi + reach)
            << "guide " << g << " node " << i << " round " << round;
      }
      listed += static_cast<long>(nodes.size());
      for (std::size_t i = 0; i < kNodes; ++i) {
        if (!guide_touch_possible(b, x[i], y[i])) continue;
        ++inside;
        ASSERT_EQ(on_list[i], 1) << "guide " << g << " node " << i << " round " << round;
      }
    }
  }
  // both paths taken often: lists kept, lists rebuilt; many pairs inside boxes; the lists short
  EXPECT_GT(kept, 100);
  EXPECT_GT(hint.rebuilds(), 30U);
  EXPECT_GT(inside, 100000);
  EXPECT_LT(listed, static_cast<long>(kGuides * kNodes * 400) / 4);
}

// A guide with a non-finite coordinate (its box the whole plane) lists every node; a node at a
// non-finite position is on no finite guide's list and forces a rebuild at every update.
TEST(DynamicsGuideHint, NonFiniteGuidesAndNodes) {
  std::mt19937_64 rng(7);
  std::vector<Guide> guides{random_guide(rng, 0), random_guide(rng, 1)};
  guides[1].centre_x = NAN;
  std::vector<double> x{guides[0].x0, 0.3, NAN}, y{guides[0].y0, -0.2, 1.0};
  GuideHint hint(0.01);
  EXPECT_TRUE(hint.update(guides, x, y));
  ASSERT_EQ(hint.nodes(1).size(), 3U);
  for (const std::uint32_t i : hint.nodes(0)) EXPECT_NE(i, 2U);
  EXPECT_EQ(hint.nodes(0).size(), 1U);  // the node on the rail's first end
  EXPECT_TRUE(hint.update(guides, x, y));
  x[2] = 5.0;
  EXPECT_TRUE(hint.update(guides, x, y));
  EXPECT_FALSE(hint.update(guides, x, y));
}

// The conveyor of validation (6b) with each level rail cut into 12 pieces (26 guides), 0.1 s of
// motion (the chain moves 24 mm, five of the hint's margins): states and works bit-identical.
TEST(DynamicsGuideHint, IntegratorResultsBitIdenticalWithAndWithoutTheHint) {
  constexpr double kPitch = 0.01905;
  testing::Conveyor conveyor;  // validation (6b)'s loop and guides
  conveyor.pieces = 12;
  const testing::Loop loop = testing::conveyor_loop(conveyor);
  const Model& m = loop.model;
  const State& s0 = loop.state;
  ASSERT_EQ(m.guides.size(), 26U);
  const Sprocket& a = m.sprockets[0];
  State with = s0, without = s0;
  Integrator hinted(m, {.step = 1e-4, .theta = 0.6});
  Integrator every(m, {.step = 1e-4, .theta = 0.6, .guide_hint = false});
  const auto same = [](const std::vector<double>& p, const std::vector<double>& q) {
    return p.size() == q.size() && std::memcmp(p.data(), q.data(), p.size() * sizeof(double)) == 0;
  };
  double friction = 0.0;
  for (int step = 0; step < 1000; ++step) {
    const StepReport ra = hinted.step(m, with);
    const StepReport rb = every.step(m, without);
    ASSERT_TRUE(ra.converged && rb.converged) << "step " << step;
    ASSERT_EQ(ra.iterations, rb.iterations) << "step " << step;
    ASSERT_TRUE(same(with.x, without.x) && same(with.y, without.y) && same(with.vx, without.vx) &&
                same(with.vy, without.vy) && same(with.angle, without.angle) &&
                same(with.speed, without.speed))
        << "step " << step;
    ASSERT_EQ(std::memcmp(&ra.friction_work, &rb.friction_work, sizeof(double)), 0);
    ASSERT_EQ(std::memcmp(&ra.contact_damping_work, &rb.contact_damping_work, sizeof(double)), 0);
    friction += ra.friction_work;
  }
  EXPECT_LT(friction, -1e-3);  // the rails carried the chain and rubbed it
  EXPECT_GT(std::abs(with.angle[0] - s0.angle[0]) * a.pitch_radius, 4.0 * 0.25 * kPitch);
}

// The every-pair loops kept as the oracles of lift_onto_guides and of energy()'s guide term.
void lift_every_pair(const std::vector<Guide>& guides, std::vector<double>& x,
                     std::vector<double>& y) {
  for (const Guide& g : guides) {
    for (std::size_t i = 0; i < x.size(); ++i) {
      const GuideContact c = guide_contact(g, x[i], y[i], 0.0, 0.0);
      if (!c.active) continue;
      x[i] += c.penetration * c.nx;
      y[i] += c.penetration * c.ny;
    }
  }
}

bool same_bits(const std::vector<double>& p, const std::vector<double>& q) {
  return p.size() == q.size() && std::memcmp(p.data(), q.data(), p.size() * sizeof(double)) == 0;
}

// Random guides laid over each other (a node lifted by one rail into the next one's box), nodes
// on and near them, jumps and non-finite guides and nodes: the positions bit-identical to the loop
// over every guide and every node, and many nodes lifted, some more than once.
TEST(DynamicsGuideHint, LiftOntoGuidesBitIdenticalToEveryPair) {
  std::mt19937_64 rng(2126);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  long lifted = 0, twice = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const std::size_t count = 1 + static_cast<std::size_t>(60.0 * u01(rng));
    std::vector<Guide> guides;
    for (std::size_t g = 0; g < count; ++g) {
      guides.push_back(random_guide(rng, static_cast<int>(g + trial)));
      if (g > 0 && u01(rng) < 0.3) {  // a copy of the last one, shifted by under a roller radius
        Guide copy = guides[g - 1];
        const double dx = (u01(rng) - 0.5) * copy.roller_radius;
        const double dy = (u01(rng) - 0.5) * copy.roller_radius;
        copy.x0 += dx;
        copy.x1 += dx;
        copy.centre_x += dx;
        copy.y0 += dy;
        copy.y1 += dy;
        copy.centre_y += dy;
        guides.back() = copy;
      }
    }
    if (trial % 10 == 9) guides[count / 2].x0 = NAN;  // no finite box: tried against every node
    const std::size_t n = 500;
    std::vector<double> x(n), y(n);
    for (std::size_t i = 0; i < n; ++i) place(rng, guides, 0.005, x[i], y[i]);
    if (trial % 7 == 3) {
      x[3] = NAN;
      y[4] = INFINITY;
    }
    std::vector<double> ex = x, ey = y;
    lift_every_pair(guides, ex, ey);
    std::vector<double> hx = x, hy = y;
    lift_onto_guides(guides, hx, hy);
    ASSERT_TRUE(same_bits(hx, ex) && same_bits(hy, ey)) << "trial " << trial;
    for (std::size_t i = 0; i < n; ++i) {
      if (!(x[i] == ex[i] && y[i] == ey[i]) && !std::isnan(x[i]) && !std::isnan(y[i])) ++lifted;
      int moves = 0;
      double px = x[i], py = y[i];
      for (const Guide& g : guides) {
        const GuideContact c = guide_contact(g, px, py, 0.0, 0.0);
        if (!c.active) continue;
        px += c.penetration * c.nx;
        py += c.penetration * c.ny;
        ++moves;
      }
      if (moves > 1) ++twice;
    }
  }
  EXPECT_GT(lifted, 2000);
  EXPECT_GT(twice, 100);
}

// A straight rail from (x0, y0) to (x1, y1), the rollers of radius r on its left.
Guide straight_rail(double x0, double y0, double x1, double y1, double r) {
  Guide g;
  g.kind = Guide::Kind::kStraight;
  g.x0 = x0;
  g.y0 = y0;
  g.x1 = x1;
  g.y1 = y1;
  g.roller_radius = r;
  return g;
}

// Two rails whose lifts disagree (docs/models/dynamics.md, "Guides against the starting path:
// several rails"), 12B rollers (r = 6.035 mm): a rail A along y = 0 (x from 0 to 0.1 m, rollers
// above) and a rail B, 9.5 mm above it (x from 0.02 to 0.08 m, rollers above): a node 3 mm into A
// is 12.5 mm behind B's surface, out of its contact, until A lifts it onto its surface, 9.5 mm
// into B's (past its surface): B pulls it through, named. With B facing down 10 mm above A (a
// channel narrower than a roller), a node 4.035 mm into A lifted onto it is 2.07 mm into B, which
// pushes it back 2.07 mm into A, named. Each node's moves as the loop over every guide makes them;
// a node on one rail alone and nodes clear of both give no conflict.
TEST(DynamicsGuideHint, LiftNamesANodePulledThroughOrLeftInsideAnotherRail) {
  const double r = 0.006035;
  const auto rail = [&](double x0, double y0, double x1, double y1) {
    return straight_rail(x0, y0, x1, y1, r);
  };
  const std::vector<Guide> stacked{rail(0.0, 0.0, 0.1, 0.0), rail(0.02, 0.0095, 0.08, 0.0095)};
  // node 0 under B, 3 mm into A; node 1 into A beyond B's ends; node 2 clear of both
  std::vector<double> x{0.05, 0.09, 0.05}, y{r - 0.003, r - 0.003, 0.05};
  std::vector<double> ex = x, ey = y;
  lift_every_pair(stacked, ex, ey);
  const std::vector<LiftConflict> through = lift_onto_guides(stacked, x, y);
  EXPECT_TRUE(same_bits(x, ex) && same_bits(y, ey));
  ASSERT_EQ(through.size(), 1U);
  EXPECT_EQ(through[0].node, 0U);
  EXPECT_EQ(through[0].first, 0U);
  EXPECT_EQ(through[0].second, 1U);
  EXPECT_TRUE(through[0].through);
  EXPECT_NEAR(through[0].depth, 0.0095, 1e-12);
  EXPECT_NEAR(y[0], 0.0095 + r, 1e-12);  // pulled through B onto its top

  const std::vector<Guide> channel{rail(0.0, 0.0, 0.1, 0.0), rail(0.1, 0.01, 0.0, 0.01)};
  std::vector<double> cx{0.05, 0.05}, cy{0.002, 0.005};
  std::vector<double> fx = cx, fy = cy;
  lift_every_pair(channel, fx, fy);
  const std::vector<LiftConflict> inside = lift_onto_guides(channel, cx, cy);
  EXPECT_TRUE(same_bits(cx, fx) && same_bits(cy, fy));
  ASSERT_EQ(inside.size(), 2U);  // both nodes end 10 mm − r from B's surface, inside A
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(inside[k].node, k);
    EXPECT_EQ(inside[k].first, 1U);
    EXPECT_EQ(inside[k].second, 0U);
    EXPECT_FALSE(inside[k].through);
    EXPECT_NEAR(inside[k].depth, 2.0 * r - 0.01, 1e-12);
  }
}

// The conflict's kind from its depth, not from the rails' order: the stacked rails of the test
// above given the other way round (B first). A lifts the node 9.5 mm into B, past its surface
// (more than the roller radius), and B, earlier in the order, no longer moves it: named as behind
// B's surface (pulled through it), as when B comes after A, not as left inside B's contact.
TEST(DynamicsGuideHint, LiftNamesTheConflictsKindByDepthWhateverTheOrder) {
  const double r = 0.006035;
  const auto rail = [&](double x0, double y0, double x1, double y1) {
    return straight_rail(x0, y0, x1, y1, r);
  };
  const std::vector<Guide> swapped{rail(0.02, 0.0095, 0.08, 0.0095), rail(0.0, 0.0, 0.1, 0.0)};
  std::vector<double> x{0.05}, y{r - 0.003};
  std::vector<double> ex = x, ey = y;
  lift_every_pair(swapped, ex, ey);
  const std::vector<LiftConflict> found = lift_onto_guides(swapped, x, y);
  EXPECT_TRUE(same_bits(x, ex) && same_bits(y, ey));
  ASSERT_EQ(found.size(), 1U);
  EXPECT_EQ(found[0].node, 0U);
  EXPECT_EQ(found[0].first, 1U);
  EXPECT_EQ(found[0].second, 0U);
  EXPECT_TRUE(found[0].through);
  EXPECT_NEAR(found[0].depth, 0.0095, 1e-12);
  EXPECT_NEAR(y[0], r, 1e-12);  // on A's surface, behind B's
}

// The many-guide conveyor's start, its spans laid a third of a roller radius into the rails, and
// energy() at it and after lifting: the rails' elastic energy is the every-pair sum (summed in the
// same order, then the links', as energy() sums them), bit for bit.
TEST(DynamicsGuideHint, StartAndEnergyBitIdenticalToEveryPairOnAManyGuideConveyor) {
  testing::Conveyor conveyor;  // validation (6b)'s loop and guides
  conveyor.pieces = 12;
  const testing::Loop c = testing::conveyor_loop(conveyor);
  Model m = c.model;
  ASSERT_EQ(m.guides.size(), 26U);
  m.sprockets.clear();  // energy()'s elastic sum is then the guides' and the links' alone
  State s = c.state;
  const double r = m.guides.front().roller_radius;
  for (std::size_t i = 0; i < s.x.size(); ++i) s.y[i] -= (s.y[i] > 0.0 ? 1.0 : -1.0) * r / 3.0;
  const auto oracle = [&](const State& st) {
    double e = 0.0;
    for (const Guide& g : m.guides) {
      for (std::size_t i = 0; i < m.nodes(); ++i) {
        const GuideContact gc = guide_contact(g, st.x[i], st.y[i], 0.0, 0.0);
        if (gc.active) e += gc.energy;
      }
    }
    for (std::size_t j = 0; j < m.links(); ++j) {
      const std::size_t b = (j + 1) % m.nodes();
      const double stretch = std::hypot(st.x[b] - st.x[j], st.y[b] - st.y[j]) - m.rest_length(j);
      e += 0.5 * m.axial_stiffness * stretch * stretch;
    }
    return e;
  };
  const double before = energy(m, s).elastic, want_before = oracle(s);
  EXPECT_EQ(std::memcmp(&before, &want_before, sizeof(double)), 0);
  double rails = 0.0;
  for (const Guide& g : m.guides)
    for (std::size_t i = 0; i < m.nodes(); ++i)
      rails += guide_contact(g, s.x[i], s.y[i], 0.0, 0.0).energy;
  EXPECT_GT(rails, 0.0);  // the rollers are pressed into the rails: the guide term is not empty
  State every = s;
  lift_every_pair(m.guides, every.x, every.y);
  lift_onto_guides(m.guides, s.x, s.y);
  ASSERT_TRUE(same_bits(s.x, every.x) && same_bits(s.y, every.y));
  EXPECT_NE(std::memcmp(s.y.data(), c.state.y.data(), s.y.size() * sizeof(double)), 0);
  const double after = energy(m, s).elastic, want_after = oracle(s);
  EXPECT_EQ(std::memcmp(&after, &want_after, sizeof(double)), 0);
}

// energy()'s wheel term on random states of the drive and of the many-guide conveyor (rollers
// moved by up to 0.6 roller radii, wheels turned at random, a third wheel laid over the chain at a
// random place, and now and then a node thrown far off or made non-finite): the elastic energy is
// the every-pair sum — every wheel against every node, then every guide against every node, then
// the links', in energy()'s order — bit for bit, and the seats are pressed (the term is not empty);
// the same through one EnergyScratch kept over every trial (the guard's evaluations, analysis.cpp).
TEST(DynamicsGuideHint, EnergyWheelTermBitIdenticalToEveryPair) {
  std::mt19937_64 rng(2127);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  testing::Conveyor conveyor;
  conveyor.pieces = 12;
  const testing::Loop loops[2] = {testing::benchmark_drive(), testing::conveyor_loop(conveyor)};
  long pressed = 0;
  EnergyScratch scratch;
  for (int trial = 0; trial < 40; ++trial) {
    const testing::Loop& base = loops[trial % 2];
    Model m = base.model;
    State s = base.state;
    ASSERT_GE(m.sprockets.size(), 2U);
    Sprocket extra = m.sprockets[trial % 2];
    extra.driver = false;
    extra.inertia = 0.01;
    extra.centre_x = s.x[static_cast<std::size_t>(u01(rng) * static_cast<double>(s.x.size()))];
    extra.centre_y = 0.5 * extra.pitch_radius * (u01(rng) - 0.5);
    m.sprockets.push_back(extra);
    s.angle.push_back(0.0);
    s.speed.push_back(0.0);
    s.slide.push_back(0.0);
    s.slide_speed.push_back(0.0);
    for (const Sprocket& w : m.sprockets) ASSERT_FALSE(w.takeup || w.pocket);
    const double r = m.sprockets.front().roller_radius;
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      s.x[i] += 1.2 * r * (u01(rng) - 0.5);
      s.y[i] += 1.2 * r * (u01(rng) - 0.5);
    }
    for (double& a : s.angle) a = 2.0 * kPi * u01(rng);
    if (trial % 5 == 4) {
      s.x[7] = 1e3;
      s.y[11] = NAN;
    }
    const std::size_t n = m.nodes();
    double want = 0.0, seats = 0.0;
    for (std::size_t w = 0; w < m.sprockets.size(); ++w) {
      for (std::size_t i = 0; i < n; ++i) {
        const SeatContact c =
            wheel_contact(m.sprockets[w], s.x[i], s.y[i], 0.0, 0.0, s.angle[w], 0.0);
        if (!c.active) continue;
        want += c.energy;
        seats += c.energy;
        ++pressed;
      }
    }
    for (const Guide& g : m.guides) {
      for (std::size_t i = 0; i < n; ++i) {
        const GuideContact gc = guide_contact(g, s.x[i], s.y[i], 0.0, 0.0);
        if (gc.active) want += gc.energy;
      }
    }
    for (std::size_t j = 0; j < m.links(); ++j) {
      const std::size_t b = (j + 1) % n;
      const double stretch = std::hypot(s.x[b] - s.x[j], s.y[b] - s.y[j]) - m.rest_length(j);
      want += 0.5 * m.axial_stiffness * stretch * stretch;
    }
    const double got = energy(m, s).elastic;
    // and with one scratch kept over every trial (the drive's wheels and the conveyor's, its
    // guides or none, their boxes changing from trial to trial): the same bits
    const double kept = energy(m, s, scratch).elastic;
    if (std::isnan(want)) {
      EXPECT_TRUE(std::isnan(got)) << "trial " << trial;
      EXPECT_TRUE(std::isnan(kept)) << "trial " << trial;
    } else {
      EXPECT_EQ(std::memcmp(&got, &want, sizeof(double)), 0)
          << "trial " << trial << ": " << got << " vs " << want;
      EXPECT_EQ(std::memcmp(&kept, &want, sizeof(double)), 0)
          << "trial " << trial << ": " << kept << " vs " << want;
    }
    EXPECT_GT(seats, 0.0) << "trial " << trial;
  }
  EXPECT_GT(pressed, 40 * 20);
}

}  // namespace
}  // namespace catena::dynamics
