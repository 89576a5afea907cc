#include "catena/strength/loop.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

namespace catena::strength {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kMaxFactor = 10.0;     // [-] k: a turn that multiplies by > 10 is a typo
constexpr double kMaxWrap = 2.0 * kPi;  // [rad] α: one full wrap
constexpr double kMaxFriction = 1.0;    // [-] f
constexpr double kMaxResistance = 1.0;  // [-] w
constexpr double kMaxLoss = 0.5;        // [-] ξ

std::string g(double v) {
  char b[48];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}

std::string field(std::size_t i, const char* name) {
  return "segment[" + std::to_string(i) + "]." + name;
}

// value within [lo, hi] (and finite); appends an Issue otherwise (the strings are built only
// then: validation runs on every solve)
void in_range(std::vector<Issue>& out, const std::string& name, double value, double lo, double hi,
              const char* unit, const char* expected) {
  if (!std::isfinite(value) || value < lo || value > hi)
    out.push_back({name, check::format_si(value, unit), expected});
}
void in_range(std::vector<Issue>& out, std::size_t i, const char* name, double value, double lo,
              double hi, const char* unit, const char* expected) {
  if (!std::isfinite(value) || value < lo || value > hi)
    out.push_back({field(i, name), check::format_si(value, unit), expected});
}

std::string label(const Loop& loop, std::size_t i) {
  const Segment& s = loop.segments[i];
  return "segment " + std::to_string(i) + (s.name.empty() ? "" : " '" + s.name + "'") + " (" +
         to_string(s.kind) + ")";
}

}  // namespace

const char* to_string(SegmentKind kind) {
  switch (kind) {
    case SegmentKind::kStraight:
      return "straight";
    case SegmentKind::kTurn:
      return "turn";
    case SegmentKind::kTakeup:
      return "takeup";
    case SegmentKind::kDrive:
      return "drive";
  }
  return "?";
}

