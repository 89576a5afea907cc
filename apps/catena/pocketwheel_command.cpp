// catena pocketwheel: round-link chain running onto a pocket wheel (seed 003).
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>

#include "catena/io/drawing.hpp"
#include "catena/pocketwheel/layout.hpp"
#include "catena/pocketwheel/run_on.hpp"
#include "catena/pocketwheel/run_on_numeric.hpp"
#include "cli_support.hpp"
#include "commands.hpp"

namespace catena::cli {
namespace {

using io::QuantityKind;
using pocketwheel::chain_layout;
using pocketwheel::ChainLayout;
using pocketwheel::Guide;
using pocketwheel::GuideKind;
using pocketwheel::RunOnResult;
using pocketwheel::SpanModel;

// The paper's example (003 figs. 2–3): chain Ø18×64, z = 8, ω = 5 1/s, l = 0.256 m.
constexpr const char* kExamplePitch = "64mm";
constexpr const char* kExampleWire = "18mm";
constexpr const char* kExampleTeeth = "8";
constexpr const char* kExampleOmega = "5 1/s";
constexpr const char* kDefaultGuideEnd = "256mm";

struct Flags {
  std::string pitch, wire, teeth, omega, guide, guide_height, guide_end, span_model = "slider";
  std::string strand_mass, points = "721", format = "table", output, csv, method = "closed";
  std::string svg, dxf;
  bool example = false;
};

struct Request {
  pocketwheel::PocketWheel wheel;
  std::vector<Guide> guides;  // one, or the paper's three with --example and no --guide
  pocketwheel::Sampling sampling;
  bool numeric = false;
};

double deg(double rad) { return rad * 180.0 / std::numbers::pi; }

Request read(const Flags& f) {
  FlagReader in;
  auto required = [&](const std::string& flag, const std::string& text, const char* example) {
    if (!text.empty()) return text;
    if (f.example) return std::string(example);
    in.add({flag, "(missing)", "a value (or --example for the paper's example)"});
    return std::string();
  };
  Request r;
  const std::string pitch = required("--pitch", f.pitch, kExamplePitch);
  const std::string wire = required("--wire", f.wire, kExampleWire);
  const std::string teeth = required("--teeth", f.teeth, kExampleTeeth);
  const std::string omega = required("--omega", f.omega, kExampleOmega);
  r.wheel.pitch = in.quantity("--pitch", pitch, QuantityKind::kLength).value_or(NAN);
  r.wheel.wire = in.quantity("--wire", wire, QuantityKind::kLength).value_or(NAN);
  if (!teeth.empty()) r.wheel.teeth = in.integer("--teeth", teeth, 3).value_or(0);
  r.sampling.omega = in.quantity("--omega", omega, QuantityKind::kAngularSpeed).value_or(NAN);
  r.sampling.points = in.integer("--points", f.points, 2).value_or(2);
  if (!f.strand_mass.empty()) {
    r.sampling.strand_mass = in.quantity("--strand-mass", f.strand_mass, QuantityKind::kMass);
    if (!r.sampling.strand_mass) r.sampling.strand_mass = NAN;
  }
  r.numeric = f.method == "numeric";

  Guide guide;
  guide.span_model = f.span_model == "pivot" ? SpanModel::kPivot : SpanModel::kSlider;
  guide.end_distance =
      in.quantity("--guide-end", f.guide_end.empty() ? kDefaultGuideEnd : f.guide_end,
                  QuantityKind::kLength)
          .value_or(NAN);
  const std::map<std::string, GuideKind> kinds{{"none", GuideKind::kNone},
                                               {"chordal", GuideKind::kChordal},
                                               {"tangential", GuideKind::kTangential},
                                               {"height", GuideKind::kHeight}};
  if (f.guide.empty() && f.example) {
    for (GuideKind kind : {GuideKind::kNone, GuideKind::kChordal, GuideKind::kTangential}) {
      guide.kind = kind;
      r.guides.push_back(guide);
    }
  } else {
    guide.kind = kinds.at(f.guide.empty() ? "none" : f.guide);
    if (guide.kind == GuideKind::kHeight) {
      if (f.guide_height.empty()) {
        in.add({"--guide-height", "(missing)", "a length H, required with --guide height"});
      } else {
        guide.height =
            in.quantity("--guide-height", f.guide_height, QuantityKind::kLength).value_or(NAN);
      }
    } else if (!f.guide_height.empty()) {
      in.add({"--guide-height", f.guide_height, "no value unless --guide height is chosen"});
    }
    r.guides.push_back(guide);
  }
  in.throw_if_any();  // units and syntax first: model checks need numbers
  for (const Guide& each : r.guides) in.add_model_issues(pocketwheel::validate(r.wheel, each));
  in.add_model_issues(pocketwheel::validate(r.sampling));
  in.throw_if_any();
  return r;
}

RunOnResult analyse(const Request& r, const Guide& guide) {
  try {
    return r.numeric ? pocketwheel::numeric::run_on(r.wheel, guide, r.sampling)
                     : pocketwheel::run_on(r.wheel, guide, r.sampling);
  } catch (const InputError& error) {
    FlagReader renamed;
    renamed.add_model_issues(error.issues());
    renamed.throw_if_any();
    throw;
  }
}

// The wheel at φ = 0: pitch circle, seated joints and links, the free strand, the guide.
io::Drawing wheel_drawing(const Request& r, const RunOnResult& res) {
  const ChainLayout layout = chain_layout(r.wheel, res.plan);
  const double radius = res.plan.geometry.pitch_radius, d = r.wheel.wire;
  io::Drawing drawing;
  drawing.title = "Catena pocket wheel at phi = 0";
  auto circle = [&](const char* layer, double cx, double cy, double rr, double width,
                    unsigned rgb) {
    io::Polyline p{layer, {}, true, width, rgb};
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
        {"GUIDE", {{-l, h}, {-l - 3.0 * r.wheel.pitch, h}}, false, 0.8, 0x2ca02c});
  }
  return drawing;
}

std::string guide_label(const Guide& guide) {
  std::string label = pocketwheel::to_string(guide.kind);
  if (guide.kind != GuideKind::kNone)
    label += std::string(" (") + pocketwheel::to_string(guide.span_model) + ")";
  return label;
}

nlohmann::ordered_json to_json(const Request& r, const RunOnResult& res) {
  using nlohmann::ordered_json;
  const auto& geo = res.plan.geometry;
  const bool forced = res.plan.guide.kind != GuideKind::kNone;
  ordered_json j;
  j["model"] = "pocketwheel.run_on";
  j["source"] = "003 Dolipinski, Reich, Adamowicz, Ziegler, eqs. (1)-(43), corrected";
  j["method"] = r.numeric ? "numeric" : "closed";
  j["guide"] = pocketwheel::to_string(res.plan.guide.kind);
  j["span_model"] =
      forced ? ordered_json(pocketwheel::to_string(res.plan.guide.span_model)) : ordered_json();
  j["pitch"] = r.wheel.pitch;
  j["wire"] = r.wheel.wire;
  j["teeth"] = r.wheel.teeth;
  j["omega"] = r.sampling.omega;
  j["guide_end"] = forced ? ordered_json(res.plan.guide.end_distance) : ordered_json();
  j["pitch_radius"] = geo.pitch_radius;
  j["delta1"] = geo.delta1;
  j["delta2"] = geo.delta2;
  j["transverse_displacement"] = geo.transverse_displacement;
  j["period"] = res.period;
  j["guide_height"] = forced ? ordered_json(res.plan.guide_height) : ordered_json();
  j["seating_angles"] = res.plan.seating_angles;
  j["first_link"] = res.plan.first_link;
  j["extremes"] = {{"vx_min", res.extremes.vx_min},
                   {"vx_max", res.extremes.vx_max},
                   {"ax_min", res.extremes.ax_min},
                   {"ax_max", res.extremes.ax_max}};
  ordered_json series;
  series["phi"] = res.series.phi;
  series["time"] = res.series.time;
  series["x"] = res.series.x;
  series["vx"] = res.series.vx;
  series["ax"] = res.series.ax;
  if (!forced) {
    series["vy"] = res.series.vy;
    series["ay"] = res.series.ay;
  }
  if (r.sampling.strand_mass) series["inertial_force"] = res.series.inertial_force;
  j["series"] = series;
  j["diagnostics"] = diagnostics_json(res.diagnostics);
  j["units"] = {{"pitch", "m"},
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
                {"inertial_force", "N"}};
  return j;
}

// Columns of the series CSV for one result; `suffix` distinguishes guides in --example.
void csv_columns(const RunOnResult& res, bool mass, const std::string& suffix,
                 std::vector<std::pair<std::string, const std::vector<double>*>>& cols) {
  cols.push_back({"x" + suffix, &res.series.x});
  cols.push_back({"vx" + suffix, &res.series.vx});
  cols.push_back({"ax" + suffix, &res.series.ax});
  if (!res.series.vy.empty()) {
    cols.push_back({"vy" + suffix, &res.series.vy});
    cols.push_back({"ay" + suffix, &res.series.ay});
  }
  if (mass) cols.push_back({"inertial_force" + suffix, &res.series.inertial_force});
}

std::string to_csv(const Request& r, const std::vector<RunOnResult>& results) {
  std::vector<std::pair<std::string, const std::vector<double>*>> cols{
      {"phi", &results.front().series.phi}, {"time", &results.front().series.time}};
  for (std::size_t i = 0; i < results.size(); ++i) {
    const std::string suffix =
        results.size() == 1 ? "" : std::string("_") + pocketwheel::to_string(r.guides[i].kind);
    csv_columns(results[i], r.sampling.strand_mass.has_value(), suffix, cols);
  }
  std::ostringstream out;
  for (std::size_t c = 0; c < cols.size(); ++c) out << (c ? "," : "") << cols[c].first;
  out << "\n";
  const std::size_t n = cols.front().second->size();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t c = 0; c < cols.size(); ++c)
      out << (c ? "," : "") << format_g((*cols[c].second)[i], 12);
    out << "\n";
  }
  return out.str();
}

