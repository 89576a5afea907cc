// The chain model and state: validation, energy and link tensions (docs/models/dynamics.md).
#include "catena/dynamics/chain.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <numbers>
#include <string>

#include "catena/core/round.hpp"
#include "catena/drive/sprocket.hpp"
#include "catena/dynamics/guide_hint.hpp"
#include "catena/dynamics/pocket_wheel.hpp"

namespace catena::dynamics {
namespace {
constexpr std::size_t kMaxNodes = 10'000'000;

// [m] ρ_c = R ± r: the radius of an arc guide's roller centres' line (R − r inside).
double roller_line(const Guide& g) {
  return g.inside ? g.radius - g.roller_radius : g.radius + g.roller_radius;
}

// A loaded arc guide's checks (docs/models/dynamics.md, "A conveyed load"): the load must press
// the chain onto the rail over the whole arc, n·g < 0 at every angle φ in [start, end] (n = ±(cos
// φ, sin φ), outward on an outside arc, inward on an inside one): the largest n·g over the arc is
// at an end or where n points along g (so a loaded arc sweeps less than π, and its ramps, a half
// pitch beyond its ends, stay clear of each other round the back whenever ρ_c > p/π). And the
// roller centres' line's radius ρ_c at least a pitch: the gate carries a node up to a pitch off
// the line on its free side (inward on an inside arc, |q − C| ≥ ρ_c − p), so it does not reach
// past the centre, where |q − C| → 0 and the arc's parametrisation ∂s/∂q = ρ_c t/|q − C| blows
// up. Both problems are reported, not only the first.
void arc_load_presses(std::vector<Issue>& out, const std::string& f, const Guide& g,
                      const Model& model) {
  const double a0 = g.start_angle, a1 = g.end_angle;
  if (!std::isfinite(a0) || !std::isfinite(a1) || !(a1 > a0) || !std::isfinite(g.radius)) return;
  const double sgn = g.inside ? -1.0 : 1.0;
  const double gx = model.gravity_x, gy = model.gravity_y;
  auto press = [&](double phi) { return sgn * (gx * std::cos(phi) + gy * std::sin(phi)); };
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  double worst = a0;
  if (press(a1) > press(worst)) worst = a1;
  if (gx != 0.0 || gy != 0.0) {
    double peak = std::atan2(sgn * gy, sgn * gx);  // n along g
    peak += kTwoPi * std::ceil((a0 - peak) / kTwoPi);
    if (peak <= a1 && press(peak) > press(worst)) worst = peak;
  }
  const double at = press(worst);
  if (!(at < 0.0)) {
    out.push_back({f + "load_per_metre", check::format_si(g.load_per_metre, "kg/m"),
                   "0 on this arc: the load must press the chain onto the rail over the whole "
                   "arc, and at " +
                       check::format_si(worst * 180.0 / std::numbers::pi, "deg") +
                       " this arc's carrying side (" + (g.inside ? "inward" : "outward") +
                       ") faces " + (at > 0.0 ? "down" : "sideways or there is no gravity") +
                       " (n.g = " + check::format_si(at + 0.0, "m/s^2") + ", must be < 0)"});
  }
  const double line = roller_line(g);
  if (model.pitch > 0.0 && std::isfinite(line) && !(line >= model.pitch))
    out.push_back({f + "radius", check::format_si(g.radius, "m"),
                   "a loaded arc whose roller centres' line has a radius of at least a pitch " +
                       check::format_si(model.pitch, "m") + " (the load's ramps at its ends)"});
}

// A LineLaw's width and constants (named line_width, line, line_cap_depth under `f`), as
// use_line_law sets them for the `what` (seat or rail).
void check_line_law(std::vector<Issue>& out, const std::string& f, const LineLaw& l,
                    const char* what) {
  check::finite_positive(out, (f + "line_width").c_str(), l.width, "m");
  const contact::LineApproach& a = l.law;
  if (!(a.a > 0.0 && std::isfinite(a.a) && std::isfinite(a.c) && std::isfinite(a.cap_load()) &&
        a.cap_load() > 0.0))
    out.push_back({f + "line", "(constants)",
                   std::string("a line contact with finite A > 0 and C (line_approach of the ") +
                       what + ")"});
  else if (!(l.cap_depth > 0.0 && std::isfinite(l.cap_depth) && l.cap_stiffness > 0.0 &&
             std::isfinite(l.cap_stiffness)))
    out.push_back({f + "line_cap_depth", "(constants)",
                   "the cap's constants of the line (set by use_line_law)"});
}

// A point's place on an arc guide, the conveyed load's (rail_load) and the stick law's
// (guide_position) parametrisation: s = ρ_c φ along the roller centres' line (radius ρ_c = R ± r)
// from the arc's start angle, counter-clockwise, φ the point's angle taken within π of the arc's
// middle; L = ρ_c × sweep its length, d = |q − C| and ∂s/∂q = ρ_c t/d (t the counter-clockwise
// tangent). `ok` is false at the centre (no angle).
struct ArcPlace {
  bool ok = false;
  double s = 0.0, len = 0.0, line = 0.0, d = 0.0;
  double dsx = 0.0, dsy = 0.0;
};
ArcPlace arc_place(const Guide& g, double x, double y) {
  ArcPlace p;
  const double rx = x - g.centre_x, ry = y - g.centre_y;
  const double d2 = rx * rx + ry * ry, d = std::sqrt(d2);
  if (!(d > 0.0)) return p;
  p.ok = true;
  p.d = d;
  p.line = roller_line(g);
  const double sweep = g.end_angle - g.start_angle;
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  double phi = std::atan2(ry, rx) - g.start_angle;
  phi -= kTwoPi * std::floor((phi - 0.5 * sweep + std::numbers::pi) / kTwoPi);
  p.s = p.line * phi;
  p.len = p.line * sweep;
  p.dsx = -p.line * ry / d2;  // ∂φ/∂q = t/d, t = (−r_y, r_x)/d
  p.dsy = p.line * rx / d2;
  return p;
}

// The stick law's tangential position s along the contact's tangent t = (−n_y, n_x) and ∂s/∂q:
// on a straight rail s = (q − P₀)·t, ∂s/∂q = t (t = −u); on an arc ±ρ_c φ (arc_place; t is the
// counter-clockwise tangent on an outside arc, the clockwise one inside), ∂s/∂q = ρ_c t/|q − C|.
// On an arc also the Hessian of s, ∂²s/∂q² = [[hxx, hxy], [hxy, hyy]] (0 on a straight rail):
// the stick damper's ∂ṡ/∂q = ∂²s/∂q² v; and σ = ρ_c/|q − C|, ∂s/∂q = σ t, with its gradient
// ∂σ/∂q = −ρ_c (q − C)/|q − C|³ (σ = 1 exactly, ∂σ/∂q = 0 on a straight rail).
struct GuidePlace {
  double s = 0.0, dsx = 0.0, dsy = 0.0;
  double hxx = 0.0, hxy = 0.0, hyy = 0.0;
  double sigma = 1.0, dsigx = 0.0, dsigy = 0.0;
};
GuidePlace guide_place(const Guide& g, const GuideFrame& frame, double x, double y) {
  if (g.kind == Guide::Kind::kStraight)
    return {-((x - g.x0) * frame.ux + (y - g.y0) * frame.uy), -frame.ux, -frame.uy};
  const ArcPlace p = arc_place(g, x, y);
  const double sgn = g.inside ? -1.0 : 1.0;
  // ∂s/∂q = ±ρ_c (−r_y, r_x)/d² (+ outside): its derivatives, with ∂(1/d²)/∂q = −2 r/d⁴
  const double rx = x - g.centre_x, ry = y - g.centre_y, d2 = p.d * p.d;
  const double k = sgn * p.line / (d2 * d2);
  GuidePlace out{
      sgn * p.s,         sgn * p.dsx, sgn * p.dsy, 2.0 * k * rx * ry, k * (ry * ry - rx * rx),
      -2.0 * k * rx * ry};
  // σ = ρ_c/d, ∂σ/∂q = −ρ_c r/d³
  out.sigma = p.line / p.d;
  out.dsigx = -out.sigma * rx / d2;
  out.dsigy = -out.sigma * ry / d2;
  return out;
}
}  // namespace

std::vector<Issue> validate(const Model& model) {
  std::vector<Issue> out;
  const std::size_t n = model.nodes();
  const std::size_t min_nodes = model.closed ? 3 : 2;
  if (n < min_nodes || n > kMaxNodes) {
    out.push_back({"nodes", std::to_string(n),
                   std::string("an integer in [") + std::to_string(min_nodes) + ", " +
                       std::to_string(kMaxNodes) + "] (" +
                       (model.closed ? "closed loop" : "open chain") + ")"});
  }
  check::finite_positive(out, "pitch", model.pitch, "m");
  check::finite_positive(out, "axial_stiffness", model.axial_stiffness, "N/m");
  if (!std::isfinite(model.axial_damping) || model.axial_damping < 0.0) {
    out.push_back({"axial_damping", check::format_si(model.axial_damping, "N*s/m"),
                   "a finite value >= 0 N*s/m"});
  }
  if (model.links_carry_compression && model.links_discrete_gradient) {
    out.push_back({"links_discrete_gradient", "true",
                   "false with links_carry_compression (the bilateral link's force at theta = "
                   "0.5 is the discrete gradient of its energy already)"});
  }
  for (std::size_t q = 0; q < 2; ++q) {
    const double jam = model.link_jam_length[q];
    const std::string field = "link_jam_length[" + std::to_string(q) + "]";
    if (model.links_carry_compression) {
      if (jam != 0.0)
        out.push_back({field, check::format_si(jam, "m"),
                       "0 with links_carry_compression (a bilateral link pushes already)"});
      continue;
    }
    if (model.link_bilateral[q]) {
      if (jam != 0.0)
        out.push_back(
            {field, check::format_si(jam, "m"),
             "0 with link_bilateral[" + std::to_string(q) + "] (a bilateral link pushes already)"});
      continue;
    }
    // the jam's ramp below the tension's: s_j + ε/2 ≤ −ε/2 (its bound read only with a valid ε,
    // named below otherwise)
    if (!(std::isfinite(model.link_smoothing) && model.link_smoothing > 0.0)) continue;
    const double top = model.jam_length_bound(q);
    if (jam != 0.0 && !(std::isfinite(jam) && jam > 0.0 && jam <= top)) {
      out.push_back({field, check::format_si(jam, "m"),
                     "0 (no jam) or in (0, " + check::format_si(top, "m") +
                         "] (the link's rest length less link_smoothing)"});
    }
  }
  if (!model.links_carry_compression) {
    check::finite_positive(out, "link_smoothing", model.link_smoothing, "m");
    if (model.hinge.active())
      out.push_back({"links_carry_compression", "false",
                     "true with hinge friction (the hinges' load of tension-only links is not "
                     "built)"});
  }
  if (!std::isfinite(model.drag) || model.drag < 0.0) {
    out.push_back({"drag", check::format_si(model.drag, "1/s"), "a finite value >= 0 1/s"});
  }
  if (!std::isfinite(model.gravity_x) || !std::isfinite(model.gravity_y)) {
    out.push_back(
        {"gravity",
         check::format_si(model.gravity_x, "") + ", " + check::format_si(model.gravity_y, "m/s^2"),
         "finite components"});
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(model.mass[i]) || model.mass[i] <= 0.0) {
      out.push_back({"mass[" + std::to_string(i) + "]", check::format_si(model.mass[i], "kg"),
                     "a finite value > 0 kg"});
      break;  // one line for a whole bad array is enough to name it
    }
  }
  if (!std::isfinite(model.alternation) || model.alternation < 0.0 ||
      !(model.alternation < model.pitch)) {
    out.push_back({"alternation", check::format_si(model.alternation, "m"),
                   "a length in [0, pitch) m (links of p + a and p - a)"});
  } else if (model.alternation > 0.0 && model.closed && n % 2 != 0) {
    out.push_back({"alternation", check::format_si(model.alternation, "m"),
                   "0 for a closed loop of an odd number of links (" + std::to_string(n) +
                       "): p + a and p - a must alternate round the loop"});
  }
  if (!model.pinned.empty() && model.pinned.size() != n) {
    out.push_back({"pinned", std::to_string(model.pinned.size()) + " entries",
                   "empty or one entry per node (" + std::to_string(n) + ")"});
  }
  for (std::size_t l = 0; l < model.loads.size(); ++l) {
    const NodeLoad& f = model.loads[l];
    const std::string at = "load[" + std::to_string(l) + "].";
    if (f.node >= n) {
      out.push_back(
          {at + "node", std::to_string(f.node), "a node index in [0, " + std::to_string(n) + ")"});
    }
    if (!std::isfinite(f.fx) || !std::isfinite(f.fy)) {
      out.push_back({at + "force", check::format_si(f.fx, "") + ", " + check::format_si(f.fy, "N"),
                     "finite components"});
    }
  }
  for (std::size_t w = 0; w < model.sprockets.size(); ++w) {
    const Sprocket& s = model.sprockets[w];
    const std::string f = "sprocket[" + std::to_string(w) + "].";
    check::finite(out, (f + "centre_x").c_str(), s.centre_x, "m");
    check::finite(out, (f + "centre_y").c_str(), s.centre_y, "m");
    if (s.teeth < 3 || s.teeth > 1000) {
      out.push_back({f + "teeth", std::to_string(s.teeth), "an integer in [3, 1000]"});
    }
    check::finite_positive(out, (f + "pitch_radius").c_str(), s.pitch_radius, "m");
    if (s.pocket) {
      const std::size_t before = out.size();
      pocket_issues(out, s, f);
      // the polygon's sides must be the chain's links, p + a on the δ1 side and p − a on the δ2
      // side: a pocket wheel with equal links (alternation 0) or another wire strains every link
      const double tau = 2.0 * std::numbers::pi / s.teeth;
      const double side1 = 2.0 * s.pitch_radius * std::sin(0.5 * s.pocket_angle);
      const double side2 = 2.0 * s.pitch_radius * std::sin(0.5 * (tau - s.pocket_angle));
      const double p = model.pitch, a = model.alternation;
      if (out.size() == before && p > 0.0 && std::isfinite(a) &&
          !(std::abs(side1 - (p + a)) <= 0.01 * p && std::abs(side2 - (p - a)) <= 0.01 * p)) {
        out.push_back({f + "pocket_angle", check::format_si(s.pocket_angle, "rad"),
                       "a polygon whose sides (" + check::format_si(side1, "m") + ", " +
                           check::format_si(side2, "m") +
                           ") are the chain's links p + a and p - a (" +
                           check::format_si(p + a, "m") + ", " + check::format_si(p - a, "m") +
                           ") within 1 % of p: set the model's alternation to the wire diameter"});
      }
    } else {
      check::finite_positive(out, (f + "roller_radius").c_str(), s.roller_radius, "m");
      if (!std::isfinite(s.seat_radius) || !(s.seat_radius >= s.roller_radius)) {
        out.push_back(
            {f + "seat_radius", check::format_si(s.seat_radius, "m"),
             "a finite value >= the roller radius " + check::format_si(s.roller_radius, "m")});
      }
      if (!std::isfinite(s.seating_angle) || !(s.seating_angle > 0.0) ||
          !(s.seating_angle < std::numbers::pi)) {
        out.push_back({f + "seating_angle", check::format_si(s.seating_angle, "rad"),
                       "an angle in (0, pi) rad"});
      }
      if (!std::isfinite(s.flank_radius) || !(s.flank_radius >= 0.0)) {
        out.push_back({f + "flank_radius", check::format_si(s.flank_radius, "m"),
                       "0 (straight flanks) or a finite value > 0"});
      }
      if (!std::isfinite(s.tip_radius) || !(s.tip_radius == 0.0 || s.tip_radius > s.pitch_radius)) {
        out.push_back({f + "tip_radius", check::format_si(s.tip_radius, "m"),
                       "0 (no tip) or a finite value > the pitch radius " +
                           check::format_si(s.pitch_radius, "m")});
      }
      check::finite_positive(out, (f + "contact_stiffness").c_str(), s.contact_stiffness, "N/m");
      if (!std::isfinite(s.contact_smoothing) || !(s.contact_smoothing > 0.0) ||
          !(s.contact_smoothing <= s.roller_radius)) {
        out.push_back({f + "contact_smoothing", check::format_si(s.contact_smoothing, "m"),
                       "a length in (0, roller radius]"});
      }
    }
    if (s.line_law) {
      if (s.pocket)
        out.push_back({f + "line_law", "on a pocket wheel", "the linear law on a pocket wheel"});
      check_line_law(out, f, s.line, "seat");
    }
    if (!std::isfinite(s.contact_damping) || s.contact_damping < 0.0) {
      out.push_back({f + "contact_damping", check::format_si(s.contact_damping, "N*s/m"),
                     "a finite value >= 0 N*s/m"});
    }
    if (s.takeup) {
      if (s.driver)
        out.push_back({f + "takeup", "on a driver", "a take-up on a driven wheel or an idler"});
      if (!std::isfinite(s.takeup_dx) || !std::isfinite(s.takeup_dy) ||
          !(std::abs(std::hypot(s.takeup_dx, s.takeup_dy) - 1.0) <= 1e-9))
        out.push_back({f + "takeup_direction",
                       "(" + check::format_si(s.takeup_dx, "") + ", " +
                           check::format_si(s.takeup_dy, "") + ")",
                       "a unit vector"});
      check::finite(out, (f + "takeup_force").c_str(), s.takeup_force, "N");
      if (!std::isfinite(s.takeup_stiffness) || !(s.takeup_stiffness >= 0.0))
        out.push_back({f + "takeup_stiffness", check::format_si(s.takeup_stiffness, "N/m"),
                       "a finite value >= 0 N/m"});
      if (!std::isfinite(s.takeup_damping) || !(s.takeup_damping >= 0.0))
        out.push_back({f + "takeup_damping", check::format_si(s.takeup_damping, "N*s/m"),
                       "a finite value >= 0 N*s/m"});
      check::finite_positive(out, (f + "takeup_mass").c_str(), s.takeup_mass, "kg");
      // the travel holds the start (s = 0); an end may be infinite (no stop there)
      if (std::isnan(s.takeup_travel_min) || !(s.takeup_travel_min <= 0.0))
        out.push_back({f + "takeup_travel_min", check::format_si(s.takeup_travel_min, "m"),
                       "<= 0 m (the start, s = 0, within the travel), or -infinity"});
      if (std::isnan(s.takeup_travel_max) || !(s.takeup_travel_max >= 0.0))
        out.push_back({f + "takeup_travel_max", check::format_si(s.takeup_travel_max, "m"),
                       ">= 0 m (the start, s = 0, within the travel), or +infinity"});
    }
    if (!std::isfinite(s.friction) || !(s.friction >= 0.0) || !(s.friction <= 1.0)) {
      out.push_back({f + "friction", check::format_si(s.friction, ""), "a number in [0, 1]"});
    }
    if (!std::isfinite(s.friction_band) || !(s.friction_band > 0.0) || !(s.friction_band <= 1.0)) {
      out.push_back(
          {f + "friction_band", check::format_si(s.friction_band, "m/s"), "a speed in (0, 1] m/s"});
    }
    if (s.driver) {
      check::finite(out, (f + "speed").c_str(), s.speed, "rad/s");
    } else {
      check::finite_positive(out, (f + "inertia").c_str(), s.inertia, "kg*m^2");
      check::finite(out, (f + "load_torque").c_str(), s.load_torque, "N*m");
    }
  }
  for (std::size_t w = 0; w < model.guides.size(); ++w) {
    const Guide& g = model.guides[w];
    const std::string f = "guide[" + std::to_string(w) + "].";
    if (g.kind == Guide::Kind::kStraight) {
      const bool ends =
          std::isfinite(g.x0) && std::isfinite(g.y0) && std::isfinite(g.x1) && std::isfinite(g.y1);
      if (!ends || !(std::hypot(g.x1 - g.x0, g.y1 - g.y0) > 0.0)) {
        out.push_back({f + "end", check::format_si(std::hypot(g.x1 - g.x0, g.y1 - g.y0), "m"),
                       "finite end points at a distance > 0 m"});
      }
    } else {
      check::finite(out, (f + "centre_x").c_str(), g.centre_x, "m");
      check::finite(out, (f + "centre_y").c_str(), g.centre_y, "m");
      check::finite_positive(out, (f + "radius").c_str(), g.radius, "m");
      if (g.inside && std::isfinite(g.radius) && !(g.radius > g.roller_radius)) {
        out.push_back({f + "radius", check::format_si(g.radius, "m"),
                       "more than the roller radius " + check::format_si(g.roller_radius, "m") +
                           " (rollers inside the arc)"});
      }
      check::finite(out, (f + "start_angle").c_str(), g.start_angle, "rad");
      const double sweep = g.end_angle - g.start_angle;
      if (!std::isfinite(g.end_angle) || !(sweep > 0.0) || !(sweep <= 2.0 * std::numbers::pi)) {
        out.push_back({f + "end_angle", check::format_si(g.end_angle, "rad"),
                       "an angle in (start_angle, start_angle + 2 pi] rad"});
      }
    }
    check::finite_positive(out, (f + "roller_radius").c_str(), g.roller_radius, "m");
    if (g.line_law)
      check_line_law(out, f, g.line, "rail");
    else
      check::finite_positive(out, (f + "contact_stiffness").c_str(), g.contact_stiffness, "N/m");
    if (!(g.rail.modulus >= kLeastRailModulus && g.rail.modulus <= kMostRailModulus))
      out.push_back({f + "rail_modulus", check::format_si(g.rail.modulus, "Pa"),
                     "a modulus in [0.1, 1000] GPa (polymers, UHMW-PE 0.5-1 GPa, to steel)"});
    if (!(g.rail.poisson >= 0.0 && g.rail.poisson < 0.5))
      out.push_back({f + "rail_poisson", check::format_si(g.rail.poisson, ""), "0 <= nu < 0.5"});
    if (!std::isfinite(g.contact_damping) || g.contact_damping < 0.0) {
      out.push_back({f + "contact_damping", check::format_si(g.contact_damping, "N*s/m"),
                     "a finite value >= 0 N*s/m"});
    }
    if (!std::isfinite(g.contact_smoothing) || !(g.contact_smoothing > 0.0) ||
        !(g.contact_smoothing <= g.roller_radius)) {
      out.push_back({f + "contact_smoothing", check::format_si(g.contact_smoothing, "m"),
                     "a length in (0, roller radius]"});
    }
    if (!std::isfinite(g.friction) || !(g.friction >= 0.0) || !(g.friction <= 1.0)) {
      out.push_back({f + "friction", check::format_si(g.friction, ""), "a number in [0, 1]"});
    }
    if (!std::isfinite(g.friction_band) || !(g.friction_band > 0.0) || !(g.friction_band <= 1.0)) {
      out.push_back(
          {f + "friction_band", check::format_si(g.friction_band, "m/s"), "a speed in (0, 1] m/s"});
    }
    if (!std::isfinite(g.stick_stiffness) || !(g.stick_stiffness >= 0.0)) {
      out.push_back({f + "stick_stiffness", check::format_si(g.stick_stiffness, "N/m"),
                     "a finite stiffness >= 0 N/m (0: the regularised friction)"});
    } else if (g.stick_stiffness > 0.0 && g.friction == 0.0) {
      out.push_back({f + "stick_stiffness", check::format_si(g.stick_stiffness, "N/m"),
                     "0 on a frictionless guide (friction = 0: nothing to stick with)"});
    }
    if (!std::isfinite(g.stick_damping) || !(g.stick_damping >= 0.0)) {
      out.push_back({f + "stick_damping", check::format_si(g.stick_damping, "N*s/m"),
                     "a finite damping >= 0 N*s/m (0: the stick law's bare spring)"});
    } else if (g.stick_damping > 0.0 && !(g.stick_stiffness > 0.0)) {
      out.push_back({f + "stick_damping", check::format_si(g.stick_damping, "N*s/m"),
                     "0 without stick_stiffness (a damper on the stick law's spring)"});
    }
    if (g.load_inertia && !(g.load_per_metre > 0.0))
      out.push_back({f + "load_inertia", "true",
                     "false without a load (load_per_metre > 0 kg/m): there is no load to move"});
    if (!std::isfinite(g.load_speed) || !(std::abs(g.load_speed) <= kMaxLoadSpeed))
      out.push_back({f + "load_speed", check::format_si(g.load_speed, "m/s"),
                     "a speed in [-" + check::format_si(kMaxLoadSpeed, "") + ", " +
                         check::format_si(kMaxLoadSpeed, "") + "] m/s"});
    else if (g.load_speed != 0.0 && !g.load_inertia)
      out.push_back({f + "load_speed", check::format_si(g.load_speed, "m/s"),
                     "0 without load_inertia = true (the arriving material's speed acts through "
                     "the load's inertia)"});
    if (!std::isfinite(g.load_per_metre) || !(g.load_per_metre >= 0.0) ||
        !(g.load_per_metre <= kMaxRailLoad)) {
      out.push_back({f + "load_per_metre", check::format_si(g.load_per_metre, "kg/m"),
                     "a load per metre in [0, " + check::format_si(kMaxRailLoad, "") + "] kg/m"});
    } else if (g.load_per_metre > 0.0 && g.kind == Guide::Kind::kArc) {
      arc_load_presses(out, f, g, model);
    } else if (g.load_per_metre > 0.0 && std::isfinite(g.x0 + g.y0 + g.x1 + g.y1) &&
               std::hypot(g.x1 - g.x0, g.y1 - g.y0) > 0.0) {
      // the load's weight must press the chain onto the rail: n·g < 0, n = (−u_y, u_x) the free
      // (carrying) side's normal; else it pulls the chain off and is dropped a pitch away
      const GuideFrame fr = guide_frame(g);
      const double press = -fr.uy * model.gravity_x + fr.ux * model.gravity_y;
      if (!(press < 0.0))
        out.push_back({f + "load_per_metre", check::format_si(g.load_per_metre, "kg/m"),
                       "0 on this guide: the load must press the chain onto the rail, and this "
                       "rail's carrying side (left going from its first end to its second) faces " +
                           std::string(press > 0.0 ? "down" : "sideways or there is no gravity") +
                           " (n.g = " + check::format_si(press + 0.0, "m/s^2") + ", must be < 0)"});
    }
  }
  std::vector<Issue> hinge = validate(model.hinge, model.pitch);
  out.insert(out.end(), hinge.begin(), hinge.end());
  if (!model.mass.empty()) {
    hinge = validate_pin_links(model.hinge, model.links(), model.closed);
    out.insert(out.end(), hinge.begin(), hinge.end());
  }
  return out;
}

