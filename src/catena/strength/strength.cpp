// Strength checks of the conveyor chain's roller and plates (seed 000 §1.5); see strength.hpp
// and docs/models/strength.md for the reconstruction.
#include "catena/strength/strength.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "catena/core/hertz.hpp"

namespace catena::strength {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr const char* kPlateName[4] = {"lower outer plate", "lower inner plate",
                                       "upper inner plate", "upper outer plate"};

std::string fmt(const char* format, double v) {
  char b[96];
  std::snprintf(b, sizeof b, format, v);
  return b;
}

std::string mm(double v) { return fmt("%.4g mm", v * 1e3); }

bool point(const Block& b) { return b.end == b.begin; }

double section_modulus(double d, double di) {
  return kPi * (d * d * d * d - di * di * di * di) / (32.0 * d);
}
double section_area(double d, double di) { return kPi * (d * d - di * di) / 4.0; }

double hole_of(const Hinge& h) { return h.hole_diameter > 0.0 ? h.hole_diameter : h.pin_diameter; }

Check make_check(std::string name, std::string section, double stress, double allowable,
                 double required) {
  Check c{std::move(name), std::move(section), stress, allowable, required, 0.0, true};
  c.safety_factor = stress > 0.0 ? allowable / stress : std::numeric_limits<double>::infinity();
  c.ok = c.safety_factor >= required;
  return c;
}

}  // namespace

