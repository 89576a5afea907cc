// `wear` — hinge wear and elongation life (seed 000 §2) — as an analysis.
#include "catena/wear/analysis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>

#include "catena/strength/loop_analysis.hpp"

namespace catena::wear {
namespace {

using analysis::format_g;
using analysis::Inputs;
using analysis::Record;
using analysis::Value;

const std::vector<std::string> kCommon = {"hinge",
                                          "pitch",
                                          "teeth",
                                          "strokes",
                                          "articulations",
                                          "tension",
                                          "speed",
                                          "loop_length",
                                          "wear_coefficient",
                                          "plate_hardness",
                                          "roller_hardness",
                                          "contact_length",
                                          "friction",
                                          "limits",
                                          "block_passes",
                                          "samples",
                                          "tension_source",
                                          "loop",
                                          "compare_wear_coefficient"};
const std::vector<std::string> kSlidingKeys = {"journal_diameter", "tooth_diameter",
                                               "tooth_friction", "flank_angle"};
const std::vector<std::string> kRollingKeys = {"pin_diameter",  "half_thickness", "plate_radius",
                                               "roller_radius", "rolling_limit",  "creep"};

// As the engagement analysis: the hinge decides which inputs apply; the other hinge's are refused.
void check(const Inputs& in, std::vector<Issue>& issues) {
  const std::string& hinge = in.text("hinge");
  const bool rolling = hinge == "rolling";
  std::vector<Issue> added;
  if (in.present("hinge") && hinge != "sliding" && !rolling)
    added.push_back({"hinge", hinge, "sliding or rolling"});
  // compare_wear_coefficient runs the other hinge too: its keys are read then
  const bool compare = in.present("compare_wear_coefficient");
  static const std::vector<std::string> kNone;
  const std::vector<std::string>& refused =
      compare ? kNone : (rolling ? kSlidingKeys : kRollingKeys);
  std::vector<std::string> own = rolling ? kRollingKeys : kSlidingKeys;
  if (compare) {
    const std::vector<std::string>& other = rolling ? kSlidingKeys : kRollingKeys;
    own.insert(own.end(), other.begin(), other.end());
  }
  for (const std::string& key : refused) {
    if (in.given(key)) {
      added.push_back({key, in.text(key),
                       rolling ? "nothing: only the sliding hinge uses it"
                               : "nothing: only the rolling hinge uses it"});
    }
  }
  if (rolling || compare) {
    for (const char* key : {"pin_diameter", "half_thickness", "plate_radius"}) {
      if (!in.given(key))
        added.push_back(
            {key, "(missing)",
             rolling ? "a value" : "a value: compare_wear_coefficient runs the rolling hinge too"});
    }
  }
  // Loads: a given tension, or the loop's tensions at the sprockets (then speed and loop length
  // default to the loop's). Whether the [loop] table is there is its reader's to say.
  if (in.text("tension_source") == "loop") {
    if (!in.given("loop") || in.text("loop").empty())
      added.push_back({"loop", "(missing)",
                       "a [loop] table (case file) or --loop FILE: tension_source = loop takes the "
                       "tensions from it"});
  } else {
    for (const char* key : {"tension", "speed", "loop_length"}) {
      if (!in.present(key)) added.push_back({key, "(missing)", "a value"});
    }
  }
  std::vector<std::string> order = kCommon;
  order.insert(order.end(), refused.begin(), refused.end());
  order.insert(order.end(), own.begin(), own.end());
  issues = analysis::in_read_order(issues, added, order, [&](const std::string& key) {
    return std::find(refused.begin(), refused.end(), key) == refused.end();
  });
}

std::string limit_key(double limit) { return format_g(limit * 100.0, 6); }

Value to_value(const WearAnalysis& w) {
  const Input& in = w.input;
  const Result& r = w.result;
  const Articulation& a = r.first;
  const Articulation& ps = r.pass;
  const bool rolling = in.hinge == HingeKind::kRolling;
  Value j = Value::object();
  j["model"] = rolling ? "wear.rolling_hinge" : "wear.sliding_hinge";
  j["source"] =
      "000 Pudans, section 2 and conclusions 8, 10, 11; Archard wear on the sliding of the "
      "engagement (eqs. 24-25) and hinge (eqs. 3, 21) models; Carter creep";
  j["hinge"] = rolling ? "rolling" : "sliding";
  std::vector<double> hours, percent;
  for (const Point& p : r.series) {
    hours.push_back(p.hours);
    percent.push_back(100.0 * p.elongation);
  }
  j["elongation"] = Value::object({{"hours", hours}, {"percent", percent}});
  Value life = Value::object();
  std::vector<double> sorted = in.limits;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 0; i < sorted.size(); ++i)
    life[limit_key(sorted[i])] = Value(r.life_hours[i]);
  j["life_hours"] = std::move(life);
  // The thesis' chain has pivots ("rollers") and plates; no pin, no bush (null: absent parts).
  j["wear_depth"] = Value::object({{"roller", r.at_end.roller},
                                   {"plate", r.at_end.plate},
                                   {"pin", Value()},
                                   {"bush", Value()}});
  Value sliding = Value::object();
  sliding["articulations"] = in.articulations;
  sliding["mutual_turn"] = a.mutual_turn;
  sliding["pivot_plate"] = ps.slide_pivot_plate;
  if (rolling) {
    sliding["plate_turn"] = a.plate_turn;
    sliding["rolling_limit"] = a.rolling_limit;
    sliding["rolled_turn"] = a.rolled_turn;
    sliding["gross_slide"] = 2.0 * ps.gross_slide;
    sliding["micro_slip"] = 2.0 * ps.micro_slip;
    sliding["rolled_arc"] = a.rolled_arc;
    sliding["half_width"] = a.half_width;
  } else {
    sliding["pivot_turns"] = a.turned;
    sliding["link1"] = ps.slide_link1;
    sliding["link2"] = ps.slide_link2;
    sliding["tooth"] = ps.slide_tooth;
    sliding["neck_spread"] = a.neck_spread;
  }
  sliding["band"] = a.band;
  sliding["roller_depth"] = ps.roller_depth;
  sliding["plate_depth"] = ps.plate_depth;
  j["sliding_per_pass"] = std::move(sliding);
  j["calibration"] =
      Value::object({{"wear_coefficient", in.wear_coefficient},
                     {"source",
                      "given (wear_coefficient); the thesis prints no absolute wear, so no "
                      "coefficient is fitted to it: sliding/rolling ratios do not depend on k "
                      "(docs/models/wear.md)"},
                     {"fitted", false}});
  j["passes_per_hour"] = r.passes_per_hour;
  j["block_passes"] = r.block_passes;
  j["diagnostics"] = analysis::diagnostics_value(r.diagnostics);
  j["units"] = analysis::units_value({{"hours", "h"},
                                      {"percent", "%"},
                                      {"life_hours", "h"},
                                      {"roller", "m"},
                                      {"plate", "m"},
                                      {"pin", "m"},
                                      {"bush", "m"},
                                      {"mutual_turn", "rad"},
                                      {"pivot_plate", "m"},
                                      {"plate_turn", "rad"},
                                      {"rolling_limit", "rad"},
                                      {"rolled_turn", "rad"},
                                      {"gross_slide", "m"},
                                      {"micro_slip", "m"},
                                      {"rolled_arc", "m"},
                                      {"half_width", "m"},
                                      {"pivot_turns", "rad"},
                                      {"link1", "m"},
                                      {"link2", "m"},
                                      {"tooth", "m"},
                                      {"neck_spread", "1"},
                                      {"band", "m"},
                                      {"roller_depth", "m"},
                                      {"plate_depth", "m"},
                                      {"wear_coefficient", "1"},
                                      {"passes_per_hour", "1/h"},
                                      {"block_passes", "1"},
                                      {"limit", "SI"}});
  // compare_wear_coefficient (only then): the other hinge's life beside this one's, and the
  // sliding/rolling ratios of the new chains per pass (the thesis' ratios, docs/models/wear.md)
  if (w.other) {
    const Input& oi = w.other->input;
    const Result& o = w.other->result;
    const bool o_rolling = oi.hinge == HingeKind::kRolling;
    std::vector<double> oh, op;
    for (const Point& p : o.series) {
      oh.push_back(p.hours);
      op.push_back(100.0 * p.elongation);
    }
    Value olife = Value::object();
    for (std::size_t i = 0; i < sorted.size(); ++i)
      olife[limit_key(sorted[i])] = Value(o.life_hours[i]);
    const Articulation& sl = rolling ? o.pass : ps;
    const Articulation& ro = rolling ? ps : o.pass;
    auto ratio = [](double num, double den) { return den > 0.0 ? Value(num / den) : Value(); };
    j["compare"] =
        Value::object({{"hinge", o_rolling ? "rolling" : "sliding"},
                       {"model", o_rolling ? "wear.rolling_hinge" : "wear.sliding_hinge"},
                       {"wear_coefficient", oi.wear_coefficient},
                       {"elongation", Value::object({{"hours", oh}, {"percent", op}})},
                       {"life_hours", std::move(olife)},
                       {"wear_depth", Value::object({{"roller", o.at_end.roller},
                                                     {"plate", o.at_end.plate},
                                                     {"pin", Value()},
                                                     {"bush", Value()}})},
                       {"pivot_plate", o.pass.slide_pivot_plate},
                       {"roller_depth", o.pass.roller_depth},
                       {"plate_depth", o.pass.plate_depth},
                       {"sliding_to_rolling",
                        Value::object({{"pitch_extension", ratio(sl.roller_depth + sl.plate_depth,
                                                                 ro.roller_depth + ro.plate_depth)},
                                       {"roller", ratio(sl.roller_depth, ro.roller_depth)},
                                       {"plate", ratio(sl.plate_depth, ro.plate_depth)}})}});
    j["units"]["sliding_to_rolling"] = "1";
  }
  // tension_source = loop (only then, so that a given tension's output stays as it was): the
  // loads of every articulation and where in the loop each came from
  if (w.loads.from_loop) {
    Value points = Value::array();
    for (const LoopLoad& p : w.loads.points)
      points.push_back(Value::object({{"segment", p.segment},
                                      {"name", p.name},
                                      {"at", p.entry ? "entry" : "exit"},
                                      {"tension", p.tension}}));
    j["loads"] =
        Value::object({{"source", "loop"},
                       {"tensions", in.tensions},
                       {"points", std::move(points)},
                       {"speed", in.speed},
                       {"speed_from", w.loads.speed_from_loop ? "loop" : "given"},
                       {"loop_length", in.loop_length},
                       {"loop_length_from", w.loads.loop_length_from_loop ? "loop" : "given"}});
    Value& units = j["units"];
    units["tension"] = "N";
    units["tensions"] = "N";
    units["speed"] = "m/s";
    units["loop_length"] = "m";
  }
  return j;
}

std::string to_table(const WearAnalysis& w) {
  const Input& in = w.input;
  const Result& r = w.result;
  const Articulation& a = r.first;
  const Articulation& ps = r.pass;
  const bool rolling = in.hinge == HingeKind::kRolling;
  std::ostringstream out;
  out << "Catena wear: " << (rolling ? "rolling" : "sliding")
      << "-friction hinge chain, Archard wear on the kinematics' sliding (seed 000 section 2)\n";
  out << "F = ";
  if (in.tensions.empty()) {
    out << format_g(in.tension / 1e3);
  } else {
    for (std::size_t i = 0; i < in.tensions.size(); ++i)
      out << (i ? "/" : "") << format_g(in.tensions[i] / 1e3);
  }
  out << " kN, " << in.articulations << " articulations per pass of "
      << format_g(a.mutual_turn * 180.0 / std::numbers::pi) << " deg, "
      << format_g(r.passes_per_hour) << " passes/h, k = " << format_g(in.wear_coefficient) << "\n";
  if (w.loads.from_loop) {
    out << "loads from the loop: ";
    for (std::size_t i = 0; i < w.loads.points.size(); ++i) {
      const LoopLoad& p = w.loads.points[i];
      out << (i ? ", " : "") << (p.name.empty() ? "segment " + std::to_string(p.segment) : p.name)
          << (p.entry ? " in " : " out ") << format_g(p.tension / 1e3) << " kN";
    }
    out << "; v = " << format_g(in.speed) << " m/s" << (w.loads.speed_from_loop ? " (loop)" : "")
        << ", loop length " << format_g(in.loop_length) << " m"
        << (w.loads.loop_length_from_loop ? " (the loop's path)" : "") << "\n";
  }
  out << "pivot-plate sliding per pass: " << format_g(ps.slide_pivot_plate * 1e3) << " mm";
  if (rolling) {
    out << " (gross " << format_g(2.0 * ps.gross_slide * 1e3) << " mm, micro-slip "
        << format_g(2.0 * ps.micro_slip * 1e3) << " mm; rolling limit "
        << format_g(a.rolling_limit * 180.0 / std::numbers::pi) << " deg of a "
        << format_g(a.plate_turn * 180.0 / std::numbers::pi) << " deg plate turn)\n";
  } else {
    out << " (link 1 bores " << format_g(ps.slide_link1 * 1e3) << " mm, link 2 bores "
        << format_g(ps.slide_link2 * 1e3) << " mm; tooth " << format_g(ps.slide_tooth * 1e3)
        << " mm)\n";
  }
  out << "wear depth per pass: roller (pivot) " << format_g(ps.roller_depth * 1e9) << " nm, plate "
      << format_g(ps.plate_depth * 1e9) << " nm\n\n";
  out << "  limit[%]   life[h]\n";
  std::vector<double> sorted = in.limits;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    char line[120];
    if (r.life_hours[i]) {
      std::snprintf(line, sizeof line, "  %8s %9.4g\n", limit_key(sorted[i]).c_str(),
                    *r.life_hours[i]);
    } else {
      std::snprintf(line, sizeof line, "  %8s %9s\n", limit_key(sorted[i]).c_str(), "never");
    }
    out << line;
  }
  out << "\nwear depth at " << format_g(r.at_end.hours) << " h: roller (pivot) "
      << format_g(r.at_end.roller * 1e3) << " mm, plate " << format_g(r.at_end.plate * 1e3)
      << " mm (this chain has no pin or bush)\n";
  for (const Diagnostic& d : r.diagnostics)
    out << "\n" << to_string(d.severity) << ": " << d.message << "\n";
  return out.str();
}