GuideBounds guide_bounds(const Guide& g) {
  // guide_contact is active only at 0 < g < 2r: within r of the straight segment's line between
  // its ends (so within r of the segment in each axis), or at a distance in (R − r, R + r) from
  // the arc's centre, inside or outside.
  const double r = std::abs(g.roller_radius);
  double x_lo = 0.0, x_hi = 0.0, y_lo = 0.0, y_hi = 0.0;
  if (g.kind == Guide::Kind::kStraight) {
    x_lo = std::min(g.x0, g.x1) - r;
    x_hi = std::max(g.x0, g.x1) + r;
    y_lo = std::min(g.y0, g.y1) - r;
    y_hi = std::max(g.y0, g.y1) + r;
  } else {
    const double reach = std::abs(g.radius) + r;
    x_lo = g.centre_x - reach;
    x_hi = g.centre_x + reach;
    y_lo = g.centre_y - reach;
    y_hi = g.centre_y + reach;
  }
  // a non-finite input (std::min and std::max pass a NaN over): no cull, guide_contact decides
  const double sum = g.kind == Guide::Kind::kStraight ? g.x0 + g.x1 + g.y0 + g.y1 + r
                                                      : g.centre_x + g.centre_y + g.radius + r;
  if (!std::isfinite(sum)) return {-INFINITY, INFINITY, -INFINITY, INFINITY};
  const double pad =
      1e-9 * (std::max({std::abs(x_lo), std::abs(x_hi), std::abs(y_lo), std::abs(y_hi)}) + r);
  return {x_lo - pad, x_hi + pad, y_lo - pad, y_hi + pad};
}

std::vector<Issue> validate(const LeadIn& lead) {
  std::vector<Issue> out;
  check::finite_positive(out, "lead_in_radius", lead.radius, "m");
  // at least 0.1 deg: a sweep of 1e-15 deg gave an arc whose end angle equals its start in
  // double precision, refused as an inner guide's end_angle the user never wrote
  constexpr double kLeast = 0.1 * std::numbers::pi / 180.0;
  if (!std::isfinite(lead.angle) || !(lead.angle >= kLeast) ||
      !(lead.angle <= 0.5 * std::numbers::pi))
    out.push_back({"lead_in_angle", check::format_si(lead.angle * 180.0 / std::numbers::pi, "deg"),
                   "an angle in [0.1, 90] deg"});
  return out;
}

