// The seat contacts' shortcuts (docs/models/dynamics.md, "Solver"): the seat index without the
// arctangent, the wheel's tooth constants and seat directions taken once, and the wheels'
// candidate lists. Each must give exactly what the plain computation gives, bit for bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

#include "catena/drive/sprocket.hpp"
#include "catena/dynamics/chain.hpp"
#include "catena/dynamics/integrator.hpp"
#include "two_wheel_loops.hpp"

namespace catena::dynamics {
namespace {

constexpr double kPi = std::numbers::pi;

double plain_seat(double rx, double ry, double angle, double tau) {
  return std::nearbyint((std::atan2(ry, rx) - angle) / tau);
}

// equal, or both NaN
bool same(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

TEST(DynamicsSeatConstants, NearestSeatIsTheArctangentFormulaOverRandomRollers) {
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  long mismatches = 0, trials = 0;
  for (const int z : {3, 6, 9, 17, 20, 40, 120}) {
    const double tau = 2.0 * kPi / z;
    for (int trial = 0; trial < 200000; ++trial) {
      const double scale = std::pow(10.0, -6.0 + 7.0 * u(rng));  // 1 µm .. 10 m
      const double a = 2.0 * kPi * u(rng);
      const double rx = scale * std::cos(a), ry = scale * std::sin(a);
      // angles near zero and far out (a wheel that has turned for hours)
      const double angle = (trial % 3 == 0   ? 10.0
                            : trial % 3 == 1 ? 1e4
                                             : 1e6) *
                           (2.0 * u(rng) - 1.0);
      ++trials;
      if (!same(nearest_seat(rx, ry, angle, tau), plain_seat(rx, ry, angle, tau))) ++mismatches;
    }
  }
  EXPECT_EQ(mismatches, 0) << "of " << trials;
}

TEST(DynamicsSeatConstants, NearestSeatIsTheArctangentFormulaHalfWayBetweenSeats) {
  // rollers at x = (φ − angle)/τ = k + ½ + δ: where the two ways could round apart
  std::mt19937_64 rng(22);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  long mismatches = 0, trials = 0;
  for (const int z : {3, 6, 17, 20, 40}) {
    const double tau = 2.0 * kPi / z;
    for (const double delta : {0.0, 1e-16, -1e-16, 1e-13, -1e-13, 1e-10, -1e-10, 1e-8, -1e-8, 1e-7,
                               -1e-7, 1e-6, -1e-6, 1e-5, -1e-5, 1e-3, -1e-3}) {
      for (int trial = 0; trial < 4000; ++trial) {
        const double angle = (trial % 2 == 0 ? 5.0 : 5e5) * (2.0 * u(rng) - 1.0);
        const double k = std::floor(z * u(rng));
        const double phi = angle + (k + 0.5 + delta) * tau;
        const double scale = 0.01 + u(rng);
        const double rx = scale * std::cos(phi), ry = scale * std::sin(phi);
        ++trials;
        if (!same(nearest_seat(rx, ry, angle, tau), plain_seat(rx, ry, angle, tau))) ++mismatches;
      }
    }
  }
  EXPECT_EQ(mismatches, 0) << "of " << trials;
}

TEST(DynamicsSeatConstants, NearestSeatIsTheArctangentFormulaOnTheAxesAndAtOddInputs) {
  const double tau = 2.0 * kPi / 20;
  const double values[] = {0.0,   -0.0,   1.0,      -1.0,      1e-300, -1e-300,
                           1e300, -1e300, INFINITY, -INFINITY, NAN};
  for (const double rx : values) {
    for (const double ry : values) {
      for (const double angle : {0.0, -0.0, kPi, -kPi, 0.5 * tau, -0.5 * tau, 1e7, double{NAN}}) {
        EXPECT_TRUE(same(nearest_seat(rx, ry, angle, tau), plain_seat(rx, ry, angle, tau)))
            << rx << " " << ry << " " << angle;
      }
    }
  }
}

// The oracle of SeatContactMatchesMainsPlainFormula: `main`'s seat_contact and its force law as
// they were before the seat contacts' shortcuts (the tooth constants once a step, the seat index
// without atan2, the contact after the seat is chosen), written out here unchanged except for
// their names: our own code, kept as the independent reference the shortcuts must reproduce. The
// library's seat_contact(w, …) now calls seat_contact(w, seat_geometry(w), …), so comparing
// those two with each other could not fail; this keeps the plain computation outside the
// library.
void main_seat_law(const Sprocket& w, double g, double rx, double ry, double vx, double vy,
                   double speed, SeatContact& c) {
  // rate of penetration: the roller's velocity relative to the wheel's material point under it
  const double rate = (vx + speed * ry) * c.nx + (vy - speed * rx) * c.ny;
  const double eps = w.contact_smoothing, kc = w.contact_stiffness;
  const double elastic = g < eps ? 0.5 * kc * g * g / eps : kc * (g - 0.5 * eps);
  c.stiffness = g < eps ? kc * g / eps : kc;
  c.energy =
      g < eps ? kc * g * g * g / (6.0 * eps) : kc * (0.5 * g * g - 0.5 * eps * g + eps * eps / 6.0);
  c.damping = w.contact_damping * std::min(1.0, g / eps);
  c.force = std::max(0.0, elastic + c.damping * rate);
  // ∂f/∂g: the elastic slope, and the damping's ramp over the first ε
  if (g < eps) c.stiffness += w.contact_damping * rate / eps;
  if (c.force <= 0.0) c.stiffness = c.damping = 0.0;
  // the contact's power on roller and wheel together is −f ġ (the torque's share included);
  // the part of the damper, f − f_el, is the dissipation
  c.damping_power = -(c.force - elastic) * rate;
  c.active = true;
  c.penetration = g;
  // the reaction +f n acts on the wheel along the line through the roller centre q
  c.torque = c.force * (rx * c.ny - ry * c.nx);
}

SeatContact main_seat_contact(const Sprocket& w, double x, double y, double vx, double vy,
                              double angle, double speed) {
  SeatContact c;
  const double rx = x - w.centre_x, ry = y - w.centre_y;
  const double reach = contact_reach(w);
  if (rx * rx + ry * ry > reach * reach) return c;  // clear of the wheel
  // The nearest seat from the roller's angle about the centre: O(1), no search.
  const double tau = 2.0 * std::numbers::pi / w.teeth;
  const double k = std::nearbyint((std::atan2(ry, rx) - angle) / tau);
  const double sigma = angle + k * tau;
  const double cs = std::cos(sigma), sn = std::sin(sigma);
  c.seat = static_cast<int>(k);
  c.seat_x = w.centre_x + w.pitch_radius * cs;
  c.seat_y = w.centre_y + w.pitch_radius * sn;
  const double ex = x - c.seat_x, ey = y - c.seat_y;
  // The tooth gap about the seat centre C: the seating arc of radius ri over the seating angle α
  // about the inward radial, and beyond its ends the flanks, taken as the straight lines tangent
  // to the arc there (the ISO flank arc re is several pitches: nearly straight over a roller).
  // γ is the angle of e = q − C from the inward radial, towards the tangent t = (−sin σ, cos σ).
  const double e_in = -(ex * cs + ey * sn), e_t = -ex * sn + ey * cs;
  const double half = 0.5 * w.seating_angle;
  const double ch = std::cos(half), sh_abs = std::sin(half);
  const double r = w.roller_radius, ri = w.seat_radius;
  double g = 0.0;
  // |γ| ≤ α/2 with γ = atan2(e_t, e_in) and α/2 < π/2, without the atan2: e lies within α/2 of
  // the inward radial iff |e_t| cos(α/2) ≤ e_in sin(α/2) with e_in ≥ 0 (γ = 0 at e = 0).
  if (e_in >= 0.0 && std::abs(e_t) * ch <= e_in * sh_abs) {
    const double dist = std::sqrt(ex * ex + ey * ey);
    if (!(dist > 0.0)) return c;
    g = dist + r - ri;
    c.nx = ex / dist;
    c.ny = ey / dist;
    c.curvature = 1.0 / dist;
    c.surface = 0;
  } else {
    // The tooth on the roller's side (side = ±1 towards ±t). In the seat's frame mirrored to
    // side +1 — coordinates a along the inward radial, b = side·e_t — the flank leaves the arc's
    // end J = ri m, m = (cos α/2, sin α/2) (into the tooth); the wheel's centre O is at (R, 0).
    // The flank is the ISO arc of radius re, convex, centred at F = (ri + re) m (the tooth lies
    // inside that circle), or with re = 0 the straight line tangent to the arc at J.
    const double side = e_t > 0.0 ? 1.0 : -1.0;
    const double a = e_in, b = side * e_t;
    // a vector (va, vb) of the mirrored frame in world axes: va (−cos σ, −sin σ) +
    // side vb (−sin σ, cos σ)
    auto world = [&](double va, double vb, double& wx, double& wy) {
      wx = -cs * va - side * sn * vb;
      wy = -sn * va + side * cs * vb;
    };
    const double R = w.pitch_radius, Ra = w.tip_radius, re = w.flank_radius;
    const double fa = (ri + re) * ch, fb = (ri + re) * sh_abs;  // F (re > 0)
    // depth of q inside the flank's surface (> 0 inside the tooth)
    double depth_flank = 0.0, fdist = 0.0;
    if (re > 0.0) {
      fdist = std::hypot(a - fa, b - fb);
      depth_flank = re - fdist;
    } else {
      depth_flank = a * ch + b * sh_abs - ri;  // (q − C)·m − ri
    }
    // The flank ends at the tooth's corner K: where it meets the tip circle |K − O| = Ra, or,
    // if the tooth's two flanks meet below the tip circle, at their apex A on the tooth's centre
    // line (at τ/2 from the seat's radial, direction (−cos τ/2, sin τ/2) from O).
    bool has_corner = false, tip_arc = false;
    double ka = 0.0, kb = 0.0;
    if (Ra > 0.0) {
      const double th2 = 0.5 * tau, da = -std::cos(th2), db = std::sin(th2);
      if (re > 0.0) {
        // apex: |O + μ d − F| = re, the outer root
        const double wa = R - fa, wb = -fb;
        const double wd = wa * da + wb * db;
        const double disc = wd * wd - (wa * wa + wb * wb) + re * re;
        if (disc >= 0.0) {
          const double mu = -wd + std::sqrt(disc);
          if (mu > 0.0 && mu <= Ra) {
            ka = R + mu * da;
            kb = mu * db;
            has_corner = true;
          }
        }
        if (!has_corner) {
          // the flank circle's crossings of the tip circle; K the first from J along the flank
          // (clockwise about F in (a, b))
          const double ua = fa - R, ub = fb, dd = std::hypot(ua, ub);
          const double x0 = (Ra * Ra - re * re + dd * dd) / (2.0 * dd);
          const double h2 = Ra * Ra - x0 * x0;
          if (h2 >= 0.0 && dd > 0.0) {
            const double hh = std::sqrt(h2);
            double best = INFINITY;
            for (const double sgn : {-1.0, 1.0}) {
              const double pa = R + (x0 * ua - sgn * hh * ub) / dd;
              const double pb = (x0 * ub + sgn * hh * ua) / dd;
              // angle about F from J (direction −m) clockwise
              const double ja = -ch, jb = -sh_abs, qa = pa - fa, qb = pb - fb;
              double phi = std::atan2(-(ja * qb - jb * qa), ja * qa + jb * qb);
              if (phi < 0.0) phi += 2.0 * std::numbers::pi;
              if (phi < best) {
                best = phi;
                ka = pa;
                kb = pb;
              }
            }
            has_corner = tip_arc = true;
          }
        }
      } else {
        // straight flank J + λ u, u = (−sin α/2, cos α/2): |J + λ u − O| = Ra gives
        // λ² + 2 R sin(α/2) λ + R² + ri² − 2 R ri cos(α/2) − Ra² = 0; the apex
        // λ_A = (R sin(τ/2) − ri sin(α/2 + τ/2)) / cos(α/2 + τ/2)
        double lk = 0.0;
        const double cq = R * R + ri * ri - 2.0 * R * ri * ch - Ra * Ra;
        const double disc = R * R * sh_abs * sh_abs - cq;
        if (disc >= 0.0) {
          lk = -R * sh_abs + std::sqrt(disc);
          has_corner = tip_arc = lk > 0.0;
        }
        const double cos_apex = std::cos(half + th2);
        if (cos_apex > 0.0) {
          const double la = (R * std::sin(th2) - ri * std::sin(half + th2)) / cos_apex;
          if (la > 0.0 && (!has_corner || la <= lk)) {
            lk = la;
            has_corner = true;
            tip_arc = false;
          }
        }
        ka = ri * ch - lk * sh_abs;
        kb = ri * sh_abs + lk * ch;
      }
    }
    // q beyond K along the flank: for the arc, turned clockwise about F past K; for the line,
    // past K along u
    bool past_k = false;
    if (has_corner) {
      if (re > 0.0) {
        past_k = (ka - fa) * (b - fb) - (kb - fb) * (a - fa) < 0.0;
      } else {
        past_k = (a - ka) * -sh_abs + (b - kb) * ch > 0.0;
      }
    }
    // q − O in (a, b), its distance from the centre
    const double oa = a - R, ob = b;
    const double rho = std::sqrt(oa * oa + ob * ob);
    const double depth_tip = Ra - rho;  // > 0 inside the tip circle
    // Beyond K's radial towards the tooth's centre line: (K − O) × (q − O) ≤ 0 in (a, b).
    const bool beyond_k = (ka - R) * ob - kb * oa <= 0.0;
    enum { kFlank, kCorner, kTip } where = kFlank;
    if (has_corner) {
      if (depth_flank >= 0.0 && (!tip_arc || depth_tip >= 0.0)) {
        // inside the tooth (a roller centre past its surface): the nearer of flank and tip
        where = tip_arc && depth_tip < depth_flank ? kTip : kFlank;
      } else if (depth_flank < 0.0 && !past_k) {
        where = kFlank;
      } else if (tip_arc && depth_tip < 0.0 && beyond_k) {
        where = kTip;
      } else {
        where = kCorner;
      }
    }
    if (where == kFlank && re > 0.0) {
      if (!(fdist > 0.0)) return c;
      world((fa - a) / fdist, (fb - b) / fdist, c.nx, c.ny);  // n = (F − q)/|F − q|
      g = r + depth_flank;
      c.curvature = -1.0 / fdist;
      c.surface = 1;
    } else if (where == kFlank) {
      world(ch, sh_abs, c.nx, c.ny);
      g = ex * c.nx + ey * c.ny + r - ri;  // depth_flank + r, as the form without a tip wrote it
      c.curvature = 0.0;
      c.surface = 1;
    } else if (where == kTip) {
      if (!(rho > 0.0)) return c;
      world(-oa / rho, -ob / rho, c.nx, c.ny);  // n = −(q − O)/|q − O|
      g = r + depth_tip;
      c.curvature = -1.0 / rho;
      c.surface = 3;
    } else {
      const double da = ka - a, db = kb - b;  // K − q
      const double dist = std::sqrt(da * da + db * db);
      if (!(dist > 0.0)) return c;
      world(da / dist, db / dist, c.nx, c.ny);
      g = r - dist;
      c.curvature = -1.0 / dist;
      c.surface = 2;
    }
  }
  if (!(g > 0.0)) return c;
  main_seat_law(w, g, rx, ry, vx, vy, speed, c);
  return c;
}

TEST(DynamicsSeatConstants, SeatContactWithTheWheelsConstantsIsSeatContact) {
  // every surface of the gap (arc, flank, corner, tip): rollers all round a wheel, near the
  // pitch circle, on wheels with and without a tip circle and a flank arc. The reference is
  // main_seat_contact above (main's plain formula); the shortcuts claim the same arithmetic, so
  // every field is expected bit-identical (EXPECT_EQ, no tolerance).
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  long surfaces[4] = {0, 0, 0, 0};
  for (const int z : {9, 20, 40}) {
    Sprocket w = iso606_sprocket(0.01905, 0.01207, 0.01168, z, 0.3, -0.2, 2e8, 800.0);
    for (const bool straight : {false, true}) {
      if (straight) w.flank_radius = 0.0;
      const SeatGeometry t = seat_geometry(w);
      for (int trial = 0; trial < 3000; ++trial) {
        const double r = w.pitch_radius + 0.02 * (u(rng) - 0.5), a = 2.0 * kPi * u(rng);
        const double x = w.centre_x + r * std::cos(a), y = w.centre_y + r * std::sin(a);
        const double vx = u(rng) - 0.5, vy = u(rng) - 0.5, psi = 10.0 * u(rng), omega = 30.0;
        const SeatContact m = main_seat_contact(w, x, y, vx, vy, psi, omega);
        const SeatContact c = seat_contact(w, x, y, vx, vy, psi, omega);
        const SeatContact d = seat_contact(w, t, x, y, vx, vy, psi, omega);
        const double k = nearest_seat(x - w.centre_x, y - w.centre_y, psi, t.tau);
        const double sigma = psi + k * t.tau;
        const SeatContact e =
            std::hypot(x - w.centre_x, y - w.centre_y) > t.reach
                ? SeatContact{}
                : seat_contact_at(w, t, x, y, vx, vy, omega, k, std::cos(sigma), std::sin(sigma));
        if (m.active) ++surfaces[m.surface];
        for (const SeatContact* o : {&c, &d, &e}) {
          EXPECT_EQ(o->active, m.active);
          EXPECT_EQ(o->seat, m.seat);
          EXPECT_EQ(o->surface, m.surface);
          EXPECT_EQ(o->force, m.force);
          EXPECT_EQ(o->penetration, m.penetration);
          EXPECT_EQ(o->stiffness, m.stiffness);
          EXPECT_EQ(o->damping, m.damping);
          EXPECT_EQ(o->energy, m.energy);
          EXPECT_EQ(o->damping_power, m.damping_power);
          EXPECT_EQ(o->nx, m.nx);
          EXPECT_EQ(o->ny, m.ny);
          EXPECT_EQ(o->torque, m.torque);
          EXPECT_EQ(o->curvature, m.curvature);
          EXPECT_EQ(o->seat_x, m.seat_x);
          EXPECT_EQ(o->seat_y, m.seat_y);
        }
      }
    }
  }
  std::printf("active contacts by surface: arc %ld, flank %ld, corner %ld, tip %ld\n", surfaces[0],
              surfaces[1], surfaces[2], surfaces[3]);
  for (int s = 0; s < 4; ++s) EXPECT_GT(surfaces[s], 0) << "surface " << s << " never touched";
}

// The benchmark's drive (200 links of 12B over two z = 20 wheels, the driven one J = 0.05 kg·m²;
// tests/dynamics/two_wheel_loops.hpp)
using Drive = testing::Loop;
Drive drive() { return testing::benchmark_drive(); }

// Unknowns with every node moved `shift` places along the loop (and a small jitter): nodes that
// were far from a wheel are on it now.
std::vector<double> shifted(const Drive& d, std::size_t shift, double jitter, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-jitter, jitter);
  const std::size_t n = d.model.nodes();
  std::vector<double> v(2 * n + 1);
  for (std::size_t i = 0; i < n; ++i) {
    v[2 * i] = d.state.x[(i + shift) % n] + u(rng);
    v[2 * i + 1] = d.state.y[(i + shift) % n] + u(rng);
  }
  v[2 * n] = d.state.angle[1] + 1e-4 * d.state.speed[1];
  return v;
}

TEST(DynamicsSeatConstants, CandidateListsGiveTheResidualOfAFreshIntegrator) {
  // One integrator evaluated at iterates far apart (its lists out of date: remade) and close
  // together (kept), against a fresh integrator at each: the same residual and Jacobian, bit for
  // bit, and a non-finite iterate in between changes nothing after it.
  const Drive d = drive();
  std::mt19937 rng(24);
  Integrator kept(d.model, {.step = 1e-4, .theta = 0.6});
  const std::size_t shifts[] = {0, 0, 1, 1, 5, 37, 37, 100, 3};
  const double jitters[] = {0.0, 1e-4, 1e-3, 2e-3, 1e-5, 0.0, 5e-3, 1e-6, 1e-4};
  for (int pass = 0; pass < 9; ++pass) {
    std::vector<double> v = shifted(d, shifts[pass], jitters[pass], rng);
    if (pass == 6) {  // a non-finite iterate first: no lists, every node tested
      std::vector<double> bad = v;
      bad[10] = NAN;
      std::vector<double> rb;
      kept.newton_system(d.model, d.state, bad, rb, nullptr);
      EXPECT_TRUE(std::isnan(rb[10]));
    }
    std::vector<double> r1, r2, j1, j2;
    kept.newton_system(d.model, d.state, v, r1, &j1);
    Integrator fresh(d.model, {.step = 1e-4, .theta = 0.6});
    fresh.newton_system(d.model, d.state, v, r2, &j2);
    ASSERT_EQ(r1.size(), r2.size());
    long differ = 0;
    for (std::size_t i = 0; i < r1.size(); ++i) differ += r1[i] != r2[i];
    for (std::size_t i = 0; i < j1.size(); ++i) differ += j1[i] != j2[i];
    EXPECT_EQ(differ, 0) << "pass " << pass;
  }
}

TEST(DynamicsSeatConstants, StepsWithOneIntegratorMatchStepsWithAFreshOneEachStep) {
  // A fresh integrator has no lists, no seat directions and no predictor history: give it the
  // kept one's history by stepping both from the same states; the kept one's lists and tables
  // carry over steps. Constant-velocity predictor in both (a fresh integrator has no history):
  // compared on the first step from each state.
  Drive d = drive();
  Integrator kept(d.model, {.step = 1e-4, .theta = 0.6});
  for (int step = 0; step < 300; ++step) {
    State a = d.state, b = d.state;
    a.time = b.time = -1.0 - step;  // no history in either
    Integrator fresh(d.model, {.step = 1e-4, .theta = 0.6});
    const StepReport ra = kept.step(d.model, a);
    const StepReport rb = fresh.step(d.model, b);
    ASSERT_TRUE(ra.converged && rb.converged);
    EXPECT_EQ(ra.iterations, rb.iterations);
    EXPECT_EQ(ra.max_penetration, rb.max_penetration);
    EXPECT_EQ(kept.applied_torque()[1], fresh.applied_torque()[1]);
    long differ = 0;
    for (std::size_t i = 0; i < a.x.size(); ++i) differ += a.x[i] != b.x[i] || a.vy[i] != b.vy[i];
    EXPECT_EQ(differ, 0) << "step " << step;
    Integrator advance(d.model, {.step = 1e-4, .theta = 0.6});
    ASSERT_TRUE(advance.step(d.model, d.state).converged);  // the next state: 0.1 ms on
  }
}

}  // namespace
}  // namespace catena::dynamics
