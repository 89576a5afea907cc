// A chain drawn slowly and steadily over a loaded arc rail (Guide::load_per_metre on an arc;
// docs/models/dynamics.md, "A conveyed load"), against the capstan equation with distributed
// weight integrated independently (classical RK4, fine steps).
//
// The rig: a level frictionless entry rail, the arc (30°, friction μ, carrying q_L), a
// frictionless straight exit rail tangent to it. The chain's entry end is held back by a constant
// force T_in along the entry rail (frictionless and level: the arc's entry tension is T_in); its
// exit end is a node of 1000 kg, its weight balanced by a constant force, drawn along the exit
// rail by another — a sled so heavy that the chain's speed barely changes over the run
// (0.2 m/s at the start) whatever the tensions. Convex: an outside arc over a hump's top, the
// chain going from the level down 30°; concave: an inside arc in a valley, from the level up 30°.
//
// Along the arc (s the arc length on the roller centres' line, radius ρ, in the direction of
// motion t; n the free side's normal, σ = +1 on a convex arc, −1 on a concave one), the forces on
// an element ds of a chain of q per metre carrying q_L: dT/ds t + T dt/ds + N n − μ N t +
// (q + q_L) g = q v² dt/ds, with dt/ds = −σ n/ρ (the load has no inertia in the model). Across:
//   N = σ (T − q v²)/ρ − (q + q_L) g·n   (the rail's normal force per metre, > 0);
// along:
//   dT/ds = μ N − (q + q_L) g·t.
// On the frictionless straight exit rail (no load) dT/ds = −q g·t. The simulation's link tension
// at the link nearest the arc's exit, averaged over the run's second second, is compared with
// that solution at the link's middle within 1 %.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "catena/dynamics/chain.hpp"
#include "catena/dynamics/integrator.hpp"

