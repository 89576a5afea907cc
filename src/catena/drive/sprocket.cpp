// The ISO 606 tooth form (docs/models/sprocket.md). Radii in mm inside (the cube root of ri,max
// needs mm), SI at the interface.
#include "catena/drive/sprocket.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace catena::drive {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;
constexpr int kMinTeeth = 6;
constexpr int kMaxTeeth = 500;
constexpr int kMaxStrands = 8;

struct Vec {
  double x = 0.0, y = 0.0;
};
Vec operator+(Vec a, Vec b) { return {a.x + b.x, a.y + b.y}; }
Vec operator*(double k, Vec a) { return {k * a.x, k * a.y}; }
double dot(Vec a, Vec b) { return a.x * b.x + a.y * b.y; }
double norm(Vec a) { return std::hypot(a.x, a.y); }
Vec polar(double r, double angle) { return {r * std::cos(angle), r * std::sin(angle)}; }

// The construction of one gap form in the frame of gap 0: the roller centre C on the +x axis at
// the pitch radius, the tooth that follows (towards gap 1) on the +y side. The seating arc is
// centred on C, radius ri, symmetric about the x axis over the seating angle α; it ends at
// J = C + ri u, u = (−cos α/2, sin α/2). The flank is the arc of radius re tangent to it at J,
// convex (the tooth's side): its centre is E = C + (ri + re) u.
struct Construction {
  Vec c, j, e;
  double ri = 0.0, half_angle = 0.0, re = 0.0;
  double tooth_angle = 0.0;  // π/z: the tooth's centre line
};

Construction construct(double pitch_radius, double ri, double alpha, double re, int z) {
  Construction k;
  k.ri = ri;
  k.re = re;
  k.half_angle = alpha / 2;
  k.tooth_angle = kPi / z;
  k.c = {pitch_radius, 0.0};
  const Vec u{-std::cos(k.half_angle), std::sin(k.half_angle)};
  k.j = k.c + ri * u;
  k.e = k.c + (ri + re) * u;
  return k;
}

// The flank's angle ψ around E (X = E + re (cos ψ, sin ψ)); along the flank from J outwards ψ
// grows. ψ at J:
double flank_start(const Construction& k) { return std::atan2(k.j.y - k.e.y, k.j.x - k.e.x); }

// The smallest ψ > ψ0 (mod 2π) among `candidates`.
double first_after(double psi0, std::initializer_list<double> candidates) {
  double best = INFINITY;
  for (double c : candidates) {
    double d = std::fmod(c - psi0, 2 * kPi);
    if (d <= 0) d += 2 * kPi;
    best = std::min(best, d);
  }
  return psi0 + best;
}

// The flank's crossing of the tooth's centre line (the ray at π/z), the outer root of
// |t v − E| = re; its distance t from the centre. NaN when the flank misses the line.
double meeting_radius(const Construction& k) {
  const Vec v = polar(1.0, k.tooth_angle);
  const double ve = dot(v, k.e);
  const double disc = ve * ve - dot(k.e, k.e) + k.re * k.re;
  if (disc < 0) return NAN;
  return ve + std::sqrt(disc);
}

GapForm form(double pitch_radius, double ri, double alpha, double re, int z, double tip_max) {
  const Construction k = construct(pitch_radius, ri, alpha, re, z);
  GapForm f;
  f.seating_radius = ri;
  f.seating_angle = alpha;
  f.flank_radius = re;
  f.flank_meeting_diameter = 2 * meeting_radius(k);
  f.flanks_meet_below_tip = f.flank_meeting_diameter < tip_max;
  f.outline_tip_diameter = std::min(f.flank_meeting_diameter, tip_max);
  return f;
}

}  // namespace

