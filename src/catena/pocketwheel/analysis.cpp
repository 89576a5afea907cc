// `pocketwheel` — round-link chain running onto a pocket wheel (seed 003) — as an analysis.
#include "catena/pocketwheel/analysis.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>

#include "catena/pocketwheel/layout.hpp"
#include "catena/pocketwheel/run_on_numeric.hpp"

namespace catena::pocketwheel {
namespace {

using analysis::format_g;
using analysis::Inputs;
using analysis::Record;
using analysis::Value;

double deg(double rad) { return rad * 180.0 / std::numbers::pi; }

GuideKind guide_kind(const std::string& name) {
  if (name == "chordal") return GuideKind::kChordal;
  if (name == "tangential") return GuideKind::kTangential;
  if (name == "height") return GuideKind::kHeight;
  return GuideKind::kNone;
}

// --guide-height belongs to --guide height alone (the paper's example compares the three fixed
// guides and ignores it).
void check(const Inputs& in, std::vector<Issue>& issues) {
  if (in.flag("example") && !in.given("guide")) return;
  if (in.text("guide") == "height") {
    if (!in.given("guide_height"))
      issues.push_back({"guide_height", "(missing)", "a length H, required with --guide height"});
  } else if (in.given("guide_height")) {
    issues.push_back(
        {"guide_height", in.text("guide_height"), "no value unless --guide height is chosen"});
  }
}

// The wheel at φ = 0: pitch circle, seated joints and links, the free strand, the guide.
Drawing wheel_drawing(const PocketWheel& wheel, const RunOnResult& res) {
  const ChainLayout layout = chain_layout(wheel, res.plan);
  const double radius = res.plan.geometry.pitch_radius, d = wheel.wire;
  Drawing drawing;
  drawing.title = "Catena pocket wheel at phi = 0";
  auto circle = [&](const char* layer, double cx, double cy, double rr, double width,
                    unsigned rgb) {
    Polyline p{layer, {}, true, width, rgb};
    for (int i = 0; i < 144; ++i) {
      const double a = 2.0 * std::numbers::pi * i / 144.0;
      p.points.push_back({cx + rr * std::cos(a), cy + rr * std::sin(a)});
    }
    drawing.polylines.push_back(std::move(p));
  };
  circle("PITCH_CIRCLE", 0.0, 0.0, radius, 0.18, 0x888888);
  drawing.polylines.push_back(
      {"AXIS", {{-0.1 * radius, 0.0}, {0.1 * radius, 0.0}}, false, 0.18, 0x888888});
  drawing.polylines.push_back(
      {"AXIS", {{0.0, -0.1 * radius}, {0.0, 0.1 * radius}}, false, 0.18, 0x888888});
  drawing.polylines.push_back({"SEATED_CHAIN", layout.seated, false, 0.5, 0x1f77b4});
  drawing.polylines.push_back({"STRAND", layout.strand, false, 0.5, 0xd62728});
  for (std::size_t i = 0; i < layout.seated.size(); ++i) {
    circle(i == 0 ? "CRANK_JOINT" : "JOINTS", layout.seated[i].first, layout.seated[i].second,
           0.5 * d, i == 0 ? 0.5 : 0.25, i == 0 ? 0xd62728 : 0x1f77b4);
  }
  if (res.plan.guide.kind != GuideKind::kNone) {
    // the guide's running surface, half a wire below the chain's centre line
    const double l = res.plan.guide.end_distance, h = res.plan.guide_height - 0.5 * d;
    drawing.polylines.push_back(
        {"GUIDE", {{-l, h}, {-l - 3.0 * wheel.pitch, h}}, false, 0.8, 0x2ca02c});
  }
  return drawing;
}

std::string guide_label(const Guide& guide) {
  std::string label = to_string(guide.kind);
  if (guide.kind != GuideKind::kNone)
    label += std::string(" (") + to_string(guide.span_model) + ")";
  return label;
}

Value to_value(const RunOnAnalysis& a, const RunOnResult& res) {
  const auto& geo = res.plan.geometry;
  const bool forced = res.plan.guide.kind != GuideKind::kNone;
  Value j = Value::object();
  j["model"] = "pocketwheel.run_on";
  j["source"] = "003 Dolipinski, Reich, Adamowicz, Ziegler, eqs. (1)-(43), corrected";
  j["method"] = a.numeric ? "numeric" : "closed";
  j["guide"] = to_string(res.plan.guide.kind);
  j["span_model"] = forced ? Value(to_string(res.plan.guide.span_model)) : Value();
  j["pitch"] = a.wheel.pitch;
  j["wire"] = a.wheel.wire;
  j["teeth"] = a.wheel.teeth;
  j["omega"] = a.sampling.omega;
  j["guide_end"] = forced ? Value(res.plan.guide.end_distance) : Value();
  j["pitch_radius"] = geo.pitch_radius;
  j["delta1"] = geo.delta1;
  j["delta2"] = geo.delta2;
  j["transverse_displacement"] = geo.transverse_displacement;
  j["period"] = res.period;
  j["guide_height"] = forced ? Value(res.plan.guide_height) : Value();
  j["seating_angles"] = res.plan.seating_angles;
  j["first_link"] = res.plan.first_link;
  j["extremes"] = Value::object({{"vx_min", res.extremes.vx_min},
                                 {"vx_max", res.extremes.vx_max},
                                 {"ax_min", res.extremes.ax_min},
                                 {"ax_max", res.extremes.ax_max}});
  Value series = Value::object();
  series["phi"] = res.series.phi;
  series["time"] = res.series.time;
  series["x"] = res.series.x;
  series["vx"] = res.series.vx;
  series["ax"] = res.series.ax;
  if (!forced) {
    series["vy"] = res.series.vy;
    series["ay"] = res.series.ay;
  }
  if (a.sampling.strand_mass) series["inertial_force"] = res.series.inertial_force;
  j["series"] = std::move(series);
  j["diagnostics"] = analysis::diagnostics_value(res.diagnostics);
  j["units"] = analysis::units_value({{"pitch", "m"},
                                      {"wire", "m"},
                                      {"teeth", "1"},
                                      {"omega", "rad/s"},
                                      {"guide_end", "m"},
                                      {"pitch_radius", "m"},
                                      {"delta1", "rad"},
                                      {"delta2", "rad"},
                                      {"transverse_displacement", "m"},
                                      {"period", "s"},
                                      {"guide_height", "m"},
                                      {"seating_angles", "rad"},
                                      {"first_link", "m"},
                                      {"vx_min", "m/s"},
                                      {"vx_max", "m/s"},
                                      {"ax_min", "m/s^2"},
                                      {"ax_max", "m/s^2"},
                                      {"phi", "rad"},
                                      {"time", "s"},
                                      {"x", "m"},
                                      {"vx", "m/s"},
                                      {"ax", "m/s^2"},
                                      {"vy", "m/s"},
                                      {"ay", "m/s^2"},
                                      {"inertial_force", "N"}});
  return j;
}

// The series as CSV columns; with several guides each column but φ and t carries the guide.
std::vector<analysis::Column> csv_columns(const RunOnAnalysis& a) {
  const auto& results = a.results;
  std::vector<analysis::Column> cols{{"phi", results.front().series.phi},
                                     {"time", results.front().series.time}};
  for (std::size_t i = 0; i < results.size(); ++i) {
    const RunOnSeries& s = results[i].series;
    const std::string suffix =
        results.size() == 1 ? "" : std::string("_") + to_string(a.guides[i].kind);
    cols.push_back({"x" + suffix, s.x});
    cols.push_back({"vx" + suffix, s.vx});
    cols.push_back({"ax" + suffix, s.ax});
    if (!s.vy.empty()) {
      cols.push_back({"vy" + suffix, s.vy});
      cols.push_back({"ay" + suffix, s.ay});
    }
    if (a.sampling.strand_mass) cols.push_back({"inertial_force" + suffix, s.inertial_force});
  }
  return cols;
}

std::string to_table(const RunOnAnalysis& a) {
  const auto& results = a.results;
  const auto& geo = results.front().plan.geometry;
  std::ostringstream out;
  out << "Catena pocketwheel: round-link chain running onto a pocket wheel (seed 003)\n";
  out << "chain d x t = " << format_g(a.wheel.wire * 1e3) << " x " << format_g(a.wheel.pitch * 1e3)
      << " mm, z = " << a.wheel.teeth << ", omega = " << format_g(a.sampling.omega) << " rad/s ("
      << format_g(a.sampling.omega * 30.0 / std::numbers::pi)
      << " rpm), method: " << (a.numeric ? "numeric" : "closed form") << "\n\n";
  char line[256];
  std::snprintf(line, sizeof line, "  %-34s %s mm\n", "pitch radius R (eq. 6)",
                format_g(geo.pitch_radius * 1e3).c_str());
  out << line;
  std::snprintf(line, sizeof line, "  %-34s %s / %s deg\n", "delta1 / delta2 (eqs. 7-8)",
                format_g(deg(geo.delta1)).c_str(), format_g(deg(geo.delta2)).c_str());
  out << line;
  std::snprintf(line, sizeof line, "  %-34s %s mm\n", "transverse displacement dy (free)",
                format_g(geo.transverse_displacement * 1e3).c_str());
  out << line;
  std::snprintf(line, sizeof line, "  %-34s %s s (%s deg of wheel turn)\n", "tooth period",
                format_g(results.front().period).c_str(), format_g(deg(geo.tooth_angle)).c_str());
  out << line << "\n";
  std::snprintf(line, sizeof line, "  %-26s", "guide");
  out << line;
  for (const auto& res : results) {
    std::snprintf(line, sizeof line, " %22s", guide_label(res.plan.guide).c_str());
    out << line;
  }
  out << "\n";
  auto row = [&](const char* label, auto value) {
    std::snprintf(line, sizeof line, "  %-26s", label);
    out << line;
    for (const auto& res : results) {
      std::snprintf(line, sizeof line, " %22s", value(res).c_str());
      out << line;
    }
    out << "\n";
  };
  row("guide height H [mm]", [](const RunOnResult& res) {
    return res.plan.guide.kind == GuideKind::kNone ? std::string("-")
                                                   : format_g(res.plan.guide_height * 1e3);
  });
  row("guide end l [mm]", [](const RunOnResult& res) {
    return res.plan.guide.kind == GuideKind::kNone ? std::string("-")
                                                   : format_g(res.plan.guide.end_distance * 1e3);
  });
  row("seating angles [deg]", [](const RunOnResult& res) {
    std::string s;
    for (double v : res.plan.seating_angles) s += (s.empty() ? "" : ", ") + format_g(deg(v), 5);
    return s;
  });
  row("v_x min [m/s]", [](const RunOnResult& res) { return format_g(res.extremes.vx_min); });
  row("v_x max [m/s]", [](const RunOnResult& res) { return format_g(res.extremes.vx_max); });
  row("a_x min [m/s^2]", [](const RunOnResult& res) { return format_g(res.extremes.ax_min); });
  row("a_x max [m/s^2]", [](const RunOnResult& res) { return format_g(res.extremes.ax_max); });
  row("travel per period [mm]",
      [](const RunOnResult& res) { return format_g(res.series.x.back() * 1e3); });
  if (a.sampling.strand_mass) {
    row("max |inertial force| [N]", [&](const RunOnResult& res) {
      return format_g(*a.sampling.strand_mass *
                      std::max(std::abs(res.extremes.ax_min), std::abs(res.extremes.ax_max)));
    });
  }
  return out.str();
}

Record describe(const RunOnAnalysis& a, const Inputs&) {
  Record rec;
  if (a.results.size() == 1) {
    rec.data = to_value(a, a.results.front());
  } else {
    rec.data = Value::array();
    for (const auto& res : a.results) rec.data.push_back(to_value(a, res));
  }
  for (const auto& res : a.results)
    rec.diagnostics.insert(rec.diagnostics.end(), res.diagnostics.begin(), res.diagnostics.end());
  rec.table = to_table(a);
  rec.columns = csv_columns(a);
  if (a.results.size() == 1) {
    rec.drawings.push_back(wheel_drawing(a.wheel, a.results.front()));
    const Value& r = rec.data;
    const Value& series = r.at("series");
    rec.charts.push_back(
        analysis::series_chart(r, series, "Strand position over one tooth period", "phi", {"x"}));
    rec.charts.push_back(
        analysis::series_chart(r, series, "Strand velocity", "phi", {"vx", "vy"}, "velocity"));
    rec.charts.push_back(analysis::series_chart(r, series, "Strand acceleration", "phi",
                                                {"ax", "ay"}, "acceleration"));
    if (series.contains("inertial_force"))
      rec.charts.push_back(analysis::series_chart(r, series, "Inertial force of the strand −M·a_x",
                                                  "phi", {"inertial_force"}));
  } else {
    rec.drawing_unavailable = "one run-on to draw: choose --guide";
  }
  return rec;
}

analysis::Analysis make() {
  using namespace analysis;
  using K = QuantityKind;
  Analysis a;
  a.name = "pocketwheel";
  a.command = {"pocketwheel"};
  a.title = "Round-link chain running onto a pocket wheel (seed 003)";
  a.help =
      "Round-link chain running onto a pocket wheel (seed 003): free or guided run-on, strand "
      "position, velocity and acceleration over one tooth period";
  a.seed = "003";
  a.docs = "docs/models/pocketwheel.md";
  a.chain_types = {"round-link"};
  a.formats = {.table = true, .csv = true, .drawing = true};
  a.example_doc =
      "fill missing flags with the paper's example (chain 18x64, z = 8, omega = 5 1/s, l = 256 "
      "mm); without --guide, compare free, chordal and tangential run-on";
  // The paper's example (003 figs. 2–3): chain Ø18×64, z = 8, ω = 5 1/s, l = 0.256 m.
  a.parameters = {
      quantity("pitch", K::kLength, "chain pitch t") | Required{} | Example{"64mm"},
      quantity("wire", K::kLength, "wire diameter d of the links") | Required{} | Example{"18mm"},
      // Work: 0.16 ms and 4.1 kB a tooth (10⁵ teeth: 16.6 s, 422 MB max RSS; 10⁶ did not finish
      // in 30 s; docs/reliability.md).
      integer("teeth", 3, "number of teeth (pockets) z, >= 3") | Required{} | Example{"8"} |
          Work{.cap = 10000, .seconds = 0.16e-3, .bytes = 4100.0},
      quantity("omega", K::kAngularSpeed, "wheel angular speed (5 1/s, 47.75 rpm)") | Required{} |
          Example{"5 1/s"},
      // Work: 65 µs and 850 B a point (10⁶ points: 65 s, 844 MB max RSS; docs/reliability.md).
      integer("points", 2, "samples over [0, 2pi/z], both ends") | Default{"721"} |
          Work{.cap = 100000, .seconds = 65e-6, .bytes = 850.0},
      quantity("strand_mass", K::kMass,
               "mass moving with the strand, for the inertial force -M a_x"),
      quantity("guide_end", K::kLength,
               "distance l of the guide end from the wheel axis (the paper's: 256 mm)") |
          Default{"256mm"},
      choice("guide", {"none", "chordal", "tangential", "height"}, "run-on") | Default{"none"},
      quantity("guide_height", K::kLength,
               "guide height H for --guide height, from R cos(delta1/2) to R"),
      choice("span_model", {"slider", "pivot"},
             "free span model: slider (the paper's bar) or pivot (bends over the guide edge)") |
          Default{"slider"},
      choice("method", {"closed", "numeric"},
             "closed (closed forms) or numeric (independent geometric solver)") |
          Default{"closed"},
      flag("example", a.example_doc),
  };
  a.check = check;
  set_functions<RunOnAnalysis>(a, run_on_analysis_run, describe);
  return a;
}

}  // namespace

RunOnAnalysis run_on_analysis_run(const analysis::Inputs& in) {
  RunOnAnalysis a;
  a.wheel.pitch = in.number("pitch");
  a.wheel.wire = in.number("wire");
  a.wheel.teeth = in.integer("teeth");
  a.sampling.omega = in.number("omega");
  a.sampling.points = in.integer("points");
  a.sampling.strand_mass = in.optional("strand_mass");
  a.numeric = in.text("method") == "numeric";
  Guide guide;
  guide.span_model = in.text("span_model") == "pivot" ? SpanModel::kPivot : SpanModel::kSlider;
  guide.end_distance = in.number("guide_end");
  if (in.flag("example") && !in.given("guide")) {
    for (GuideKind kind : {GuideKind::kNone, GuideKind::kChordal, GuideKind::kTangential}) {
      guide.kind = kind;
      a.guides.push_back(guide);
    }
  } else {
    guide.kind = guide_kind(in.text("guide"));
    if (guide.kind == GuideKind::kHeight) guide.height = in.number("guide_height");
    a.guides.push_back(guide);
  }
  std::vector<Issue> issues;
  for (const Guide& each : a.guides) {
    const auto found = validate(a.wheel, each);
    issues.insert(issues.end(), found.begin(), found.end());
  }
  const auto found = validate(a.sampling);
  issues.insert(issues.end(), found.begin(), found.end());
  throw_if_any(issues);
  for (const Guide& each : a.guides) {
    a.results.push_back(a.numeric ? numeric::run_on(a.wheel, each, a.sampling)
                                  : run_on(a.wheel, each, a.sampling));
  }
  return a;
}

const analysis::Analysis& run_on_analysis() {
  static const analysis::Analysis a = make();
  return a;
}

}  // namespace catena::pocketwheel