namespace catena::dynamics {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kPitch = 0.01905;   // [m] 12B
constexpr double kNodeMass = 0.024;  // [kg] q = 1.26 kg/m
constexpr double kRoller = 0.006;    // [m] r
constexpr double kG = 9.81;          // [m/s²] along −y
constexpr double kSled = 1000.0;     // [kg] the exit end node

struct ArcRig {
  bool convex = true;
  double radius = 0.5;  // [m] R, the rail's surface
  double friction = 0.1;
  double load = 5.0;    // [kg/m] q_L on the arc
  double entry = 20.0;  // [N] T_in
  double speed = 0.2;   // [m/s] at the start
};

// The rig's path: s from the arc's entry along the roller centres' line (< 0 on the entry rail,
// > the arc's length on the exit rail), its point and its direction of motion.
struct Path {
  double cx = 0.0, cy = 0.0, rho = 0.0, sweep = kPi / 6, from = 0.0, turn = 0.0;
  double length = 0.0;  // [m] the arc's on the roller centres' line
  void point(double s, double& x, double& y, double& tx, double& ty) const {
    const double a = std::clamp(s, 0.0, length) / rho, phi = from + turn * a;
    tx = -turn * std::sin(phi);
    ty = turn * std::cos(phi);
    if (s < 0.0) {
      x = s;
      y = kRoller;
      return;
    }
    x = cx + rho * std::cos(phi);
    y = cy + rho * std::sin(phi);
    if (s > length) {
      x += (s - length) * tx;
      y += (s - length) * ty;
    }
  }
  // s of a point near the path
  double place(double x, double y) const {
    double a = turn * (std::atan2(y - cy, x - cx) - from);
    a -= 2 * kPi * std::floor((a + kPi) / (2 * kPi));
    if (a < 0.0) return x;
    if (a <= sweep) return rho * a;
    double ex = 0.0, ey = 0.0, tx = 0.0, ty = 0.0;
    point(length, ex, ey, tx, ty);
    return length + (x - ex) * tx + (y - ey) * ty;
  }
};

Path path_of(const ArcRig& d) {
  Path p;
  p.cx = 0.0;
  p.cy = d.convex ? -d.radius : d.radius;
  p.rho = d.convex ? d.radius + kRoller : d.radius - kRoller;
  p.from = d.convex ? kPi / 2 : 1.5 * kPi;
  p.turn = d.convex ? -1.0 : 1.0;  // clockwise over the hump, counter-clockwise in the valley
  p.length = p.rho * p.sweep;
  return p;
}

// The capstan equation with distributed weight (above) from T_in at the arc's entry, by RK4 on a
// grid of `steps` per metre; T(s) at s in [0, s_end], interpolated linearly between grid points.
struct Capstan {
  double ds = 0.0;
  std::vector<double> t;
  double at(double s) const {
    if (s <= 0.0) return t.front();
    const double k = s / ds;
    const auto i = static_cast<std::size_t>(k);
    if (i + 1 >= t.size()) return t.back();
    return t[i] + (k - static_cast<double>(i)) * (t[i + 1] - t[i]);
  }
};

Capstan capstan(const ArcRig& d, const Path& p, double s_end) {
  const double q = kNodeMass / kPitch, sigma = d.convex ? 1.0 : -1.0;
  auto slope = [&](double s, double tension) {
    double x = 0.0, y = 0.0, tx = 0.0, ty = 0.0;
    p.point(s, x, y, tx, ty);
    const double gt = -kG * ty;  // g·t, g = (0, −g)
    if (s > p.length) return -q * gt;
    const double phi = p.from + p.turn * s / p.rho;
    const double gn = -kG * sigma * std::sin(phi);  // g·n, n = σ (cos φ, sin φ) the free side
    const double normal = sigma * (tension - q * d.speed * d.speed) / p.rho - (q + d.load) * gn;
    return d.friction * normal - (q + d.load) * gt;
  };
  Capstan c;
  const auto n = static_cast<std::size_t>(std::ceil(s_end * 4000.0));
  c.ds = s_end / static_cast<double>(n);
  c.t.assign(n + 1, d.entry);
  for (std::size_t i = 0; i < n; ++i) {  // the arc's exit falls between grid points: step there
    const double s = c.ds * static_cast<double>(i), h = c.ds, t0 = c.t[i];
    const double k1 = slope(s, t0), k2 = slope(s + 0.5 * h, t0 + 0.5 * h * k1);
    const double k3 = slope(s + 0.5 * h, t0 + 0.5 * h * k2), k4 = slope(s + h, t0 + h * k3);
    c.t[i + 1] = t0 + h * (k1 + 2 * k2 + 2 * k3 + k4) / 6.0;
  }
  return c;
}

struct ArcRun {
  double tension = 0.0;    // [N] the simulation's, at the link nearest the arc's exit, mean
  double reference = 0.0;  // [N] the capstan equation's at that link's middle, mean
  double speed_end = 0.0;  // [m/s] the chain's at the run's end
};

ArcRun run(const ArcRig& d, bool arc_loaded = true) {
  const Path p = path_of(d);
  const double entry_run = 0.4, exit_run = 0.1;  // [m] the chain's ends from the arc's ends
  const auto n = static_cast<std::size_t>(std::ceil((entry_run + p.length + exit_run) / kPitch));
  Model m = uniform_chain(n, false, kPitch, kNodeMass, 5e7, 100.0, false);
  m.gravity_y = -kG;
  m.mass.back() = kSled;
  double ox = 0.0, oy = 0.0, otx = 0.0, oty = 0.0;  // the exit rail's direction
  p.point(p.length, ox, oy, otx, oty);
  // the sled drawn by the force the capstan equation gives at its start (any force would do: its
  // mass keeps the chain's acceleration (F − T)/M, and so the tensions' inertial part, negligible;
  // the run checks its speed)
  const Capstan ref = capstan(d, p, p.length + exit_run + 0.4);
  const double pull = ref.at(-entry_run + kPitch * static_cast<double>(n - 1));
  m.loads = {{0, -d.entry, 0.0}, {n - 1, pull * otx, pull * oty + kSled * kG}};
  Guide rail;
  rail.roller_radius = kRoller;
  rail.contact_stiffness = 1e7;
  rail.contact_damping = 100.0;
  Guide in = rail, out = rail, arc = rail;
  in.x0 = -1.0;
  in.x1 = 0.0;
  const double sx = ox - kRoller * (-oty), sy = oy - kRoller * otx;  // the exit rail's surface
  out.x0 = sx;
  out.y0 = sy;
  out.x1 = sx + otx;
  out.y1 = sy + oty;
  arc.kind = Guide::Kind::kArc;
  arc.inside = !d.convex;
  arc.centre_x = p.cx;
  arc.centre_y = p.cy;
  arc.radius = d.radius;
  arc.start_angle = d.convex ? kPi / 3 : 1.5 * kPi;
  arc.end_angle = arc.start_angle + p.sweep;
  arc.friction = d.friction;
  arc.load_per_metre = arc_loaded ? d.load : 0.0;
  m.guides = {in, arc, out};
  EXPECT_TRUE(validate(m).empty());
  State s(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    double tx = 0.0, ty = 0.0;
    p.point(-entry_run + kPitch * static_cast<double>(i), s.x[i], s.y[i], tx, ty);
    s.vx[i] = d.speed * tx;
    s.vy[i] = d.speed * ty;
  }
  Integrator integ(m, {.step = 1e-4, .theta = 0.6});
  std::vector<double> tension(m.links());
  ArcRun r;
  int samples = 0;
  const double t0 = 0.4, t1 = 1.4;
  while (s.time < t1 - 0.5e-4) {
    if (!integ.step(m, s).converged) {
      ADD_FAILURE() << "a step did not converge at t = " << s.time;
      return r;
    }
    if (s.time < t0) continue;
    link_tensions(m, s, tension);
    std::size_t best = 0;
    double gap = INFINITY;
    for (std::size_t j = 0; j + 1 < n; ++j) {
      const double at = p.place(0.5 * (s.x[j] + s.x[j + 1]), 0.5 * (s.y[j] + s.y[j + 1]));
      if (std::abs(at - p.length) < gap) {
        gap = std::abs(at - p.length);
        best = j;
      }
    }
    r.tension += tension[best];
    r.reference +=
        ref.at(p.place(0.5 * (s.x[best] + s.x[best + 1]), 0.5 * (s.y[best] + s.y[best + 1])));
    ++samples;
  }
  r.tension /= samples;
  r.reference /= samples;
  r.speed_end = std::hypot(s.vx[n / 2], s.vy[n / 2]);
  return r;
}

void compare(const ArcRig& d) {
  const ArcRun r = run(d);
  const ArcRun bare = run(d, false);  // the same rig with the arc's load switched off
  std::printf(
      "%s arc R %.2f m mu %.2f q_L %.1f kg/m T_in %.1f N: exit %.4f N, capstan %.4f N (%+.3f %%); "
      "unloaded arc %.4f N (%+.2f %%); speed at the end %.4f m/s\n",
      d.convex ? "convex" : "concave", d.radius, d.friction, d.load, d.entry, r.tension,
      r.reference, 100 * (r.tension / r.reference - 1), bare.tension,
      100 * (bare.tension / r.reference - 1), r.speed_end);
  EXPECT_NEAR(r.tension / r.reference, 1.0, 0.01);
  EXPECT_NEAR(r.speed_end, d.speed, 0.05 * d.speed) << "the sled kept the chain's speed";
  // the load's part is what is checked: without it the exit tension is off by more than 3 %
  EXPECT_GT(std::abs(bare.tension / r.reference - 1), 0.03);
}

// Over a hump's top: from the level down 30° on an outside arc of R = 0.5 m.
TEST(DynamicsArcLoad, ConvexArcMatchesTheCapstanEquation) {
  ArcRig d;
  compare(d);
}

// In a valley: from the level up 30° on an inside arc of R = 1 m, the tension low enough that the
// weight holds the chain on the rail (T/ρ < (q + q_L) g cos β).
TEST(DynamicsArcLoad, ConcaveArcMatchesTheCapstanEquation) {
  ArcRig d;
  d.convex = false;
  d.radius = 1.0;
  d.friction = 0.3;
  d.load = 3.0;
  d.entry = 15.0;
  compare(d);
}

}  // namespace
}  // namespace catena::dynamics
