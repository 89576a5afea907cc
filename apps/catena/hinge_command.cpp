// catena hinge: rolling-friction hinge synthesis, kinematics and pitch change (seed 000 §1.2–1.3);
// catena hinge sweep: the design sweep over R1.
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <tuple>

#include "catena/hinge/aperture.hpp"
#include "catena/hinge/kinematics.hpp"
#include "catena/hinge/sweep.hpp"
#include "catena/hinge/synthesis.hpp"
#include "catena/io/drawing.hpp"
#include "cli_support.hpp"
#include "commands.hpp"

namespace catena::cli {
namespace {

using io::QuantityKind;
using nlohmann::ordered_json;
using namespace catena::hinge;

struct Flags {
  std::string pin_diameter, half_thickness, plate_radius, teeth, strokes = "1", roller_radius;
  bool flat = false;
  std::string face_half_length, loaded_length;
  std::string tension, allowable_shear, contact_length, modulus = "210GPa", poisson = "0.3";
  std::string allowable_contact, pitch, friction, points = "101", format = "table", output;
  std::string svg, dxf, count = "20", clearance = "0.5mm";
};

struct Request {
  Hinge hinge;
  Loads loads;
  std::optional<double> pitch;
  int points = 101;
  int count = 20;
  double clearance = 0.5e-3;  ///< [m] aperture clearance
};

double deg(double rad) { return rad * 180.0 / std::numbers::pi; }
ordered_json opt(const std::optional<double>& v) { return v ? ordered_json(*v) : ordered_json(); }

Request read(const Flags& f, bool sweep = false) {
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
  auto optional = [&](const std::string& flag, const std::string& text, QuantityKind kind) {
    std::optional<double> v = in.quantity(flag, text, kind);
    if (!text.empty() && !v) v = NAN;
    return v;
  };
  Hinge& h = r.hinge;
  h.face = f.flat ? Face::kFlat : Face::kConcave;
  h.pin_diameter = required("--pin-diameter", f.pin_diameter, QuantityKind::kLength);
  h.half_thickness = required("--half-thickness", f.half_thickness, QuantityKind::kLength);
  if (sweep) {
    // the sweep sets R1 itself; flags that only the single analysis uses are refused, not ignored
    const std::pair<const char*, const std::string*> unused[] = {
        {"--plate-radius", &f.plate_radius},
        {"--roller-radius", &f.roller_radius},
        {"--pitch", &f.pitch},
        {"--svg", &f.svg},
        {"--dxf", &f.dxf}};
    for (auto [flag, text] : unused) {
      if (!text->empty()) in.add({flag, *text, "nothing: 'hinge sweep' does not use it"});
    }
    if (f.points != "101" || f.clearance != "0.5mm" || f.flat) {
      in.add({"--points/--clearance/--flat", "given", "nothing: 'hinge sweep' does not use them"});
    }
    // a placeholder inside the valid range; the sweep replaces it
    h.plate_radius = 1.0;
  } else {
    h.plate_radius = required("--plate-radius", f.plate_radius, QuantityKind::kLength);
  }
  if (f.teeth.empty()) {
    in.add({"--teeth", "(missing)", "a whole number z ≥ 3"});
  } else {
    h.teeth = in.integer("--teeth", f.teeth, 3).value_or(0);
  }
  h.strokes = in.integer("--strokes", f.strokes, 1).value_or(1);
  if (!f.roller_radius.empty()) {
    if (f.flat) in.add({"--roller-radius", f.roller_radius, "no R2 together with --flat"});
    h.roller_radius =
        in.quantity("--roller-radius", f.roller_radius, QuantityKind::kLength).value_or(NAN);
  }
  if (f.flat) {
    h.face_half_length = required("--face-half-length", f.face_half_length, QuantityKind::kLength);
    h.loaded_length = required("--loaded-length", f.loaded_length, QuantityKind::kLength);
  } else if (!f.face_half_length.empty() || !f.loaded_length.empty()) {
    in.add({"--face-half-length/--loaded-length", "given", "only with --flat"});
  }
  Loads& l = r.loads;
  l.tension = optional("--tension", f.tension, QuantityKind::kForce);
  l.allowable_shear = optional("--allowable-shear", f.allowable_shear, QuantityKind::kStress);
  l.contact_length = optional("--contact-length", f.contact_length, QuantityKind::kLength);
  l.allowable_contact = optional("--allowable-contact", f.allowable_contact, QuantityKind::kStress);
  const double modulus = required("--modulus", f.modulus, QuantityKind::kStress);
  char* end = nullptr;
  const double poisson = std::strtod(f.poisson.c_str(), &end);
  if (f.poisson.empty() || *end != '\0')
    in.add({"--poisson", "'" + f.poisson + "'", "a number 0 ≤ ν < 0.5"});
  l.plate = l.roller = Elastic{modulus, poisson};
  if (!f.friction.empty()) {
    const double fr = std::strtod(f.friction.c_str(), &end);
    if (*end != '\0') {
      in.add({"--friction", "'" + f.friction + "'", "a friction factor f ≥ 0"});
    } else {
      l.friction = fr;
    }
  }
  r.pitch = optional("--pitch", f.pitch, QuantityKind::kLength);
  r.points = in.integer("--points", f.points, 2).value_or(2);
  r.count = in.integer("--count", f.count, 2).value_or(2);
  r.clearance = in.quantity("--clearance", f.clearance, QuantityKind::kLength).value_or(NAN);
  in.throw_if_any();
  in.add_model_issues(validate(r.hinge));
  in.add_model_issues(validate(r.loads));
  if (r.pitch && (!std::isfinite(*r.pitch) || *r.pitch <= 0))
    in.add({"--pitch", format_g(*r.pitch), "a pitch > 0"});
  if (!(r.clearance >= 0.0) || r.clearance > 0.5 * r.hinge.pin_diameter) {
    in.add({"--clearance", f.clearance, "a clearance from 0 to d/2"});
  }
  in.throw_if_any();
  return r;
}

// The hinge drawing: aperture, roller at φ = 0 and φmax, the plate's arc, the centre's path and
// the feature points' trajectories (eq. 11).
io::Drawing hinge_drawing(const Request& r, const Synthesis& s, const Aperture& ap) {
  io::Drawing d;
  d.title = "Catena rolling-friction hinge";
  auto add = [&](const char* layer, const std::vector<Point>& pts, bool closed, double width,
                 unsigned rgb) {
    io::Polyline p{layer, {}, closed, width, rgb};
    for (const Point& q : pts) p.points.push_back({q.x, q.y});
    d.polylines.push_back(std::move(p));
  };
  add("APERTURE", ap.contour, true, 0.35, 0x000000);
  const std::vector<Point> body = roller_outline(r.hinge, s.r2);
  for (auto [layer, phi, rgb] : {std::tuple{"ROLLER_PHI0", 0.0, 0x1f77b4u},
                                 std::tuple{"ROLLER_PHIMAX", s.phi_max, 0xd62728u}}) {
    const Pose p = pose(r.hinge, s.r2, phi);
    std::vector<Point> pts;
    for (const Point& q : body) pts.push_back(roller_point(p, q));
    add(layer, pts, true, 0.25, rgb);
  }
  std::vector<Point> centre, arc;
  std::vector<std::vector<Point>> corners(4);
  const std::vector<Point> features = feature_points(r.hinge, s.r2);
  for (int i = 0; i <= 90; ++i) {
    const Pose p = pose(r.hinge, s.r2, s.phi_max * i / 90.0);
    centre.push_back(p.centre);
    arc.push_back(p.contact);
    for (std::size_t k = 0; k < 4; ++k) corners[k].push_back(roller_point(p, features[k]));
  }
  add("O2_PATH", centre, false, 0.18, 0x2ca02c);
  add("WORKING_ARC", arc, false, 0.5, 0xff7f0e);
  for (std::size_t k = 0; k < 4; ++k) add("FEATURE_PATHS", corners[k], false, 0.18, 0x9467bd);
  return d;
}

int run_hinge(const Flags& f) {
  const Request r = read(f);
  const Synthesis s = synthesize(r.hinge, r.loads);
  const std::size_t n = static_cast<std::size_t>(r.points);
  std::vector<double> phi(n), dt(n), dt_t, m1x(n), m1y(n), o2x(n), o2y(n);
  for (std::size_t i = 0; i < n; ++i) {
    phi[i] =
        i + 1 == n ? s.phi_max : s.phi_max * static_cast<double>(i) / static_cast<double>(n - 1);
    const Pose p = pose(r.hinge, s.r2, phi[i]);
    dt[i] = 2.0 * p.centre.x;
    m1x[i] = p.contact.x;
    m1y[i] = p.contact.y;
    o2x[i] = p.centre.x;
    o2y[i] = p.centre.y;
    if (r.pitch) dt_t.push_back(dt[i] / *r.pitch);
  }
  std::optional<Aperture> ap;
  if (!f.svg.empty() || !f.dxf.empty()) ap = aperture(r.hinge, s.r2, ApertureOptions{r.clearance});
  std::string text;
  if (f.format == "json") {
    ordered_json j;
    j["model"] = "hinge.rolling_friction";
    j["source"] = "000 Pudans, section 1.2-1.3, eqs. (1)-(21), corrected";
    j["face"] = r.hinge.face == Face::kFlat ? "flat" : "concave";
    j["x_N1"] = s.x_n1;
    j["psi1_max"] = s.psi1_max;
    j["gamma_max"] = s.gamma_max;
    j["phi_max"] = s.phi_max;
    j["R1"] = r.hinge.plate_radius;
    j["R1_max"] = s.r1_max;
    j["R2"] = std::isfinite(s.r2) ? ordered_json(s.r2) : ordered_json();
    j["R2_from_eq6"] = s.r2_from_eq6;
    j["a_min"] = opt(s.a_min);
    j["step1"] = s.step1 ? ordered_json{{"a_min", s.step1->a_min}, {"R1_max", s.step1->r1_max}}
                         : ordered_json();
    j["section_area"] = s.section_area;
    j["section_area_eq10"] = s.section_area_eq10;
    j["shear_stress"] = opt(s.shear_stress);
    j["rolling_limit"] = opt(s.rolling_limit);
    j["contact_stress"] = opt(s.contact_stress);
    j["contact_half_width"] = opt(s.contact_half_width);
    j["face_margin"] = s.face_margin;
    j["max_pitch_change"] = max_pitch_change(r.hinge, s.r2);
    ordered_json pc{{"phi", phi}, {"dt", dt}};
    if (r.pitch) pc["dt_over_t"] = dt_t;
    j["pitch_change"] = pc;
    j["trajectories"] = {{"phi", phi}, {"M1x", m1x}, {"M1y", m1y}, {"O2x", o2x}, {"O2y", o2y}};
    if (ap) {
      double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
      for (const Point& q : ap->contour) {
        xmin = std::min(xmin, q.x), xmax = std::max(xmax, q.x), ymin = std::min(ymin, q.y),
        ymax = std::max(ymax, q.y);
      }
      j["aperture"] = {{"clearance", ap->clearance},
                       {"points", ap->contour.size()},
                       {"xmin", xmin},
                       {"xmax", xmax},
                       {"ymin", ymin},
                       {"ymax", ymax}};
    }
    j["diagnostics"] = diagnostics_json(s.diagnostics);
    j["units"] = {{"x_N1", "m"},
                  {"psi1_max", "rad"},
                  {"gamma_max", "rad"},
                  {"phi_max", "rad"},
                  {"R1", "m"},
                  {"R1_max", "m"},
                  {"R2", "m"},
                  {"a_min", "m"},
                  {"section_area", "m^2"},
                  {"section_area_eq10", "m^2"},
                  {"shear_stress", "Pa"},
                  {"rolling_limit", "rad"},
                  {"contact_stress", "Pa"},
                  {"contact_half_width", "m"},
                  {"face_margin", "m"},
                  {"max_pitch_change", "m"},
                  {"phi", "rad"},
                  {"dt", "m"},
                  {"dt_over_t", "1"},
                  {"M1x", "m"},
                  {"M1y", "m"},
                  {"O2x", "m"},
                  {"O2y", "m"},
                  {"clearance", "m"},
                  {"xmin", "m"},
                  {"xmax", "m"},
                  {"ymin", "m"},
                  {"ymax", "m"},
                  {"limit", "SI"}};
    text = j.dump(2) + "\n";
  } else if (f.format == "csv") {
    std::ostringstream out;
    out << "phi,dt" << (r.pitch ? ",dt_over_t" : "") << ",M1x,M1y,O2x,O2y\n";
    for (std::size_t i = 0; i < n; ++i) {
      out << format_g(phi[i], 12) << "," << format_g(dt[i], 12);
      if (r.pitch) out << "," << format_g(dt_t[i], 12);
      out << "," << format_g(m1x[i], 12) << "," << format_g(m1y[i], 12) << ","
          << format_g(o2x[i], 12) << "," << format_g(o2y[i], 12) << "\n";
    }
    text = out.str();
  } else {
    std::ostringstream out;
    char line[256];
    auto row = [&](const char* label, const std::string& value) {
      std::snprintf(line, sizeof line, "  %-42s %s\n", label, value.c_str());
      out << line;
    };
    out << "Catena hinge: rolling-friction hinge (seed 000 section 1.2-1.3), "
        << (r.hinge.face == Face::kFlat ? "flat" : "concave") << " roller faces\n";
    out << "d = " << format_g(r.hinge.pin_diameter * 1e3)
        << " mm, a = " << format_g(r.hinge.half_thickness * 1e3)
        << " mm, R1 = " << format_g(r.hinge.plate_radius * 1e3) << " mm, z = " << r.hinge.teeth
        << ", m = " << r.hinge.strokes << "\n\n";
    row("gamma_max, roller turn (eq. 12) [deg]", format_g(deg(s.gamma_max)));
    row("x of N1 (eq. 4) [mm]", format_g(s.x_n1 * 1e3));
    row("psi1_max (eq. 5) [deg]", format_g(deg(s.psi1_max)));
    row("R1_max (eq. 7) [mm]", format_g(s.r1_max * 1e3));
    row(s.r2_from_eq6 ? "R2 (eq. 6) [mm]" : "R2 (given) [mm]",
        std::isfinite(s.r2) ? format_g(s.r2 * 1e3) : "flat");
    row("face margin at phi_max [mm]", format_g(s.face_margin * 1e3));
    row("section: true / eq. (10) [mm^2]",
        format_g(s.section_area * 1e6) + " / " + format_g(s.section_area_eq10 * 1e6));
    if (s.a_min) row("a_min (eq. 10) [mm]", format_g(*s.a_min * 1e3));
    if (s.step1) {
      row("step 1, eqs. (7)+(10): a_min / R1max [mm]",
          format_g(s.step1->a_min * 1e3) + " / " + format_g(s.step1->r1_max * 1e3));
    }
    if (s.shear_stress) row("shear stress F/A [MPa]", format_g(*s.shear_stress / 1e6));
    if (s.contact_stress)
      row("Hertz contact stress sigma_H [MPa]", format_g(*s.contact_stress / 1e6));
    if (s.rolling_limit) row("rolling limit (eq. 21) [deg]", format_g(deg(*s.rolling_limit)));
    row("largest |pitch change| [mm]", format_g(max_pitch_change(r.hinge, s.r2) * 1e3));
    row("pitch change at phi_max [mm]", format_g(dt.back() * 1e3));
    if (r.pitch) row("pitch change at phi_max / t [-]", format_g(dt_t.back()));
    for (const Diagnostic& d : s.diagnostics)
      out << "\n" << to_string(d.severity) << ": " << d.message << "\n";
    text = out.str();
  }
  // everything is computed before any file is written, and the files are written all or nothing
  Outputs outputs;
  if (ap) {
    const io::Drawing drawing = hinge_drawing(r, s, *ap);
    if (!f.svg.empty()) outputs.add("--svg", f.svg, io::to_svg(drawing));
    if (!f.dxf.empty()) outputs.add("--dxf", f.dxf, io::to_dxf(drawing));
  }
  if (!f.output.empty()) outputs.add("--output", f.output, text);
  outputs.commit(f.output.empty() ? text : "");
  return 0;
}

int run_sweep(const Flags& f) {
  const Request r = read(f, true);
  const Sweep sw = sweep(r.hinge, r.loads, r.count);
  std::string text;
  auto cell = [](const std::optional<double>& v, double scale) {
    return v ? format_g(*v * scale) : std::string("-");
  };
  if (f.format == "json") {
    ordered_json rows = ordered_json::array();
    for (const SweepRow& row : sw.rows) {
      rows.push_back({{"R1", row.r1},
                      {"R2", row.r2},
                      {"psi1_max", row.psi1_max},
                      {"effective_radius", row.effective_radius},
                      {"contact_stress", opt(row.contact_stress)},
                      {"rolling_limit", opt(row.rolling_limit)},
                      {"a_min", opt(row.a_min)},
                      {"max_pitch_change", row.max_pitch_change},
                      {"face_margin", row.face_margin},
                      {"feasible", row.feasible}});
    }
    ordered_json j{{"model", "hinge.rolling_friction_sweep"},
                   {"source", "000 Pudans, section 1.2, eqs. (4)-(7), (10), (21), corrected"},
                   {"rows", rows},
                   {"best", sw.best ? ordered_json(*sw.best) : ordered_json()},
                   {"criterion", sw.criterion},
                   {"units",
                    {{"R1", "m"},
                     {"R2", "m"},
                     {"psi1_max", "rad"},
                     {"effective_radius", "m"},
                     {"contact_stress", "Pa"},
                     {"rolling_limit", "rad"},
                     {"a_min", "m"},
                     {"max_pitch_change", "m"},
                     {"face_margin", "m"}}}};
    text = j.dump(2) + "\n";
  } else {
    const bool csv = f.format == "csv";
    std::ostringstream out;
    if (csv) {
      out << "R1,R2,psi1_max,effective_radius,contact_stress,rolling_limit,a_min,max_pitch_change,"
             "face_margin,feasible\n";
    } else {
      out << "Catena hinge sweep: R1 up to R1max with R2 from eq. (6) (seed 000 section 1.2)\n\n";
      char head[256];
      std::snprintf(head, sizeof head, "  %10s %12s %10s %12s %12s %10s %10s %10s %9s\n", "R1 [mm]",
                    "R2 [mm]", "psi1 [deg]", "R* [mm]", "sigmaH [MPa]", "roll [deg]", "a_min [mm]",
                    "|dt| [mm]", "feasible");
      out << head;
    }
    for (std::size_t i = 0; i < sw.rows.size(); ++i) {
      const SweepRow& row = sw.rows[i];
      if (csv) {
        out << format_g(row.r1, 12) << "," << format_g(row.r2, 12) << ","
            << format_g(row.psi1_max, 12) << "," << format_g(row.effective_radius, 12) << ","
            << (row.contact_stress ? format_g(*row.contact_stress, 12) : "") << ","
            << (row.rolling_limit ? format_g(*row.rolling_limit, 12) : "") << ","
            << (row.a_min ? format_g(*row.a_min, 12) : "") << ","
            << format_g(row.max_pitch_change, 12) << "," << format_g(row.face_margin, 12) << ","
            << (row.feasible ? 1 : 0) << "\n";
      } else {
        char line[256];
        std::snprintf(line, sizeof line, "%s %10s %12s %10s %12s %12s %10s %10s %10s %9s\n",
                      sw.best && *sw.best == i ? "*" : " ", format_g(row.r1 * 1e3).c_str(),
                      format_g(row.r2 * 1e3).c_str(), format_g(deg(row.psi1_max)).c_str(),
                      format_g(row.effective_radius * 1e3).c_str(),
                      cell(row.contact_stress, 1e-6).c_str(),
                      row.rolling_limit ? format_g(deg(*row.rolling_limit)).c_str() : "-",
                      cell(row.a_min, 1e3).c_str(), format_g(row.max_pitch_change * 1e3).c_str(),
                      row.feasible ? "yes" : "no");
        out << line;
      }
    }
    if (!csv) out << "\n* best: " << sw.criterion << "\n";
    text = out.str();
  }
  write_text_output(f.output, text);
  return 0;
}

}  // namespace

std::function<int()> add_hinge(CLI::App& app) {
  auto f = std::make_shared<Flags>();
  CLI::App* cmd = app.add_subcommand(
      "hinge",
      "Rolling-friction hinge (seed 000 section 1.2-1.3): synthesis, contact point and roller "
      "centre trajectories, pitch change; 'hinge sweep' for the design sweep over R1");
  cmd->add_option("--pin-diameter", f->pin_diameter,
                  "d, diameter of the roller's cylindrical part (bare: mm)");
  cmd->add_option("--half-thickness", f->half_thickness,
                  "a, roller centre to its working face (flat faces: b of fig. 8) (bare: mm)");
  cmd->add_option("--plate-radius", f->plate_radius,
                  "R1, the plate's convex working arc (bare: mm)");
  cmd->add_option("--teeth", f->teeth, "z, sprocket teeth");
  cmd->add_option("--strokes", f->strokes,
                  "m, sprocket strokes (default 1): gamma_max = 180deg m/z");
  cmd->add_option("--roller-radius", f->roller_radius, "R2 of the concave faces (default: eq. 6)");
  cmd->add_flag("--flat", f->flat, "flat roller faces (section 1.3.1)");
  cmd->add_option("--face-half-length", f->face_half_length,
                  "flat faces: a of fig. 8, half the face length L");
  cmd->add_option(
      "--loaded-length", f->loaded_length,
      "flat faces: c of fig. 8, face length loaded in straight running (contact at c - a)");
  cmd->add_option("--tension", f->tension, "chain tension F (bare: N)");
  cmd->add_option("--allowable-shear", f->allowable_shear, "[tau] of the roller (bare: MPa)");
  cmd->add_option("--contact-length", f->contact_length,
                  "length of the R1-R2 line contact (bare: mm)");
  cmd->add_option("--modulus", f->modulus, "Young's modulus of plate and roller (default 210GPa)");
  cmd->add_option("--poisson", f->poisson, "Poisson's ratio (default 0.3)");
  cmd->add_option("--allowable-contact", f->allowable_contact, "[sigma_H] (bare: MPa)");
  cmd->add_option("--pitch", f->pitch, "chain pitch t, for dt/t (bare: mm)");
  cmd->add_option("--friction", f->friction,
                  "friction factor f roller-plate, for the rolling limit");
  cmd->add_option("--points", f->points, "samples over [0, phi_max], both ends (default 101)");
  cmd->add_option("--format", f->format, "table|json|csv (default table)")
      ->check(CLI::IsMember({"table", "json", "csv"}));
  cmd->add_option("--output", f->output, "write the output to FILE instead of stdout");
  cmd->add_option("--svg", f->svg,
                  "hinge drawing (aperture, roller at 0 and phi_max, paths) as SVG, mm");
  cmd->add_option("--dxf", f->dxf, "the same drawing as DXF (R12, mm; aperture on layer APERTURE)");
  cmd->add_option("--clearance", f->clearance,
                  "aperture clearance off the working arc (default 0.5mm)");
  CLI::App* sw = cmd->add_subcommand("sweep", "design sweep over R1 up to R1max (table/json/csv)");
  sw->fallthrough();
  sw->add_option("--count", f->count, "number of R1 values (default 20)");
  return [f, sw]() { return sw->parsed() ? run_sweep(*f) : run_hinge(*f); };
}

}  // namespace catena::cli