std::vector<Issue> validate(const SprocketInput& in) {
  std::vector<Issue> out;
  auto mm = [](double v) { return check::format_si(v, "m"); };
  if (!(std::isfinite(in.pitch) && in.pitch > 0))
    out.push_back({"pitch", mm(in.pitch), "a pitch p > 0"});
  if (!(std::isfinite(in.roller_diameter) && in.roller_diameter > 0))
    out.push_back({"roller_diameter", mm(in.roller_diameter), "a roller diameter d1 > 0"});
  else if (in.pitch > 0 && !(in.roller_diameter < in.pitch))
    out.push_back({"roller_diameter", mm(in.roller_diameter),
                   "d1 < p = " + mm(in.pitch) + " (neighbouring rollers would overlap)"});
  if (!(std::isfinite(in.inner_width) && in.inner_width > 0))
    out.push_back({"inner_width", mm(in.inner_width), "an inner width b1 > 0"});
  if (in.teeth < kMinTeeth || in.teeth > kMaxTeeth)
    out.push_back(
        {"teeth", std::to_string(in.teeth),
         "a tooth count z from " + std::to_string(kMinTeeth) + " to " + std::to_string(kMaxTeeth)});
  if (in.strands < 1 || in.strands > kMaxStrands)
    out.push_back({"strands", std::to_string(in.strands),
                   "a strand count from 1 to " + std::to_string(kMaxStrands)});
  if (in.transverse_pitch && !(std::isfinite(*in.transverse_pitch) && *in.transverse_pitch > 0))
    out.push_back({"transverse_pitch", mm(*in.transverse_pitch), "a transverse pitch pt > 0"});
  if (in.tooth_width) {
    if (!(std::isfinite(*in.tooth_width) && *in.tooth_width > 0))
      out.push_back({"tooth_width", mm(*in.tooth_width), "a tooth width bf1 > 0"});
    else if (in.inner_width > 0 && !(*in.tooth_width < in.inner_width))
      out.push_back({"tooth_width", mm(*in.tooth_width),
                     "bf1 < b1 = " + mm(in.inner_width) + " (the tooth runs between the plates)"});
  }
  return out;
}

Sprocket sprocket(const SprocketInput& in) {
  throw_if_any(validate(in));
  Sprocket s;
  s.input = in;
  const double p = in.pitch * 1e3, d1 = in.roller_diameter * 1e3;  // mm
  const double z = in.teeth;
  const double d = p / std::sin(kPi / z);
  const double ri_min = 0.505 * d1;
  const double ri_max = 0.505 * d1 + 0.069 * std::cbrt(d1);
  const double alpha_min = (120.0 - 90.0 / z) * kDeg;
  const double alpha_max = (140.0 - 90.0 / z) * kDeg;
  const double re_min = 0.12 * d1 * (z + 2);
  const double re_max = 0.008 * d1 * (z * z + 180);
  const double da_max = d + 1.25 * p - d1;
  const double da_min = d + p * (1 - 1.6 / z) - d1;
  s.pitch_diameter = d * 1e-3;
  s.root_diameter = (d - d1) * 1e-3;
  s.seat_diameter_min = (d - 2 * ri_max) * 1e-3;
  s.seat_diameter_max = (d - 2 * ri_min) * 1e-3;
  s.tip_diameter_min = da_min * 1e-3;
  s.tip_diameter_max = da_max * 1e-3;
  s.seating_radius_min = ri_min * 1e-3;
  s.seating_radius_max = ri_max * 1e-3;
  s.seating_angle_min = alpha_min;
  s.seating_angle_max = alpha_max;
  s.flank_radius_min = re_min * 1e-3;
  s.flank_radius_max = re_max * 1e-3;
  if (in.tooth_width) {
    s.tooth_width = in.tooth_width;
  } else if (in.strands == 1 && p > 12.7) {
    s.tooth_width = 0.95 * in.inner_width;
  }
  if (in.strands > 1 && s.tooth_width && in.transverse_pitch)
    s.strand_width = *in.transverse_pitch * (in.strands - 1) + *s.tooth_width;
  s.side_radius = in.pitch;
  s.side_relief_min = 0.10 * in.pitch;
  s.side_relief_max = 0.15 * in.pitch;
  const double mr =
      in.teeth % 2 == 0 ? d + d1 : d * std::cos(kPi / 2 / z) + d1;  // 90°/z in radians
  s.measurement_over_pins = mr * 1e-3;
  // the forms, in metres
  const double radius = s.pitch_diameter / 2;
  s.min_gap = form(radius, s.seating_radius_min, alpha_max, s.flank_radius_max, in.teeth,
                   s.tip_diameter_max);
  s.max_gap = form(radius, s.seating_radius_max, alpha_min, s.flank_radius_min, in.teeth,
                   s.tip_diameter_max);
  return s;
}