std::vector<analysis::Column> csv_columns(const WearAnalysis& w) {
  std::vector<analysis::Column> cols = {
      {"hours", {}, 12}, {"percent", {}, 12}, {"roller", {}, 12}, {"plate", {}, 12}};
  for (const Point& p : w.result.series) {
    cols[0].values.push_back(p.hours);
    cols[1].values.push_back(100.0 * p.elongation);
    cols[2].values.push_back(p.roller);
    cols[3].values.push_back(p.plate);
  }
  return cols;
}

Record describe(const WearAnalysis& w, const Inputs&) {
  Record rec;
  rec.data = to_value(w);
  rec.diagnostics = w.result.diagnostics;
  rec.table = to_table(w);
  rec.columns = csv_columns(w);
  analysis::Chart c;
  c.x_label = "hours [h]";
  c.y_label = "elongation [%]";
  const Value& e = rec.data.at("elongation");
  const bool rolling = w.input.hinge == HingeKind::kRolling;
  if (!w.other) {
    c.title =
        std::string("Elongation of the ") + (rolling ? "rolling" : "sliding") + "-hinge chain";
    c.traces.push_back(
        {rolling ? "rolling" : "sliding", e.at("hours").numbers(), e.at("percent").numbers()});
    rec.charts.push_back(std::move(c));
    return rec;
  }
  // both chains on one chart, the sliding one first, and the retirement limits across it
  const Value& o = rec.data.at("compare").at("elongation");
  analysis::Trace self{rolling ? "rolling" : "sliding", e.at("hours").numbers(),
                       e.at("percent").numbers()};
  analysis::Trace other{rolling ? "sliding" : "rolling", o.at("hours").numbers(),
                        o.at("percent").numbers()};
  c.title = "Elongation of the sliding- and the rolling-hinge chain";
  c.traces.push_back(rolling ? other : self);
  c.traces.push_back(rolling ? self : other);
  double end = 0.0;
  for (const analysis::Trace& t : c.traces)
    for (double h : t.x) end = std::max(end, h);
  std::vector<double> limits = w.input.limits;
  std::sort(limits.begin(), limits.end());
  for (double l : limits)
    c.traces.push_back({"limit " + limit_key(l) + " %", {0.0, end}, {100.0 * l, 100.0 * l}});
  rec.charts.push_back(std::move(c));
  return rec;
}