std::vector<Issue> validate(const Loop& loop) {
  std::vector<Issue> out;
  const std::size_t n = loop.segments.size();
  if (n == 0) {
    out.push_back({"segments", "(none)",
                   "a closed loop of segments in travel order: at least one take-up and the "
                   "drive, the drive last"});
  }
  std::size_t drives = 0, takeups = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Segment& s = loop.segments[i];
    switch (s.kind) {
      case SegmentKind::kStraight:
        if (!(std::isfinite(s.length) && s.length > 0.0 && s.length <= 1e6))
          out.push_back({field(i, "length"), check::format_si(s.length, "m"),
                         "a length 0 < L ≤ 1000 km along the run"});
        in_range(out, i, "incline", s.incline, -kPi / 2, kPi / 2, "rad",
                 "an incline β in [-90°, 90°] (positive rising in the travel direction)");
        in_range(out, i, "chain_weight", s.chain_weight, 0.0, 1e7, "N/m",
                 "a chain weight per metre q0 in [0, 1e7] N/m");
        in_range(out, i, "load_weight", s.load_weight, 0.0, 1e7, "N/m",
                 "a load weight per metre q in [0, 1e7] N/m (0 on the return run)");
        in_range(out, i, "resistance", s.resistance, 0.0, kMaxResistance, "",
                 "a running resistance factor w in [0, 1]");
        break;
      case SegmentKind::kTurn: {
        const bool euler = s.wrap.has_value() || s.friction.has_value();
        if (s.factor && euler) {
          out.push_back({field(i, "factor"), g(*s.factor),
                         "either a factor k or a wrap angle and friction (S_out = S_in·exp(f·α)), "
                         "not both"});
        } else if (s.factor) {
          // k < 1 would make a passive turn give energy back to the chain: an error, not a
          // diagnostic (no design has it; it is a typo such as 0.05 for 1.05)
          in_range(out, i, "factor", *s.factor, 1.0, kMaxFactor, "",
                   "a turn resistance factor k in [1, 10] (S_out = k·S_in; a passive turn "
                   "cannot lower the tension, so k ≥ 1)");
        } else if (euler) {
          if (!s.wrap) out.push_back({field(i, "wrap"), "(missing)", "a wrap angle α with f"});
          if (!s.friction)
            out.push_back({field(i, "friction"), "(missing)", "a friction factor f with α"});
          if (s.wrap)
            in_range(out, i, "wrap", *s.wrap, 0.0, kMaxWrap, "rad", "a wrap angle α in [0°, 360°]");
          if (s.friction)
            in_range(out, i, "friction", *s.friction, 0.0, kMaxFriction, "",
                     "a friction factor f in [0, 1]");
        } else {
          out.push_back({field(i, "factor"), "(missing)",
                         "a turn resistance factor k ≥ 1, or a wrap angle and friction"});
        }
        break;
      }
      case SegmentKind::kTakeup:
        ++takeups;
        in_range(out, i, "pretension", s.pretension, 0.0, 1e9, "N",
                 "a take-up pretension S0 in [0, 1e9] N");
        break;
      case SegmentKind::kDrive:
        ++drives;
        in_range(out, i, "loss", s.loss, 0.0, kMaxLoss, "",
                 "a drive sprocket loss factor ξ in [0, 0.5]");
        if (i + 1 != n)
          out.push_back({field(i, "kind"), "drive",
                         "the drive as the last segment: the list starts just after the drive "
                         "sprocket (its slack side) and the drive closes the loop"});
        break;
    }
  }
  if (n > 0 && drives != 1)
    out.push_back({"segments", std::to_string(drives) + " drives",
                   "exactly one segment of kind drive (the last)"});
  if (n > 0 && takeups != 1)
    out.push_back({"segments", std::to_string(takeups) + " take-ups",
                   "exactly one segment of kind takeup (its pretension fixes the loop's tension "
                   "level)"});
  if (!(std::isfinite(loop.speed) && loop.speed > 0.0 && loop.speed <= 100.0))
    out.push_back(
        {"speed", check::format_si(loop.speed, "m/s"), "a chain speed v in (0, 100] m/s"});
  if (!(loop.efficiency > 0.0 && loop.efficiency <= 1.0))
    out.push_back({"efficiency", g(loop.efficiency), "a drive efficiency η in (0, 1]"});
  if (loop.min_tension)
    in_range(out, "min_tension", *loop.min_tension, 0.0, 1e9, "N",
             "a least allowed tension in [0, 1e9] N");
  if (loop.allowable_tension)
    if (!(std::isfinite(*loop.allowable_tension) && *loop.allowable_tension > 0.0))
      out.push_back({"allowable_tension", check::format_si(*loop.allowable_tension, "N"),
                     "an allowable tension > 0 N (breaking force / safety factor)"});
  return out;
}

Affine affine(const Segment& s) {
  switch (s.kind) {
    case SegmentKind::kStraight:
      // Spivakovsky & Dyachkov: W = (q + q0)·L·(w·cosβ ± sinβ); L along the run, so L·cosβ is
      // its horizontal projection and L·sinβ the height it climbs (negative when descending)
      return {1.0, (s.chain_weight + s.load_weight) * s.length *
                       (s.resistance * std::cos(s.incline) + std::sin(s.incline))};
    case SegmentKind::kTurn:
      // Euler's belt formula for a chain sliding round a curved guide, or a lumped factor k
      return {s.factor ? *s.factor : std::exp(s.friction.value_or(0.0) * s.wrap.value_or(0.0)),
              0.0};
    case SegmentKind::kTakeup:
    case SegmentKind::kDrive:
      return {1.0, 0.0};
  }
  return {1.0, 0.0};
}