std::vector<std::pair<double, double>> tooth_outline(const Sprocket& s, const GapForm& f,
                                                     int points_per_arc) {
  const int n = std::max(points_per_arc, 2);
  const int z = s.input.teeth;
  const Construction k =
      construct(s.pitch_diameter / 2, f.seating_radius, f.seating_angle, f.flank_radius, z);
  std::vector<Vec> half;  // from the seat's bottom on the x axis to the tooth's centre line
  // the seating arc: around C from the bottom (angle π) to J (angle π − α/2)
  for (int i = 0; i < n; ++i) {
    const double t = kPi - k.half_angle * i / (n - 1);
    half.push_back(k.c + polar(k.ri, t));
  }
  // the flank: around E from J to the meeting point or the tip circle
  const double psi0 = flank_start(k);
  const double tip = s.tip_diameter_max / 2;
  const Vec meet = polar(f.flank_meeting_diameter / 2, k.tooth_angle);
  double psi_end = std::atan2(meet.y - k.e.y, meet.x - k.e.x);
  bool tip_arc = false;
  if (!f.flanks_meet_below_tip) {
    // |E + re e(ψ)| = Ra: |E| cos(ψ − φE) = (Ra² − |E|² − re²) / (2 re)
    const double ce = (tip * tip - dot(k.e, k.e) - k.re * k.re) / (2 * k.re * norm(k.e));
    const double phi_e = std::atan2(k.e.y, k.e.x);
    const double w = std::acos(std::clamp(ce, -1.0, 1.0));
    psi_end = first_after(psi0, {phi_e + w, phi_e - w});
    tip_arc = true;
  } else {
    psi_end = first_after(psi0, {psi_end});
  }
  for (int i = 1; i < n; ++i) {
    const double psi = psi0 + (psi_end - psi0) * i / (n - 1);
    half.push_back(k.e + polar(k.re, psi));
  }
  if (tip_arc) {  // along the tip circle to the centre line
    const double from = std::atan2(half.back().y, half.back().x);
    for (int i = 1; i < n; ++i)
      half.push_back(polar(tip, from + (k.tooth_angle - from) * i / (n - 1)));
  }
  // one pitch: the half, then its mirror image about the centre line, reversed (the centre-line
  // point once, the next seat's bottom left to the next pitch)
  std::vector<Vec> pitch = half;
  const double c2 = std::cos(2 * k.tooth_angle), s2 = std::sin(2 * k.tooth_angle);
  for (int i = static_cast<int>(half.size()) - 2; i >= 1; --i) {
    const Vec q = half[static_cast<std::size_t>(i)];
    pitch.push_back({c2 * q.x + s2 * q.y, s2 * q.x - c2 * q.y});
  }
  std::vector<std::pair<double, double>> out;
  out.reserve(pitch.size() * static_cast<std::size_t>(z));
  for (int t = 0; t < z; ++t) {
    const double a = 2 * kPi * t / z, ca = std::cos(a), sa = std::sin(a);
    for (const Vec& q : pitch) out.emplace_back(ca * q.x - sa * q.y, sa * q.x + ca * q.y);
  }
  return out;
}

}  // namespace catena::drive