// The [loop] table as `catena loop` reads it; optional here (only tension_source = loop reads it),
// a --loop FILE on the command line.
analysis::Parameter loop_table() {
  analysis::Parameter p = strength::loop_table_parameter();
  p.required = false;
  p.doc =
      "tension_source = loop: TOML file with a [loop] table and [[loop.segment]] tables (a case "
      "file works); in a case file, its own [loop] table";
  return p;
}

analysis::Analysis make() {
  using namespace analysis;
  using K = QuantityKind;
  Analysis a;
  a.name = "wear";
  a.command = {"wear"};
  a.title = "Hinge wear and elongation life, sliding vs rolling hinges (seed 000 §2)";
  a.help =
      "Archard wear of the pivots and plates from the sliding of each articulation (engagement "
      "criteria 24/25, hinge rolling limit eq. 21, Carter micro-slip): elongation over time and "
      "life to the retirement limits, seed 000 section 2";
  a.seed = "000 §2";
  a.docs = "docs/models/wear.md";
  a.chain_types = {"rolling-hinge", "sliding-hinge"};
  a.formats = {.table = true, .csv = true, .drawing = false};
  a.parameters = {
      text("hinge", "sliding|rolling") | Required{"sliding or rolling"} | CliOnly{},
      quantity("pitch", K::kLength, "chain pitch t") | Required{},
      integer("teeth", 3, "z, sprocket teeth") | Required{"a whole number z >= 3"},
      integer("strokes", 1, "m, sprocket strokes; mutual turn 360deg*m/z") | Default{"1"},
      integer("articulations", 1, "articulations per pass (2 per sprocket)") | Default{"4"},
      quantity("tension", K::kForce,
               "chain tension F at every articulation, or one per articulation of a pass "
               "(required unless tension_source = loop)") |
          ListOf{},
      quantity("speed", K::kSpeed, "chain speed v (tension_source = loop: the loop's by default)"),
      quantity("loop_length", K::kLength,
               "chain length of the loop; a pass takes loop_length/speed (give its unit: 10m; "
               "tension_source = loop: the loop's path length by default)"),
      number("wear_coefficient", "Archard k of the pivot-plate pair, 0 < k < 1") | Required{},
      quantity("plate_hardness", K::kStress,
               "H of the plates (42 HRC = 412 HV = 4040 MPa: thesis concl. 10, ASTM E140)") |
          Default{"4040MPa"},
      quantity("roller_hardness", K::kStress,
               "H of the pivots (30 HRC = 302 HV = 2962 MPa: thesis concl. 10, ASTM E140)") |
          Default{"2962MPa"},
      quantity("contact_length", K::kLength, "L, bearing length of one pivot-plate interface") |
          Required{},
      number("friction", "f, pivot-plate friction, 0 < f < 1") | Required{},
      number("limits", "retirement elongations in percent") | Default{"1.5,2,3"} | ListOf{},
      number("block_passes", "passes per block between re-solves (0: automatic)") | Default{"0"},
      integer("samples", 3, "samples of one articulation") | Default{"181"},
      quantity("journal_diameter", K::kLength, "sliding: d1, pivot neck in the plate bore") |
          Default{"40mm"},
      quantity("tooth_diameter", K::kLength, "sliding: d2, pivot on the tooth") | Default{"40mm"},
      number("tooth_friction", "sliding: pivot-tooth friction in (24)/(25) (default = friction)"),
      quantity("flank_angle", K::kAngle, "sliding: psi, tooth normal's tilt") | Default{"0deg"},
      quantity("pin_diameter", K::kLength, "rolling: d, pivot's cylindrical part"),
      quantity("half_thickness", K::kLength, "rolling: a, centre to working face"),
      quantity("plate_radius", K::kLength, "rolling: R1, plate's working arc"),
      quantity("roller_radius", K::kLength, "rolling: R2 of the faces (default: eq. 6)"),
      choice("rolling_limit", {"friction", "guided"},
             "rolling: friction = roll to eq. (21) then slide; guided = roll throughout") |
          Default{"friction"},
      choice("creep", {"carter", "none"}, "rolling: micro-slip law of the rolling contact") |
          Default{"carter"},
      choice("tension_source", {"given", "loop"},
             "given = tension; loop = the loop's tension where the chain enters and leaves each "
             "sprocket (the drive and every turn given by a factor)") |
          Default{"given"},
      loop_table(),
      number("compare_wear_coefficient",
             "Archard k of the other hinge's pair, 0 < k < 1: given, the other hinge type runs "
             "too on the same chain, sprocket and loads, and the report charts both"),
  };
  a.check = check;
  a.variants = {
      {"rolling-hinge", {{{"hinge", "rolling"}}, kSlidingKeys}},
      {"sliding-hinge", {{{"hinge", "sliding"}}, kRollingKeys}},
  };
  set_functions<WearAnalysis>(a, wear_analysis_run, describe);
  return a;
}