std::string to_table(const Request& r, const std::vector<RunOnResult>& results) {
  const auto& geo = results.front().plan.geometry;
  std::ostringstream out;
  out << "Catena pocketwheel: round-link chain running onto a pocket wheel (seed 003)\n";
  out << "chain d x t = " << format_g(r.wheel.wire * 1e3) << " x " << format_g(r.wheel.pitch * 1e3)
      << " mm, z = " << r.wheel.teeth << ", omega = " << format_g(r.sampling.omega) << " rad/s ("
      << format_g(r.sampling.omega * 30.0 / std::numbers::pi)
      << " rpm), method: " << (r.numeric ? "numeric" : "closed form") << "\n\n";
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
    for (double a : res.plan.seating_angles) s += (s.empty() ? "" : ", ") + format_g(deg(a), 5);
    return s;
  });
  row("v_x min [m/s]", [](const RunOnResult& res) { return format_g(res.extremes.vx_min); });
  row("v_x max [m/s]", [](const RunOnResult& res) { return format_g(res.extremes.vx_max); });
  row("a_x min [m/s^2]", [](const RunOnResult& res) { return format_g(res.extremes.ax_min); });
  row("a_x max [m/s^2]", [](const RunOnResult& res) { return format_g(res.extremes.ax_max); });
  row("travel per period [mm]",
      [](const RunOnResult& res) { return format_g(res.series.x.back() * 1e3); });
  if (r.sampling.strand_mass) {
    row("max |inertial force| [N]", [&](const RunOnResult& res) {
      return format_g(*r.sampling.strand_mass *
                      std::max(std::abs(res.extremes.ax_min), std::abs(res.extremes.ax_max)));
    });
  }
  return out.str();
}

}  // namespace

