// `engagement` — chain–sprocket engagement forces for sliding and rolling hinges (seed 000
// §1.6.1–1.6.2) — as an analysis.
#include "catena/engagement/analysis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>

namespace catena::engagement {
namespace {

using analysis::format_g;
using analysis::Inputs;
using analysis::Record;
using analysis::Value;

double deg(double rad) { return rad * 180.0 / std::numbers::pi; }

// The inputs every engagement reads, then each hinge's own.
const std::vector<std::string> kCommon = {"hinge",   "pitch",       "teeth",  "strokes",
                                          "tension", "flank_angle", "points", "wrap_angle"};
const std::vector<std::string> kSlidingKeys = {"friction", "tooth_friction", "journal_diameter",
                                               "tooth_diameter"};
const std::vector<std::string> kRollingKeys = {"pin_diameter",        "half_thickness",
                                               "plate_radius",        "roller_radius",
                                               "rolling_coefficient", "tooth_arm"};

// The hinge decides which inputs apply: the other hinge's are refused, not read (their values
// are not parsed), and the problems come out in the order the inputs are read — the common
// ones, the refused ones, then the hinge's own; each key's problems as the binder found them,
// then this check's.
void check(const Inputs& in, std::vector<Issue>& issues) {
  const std::string& hinge = in.text("hinge");
  const bool rolling = hinge == "rolling";
  std::vector<Issue> added;
  if (in.present("hinge") && hinge != "sliding" && !rolling)
    added.push_back({"hinge", hinge, "sliding or rolling"});
  const std::vector<std::string>& refused = rolling ? kSlidingKeys : kRollingKeys;
  const std::vector<std::string>& own = rolling ? kRollingKeys : kSlidingKeys;
  for (const std::string& key : refused) {
    if (in.given(key)) {
      added.push_back({key, in.text(key),
                       rolling ? "nothing: only the sliding hinge uses it"
                               : "nothing: only the rolling hinge uses it"});
    }
  }
  if (rolling) {
    for (const char* key : {"pin_diameter", "half_thickness", "plate_radius"}) {
      if (!in.given(key)) added.push_back({key, "(missing)", "a value"});
    }
  } else if (in.given("tooth_friction") && !(in.number("tooth_friction") >= 0.0)) {
    added.push_back({"tooth_friction", in.text("tooth_friction"), "a friction factor >= 0"});
  }
  std::vector<std::string> order = kCommon;
  order.insert(order.end(), refused.begin(), refused.end());
  order.insert(order.end(), own.begin(), own.end());
  issues = analysis::in_read_order(issues, added, order, [&](const std::string& key) {
    return std::find(refused.begin(), refused.end(), key) == refused.end();
  });
}

Value to_value(const EngagementAnalysis& a) {
  const Result& res = a.result;
  Value gamma = Value::array(), f2 = Value::array(), fn = Value::array(), xi = Value::array(),
        rr = Value::array(), resid = Value::array(), ff = Value::array(), turns = Value::array();
  for (const Sample& s : res.series) {
    gamma.push_back(s.gamma);
    f2.push_back(s.f2);
    fn.push_back(s.fn);
    resid.push_back(s.residual);
    if (a.rolling) {
      xi.push_back(s.xi);
      rr.push_back(std::max(s.f1k, s.f2k));
    } else {
      xi.push_back(Value());
      rr.push_back(Value());
      ff.push_back(s.friction_force);
      turns.push_back(s.roller_turns);
    }
  }
  Value series = Value::object({{"gamma", gamma},
                                {"F2", f2},
                                {"FN", fn},
                                {"xi", xi},
                                {"rolling_resistance", rr},
                                {"residual", resid}});
  if (!a.rolling) {
    series["friction_force"] = ff;
    series["roller_turns"] = turns;
  }
  Value ranges = Value::array();
  for (const Range& g : res.roller_turns)
    ranges.push_back(Value::object({{"from", g.from}, {"to", g.to}}));
  Value j = Value::object();
  j["model"] = a.rolling ? "engagement.rolling_hinge" : "engagement.sliding_hinge";
  j["source"] = a.rolling ? "000 Pudans, section 1.6.2, eq. (28), reconstructed"
                          : "000 Pudans, section 1.6.1, eqs. (24)-(27), fig. 25 reconstructed";
  j["hinge"] = a.rolling ? "rolling" : "sliding";
  j["pitch"] = a.pitch;
  j["tension"] = a.tension;
  j["gamma_sigma"] = res.angles.gamma_sigma;
  j["angles"] = Value::object({{"alpha", res.angles.alpha},
                               {"epsilon", res.angles.epsilon},
                               {"psi", res.angles.psi},
                               {"beta1", res.angles.beta1}});
  j["series"] = std::move(series);
  j["roller_turns"] = std::move(ranges);
  j["max_residual"] = res.max_residual;
  j["wrap"] = Value::object({{"pitch_radius", a.wrap.pitch_radius},
                             {"rollers", a.wrap.rollers},
                             {"tension", a.wrap.tension},
                             {"tooth_load", a.wrap.tooth_load},
                             {"torque", a.wrap.torque}});
  j["diagnostics"] = analysis::diagnostics_value(res.diagnostics);
  j["units"] = analysis::units_value(
      {{"pitch", "m"},        {"tension", "N"},        {"gamma_sigma", "rad"},
       {"alpha", "rad"},      {"epsilon", "rad"},      {"psi", "rad"},
       {"beta1", "rad"},      {"gamma", "rad"},        {"F2", "N"},
       {"FN", "N"},           {"xi", "rad"},           {"rolling_resistance", "N"},
       {"residual", "1"},     {"friction_force", "N"}, {"from", "rad"},
       {"to", "rad"},         {"max_residual", "1"},   {"limit", "SI"},
       {"pitch_radius", "m"}, {"tooth_load", "N"},     {"torque", "N*m"}});
  return j;
}

// The series as CSV columns; a sliding hinge has no roller turn ξ or rolling resistance (empty
// cells).
std::vector<analysis::Column> csv_columns(const EngagementAnalysis& a) {
  std::vector<analysis::Column> cols = {{"gamma", {}, 12},
                                        {"F2", {}, 12},
                                        {"FN", {}, 12},
                                        {"xi", {}, 12},
                                        {"rolling_resistance", {}, 12},
                                        {"residual", {}, 6}};
  for (const Sample& s : a.result.series) {
    cols[0].values.push_back(s.gamma);
    cols[1].values.push_back(s.f2);
    cols[2].values.push_back(s.fn);
    if (a.rolling) {
      cols[3].values.push_back(s.xi);
      cols[4].values.push_back(std::max(s.f1k, s.f2k));
    }
    cols[5].values.push_back(s.residual);
  }
  return cols;
}

std::string to_table(const EngagementAnalysis& a) {
  const Result& res = a.result;
  const Wrap& w = a.wrap;
  const std::size_t n = res.series.size();
  std::ostringstream out;
  out << "Catena engagement: " << (a.rolling ? "rolling" : "sliding")
      << "-friction hinge entering a sprocket (seed 000 section 1.6)\n";
  out << "F1 = " << format_g(a.tension / 1e3)
      << " kN, gammaSigma = " << format_g(deg(res.angles.gamma_sigma))
      << " deg, beta1 = " << format_g(deg(res.angles.beta1))
      << " deg, epsilon = " << format_g(deg(res.angles.epsilon)) << " deg\n\n";
  out << "  gamma[deg]    F2[kN]    FN[kN]   " << (a.rolling ? " xi[deg]  Fk[N]" : " turns")
      << "   residual\n";
  const std::size_t step = n > 11 ? (n - 1) / 10 : 1;
  for (std::size_t i = 0; i < n; i += step) {
    const Sample& s = res.series[i];
    char line[200];
    if (a.rolling) {
      std::snprintf(line, sizeof line, "  %10.3f %9.4f %9.4f %8.4f %6.2f %10.2e\n", deg(s.gamma),
                    s.f2 / 1e3, s.fn / 1e3, deg(s.xi), std::max(s.f1k, s.f2k), s.residual);
    } else {
      std::snprintf(line, sizeof line, "  %10.3f %9.4f %9.4f %6s %10.2e\n", deg(s.gamma),
                    s.f2 / 1e3, s.fn / 1e3, s.roller_turns ? "yes" : "no", s.residual);
    }
    out << line;
  }
  out << "\nroller turns over gamma [deg]:";
  for (const Range& rg : res.roller_turns)
    out << " [" << format_g(deg(rg.from)) << ", " << format_g(deg(rg.to)) << "]";
  if (res.roller_turns.empty()) out << " none";
  out << "\nlargest equilibrium residual: " << format_g(res.max_residual, 3) << "\n";
  out << "whole wrap: " << w.rollers << " seated rollers, tension "
      << format_g(w.tension.front() / 1e3) << " -> " << format_g(w.tension.back() / 1e3)
      << " kN, sprocket torque " << format_g(w.torque / 1e3) << " kN*m (tooth normals only)\n";
  // a torque of 0 is no failure: radial tooth normals (flank angle 0) take no moment about the
  // axis; what the chain's tension drop puts on the sprocket then goes through tooth friction
  if (std::abs(w.torque) <= 1e-9 * std::abs(w.tension.front()) * w.pitch_radius) {
    // the global balance of the engaged chain: the tension drop times the side distance
    const double pull = (w.tension.front() - w.tension.back()) * w.pitch_radius *
                        std::cos(res.angles.gamma_sigma / 2);
    out << "  (radial tooth normals, flank angle 0, take no moment about the axis; ";
    if (std::abs(pull) <= 1e-9 * std::abs(w.tension.front()) * w.pitch_radius)
      out << "the tension passes every roller unchanged, so the sprocket transmits none)\n";
    else
      out << "the tension drop times R·cos(gammaSigma/2), " << format_g(pull / 1e3)
          << " kN*m, goes through friction, which this torque does not count)\n";
  }
  for (const Diagnostic& d : res.diagnostics)
    out << "\n" << to_string(d.severity) << ": " << d.message << "\n";
  return out.str();
}

Record describe(const EngagementAnalysis& a, const Inputs&) {
  Record rec;
  rec.data = to_value(a);
  rec.diagnostics = a.result.diagnostics;
  rec.table = to_table(a);
  rec.columns = csv_columns(a);
  rec.labels = {
      {"wrap.pitch_radius", "Wrap: pitch radius R", ""},
      {"wrap.rollers", "Wrap: seated rollers", ""},
      {"wrap.tension", "Wrap: tension before each roller", "kN"},
      {"wrap.tooth_load", "Wrap: tooth load of each roller", "kN"},
      {"wrap.torque", "Wrap: sprocket torque from the tooth normals, Σ R·F_N·sin ψ", "kN·m"}};
  const Value& r = rec.data;
  const Value& series = r.at("series");
  rec.charts.push_back(analysis::series_chart(
      r, series, "Link and tooth forces over the engagement", "gamma", {"F2", "FN"}, "force"));
  if (a.rolling) {
    rec.charts.push_back(analysis::series_chart(r, series, "Roller turn ξ over the engagement",
                                                "gamma", {"xi"}, "ξ"));
  }
  analysis::Chart c;
  c.title = "Tension before each seated roller around the sprocket";
  c.x_label = "roller k";
  c.integer_x = true;
  c.y_label = "tension [" + analysis::unit_of(r, "tension") + "]";
  const Value& tension = r.at("wrap").at("tension");
  std::vector<double> k;
  for (std::size_t i = 0; i < tension.size(); ++i) k.push_back(static_cast<double>(i));
  c.traces.push_back({"tension", k, tension.numbers()});
  rec.charts.push_back(std::move(c));
  return rec;
}

analysis::Analysis make() {
  using namespace analysis;
  using K = QuantityKind;
  Analysis a;
  a.name = "engagement";
  a.command = {"engagement"};
  a.title = "Chain–sprocket engagement forces (seed 000 §1.6)";
  a.help =
      "Chain-sprocket engagement forces F2, F_N (and the roller turn xi) for sliding and rolling "
      "hinges over one engagement, seed 000 section 1.6";
  a.seed = "000 §1.6";
  a.docs = "docs/models/engagement.md";
  a.chain_types = {"rolling-hinge", "sliding-hinge"};
  a.formats = {.table = true, .csv = true, .drawing = false};
  // In the order the inputs are read (the problems come out in this order): the common ones,
  // then each hinge's own (see `check`).
  a.parameters = {
      // chain.type decides it in a case file
      text("hinge", "sliding|rolling") | Required{"sliding or rolling"} | CliOnly{},
      quantity("pitch", K::kLength, "chain pitch t") | Required{},
      // Work: the whole wrap seats wrap_angle/gammaSigma ≈ z/2m rollers, each a tension and a
      // tooth load: 6 µs and 140 B a tooth (10⁶ teeth: 6.0 s, 136 MB max RSS, 21 MB of JSON;
      // 10⁹ did not finish in 30 s; docs/reliability.md).
      integer("teeth", 3, "z, sprocket teeth") | Required{"a whole number z >= 3"} |
          Work{.cap = 100000, .seconds = 6e-6, .bytes = 140.0},
      integer("strokes", 1, "m, sprocket strokes; gammaSigma = 360deg*m/z") | Default{"1"},
      quantity("tension", K::kForce, "F1 of the link entering engagement") | Required{},
      quantity("flank_angle", K::kAngle,
               "psi, tilt of the tooth normal from the radius towards the motion") |
          Default{"0deg"},
      // Work: 46 µs and 1 kB a point (10⁵ points: 4.6 s, 99 MB max RSS; docs/reliability.md).
      integer("points", 2, "samples over [0, gammaSigma], both ends") | Default{"91"} |
          Work{.cap = 100000, .seconds = 46e-6, .bytes = 1000.0},
      quantity("wrap_angle", K::kAngle, "whole wrap: angle of the engaged arc") | Default{"180deg"},
      number("friction", "sliding: f = f1, roller-plate friction") | Default{"0"},
      number("tooth_friction",
             "sliding: roller-tooth friction in (24)/(25) (default = --friction)"),
      quantity("journal_diameter", K::kLength, "sliding: d1 of (24)/(25)") | Default{"40mm"},
      quantity("tooth_diameter", K::kLength, "sliding: d2 of (24)/(25)") | Default{"40mm"},
      quantity("pin_diameter", K::kLength,
               "rolling: d, roller's cylindrical part; required with --hinge rolling"),
      quantity("half_thickness", K::kLength,
               "rolling: a, centre to working face; required with --hinge rolling"),
      quantity("plate_radius", K::kLength,
               "rolling: R1, plate's working arc; required with --hinge rolling"),
      quantity("roller_radius", K::kLength, "rolling: R2 of the faces (default: eq. 6)"),
      number("rolling_coefficient", "rolling: c_r, rolling resistance F_k = c_r*F") |
          Default{"0.001"},
      quantity("tooth_arm", K::kLength,
               "rolling: lambda1, rolling-resistance arm of F_N at the tooth") |
          Default{"0mm"},
  };
  a.check = check;
  a.variants = {
      {"rolling-hinge", {{{"hinge", "rolling"}}, kSlidingKeys}},
      {"sliding-hinge", {{{"hinge", "sliding"}}, kRollingKeys}},
  };
  set_functions<EngagementAnalysis>(a, engagement_analysis_run, describe);
  return a;
}

}  // namespace

EngagementAnalysis engagement_analysis_run(const analysis::Inputs& in) {
  EngagementAnalysis a;
  a.rolling = in.text("hinge") == "rolling";
  a.pitch = in.number("pitch");
  a.tension = in.number("tension");
  a.wrap_angle = in.number("wrap_angle");
  const int teeth = in.integer("teeth"), strokes = in.integer("strokes");
  const double flank = in.number("flank_angle");
  const int points = in.integer("points");
  if (a.rolling) {
    RollingInput& ri = a.rolling_in;
    ri.hinge.pin_diameter = in.number("pin_diameter");
    ri.hinge.half_thickness = in.number("half_thickness");
    ri.hinge.plate_radius = in.number("plate_radius");
    if (const auto r2 = in.optional("roller_radius")) ri.hinge.roller_radius = *r2;
    ri.hinge.teeth = teeth;
    ri.hinge.strokes = strokes;
    ri.tension = a.tension;
    ri.flank_angle = flank;
    ri.rolling_coefficient = in.number("rolling_coefficient");
    ri.tooth_arm = in.number("tooth_arm");
    ri.points = points;
  } else {
    SlidingInput& si = a.sliding;
    si.tension = a.tension;
    si.teeth = teeth;
    si.strokes = strokes;
    si.flank_angle = flank;
    si.friction = in.number("friction");
    si.tooth_friction = in.optional("tooth_friction").value_or(-1.0);
    si.journal_diameter = in.number("journal_diameter");
    si.tooth_diameter = in.number("tooth_diameter");
    si.points = points;
  }
  std::vector<Issue> issues;
  if (!(a.pitch > 0.0) || !std::isfinite(a.pitch))
    issues.push_back({"pitch", in.text("pitch"), "a pitch > 0"});
  if (!(a.wrap_angle > 0.0) || !(a.wrap_angle <= 2.0 * std::numbers::pi))
    issues.push_back({"wrap_angle", in.text("wrap_angle"), "a wrap angle in (0, 360deg]"});
  const auto found = a.rolling ? validate(a.rolling_in) : validate(a.sliding);
  issues.insert(issues.end(), found.begin(), found.end());
  throw_if_any(issues);
  a.result = a.rolling ? solve_rolling(a.rolling_in) : solve_sliding(a.sliding);
  a.wrap = wrap(a.result, a.tension, a.pitch, a.wrap_angle);
  return a;
}

const analysis::Analysis& engagement_analysis() {
  static const analysis::Analysis a = make();
  return a;
}

}  // namespace catena::engagement