// tension_source = loop: the loop solved as `catena loop` solves it; each sprocket (the drive, and
// every turn given by a factor: a wheel; a turn given by wrap and friction is a curved guide the
// chain slides round, without a tooth's articulation) gives two articulations, entering under the
// tension there and leaving under the tension there. Speed and loop length default to the loop's.
void load_from_loop(const Inputs& in, WearAnalysis& w) {
  Input& x = w.input;
  const strength::LoopAnalysis loop = strength::loop_from_table(in.at("loop"));
  w.loads.from_loop = true;
  for (std::size_t i = 0; i < loop.loop.segments.size(); ++i) {
    const strength::Segment& s = loop.loop.segments[i];
    const bool sprocket = s.kind == strength::SegmentKind::kDrive ||
                          (s.kind == strength::SegmentKind::kTurn && s.factor.has_value());
    if (!sprocket) continue;
    const strength::SegmentTension& t = loop.result.segments[i];
    w.loads.points.push_back({i, s.name, true, t.tension_in});
    w.loads.points.push_back({i, s.name, false, t.tension_out});
  }
  std::vector<Issue> issues;
  if (w.loads.points.empty())
    issues.push_back({"loop", "(no sprocket)",
                      "a loop with a drive segment (tension_source = loop reads its sprockets)"});
  for (const LoopLoad& p : w.loads.points) {
    x.tensions.push_back(p.tension);
    if (p.tension < 0.0) {
      issues.push_back({"loop.segment[" + std::to_string(p.segment) + "]",
                        format_g(p.tension) + " N " + (p.entry ? "entering" : "leaving"),
                        "a tension >= 0 where the chain meets a sprocket (raise the take-up's "
                        "pretension; `catena loop` shows the tensions)"});
    }
  }
  throw_if_any(issues);
  x.tension = x.tensions.front();
  const int count = static_cast<int>(x.tensions.size());
  if (!in.given("articulations")) {
    x.articulations = count;
  } else if (x.articulations != count) {
    issues.push_back({"articulations", in.text("articulations"),
                      std::to_string(count) + " (2 per sprocket of the [loop] table), or not "
                                              "given: tension_source = loop"});
  }
  const double v = loop.loop.speed;
  if (!in.present("speed")) {
    x.speed = v;
    w.loads.speed_from_loop = true;
  } else if (std::abs(x.speed - v) > 1e-9 * v) {
    issues.push_back(
        {"speed", in.text("speed"),
         "the [loop] table's speed " + format_g(v) + " m/s, or not given (tension_source = loop)"});
  }
  if (!in.present("loop_length")) {
    x.loop_length = loop.result.length;
    w.loads.loop_length_from_loop = true;
  }
  throw_if_any(issues);
}

}  // namespace