namespace {
// An arc rail whose centre, radius and sweep validate would accept (else its own checks name them
// and no lead-in is laid on it)
bool arc_rail_valid(const Guide& rail) {
  const double sweep = rail.end_angle - rail.start_angle;
  return rail.kind == Guide::Kind::kArc && std::isfinite(rail.centre_x) &&
         std::isfinite(rail.centre_y) && std::isfinite(rail.radius) && rail.radius > 0.0 &&
         std::isfinite(rail.start_angle) && std::isfinite(rail.end_angle) && sweep > 0.0 &&
         sweep <= 2.0 * std::numbers::pi;
}
}  // namespace

double lead_in_cover(const Guide& rail, const LeadIn& lead) {
  if (rail.kind != Guide::Kind::kArc) return NAN;
  const double rho = rail.radius, big = lead.radius, alpha = lead.angle;
  const double reach = big + rail.roller_radius;  // the roller centres' farthest from its centre
  // in the end's frame (x along e from C, y past the end) the lead-in's centre is at
  // (ρ ∓ R, 0) and the roller centres it touches at (ρ ∓ R ± s cos θ, s sin θ), s ≤ R + r,
  // θ ≤ α ≤ π/2: their angle from C grows with s, and with θ outside (its derivative
  // ∝ s ((ρ − R) cos θ + s)); inside it peaks where the line from C touches the circle of R + r
  if (!rail.inside) {
    if (!(big < rho)) return NAN;
    return std::atan2(reach * std::sin(alpha), rho - big + reach * std::cos(alpha));
  }
  if (!(rho > rail.roller_radius)) return NAN;
  const double far = rho + big;  // |C_L − C|
  if (std::cos(alpha) <= reach / far) return std::asin(reach / far);
  return std::atan2(reach * std::sin(alpha), far - reach * std::cos(alpha));
}

double lead_in_angle_limit(const Guide& rail, const LeadIn& lead, double cover) {
  if (rail.kind != Guide::Kind::kArc || !(cover >= 0.0)) return NAN;
  const double rho = rail.radius, big = lead.radius, reach = big + rail.roller_radius;
  const double most = 0.5 * std::numbers::pi;
  // lead_in_cover's β set to `cover` and solved for α: outside tan β = reach sin α / (ρ − R +
  // reach cos α), i.e. reach sin(α − β) = (ρ − R) sin β, β growing with α up to α = π/2; inside
  // tan β = reach sin α / (ρ + R − reach cos α), i.e. reach sin(α + β) = (ρ + R) sin β, β growing
  // up to the tangent from C, where α + β = π/2 (beyond it β stays there, up to α = π/2)
  if (!rail.inside) {
    if (!(big < rho)) return NAN;
    if (cover >= std::atan2(reach, rho - big)) return most;
    return std::min(most, cover + std::asin((rho - big) * std::sin(cover) / reach));
  }
  if (!(rho > rail.roller_radius)) return NAN;
  const double far = rho + big;
  if (cover >= std::asin(reach / far)) return most;
  return std::min(most, std::asin(far * std::sin(cover) / reach) - cover);
}

std::vector<Issue> validate(const LeadIn& lead, const Guide& rail) {
  std::vector<Issue> out = validate(lead);
  if (!out.empty() || !arc_rail_valid(rail)) return out;
  const double deg = 180.0 / std::numbers::pi;
  if (!rail.inside && !(lead.radius < rail.radius)) {
    out.push_back({"lead_in_radius", check::format_si(lead.radius, "m"),
                   "a lead-in radius 0 < R < " + check::format_si(rail.radius, "m") +
                       ", the arc's surface radius (rollers outside an arc: the lead-in bends "
                       "away from the rail's circle only curving more sharply; R = the radius "
                       "continues the rail, a larger R rises above its circle)"});
    return out;
  }
  const double open = 2.0 * std::numbers::pi - (rail.end_angle - rail.start_angle);
  if (!(open > 1e-9)) {  // a closed ring (to the angles' rounding): no angle or radius helps
    out.push_back({"lead_in_radius", check::format_si(lead.radius, "m"),
                   "no lead-in on a closed ring (end_angle - start_angle = 360 deg): it has no "
                   "end to lead in from"});
    return out;
  }
  const double cover = lead_in_cover(rail, lead);
  if (!std::isfinite(cover)) return out;  // inside an arc no wider than a roller: its own check
  const int ends = (lead.at_start ? 1 : 0) + (lead.at_end ? 1 : 0);
  if (!(ends * cover > open)) return out;
  // what fits, rounded down so that the value named fits: the angle at this radius (closed form,
  // lead_in_angle_limit), the radius at this angle (bisected: the cover grows with R), one end
  const double each = open / ends;
  constexpr double kLeast = 0.1 * std::numbers::pi / 180.0;  // validate(LeadIn)'s
  std::vector<std::string> fits;
  const double angle = check::down_to(lead_in_angle_limit(rail, lead, each) * deg, 4);
  if (angle >= kLeast * deg)
    fits.push_back("lead_in_angle <= " + check::format_si(angle, "deg") +
                   " at this lead_in_radius");
  if (lead_in_cover(rail, {0.0, lead.angle, true, true}) <= each) {
    double lo = 0.0, hi = lead.radius;  // cover(lo) fits, cover(hi) does not
    for (int i = 0; i < 200 && lo < hi && std::nextafter(lo, hi) < hi; ++i) {
      const double mid = 0.5 * (lo + hi);
      (lead_in_cover(rail, {mid, lead.angle, true, true}) <= each ? lo : hi) = mid;
    }
    const double radius = check::down_to(lo, 4);
    if (radius > 0.0)
      fits.push_back("lead_in_radius <= " + check::format_si(radius, "m") +
                     " at this lead_in_angle");
  }
  if (ends == 2 && cover <= open) fits.push_back("one lead_in_end");
  std::string remedy;
  for (const std::string& f : fits) remedy += (remedy.empty() ? "" : ", or ") + f;
  if (remedy.empty())
    remedy = "no lead-in of 0.1 deg or more fits it at any radius (a shorter arc would)";
  out.push_back({"lead_in_angle", check::format_si(lead.angle * deg, "deg"),
                 "a lead-in whose contact, " + check::format_si(cover * deg, "deg") +
                     " round the arc's centre at " +
                     (ends == 1 ? std::string("its end") : "each of its 2 ends") +
                     ", fits the arc's open part, 360 deg - (end_angle - start_angle) = " +
                     check::format_si(open * deg, "deg") +
                     " (else a roller meets the rail and a lead-in at once): " + remedy});
  return out;
}

std::vector<Guide> lead_in_arcs(const Guide& rail, const LeadIn& lead) {
  std::vector<Guide> out;
  if (!validate(lead, rail).empty()) return out;
  auto arc = [&](double cx, double cy, double from, double to) {
    Guide g = rail;
    g.kind = Guide::Kind::kArc;
    g.x0 = g.y0 = g.x1 = g.y1 = 0.0;
    g.centre_x = cx;
    g.centre_y = cy;
    g.radius = lead.radius;
    g.start_angle = from;
    g.end_angle = to;
    g.inside = false;        // the rollers ride outside the lead-in, on a straight or arc rail
    g.load_per_metre = 0.0;  // the rail's load is the rail's (an arc carries none)
    g.load_inertia = false;
    g.load_speed = 0.0;
    g.stick_stiffness = 0.0;  // a lead-in slides with the regularised law (not the rail's k_t)
    g.stick_damping = 0.0;
    if (rail.line_law) use_line_law(g, rail.line.width);  // the arc's own curvature
    out.push_back(g);
  };
  if (rail.kind == Guide::Kind::kArc) {
    if (!arc_rail_valid(rail)) return out;
    // The lead-in's centre on the line from C through the end, R from the end on the rail's far
    // side: C + (ρ − R) e outside (its surface point at the end at the end's angle a), C + (ρ + R)
    // e inside (there at a + π). Past the end the rail runs on along its counter-clockwise tangent
    // t at the end angle, past the start along −t. Outside, the lead-in's counter-clockwise tangent
    // at a is t: its arc runs from a on to a + α at the end, from a − α to a at the start.
    // Inside, it is −t at a + π: from a + π − α to a + π at the end, from a + π to a + π + α at the
    // start.
    const double pi = std::numbers::pi;
    const double off = rail.inside ? rail.radius + lead.radius : rail.radius - lead.radius;
    auto at = [&](double a, double from, double to) {
      arc(rail.centre_x + off * std::cos(a), rail.centre_y + off * std::sin(a), from, to);
    };
    const double a0 = rail.start_angle, a1 = rail.end_angle;
    if (lead.at_start) {
      if (rail.inside)
        at(a0, a0 + pi, a0 + pi + lead.angle);
      else
        at(a0, a0 - lead.angle, a0);
    }
    if (lead.at_end) {
      if (rail.inside)
        at(a1, a1 + pi - lead.angle, a1 + pi);
      else
        at(a1, a1, a1 + lead.angle);
    }
    return out;
  }
  const GuideFrame f = guide_frame(rail);
  if (!(f.length > 0.0) || !std::isfinite(f.length)) return out;
  // the free side's normal n = perp(u); the arc's centre R below the rail's end along −n, its
  // surface point at the end's angle atan2(n); going on along the rail turns from n toward u
  // (clockwise) at the second end, toward −u (counter-clockwise) at the first
  const double nx = -f.uy, ny = f.ux;
  const double up = std::atan2(ny, nx);
  if (lead.at_start)
    arc(rail.x0 - lead.radius * nx, rail.y0 - lead.radius * ny, up, up + lead.angle);
  if (lead.at_end) arc(rail.x1 - lead.radius * nx, rail.y1 - lead.radius * ny, up - lead.angle, up);
  return out;
}

GuideFrame guide_frame(const Guide& g) {
  if (g.kind != Guide::Kind::kStraight) return {};
  const double ax = g.x1 - g.x0, ay = g.y1 - g.y0;
  const double len = std::sqrt(ax * ax + ay * ay);
  return {ax / len, ay / len, len};
}

RailLoad rail_load(const Guide& g, const GuideFrame& frame, double pitch, double gravity_x,
                   double gravity_y, double x, double y) {
  RailLoad out;
  if (!(g.load_per_metre > 0.0) || !(pitch > 0.0)) return out;
  // the node's place along the rail s, its length L, its place across it from the roller centres'
  // line (along the free side's normal) and ∂s/∂q
  double s = 0.0, len = 0.0, across = 0.0, dsx = 0.0, dsy = 0.0;
  if (g.kind == Guide::Kind::kStraight) {
    if (!(frame.length > 0.0)) return out;
    const double rx = x - g.x0, ry = y - g.y0;
    s = rx * frame.ux + ry * frame.uy;
    across = -rx * frame.uy + ry * frame.ux - g.roller_radius;
    len = frame.length;
    dsx = frame.ux;
    dsy = frame.uy;
  } else {
    // an arc: s = ρ_c φ along the roller centres' line from its start angle (arc_place)
    const ArcPlace p = arc_place(g, x, y);
    if (!p.ok) return out;
    s = p.s;
    len = p.len;
    across = g.inside ? p.line - p.d : p.d - p.line;
    dsx = p.dsx;
    dsy = p.dsy;
  }
  // the carried side only: up to a pitch off the rail (a roller lifted by the chain's motion),
  // at most a roller radius into it (a carried roller's centre is never behind the surface); a
  // strand behind the rail — the chain's other run, another guided strand — carries none
  if (!(across >= -g.roller_radius && across <= pitch)) return out;
  const double half = 0.5 * pitch;
  const double hi = std::min(s + half, len), lo = std::max(s - half, 0.0);
  if (!(hi > lo)) return out;  // beyond the ramp at either end
  out.active = true;
  out.share = (hi - lo) / pitch;
  const double slope = ((s + half < len ? 1.0 : 0.0) - (s - half > 0.0 ? 1.0 : 0.0)) / pitch;
  const double weight = g.load_per_metre * pitch;  // [kg] one pitch's load
  out.fx = weight * gravity_x * out.share;
  out.fy = weight * gravity_y * out.share;
  const double ax = weight * gravity_x * slope, ay = weight * gravity_y * slope;
  out.dq[0] = ax * dsx;
  out.dq[1] = ax * dsy;
  out.dq[2] = ay * dsx;
  out.dq[3] = ay * dsy;
  return out;
}

LoadMass load_mass(const Model& model, std::span<const GuideFrame> frames, double x, double y,
                   std::span<LoadPiece> pieces) {
  LoadMass out;
  for (std::size_t g = 0; g < model.guides.size(); ++g) {
    const Guide& guide = model.guides[g];
    if (!pieces.empty()) pieces[g] = {};
    if (!guide.load_inertia || !(guide.load_per_metre > 0.0)) continue;
    // the load's weight under a unit gravity along x: q_L p w(s) and its gradient
    const RailLoad l = rail_load(guide, frames[g], model.pitch, 1.0, 0.0, x, y);
    if (!l.active) continue;
    out.mass += l.fx;
    out.dx += l.dq[0];
    out.dy += l.dq[1];
    LoadPiece piece{.active = true, .mass = l.fx, .dx = l.dq[0], .dy = l.dq[1]};
    if (guide.load_speed != 0.0) {
      // the arriving momentum m_g u_g: u_g = load_speed t, t the rail's direction (constant) or
      // the arc's counter-clockwise tangent at q, t = (−r_y, r_x)/|r|, r = q − C, ∂t/∂q = −n tᵀ/|r|
      piece.tx = frames[g].ux;
      piece.ty = frames[g].uy;
      if (guide.kind == Guide::Kind::kArc) {
        const double rx = x - guide.centre_x, ry = y - guide.centre_y;
        const double d = std::hypot(rx, ry);  // > 0: the share is active
        const double nx = rx / d, ny = ry / d;
        piece.tx = -ny;
        piece.ty = nx;
        piece.dt[0] = -nx * piece.tx / d;
        piece.dt[1] = -nx * piece.ty / d;
        piece.dt[2] = -ny * piece.tx / d;
        piece.dt[3] = -ny * piece.ty / d;
      }
      const double u = guide.load_speed, tx = piece.tx, ty = piece.ty;
      const double* dt = piece.dt;
      out.px += l.fx * u * tx;
      out.py += l.fx * u * ty;
      out.dp[0] += u * (tx * l.dq[0] + l.fx * dt[0]);
      out.dp[1] += u * (tx * l.dq[1] + l.fx * dt[1]);
      out.dp[2] += u * (ty * l.dq[0] + l.fx * dt[2]);
      out.dp[3] += u * (ty * l.dq[1] + l.fx * dt[3]);
    }
    if (!pieces.empty()) pieces[g] = piece;
  }
  return out;
}