std::vector<Issue> validate(const Input& in) {
  std::vector<Issue> out;
  const Hinge& h = in.hinge;
  const Loads& l = in.loads;
  const Material& m = in.material;
  bool too_high = false;
  for (std::size_t i = 0; i < 4; ++i) {
    check::finite(out, "heights", h.heights[i], "m");
    check::finite_positive(out, "widths", h.widths[i], "m");
    too_high = too_high || (std::isfinite(h.heights[i]) && std::abs(h.heights[i]) > 10.0);
  }
  // Plate heights within a link are millimetres; beyond 10 m the layouts' moments overflow or
  // cancel (issue 18: 1e13 mm gave NaN plate forces): refused with the range, named once.
  if (too_high) out.push_back({"heights", "(over 10 m)", "plate mid-plane heights |h| ≤ 10 m"});
  for (std::size_t i = 0; i + 1 < 4; ++i) {
    const double top = h.heights[i] + 0.5 * h.widths[i];
    const double next = h.heights[i + 1] - 0.5 * h.widths[i + 1];
    if (std::isfinite(top) && std::isfinite(next) && !(top <= next + 1e-12 * std::abs(next)))
      out.push_back({"heights", check::format_si(h.heights[i + 1], "m"),
                     std::string("plates bottom to top without overlap: the ") + kPlateName[i + 1] +
                         " (mid-plane minus half its width) must start at or above the " +
                         kPlateName[i] + "'s top, " + check::format_si(top, "m")});
  }
  check::finite_positive(out, "pin_diameter", h.pin_diameter, "m");
  if (!(h.bore >= 0.0 && std::isfinite(h.bore)) ||
      (std::isfinite(h.pin_diameter) && h.pin_diameter > 0 && !(h.bore < h.pin_diameter)))
    out.push_back(
        {"bore", check::format_si(h.bore, "m"), "0 ≤ bore < pin diameter (0: a solid roller)"});
  if (!(h.hole_diameter >= 0.0 && std::isfinite(h.hole_diameter)))
    out.push_back({"hole_diameter", check::format_si(h.hole_diameter, "m"),
                   "a length > 0 m (0 or omitted: the pin diameter)"});
  check::finite_positive(out, "plate_width", h.plate_width, "m");
  check::finite_positive(out, "end_distance", h.end_distance, "m");
  const double dh = hole_of(h);
  if (std::isfinite(dh) && dh > 0 && std::isfinite(h.plate_width) && h.plate_width > 0 &&
      !(dh < h.plate_width))
    out.push_back({"hole_diameter", check::format_si(dh, "m"),
                   "a hole smaller than the plate width b = " +
                       check::format_si(h.plate_width, "m") + " (else no net section is left)"});
  if (std::isfinite(dh) && dh > 0 && std::isfinite(h.end_distance) && h.end_distance > 0 &&
      !(h.end_distance > 0.5 * dh))
    out.push_back({"end_distance", check::format_si(h.end_distance, "m"),
                   "more than the hole radius " + check::format_si(0.5 * dh, "m") +
                       " (hole centre to plate end)"});
  if (!(h.stress_concentration >= 1.0 && std::isfinite(h.stress_concentration)))
    out.push_back({"stress_concentration", fmt("%g", h.stress_concentration), "K_t ≥ 1"});
  if (h.kind == HingeKind::kSliding) {
    if (!(h.contact_angle > 0.0 && h.contact_angle <= kPi + 1e-12))
      out.push_back({"contact_angle", check::format_si(h.contact_angle, "rad"),
                     "0 < γ ≤ 180° (the pin's contact arc)"});
  } else {
    check::finite_positive(out, "plate_radius", h.r1, "m");
    check::finite_positive(out, "roller_radius", h.r2, "m");
    if (std::isfinite(h.r1) && std::isfinite(h.r2) && h.r1 > 0 && h.r2 > 0 && !(h.r2 > h.r1))
      out.push_back({"roller_radius", check::format_si(h.r2, "m"),
                     "R2 > R1 = " + check::format_si(h.r1, "m") + " (R1 rolls inside R2)"});
  }
  check::finite_positive(out, "modulus", h.modulus, "Pa");
  if (!(h.poisson >= 0.0 && h.poisson < 0.5))
    out.push_back({"poisson", fmt("%g", h.poisson), "0 ≤ ν < 0.5"});

  check::finite_positive(out, "tension", l.tension, "N");
  if (!(l.exit_tension >= 0.0 && std::isfinite(l.exit_tension)))
    out.push_back({"exit_tension", check::format_si(l.exit_tension, "N"),
                   "S2 ≥ 0, the seated link's tension"});
  if (!(l.link_angle >= 0.0 && l.link_angle < kPi))
    out.push_back({"link_angle", check::format_si(l.link_angle, "rad"), "0 ≤ θ < 180°"});
  if (std::isfinite(l.tension) && l.tension > 0 && l.exit_tension >= 0 &&
      std::isfinite(l.exit_tension) && l.link_angle >= 0 && l.link_angle < kPi &&
      !(l.exit_tension * std::cos(l.link_angle) <= l.tension))
    out.push_back({"exit_tension", check::format_si(l.exit_tension, "N"),
                   "S2·cos θ ≤ S = " + check::format_si(l.tension, "N") +
                       " (the tooth can only push the roller against the free link's pull)"});
  check::finite(out, "load_height", l.load_height, "m");
  if (!(l.tooth_width >= 0.0 && std::isfinite(l.tooth_width)))
    out.push_back({"tooth_width", check::format_si(l.tooth_width, "m"), "a length ≥ 0 m"});
  const double gap_lo = h.heights[1] + 0.5 * h.widths[1];
  const double gap_hi = h.heights[2] - 0.5 * h.widths[2];
  const double t_lo = l.load_height - 0.5 * l.tooth_width;
  const double t_hi = l.load_height + 0.5 * l.tooth_width;
  if (std::isfinite(gap_lo) && std::isfinite(gap_hi) && std::isfinite(l.tooth_width) &&
      l.tooth_width >= 0 && gap_hi > gap_lo && l.tooth_width > gap_hi - gap_lo + 1e-12) {
    // no L1 fits a tooth wider than the gap: the width is what is wrong
    out.push_back({"tooth_width", check::format_si(l.tooth_width, "m"),
                   "a tooth width ≤ the gap between the inner plates, " +
                       check::format_si(gap_hi - gap_lo, "m") + " ([" +
                       check::format_si(gap_lo, "m") + ", " + check::format_si(gap_hi, "m") +
                       "])"});
  } else if (std::isfinite(gap_lo) && std::isfinite(gap_hi) && std::isfinite(t_lo) &&
             std::isfinite(t_hi) && l.tooth_width >= 0 && gap_hi > gap_lo &&
             !(t_lo >= gap_lo - 1e-12 && t_hi <= gap_hi + 1e-12)) {
    out.push_back({"load_height", check::format_si(l.load_height, "m"),
                   "the tooth load (L1 ± tooth width/2) between the inner plates, within [" +
                       check::format_si(gap_lo, "m") + ", " + check::format_si(gap_hi, "m") + "]"});
  }

  check::finite_positive(out, "roller_yield", m.roller_yield, "Pa");
  check::finite_positive(out, "plate_yield", m.plate_yield, "Pa");
  if (!(m.plate_ultimate >= 0.0 && std::isfinite(m.plate_ultimate)))
    out.push_back({"plate_ultimate", check::format_si(m.plate_ultimate, "Pa"),
                   "a stress > 0 Pa (0 or omitted: no ultimate check)"});
  if (h.kind == HingeKind::kSliding)
    check::finite_positive(out, "allowable_pressure", m.allowable_pressure, "Pa");
  else
    check::finite_positive(out, "allowable_contact", m.allowable_contact, "Pa");
  if (!(m.required > 0.0 && std::isfinite(m.required)))
    out.push_back({"safety_factor", fmt("%g", m.required), "a required safety factor > 0"});
  return out;
}