LoopResult solve(const Loop& loop) {
  throw_if_any(validate(loop));
  const std::size_t n = loop.segments.size();
  const std::size_t drive = n - 1;

  // the take-up condition: S at the take-up = (A·S_slack + B) = S0, with (A, B) the composition
  // of the segments before it; A ≥ 1 > 0 since every a ≥ 1
  double A = 1.0, B = 0.0;
  std::size_t takeup = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (loop.segments[i].kind == SegmentKind::kTakeup) {
      takeup = i;
      break;
    }
    const Affine m = affine(loop.segments[i]);
    A = m.a * A;
    B = m.a * B + m.b;
  }
  const double s0 = loop.segments[takeup].pretension;

  LoopResult r;
  r.slack_tension = (s0 - B) / A;
  r.segments.resize(n);
  double S = r.slack_tension, s = 0.0;
  for (std::size_t i = 0; i < drive; ++i) {
    const Segment& seg = loop.segments[i];
    SegmentTension& t = r.segments[i];
    t.s_start = s;
    t.tension_in = S;
    if (i == takeup) S = s0;  // exact at its own point, no round-off carried into it
    const Affine m = affine(seg);
    S = m.a * S + m.b;
    if (seg.kind == SegmentKind::kStraight) s += seg.length;
    t.s_end = s;
    t.tension_out = S;
    t.resistance = t.tension_out - t.tension_in;
  }
  r.tight_tension = S;
  r.length = s;
  const double xi = loop.segments[drive].loss;
  r.drive_force = (r.tight_tension - r.slack_tension) + xi * (r.tight_tension + r.slack_tension);
  SegmentTension& d = r.segments[drive];
  d.s_start = d.s_end = s;
  d.tension_in = r.tight_tension;
  d.tension_out = r.slack_tension;
  d.resistance = -r.drive_force;
  r.power = r.drive_force >= 0.0 ? r.drive_force * loop.speed / loop.efficiency
                                 : r.drive_force * loop.speed * loop.efficiency;

  // extremes over every point (start and end of each segment); the first occurrence wins
  r.max = {r.segments[0].tension_in, 0, false, 0.0};
  r.min = r.max;
  for (std::size_t i = 0; i < n; ++i) {
    for (const bool at_end : {false, true}) {
      const SegmentTension& t = r.segments[i];
      const double v = at_end ? t.tension_out : t.tension_in;
      const double where = at_end ? t.s_end : t.s_start;
      if (v > r.max.tension) r.max = {v, i, at_end, where};
      if (v < r.min.tension) r.min = {v, i, at_end, where};
    }
  }

  auto at = [&](const Extremum& e) {
    return label(loop, e.segment) + (e.at_end ? " end" : " start") + ", s = " + g(e.s) + " m";
  };
  if (r.min.tension < 0.0) {
    r.diagnostics.push_back(
        {Diagnostic::Severity::kInfeasible, "loop.chain_slack",
         "the tension falls to " + g(r.min.tension) + " N at " + at(r.min) +
             ": a chain carries no compression, so it goes slack there and the contour method "
             "(a taut chain) no longer holds; raise the take-up pretension by at least " +
             g(-r.min.tension) + " N or move the take-up to that point",
         r.min.tension, 0.0, "N"});
  } else if (loop.min_tension && r.min.tension < *loop.min_tension) {
    r.diagnostics.push_back({Diagnostic::Severity::kWarning, "loop.below_min_tension",
                             "the tension falls to " + g(r.min.tension) + " N at " + at(r.min) +
                                 ", below the least allowed " + g(*loop.min_tension) +
                                 " N (min_tension)",
                             r.min.tension, *loop.min_tension, "N"});
  }
  if (loop.allowable_tension && r.max.tension > *loop.allowable_tension) {
    r.diagnostics.push_back({Diagnostic::Severity::kInfeasible, "loop.over_allowable_tension",
                             "the greatest tension " + g(r.max.tension) + " N at " + at(r.max) +
                                 " exceeds the allowable " + g(*loop.allowable_tension) +
                                 " N (allowable_tension: breaking force / safety factor)",
                             r.max.tension, *loop.allowable_tension, "N"});
  }
  if (r.drive_force < 0.0) {
    r.diagnostics.push_back(
        {Diagnostic::Severity::kInfo, "loop.drive_brakes",
         "the drive force is negative (" + g(r.drive_force) +
             " N): the load runs the loop downhill and the drive brakes it; power is the braking "
             "power through the drive train, F·v·η",
         r.drive_force, 0.0, "N"});
  }
  return r;
}

}  // namespace catena::strength
