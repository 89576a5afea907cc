// `hinge` and `hinge sweep` — the rolling-friction hinge (seed 000 §1.2–1.3) — as analyses.
#include "catena/hinge/analysis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>
#include <tuple>

#include "catena/core/progress.hpp"
#include "catena/hinge/kinematics.hpp"

namespace catena::hinge {
namespace {

using analysis::format_g;
using analysis::Inputs;
using analysis::Record;
using analysis::Value;

double deg(double rad) { return rad * 180.0 / std::numbers::pi; }

// The faces: R2 belongs to concave faces, the face lengths a and c of fig. 8 to flat ones.
void check_faces(const Inputs& in, std::vector<Issue>& issues) {
  const bool flat = in.flag("flat");
  if (flat && in.given("roller_radius"))
    issues.push_back({"roller_radius", in.text("roller_radius"), "no R2 together with --flat"});
  if (flat) {
    for (const char* key : {"face_half_length", "loaded_length"}) {
      if (!in.present(key)) issues.push_back({key, "(missing)", "a value"});
    }
  } else if (in.given("face_half_length") || in.given("loaded_length")) {
    issues.push_back({"--face-half-length/--loaded-length", "given", "only with --flat"});
  }
}

// The sweep sets R1 itself: values that only the single analysis uses are refused, not ignored.
void check_sweep(const Inputs& in, std::vector<Issue>& issues) {
  for (const char* key : {"plate_radius", "roller_radius", "pitch", "svg", "dxf"}) {
    if (in.given(key))
      issues.push_back({key, in.text(key), "nothing: 'hinge sweep' does not use it"});
  }
  if (in.text("points") != "101" || in.text("clearance") != "0.5mm" || in.flag("flat")) {
    issues.push_back(
        {"--points/--clearance/--flat", "given", "nothing: 'hinge sweep' does not use them"});
  }
  check_faces(in, issues);
}

// The hinge and its loads as both analyses read them; the sweep's R1 is a placeholder inside
// the valid range (the sweep replaces it).
void read_hinge(const Inputs& in, bool sweep, Hinge& h, Loads& l) {
  h.face = in.flag("flat") ? Face::kFlat : Face::kConcave;
  h.pin_diameter = in.number("pin_diameter");
  h.half_thickness = in.number("half_thickness");
  h.plate_radius = sweep ? 1.0 : in.number("plate_radius");
  h.teeth = in.integer("teeth");
  h.strokes = in.integer("strokes");
  if (in.present("roller_radius")) h.roller_radius = in.number("roller_radius");
  if (h.face == Face::kFlat) {
    h.face_half_length = in.number("face_half_length");
    h.loaded_length = in.number("loaded_length");
  }
  l.tension = in.optional("tension");
  l.allowable_shear = in.optional("allowable_shear");
  l.contact_length = in.optional("contact_length");
  l.allowable_contact = in.optional("allowable_contact");
  l.plate = l.roller = Elastic{in.number("modulus"), in.number("poisson")};
  l.friction = in.optional("friction");
}

// Model checks, after every value could be read.
void validate_inputs(const Inputs& in, const Hinge& h, const Loads& l) {
  std::vector<Issue> issues = validate(h);
  const auto found = validate(l);
  issues.insert(issues.end(), found.begin(), found.end());
  const std::optional<double> pitch = in.optional("pitch");
  if (pitch && (!std::isfinite(*pitch) || *pitch <= 0)) {
    issues.push_back({"pitch", format_g(*pitch), "a pitch > 0"});
  } else if (pitch && std::isfinite(h.pin_diameter) && h.pin_diameter > 0 &&
             !(*pitch > h.pin_diameter)) {  // the pins of one link would overlap
    issues.push_back({"pitch", in.text("pitch"),
                      "a pitch t > the pin diameter d = " + format_g(h.pin_diameter * 1e3) +
                          " mm (two pins a pitch apart)"});
  }
  const double clearance = in.number("clearance");
  if (!(clearance >= 0.0) || clearance > 0.5 * h.pin_diameter)
    issues.push_back({"clearance", in.text("clearance"), "a clearance from 0 to d/2"});
  throw_if_any(issues);
}

// The hinge drawing: aperture, roller at φ = 0 and φmax, the plate's arc, the centre's path and
// the feature points' trajectories (eq. 11).
Drawing hinge_drawing(const HingeAnalysis& a) {
  const Hinge& hinge = a.hinge;
  const Synthesis& s = a.synthesis;
  Drawing d;
  d.title = "Catena rolling-friction hinge";
  auto add = [&](const char* layer, const std::vector<Point>& pts, bool closed, double width,
                 unsigned rgb) {
    Polyline p{layer, {}, closed, width, rgb};
    for (const Point& q : pts) p.points.push_back({q.x, q.y});
    d.polylines.push_back(std::move(p));
  };
  add("APERTURE", a.aperture->contour, true, 0.35, 0x000000);
  const std::vector<Point> body = roller_outline(hinge, s.r2);
  for (auto [layer, phi, rgb] : {std::tuple{"ROLLER_PHI0", 0.0, 0x1f77b4u},
                                 std::tuple{"ROLLER_PHIMAX", s.phi_max, 0xd62728u}}) {
    const Pose p = pose(hinge, s.r2, phi);
    std::vector<Point> pts;
    for (const Point& q : body) pts.push_back(roller_point(p, q));
    add(layer, pts, true, 0.25, rgb);
  }
  std::vector<Point> centre, arc;
  std::vector<std::vector<Point>> corners(4);
  const std::vector<Point> features = feature_points(hinge, s.r2);
  for (int i = 0; i <= 90; ++i) {
    const Pose p = pose(hinge, s.r2, s.phi_max * i / 90.0);
    centre.push_back(p.centre);
    arc.push_back(p.contact);
    for (std::size_t k = 0; k < 4; ++k) corners[k].push_back(roller_point(p, features[k]));
  }
  add("O2_PATH", centre, false, 0.18, 0x2ca02c);
  add("WORKING_ARC", arc, false, 0.5, 0xff7f0e);
  for (std::size_t k = 0; k < 4; ++k) add("FEATURE_PATHS", corners[k], false, 0.18, 0x9467bd);
  return d;
}

Value hinge_value(const HingeAnalysis& a) {
  const Synthesis& s = a.synthesis;
  Value j = Value::object();
  j["model"] = "hinge.rolling_friction";
  j["source"] = "000 Pudans, section 1.2-1.3, eqs. (1)-(21), corrected";
  j["face"] = a.hinge.face == Face::kFlat ? "flat" : "concave";
  j["x_N1"] = s.x_n1;
  j["psi1_max"] = s.psi1_max;
  j["gamma_max"] = s.gamma_max;
  j["phi_max"] = s.phi_max;
  j["R1"] = a.hinge.plate_radius;
  j["R1_max"] = s.r1_max;
  j["R2"] = std::isfinite(s.r2) ? Value(s.r2) : Value();
  j["R2_from_eq6"] = s.r2_from_eq6;
  j["a_min"] = s.a_min;
  j["step1"] =
      s.step1 ? Value::object({{"a_min", s.step1->a_min}, {"R1_max", s.step1->r1_max}}) : Value();
  j["section_area"] = s.section_area;
  j["section_area_eq10"] = s.section_area_eq10;
  j["shear_stress"] = s.shear_stress;
  j["rolling_limit"] = s.rolling_limit;
  j["contact_stress"] = s.contact_stress;
  j["contact_half_width"] = s.contact_half_width;
  j["face_margin"] = s.face_margin;
  j["max_pitch_change"] = a.max_pitch_change;
  Value pc = Value::object({{"phi", a.phi}, {"dt", a.dt}});
  if (a.pitch) pc["dt_over_t"] = a.dt_over_t;
  j["pitch_change"] = std::move(pc);
  j["trajectories"] = Value::object(
      {{"phi", a.phi}, {"M1x", a.m1x}, {"M1y", a.m1y}, {"O2x", a.o2x}, {"O2y", a.o2y}});
  if (a.aperture) {
    double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
    for (const Point& q : a.aperture->contour) {
      xmin = std::min(xmin, q.x), xmax = std::max(xmax, q.x), ymin = std::min(ymin, q.y),
      ymax = std::max(ymax, q.y);
    }
    j["aperture"] = Value::object({{"clearance", a.aperture->clearance},
                                   {"points", a.aperture->contour.size()},
                                   {"xmin", xmin},
                                   {"xmax", xmax},
                                   {"ymin", ymin},
                                   {"ymax", ymax}});
  }
  j["diagnostics"] = analysis::diagnostics_value(s.diagnostics);
  j["units"] = analysis::units_value({{"x_N1", "m"},
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
                                      {"limit", "SI"}});
  return j;
}

std::string hinge_table(const HingeAnalysis& a) {
  const Synthesis& s = a.synthesis;
  const Hinge& h = a.hinge;
  std::ostringstream out;
  char line[256];
  auto row = [&](const char* label, const std::string& value) {
    std::snprintf(line, sizeof line, "  %-42s %s\n", label, value.c_str());
    out << line;
  };
  out << "Catena hinge: rolling-friction hinge (seed 000 section 1.2-1.3), "
      << (h.face == Face::kFlat ? "flat" : "concave") << " roller faces\n";
  out << "d = " << format_g(h.pin_diameter * 1e3) << " mm, a = " << format_g(h.half_thickness * 1e3)
      << " mm, R1 = " << format_g(h.plate_radius * 1e3) << " mm, z = " << h.teeth
      << ", m = " << h.strokes << "\n\n";
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
  row("largest |pitch change| [mm]", format_g(a.max_pitch_change * 1e3));
  row("pitch change at phi_max [mm]", format_g(a.dt.back() * 1e3));
  if (a.pitch) row("pitch change at phi_max / t [-]", format_g(a.dt_over_t.back()));
  for (const Diagnostic& d : s.diagnostics)
    out << "\n" << to_string(d.severity) << ": " << d.message << "\n";
  return out.str();
}

Record describe_hinge(const HingeAnalysis& a, const Inputs&) {
  Record rec;
  rec.data = hinge_value(a);
  rec.diagnostics = a.synthesis.diagnostics;
  rec.table = hinge_table(a);
  rec.columns = {{"phi", a.phi}, {"dt", a.dt}};
  if (a.pitch) rec.columns.push_back({"dt_over_t", a.dt_over_t});
  rec.columns.push_back({"M1x", a.m1x});
  rec.columns.push_back({"M1y", a.m1y});
  rec.columns.push_back({"O2x", a.o2x});
  rec.columns.push_back({"O2y", a.o2y});
  if (a.aperture) rec.drawings.push_back(hinge_drawing(a));
  const Value& r = rec.data;
  rec.charts.push_back(analysis::series_chart(
      r, r.at("pitch_change"), "Pitch change over the roller turn", "phi", {"dt"}, "Δt"));
  const Value& t = r.at("trajectories");
  analysis::Chart paths;
  paths.title = "Contact point M1 and roller centre O2 (plate frame)";
  paths.x_label = "x [mm]";
  paths.y_label = "y [mm]";
  paths.equal_axes = true;
  paths.traces.push_back({"contact point M1", t.at("M1x").numbers(1e3), t.at("M1y").numbers(1e3)});
  paths.traces.push_back({"roller centre O2", t.at("O2x").numbers(1e3), t.at("O2y").numbers(1e3)});
  rec.charts.push_back(std::move(paths));
  return rec;
}

// An optional value as a number: NaN when absent (an empty CSV cell, a gap in a chart).
double or_nan(const std::optional<double>& v) { return v ? *v : NAN; }

Value sweep_value(const SweepAnalysis& a) {
  const Sweep& sw = a.sweep;
  Value rows = Value::array();
  for (const SweepRow& row : sw.rows) {
    rows.push_back(Value::object({{"R1", row.r1},
                                  {"R2", row.r2},
                                  {"psi1_max", row.psi1_max},
                                  {"effective_radius", row.effective_radius},
                                  {"contact_stress", row.contact_stress},
                                  {"rolling_limit", row.rolling_limit},
                                  {"a_min", row.a_min},
                                  {"max_pitch_change", row.max_pitch_change},
                                  {"face_margin", row.face_margin},
                                  {"feasible", row.feasible}}));
  }
  return Value::object({{"model", "hinge.rolling_friction_sweep"},
                        {"source", "000 Pudans, section 1.2, eqs. (4)-(7), (10), (21), corrected"},
                        {"rows", std::move(rows)},
                        {"best", sw.best ? Value(*sw.best) : Value()},
                        {"criterion", sw.criterion},
                        {"units", analysis::units_value({{"R1", "m"},
                                                         {"R2", "m"},
                                                         {"psi1_max", "rad"},
                                                         {"effective_radius", "m"},
                                                         {"contact_stress", "Pa"},
                                                         {"rolling_limit", "rad"},
                                                         {"a_min", "m"},
                                                         {"max_pitch_change", "m"},
                                                         {"face_margin", "m"}})}});
}

std::string sweep_table(const SweepAnalysis& a) {
  const Sweep& sw = a.sweep;
  auto cell = [](const std::optional<double>& v, double scale) {
    return v ? format_g(*v * scale) : std::string("-");
  };
  std::ostringstream out;
  out << "Catena hinge sweep: R1 up to R1max with R2 from eq. (6) (seed 000 section 1.2)\n\n";
  char head[256];
  std::snprintf(head, sizeof head, "  %10s %12s %10s %12s %12s %10s %10s %10s %9s\n", "R1 [mm]",
                "R2 [mm]", "psi1 [deg]", "R* [mm]", "sigmaH [MPa]", "roll [deg]", "a_min [mm]",
                "|dt| [mm]", "feasible");
  out << head;
  for (std::size_t i = 0; i < sw.rows.size(); ++i) {
    const SweepRow& row = sw.rows[i];
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
  out << "\n* best: " << sw.criterion << "\n";
  return out.str();
}

Record describe_sweep(const SweepAnalysis& a, const Inputs&) {
  Record rec;
  rec.data = sweep_value(a);
  rec.table = sweep_table(a);
  std::vector<analysis::Column> cols = {{"R1", {}},
                                        {"R2", {}},
                                        {"psi1_max", {}},
                                        {"effective_radius", {}},
                                        {.name = "contact_stress", .blank_nan = true},
                                        {.name = "rolling_limit", .blank_nan = true},
                                        {.name = "a_min", .blank_nan = true},
                                        {"max_pitch_change", {}},
                                        {"face_margin", {}},
                                        {"feasible", {}}};
  for (const SweepRow& row : a.sweep.rows) {
    const double values[] = {row.r1,
                             row.r2,
                             row.psi1_max,
                             row.effective_radius,
                             or_nan(row.contact_stress),
                             or_nan(row.rolling_limit),
                             or_nan(row.a_min),
                             row.max_pitch_change,
                             row.face_margin,
                             row.feasible ? 1.0 : 0.0};
    for (std::size_t c = 0; c < cols.size(); ++c) cols[c].values.push_back(values[c]);
  }
  rec.columns = std::move(cols);
  // the report: the design quantities versus R1 (the rows themselves become its Designs grid)
  const Value& r = rec.data;
  Value table = Value::object();
  for (const char* key : {"R1", "contact_stress", "rolling_limit", "max_pitch_change"}) {
    Value column = Value::array();
    for (const Value& row : r.at("rows").as_array()) column.push_back(row.at(key));
    table[key] = std::move(column);
  }
  rec.charts.push_back(analysis::series_chart(r, table, "Hertz contact stress versus R1", "R1",
                                              {"contact_stress"}, "σH"));
  rec.charts.push_back(analysis::series_chart(r, table, "Rolling limit versus R1", "R1",
                                              {"rolling_limit"}, "rolling limit"));
  rec.charts.push_back(analysis::series_chart(r, table, "Largest pitch change versus R1", "R1",
                                              {"max_pitch_change"}, "|Δt|"));
  rec.design_keys = {"R1", "R2"};
  rec.labels = {{"psi1_max", "ψ1max", ""},
                {"effective_radius", "R*", ""},
                {"contact_stress", "σH", ""},
                {"rolling_limit", "γ roll (eq. 21)", ""},
                {"a_min", "a min", ""},
                {"max_pitch_change", "|Δt| max", ""},
                {"face_margin", "face margin", ""}};
  return rec;
}

// A parameter of the single analysis that the sweep takes only to refuse it: on the command line
// only, never from a case file (its own table nor the shared ones).
analysis::Parameter refused(analysis::Parameter p) {
  p = std::move(p) | analysis::NotShared{} | analysis::CliOnly{};
  p.doc += "; refused: 'hinge sweep' does not use it";
  return p;
}

// The parameters of both, in the order the command read them (messages come out in that order).
std::vector<analysis::Parameter> parameters(bool sweep) {
  using namespace analysis;
  using K = QuantityKind;
  std::vector<Parameter> p;
  p.push_back(quantity("pin_diameter", K::kLength, "d, diameter of the roller's cylindrical part") |
              Required{});
  p.push_back(quantity("half_thickness", K::kLength,
                       "a, roller centre to its working face (flat faces: b of fig. 8)") |
              Required{});
  if (sweep) {
    p.push_back(refused(text("plate_radius", "R1: the sweep sets it")));
  } else {
    p.push_back(quantity("plate_radius", K::kLength, "R1, the plate's convex working arc") |
                Required{});
  }
  p.push_back(integer("teeth", 3, "z, sprocket teeth") | Required{"a whole number z ≥ 3"});
  p.push_back(integer("strokes", 1, "m, sprocket strokes: gamma_max = 180deg m/z") | Default{"1"});
  Parameter roller_radius =
      quantity("roller_radius", K::kLength, "R2 of the concave faces (default: eq. 6)");
  Parameter flat = analysis::flag("flat", "flat roller faces (section 1.3.1)");
  Parameter face_half_length =
      quantity("face_half_length", K::kLength, "flat faces: a of fig. 8, half the face length L");
  Parameter loaded_length = quantity(
      "loaded_length", K::kLength,
      "flat faces: c of fig. 8, face length loaded in straight running (contact at c - a)");
  if (sweep) {
    for (Parameter* each : {&roller_radius, &flat, &face_half_length, &loaded_length})
      *each = refused(*each);
  }
  p.push_back(roller_radius);
  p.push_back(flat);
  p.push_back(face_half_length);
  p.push_back(loaded_length);
  p.push_back(quantity("tension", K::kForce, "chain tension F"));
  p.push_back(quantity("allowable_shear", K::kStress, "[tau] of the roller"));
  p.push_back(quantity("contact_length", K::kLength, "length of the R1-R2 line contact"));
  p.push_back(quantity("allowable_contact", K::kStress, "[sigma_H]"));
  p.push_back(quantity("modulus", K::kStress, "Young's modulus of plate and roller") |
              Default{"210GPa"});
  Parameter poisson = number("poisson", "Poisson's ratio") | Default{"0.3"};
  poisson.expected = "a number 0 ≤ ν < 0.5";
  p.push_back(poisson);
  Parameter friction = number("friction", "friction factor f roller-plate, for the rolling limit");
  friction.expected = "a friction factor f ≥ 0";
  p.push_back(friction);
  Parameter pitch = quantity("pitch", K::kLength, "chain pitch t, for dt/t");
  // Work: 85 µs and 860 B a point (10⁶ points: 85 s, 862 MB max RSS; docs/reliability.md).
  Parameter points = integer("points", 2, "samples over [0, phi_max], both ends") | Default{"101"} |
                     Work{.cap = 100000, .seconds = 85e-6, .bytes = 860.0};
  Parameter clearance =
      quantity("clearance", K::kLength, "aperture clearance off the working arc") |
      Default{"0.5mm"};
  if (sweep) {
    for (Parameter* each : {&pitch, &points, &clearance}) *each = refused(*each);
  }
  p.push_back(pitch);
  p.push_back(points);
  // Work: 0.25 ms and 2.9 kB an R1 value (30 000 values: 7.6 s, 86 MB max RSS).
  if (sweep)
    p.push_back(integer("count", 2, "number of R1 values") | Default{"20"} |
                Work{.cap = 40000, .seconds = 250e-6, .bytes = 2900.0});
  p.push_back(clearance);
  if (sweep) {
    // the single analysis' drawing outputs, refused like its other flags
    p.push_back(refused(text("svg", "the hinge drawing: the sweep draws none")));
    p.push_back(refused(text("dxf", "the hinge drawing: the sweep draws none")));
  }
  return p;
}

analysis::Analysis make_hinge() {
  analysis::Analysis a;
  a.name = "hinge";
  a.command = {"hinge"};
  a.title = "Rolling-friction hinge: synthesis, kinematics, pitch change (seed 000 §1.2–1.3)";
  a.help =
      "Rolling-friction hinge (seed 000 section 1.2-1.3): synthesis, contact point and roller "
      "centre trajectories, pitch change; 'hinge sweep' for the design sweep over R1";
  a.seed = "000 §1.2–1.3";
  a.docs = "docs/models/hinge.md";
  a.chain_types = {"rolling-hinge"};
  a.formats = {.table = true, .csv = true, .drawing = true};
  a.parameters = parameters(false);
  a.check = check_faces;
  analysis::set_functions<HingeAnalysis>(a, hinge_analysis_run, describe_hinge);
  return a;
}

analysis::Analysis make_sweep() {
  analysis::Analysis a;
  a.name = "hinge_sweep";
  a.command = {"hinge", "sweep"};
  a.title = "Rolling-friction hinge: design sweep over R1 (seed 000 §1.2)";
  a.help = "design sweep over R1 up to R1max (table/json/csv)";
  a.seed = "000 §1.2";
  a.docs = "docs/models/hinge.md";
  a.chain_types = {"rolling-hinge"};
  a.formats = {.table = true, .csv = true, .drawing = false};
  a.parameters = parameters(true);
  a.check = check_sweep;
  analysis::set_functions<SweepAnalysis>(a, sweep_analysis_run, describe_sweep);
  return a;
}

}  // namespace

HingeAnalysis hinge_analysis_run(const Inputs& in) {
  HingeAnalysis a;
  read_hinge(in, false, a.hinge, a.loads);
  validate_inputs(in, a.hinge, a.loads);
  a.pitch = in.optional("pitch");
  a.synthesis = synthesize(a.hinge, a.loads);
  const Synthesis& s = a.synthesis;
  const std::size_t n = static_cast<std::size_t>(in.integer("points"));
  a.phi.resize(n), a.dt.resize(n), a.m1x.resize(n), a.m1y.resize(n), a.o2x.resize(n),
      a.o2y.resize(n);
  ProgressLoop loop(n, "points");
  for (std::size_t i = 0; i < n; ++i) {
    loop.step(i);
    a.phi[i] =
        i + 1 == n ? s.phi_max : s.phi_max * static_cast<double>(i) / static_cast<double>(n - 1);
    const Pose p = pose(a.hinge, s.r2, a.phi[i]);
    a.dt[i] = 2.0 * p.centre.x;
    a.m1x[i] = p.contact.x;
    a.m1y[i] = p.contact.y;
    a.o2x[i] = p.centre.x;
    a.o2y[i] = p.centre.y;
    if (a.pitch) a.dt_over_t.push_back(a.dt[i] / *a.pitch);
  }
  loop.step(n);
  a.max_pitch_change = max_pitch_change(a.hinge, s.r2);
  if (in.drawing_wanted())
    a.aperture = aperture(a.hinge, s.r2, ApertureOptions{in.number("clearance")});
  return a;
}

SweepAnalysis sweep_analysis_run(const Inputs& in) {
  SweepAnalysis a;
  read_hinge(in, true, a.hinge, a.loads);
  validate_inputs(in, a.hinge, a.loads);
  a.count = in.integer("count");
  a.sweep = sweep(a.hinge, a.loads, a.count);
  return a;
}

const analysis::Analysis& hinge_analysis() {
  static const analysis::Analysis a = make_hinge();
  return a;
}

const analysis::Analysis& sweep_analysis() {
  static const analysis::Analysis a = make_sweep();
  return a;
}

}  // namespace catena::hinge