bool any_load_inertia(std::span<const Guide> guides) {
  return std::any_of(guides.begin(), guides.end(),
                     [](const Guide& g) { return g.load_inertia && g.load_per_metre > 0.0; });
}

GuideContact guide_contact(const Guide& gd, double x, double y, double vx, double vy) {
  return guide_contact(gd, guide_frame(gd), x, y, vx, vy);
}

GuideContact guide_contact(const Guide& gd, const GuideFrame& frame, double x, double y, double vx,
                           double vy) {
  return guide_contact(gd, frame, x, y, vx, vy, NAN);
}

double guide_position(const Guide& g, const GuideFrame& frame, double x, double y) {
  return guide_place(g, frame, x, y).s;
}

double stick_stretch(const Guide& g, double s, double anchor) {
  const double d = s - anchor;
  if (g.kind == Guide::Kind::kStraight) return d;
  // an arc: within half the rollers' line's circle of the anchor (a closed arc's seam, where φ
  // jumps by 2π, is no slip); a stretch within that is kept bit for bit
  const double round = 2.0 * std::numbers::pi * std::abs(roller_line(g));
  if (!(round > 0.0)) return d;
  return d - round * std::floor(d / round + 0.5);
}

double stick_anchor_after(const Guide& g, const GuideContact& c, double anchor, double end) {
  if (!c.active || !(c.normal_force > 0.0)) return NAN;  // off the rail or lifting: released
  if (!std::isfinite(anchor)) return end;                // first touch: it sticks where it is
  // the spring's reach (the force the step applied): the spring is left at the step's end
  // s₁ stretched by at most that, the anchor following the roller beyond it (the slip); the
  // spring's force along t is σ k_t (s − a) (∂s/∂q = σ t; σ = 1 on a straight rail), so its reach
  // in s is μ f/(k_t σ), σ taken at the θ point
  const double reach =
      g.friction * std::max(c.normal_force, 0.0) / g.stick_stiffness / c.position_scale;
  const double d = stick_stretch(g, end, anchor);
  if (std::abs(d) <= reach) return anchor;
  return end - std::copysign(reach, d);
}

namespace {
// A contact's elastic part at the gap g (0 for g ≤ 0): the line law, or the penalty k_c with its
// C¹ ramp over the first ε. A rail's and a seat's.
LineForce contact_elastic(bool line_law, const LineLaw& line, double kc, double eps, double g) {
  if (line_law) return line_force(line, g);
  if (!(g > 0.0)) return {};
  return detail::penalty_ramp(kc, eps, g);
}
LineForce rail_elastic(const Guide& gd, double g) {
  return contact_elastic(gd.line_law, gd.line, gd.contact_stiffness, gd.contact_smoothing, g);
}
LineForce seat_elastic(const Sprocket& w, double g) {
  return contact_elastic(w.line_law, w.line, w.contact_stiffness, w.contact_smoothing, g);
}

// The gap g at (x, y) in the rail's geometry with no test of its ends or sides (∂g/∂q = −n, n
// returned): r − (q − P₀)·n on a straight rail (n the left normal: the free side), R + r − |q − C|
// outside an arc, |q − C| − (R − r) inside it. `curvature`, if given, gets κ with ∂n/∂q = κ t tᵀ:
// 0 on a straight rail, ±1/|q − C| on an arc (0 at its centre, where n is 0).
double rail_gap(const Guide& gd, const GuideFrame& frame, double x, double y, double& nx,
                double& ny, double* curvature = nullptr) {
  const double r = gd.roller_radius;
  if (gd.kind == Guide::Kind::kStraight) {
    nx = -frame.uy;
    ny = frame.ux;
    if (curvature != nullptr) *curvature = 0.0;
    return r - ((x - gd.x0) * nx + (y - gd.y0) * ny);
  }
  const double rx = x - gd.centre_x, ry = y - gd.centre_y;
  const double d = std::sqrt(rx * rx + ry * ry);
  const double sgn = gd.inside ? -1.0 : 1.0;
  nx = d > 0.0 ? sgn * rx / d : 0.0;
  ny = d > 0.0 ? sgn * ry / d : 0.0;
  if (curvature != nullptr) *curvature = d > 0.0 ? sgn / d : 0.0;
  return gd.inside ? d - (gd.radius - r) : gd.radius + r - d;
}

// The rail's ends: (x, y) along the straight rail's length, within the arc's angles (and off its
// centre); `along` gets its place, from (x0, y0) along the straight rail, the angle from
// start_angle round the arc's centre in [0, 2π) (GuideSpot).
inline bool between_rail_ends(const Guide& gd, const GuideFrame& frame, double x, double y,
                              double& along) {
  if (gd.kind == Guide::Kind::kStraight) {
    along = (x - gd.x0) * frame.ux + (y - gd.y0) * frame.uy;
    return along >= 0.0 && along <= frame.length;
  }
  const double rx = x - gd.centre_x, ry = y - gd.centre_y;
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  double a = std::atan2(ry, rx) - gd.start_angle;
  a -= kTwoPi * std::floor(a / kTwoPi);
  along = a;
  if (!(rx * rx + ry * ry > 0.0)) return false;  // at the centre: no normal
  return !(a > gd.end_angle - gd.start_angle);
}

// The discrete gradient of a contact's energy between the gaps g0 and g1: f_e and ∂f_e/∂g₁.
// `elastic(g)` is the law (rail_elastic, seat_elastic).
struct DiscreteGradient {
  double force = 0.0, slope = 0.0;
};
// `floor` [m]: the smallest scale of the threshold (a tension-only link's ε, whose stretch
// passes through 0 in the middle of its ramp; 0 for the contacts, whose energy is 0 at g = 0).
// `start_energy()` gives elastic(g0).energy (called only where the quotient reads it: a caller
// that keeps the step's start may give it from its memo). `centre` [m]: where the threshold's |g|
// is measured from (a jammed link's s_j; else 0).
template <class Law, class StartEnergy>
DiscreteGradient discrete_gradient(const Law& elastic, const StartEnergy& start_energy, double g0,
                                   double g1, double floor, double centre = 0.0) {
  DiscreteGradient out;
  const double dg = g1 - g0;
  // the quotient's rounding is ~1e-16 g/|dg| of the force: past 1e-6 of the gap, 1e-10; below it
  // the midpoint's force, within (dg/g)² ~ 1e-12 of the quotient
  if (std::abs(dg) >
      1e-6 * std::max(std::max(std::abs(g0 - centre), std::abs(g1 - centre)), floor)) {
    const double e0 = start_energy();
    const LineForce e1 = elastic(g1);
    out.force = (e1.energy - e0) / dg;
    out.slope = (e1.force - out.force) / dg;
  } else {
    const LineForce m = elastic(0.5 * (g0 + g1));
    out.force = m.force;
    out.slope = 0.5 * m.stiffness;
  }
  return out;
}
template <class Law>
DiscreteGradient discrete_gradient(const Law& elastic, double g0, double g1, double floor = 0.0) {
  return discrete_gradient(
      elastic, [&] { return elastic(g0).energy; }, g0, g1, floor);
}

// A contact's damper over the step from the gap g0 to g1 (the discrete gradient's; docs
// "Sprockets: the discrete gradient", "The damper over the step"): f_d = (C(g₁) − C(g₀))/h,
// C(g) = ∫₀^g c(s) ds the integral of the ramped coefficient c(g) = c_c min(1, g/ε) (0 for g ≤ 0),
// c_c (g₁ − g₀)/h once both ends are past ε, and ∂f_d/∂g₁ = c(g₁)/h. The slope is never
// negative, and the work −f_d Δg = −c̄ Δg²/h is never positive (c̄ the mean of c over [g₀, g₁]).
// The θ point's c(g_θ) ġ_θ falls as the roller goes deeper while it leaves (∂f/∂g = c_c ġ/ε < 0
// within the ramp), which can fold the step's residual along n. A seat's and a rail's.
struct StepDamper {
  double force = 0.0, slope = 0.0;
};
// the damper from the start's integral c0 = C(g₀) (a caller's memo of the step's start) to g1
StepDamper step_damper_from(double cc, double eps, double c0, double g1, double h) {
  return {(detail::damper_integral(cc, eps, g1) - c0) / h, cc * std::clamp(g1 / eps, 0.0, 1.0) / h};
}
StepDamper step_damper(double cc, double eps, double g0, double g1, double h) {
  return step_damper_from(cc, eps, detail::damper_integral(cc, eps, g0), g1, h);
}
}  // namespace

namespace {
// link_force's energy, the elastic force and its slope as a law for discrete_gradient
LineForce link_elastic(const Model& model, double s, std::size_t link) {
  const LinkForce f = link_force(model, s, 0.0, link);
  return LineForce{f.elastic, f.stiffness, f.energy};
}
}  // namespace

LinkForce link_jam_force(const Model& model, double s, double rate, std::size_t link) {
  const double k = model.axial_stiffness, c = model.axial_damping, eps = model.link_smoothing;
  LinkForce out;
  // the jam (validated below the tension's ramp): w = s_j − s, how far the joints are inside
  // l_jam, and v = w + ε/2 its ramp's depth
  const double w = (model.jam_length(link) - model.rest_length(link)) - s, v = w + 0.5 * eps;
  if (!(v > 0.0)) return out;  // slack: between the jam and the tension's ramp
  const bool ramp = v < eps;
  out.elastic = ramp ? -k * v * v / (2.0 * eps) : -k * w;
  out.energy = ramp ? k * v * v * v / (6.0 * eps) : 0.5 * k * w * w + k * eps * eps / 24.0;
  const double r = ramp ? v / eps : 1.0;
  const double tension = out.elastic + c * r * rate;
  if (!(tension < 0.0)) return out;  // lengthening faster than the jam pushes: free
  out.tension = tension;
  out.stiffness = ramp ? k * v / eps - c * rate / eps : k;
  out.damping = c * r;
  return out;
}

LinkStep link_step_force(const Model& model, double s0, double s1, double h, std::size_t link) {
  return link_step_force(model, s0, s1, h, link, link_step_start(model, s0, link));
}

LinkStep link_step_force(const Model& model, double s0, double s1, double h, std::size_t link,
                         const LinkStart& start) {
  if (model.bilateral(link)) {
    // the quotient of ½ k s² is k (s₀ + s₁)/2 (exactly, but for rounding), its slope ½ k; the
    // damper c (s₁ − s₀)/h: the bilateral link's θ = ½ force, never clamped
    const double k = model.axial_stiffness, c = model.axial_damping;
    LinkStep out;
    out.elastic = 0.5 * k * (s0 + s1);
    out.tension = out.elastic + c * (s1 - s0) / h;
    out.slope = 0.5 * k + c / h;
    return out;
  }
  const double eps = model.link_smoothing;
  const double jam = model.jam_length(link);
  const double sj = jam > 0.0 ? jam - model.rest_length(link) : 0.0;  // s_j, the jam's stretch
  // The spring: the quotient of link_force's own energy (the one energy() reports), with the
  // threshold's scale at least ε. Beyond the ramp E is quadratic and the mean stretch's T_e is the
  // quotient exactly; within it E''' = k/ε and the mean's force misses the quotient by
  // k Δs²/24ε ≤ 4e-14 k ε at |Δs| ≤ 1e-6 ε (across a ramp's end, where E''' jumps, by no more),
  // a work of < 1e-19 k ε² a step; the quotient's rounding, ~2e-16 E/|Δs|, stays below ~1e-10
  // of k max(ε, |s|) past the threshold. Near the jam the same holds with |s − s_j| (its ramp is
  // centred there): the scale is measured from the nearer ramp's centre.
  const DiscreteGradient spring =
      discrete_gradient([&](double s) { return link_elastic(model, s, link); },
                        [&] { return start.energy; }, s0, s1, eps, s0 + s1 < sj ? sj : 0.0);
  // the damper over the step: C(u) = ∫₀^u c min(1, v/ε) dv, the seats' (its work never positive)
  const double u0 = s0 + 0.5 * eps, u1 = s1 + 0.5 * eps;
  StepDamper damper = step_damper_from(model.axial_damping, eps, start.damper, u1, h);
  // the jam's, the mirror image's: its tension −(C(v₁) − C(v₀))/h with v = s_j − s + ε/2 (v falls
  // as s grows: its work is never positive either), ∂/∂s₁ = +c min(1, v₁/ε)/h
  bool pushes = false;
  if (jam > 0.0) {
    const double v0 = sj - s0 + 0.5 * eps, v1 = sj - s1 + 0.5 * eps;
    const StepDamper d = step_damper_from(model.axial_damping, eps, start.jam_damper, v1, h);
    damper.force -= d.force;
    damper.slope += d.slope;
    pushes = v0 > 0.0 || v1 > 0.0;
  }
  LinkStep out;
  out.elastic = spring.force;
  const double tension = spring.force + damper.force;
  // It pulls only on a step that touches the tension's ramp (shortening faster than the spring
  // pulls: slack; without a jam T > 0 needs that), pushes only on one that touches the jam's
  // (lengthening faster than it pushes: free). Where clamped the damper's share −T_dg does the
  // work T_dg (s₁ − s₀) ≤ 0: T_dg ≥ 0 and s₁ < s₀, or T_dg ≤ 0 and s₁ > s₀.
  const bool pulls = u0 > 0.0 || u1 > 0.0;
  if (!((tension > 0.0 && pulls) || (tension < 0.0 && pushes))) return out;
  out.tension = tension;
  out.slope = spring.slope + damper.slope;
  return out;
}

GuideSpot guide_spot(const Guide& g, const GuideFrame& frame, double x, double y) {
  GuideSpot out;
  out.between = between_rail_ends(g, frame, x, y, out.along);
  double nx = 0.0, ny = 0.0;
  out.gap = rail_gap(g, frame, x, y, nx, ny);
  return out;
}