std::function<int()> add_pocketwheel(CLI::App& app) {
  auto flags = std::make_shared<Flags>();
  CLI::App* cmd = app.add_subcommand(
      "pocketwheel",
      "Round-link chain running onto a pocket wheel (seed 003): free or guided run-on, strand "
      "position, velocity and acceleration over one tooth period");
  cmd->add_option("--pitch", flags->pitch, "chain pitch t (length; bare number: mm)");
  cmd->add_option("--wire", flags->wire, "wire diameter d of the links (length; bare: mm)");
  cmd->add_option("--teeth", flags->teeth, "number of teeth (pockets) z, >= 3");
  cmd->add_option("--omega", flags->omega, "wheel angular speed (5 1/s, 47.75 rpm; bare: 1/s)");
  cmd->add_option("--guide", flags->guide, "run-on: none|chordal|tangential|height (default none)")
      ->check(CLI::IsMember({"none", "chordal", "tangential", "height"}));
  cmd->add_option("--guide-height", flags->guide_height,
                  "guide height H for --guide height, from R cos(delta1/2) to R (bare: mm)");
  cmd->add_option("--guide-end", flags->guide_end,
                  "distance l of the guide end from the wheel axis (default 256mm, the paper's)");
  cmd->add_option("--span-model", flags->span_model,
                  "free span model: slider (the paper's bar) or pivot (bends over the guide edge)")
      ->check(CLI::IsMember({"slider", "pivot"}));
  cmd->add_option("--strand-mass", flags->strand_mass,
                  "mass moving with the strand, for the inertial force -M a_x (bare: kg)");
  cmd->add_option("--points", flags->points, "samples over [0, 2pi/z], both ends (default 721)");
  cmd->add_option("--format", flags->format, "output: table|json|csv (default table)")
      ->check(CLI::IsMember({"table", "json", "csv"}));
  cmd->add_option("--output", flags->output, "write the output to FILE instead of stdout");
  cmd->add_option("--csv", flags->csv, "also write the series as CSV to FILE");
  cmd->add_option("--svg", flags->svg,
                  "drawing of the wheel at phi = 0 (pitch circle, seated joints, strand, guide) as "
                  "SVG, mm; one --guide");
  cmd->add_option("--dxf", flags->dxf, "the same drawing as DXF (R12, mm)");
  cmd->add_option("--method", flags->method,
                  "closed (closed forms, default) or numeric (independent geometric solver)")
      ->check(CLI::IsMember({"closed", "numeric"}));
  cmd->add_flag("--example", flags->example,
                "fill missing flags with the paper's example (chain 18x64, z = 8, omega = 5 1/s, "
                "l = 256 mm); without --guide, compare free, chordal and tangential run-on");
  return [flags]() {
    const Request request = read(*flags);
    std::vector<RunOnResult> results;
    for (const Guide& guide : request.guides) results.push_back(analyse(request, guide));
    std::string text;
    if (flags->format == "json") {
      if (results.size() == 1) {
        text = to_json(request, results.front()).dump(2) + "\n";
      } else {
        nlohmann::ordered_json all = nlohmann::ordered_json::array();
        for (const auto& res : results) all.push_back(to_json(request, res));
        text = all.dump(2) + "\n";
      }
    } else if (flags->format == "csv") {
      text = to_csv(request, results);
    } else {
      text = to_table(request, results);
    }
    // Everything is computed before anything is written, and written all or nothing.
    Outputs outputs;
    if (!flags->svg.empty() || !flags->dxf.empty()) {
      if (results.size() != 1) {
        throw InputError({{flags->svg.empty() ? "--dxf" : "--svg", "given",
                           "one run-on to draw: choose --guide"}});
      }
      const io::Drawing drawing = wheel_drawing(request, results.front());
      if (!flags->svg.empty()) outputs.add("--svg", flags->svg, io::to_svg(drawing));
      if (!flags->dxf.empty()) outputs.add("--dxf", flags->dxf, io::to_dxf(drawing));
    }
    if (!flags->csv.empty()) outputs.add("--csv", flags->csv, to_csv(request, results));
    if (!flags->output.empty()) outputs.add("--output", flags->output, text);
    outputs.commit(flags->output.empty() ? text : "");
    if (!flags->csv.empty()) std::cerr << "catena: wrote the series to " << flags->csv << "\n";
    return 0;
  };
}

}  // namespace catena::cli