std::array<double, 2> tooth_force(const Loads& l) {
  return {l.exit_tension * std::cos(l.link_angle) - l.tension,
          -l.exit_tension * std::sin(l.link_angle)};
}

LayoutLoads layout_loads(const Input& in, int layout) {
  const Hinge& h = in.hinge;
  const double l1 = in.loads.load_height;
  const auto n = tooth_force(in.loads);
  LayoutLoads out;
  out.layout = layout;
  // layout 1: the inner link is seated, S enters through the outer plates; layout 2: swapped
  const int p = layout == 1 ? kLowerOuter : kLowerInner,
            q = layout == 1 ? kUpperOuter : kUpperInner;
  const int a = layout == 1 ? kLowerInner : kLowerOuter,
            b = layout == 1 ? kUpperInner : kUpperOuter;
  const auto z = [&](int i) { return h.heights[static_cast<std::size_t>(i)]; };
  const auto at = [](std::array<double, 4>& f, int i) -> double& {
    return f[static_cast<std::size_t>(i)];
  };
  // per direction: the free plates carry `free` each, the tooth `tooth` at L1; the seated
  // plates a, b balance them: Fa + Fb = −(2 free + tooth), Fa za + Fb zb = −(free (zp + zq) +
  // tooth L1) (a uniform block acts at its centre, the plate's mid-plane)
  const auto split = [&](std::array<double, 4>& f, double free, double tooth) {
    at(f, p) = free;
    at(f, q) = free;
    const double sum = -(2.0 * free + tooth);
    const double mom = -(free * (z(p) + z(q)) + tooth * l1);
    at(f, b) = (mom - sum * z(a)) / (z(b) - z(a));
    at(f, a) = sum - at(f, b);
  };
  split(out.plate_force, 0.5 * in.loads.tension, n[0]);
  split(out.plate_force_y, 0.0, n[1]);
  out.tooth = {l1 - 0.5 * in.loads.tooth_width, l1 + 0.5 * in.loads.tooth_width, n[0]};
  out.tooth_y = n[1];
  return out;
}

Beam beam(const Input& in, const LayoutLoads& loads, int component) {
  const Hinge& h = in.hinge;
  const auto& f = component == 0 ? loads.plate_force : loads.plate_force_y;
  Beam out;
  for (std::size_t i = 0; i < 4; ++i)
    out.blocks.push_back(
        {h.heights[i] - 0.5 * h.widths[i], h.heights[i] + 0.5 * h.widths[i], f[i]});
  out.blocks.push_back(loads.tooth);
  if (component != 0) out.blocks.back().force = loads.tooth_y;
  out.start = out.blocks[0].begin;
  out.stop = out.blocks[3].end;
  return out;
}

double shear(const Beam& b, double z, bool above) {
  double q = 0.0;
  for (const Block& k : b.blocks) {
    if (point(k)) {
      if (z > k.begin || (above && z == k.begin)) q += k.force;
    } else {
      q += k.force * std::clamp((z - k.begin) / (k.end - k.begin), 0.0, 1.0);
    }
  }
  return q;
}

double moment(const Beam& b, double z) {
  double m = 0.0;
  for (const Block& k : b.blocks) {
    if (!(z > k.begin)) continue;
    if (point(k)) {
      m += k.force * (z - k.begin);
    } else if (z >= k.end) {
      m += k.force * (z - 0.5 * (k.begin + k.end));
    } else {
      const double u = z - k.begin;
      m += k.force / (k.end - k.begin) * 0.5 * u * u;
    }
  }
  return m;
}