GuideContact guide_contact(const Guide& gd, const GuideFrame& frame, double x, double y, double vx,
                           double vy, double anchor) {
  return guide_contact(gd, frame, x, y, vx, vy, anchor, nullptr);
}

GuideContact guide_contact(const Guide& gd, const GuideFrame& frame, double x, double y, double vx,
                           double vy, double anchor, const GuideStep* step) {
  GuideContact c;
  const double r = gd.roller_radius;
  double along = 0.0;
  if (!between_rail_ends(gd, frame, x, y, along)) return c;
  double nx = 0.0, ny = 0.0, kappa = 0.0;
  const double g = rail_gap(gd, frame, x, y, nx, ny, &kappa);
  // One-sided: a roller whose centre is past the rail's surface is on its far side, not pressed
  // into it (so a rail does not catch the chain's other run behind it).
  if (!(g < 2.0 * r)) return c;
  // the discrete gradient over the step: the gaps at its ends, ∂g₁/∂x₁ = −n₁; the damper over the
  // step too (step_damper, as the seats')
  const bool gradient = step != nullptr && gd.discrete_gradient;
  double g1 = 0.0, n1x = 0.0, n1y = 0.0, dg = 0.0;
  // On an arc the gap is ±(R ± r − ρ), ρ = |q − C|: a function of ρ alone, so the discrete
  // gradient is the links' (Simo–Tarnow): the normal force f acts along ν = s (q_θ − C)/ρ̄,
  // ρ̄ = (ρ₀ + ρ₁)/2, s = ±1 as n = s (q − C)/|q − C| (docs "Guides: the discrete gradient", "On an
  // arc"). At θ = ½, q_θ − C = (r₀ + r₁)/2 and ν·(x₁ − x₀) = s (ρ₁² − ρ₀²)/(ρ₀ + ρ₁) = −Δg exactly:
  // f's work is −f Δg, the elastic part's −ΔE (to the gaps' rounding, ~1e-16 ρ each: f_e stays the
  // secant of the rounded gaps, smooth however small Δg). `bend` = s/ρ̄ (∂ν/∂q_θ = bend I); 0 on a
  // straight rail (ν = n).
  bool radial = gradient && gd.kind != Guide::Kind::kStraight;
  double bend = 0.0;
  DiscreteGradient dgr;
  StepDamper damper;
  if (gradient) {
    double n0x = 0.0, n0y = 0.0;
    const double g0 = rail_gap(gd, frame, step->x0, step->y0, n0x, n0y);
    g1 = rail_gap(gd, frame, step->x1, step->y1, n1x, n1y);
    if (!(std::max(g0, g1) > 0.0)) return c;
    if (radial) {
      const double r0x = step->x0 - gd.centre_x, r0y = step->y0 - gd.centre_y;
      const double r1x = step->x1 - gd.centre_x, r1y = step->y1 - gd.centre_y;
      // ρ₀ + ρ₁ > 0 where the θ point lies on the segment x₀x₁ (the integrator's), being off the
      // centre (tested above); a step with both ends at the centre keeps n
      const double rho = std::sqrt(r0x * r0x + r0y * r0y) + std::sqrt(r1x * r1x + r1y * r1y);
      radial = rho > 0.0;
      bend = radial ? 2.0 * (gd.inside ? -1.0 : 1.0) / rho : 0.0;
    }
    dgr = discrete_gradient([&](double gap) { return rail_elastic(gd, gap); }, g0, g1);
    damper = step_damper(gd.contact_damping, gd.contact_smoothing, g0, g1, step->h);
    dg = g1 - g0;
  } else if (!(g > 0.0)) {
    return c;
  }
  // ν, the normal force's direction: n, or on an arc with the discrete gradient s (q_θ − C)/ρ̄
  // (|ν| = |q_θ − C|/ρ̄, within ~(Δx/ρ)²/8 of 1)
  const double ux = radial ? bend * (x - gd.centre_x) : nx;
  const double uy = radial ? bend * (y - gd.centre_y) : ny;
  const double tx = -ny, ty = nx;
  const double vn = vx * nx + vy * ny, vt = vx * tx + vy * ty;
  const double rate = -vn;  // ġ
  const double eps = gd.contact_smoothing;
  // the normal force's elastic part: the line law (as the seats') or the penalty with its ramp,
  // at the θ point or the discrete gradient over the step
  const LineForce lf = rail_elastic(gd, g);
  const double elastic = gradient ? dgr.force : lf.force;
  const double slope = gradient ? 0.0 : lf.stiffness;  // ∂f_e/∂q at the θ point
  // the θ point's damper (without the discrete gradient) ramps in over the first ε, none at g ≤ 0;
  // with it, nothing at the θ point: the damper is the step's, a function of g₀ and g₁ alone
  const double cg = gradient ? 0.0 : gd.contact_damping * std::clamp(g / eps, 0.0, 1.0);
  const double dcg = !gradient && g > 0.0 && g < eps ? gd.contact_damping / eps : 0.0;
  c.active = true;
  c.penetration = g;
  c.nx = nx;
  c.ny = ny;
  c.slip = vt;
  const bool stick = gd.stick_stiffness > 0.0 && std::isfinite(anchor);
  GuidePlace place;
  if (stick) {
    place = guide_place(gd, frame, x, y);
    c.position = place.s;
    c.position_scale = place.sigma;
  }
  c.energy = lf.energy;
  const double f = gradient ? elastic + damper.force : elastic + cg * rate;
  // the damper's power: −(f − f_e) ġ, over the step −f_d Δg/h (the work −c̄ Δg²/h ≤ 0); separating
  // (f ≤ 0: no force) the damper cancels the elastic part, f_e ġ (f_e Δg/h: the clamp needs
  // f_d < 0, so Δg < 0)
  if (!(f > 0.0)) {
    c.damping_power = gradient ? elastic * dg / step->h : elastic * rate;
    return c;
  }
  c.damping_power = gradient ? -damper.force * dg / step->h : -cg * rate * rate;
  // f and its gradients (∂g/∂q = −n, ∂ġ/∂q = −κ v_t tᵀ, ∂ġ/∂v = −nᵀ)
  const double fg = slope + dcg * rate;
  const double dfq[2] = {-fg * nx - cg * kappa * vt * tx, -fg * ny - cg * kappa * vt * ty};
  // the discrete gradient's dependence on x₁ = x₀ + h v: h ∂f/∂x₁ = −h (∂f_e/∂g₁ + ∂f_d/∂g₁) n₁
  const double dgv = gradient ? step->h * (dgr.slope + damper.slope) : 0.0;
  const double dfv[2] = {-cg * nx - dgv * n1x, -cg * ny - dgv * n1y};
  // the friction f_t and its gradients, by the stick law or the regularised one
  double ft = 0.0, dftq[2] = {0.0, 0.0}, dftv[2] = {0.0, 0.0};
  if (stick) {
    // the stick law: the spring's energy ½ k_t (s − a)² and the damper's dissipation ½ c_t ṡ²
    // (Guide::stick_damping, ṡ = ∂s/∂q · v) give the force −(k_t (s − a) + c_t ṡ) ∂s/∂q, with
    // ∂s/∂q = σ t (σ = 1 on a straight rail, ρ_c/|q − C| on an arc; guide_place): f_t = σ p,
    // p = −k_t (s − a) − c_t ṡ, while that is within ±μ f, else μ f against it (sliding). Its
    // gradient σ ∂p/∂q + p ∂σ/∂q, with t turning with the roller on an arc (the −f_t κ n tᵀ term
    // below), makes ∂F/∂q = −k_t ∂s/∂q ∂s/∂qᵀ + p ∂²s/∂q² − c_t ∂s/∂q (∂²s/∂q² v)ᵀ.
    const double mu = gd.friction, kt = gd.stick_stiffness, ct = gd.stick_damping;
    const double d = stick_stretch(gd, c.position, anchor);
    const bool arc = gd.kind != Guide::Kind::kStraight;  // σ ≠ 1: straight rails kept bit for bit
    double p = -kt * d;
    const double sdot = ct > 0.0 ? place.dsx * vx + place.dsy * vy : 0.0;
    if (ct > 0.0) p -= ct * sdot;
    ft = arc ? place.sigma * p : p;
    if (std::abs(ft) <= mu * f) {
      c.sticking = true;
      dftq[0] = -kt * place.dsx;
      dftq[1] = -kt * place.dsy;
      if (ct > 0.0) {
        dftq[0] -= ct * (place.hxx * vx + place.hxy * vy);
        dftq[1] -= ct * (place.hxy * vx + place.hyy * vy);
        dftv[0] = -ct * place.dsx;
        dftv[1] = -ct * place.dsy;
      }
      if (arc) {
        for (int j = 0; j < 2; ++j) {
          dftq[j] *= place.sigma;
          dftv[j] *= place.sigma;
        }
        dftq[0] += p * place.dsigx;
        dftq[1] += p * place.dsigy;
      }
    } else {
      const double sgn = ft < 0.0 ? 1.0 : -1.0;  // against the spring and damper (d > 0: ft < 0)
      ft = -mu * f * sgn;
      dftq[0] = -mu * sgn * dfq[0];
      dftq[1] = -mu * sgn * dfq[1];
      dftv[0] = -mu * sgn * dfv[0];
      dftv[1] = -mu * sgn * dfv[1];
    }
  } else {
    // friction −μ f φ(v_t), φ = v_t/√(v_t² + v_ε²); ∂v_t/∂q = −κ v_n tᵀ (t turns with n on an arc)
    const double ve2 = gd.friction_band * gd.friction_band;
    const double root = std::sqrt(vt * vt + ve2);
    const double phi = vt / root, dphi = ve2 / (root * root * root);
    const double mu = gd.friction;
    ft = -mu * f * phi;
    dftq[0] = -mu * phi * dfq[0] + mu * f * dphi * kappa * vn * tx;
    dftq[1] = -mu * phi * dfq[1] + mu * f * dphi * kappa * vn * ty;
    dftv[0] = -mu * phi * dfv[0] - mu * f * dphi * tx;
    dftv[1] = -mu * phi * dfv[1] - mu * f * dphi * ty;
  }
  c.normal_force = f;
  c.friction_force = ft;
  c.fx = f * ux + ft * tx;
  c.fy = f * uy + ft * ty;
  // ∂F/∂q = ν ⊗ ∂f/∂q + f ∂ν/∂q + t ⊗ ∂f_t/∂q − f_t κ n tᵀ (∂t/∂q = −κ n tᵀ; κ = 0 straight),
  // ∂F/∂v = ν ⊗ w + t ⊗ ∂f_t/∂v. Along n (ν = n): ∂n/∂q = κ t tᵀ and w = ∂f/∂v. On an arc with
  // the discrete gradient (`radial`): ∂ν/∂q_θ = bend I (∂f/∂q is 0 there: the step's f depends on
  // x₁ alone), and ∂ν/∂x₁ = −(bend/2) ν ⊗ n₁ (through ρ₁ in ρ̄) besides
  // ∂f/∂x₁ = −(∂f_e/∂g₁ + ∂f_d/∂g₁) n₁ (dfv/h): w = dfv − h f (bend/2) n₁
  const double u[2] = {ux, uy}, t[2] = {tx, ty}, n[2] = {nx, ny};
  const double half = radial ? 0.5 * step->h * f * bend : 0.0;
  const double w[2] = {radial ? dfv[0] - half * n1x : dfv[0],
                       radial ? dfv[1] - half * n1y : dfv[1]};
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      const double turn = radial ? (i == j ? f * bend : 0.0) : f * kappa * t[i] * t[j];
      c.dq[2 * i + j] = u[i] * dfq[j] + turn + t[i] * dftq[j] - ft * kappa * n[i] * t[j];
      c.dv[2 * i + j] = u[i] * w[j] + t[i] * dftv[j];
    }
  }
  return c;
}

Sprocket iso606_sprocket(double pitch, double roller_diameter, double inner_width, int teeth,
                         double centre_x, double centre_y, double contact_stiffness,
                         double contact_damping) {
  const drive::Sprocket iso = drive::sprocket({.pitch = pitch,
                                               .roller_diameter = roller_diameter,
                                               .inner_width = inner_width,
                                               .teeth = teeth});
  Sprocket s;
  s.centre_x = centre_x;
  s.centre_y = centre_y;
  s.teeth = teeth;
  s.pitch_radius = 0.5 * iso.pitch_diameter;
  s.seat_radius = iso.min_gap.seating_radius;
  s.seating_angle = iso.min_gap.seating_angle;
  s.tip_radius = 0.5 * iso.tip_diameter_max;
  s.flank_radius = iso.min_gap.flank_radius;
  s.roller_radius = 0.5 * roller_diameter;
  s.contact_stiffness = contact_stiffness;
  s.contact_damping = contact_damping;
  s.tip_radius = articulation_tip_radius(s);
  return s;
}

double articulation_interference(const Sprocket& w) {
  constexpr double kPi = std::numbers::pi;
  constexpr int kSamples = 2000;
  // the wheel at angle π/2 about the origin: seat 0 at the top, C0 = (0, R); its clockwise
  // neighbour's centre lies at the chord from C0, at −π/z from +x
  const double R = w.pitch_radius, step = kPi / w.teeth, chord = 2.0 * R * std::sin(step);
  double worst = 0.0;
  for (int k = 0; k <= kSamples; ++k) {
    const double beta = -step + 0.5 * kPi * k / kSamples;
    Sprocket probe = w;
    probe.centre_x = 0.0;
    probe.centre_y = 0.0;
    const SeatContact c = seat_contact(probe, chord * std::cos(beta), R + chord * std::sin(beta),
                                       0.0, 0.0, 0.5 * kPi, 0.0);
    worst = std::max(worst, c.active ? c.penetration : 0.0);
  }
  return worst;
}

double articulation_tip_radius(const Sprocket& w) {
  if (w.tip_radius <= 0.0 || articulation_interference(w) <= 0.0) return w.tip_radius;
  Sprocket probe = w;
  double lo = w.pitch_radius, hi = w.tip_radius;
  probe.tip_radius = lo;  // a tooth cut at the pitch circle; if even it is in the way, no cure
  if (articulation_interference(probe) > 0.0) return w.tip_radius;
  while (hi - lo > 1e-9) {
    probe.tip_radius = 0.5 * (lo + hi);
    (articulation_interference(probe) <= 0.0 ? lo : hi) = probe.tip_radius;
  }
  // 1 µm below the sampled limit: between the path's samples the corner may stand proud by
  // nanometres (never below the pitch circle, which was found clear)
  return std::max(lo - 1e-6, w.pitch_radius);
}

