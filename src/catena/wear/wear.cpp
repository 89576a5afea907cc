// Hinge wear and elongation life (docs/models/wear.md).
#include "catena/wear/wear.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "catena/core/progress.hpp"
#include "catena/engagement/engagement.hpp"
#include "catena/hinge/kinematics.hpp"
#include "catena/hinge/synthesis.hpp"

namespace catena::wear {
namespace {

using S = Diagnostic::Severity;
constexpr double kPi = std::numbers::pi;

std::string num(double v) { return check::format_si(v, ""); }

// R2 of the rolling hinge: given, or eq. (6) of the hinge model; nothing when eq. (6) has none.
std::optional<double> face_radius(const hinge::Hinge& h) {
  if (h.roller_radius > 0.0) return h.roller_radius;
  return hinge::r2_eq6(h.pin_diameter, h.half_thickness, h.plate_radius, hinge::gamma_max(h));
}

hinge::Hinge rolling_geometry(const Input& in) {
  hinge::Hinge h = in.geometry;
  h.face = hinge::Face::kConcave;
  h.teeth = in.teeth;
  h.strokes = in.strokes;
  return h;
}

// The sliding hinge: criteria (24)/(25) of the engagement model on the worn neck say over which
// part of the mutual turn the pivot turns against the tooth; there the sliding moves from link
// 1's bores to link 2's bores and the tooth.
void articulate_sliding(const Input& in, const Worn& worn, Articulation& a) {
  engagement::SlidingInput si;
  si.tension = in.tension;
  si.teeth = in.teeth;
  si.strokes = in.strokes;
  si.flank_angle = in.flank_angle;
  si.friction = in.friction;
  si.tooth_friction = in.tooth_friction;
  const double d1 = in.journal_diameter - 2.0 * worn.roller;
  si.journal_diameter = d1;
  si.tooth_diameter = in.tooth_diameter;
  si.points = std::max(in.samples, 2);
  const engagement::Result r = engagement::solve_sliding(si);
  double turned = 0.0;
  for (const engagement::Range& g : r.roller_turns) turned += g.to - g.from;
  turned = std::clamp(turned, 0.0, a.mutual_turn);
  a.turned = turned;
  const double radius = 0.5 * d1;
  a.slide_link1 = radius * (a.mutual_turn - turned);
  a.slide_link2 = radius * turned;
  a.slide_tooth = 0.5 * in.tooth_diameter * turned;
  // A pivot that turns at all indexes round in its bores pass after pass: its wear spreads over
  // the neck's circumference (π·d1·L) instead of the projected bearing area (d1·L).
  a.neck_spread = turned > 0.0 ? 1.0 / kPi : 1.0;
  a.slide_pivot_plate = a.slide_link1 + a.slide_link2;
  a.band = d1;
  const double area = d1 * in.contact_length;
  const double k = in.wear_coefficient, f = in.tension;
  // Each interface carries F; the bore's contact stays where the load points, so its depth is
  // V/(d1·L) (the nominal pressure F/(d1·L) times k·s/H).
  a.plate_depth = archard_volume(k, f, a.slide_pivot_plate, in.plate_hardness) / area;
  a.roller_depth =
      archard_volume(k, f, a.slide_pivot_plate, in.roller_hardness) / area * a.neck_spread;
  for (const Diagnostic& d : r.diagnostics) a.diagnostics.push_back(d);
}

// The rolling hinge: each plate turns θ = Δφ/2 against the pivot (eq. 3); it rolls up to the
// rolling limit of eq. (21) and slides beyond it (or rolls throughout when guided); the rolled
// part carries Carter micro-slip at the traction ratio tan ψ1 / f (the force angle of eq. 20 is
// ψ1, docs/models/hinge.md).
void articulate_rolling(const Input& in, const Worn& worn, Articulation& a) {
  hinge::Hinge h = rolling_geometry(in);
  const std::optional<double> r2_new = face_radius(h);
  const double r1 = h.plate_radius - worn.plate;
  const double r2 = *r2_new + worn.roller;
  h.plate_radius = r1;
  h.roller_radius = r2;
  const double theta = 0.5 * a.mutual_turn;
  a.plate_turn = theta;
  a.rolling_limit = hinge::rolling_limit(in.friction, r1, r2);
  const bool guided = in.limit == RollingLimit::kGuided;
  a.rolled_turn = guided ? theta : std::min(theta, a.rolling_limit);
  a.gross_slide = guided ? 0.0 : r1 * std::max(0.0, theta - a.rolling_limit);
  const double e_star = contact_modulus(in.plate_elastic, in.roller_elastic);
  const double r_star = conformal_radius(r1, r2);
  const LineContact lc = line_contact(in.tension / in.contact_length, r_star, e_star);
  a.half_width = lc.half_width;
  // Micro-slip: ∫ creep dl over the contact's travel l = R1·ψ1 on the plate arc, ψ1 from the
  // hinge model's pose at the mutual turn φ = 2θ'.
  const int n = std::max(in.samples, 3);
  double slip = 0.0, psi_prev = 0.0, creep_prev = 0.0;
  for (int i = 0; i <= n - 1; ++i) {
    const double t = a.rolled_turn * static_cast<double>(i) / static_cast<double>(n - 1);
    const double psi1 = hinge::pose(h, r2, 2.0 * t).psi1;
    double creep = 0.0;
    if (in.creep == Creep::kCarter) {
      const double ratio = std::min(std::tan(std::fabs(psi1)) / in.friction, 1.0);
      creep = carter_creep(in.friction, lc.half_width, r_star, ratio);
    }
    if (i > 0) slip += 0.5 * (creep + creep_prev) * r1 * std::fabs(psi1 - psi_prev);
    psi_prev = psi1;
    creep_prev = creep;
  }
  a.micro_slip = slip;
  a.rolled_arc = r1 * std::fabs(psi_prev);
  a.band = a.rolled_arc + 2.0 * lc.half_width;
  const double per_interface = a.gross_slide + a.micro_slip;
  a.slide_pivot_plate = 2.0 * per_interface;
  const double area = a.band * in.contact_length;
  const double k = in.wear_coefficient, f = in.tension;
  a.plate_depth = 2.0 * archard_volume(k, f, per_interface, in.plate_hardness) / area;
  a.roller_depth = 2.0 * archard_volume(k, f, per_interface, in.roller_hardness) / area;
  if (!guided && theta > a.rolling_limit) {
    a.diagnostics.push_back(
        {S::kWarning, "wear.slides_beyond_rolling_limit",
         "friction alone keeps the hinge rolling up to a plate turn of " +
             check::format_si(a.rolling_limit * 180.0 / kPi, "deg") +
             " (eq. 21) but each plate turns " + check::format_si(theta * 180.0 / kPi, "deg") +
             " per articulation: the rest slides (rolling_limit = guided: the aperture keeps it "
             "rolling)",
         theta, a.rolling_limit});
  }
}

}  // namespace

double archard_volume(double k, double force, double sliding, double hardness) {
  return k * force * sliding / hardness;
}

double carter_creep(double friction, double half_width, double radius, double traction_ratio) {
  const double q = std::clamp(traction_ratio, 0.0, 1.0);
  return friction * half_width / radius * (1.0 - std::sqrt(1.0 - q));
}

std::vector<Issue> validate(const Input& in) {
  std::vector<Issue> out;
  check::finite_positive(out, "pitch", in.pitch, "m");
  if (in.teeth < 3) out.push_back({"teeth", std::to_string(in.teeth), "a whole number z >= 3"});
  if (in.strokes < 1 || 2 * in.strokes >= std::max(in.teeth, 3))
    out.push_back({"strokes", std::to_string(in.strokes), "a whole number 1 <= m < z/2"});
  if (in.articulations < 1)
    out.push_back({"articulations", std::to_string(in.articulations), "a whole number >= 1"});
  if (in.tensions.empty()) {
    check::finite_positive(out, "tension", in.tension, "N");
  } else {
    bool loaded = false;
    for (double f : in.tensions) {
      if (!(f >= 0.0) || !std::isfinite(f))
        out.push_back({"tension", check::format_si(f, "N"), "tensions >= 0 N"});
      loaded = loaded || f > 0.0;
    }
    if (!loaded) out.push_back({"tension", "0 N", "at least one articulation under tension > 0"});
    if (in.tensions.size() != static_cast<std::size_t>(std::max(in.articulations, 0)))
      out.push_back({"tension", std::to_string(in.tensions.size()) + " values",
                     "one tension, or one per articulation (articulations = " +
                         std::to_string(in.articulations) + ")"});
  }
  check::finite_positive(out, "speed", in.speed, "m/s");
  check::finite_positive(out, "loop_length", in.loop_length, "m");
  if (!(in.wear_coefficient > 0.0) || !(in.wear_coefficient < 1.0))
    out.push_back({"wear_coefficient", num(in.wear_coefficient), "an Archard k in (0, 1)"});
  check::finite_positive(out, "plate_hardness", in.plate_hardness, "Pa");
  check::finite_positive(out, "roller_hardness", in.roller_hardness, "Pa");
  check::finite_positive(out, "contact_length", in.contact_length, "m");
  if (!(in.friction > 0.0) || !(in.friction < 1.0))
    out.push_back({"friction", num(in.friction), "a friction factor f in (0, 1)"});
  for (double l : in.limits) {
    if (!(l > 0.0) || !(l < 0.5))
      out.push_back({"limits", num(l * 100.0), "elongation limits in (0, 50) percent"});
  }
  if (in.limits.empty()) out.push_back({"limits", "(none)", "at least one elongation limit"});
  if (!(in.block_passes >= 0.0) || !std::isfinite(in.block_passes))
    out.push_back({"block_passes", num(in.block_passes), "passes per block >= 0 (0: automatic)"});
  if (in.samples < 3 || in.samples > 100000)
    out.push_back({"samples", std::to_string(in.samples), "a whole number in [3, 100000]"});
  if (in.hinge == HingeKind::kSliding) {
    check::finite_positive(out, "journal_diameter", in.journal_diameter, "m");
    check::finite_positive(out, "tooth_diameter", in.tooth_diameter, "m");
    if (!std::isfinite(in.tooth_friction))
      out.push_back({"tooth_friction", num(in.tooth_friction), "a friction factor >= 0"});
    if (!std::isfinite(in.flank_angle) || !(std::fabs(in.flank_angle) < 0.5 * kPi))
      out.push_back({"flank_angle", num(in.flank_angle), "|psi| < 90 deg"});
  } else {
    const hinge::Hinge h = rolling_geometry(in);
    std::vector<Issue> found = hinge::validate(h);
    for (Issue& i : found) {
      if (i.field != "teeth" && i.field != "strokes") out.push_back(std::move(i));
    }
    if (found.empty() && !face_radius(h))
      out.push_back({"plate_radius", check::format_si(h.plate_radius, "m"),
                     "R1 <= R1max so that eq. (6) gives R2, or a given roller_radius"});
  }
  return out;
}

Articulation articulate(const Input& in, const Worn& worn) {
  throw_if_any(validate(in));
  Articulation a;
  a.mutual_turn = engagement::gamma_sigma(in.teeth, in.strokes);
  if (in.hinge == HingeKind::kSliding) {
    articulate_sliding(in, worn, a);
  } else {
    articulate_rolling(in, worn, a);
  }
  return a;
}

namespace {

// One pass: every articulation under its own tension, slides and depths summed; the angles, band
// and half-width of the first loaded articulation.
Articulation whole_pass(const Input& in, const Worn& worn) {
  Articulation sum;
  bool first = true;
  const int n = in.articulations;
  for (int i = 0; i < n; ++i) {
    Input x = in;
    x.tensions.clear();
    x.tension = in.tensions.empty() ? in.tension : in.tensions[static_cast<std::size_t>(i)];
    if (!(x.tension > 0.0)) continue;  // a slack articulation carries no load: no wear
    const Articulation a = articulate(x, worn);
    if (first) {
      sum = a;
      first = false;
      continue;
    }
    sum.slide_link1 += a.slide_link1;
    sum.slide_link2 += a.slide_link2;
    sum.slide_tooth += a.slide_tooth;
    sum.gross_slide += a.gross_slide;
    sum.micro_slip += a.micro_slip;
    sum.slide_pivot_plate += a.slide_pivot_plate;
    sum.roller_depth += a.roller_depth;
    sum.plate_depth += a.plate_depth;
  }
  return sum;
}

}  // namespace

Result run(const Input& input) {
  throw_if_any(validate(input));
  Input in = input;
  std::sort(in.limits.begin(), in.limits.end());
  Result res;
  res.mutual_turn = engagement::gamma_sigma(in.teeth, in.strokes);
  res.passes_per_hour = in.speed * 3600.0 / in.loop_length;
  Worn worn;
  res.pass = whole_pass(in, worn);
  res.first = res.pass;  // the first loaded articulation's angles; its slides are the pass's
  if (in.tensions.empty()) {
    res.first = articulate(in, worn);
  } else {
    Input x = in;
    x.tensions.clear();
    x.tension = *std::max_element(in.tensions.begin(), in.tensions.end());
    res.first = articulate(x, worn);
  }
  res.diagnostics = res.pass.diagnostics;
  const double rate0 = (res.pass.roller_depth + res.pass.plate_depth) / in.pitch;
  res.series.push_back({});
  res.life_hours.assign(in.limits.size(), std::nullopt);
  if (!(rate0 > 0.0)) {
    res.diagnostics.push_back({S::kInfo, "wear.no_sliding",
                               "no pivot-plate sliding per articulation: no wear, the chain does "
                               "not elongate and no retirement limit is reached",
                               0.0, 0.0});
    res.at_end = res.series.back();
    return res;
  }
  const double last = in.limits.back();
  res.block_passes = in.block_passes > 0.0 ? in.block_passes : std::max(1.0, last / rate0 / 400.0);
  constexpr int kMaxBlocks = 200000;
  Point p;
  int blocks = 0;
  // progress: how far the elongation has come towards the last limit, in thousandths
  constexpr std::size_t kPermille = 1000;
  ProgressLoop loop(kPermille, "‰ of the last limit");
  while (p.elongation < last && blocks < kMaxBlocks) {
    loop.step(static_cast<std::size_t>(std::clamp(p.elongation / last, 0.0, 1.0) * kPermille));
    // Re-solve the articulation on the worn geometry, then extrapolate over the block.
    const Articulation a = blocks == 0 ? res.pass : whole_pass(in, worn);
    Point next = p;
    next.roller += a.roller_depth * res.block_passes;
    next.plate += a.plate_depth * res.block_passes;
    next.elongation = (next.roller + next.plate) / in.pitch;
    next.hours += res.block_passes / res.passes_per_hour;
    for (std::size_t j = 0; j < in.limits.size(); ++j) {
      if (!res.life_hours[j] && next.elongation >= in.limits[j]) {
        const double frac = (in.limits[j] - p.elongation) / (next.elongation - p.elongation);
        res.life_hours[j] = p.hours + frac * (next.hours - p.hours);
      }
    }
    // The worn state per interface (two interfaces per hinge share the depth).
    worn.roller = 0.5 * next.roller;
    worn.plate = 0.5 * next.plate;
    p = next;
    res.series.push_back(p);
    ++blocks;
  }
  loop.step(kPermille);
  if (blocks >= kMaxBlocks) {
    res.diagnostics.push_back({S::kWarning, "wear.block_limit",
                               "stopped after the largest number of blocks before the last "
                               "limit; give a larger block_passes",
                               static_cast<double>(blocks), static_cast<double>(kMaxBlocks)});
  }
  res.at_end = p;
  return res;
}

}  // namespace catena::wear