namespace {

Diagram sample(const Beam& b, const Beam* y, int per_block) {
  std::vector<double> xs{b.start, b.stop};
  std::vector<double> points;
  for (const Block& k : b.blocks) {
    xs.push_back(k.begin);
    xs.push_back(k.end);
    if (point(k)) {
      points.push_back(k.begin);
      continue;
    }
    for (int i = 1; i <= per_block; ++i)
      xs.push_back(k.begin + (k.end - k.begin) * i / (per_block + 1.0));
  }
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  Diagram d;
  auto push = [&](double x, bool above) {
    d.x.push_back(x);
    d.moment.push_back(moment(b, x));
    d.shear.push_back(shear(b, x, above));
    if (y) {
      d.moment_y.push_back(moment(*y, x));
      d.shear_y.push_back(shear(*y, x, above));
    }
  };
  for (double x : xs) {
    push(x, false);
    // the value just above a point load
    if (std::find(points.begin(), points.end(), x) != points.end()) push(x, true);
  }
  return d;
}

// Block boundaries and the roller's ends, sorted, unique.
std::vector<double> boundaries(const Beam& b) {
  std::vector<double> xs{b.start, b.stop};
  for (const Block& k : b.blocks) {
    xs.push_back(k.begin);
    xs.push_back(k.end);
  }
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  return xs;
}

}  // namespace

Diagram diagram(const Beam& b, int per_block) { return sample(b, nullptr, per_block); }
Diagram diagram(const Beam& x, const Beam& y, int per_block) { return sample(x, &y, per_block); }

Extremes extremes(const Beam& x, const Beam& y) {
  bool planar = false;
  for (const Block& k : y.blocks) planar |= k.force != 0.0;
  if (!planar) return extremes(x);
  Extremes e;
  const auto m = [&](double z) { return std::hypot(moment(x, z), moment(y, z)); };
  const auto consider = [&](double z) {
    const double v = m(z);
    if (v > e.moment) {
      e.moment = v;
      e.moment_at = z;
    }
    for (bool above : {false, true}) {
      const double q = std::hypot(shear(x, z, above), shear(y, z, above));
      if (q > e.shear) {
        e.shear = q;
        e.shear_at = z;
      }
    }
  };
  // d|M|²/dz / 2 = Mx Qx + My Qy (continuous inside an interval between boundaries)
  const auto slope = [&](double z) {
    return moment(x, z) * shear(x, z) + moment(y, z) * shear(y, z);
  };
  const std::vector<double> xs = boundaries(x);
  for (double z : xs) consider(z);
  constexpr int kScan = 64;
  for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
    const double a = xs[i], b = xs[i + 1];
    double z0 = a, f0 = slope(a + 1e-12 * (b - a));
    for (int j = 1; j <= kScan; ++j) {
      const double z1 = j == kScan ? b : a + (b - a) * j / kScan;
      const double f1 = slope(j == kScan ? b - 1e-12 * (b - a) : z1);
      if (f0 > 0.0 && f1 < 0.0) {  // a maximum of |M|² between z0 and z1
        double lo = z0, hi = z1;
        for (int it = 0; it < 100 && hi - lo > 1e-15 * (b - a); ++it) {
          const double mid = 0.5 * (lo + hi);
          (slope(mid) > 0.0 ? lo : hi) = mid;
        }
        consider(0.5 * (lo + hi));
      }
      z0 = z1;
      f0 = f1;
    }
  }
  return e;
}

Extremes extremes(const Beam& b) {
  Extremes e;
  auto consider = [&](double z) {
    const double m = std::abs(moment(b, z));
    if (m > e.moment) e = {m, z, e.shear, e.shear_at};
    for (bool above : {false, true}) {
      const double q = std::abs(shear(b, z, above));
      if (q > e.shear) {
        e.shear = q;
        e.shear_at = z;
      }
    }
  };
  const std::vector<double> xs = boundaries(b);
  for (double z : xs) consider(z);
  // between consecutive boundaries Q is linear: M has a stationary point where Q = 0
  for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
    const double q0 = shear(b, xs[i], true), q1 = shear(b, xs[i + 1], false);
    if ((q0 < 0.0 && q1 > 0.0) || (q0 > 0.0 && q1 < 0.0))
      consider(xs[i] + (xs[i + 1] - xs[i]) * q0 / (q0 - q1));
  }
  return e;
}