State two_sprocket_loop(int teeth, int span, double pitch, double pitch_radius, double omega) {
  constexpr double kPi = std::numbers::pi;
  const int z = teeth, m = span;
  const double r = pitch_radius, v = omega * r, centre = m * pitch;
  State s(static_cast<std::size_t>(z + 2 * m), 2);
  std::size_t i = 0;
  auto put = [&](double x, double y, double vx, double vy) {
    s.x[i] = x;
    s.y[i] = y;
    s.vx[i] = vx;
    s.vy[i] = vy;
    ++i;
  };
  for (int k = 0; k <= z / 2; ++k) {
    const double t = kPi / 2 + 2 * kPi * k / z;
    put(r * std::cos(t), r * std::sin(t), -v * std::sin(t), v * std::cos(t));
  }
  for (int j = 1; j < m; ++j) put(j * pitch, -r, v, 0.0);
  for (int k = 0; k <= z / 2; ++k) {
    const double t = -kPi / 2 + 2 * kPi * k / z;
    put(centre + r * std::cos(t), r * std::sin(t), -v * std::sin(t), v * std::cos(t));
  }
  for (int j = 1; j < m; ++j) put(centre - j * pitch, r, -v, 0.0);
  s.angle = {kPi / 2, -kPi / 2};
  s.speed = {omega, omega};
  return s;
}

std::array<std::size_t, 2> span_middle_links(const State& state, double centre_distance) {
  const std::size_t n = state.nodes();
  std::array<std::size_t, 2> link{0, 0};
  std::array<double, 2> gap{INFINITY, INFINITY};
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t e = (j + 1) % n;
    const double xm = 0.5 * (state.x[j] + state.x[e]), ym = 0.5 * (state.y[j] + state.y[e]);
    const double g = std::abs(xm - 0.5 * centre_distance);
    if (ym == 0.0) continue;
    const std::size_t k = ym > 0.0 ? 0 : 1;
    if (g < gap[k]) gap[k] = g, link[k] = j;
  }
  return link;
}

contact::RollerTooth seat_line_contact(const Sprocket& w, double width) {
  contact::RollerTooth c;
  c.roller_diameter = 2.0 * w.roller_radius;
  c.roller_length = width;
  c.tooth_radius = w.seat_radius;
  c.profile = contact::Profile::kConcave;
  return c;
}

LineLaw make_line_law(const contact::LineApproach& law, double width) {
  LineLaw l;
  l.law = law;
  l.width = width;
  const double q_cap = law.cap_load();
  l.cap_depth = law.approach(q_cap);
  l.cap_force = width * q_cap;
  l.cap_stiffness = width / law.slope(q_cap);
  l.cap_energy = width * law.energy(q_cap);
  return l;
}

LineForce line_force(const LineLaw& l, double g) {
  LineForce f;
  if (!(g > 0.0)) return f;
  const double b1 = l.width, g_cap = l.cap_depth;
  if (g < g_cap) {
    const double q = l.law.load(g);
    f.force = b1 * q;
    f.stiffness = b1 / l.law.slope(q);  // → 0 at first touch (dδ/dq grows as −A ln q)
    f.energy = b1 * l.law.energy(q);
    return f;
  }
  // beyond the cap: the tangent at it (C¹), its energy the trapezoid added to the cap's
  const double k = l.cap_stiffness, s = g - g_cap, f_cap = l.cap_force;
  f.force = f_cap + k * s;
  f.stiffness = k;
  f.energy = l.cap_energy + f_cap * s + 0.5 * k * s * s;
  return f;
}

void use_line_law(Sprocket& w, double width) {
  w.line_law = true;
  w.line = make_line_law(contact::line_approach(seat_line_contact(w, width)), width);
}

void use_line_law(Guide& g, double width) {
  // the reduced radius: the roller r on a flat (ρ = r), outside an arc of radius R (convex on
  // convex, 1/ρ = 1/r + 1/R) or inside it (convex in concave, 1/ρ = 1/r − 1/R)
  const double r = g.roller_radius;
  double rho = r;
  if (g.kind == Guide::Kind::kArc) rho = 1.0 / (1.0 / r + (g.inside ? -1.0 : 1.0) / g.radius);
  g.line_law = true;
  g.line = make_line_law(contact::line_approach(Elastic{}, g.rail, rho, r), width);
  g.discrete_gradient = true;  // the law's default ("Guides: the discrete gradient")
}

void apply_seat_law(const Sprocket& w, double g, double rx, double ry, double vx, double vy,
                    double speed, SeatContact& c) {
  // rate of penetration: the roller's velocity relative to the wheel's material point under it
  const double rate = (vx + speed * ry) * c.nx + (vy - speed * rx) * c.ny;
  const double eps = w.contact_smoothing, kc = w.contact_stiffness;
  const LineForce lf = w.line_law ? line_force(w.line, g) : detail::penalty_ramp(kc, eps, g);
  const double elastic = lf.force;
  c.stiffness = lf.stiffness;
  c.energy = lf.energy;
  c.damping = w.contact_damping * std::min(1.0, g / eps);
  c.force = std::max(0.0, elastic + c.damping * rate);
  // ∂f/∂g: the elastic slope, and the damping's ramp over the first ε
  if (g < eps) c.stiffness += w.contact_damping * rate / eps;
  if (c.force <= 0.0) c.stiffness = c.damping = 0.0;
  // the contact's power on roller and wheel together is −f ġ (the torque's share included);
  // the part of the damper, f − f_el, is the dissipation
  c.damping_power = -(c.force - elastic) * rate;
  c.active = true;
  c.penetration = c.depth = g;
  // the reaction +f n acts on the wheel along the line through the roller centre q
  c.torque = c.force * (rx * c.ny - ry * c.nx);
}

double nearest_seat(double rx, double ry, double angle, double tau) {
  // The index is an integer: it only needs the arctangent to the distance of x = (φ − angle)/τ
  // from the nearest half-integer. φ̃, within kAtanError of std::atan2 on its branch (its sign
  // is ry's, as atan2's), gives x̃ within margin of the x the exact formula computes (the two
  // differ by the arctangents' difference and the roundings of φ − angle, ≤ ulp(|angle| + π),
  // and of the division); where x̃ is farther than that from a half-integer both round to the
  // same k. Nearer (a roller half-way between two seats: rare), and outside the ranges the
  // bound is made for, the exact formula.
  auto exact = [&] { return std::nearbyint((std::atan2(ry, rx) - angle) / tau); };
  const double ax = std::abs(rx), ay = std::abs(ry);
  const double hi = std::max(ax, ay), lo = std::min(ax, ay);
  if (!std::isfinite(rx) || !std::isfinite(ry) || !(hi > 0.0) || !(std::abs(angle) <= 1e6) ||
      !(tau > 1e-6)) {
    return exact();
  }
  // atan(t), t = lo/hi in [0, 1]: reduced to |u| ≤ tan(π/8) by atan t = π/4 + atan((t − 1)/(t + 1))
  // above tan(π/8), then atan u = u P(u²), P fitted by least squares on Chebyshev nodes (its
  // largest error over [0, tan π/8] 3.7e-9 rad, checked on a grid of 2e5 points; the test
  // checks the index against the exact formula over random and half-way rollers).
  constexpr double kAtanError = 1e-8;  // [rad] the bound the margin assumes (2.7× the fit's)
  constexpr double kTanPi8 = 0.41421356237309503;
  constexpr double kPi = std::numbers::pi;
  const double t = lo / hi;
  double u = t, base = 0.0;
  if (t > kTanPi8) {
    u = (t - 1.0) / (t + 1.0);
    base = 0.25 * kPi;
  }
  const double s = u * u;
  const double poly =
      0.9999999030331808 +
      s * (-0.33332184256159203 +
           s * (0.19961549347071814 + s * (-0.13751575773224817 + s * 0.07726173868201999)));
  double phi = base + u * poly;        // atan(lo/hi) in [0, π/4]
  if (ay > ax) phi = 0.5 * kPi - phi;  // atan(ay/ax) in [0, π/2]
  if (rx < 0.0) phi = kPi - phi;       // in [0, π]
  phi = std::copysign(phi, ry);  // atan2's branch: (−π, π], −π for ry = −0 and rx < 0
  const double x = (phi - angle) / tau;
  const double k = std::nearbyint(x);
  // |x − x̃| ≤ (kAtanError + 2 ulp(|angle| + 4))/τ + 2 ulp(|x|), bounded generously
  const double margin = 2.0 * kAtanError / tau + 16.0 * DBL_EPSILON * (std::abs(x) + 1.0);
  if (std::abs(x - k) < 0.5 - margin) return k;
  return exact();
}

SeatGeometry seat_geometry(const Sprocket& w) {
  SeatGeometry t;
  t.reach = contact_reach(w);
  const double tau = 2.0 * std::numbers::pi / w.teeth;
  t.tau = tau;
  t.sector_tan = std::tan(0.5 * tau) * (1.0 - 1e-9);
  const double half = 0.5 * w.seating_angle;
  const double ch = std::cos(half), sh_abs = std::sin(half);
  t.ch = ch;
  t.sh = sh_abs;
  const double R = w.pitch_radius, Ra = w.tip_radius, re = w.flank_radius, ri = w.seat_radius;
  const double fa = (ri + re) * ch, fb = (ri + re) * sh_abs;  // F (re > 0)
  t.fa = fa;
  t.fb = fb;
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
  t.has_corner = has_corner;
  t.tip_arc = tip_arc;
  t.ka = ka;
  t.kb = kb;
  return t;
}

SeatContact seat_contact(const Sprocket& w, double x, double y, double vx, double vy, double angle,
                         double speed) {
  return seat_contact(w, seat_geometry(w), x, y, vx, vy, angle, speed);
}

SeatContact seat_contact(const Sprocket& w, const SeatGeometry& t, double x, double y, double vx,
                         double vy, double angle, double speed) {
  const double rx = x - w.centre_x, ry = y - w.centre_y;
  if (rx * rx + ry * ry > t.reach * t.reach) return {};  // clear of the wheel
  // The nearest seat from the roller's angle about the centre: O(1), no search.
  const double k = nearest_seat(rx, ry, angle, t.tau);
  const double sigma = angle + k * t.tau;
  return seat_contact_at(w, t, x, y, vx, vy, speed, k, std::cos(sigma), std::sin(sigma));
}

namespace {
// The gap g of a roller centred at (x, y) in the seat of a wheel centred at (cx, cy) whose
// direction is (cs, sn) = (cos σ, sin σ): seat_contact_at's surfaces (the seating arc, a flank,
// the tooth's corner, the tip's arc), continuous across them, ∂g/∂q = n. The normal n, the
// curvature κ (∂n/∂q = κ t tᵀ) and the surface with it; `normal` false where n is undefined (the
// roller's centre on the arc's, the flank's or the tip's centre or on the corner), g still set.
struct SeatGap {
  bool normal = false;
  double g = 0.0, nx = 0.0, ny = 0.0, curvature = 0.0;
  int surface = 0;
};
SeatGap seat_gap(const Sprocket& w, const SeatGeometry& t, double x, double y, double cx, double cy,
                 double cs, double sn) {
  SeatGap out;
  const double ex = x - (cx + w.pitch_radius * cs), ey = y - (cy + w.pitch_radius * sn);
  // The tooth gap about the seat centre C: the seating arc of radius ri over the seating angle α
  // about the inward radial, and beyond its ends the flanks, taken as the straight lines tangent
  // to the arc there (the ISO flank arc re is several pitches: nearly straight over a roller).
  // γ is the angle of e = q − C from the inward radial, towards the tangent t = (−sin σ, cos σ).
  const double e_in = -(ex * cs + ey * sn), e_t = -ex * sn + ey * cs;
  const double ch = t.ch, sh_abs = t.sh;
  const double r = w.roller_radius, ri = w.seat_radius;
  double g = 0.0;
  // |γ| ≤ α/2 with γ = atan2(e_t, e_in) and α/2 < π/2, without the atan2: e lies within α/2 of
  // the inward radial iff |e_t| cos(α/2) ≤ e_in sin(α/2) with e_in ≥ 0 (γ = 0 at e = 0).
  if (e_in >= 0.0 && std::abs(e_t) * ch <= e_in * sh_abs) {
    const double dist = std::sqrt(ex * ex + ey * ey);
    if (!(dist > 0.0)) {
      out.g = r - ri;
      return out;
    }
    g = dist + r - ri;
    out.nx = ex / dist;
    out.ny = ey / dist;
    out.curvature = 1.0 / dist;
    out.surface = 0;
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
    const double fa = t.fa, fb = t.fb;  // F (re > 0)
    // depth of q inside the flank's surface (> 0 inside the tooth)
    double depth_flank = 0.0, fdist = 0.0;
    if (re > 0.0) {
      fdist = std::hypot(a - fa, b - fb);
      depth_flank = re - fdist;
    } else {
      depth_flank = a * ch + b * sh_abs - ri;  // (q − C)·m − ri
    }
    // The flank ends at the tooth's corner K (seat_geometry): where it meets the tip circle, or
    // at the two flanks' apex below it.
    const bool has_corner = t.has_corner, tip_arc = t.tip_arc;
    const double ka = t.ka, kb = t.kb;
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
      if (!(fdist > 0.0)) {
        out.g = r + depth_flank;
        return out;
      }
      world((fa - a) / fdist, (fb - b) / fdist, out.nx, out.ny);  // n = (F − q)/|F − q|
      g = r + depth_flank;
      out.curvature = -1.0 / fdist;
      out.surface = 1;
    } else if (where == kFlank) {
      world(ch, sh_abs, out.nx, out.ny);
      g = ex * out.nx + ey * out.ny + r -
          ri;  // depth_flank + r, as the form without a tip wrote it
      out.curvature = 0.0;
      out.surface = 1;
    } else if (where == kTip) {
      if (!(rho > 0.0)) {
        out.g = r + depth_tip;
        return out;
      }
      world(-oa / rho, -ob / rho, out.nx, out.ny);  // n = −(q − O)/|q − O|
      g = r + depth_tip;
      out.curvature = -1.0 / rho;
      out.surface = 3;
    } else {
      const double da = ka - a, db = kb - b;  // K − q
      const double dist = std::sqrt(da * da + db * db);
      if (!(dist > 0.0)) {
        out.g = r;
        return out;
      }
      world(da / dist, db / dist, out.nx, out.ny);
      g = r - dist;
      out.curvature = -1.0 / dist;
      out.surface = 2;
    }
  }
  out.g = g;
  out.normal = true;
  return out;
}