WearAnalysis wear_analysis_run(const analysis::Inputs& in) {
  WearAnalysis w;
  Input& x = w.input;
  x.hinge = in.text("hinge") == "rolling" ? HingeKind::kRolling : HingeKind::kSliding;
  x.pitch = in.number("pitch");
  x.teeth = in.integer("teeth");
  x.strokes = in.integer("strokes");
  x.articulations = in.integer("articulations");
  x.speed = in.number("speed");
  x.loop_length = in.number("loop_length");
  if (in.text("tension_source") == "loop") {
    load_from_loop(in, w);
  } else {
    x.tension = in.number("tension");
    if (in.list("tension").size() > 1) {
      x.tensions = in.list("tension");
      if (!in.given("articulations")) x.articulations = static_cast<int>(x.tensions.size());
    }
  }
  x.wear_coefficient = in.number("wear_coefficient");
  x.plate_hardness = in.number("plate_hardness");
  x.roller_hardness = in.number("roller_hardness");
  x.contact_length = in.number("contact_length");
  x.friction = in.number("friction");
  x.limits.clear();
  for (double l : in.list("limits")) x.limits.push_back(l / 100.0);
  x.block_passes = in.number("block_passes");
  x.samples = in.integer("samples");
  const auto sliding_keys = [&](Input& y) {
    y.journal_diameter = in.number("journal_diameter");
    y.tooth_diameter = in.number("tooth_diameter");
    y.tooth_friction = in.optional("tooth_friction").value_or(-1.0);
    y.flank_angle = in.number("flank_angle");
  };
  const auto rolling_keys = [&](Input& y) {
    y.geometry.pin_diameter = in.number("pin_diameter");
    y.geometry.half_thickness = in.number("half_thickness");
    y.geometry.plate_radius = in.number("plate_radius");
    if (const auto r2 = in.optional("roller_radius")) y.geometry.roller_radius = *r2;
    y.limit =
        in.text("rolling_limit") == "guided" ? RollingLimit::kGuided : RollingLimit::kFriction;
    y.creep = in.text("creep") == "none" ? Creep::kNone : Creep::kCarter;
  };
  if (x.hinge == HingeKind::kSliding) {
    sliding_keys(x);
  } else {
    rolling_keys(x);
  }
  w.result = run(x);
  // compare_wear_coefficient: the other hinge on the same chain, sprocket, loads and hardness,
  // with its own pair's k (given: nothing is fitted here)
  if (const auto k = in.optional("compare_wear_coefficient")) {
    Input o = x;
    o.wear_coefficient = *k;
    if (x.hinge == HingeKind::kSliding) {
      o.hinge = HingeKind::kRolling;
      rolling_keys(o);
    } else {
      o.hinge = HingeKind::kSliding;
      sliding_keys(o);
    }
    try {
      w.other = Other{o, run(o)};
    } catch (const InputError& e) {
      std::vector<Issue> issues = e.issues();
      for (Issue& i : issues)
        if (i.field == "wear_coefficient") i.field = "compare_wear_coefficient";
      throw InputError(issues);
    }
  }
  if (w.loads.from_loop && in.present("tension")) {
    w.result.diagnostics.push_back(
        {Diagnostic::Severity::kWarning, "wear.tension_not_used",
         "tension " + in.text("tension") +
             " is not used: tension_source = loop takes the loop's tensions at the sprockets"});
  }
  return w;
}

const analysis::Analysis& wear_analysis() {
  static const analysis::Analysis a = make();
  return a;
}

}  // namespace catena::wear