double projection(double radius, double angle) { return 2.0 * radius * std::sin(0.5 * angle); }

double shear_factor(double outer, double inner) {
  const double ro = 0.5 * outer, ri = 0.5 * inner;
  return 4.0 / 3.0 * (ro * ro + ro * ri + ri * ri) / (ro * ro + ri * ri);
}

Result assess(const Input& in) {
  throw_if_any(validate(in));
  const Hinge& h = in.hinge;
  const Material& mat = in.material;
  Result r;
  std::vector<int> which;
  if (in.layouts != Layouts::kTwo) which.push_back(1);
  if (in.layouts != Layouts::kOne) which.push_back(2);

  const double w = section_modulus(h.pin_diameter, h.bore);
  const double area = section_area(h.pin_diameter, h.bore);
  const double kq = shear_factor(h.pin_diameter, h.bore);
  const double shear_yield = mat.roller_yield / std::sqrt(3.0);  // von Mises
  for (int layout : which) {
    LayoutResult lr;
    lr.loads = layout_loads(in, layout);
    const Beam bx = beam(in, lr.loads, 0), by = beam(in, lr.loads, 1);
    lr.planar = false;
    for (const Block& k : by.blocks) lr.planar |= k.force != 0.0;
    lr.diagram = lr.planar ? diagram(bx, by) : diagram(bx);
    lr.extremes = extremes(bx, by);
    for (const Beam* bm : {&bx, &by}) {
      double sf = 0.0, sm = 0.0;
      for (const Block& k : bm->blocks) {
        sf += k.force;
        sm += k.force * 0.5 * (k.begin + k.end);
      }
      lr.force_residual = std::max(lr.force_residual, std::abs(sf));
      lr.moment_residual = std::max(lr.moment_residual, std::abs(sm));
    }
    const std::string where = "layout " + std::to_string(layout);
    r.checks.push_back(make_check("roller.bending",
                                  where + ", z = " + mm(lr.extremes.moment_at) + ": σ = M/W",
                                  lr.extremes.moment / w, mat.roller_yield, mat.required));
    r.checks.push_back(make_check(
        "roller.shear",
        where + ", z = " + mm(lr.extremes.shear_at) + ": τ = " + fmt("%.4g", kq) + "·Q/A vs σ_y/√3",
        kq * lr.extremes.shear / area, shear_yield, mat.required));
    // a seated plate is expected to pull along the seated link, û = (−cos θ, sin θ)
    const double ux = -std::cos(in.loads.link_angle), uy = std::sin(in.loads.link_angle);
    for (int i :
         {layout == 1 ? kLowerInner : kLowerOuter, layout == 1 ? kUpperInner : kUpperOuter}) {
      const auto k = static_cast<std::size_t>(i);
      const double along = lr.loads.plate_force[k] * ux + lr.loads.plate_force_y[k] * uy;
      if (along < -1e-9 * in.loads.tension)
        r.diagnostics.push_back(
            {Diagnostic::Severity::kInfo, "strength.plate_reversed",
             where + ": the " + kPlateName[k] +
                 " pushes the roller away from the seated link (the tooth load is off the middle "
                 "of the seated link's plates); its magnitude is checked",
             along, 0.0, "N"});
    }
    r.layouts.push_back(std::move(lr));
  }

  // plate checks: each plate with its largest force over the layouts, its own thickness
  const double dh = hole_of(h);
  const double net = h.plate_width - dh, end = h.end_distance - 0.5 * dh;
  Check tension, ultimate, shear_out, bearing;
  bool first = true;
  Contact worst;
  double worst_p = -1.0;
  const Elastic el{h.modulus, h.poisson};
  for (std::size_t i = 0; i < 4; ++i) {
    double f = 0.0;
    int at = which.front();
    for (const LayoutResult& lr : r.layouts) {
      const double v = std::hypot(lr.loads.plate_force[i], lr.loads.plate_force_y[i]);
      if (v > f) {
        f = v;
        at = lr.loads.layout;
      }
    }
    const double s = h.widths[i];
    const std::string where = std::string(kPlateName[i]) + ", layout " + std::to_string(at);
    const Check t =
        make_check("plate.tension",
                   where + ": net section (b − d_h)·s, K_t = " + fmt("%g", h.stress_concentration),
                   h.stress_concentration * f / (net * s), mat.plate_yield, mat.required);
    const Check u =
        make_check("plate.tension_ultimate", t.section, t.stress, mat.plate_ultimate, mat.required);
    const Check so =
        make_check("plate.shear_out", where + ": two planes (e − d_h/2)·s vs σ_y/√3",
                   f / (2.0 * end * s), mat.plate_yield / std::sqrt(3.0), mat.required);
    const Check br =
        make_check("plate.bearing", where + ": d_h·s", f / (dh * s), mat.plate_yield, mat.required);
    if (first || t.safety_factor < tension.safety_factor) tension = t;
    if (first || u.safety_factor < ultimate.safety_factor) ultimate = u;
    if (first || so.safety_factor < shear_out.safety_factor) shear_out = so;
    if (first || br.safety_factor < bearing.safety_factor) bearing = br;
    first = false;
    // the hinge contact of this plate
    Contact c;
    c.layout = at;
    c.plate = static_cast<int>(i);
    c.force = f;
    c.width = s;
    if (h.kind == HingeKind::kSliding) {
      c.radius = 0.5 * h.pin_diameter;
      c.angle = h.contact_angle;
    } else {
      c.hertz = true;
      c.effective_radius = conformal_radius(h.r1, h.r2);
      const LineContact lc = line_contact(f / s, c.effective_radius, contact_modulus(el, el));
      c.peak = lc.peak_pressure;
      c.half_width = lc.half_width;
      c.radius = h.r1;
      c.angle = 2.0 * std::asin(std::min(1.0, lc.half_width / h.r1));
    }
    c.c = projection(c.radius, c.angle);
    c.area = c.c * s;
    c.p = c.area > 0.0 ? f / c.area : 0.0;
    const double key = c.hertz ? c.peak : c.p;
    if (key > worst_p) {
      worst_p = key;
      worst = c;
    }
  }
  r.contact = worst;
  const std::string cwhere =
      std::string(kPlateName[worst.plate]) + ", layout " + std::to_string(worst.layout);
  if (h.kind == HingeKind::kSliding)
    r.checks.push_back(make_check("hinge.pressure", cwhere + ": eq. (23) p = N/(c·B)", worst.p,
                                  mat.allowable_pressure, 1.0));
  else
    r.checks.push_back(make_check("hinge.contact", cwhere + ": Hertz p0 of R1 in R2", worst.peak,
                                  mat.allowable_contact, 1.0));
  r.checks.push_back(tension);
  if (mat.plate_ultimate > 0.0) r.checks.push_back(ultimate);
  r.checks.push_back(shear_out);
  r.checks.push_back(bearing);

  // as catena warp: beyond b = 0.1·R1 the conformal contact leaves Hertz's half-space
  // assumption (Persson's conformal-cylinder theory would apply; not implemented)
  if (worst.hertz && worst.half_width > 0.1 * h.r1)
    r.diagnostics.push_back({Diagnostic::Severity::kWarning, "strength.hertz_conformal",
                             "the Hertz contact half-width b exceeds 0.1·R1: the conformal "
                             "contact of R1 in R2 is outside the half-space assumption, p0 is "
                             "approximate",
                             worst.half_width, 0.1 * h.r1, "m"});
  for (const Check& c : r.checks) {
    if (c.ok) continue;
    r.diagnostics.push_back(
        {Diagnostic::Severity::kInfeasible, "strength." + c.name,
         c.name + " (" + c.section + "): safety factor " + fmt("%.3g", c.safety_factor) +
             " below the required " + fmt("%.3g", c.required) + "; stress " +
             fmt("%.4g MPa", c.stress * 1e-6) + " exceeds the limit allowable/required = " +
             fmt("%.4g MPa", c.allowable / c.required * 1e-6),
         c.stress, c.allowable / c.required, "Pa"});
  }
  return r;
}

}  // namespace catena::strength