// seat_gap in the nearest seat of a wheel turned to `angle`, counted from the θ point's seat k:
// seat k (σ = angle + k τ, as the θ point's, bit for bit) while (x, y) lies within k's mid-tooth
// lines (SeatGeometry::sector_tan, no arctangent), else k + m, m = nearest_seat's index less k
// reduced to within half a turn (an angle past ±π gives the same seat's index a turn apart). The
// reduction is not needed for the seat (k + m and k + m ± z are the same one); it keeps seat k's
// own (cos σ, sin σ), bit for bit, for a point within the sector test's 1e-9 margin inside k's
// line whose index comes back as k ± z (m = 0, not σ ± 2π with its rounding). Past a
// mid-tooth line the θ point's seat's surfaces are not the wheel's (a roller in the next seat read
// in them is millimetres deep in the tooth); on the line the two seats' gaps are equal (the tooth
// is symmetric about it), so the gap taken in each point's nearest seat is continuous.
SeatGap seat_gap_nearest(const Sprocket& w, const SeatGeometry& t, double x, double y, double cx,
                         double cy, double angle, double k) {
  double sigma = angle + k * t.tau;
  double cs = std::cos(sigma), sn = std::sin(sigma);
  const double ex = x - cx, ey = y - cy;
  if (!(std::abs(ex * sn - ey * cs) <= t.sector_tan * (ex * cs + ey * sn))) {
    const double z = static_cast<double>(w.teeth);
    double m = nearest_seat(ex, ey, angle, t.tau) - k;
    m -= z * std::nearbyint(m / z);
    if (m != 0.0) {
      sigma = angle + (k + m) * t.tau;
      cs = std::cos(sigma);
      sn = std::sin(sigma);
    }
  }
  return seat_gap(w, t, x, y, cx, cy, cs, sn);
}

// The step's start for the θ point's seat k from the memo `m`, taken afresh there unless it holds
// this start (x₀, its centre, ψ₀) and seat: g₀ in its own nearest seat and C(g₀); E(g₀) is left
// for the quotient to take when it reads it (energy_set). The start does not move within a step,
// so the integrator's Newton iterations take it once a step, unless the θ point's seat changes.
SeatStart& step_start(const Sprocket& w, const SeatGeometry& t, const SeatStep& step, double k,
                      SeatStart& m) {
  using detail::same_bits;
  if (m.set && same_bits(m.seat, k) && same_bits(m.x0, step.x0) && same_bits(m.y0, step.y0) &&
      same_bits(m.cx0, step.cx0) && same_bits(m.cy0, step.cy0) && same_bits(m.angle0, step.angle0))
    return m;
  const double g0 = seat_gap_nearest(w, t, step.x0, step.y0, step.cx0, step.cy0, step.angle0, k).g;
  m = SeatStart{.set = true,
                .x0 = step.x0,
                .y0 = step.y0,
                .cx0 = step.cx0,
                .cy0 = step.cy0,
                .angle0 = step.angle0,
                .seat = k,
                .gap = g0,
                .damper = detail::damper_integral(w.contact_damping, w.contact_smoothing, g0)};
  return m;
}
}  // namespace

SeatContact seat_contact_at(const Sprocket& w, const SeatGeometry& t, double x, double y, double vx,
                            double vy, double speed, double k, double cs, double sn) {
  return seat_contact_at(w, t, x, y, vx, vy, speed, k, cs, sn, nullptr);
}

SeatContact seat_contact_at(const Sprocket& w, const SeatGeometry& t, double x, double y, double vx,
                            double vy, double speed, double k, double cs, double sn,
                            const SeatStep* step) {
  SeatContact c;
  const double rx = x - w.centre_x, ry = y - w.centre_y;
  c.seat = static_cast<int>(k);
  c.seat_x = w.centre_x + w.pitch_radius * cs;
  c.seat_y = w.centre_y + w.pitch_radius * sn;
  const SeatGap at = seat_gap(w, t, x, y, w.centre_x, w.centre_y, cs, sn);
  if (!at.normal) return c;
  c.nx = at.nx;
  c.ny = at.ny;
  c.curvature = at.curvature;
  c.surface = at.surface;
  const double g = at.g;
  if (step == nullptr || !w.discrete_gradient) {
    if (!(g > 0.0)) return c;
    apply_seat_law(w, g, rx, ry, vx, vy, speed, c);
    return c;
  }
  // the discrete gradient over the step: the gaps at its ends, each in its own nearest seat (the
  // θ point's k unless the end is past one of k's mid-tooth lines)
  // (the start, which does not move within a step, from the caller's memo when it holds this
  // start and seat: step_start)
  SeatStart own;  // without the caller's memo, this call's
  SeatStart& start = step_start(w, t, *step, k, step->start != nullptr ? *step->start : own);
  const SeatGap end =
      seat_gap_nearest(w, t, step->x1, step->y1, step->cx1, step->cy1, step->angle1, k);
  // active where either end is in contact: the elastic part and the damper both come from the
  // ends' gaps, so on a convex surface (a tooth's tip) a θ point inside with both ends clear
  // carries no force, and it is not a contact (no depth into max_penetration)
  if (!(std::max(start.gap, end.g) > 0.0)) return c;
  auto law = [&](double gap) { return seat_elastic(w, gap); };
  const DiscreteGradient dgr = discrete_gradient(
      law,
      [&] {
        if (!start.energy_set) {
          start.energy = law(start.gap).energy;
          start.energy_set = true;
        }
        return start.energy;
      },
      start.gap, end.g, 0.0);
  // The damper over the step too (step_damper): at θ = ½ the θ point's damper made the rollers
  // rattling across their seats (|ġ| ≈ 0.16 m/s) fold the residual along n, hθ c_c|ġ|/ε beyond
  // m/(hθ) + c_c + h ∂f_e/∂g₁, and Newton stalled at g_θ = ε.
  const double h = step->h, dg = end.g - start.gap;
  const double elastic = dgr.force;
  const StepDamper damper =
      step_damper_from(w.contact_damping, w.contact_smoothing, start.damper, end.g, h);
  c.force = std::max(0.0, elastic + damper.force);
  c.damping = c.stiffness = 0.0;  // nothing at the θ point: f depends on g₁ alone
  c.gap_slope = c.force > 0.0 ? dgr.slope + damper.slope : 0.0;
  // the damper's share f − f_e (−f_e where clamped) against the step's Δg: its work −(f − f_e) Δg
  c.damping_power = -(c.force - elastic) * dg / h;
  c.energy = seat_elastic(w, g).energy;  // the θ point's, as without the gradient
  c.active = true;
  c.penetration = c.depth = g;
  c.torque = c.force * (rx * c.ny - ry * c.nx);
  // ∂g₁/∂x₁ = n₁, ∂g₁/∂ψ₁ = −n₁·perp(x₁ − c₁) (the gap is unchanged turning x₁ and ψ₁ together)
  c.step_nx = end.nx;
  c.step_ny = end.ny;
  c.step_turn = end.nx * (step->y1 - step->cy1) - end.ny * (step->x1 - step->cx1);
  // The θ point's gradient ∇g_θ = (n, −a), a = n·perp(ρ_θ), predicts the gap's change over the
  // step as lin = n·Δ − a Δψ (Δ the roller's displacement relative to the centre); on a curved
  // surface or a turning wheel Δg differs. The rest goes along the step z = (Δ, R Δψ):
  // ∇̄g = ∇g_θ + cc (Δ, R² Δψ), cc = (Δg − lin)/(|Δ|² + R² Δψ²), so that ∇̄g·Δz = Δg and the
  // normal force's work is exactly −f Δg (−ΔE and the damper's −f_d Δg). The roller gains −S Δ,
  // the wheel −S R² Δψ, S = f cc.
  const double r2 = w.pitch_radius * w.pitch_radius;
  const double dx = (step->x1 - step->cx1) - (step->x0 - step->cx0);
  const double dy = (step->y1 - step->cy1) - (step->y0 - step->cy0);
  const double dpsi = step->turn;
  const double px = -ry, py = rx;  // perp ρ_θ
  const double arm = c.nx * px + c.ny * py;
  const double lin = c.nx * dx + c.ny * dy - arm * dpsi;
  const double den = dx * dx + dy * dy + r2 * dpsi * dpsi;
  // S = f cc with f the clamped total force: it goes to 0 with f where the damper clamps it, so the
  // residual is continuous there. Skipped for a step |Δz| < 1e-9 R: Δg − lin is then the gaps'
  // rounding (~1e-17 m at R ≈ 5 cm; the curvature's share κ|Δz|²/2 ≤ 2e-17 m on the seating arc
  // of ri − r ≈ 60 µm), S = f cc grows as 1/den from it (1.9e14 N/m at |Δz| = 1e-15 m) and the
  // work it would restore, f (Δg − lin), is the rounding's.
  const double den_floor = 1e-18 * r2;
  if (c.force > 0.0 && den > den_floor) {
    const double cc = (end.g - start.gap - lin) / den;
    c.skew = c.force * cc;
    c.skew_x = dx;
    c.skew_y = dy;
    c.torque -= c.skew * r2 * dpsi;
  }
  if (!step->jacobian) return c;  // the residual alone: no derivatives
  if (c.force > 0.0 && den > den_floor) {
    const double cc = (end.g - start.gap - lin) / den;
    // ∂n/∂q = κ t tᵀ, ∂n/∂ψ = (1 − κ t·perp ρ) t, ∂a/∂q = (κ t·perp ρ − 1) t,
    // ∂a/∂ψ = (t·perp ρ)(1 − κ t·perp ρ); the θ point moves by θ with x₁ and ψ₁
    const double th = step->theta, kap = c.curvature;
    const double tx = -c.ny, ty = c.nx;
    const double tp = tx * px + ty * py, td = tx * dx + ty * dy;
    const double lt = th * (kap * td - dpsi * (kap * tp - 1.0));
    const double dlin_x = c.nx + lt * tx, dlin_y = c.ny + lt * ty;
    const double dlin_psi = th * (1.0 - kap * tp) * (td - dpsi * tp) - arm;
    // ∂cc = (∂(Δg − lin) − cc ∂den)/den, ∂Δg/∂x₁ = n₁, ∂Δg/∂ψ₁ = step_turn
    const double dcc_x = (end.nx - dlin_x - 2.0 * cc * dx) / den;
    const double dcc_y = (end.ny - dlin_y - 2.0 * cc * dy) / den;
    const double dcc_psi = (c.step_turn - dlin_psi - 2.0 * cc * r2 * dpsi) / den;
    // ∂S = cc ∂f + f ∂cc, ∂f = (∂f/∂g₁) ∂g₁
    c.skew_dx = cc * c.gap_slope * end.nx + c.force * dcc_x;
    c.skew_dy = cc * c.gap_slope * end.ny + c.force * dcc_y;
    c.skew_dpsi = cc * c.gap_slope * c.step_turn + c.force * dcc_psi;
  }
  // the friction's share: ∂(−f n)/∂x₁ = −(∂f/∂g₁) n n₁ᵀ, in ∂/∂v as h times it (v = (x₁ − x₀)/h)
  const double hs = h * c.gap_slope;
  c.friction_dv[0] = -hs * c.nx * end.nx;
  c.friction_dv[1] = -hs * c.nx * end.ny;
  c.friction_dv[2] = -hs * c.ny * end.nx;
  c.friction_dv[3] = -hs * c.ny * end.ny;
  return c;
}

