// catena engagement: chain–sprocket engagement forces for sliding and rolling hinges (seed 000
// §1.6.1–1.6.2).
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>

#include "catena/engagement/engagement.hpp"
#include "cli_support.hpp"
#include "commands.hpp"

namespace catena::cli {
namespace {

using io::QuantityKind;
using nlohmann::ordered_json;
using namespace catena::engagement;

struct Flags {
  std::string hinge, pitch, teeth, strokes = "1", tension, flank_angle = "0deg";
  std::string friction, tooth_friction, journal_diameter, tooth_diameter;
  std::string pin_diameter, half_thickness, plate_radius, roller_radius;
  std::string rolling_coefficient, tooth_arm;
  std::string points = "91", format = "table", output, wrap_angle = "180deg";
};

double deg(double rad) { return rad * 180.0 / std::numbers::pi; }

struct Request {
  bool rolling = false;
  double pitch = 0.0;
  double wrap_angle = 0.0;
  SlidingInput sliding;
  RollingInput rolling_in;
};

Request read(const Flags& f) {
  FlagReader in;
  Request r;
  auto required = [&](const std::string& flag, const std::string& text,
                      QuantityKind kind) -> double {
    if (text.empty()) {
      in.add({flag, "(missing)", "a value"});
      return NAN;
    }
    return in.quantity(flag, text, kind).value_or(NAN);
  };
  auto number = [&](const std::string& flag, const std::string& text, double fallback) -> double {
    if (text.empty()) return fallback;
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (*end != '\0') {
      in.add({flag, "'" + text + "'", "a number"});
      return NAN;
    }
    return v;
  };
  if (f.hinge != "sliding" && f.hinge != "rolling") {
    in.add({"--hinge", f.hinge.empty() ? "(missing)" : f.hinge, "sliding or rolling"});
  }
  r.rolling = f.hinge == "rolling";
  r.pitch = required("--pitch", f.pitch, QuantityKind::kLength);
  int teeth = 0;
  if (f.teeth.empty()) {
    in.add({"--teeth", "(missing)", "a whole number z >= 3"});
  } else {
    teeth = in.integer("--teeth", f.teeth, 3).value_or(0);
  }
  const int strokes = in.integer("--strokes", f.strokes, 1).value_or(1);
  const double tension = required("--tension", f.tension, QuantityKind::kForce);
  const double flank =
      in.quantity("--flank-angle", f.flank_angle, QuantityKind::kAngle).value_or(NAN);
  const int points = in.integer("--points", f.points, 2).value_or(2);
  r.wrap_angle = in.quantity("--wrap-angle", f.wrap_angle, QuantityKind::kAngle).value_or(NAN);
  // flags of the other hinge are refused, not ignored
  auto refuse = [&](std::initializer_list<std::pair<const char*, const std::string*>> list,
                    const char* why) {
    for (auto [flag, text] : list)
      if (!text->empty()) in.add({flag, *text, why});
  };
  if (r.rolling) {
    refuse({{"--friction", &f.friction},
            {"--tooth-friction", &f.tooth_friction},
            {"--journal-diameter", &f.journal_diameter},
            {"--tooth-diameter", &f.tooth_diameter}},
           "nothing: only the sliding hinge uses it");
    RollingInput& ri = r.rolling_in;
    ri.hinge.pin_diameter = required("--pin-diameter", f.pin_diameter, QuantityKind::kLength);
    ri.hinge.half_thickness = required("--half-thickness", f.half_thickness, QuantityKind::kLength);
    ri.hinge.plate_radius = required("--plate-radius", f.plate_radius, QuantityKind::kLength);
    if (!f.roller_radius.empty()) {
      ri.hinge.roller_radius =
          in.quantity("--roller-radius", f.roller_radius, QuantityKind::kLength).value_or(NAN);
    }
    ri.hinge.teeth = teeth;
    ri.hinge.strokes = strokes;
    ri.tension = tension;
    ri.flank_angle = flank;
    ri.rolling_coefficient = number("--rolling-coefficient", f.rolling_coefficient, 1e-3);
    ri.tooth_arm =
        f.tooth_arm.empty()
            ? 0.0
            : in.quantity("--tooth-arm", f.tooth_arm, QuantityKind::kLength).value_or(NAN);
    ri.points = points;
  } else {
    refuse({{"--pin-diameter", &f.pin_diameter},
            {"--half-thickness", &f.half_thickness},
            {"--plate-radius", &f.plate_radius},
            {"--roller-radius", &f.roller_radius},
            {"--rolling-coefficient", &f.rolling_coefficient},
            {"--tooth-arm", &f.tooth_arm}},
           "nothing: only the rolling hinge uses it");
    SlidingInput& si = r.sliding;
    si.tension = tension;
    si.teeth = teeth;
    si.strokes = strokes;
    si.flank_angle = flank;
    si.friction = number("--friction", f.friction, 0.0);
    si.tooth_friction = number("--tooth-friction", f.tooth_friction, -1.0);
    if (!f.tooth_friction.empty() && !(si.tooth_friction >= 0.0)) {
      in.add({"--tooth-friction", f.tooth_friction, "a friction factor >= 0"});
    }
    si.journal_diameter =
        in.quantity("--journal-diameter", f.journal_diameter.empty() ? "40mm" : f.journal_diameter,
                    QuantityKind::kLength)
            .value_or(NAN);
    si.tooth_diameter =
        in.quantity("--tooth-diameter", f.tooth_diameter.empty() ? "40mm" : f.tooth_diameter,
                    QuantityKind::kLength)
            .value_or(NAN);
    si.points = points;
  }
  in.throw_if_any();
  if (!(r.pitch > 0.0) || !std::isfinite(r.pitch)) in.add({"--pitch", f.pitch, "a pitch > 0"});
  if (!(r.wrap_angle > 0.0) || !(r.wrap_angle <= 2.0 * std::numbers::pi)) {
    in.add({"--wrap-angle", f.wrap_angle, "a wrap angle in (0, 360deg]"});
  }
  in.add_model_issues(r.rolling ? validate(r.rolling_in) : validate(r.sliding));
  in.throw_if_any();
  return r;
}

int run_engagement(const Flags& f) {
  const Request r = read(f);
  const Result res = r.rolling ? solve_rolling(r.rolling_in) : solve_sliding(r.sliding);
  const double tension = r.rolling ? r.rolling_in.tension : r.sliding.tension;
  const std::size_t n = res.series.size();
  const Wrap w = wrap(res, tension, r.pitch, r.wrap_angle);
  std::string text;
  if (f.format == "json") {
    ordered_json gamma = ordered_json::array(), f2 = ordered_json::array(),
                 fn = ordered_json::array(), xi = ordered_json::array(), rr = ordered_json::array(),
                 resid = ordered_json::array(), ff = ordered_json::array(),
                 turns = ordered_json::array();
    auto num = [](double v) { return std::isfinite(v) ? ordered_json(v) : ordered_json(); };
    for (const Sample& s : res.series) {
      gamma.push_back(s.gamma);
      f2.push_back(num(s.f2));
      fn.push_back(num(s.fn));
      resid.push_back(num(s.residual));
      if (r.rolling) {
        xi.push_back(num(s.xi));
        rr.push_back(num(std::max(s.f1k, s.f2k)));
      } else {
        xi.push_back(nullptr);
        rr.push_back(nullptr);
        ff.push_back(s.friction_force);
        turns.push_back(s.roller_turns);
      }
    }
    ordered_json series{{"gamma", gamma},           {"F2", f2},         {"FN", fn}, {"xi", xi},
                        {"rolling_resistance", rr}, {"residual", resid}};
    if (!r.rolling) {
      series["friction_force"] = ff;
      series["roller_turns"] = turns;
    }
    ordered_json ranges = ordered_json::array();
    for (const Range& g2 : res.roller_turns) ranges.push_back({{"from", g2.from}, {"to", g2.to}});
    ordered_json j;
    j["model"] = r.rolling ? "engagement.rolling_hinge" : "engagement.sliding_hinge";
    j["source"] = r.rolling ? "000 Pudans, section 1.6.2, eq. (28), reconstructed"
                            : "000 Pudans, section 1.6.1, eqs. (24)-(27), fig. 25 reconstructed";
    j["hinge"] = r.rolling ? "rolling" : "sliding";
    j["pitch"] = r.pitch;
    j["tension"] = tension;
    j["gamma_sigma"] = res.angles.gamma_sigma;
    j["angles"] = {{"alpha", res.angles.alpha},
                   {"epsilon", res.angles.epsilon},
                   {"psi", res.angles.psi},
                   {"beta1", res.angles.beta1}};
    j["series"] = series;
    j["roller_turns"] = ranges;
    j["max_residual"] = res.max_residual;
    j["wrap"] = {{"pitch_radius", w.pitch_radius},
                 {"rollers", w.rollers},
                 {"tension", w.tension},
                 {"tooth_load", w.tooth_load},
                 {"torque", w.torque}};
    j["diagnostics"] = diagnostics_json(res.diagnostics);
    j["units"] = {{"pitch", "m"},        {"tension", "N"},        {"gamma_sigma", "rad"},
                  {"alpha", "rad"},      {"epsilon", "rad"},      {"psi", "rad"},
                  {"beta1", "rad"},      {"gamma", "rad"},        {"F2", "N"},
                  {"FN", "N"},           {"xi", "rad"},           {"rolling_resistance", "N"},
                  {"residual", "1"},     {"friction_force", "N"}, {"from", "rad"},
                  {"to", "rad"},         {"max_residual", "1"},   {"limit", "SI"},
                  {"pitch_radius", "m"}, {"tooth_load", "N"},     {"torque", "N*m"}};
    text = j.dump(2) + "\n";
  } else if (f.format == "csv") {
    std::ostringstream out;
    out << "gamma,F2,FN,xi,rolling_resistance,residual\n";
    for (const Sample& s : res.series) {
      out << format_g(s.gamma, 12) << "," << format_g(s.f2, 12) << "," << format_g(s.fn, 12) << ",";
      if (r.rolling)
        out << format_g(s.xi, 12) << "," << format_g(std::max(s.f1k, s.f2k), 12);
      else
        out << ",";
      out << "," << format_g(s.residual, 6) << "\n";
    }
    text = out.str();
  } else {
    std::ostringstream out;
    out << "Catena engagement: " << (r.rolling ? "rolling" : "sliding")
        << "-friction hinge entering a sprocket (seed 000 section 1.6)\n";
    out << "F1 = " << format_g(tension / 1e3)
        << " kN, gammaSigma = " << format_g(deg(res.angles.gamma_sigma))
        << " deg, beta1 = " << format_g(deg(res.angles.beta1))
        << " deg, epsilon = " << format_g(deg(res.angles.epsilon)) << " deg\n\n";
    out << "  gamma[deg]    F2[kN]    FN[kN]   " << (r.rolling ? " xi[deg]  Fk[N]" : " turns")
        << "   residual\n";
    const std::size_t step = n > 11 ? (n - 1) / 10 : 1;
    for (std::size_t i = 0; i < n; i += step) {
      const Sample& s = res.series[i];
      char line[200];
      if (r.rolling) {
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
    for (const Diagnostic& d : res.diagnostics)
      out << "\n" << to_string(d.severity) << ": " << d.message << "\n";
    text = out.str();
  }
  write_text_output(f.output, text);
  return 0;
}

}  // namespace

std::function<int()> add_engagement(CLI::App& app) {
  auto f = std::make_shared<Flags>();
  CLI::App* cmd = app.add_subcommand(
      "engagement",
      "Chain-sprocket engagement forces F2, F_N (and the roller turn xi) for sliding and rolling "
      "hinges over one engagement, seed 000 section 1.6");
  cmd->add_option("--hinge", f->hinge, "sliding|rolling");
  cmd->add_option("--pitch", f->pitch, "chain pitch t (bare: mm)");
  cmd->add_option("--teeth", f->teeth, "z, sprocket teeth");
  cmd->add_option("--strokes", f->strokes,
                  "m, sprocket strokes (default 1); gammaSigma = 360deg*m/z");
  cmd->add_option("--tension", f->tension, "F1 of the link entering engagement (bare: N)");
  cmd->add_option(
      "--flank-angle", f->flank_angle,
      "psi, tilt of the tooth normal from the radius towards the motion (default 0deg)");
  cmd->add_option("--friction", f->friction, "sliding: f = f1, roller-plate friction (default 0)");
  cmd->add_option("--tooth-friction", f->tooth_friction,
                  "sliding: roller-tooth friction in (24)/(25) (default = --friction)");
  cmd->add_option("--journal-diameter", f->journal_diameter,
                  "sliding: d1 of (24)/(25) (default 40mm)");
  cmd->add_option("--tooth-diameter", f->tooth_diameter, "sliding: d2 of (24)/(25) (default 40mm)");
  cmd->add_option("--pin-diameter", f->pin_diameter, "rolling: d, roller's cylindrical part");
  cmd->add_option("--half-thickness", f->half_thickness, "rolling: a, centre to working face");
  cmd->add_option("--plate-radius", f->plate_radius, "rolling: R1, plate's working arc");
  cmd->add_option("--roller-radius", f->roller_radius, "rolling: R2 of the faces (default: eq. 6)");
  cmd->add_option("--rolling-coefficient", f->rolling_coefficient,
                  "rolling: c_r, rolling resistance F_k = c_r*F (default 0.001)");
  cmd->add_option("--tooth-arm", f->tooth_arm,
                  "rolling: lambda1, rolling-resistance arm of F_N at the tooth (default 0mm)");
  cmd->add_option("--wrap-angle", f->wrap_angle,
                  "whole wrap: angle of the engaged arc (default 180deg)");
  cmd->add_option("--points", f->points, "samples over [0, gammaSigma], both ends (default 91)");
  cmd->add_option("--format", f->format, "table|json|csv (default table)")
      ->check(CLI::IsMember({"table", "json", "csv"}));
  cmd->add_option("--output", f->output, "write the output to FILE instead of stdout");
  return [f]() { return run_engagement(*f); };
}

}  // namespace catena::cli