SeatFriction seat_friction(const Sprocket& w, const SeatContact& c, double x, double y, double vx,
                           double vy, double speed) {
  SeatFriction out;
  if (!c.active || !(c.force > 0.0) || !(w.friction > 0.0)) return out;
  const double rx = x - w.centre_x, ry = y - w.centre_y;  // ρ = q − c
  const double nx = c.nx, ny = c.ny, tx = -ny, ty = nx, kappa = c.curvature;
  // the velocity relative to the wheel's material point at q: v − ω perp(ρ)
  const double wx = vx + speed * ry, wy = vy - speed * rx;
  const double vn = wx * nx + wy * ny, vt = wx * tx + wy * ty;
  // f = f_el(g) + c(g) ġ: ∂g/∂q = nᵀ, ∂ġ/∂q = (ω + κ v_t) tᵀ, ∂ġ/∂v = nᵀ
  // (∂n/∂q = κ t tᵀ, ∂t/∂q = −κ n tᵀ, ∂(v − ω perp ρ)/∂q = −ω perp)
  const double f = c.force, fg = c.stiffness, cg = c.damping;
  double dfq[2] = {fg * nx + cg * (speed + kappa * vt) * tx,
                   fg * ny + cg * (speed + kappa * vt) * ty};
  double dfv[2] = {cg * nx, cg * ny};
  // ∂v_t/∂q = −ω nᵀ − κ v_n tᵀ, ∂v_t/∂v = tᵀ
  double dvtq[2] = {-speed * nx - kappa * vn * tx, -speed * ny - kappa * vn * ty};
  double dvtv[2] = {tx, ty};
  // A pocket's mouth ramp or release: the normal force N = −f n has the exact Jacobians the
  // fields give plus X = friction_dq (friction_dv for v). With ∂f = −nᵀ ∂N, ∂n = −t tᵀ ∂N/f and
  // ∂t = n tᵀ ∂N/f, X adds −nᵀ X to ∂f, v_n tᵀ X/f to ∂v_t and f_t n tᵀ X/f to ∂F (below).
  const double* xq = c.friction_dq;
  const double* xv = c.friction_dv;
  const bool rest = xq[0] != 0.0 || xq[1] != 0.0 || xq[2] != 0.0 || xq[3] != 0.0 || xv[0] != 0.0 ||
                    xv[1] != 0.0 || xv[2] != 0.0 || xv[3] != 0.0;
  double tq[2] = {0.0, 0.0}, tv[2] = {0.0, 0.0};  // tᵀ X/f
  if (rest) {
    for (int j = 0; j < 2; ++j) {
      tq[j] = (tx * xq[j] + ty * xq[2 + j]) / f;
      tv[j] = (tx * xv[j] + ty * xv[2 + j]) / f;
      dfq[j] -= nx * xq[j] + ny * xq[2 + j];
      dfv[j] -= nx * xv[j] + ny * xv[2 + j];
      dvtq[j] += vn * tq[j];
      dvtv[j] += vn * tv[j];
    }
  }
  const double ve2 = w.friction_band * w.friction_band;
  const double root = std::sqrt(vt * vt + ve2);
  const double phi = vt / root, dphi = ve2 / (root * root * root);
  const double mu = w.friction;
  double ft = -mu * f * phi;
  double dftq[2] = {-mu * (phi * dfq[0] + f * dphi * dvtq[0]),
                    -mu * (phi * dfq[1] + f * dphi * dvtq[1])};
  double dftv[2] = {-mu * (phi * dfv[0] + f * dphi * dvtv[0]),
                    -mu * (phi * dfv[1] + f * dphi * dvtv[1])};
  // A pocket wheel's body between the pockets: the pocket's friction faded, P f_t, whose
  // ∂/∂q = P ∂f_t/∂q + f_t ∇P (P depends on q alone, and on ψ only as q does relative to the
  // wheel: the turning derivatives below hold as they are)
  const double pw = c.friction_weight, *dpw = c.friction_weight_dq;
  if (pw != 1.0 || dpw[0] != 0.0 || dpw[1] != 0.0) {
    for (int j = 0; j < 2; ++j) {
      dftq[j] = pw * dftq[j] + ft * dpw[j];
      dftv[j] *= pw;
    }
    ft *= pw;
  }
  out.friction_force = ft;
  out.slip = vt;
  out.power = ft * vt;
  out.fx = ft * tx;
  out.fy = ft * ty;
  // ∂F/∂q = t ⊗ ∂f_t/∂q − f_t κ n tᵀ, ∂F/∂v = t ⊗ ∂f_t/∂v
  out.dq[0] = tx * dftq[0] - ft * kappa * nx * tx;
  out.dq[1] = tx * dftq[1] - ft * kappa * nx * ty;
  out.dq[2] = ty * dftq[0] - ft * kappa * ny * tx;
  out.dq[3] = ty * dftq[1] - ft * kappa * ny * ty;
  out.dv[0] = tx * dftv[0];
  out.dv[1] = tx * dftv[1];
  out.dv[2] = ty * dftv[0];
  out.dv[3] = ty * dftv[1];
  if (rest) {  // F = f_t t: f_t ∂t = f_t n tᵀ X/f
    const double n[2] = {nx, ny};
    for (int i = 0; i < 2; ++i) {
      for (int j = 0; j < 2; ++j) {
        out.dq[2 * i + j] += ft * n[i] * tq[j];
        out.dv[2 * i + j] += ft * n[i] * tv[j];
      }
    }
  }
  // The contact turns with the wheel: F(ψ + a, q, v) = Rot(a) F(ψ, c + Rot(−a) ρ, Rot(−a) v),
  // so ∂F/∂ψ = perp F − ∂F/∂q perp ρ − ∂F/∂v perp v; v enters only through v − ω perp ρ, so
  // ∂F/∂ω = −∂F/∂v perp ρ. The torque (a scalar) is invariant: ∂τ/∂ψ = −∂τ/∂q perp ρ − ∂τ/∂v perp
  // v.
  const double px = -ry, py = rx;    // perp ρ
  const double pvx = -vy, pvy = vx;  // perp v
  out.domega[0] = -(out.dv[0] * px + out.dv[1] * py);
  out.domega[1] = -(out.dv[2] * px + out.dv[3] * py);
  out.dpsi[0] = -out.fy - (out.dq[0] * px + out.dq[1] * py) - (out.dv[0] * pvx + out.dv[1] * pvy);
  out.dpsi[1] = out.fx - (out.dq[2] * px + out.dq[3] * py) - (out.dv[2] * pvx + out.dv[3] * pvy);
  // τ = ρ × (−F) = ρ_y F_x − ρ_x F_y
  out.torque = ry * out.fx - rx * out.fy;
  out.torque_dq[0] = -out.fy + ry * out.dq[0] - rx * out.dq[2];
  out.torque_dq[1] = out.fx + ry * out.dq[1] - rx * out.dq[3];
  out.torque_dv[0] = ry * out.dv[0] - rx * out.dv[2];
  out.torque_dv[1] = ry * out.dv[1] - rx * out.dv[3];
  out.torque_domega = -(out.torque_dv[0] * px + out.torque_dv[1] * py);
  out.torque_dpsi = -(out.torque_dq[0] * px + out.torque_dq[1] * py) -
                    (out.torque_dv[0] * pvx + out.torque_dv[1] * pvy);
  return out;
}

Model uniform_chain(std::size_t nodes, bool closed, double pitch, double node_mass,
                    double axial_stiffness, double axial_damping, bool pin_ends) {
  Model m;
  m.closed = closed;
  m.pitch = pitch;
  m.axial_stiffness = axial_stiffness;
  m.axial_damping = axial_damping;
  m.mass.assign(nodes, node_mass);
  if (pin_ends && !closed && nodes >= 2) {
    m.pinned.assign(nodes, 0);
    m.pinned.front() = 1;
    m.pinned.back() = 1;
  }
  return m;
}

std::vector<Issue> validate(const Model& model, const State& state) {
  std::vector<Issue> out;
  const std::size_t n = model.nodes();
  if (state.x.size() != n || state.y.size() != n || state.vx.size() != n || state.vy.size() != n) {
    out.push_back({"state.x", std::to_string(state.x.size()) + " nodes",
                   "x, y, vx, vy of " + std::to_string(n) + " nodes each"});
    return out;
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(state.x[i]) || !std::isfinite(state.y[i])) {
      out.push_back({"state.x[" + std::to_string(i) + "]", "not finite", "finite positions"});
      break;
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(state.vx[i]) || !std::isfinite(state.vy[i])) {
      out.push_back({"state.v[" + std::to_string(i) + "]", "not finite", "finite velocities"});
      break;
    }
    if (model.is_pinned(i) && (state.vx[i] != 0.0 || state.vy[i] != 0.0)) {
      out.push_back(
          {"state.v[" + std::to_string(i) + "]", "moving", "zero velocity at a pinned node"});
      break;
    }
  }
  if (state.slide.size() != model.sprockets.size() ||
      state.slide_speed.size() != model.sprockets.size()) {
    out.push_back(
        {"state.slide", std::to_string(state.slide.size()) + " values",
         "slide and slide_speed of " + std::to_string(model.sprockets.size()) + " sprockets each"});
  } else {
    for (std::size_t w = 0; w < model.sprockets.size(); ++w) {
      if (!std::isfinite(state.slide[w]) || !std::isfinite(state.slide_speed[w]) ||
          (!model.sprockets[w].takeup && (state.slide[w] != 0.0 || state.slide_speed[w] != 0.0))) {
        out.push_back({"state.slide[" + std::to_string(w) + "]", "not finite or not 0",
                       "finite, and 0 on a wheel without a take-up"});
        break;
      }
    }
  }
  for (std::size_t j = 0; j < model.links() && n >= 2; ++j) {
    const std::size_t b = (j + 1) % n;
    if (!(std::hypot(state.x[b] - state.x[j], state.y[b] - state.y[j]) > 0.0)) {
      out.push_back({"state.link[" + std::to_string(j) + "]", "length 0",
                     "nodes of a link at distinct positions"});
      break;
    }
  }
  return out;
}

Energy energy(const Model& model, const State& state) {
  EnergyScratch scratch;
  return energy(model, state, scratch);
}

Energy energy(const Model& model, const State& state, EnergyScratch& scratch) {
  Energy e;
  const std::size_t n = model.nodes();
  // the conveyed load's mass (Guide::load_inertia) moves with its node: its kinetic energy
  std::vector<GuideFrame> frames;
  if (any_load_inertia(model.guides))
    for (const Guide& g : model.guides) frames.push_back(guide_frame(g));
  for (std::size_t i = 0; i < n; ++i) {
    const double m = model.mass[i] +
                     (frames.empty() ? 0.0 : load_mass(model, frames, state.x[i], state.y[i]).mass);
    e.kinetic += 0.5 * m * (state.vx[i] * state.vx[i] + state.vy[i] * state.vy[i]);
    e.potential -= model.mass[i] * (model.gravity_x * state.x[i] + model.gravity_y * state.y[i]);
  }
  for (const NodeLoad& f : model.loads) {
    if (f.node < n) e.potential -= f.fx * state.x[f.node] + f.fy * state.y[f.node];
  }
  // The wheels' contacts: each wheel against the nodes GuideHint lists inside the box of its
  // reach, in node order — the active pairs and their order are the loop over every node's
  // (bit-identical), in O(N + W + pairs) instead of O(N·W). An ISO seat is active only within
  // |q − O| ≤ reach (seat_contact's first test), so inside the box O ± reach, here padded by 1e-6
  // of the reach (and 1e-12 of the centre's coordinates) against the roundings of that test and
  // of the box's bounds; a pocket wheel's held joints may be beyond its reach, so its box is
  // unbounded (every node listed), as the integrator tries every node.
  const std::size_t wheels = std::min(model.sprockets.size(), state.speed.size());
  const auto slides_of = [&](std::size_t w) {
    return model.sprockets[w].takeup && w < state.slide.size() && w < state.slide_speed.size();
  };
  GuideHint& near_wheel = scratch.wheels;
  if (wheels > 0) {
    std::vector<GuideBounds>& boxes = scratch.boxes;
    boxes.resize(wheels);
    for (std::size_t w = 0; w < wheels; ++w) {
      const Sprocket wheel = at_slide(model.sprockets[w], slides_of(w) ? state.slide[w] : 0.0);
      const double reach = contact_reach(wheel);
      const double r = wheel.pocket
                           ? INFINITY
                           : reach + 1e-6 * reach +
                                 1e-12 * (std::abs(wheel.centre_x) + std::abs(wheel.centre_y));
      boxes[w] = {wheel.centre_x - r, wheel.centre_x + r, wheel.centre_y - r, wheel.centre_y + r};
    }
    near_wheel.update(std::span<const GuideBounds>(boxes),
                      std::span<const double>(state.x.data(), n),
                      std::span<const double>(state.y.data(), n));
  }
  for (std::size_t w = 0; w < wheels; ++w) {
    const bool slides = slides_of(w);
    const Sprocket wheel = at_slide(model.sprockets[w], slides ? state.slide[w] : 0.0);
    if (!wheel.driver) e.kinetic += 0.5 * wheel.inertia * state.speed[w] * state.speed[w];
    if (slides) {
      const double sl = state.slide[w], v = state.slide_speed[w];
      e.kinetic += 0.5 * wheel.takeup_mass * v * v;
      e.elastic += 0.5 * wheel.takeup_stiffness * sl * sl;
      const double g_along = model.gravity_x * wheel.takeup_dx + model.gravity_y * wheel.takeup_dy;
      e.potential -= (wheel.takeup_force + wheel.takeup_mass * g_along) * sl;
      e.elastic += slide_stop(model.sprockets[w], sl, 0.0).energy;  // an end stop pressed
    }
    for (const std::uint32_t i : near_wheel.nodes(w)) {
      const SeatContact c = wheel_contact(wheel, state.x[i], state.y[i], 0.0, 0.0, state.angle[w],
                                          0.0, held_pocket(state, i, w));
      if (c.active) e.elastic += c.energy;
    }
  }
  // the guides' contacts: each guide against the nodes GuideHint lists inside its box, in node
  // order (the active pairs and their order are the loop over every node's: bit-identical), in
  // O(N + G + pairs)
  if (!model.guides.empty()) {
    GuideHint& hint = scratch.guides;
    hint.update(model.guides, std::span<const double>(state.x.data(), n),
                std::span<const double>(state.y.data(), n));
    for (std::size_t g = 0; g < model.guides.size(); ++g) {
      const Guide& guide = model.guides[g];
      for (const std::uint32_t i : hint.nodes(g)) {
        const GuideContact c = guide_contact(guide, state.x[i], state.y[i], 0.0, 0.0);
        if (c.active) e.elastic += c.energy;
      }
    }
  }
  // the guides' stick springs ½ k_t (s − a)² about their anchors (Guide::stick_stiffness; the
  // sticking guides' anchors in their order, State::stick_anchor)
  std::size_t slot = 0, sticking = 0;
  for (const Guide& guide : model.guides) sticking += guide.stick_stiffness > 0.0 ? 1 : 0;
  for (const Guide& guide : model.guides) {
    if (!(guide.stick_stiffness > 0.0)) continue;
    if (state.stick_anchor.size() != sticking * n) break;  // not sized yet: none in contact
    const GuideFrame frame = guide_frame(guide);
    for (std::size_t i = 0; i < n; ++i) {
      const double a = state.stick_anchor[slot * n + i];
      if (!std::isfinite(a)) continue;
      const double d =
          stick_stretch(guide, guide_position(guide, frame, state.x[i], state.y[i]), a);
      e.elastic += 0.5 * guide.stick_stiffness * d * d;
    }
    ++slot;
  }
  for (std::size_t j = 0; j < model.links(); ++j) {
    const std::size_t b = (j + 1) % n;
    const double stretch =
        std::hypot(state.x[b] - state.x[j], state.y[b] - state.y[j]) - model.rest_length(j);
    e.elastic += link_force(model, stretch, 0.0, j).energy;
  }
  // the hinges' stick springs ½ k_t d² (HingeFriction::stick_stiffness; State::hinge_deflection,
  // empty until a step sizes it: every hinge then anchored where it is)
  if (model.hinge.sticks() && state.hinge_deflection.size() == n) {
    for (const double d : state.hinge_deflection)
      e.elastic += 0.5 * model.hinge.stick_stiffness * d * d;
  }
  return e;
}

// flatten: link_force inlined here (out of line, as GCC left it once the law read the links'
// parity flag, it cost the 12B example 0.25 % of its instructions: docs "The flat links")
[[gnu::flatten]] void link_tensions(const Model& model, const State& state,
                                    std::span<double> tension) {
  const std::size_t n = model.nodes();
  for (std::size_t j = 0; j < model.links() && j < tension.size(); ++j) {
    const std::size_t b = (j + 1) % n;
    const double dx = state.x[b] - state.x[j], dy = state.y[b] - state.y[j];
    const double l = std::hypot(dx, dy);
    const double rate = (dx * (state.vx[b] - state.vx[j]) + dy * (state.vy[b] - state.vy[j])) / l;
    tension[j] = link_force(model, l - model.rest_length(j), rate, j).tension;
  }
}

}  // namespace catena::dynamics
