// `dynamics` — a roller-chain loop over two ISO 606 sprockets in time (issue 21, Stage 3) — as an
// analysis. Its input is the [dynamics] table with [[dynamics.sprocket]] elements, so
// `catena dynamics case.toml` reads a case file's [dynamics] and ignores the rest.
//
// What it sets up is the drive the core's validation (6) runs (tests/validation/
// dynamics_drive_test.cpp): two equal sprockets (z even) on a horizontal line, a whole number of
// pitches apart, the chain wrapped half-way round each and straight between, every node moving at
// the driver's pitch-line speed. The centre distance is not an input: it follows from the links,
// (links − z)/2 pitches. Anything else (unequal wheels, idlers, a free layout) is refused, named.
#include "catena/dynamics/analysis.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <regex>
#include <sstream>

#include "catena/contact/chain_catalog.hpp"
#include "catena/contact/roller_tooth.hpp"
#include "catena/core/progress.hpp"
#include "catena/dynamics/integrator.hpp"
#include "catena/dynamics/report_charts.hpp"
#include "catena/io/bind.hpp"
#include "catena/io/case_file.hpp"
#include "catena/io/quantity.hpp"

namespace catena::dynamics {
namespace {

using analysis::format_g;
using analysis::InputValue;
using analysis::Parameter;
using analysis::ParameterType;
using analysis::Record;
using analysis::Value;
using Entry = analysis::InputValue::Entry;
using K = QuantityKind;
constexpr double kPi = std::numbers::pi;

// The work model of the table (analysis::Work, docs/reliability.md): link-steps, steps × links,
// refused above the cap unless allow_large is given. The drive's step costs about 0.5 µs CPU per
// link with sprockets on the reference machine (docs/performance.md: 100 µs a step at 200
// links), so the cap is about 25 s; memory is about 200 bytes a node, whatever the steps.
constexpr double kMaxSamples = 200'000;  // samples of the series
// node-samples (links × samples) of the opt-in positions: 10⁶ coordinates, about 20 MB of JSON
constexpr double kMaxPositions = 500'000;
constexpr analysis::Work kWork{.cap = 50'000'000, .seconds = 0.5e-6, .bytes = 0.0};

std::vector<Parameter> table_fields() {
  using analysis::number;
  using analysis::quantity;
  using analysis::text;
  return {
      text("chain",
           "ISO 606 designation (\"12B\"): pitch, roller, width and mass from the "
           "catalogue"),
      quantity("pitch", K::kLength, "pitch p (overrides the catalogue's)"),
      quantity("mass_per_metre", K::kMassPerLength, "chain mass per metre q"),
      quantity("roller_diameter", K::kLength, "roller diameter d1"),
      quantity("inner_width", K::kLength, "inner width b1"),
      number("links", "links in the closed loop, an integer z + 2m with m >= 2, at most 10000"),
      quantity("axial_stiffness", K::kForcePerLength, "axial stiffness k of one link [N/m]"),
      number("axial_damping", "axial damping c of one link [N s/m], >= 0 (default 0)"),
      quantity("pretension", K::kForce, "the loop's tension at rest, >= 0 (default 0)"),
      quantity("contact_stiffness", K::kForcePerLength,
               "roller-seat penalty k_c [N/m] (default: the Hertz line contact's secant "
               "stiffness at the expected load)"),
      number("contact_damping", "roller-seat damping c_c [N s/m], >= 0"),
      quantity("duration", K::kTime, "simulated time, > 0"),
      quantity("step", K::kTime, "time step h, > 0"),
      quantity("output_interval", K::kTime,
               "sampling interval of the series, rounded to whole steps (default: every step)"),
      number("theta", "theta of the integrator in [0.5, 1] (default 0.6; drives need >= 0.6)"),
      number("gravity",
             "true (9.80665 m/s^2), false, or g in [0, 100] m/s^2, downward (-y; default: none)"),
      text("work_balance",
           "true to add the run's work balance to the summary: input, friction, link and "
           "contact dampers, numerical (default false)"),
      text("positions",
           "true to add every node's x and y at each output sample to the JSON (default false; "
           "at most 500000 node-samples)")};
}

// [[dynamics.guide]]: a rail the rollers slide on (docs/models/dynamics.md, "Guides"), in the
// layout's coordinates (the driver's centre at the origin, the other wheel on +x, y up).
std::vector<Parameter> guide_fields() {
  using analysis::number;
  using analysis::quantity;
  using analysis::text;
  return {
      text("kind", "straight or arc"),
      quantity("x0", K::kLength, "straight: first end of the rail surface, x"),
      quantity("y0", K::kLength, "straight: first end, y"),
      quantity("x1", K::kLength, "straight: second end, x (rollers ride on the left going 0 -> 1)"),
      quantity("y1", K::kLength, "straight: second end, y"),
      quantity("centre_x", K::kLength, "arc: centre, x"),
      quantity("centre_y", K::kLength, "arc: centre, y"),
      quantity("radius", K::kLength, "arc: radius of the rail surface, > 0"),
      quantity("start_angle", K::kAngle, "arc: start, counter-clockwise from +x"),
      quantity("end_angle", K::kAngle, "arc: end, in (start_angle, start_angle + 360 deg]"),
      text("inside", "arc: true if the rollers ride inside the arc (default false: outside)"),
      number("friction", "Coulomb friction coefficient mu in [0, 1] (default 0)"),
      quantity("friction_band", K::kSpeed,
               "speed band of the regularised friction, in (0, 1] m/s (default 1 mm/s)"),
      quantity("contact_stiffness", K::kForcePerLength,
               "roller-rail penalty [N/m] (default: dynamics.contact_stiffness)"),
      number("contact_damping",
             "roller-rail damping [N s/m], >= 0 (default: dynamics.contact_damping)")};
}

std::vector<Parameter> sprocket_fields() {
  using analysis::number;
  using analysis::quantity;
  using analysis::text;
  return {number("teeth", "number of teeth z, an even integer in [8, 150]"),
          text("role", "driver or driven"),
          quantity("speed", K::kAngularSpeed, "driver: speed, counter-clockwise, > 0"),
          number("inertia", "driven: moment of inertia J [kg m^2], > 0"),
          number("load_torque", "driven: load torque T_L [N m], >= 0")};
}

const Parameter& table_parameter() {
  static const Parameter p = [] {
    Parameter t;
    t.name = "dynamics";
    t.type = ParameterType::kTable;
    t.doc =
        "TOML file with a [dynamics] table and two [[dynamics.sprocket]] tables (a case file "
        "works); in a case file, its own [dynamics] table";
    t.required = true;
    t.expected =
        "a [dynamics] table (chain, links, axial_stiffness, contact_stiffness, duration, step) and "
        "two [[dynamics.sprocket]] tables (docs/models/dynamics.md)";
    t.fields = table_fields();
    t.rows_name = "sprocket";
    t.row_fields = sprocket_fields();
    t.work = kWork;  // link-steps; refused by parse(), which knows steps × links
    return t;
  }();
  return p;
}

std::string where(const Entry& v) { return v.path + " (line " + std::to_string(v.line) + ")"; }

// One value as SI (a bare number takes the field's documented unit); an issue on failure.
std::optional<double> read(const Entry& v, const Parameter& key, std::vector<Issue>& issues) {
  if (!v.is_string && !v.is_number) {
    issues.push_back({where(v), v.text, "a number or a string"});
    return std::nullopt;
  }
  std::vector<Issue> found;
  std::optional<double> x;
  if (key.type == ParameterType::kNumber) {
    x = io::parse_number(v.text, where(v), "a plain number", found);
  } else {
    const bool bare = v.is_number || io::is_bare_number(v.text);
    x = io::parse_quantity(bare ? v.text + " " + io::bare_unit(key) : v.text, key.kind, where(v),
                           found);
    for (Issue& i : found) i.value = "'" + v.text + "'";
  }
  issues.insert(issues.end(), found.begin(), found.end());
  return x;
}

struct SprocketInput {
  int line = 0;
  std::optional<double> teeth, speed, inertia, load_torque;
  std::string role;
  bool has_role = false;
};

struct GuideInput {
  int line = 0;
  std::map<std::string, double> value;      // key → SI value (read successfully)
  std::map<std::string, std::string> text;  // kind, inside
  std::map<std::string, int> seen;          // every key given (read or not) → its line
};

struct Setup {
  std::string chain;
  double pitch = NAN, mass_per_metre = NAN, roller = NAN, width = NAN;
  int links = 0;
  double stiffness = NAN, damping = 0.0, pretension = 0.0;
  double contact_stiffness = NAN, contact_damping = NAN;
  double duration = NAN, step = NAN, interval = NAN, theta = 0.6;
  int teeth = 0;
  std::size_t driver = 0, driven = 1;
  double speed = NAN, inertia = NAN, load = 0.0;
  double gravity = 0.0;       // [m/s²] downward (−y)
  std::vector<Guide> guides;  // [[dynamics.guide]]
  bool work_balance = false;  // summary.work_balance in the output
  bool positions = false;     // positions {x, y} in the output
  // contact_stiffness omitted: the Hertz default (hertz_seat_stiffness) at this load [N]
  bool hertz_stiffness = false;
  double expected_load = NAN;
};

// The default roller-seat penalty when contact_stiffness is omitted (docs/models/dynamics.md,
// "Contact stiffness default"): the roller of diameter d1 in the ISO 606 seating arc (radius
// ri of the minimum tooth gap, the form the model's seats have), a plane-strain Hertz line
// contact over the inner width b1, steel on steel (E = 210 GPa, ν = 0.3), with the approach
// δ(q) of contact::slice_approach (Johnson 1985, eq. 5.36 form); linearised as the secant
// k = Q0/δ(Q0/b1) at the expected seat load Q0, so that the linear penalty gives the Hertz
// approach at that load. NaN when the geometry or the approach law has no value.
double hertz_seat_stiffness(double pitch, double roller, double width, int teeth, double load) {
  try {
    const Sprocket probe = iso606_sprocket(pitch, roller, width, teeth, 0.0, 0.0, 1.0, 0.0);
    contact::RollerTooth c;
    c.roller_diameter = roller;
    c.roller_length = width;
    c.tooth_radius = probe.seat_radius;
    c.profile = contact::Profile::kConcave;
    const double delta = contact::slice_approach(c, load / width);
    return delta > 0.0 && std::isfinite(delta) ? load / delta : NAN;
  } catch (const InputError&) {
    return NAN;
  }
}

bool is_integer(double x) { return std::isfinite(x) && x == std::floor(x); }

Setup parse(const analysis::Inputs& in) {
  const InputValue& file = in.at("dynamics");
  std::vector<Issue> issues;
  if (std::find(file.tables.begin(), file.tables.end(), "dynamics") == file.tables.end())
    throw InputError({{"dynamics", "(missing)", table_parameter().expected}});
  std::map<std::string, const Parameter*> top_keys, row_keys;
  for (const Parameter& p : table_parameter().fields) top_keys[p.name] = &p;
  for (const Parameter& p : table_parameter().row_fields) row_keys[p.name] = &p;

  std::map<std::string, double> value;  // [dynamics] key → SI value (read successfully)
  std::map<std::string, int> line;      // [dynamics] key → its line
  std::string chain;
  bool has_chain = false;
  std::vector<SprocketInput> wheels;
  std::vector<GuideInput> guides;
  static const std::vector<Parameter> guide_keys = guide_fields();
  static const std::regex row(R"(^dynamics\.sprocket\[(\d+)\]\.([^.]+)$)");
  static const std::regex guide_row(R"(^dynamics\.guide\[(\d+)\]\.([^.]+)$)");
  double gravity = 0.0;  // [m/s²] downward
  bool work_balance = false;
  bool positions = false;
  for (const Entry& v : file.table) {
    if (v.path.rfind("dynamics.", 0) != 0) continue;  // the rest of a case file is not ours
    std::smatch m;
    if (std::regex_match(v.path, m, guide_row)) {
      const std::size_t i = std::stoul(m[1]);
      if (i > 1000) {
        issues.push_back({where(v), v.text, "at most 1000 [[dynamics.guide]] tables"});
        continue;
      }
      if (guides.size() <= i) guides.resize(i + 1);
      GuideInput& g = guides[i];
      if (g.line == 0) g.line = v.line;
      const std::string key = m[2];
      const auto k = std::find_if(guide_keys.begin(), guide_keys.end(),
                                  [&](const Parameter& p) { return p.name == key; });
      if (k == guide_keys.end()) {
        std::string list;
        for (const Parameter& p : guide_keys) list += (list.empty() ? "" : ", ") + p.name;
        issues.push_back({where(v), v.text, "a key of a guide: " + list});
        continue;
      }
      g.seen[key] = v.line;
      if (key == "kind") {
        if (!v.is_string || (v.text != "straight" && v.text != "arc"))
          issues.push_back({where(v), "'" + v.text + "'", "straight or arc"});
        else
          g.text[key] = v.text;
        continue;
      }
      if (key == "inside") {
        if (!v.is_boolean)
          issues.push_back({where(v), "'" + v.text + "'", "true or false"});
        else
          g.text[key] = v.text;
        continue;
      }
      if (const auto x = read(v, *k, issues)) g.value[key] = *x;
      continue;
    }
    if (std::regex_match(v.path, m, row)) {
      const std::size_t i = std::stoul(m[1]);
      if (wheels.size() <= i) wheels.resize(i + 1);
      SprocketInput& w = wheels[i];
      if (w.line == 0) w.line = v.line;
      const std::string key = m[2];
      const auto k = row_keys.find(key);
      if (k == row_keys.end()) {
        issues.push_back(
            {where(v), v.text, "a key of a sprocket: teeth, role, speed, inertia, load_torque"});
        continue;
      }
      if (key == "role") {
        w.role = v.text;
        w.has_role = true;
        if (!v.is_string || (v.text != "driver" && v.text != "driven"))
          issues.push_back({where(v), "'" + v.text + "'", "driver or driven"});
        continue;
      }
      const auto x = read(v, *k->second, issues);
      if (!x) continue;
      if (key == "teeth") w.teeth = *x;
      if (key == "speed") w.speed = *x;
      if (key == "inertia") w.inertia = *x;
      if (key == "load_torque") w.load_torque = *x;
      continue;
    }
    const std::string key = v.path.substr(9);
    if (key == "gravity") {
      line[key] = v.line;
      if (v.is_boolean) {
        gravity = v.text == "true" ? 9.80665 : 0.0;  // standard gravity (CGPM 1901)
      } else if (v.is_number) {
        std::vector<Issue> found;
        const std::optional<double> g = io::parse_number(v.text, where(v), "a plain number", found);
        if (g && *g >= 0.0 && *g <= 100.0)
          gravity = *g;
        else if (g)
          issues.push_back({where(v), v.text, "true, false or g in [0, 100] m/s^2 (downward)"});
        issues.insert(issues.end(), found.begin(), found.end());
      } else {
        issues.push_back({where(v), "'" + v.text + "'",
                          "true, false or g in [0, 100] m/s^2 (a plain number, downward)"});
      }
      continue;
    }
    if (key == "work_balance") {
      line[key] = v.line;
      if (v.is_boolean)
        work_balance = v.text == "true";
      else
        issues.push_back({where(v), "'" + v.text + "'", "true or false"});
      continue;
    }
    if (key == "positions") {
      line[key] = v.line;
      if (v.is_boolean)
        positions = v.text == "true";
      else
        issues.push_back({where(v), "'" + v.text + "'", "true or false"});
      continue;
    }
    if (key.rfind("guide", 0) == 0) {
      issues.push_back({where(v), v.text, "guides as an array of tables: [[dynamics.guide]]"});
      continue;
    }
    if (key.rfind("sprocket", 0) == 0) {
      issues.push_back(
          {where(v), v.text, "sprockets as an array of tables: [[dynamics.sprocket]]"});
      continue;
    }
    const auto k = top_keys.find(key);
    if (k == top_keys.end()) {
      std::string list;
      for (const auto& [name, p] : top_keys) list += (list.empty() ? "" : ", ") + name;
      issues.push_back({where(v), v.text, "a key of [dynamics]: " + list});
      continue;
    }
    line[key] = v.line;
    if (key == "chain") {
      chain = v.text;
      has_chain = true;
      continue;
    }
    if (const auto x = read(v, *k->second, issues)) value[key] = *x;
  }
  auto at = [&](const std::string& key) {
    const auto l = line.find(key);
    return "dynamics." + key + (l == line.end() ? "" : " (line " + std::to_string(l->second) + ")");
  };
  auto shown = [&](double x) { return format_g(x, 6); };

  Setup s;
  // the chain: the catalogue's values, each overridable
  std::optional<contact::ChainDimensions> row_found;
  if (has_chain) {
    row_found = contact::iso606_chain(chain);
    if (!row_found) issues.push_back({at("chain"), "'" + chain + "'", "an ISO 606 designation"});
    s.chain = row_found ? row_found->name : chain;
  }
  auto chain_value = [&](const char* key, std::optional<double> from_catalogue,
                         const char* what) -> double {
    if (value.count(key)) return value[key];
    if (from_catalogue) return *from_catalogue;
    if (!line.count(key) && !(has_chain && !row_found))  // missing (not unreadable, no bad chain)
      issues.push_back({"dynamics." + std::string(key), "(missing)",
                        std::string(what) + " (or chain = an ISO 606 designation that has it)"});
    return NAN;
  };
  s.pitch = chain_value("pitch", row_found ? std::optional(row_found->pitch) : std::nullopt,
                        "the pitch p, e.g. \"19.05 mm\"");
  s.mass_per_metre =
      chain_value("mass_per_metre", row_found ? row_found->mass_per_metre : std::nullopt,
                  "the chain's mass per metre, e.g. \"1.25 kg/m\"");
  s.roller = chain_value("roller_diameter", row_found ? row_found->roller_diameter : std::nullopt,
                         "the roller diameter d1, e.g. \"12.07 mm\"");
  s.width = chain_value("inner_width", row_found ? row_found->inner_width : std::nullopt,
                        "the inner width b1, e.g. \"11.68 mm\"");
  for (const char* key : {"pitch", "mass_per_metre", "roller_diameter", "inner_width"}) {
    if (value.count(key) && !(value[key] > 0.0))
      issues.push_back({at(key), shown(value[key]), "> 0"});
  }

  auto required = [&](const char* key, const char* what) -> double {
    if (value.count(key)) return value[key];
    if (!line.count(key)) issues.push_back({"dynamics." + std::string(key), "(missing)", what});
    return NAN;
  };
  auto optional = [&](const char* key, double fallback) -> double {
    if (value.count(key)) return value[key];
    return line.count(key) ? NAN : fallback;  // unreadable: already reported
  };
  const double links = required("links", "the number of links in the loop, an integer");
  s.stiffness = required("axial_stiffness", "the axial stiffness k of one link, e.g. \"5e7 N/m\"");
  s.contact_stiffness = optional("contact_stiffness", NAN);  // omitted: the Hertz default below
  s.hertz_stiffness = !line.count("contact_stiffness");
  s.contact_damping = required("contact_damping", "the roller-seat damping c_c [N s/m], e.g. 800");
  s.duration = required("duration", "the simulated time, e.g. \"0.5 s\"");
  s.step = required("step", "the time step h, e.g. \"0.1 ms\"");
  s.damping = optional("axial_damping", 0.0);
  s.pretension = optional("pretension", 0.0);
  s.theta = optional("theta", 0.6);
  // the command line's --duration and --step override the table's
  if (in.present("duration")) s.duration = in.number("duration");
  if (in.present("step")) s.step = in.number("step");
  s.interval = optional("output_interval", s.step);

  auto positive = [&](const char* key, double x, bool cli) {
    if (!std::isnan(x) && !(x > 0.0 && std::isfinite(x)))
      issues.push_back({cli && in.present(key) ? std::string(key) : at(key), shown(x), "> 0"});
  };
  auto non_negative = [&](const char* key, double x) {
    if (!std::isnan(x) && !(x >= 0.0 && std::isfinite(x)))
      issues.push_back({at(key), shown(x), ">= 0"});
  };
  positive("axial_stiffness", s.stiffness, false);
  positive("contact_stiffness", s.contact_stiffness, false);
  non_negative("contact_damping", s.contact_damping);
  non_negative("axial_damping", s.damping);
  non_negative("pretension", s.pretension);
  positive("duration", s.duration, true);
  positive("step", s.step, true);
  if (value.count("output_interval")) positive("output_interval", s.interval, false);
  if (!std::isnan(s.theta) && !(s.theta >= 0.5 && s.theta <= 1.0))
    issues.push_back({at("theta"), shown(s.theta), "in [0.5, 1]"});
  if (!std::isnan(s.pretension) && !std::isnan(s.stiffness) && s.stiffness > 0 &&
      !std::isnan(s.pitch) && s.pretension / s.stiffness >= 0.1 * s.pitch)
    issues.push_back({at("pretension"), shown(s.pretension),
                      "below 0.1 k p = " + shown(0.1 * s.stiffness * s.pitch) +
                          " N (a stretch under 10 % of the pitch)"});

  // the sprockets: exactly two, one driver and one driven, equal and even teeth
  if (wheels.size() != 2) {
    issues.push_back({"dynamics.sprocket", std::to_string(wheels.size()) + " sprockets",
                      "two [[dynamics.sprocket]] tables, one driver and one driven (the only "
                      "layout built: docs/models/dynamics.md)"});
  }
  int drivers = 0, driven = 0;
  std::vector<int> teeth(wheels.size(), 0);
  for (std::size_t i = 0; i < wheels.size(); ++i) {
    const SprocketInput& w = wheels[i];
    const std::string base = "dynamics.sprocket[" + std::to_string(i) + "].";
    const std::string l = w.line ? " (line " + std::to_string(w.line) + ")" : "";
    if (!w.teeth) {
      issues.push_back({base + "teeth" + l, "(missing)", "an even integer in [8, 150]"});
    } else if (!is_integer(*w.teeth) || *w.teeth < 8 || *w.teeth > 150 ||
               static_cast<long>(*w.teeth) % 2 != 0) {
      issues.push_back({base + "teeth" + l, shown(*w.teeth), "an even integer in [8, 150]"});
    } else {
      teeth[i] = static_cast<int>(*w.teeth);
    }
    if (!w.has_role) {
      issues.push_back({base + "role" + l, "(missing)", "driver or driven"});
      continue;
    }
    if (w.role == "driver") {
      ++drivers;
      s.driver = i;
      if (!w.speed) {
        issues.push_back(
            {base + "speed" + l, "(missing)", "the driver's speed, e.g. \"13 rad/s\""});
      } else if (!(*w.speed > 0.0 && std::isfinite(*w.speed))) {
        issues.push_back({base + "speed" + l, shown(*w.speed), "> 0 (counter-clockwise)"});
      } else {
        s.speed = *w.speed;
      }
      if (w.inertia || w.load_torque)
        issues.push_back({base + "inertia" + l, "(given)",
                          "no inertia or load_torque on a driver (its speed is prescribed)"});
    } else if (w.role == "driven") {
      ++driven;
      s.driven = i;
      if (!w.inertia) {
        issues.push_back(
            {base + "inertia" + l, "(missing)", "the moment of inertia J > 0 [kg m^2]"});
      } else if (!(*w.inertia > 0.0 && std::isfinite(*w.inertia))) {
        issues.push_back({base + "inertia" + l, shown(*w.inertia), "> 0 [kg m^2]"});
      } else {
        s.inertia = *w.inertia;
      }
      if (w.load_torque && !(*w.load_torque >= 0.0 && std::isfinite(*w.load_torque)))
        issues.push_back({base + "load_torque" + l, shown(*w.load_torque), ">= 0 [N m]"});
      else if (w.load_torque)
        s.load = *w.load_torque;
      if (w.speed)
        issues.push_back({base + "speed" + l, shown(*w.speed),
                          "no speed on a driven wheel (it follows from the chain)"});
    }
  }
  if (wheels.size() == 2) {
    if (drivers != 1 || driven != 1)
      issues.push_back(
          {"dynamics.sprocket",
           std::to_string(drivers) + " driver(s), " + std::to_string(driven) + " driven",
           "one driver and one driven"});
    if (teeth[0] && teeth[1] && teeth[0] != teeth[1])
      issues.push_back({"dynamics.sprocket[1].teeth", std::to_string(teeth[1]),
                        "equal to sprocket[0].teeth = " + std::to_string(teeth[0]) +
                            " (only equal wheels are built)"});
    s.teeth = teeth[0] && teeth[0] == teeth[1] ? teeth[0] : 0;
  }
  if (!std::isnan(links)) {
    if (!is_integer(links) || links < 1 || links > 10000) {
      issues.push_back({at("links"), shown(links), "an integer in [z + 4, 10000]"});
    } else {
      s.links = static_cast<int>(links);
      if (s.teeth && (s.links - s.teeth < 4 || (s.links - s.teeth) % 2 != 0))
        issues.push_back({at("links"), std::to_string(s.links),
                          "z + 2m with m >= 2 pitches between the centres: " +
                              std::to_string(s.teeth + 4) + ", " + std::to_string(s.teeth + 6) +
                              ", ... (z = " + std::to_string(s.teeth) + ")"});
    }
  }
  // contact_stiffness omitted: the Hertz default at the expected seat load, the tight span's
  // tension T_L/R + pretension (the roller entering the driver takes it)
  if (s.hertz_stiffness && s.teeth && s.pitch > 0.0 && s.roller > 0.0 && s.width > 0.0 &&
      s.pretension >= 0.0 && s.load >= 0.0) {
    const double radius = 0.5 * s.pitch / std::sin(kPi / s.teeth);
    s.expected_load = s.load / radius + s.pretension;
    s.contact_stiffness = s.expected_load > 0.0 ? hertz_seat_stiffness(s.pitch, s.roller, s.width,
                                                                       s.teeth, s.expected_load)
                                                : NAN;
    if (std::isnan(s.contact_stiffness))
      issues.push_back({"dynamics.contact_stiffness", "(missing)",
                        "the roller-seat penalty k_c, e.g. \"2e8 N/m\" (the Hertz default needs "
                        "an expected seat load load_torque/R + pretension > 0 that the line "
                        "contact's approach law covers; here " +
                            shown(s.expected_load) + " N)"});
  }
  s.gravity = gravity;
  s.work_balance = work_balance;
  s.positions = positions;
  // the guides: kind and its geometry, all present; then the core's checks (named per field)
  for (std::size_t i = 0; i < guides.size(); ++i) {
    const GuideInput& g = guides[i];
    const std::string base = "dynamics.guide[" + std::to_string(i) + "].";
    const std::string l = g.line ? " (line " + std::to_string(g.line) + ")" : "";
    auto field = [&](const std::string& key) {
      const auto it = g.seen.find(key);
      return base + key + (it == g.seen.end() ? l : " (line " + std::to_string(it->second) + ")");
    };
    const auto kind = g.text.find("kind");
    if (kind == g.text.end()) {
      if (!g.seen.count("kind")) issues.push_back({field("kind"), "(missing)", "straight or arc"});
      continue;
    }
    const bool straight = kind->second == "straight";
    const std::vector<std::string> mine =
        straight ? std::vector<std::string>{"x0", "y0", "x1", "y1"}
                 : std::vector<std::string>{"centre_x", "centre_y", "radius", "start_angle",
                                            "end_angle"};
    const std::vector<std::string> theirs =
        straight ? std::vector<std::string>{"centre_x",    "centre_y",  "radius",
                                            "start_angle", "end_angle", "inside"}
                 : std::vector<std::string>{"x0", "y0", "x1", "y1"};
    bool complete = true;
    for (const std::string& key : mine) {
      if (g.value.count(key)) continue;
      complete = false;
      if (!g.seen.count(key))
        issues.push_back({field(key), "(missing)",
                          "the " + key + " of a" + (straight ? " straight" : "n arc") + " guide"});
    }
    for (const std::string& key : theirs) {
      if (g.seen.count(key))
        issues.push_back(
            {field(key), "(given)",
             std::string("no ") + key + " on a" + (straight ? " straight" : "n arc") + " guide"});
    }
    auto get = [&](const char* key, double fallback) {
      const auto it = g.value.find(key);
      return it != g.value.end() ? it->second : fallback;
    };
    Guide guide;
    guide.kind = straight ? Guide::Kind::kStraight : Guide::Kind::kArc;
    guide.x0 = get("x0", 0.0);
    guide.y0 = get("y0", 0.0);
    guide.x1 = get("x1", 0.0);
    guide.y1 = get("y1", 0.0);
    guide.centre_x = get("centre_x", 0.0);
    guide.centre_y = get("centre_y", 0.0);
    guide.radius = get("radius", 0.0);
    guide.start_angle = get("start_angle", 0.0);
    guide.end_angle = get("end_angle", 0.0);
    const auto inside = g.text.find("inside");
    guide.inside = inside != g.text.end() && inside->second == "true";
    guide.roller_radius = 0.5 * s.roller;
    guide.contact_stiffness = get("contact_stiffness", s.contact_stiffness);
    guide.contact_damping = get("contact_damping", s.contact_damping);
    guide.friction = get("friction", 0.0);
    guide.friction_band = get("friction_band", 1e-3);
    bool readable = true;
    for (const auto& [key, at_line] : g.seen)
      if (key != "kind" && key != "inside" && !g.value.count(key)) readable = false;
    if (!readable || !(s.roller > 0.0) || std::isnan(guide.contact_stiffness) ||
        std::isnan(guide.contact_damping))
      continue;  // already reported
    // the core's checks of the values given (a missing one is reported above)
    Model probe;
    probe.guides = {guide};
    for (const Issue& issue : validate(probe)) {
      if (issue.field.rfind("guide[0].", 0) != 0) continue;
      const std::string key = issue.field.substr(9);
      const bool given = key == "end" ? complete : g.seen.count(key) > 0;
      const bool derived = key == "roller_radius" || key == "contact_smoothing";
      if (!given && !derived) continue;
      issues.push_back({field(key == "end" ? "x1" : key), issue.value, issue.expected});
    }
    if (complete) s.guides.push_back(guide);
  }

  // the work cap: steps × links
  if (issues.empty()) {
    const double work = std::ceil(s.duration / s.step) * s.links;
    if (work > static_cast<double>(kWork.cap) && !in.large_allowed()) {
      issues.push_back({in.present("duration") ? std::string("duration") : at("duration"),
                        shown(s.duration) + " s",
                        "duration/step × links <= " + shown(static_cast<double>(kWork.cap)) +
                            " link-steps (here " + shown(work) + ", about " +
                            shown(kWork.estimated_seconds(work)) +
                            " s of CPU; allow_large (--allow-large) runs it anyway)"});
    }
  }
  // the series are held until the end (9 numbers a sample, with the JSON's ~0.5 kB): at most
  // kMaxSamples of them
  if (issues.empty()) {
    const double every = std::max(1.0, std::round(s.interval / s.step));
    const double samples = std::floor(std::round(s.duration / s.step) / every) + 1.0;
    if (samples > kMaxSamples)
      issues.push_back({at("output_interval"), shown(s.interval),
                        "at least duration / " + shown(kMaxSamples) + " = " +
                            shown(s.duration / kMaxSamples) + " s (at most " + shown(kMaxSamples) +
                            " samples; here " + shown(samples) + ")"});
    // the opt-in positions: links × samples node positions, held until the end
    if (s.positions && samples * s.links > kMaxPositions)
      issues.push_back({at("positions"), "true",
                        "at most " + shown(kMaxPositions) +
                            " node-samples (links x samples; here " + shown(samples * s.links) +
                            "): raise output_interval, shorten the run, or positions = false"});
  }
  throw_if_any(issues);
  return s;
}

struct Series {
  std::vector<double> angle, speed, torque;
};

struct Result {
  Setup setup;
  std::vector<double> time;
  std::vector<Series> sprocket;           // 2
  std::vector<std::vector<double>> span;  // upper, lower
  // positions = true: every node's x and y at each sample, [sample][node]
  std::vector<std::vector<double>> node_x, node_y;
  int steps = 0;
  double wall_time = 0.0, energy_drift = 0.0, max_penetration = 0.0;
  double friction_work = 0.0;
  // the work balance (summary.work_balance): E_end − E_0 = input + friction + link dampers +
  // contact dampers + numerical (the command's model has no drag)
  double input_work = 0.0, damper_work = 0.0, contact_damping_work = 0.0;
  double numerical_work = 0.0;
  std::vector<Diagnostic> diagnostics;
  // for the report's animation only (never in the JSON or CSV): the loop at up to
  // frame_count() instants spread over the run, and the wheels' outlines
  std::vector<LoopFrame> frames;
  std::vector<WheelOutline> outlines;
  std::vector<std::vector<std::pair<double, double>>> guides;  // rail surfaces, fixed
};

// The torque the chain puts on wheel w (counter-clockwise positive).
double chain_torque(const Model& model, const State& s, std::size_t w) {
  double sum = 0.0;
  for (std::size_t i = 0; i < s.nodes(); ++i)
    sum +=
        seat_contact(model.sprockets[w], s.x[i], s.y[i], s.vx[i], s.vy[i], s.angle[w], s.speed[w])
            .torque;
  return sum;
}

Result run(const analysis::Inputs& in) {
  Result out;
  out.setup = parse(in);
  const Setup& d = out.setup;
  const int z = d.teeth, m = (d.links - z) / 2;
  const auto n = static_cast<std::size_t>(d.links);
  const double rest = d.pitch - d.pretension / d.stiffness;
  Model model =
      uniform_chain(n, true, rest, d.mass_per_metre * d.pitch, d.stiffness, d.damping, false);
  const double centre = m * d.pitch;
  std::vector<Sprocket> wheels;
  for (std::size_t w = 0; w < 2; ++w) {
    Sprocket s = iso606_sprocket(d.pitch, d.roller, d.width, z, w == 0 ? 0.0 : centre, 0.0,
                                 d.contact_stiffness, d.contact_damping);
    if (w == d.driver) {
      s.driver = true;
      s.speed = d.speed;
    } else {
      s.inertia = d.inertia;
      s.load_torque = d.load;
    }
    wheels.push_back(s);
  }
  model.sprockets = wheels;
  model.guides = d.guides;
  model.gravity_y = -d.gravity;
  State s = two_sprocket_loop(z, m, d.pitch, wheels[0].pitch_radius, d.speed);
  // A roller that starts inside a rail is moved out along the rail's normal to touch it (the
  // spans start straight at the wheels' pitch-line height; a guide may sit a little higher).
  for (const Guide& g : model.guides) {
    for (std::size_t i = 0; i < n; ++i) {
      const GuideContact c = guide_contact(g, s.x[i], s.y[i], 0.0, 0.0);
      if (!c.active) continue;
      s.x[i] += c.penetration * c.nx;
      s.y[i] += c.penetration * c.ny;
    }
  }
  throw_if_any(validate(model, s));

  Integrator integ(model, {.step = d.step, .theta = d.theta});
  std::vector<double> tension(model.links());
  out.sprocket.resize(2);
  out.span.resize(2);
  std::vector<double> applied(2, 0.0);  // Σ of the steps' applied torques since the last sample
  int since = 0;                        // steps since the last sample
  auto sample = [&] {
    out.time.push_back(s.time);
    for (std::size_t w = 0; w < 2; ++w) {
      out.sprocket[w].angle.push_back(s.angle[w]);
      out.sprocket[w].speed.push_back(s.speed[w]);
      // the mean of the torque the steps since the last sample applied (at each step's θ point):
      // over every sample the wheel's torque balance holds; at t = 0, before any step, the
      // contact torque of the initial state
      out.sprocket[w].torque.push_back(since == 0 ? chain_torque(model, s, w) : applied[w] / since);
      applied[w] = 0.0;
    }
    link_tensions(model, s, tension);
    // the links whose middles are nearest the middles of the upper and lower spans
    std::size_t top = 0, bottom = 0;
    double top_gap = INFINITY, bottom_gap = INFINITY;
    for (std::size_t j = 0; j < n; ++j) {
      const std::size_t e = (j + 1) % n;
      const double xm = 0.5 * (s.x[j] + s.x[e]), ym = 0.5 * (s.y[j] + s.y[e]);
      const double gap = std::abs(xm - 0.5 * centre);
      if (ym > 0.0 && gap < top_gap) top_gap = gap, top = j;
      if (ym < 0.0 && gap < bottom_gap) bottom_gap = gap, bottom = j;
    }
    out.span[0].push_back(tension[top]);
    out.span[1].push_back(tension[bottom]);
    if (d.positions) {
      out.node_x.push_back(s.x);
      out.node_y.push_back(s.y);
    }
    since = 0;
  };
  const int steps = static_cast<int>(std::lround(d.duration / d.step));
  const int every = std::max(1, static_cast<int>(std::lround(d.interval / d.step)));
  // the report's animation: frames every `frame_every` steps (docs/models/dynamics.md, Report)
  for (std::size_t w = 0; w < 2; ++w)
    out.outlines.push_back(
        {"sprocket " + std::to_string(w) + (w == d.driver ? " (driver)" : " (driven)"),
         wheels[w].centre_x, wheels[w].centre_y,
         sprocket_outline(d.pitch, d.roller, d.width, wheels[w].teeth)});
  std::size_t drawn = out.outlines[0].outline.size() + out.outlines[1].outline.size() + 2;
  for (const Guide& g : d.guides) {
    out.guides.push_back(guide_polyline(g));
    drawn += out.guides.back().size();
  }
  const std::size_t frames = frame_count(n, drawn);
  const int frame_every = std::max(
      1, static_cast<int>(std::ceil(static_cast<double>(steps) / static_cast<double>(frames - 1))));
  auto snapshot = [&] { out.frames.push_back({s.time, s.x, s.y, s.angle}); };
  snapshot();
  const double e0 = energy(model, s).total();
  // the work the driver puts in and the load takes out over each step: the driver's applied
  // (θ-point) torque and the load torque times the angles the wheels turned
  double work = 0.0;
  sample();
  const auto started = std::chrono::steady_clock::now();
  ProgressLoop loop(static_cast<std::size_t>(steps), "steps");
  for (int k = 0; k < steps; ++k) {
    const std::array<double, 2> angle0{s.angle[0], s.angle[1]};
    const StepReport rep = integ.step(model, s);
    out.max_penetration = std::max(out.max_penetration, rep.max_penetration);
    if (!rep.converged) {
      out.diagnostics.push_back(
          {Diagnostic::Severity::kError, "dynamics.not_converged",
           "step " + std::to_string(k + 1) + " (t = " + format_g(s.time + d.step, 6) +
               " s) did not converge in " + std::to_string(rep.iterations) +
               " Newton iterations; the run stopped there (try a smaller step or theta nearer 1)",
           s.time + d.step, d.duration});
      break;
    }
    ++out.steps;
    const std::vector<double>& torque = integ.applied_torque();
    work += -torque[d.driver] * (s.angle[d.driver] - angle0[d.driver]) -
            d.load * (s.angle[d.driven] - angle0[d.driven]);
    for (std::size_t w = 0; w < 2; ++w) applied[w] += torque[w];
    ++since;
    if ((k + 1) % every == 0) sample();
    if ((k + 1) % frame_every == 0) snapshot();
    loop.step(static_cast<std::size_t>(k + 1));
  }
  out.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  // the guides' friction work is 0 without guides: the drift is then the same number as before
  out.friction_work = s.friction_work;
  out.energy_drift = energy(model, s).total() - e0 - work - s.friction_work;
  out.input_work = work;
  out.damper_work = s.damper_work;
  out.contact_damping_work = s.contact_damping_work;
  // what the model's dissipation does not account for: the θ-method and the contacts' penalty
  // (evaluated at the θ point, not by a discrete gradient)
  out.numerical_work = out.energy_drift - s.damper_work - s.contact_damping_work;
  if (d.theta < 0.6)
    out.diagnostics.push_back(
        {Diagnostic::Severity::kWarning, "dynamics.theta_below_0_6",
         "theta = " + format_g(d.theta, 4) +
             " < 0.6: drives with roller-seat contact diverged below 0.6 (docs/models/dynamics.md)",
         d.theta, 0.6});
  return out;
}

std::string fixed(double x, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, x);
  return buf;
}

// The summary's window (docs/models/dynamics.md, "Summary"): the whole tooth periods of the
// driver, T = 2π/(z ω), after half the run, (t_end/2, t_end/2 + n T] with n = ⌊(t_end/2)/T⌋ —
// the second half is taken as past the start-up transient (as the table's means and the
// spectrum take it), and whole periods keep the polygonal action's ripple out of the means.
// A second half shorter than one period gives the whole second half, (t_end/2, t_end]; a run
// with no sample after t = 0 gives its one sample.
struct Window {
  double start = 0.0, end = 0.0;
  int periods = 0;                  // n, 0 when the second half holds no whole period
  std::size_t first = 0, last = 0;  // the samples in the window: [first, last)
};

Window summary_window(const std::vector<double>& time, double period) {
  Window w;
  const double t_end = time.back();
  w.start = 0.5 * t_end;
  const double n = std::floor((t_end - w.start) / period);
  w.periods = n >= 1.0 && n < 1e9 ? static_cast<int>(n) : 0;
  w.end = w.periods > 0 ? w.start + n * period : t_end;
  w.first = time.size();
  for (std::size_t k = 0; k < time.size(); ++k) {
    if (time[k] > w.start && time[k] <= w.end) {
      w.first = std::min(w.first, k);
      w.last = k + 1;
    }
  }
  if (w.first >= w.last) {  // only the t = 0 sample
    w.first = time.size() - 1;
    w.last = time.size();
    w.start = w.end = t_end;
  }
  return w;
}

struct Stats {
  double mean = 0.0, min = INFINITY, max = -INFINITY;
};

Stats window_stats(const std::vector<double>& x, const Window& w) {
  Stats s;
  double sum = 0.0;
  for (std::size_t k = w.first; k < w.last; ++k) {
    sum += x[k];
    s.min = std::min(s.min, x[k]);
    s.max = std::max(s.max, x[k]);
  }
  s.mean = sum / static_cast<double>(w.last - w.first);
  return s;
}

Record describe(const Result& r, const analysis::Inputs&) {
  const Setup& d = r.setup;
  Record rec;
  rec.diagnostics = r.diagnostics;
  const double simulated = r.steps * d.step;
  const double rtf = r.wall_time > 0.0 ? simulated / r.wall_time : 0.0;
  Value j = Value::object();
  j["model"] = "dynamics.chain_loop";
  j["source"] =
      "implicit midpoint / theta-method with the discrete energy-momentum gradient (Simo & Tarnow "
      "1992), ISO 606 sprocket seats (docs/models/dynamics.md)";
  if (!d.chain.empty()) j["chain"] = d.chain;
  j["pitch"] = d.pitch;
  j["links"] = d.links;
  j["teeth"] = d.teeth;
  j["centre_distance"] = (d.links - d.teeth) / 2 * d.pitch;
  j["theta"] = d.theta;
  j["time"] = r.time;
  Value wheels = Value::array();
  for (std::size_t w = 0; w < 2; ++w) {
    wheels.push_back(Value::object({{"role", w == d.driver ? "driver" : "driven"},
                                    {"angle", r.sprocket[w].angle},
                                    {"speed", r.sprocket[w].speed},
                                    {"torque", r.sprocket[w].torque}}));
  }
  j["sprocket"] = wheels;
  // the driver turns counter-clockwise: the driver at x = 0 pulls the upper span
  const bool upper_tight = d.driver == 0;
  Value spans = Value::array();
  spans.push_back(Value::object(
      {{"name", "upper"}, {"side", upper_tight ? "tight" : "slack"}, {"tension", r.span[0]}}));
  spans.push_back(Value::object(
      {{"name", "lower"}, {"side", upper_tight ? "slack" : "tight"}, {"tension", r.span[1]}}));
  j["span"] = spans;
  j["summary"] = Value::object({{"steps", r.steps},
                                {"step", d.step},
                                {"wall_time", r.wall_time},
                                {"real_time_factor", rtf},
                                {"energy_drift", r.energy_drift},
                                {"max_penetration", r.max_penetration}});
  // gravity and guides add fields only when given: a run without them prints what it did before
  if (d.gravity > 0.0) j["gravity"] = d.gravity;
  // contact_stiffness omitted: the Hertz default used and its linearisation load
  if (d.hertz_stiffness) {
    j["contact_stiffness"] = d.contact_stiffness;
    j["contact_load"] = d.expected_load;
  }
  if (!d.guides.empty()) {
    j["guides"] = static_cast<int>(d.guides.size());
    j["summary"]["friction_work"] = r.friction_work;
  }
  // opt-in (work_balance = true): without it the output is what it was
  if (d.work_balance) {
    j["summary"]["work_balance"] = Value::object({{"input", r.input_work},
                                                  {"friction", r.friction_work},
                                                  {"link_dampers", r.damper_work},
                                                  {"contact_dampers", r.contact_damping_work},
                                                  {"numerical", r.numerical_work}});
  }
  // the scalar summaries a sweep takes as columns (objects, not arrays: arrays are series to a
  // sweep): each sprocket's mean speed and torque, each span's mean, least and greatest tension,
  // over the window of summary_window(), all added after the fields above
  const Window win = summary_window(r.time, 2 * kPi / (d.teeth * d.speed));
  j["summary"]["window_start"] = win.start;
  j["summary"]["window_end"] = win.end;
  j["summary"]["window_periods"] = win.periods;
  j["summary"]["window_samples"] = static_cast<long long>(win.last - win.first);
  for (std::size_t w = 0; w < r.sprocket.size(); ++w) {
    j["summary"]["sprocket_" + std::to_string(w)] =
        Value::object({{"mean_speed", window_stats(r.sprocket[w].speed, win).mean},
                       {"mean_torque", window_stats(r.sprocket[w].torque, win).mean}});
  }
  for (std::size_t k = 0; k < r.span.size(); ++k) {
    const Stats t = window_stats(r.span[k], win);
    j["summary"]["span_" + std::to_string(k)] =
        Value::object({{"mean_tension", t.mean}, {"min_tension", t.min}, {"max_tension", t.max}});
  }
  // opt-in (positions = true): positions.x[k][i], positions.y[k][i], node i at time[k]
  if (d.positions) {
    Value x = Value::array(), y = Value::array();
    for (std::size_t k = 0; k < r.node_x.size(); ++k) {
      x.push_back(Value(r.node_x[k]));
      y.push_back(Value(r.node_y[k]));
    }
    j["positions"] = Value::object({{"x", std::move(x)}, {"y", std::move(y)}});
  }
  j["diagnostics"] = analysis::diagnostics_value(r.diagnostics);
  j["units"] = analysis::units_value({{"pitch", "m"},
                                      {"centre_distance", "m"},
                                      {"time", "s"},
                                      {"angle", "rad"},
                                      {"speed", "rad/s"},
                                      {"torque", "N m"},
                                      {"tension", "N"},
                                      {"step", "s"},
                                      {"wall_time", "s"},
                                      {"real_time_factor", "1"},
                                      {"energy_drift", "J"},
                                      {"max_penetration", "m"},
                                      {"value", "SI"},
                                      {"limit", "SI"}});
  if (d.gravity > 0.0) j["units"]["gravity"] = "m/s^2";
  if (d.hertz_stiffness) {
    j["units"]["contact_stiffness"] = "N/m";
    j["units"]["contact_load"] = "N";
  }
  if (!d.guides.empty()) j["units"]["friction_work"] = "J";
  if (d.work_balance) j["units"]["work_balance"] = "J";
  for (const char* key : {"window_start", "window_end"}) j["units"][key] = "s";
  if (d.positions) {
    j["units"]["x"] = "m";
    j["units"]["y"] = "m";
  }
  j["units"]["mean_speed"] = "rad/s";
  j["units"]["mean_torque"] = "N m";
  for (const char* key : {"mean_tension", "min_tension", "max_tension"}) j["units"][key] = "N";
  rec.data = std::move(j);

  std::ostringstream csv;
  csv << "time,angle_0,speed_0,torque_0,angle_1,speed_1,torque_1,tension_upper,tension_lower\n";
  for (std::size_t k = 0; k < r.time.size(); ++k) {
    csv << format_g(r.time[k], 12);
    for (std::size_t w = 0; w < 2; ++w)
      csv << "," << format_g(r.sprocket[w].angle[k], 12) << ","
          << format_g(r.sprocket[w].speed[k], 12) << "," << format_g(r.sprocket[w].torque[k], 12);
    csv << "," << format_g(r.span[0][k], 12) << "," << format_g(r.span[1][k], 12) << "\n";
  }
  rec.csv = csv.str();

  // the table: means over the last half of the run
  auto late_mean = [&](const std::vector<double>& x) {
    const std::size_t from = x.size() / 2;
    double sum = 0.0;
    for (std::size_t k = from; k < x.size(); ++k) sum += x[k];
    return x.size() > from ? sum / static_cast<double>(x.size() - from) : NAN;
  };
  std::ostringstream t;
  t << "Catena dynamics: chain loop over two sprockets in time (issue 21)\n\n"
    << "  " << (d.chain.empty() ? "chain" : d.chain) << ", " << d.links << " links, z = " << d.teeth
    << " / " << d.teeth << ", centre distance "
    << format_g((d.links - d.teeth) / 2 * d.pitch * 1e3, 5) << " mm, theta " << format_g(d.theta, 3)
    << "\n  " << r.steps << " steps of " << format_g(d.step * 1e3, 4) << " ms ("
    << format_g(simulated, 5) << " s) in " << fixed(r.wall_time, 3)
    << " s wall time, real-time factor " << format_g(rtf, 3) << "\n\n"
    << "  means over the second half of the run:\n";
  for (std::size_t w = 0; w < 2; ++w)
    t << "    sprocket " << w << " (" << (w == d.driver ? "driver" : "driven") << ")  speed "
      << format_g(late_mean(r.sprocket[w].speed), 6) << " rad/s, chain torque "
      << format_g(late_mean(r.sprocket[w].torque), 5) << " N m\n";
  t << "    upper span tension " << format_g(late_mean(r.span[0]), 5) << " N ("
    << (upper_tight ? "tight" : "slack") << "), lower " << format_g(late_mean(r.span[1]), 5)
    << " N\n"
    << "  energy drift " << format_g(r.energy_drift, 4) << " J, deepest roller penetration "
    << format_g(r.max_penetration * 1e6, 4) << " um\n";
  if (d.gravity > 0.0 || !d.guides.empty())
    t << "  gravity " << format_g(d.gravity, 6) << " m/s^2, " << d.guides.size()
      << " guide(s), friction work " << format_g(r.friction_work, 5) << " J\n";
  if (d.work_balance)
    t << "  work balance: input " << format_g(r.input_work, 5) << " J, friction "
      << format_g(r.friction_work, 5) << " J, link dampers " << format_g(r.damper_work, 5)
      << " J, contact dampers " << format_g(r.contact_damping_work, 5) << " J, numerical "
      << format_g(r.numerical_work, 4) << " J\n";
  for (const Diagnostic& diag : r.diagnostics)
    t << "  " << to_string(diag.severity) << ": " << diag.message << "\n";
  rec.table = t.str();

  ReportInput report{.time = r.time, .teeth = d.teeth, .driver_speed = d.speed};
  for (std::size_t w = 0; w < 2; ++w) {
    const std::string name =
        "sprocket " + std::to_string(w) + (w == d.driver ? " (driver)" : " (driven)");
    report.speed.push_back({name, r.sprocket[w].speed});
    report.torque.push_back({name, r.sprocket[w].torque});
  }
  report.span.push_back({upper_tight ? "upper span (tight)" : "upper span (slack)", r.span[0]});
  report.span.push_back({upper_tight ? "lower span (slack)" : "lower span (tight)", r.span[1]});
  report.wheels = r.outlines;
  report.guides = r.guides;
  report.frames = r.frames;
  rec.charts = report_charts(report);
  return rec;
}

// A run's work without running it (Analysis::work_of, for a sweep's total): steps × links, the
// measure of the per-run cap; 0 for inputs parse() refuses (over the cap included).
double estimated_work(const analysis::Inputs& in) {
  try {
    const Setup s = parse(in);
    return std::ceil(s.duration / s.step) * s.links;
  } catch (const InputError&) {
    return 0.0;
  }
}

analysis::Analysis make() {
  analysis::Analysis a;
  a.name = "dynamics";
  a.command = {"dynamics"};
  a.title = "Chain-loop dynamics: a roller chain over two ISO 606 sprockets in time (issue 21)";
  a.help =
      "A roller-chain loop over a driver and a loaded driven sprocket stepped in time: sprocket "
      "angle, speed and torque, span tensions (issue 21, docs/models/dynamics.md)";
  a.seed = "issue 21";
  a.docs = "docs/models/dynamics.md";
  a.chain_types = {"roller-iso606"};
  a.formats = {.table = true, .csv = true, .drawing = false};
  using analysis::quantity;
  a.parameters = {
      table_parameter(),
      quantity("duration", K::kTime, "simulated time (overrides dynamics.duration)") |
          analysis::NotShared{},
      quantity("step", K::kTime, "time step h (overrides dynamics.step)") | analysis::NotShared{}};
  analysis::set_functions<Result>(a, run, describe);
  a.work_of = estimated_work;
  a.work_unit = "link-steps";
  return a;
}

}  // namespace

const analysis::Analysis& dynamics_analysis() {
  static const analysis::Analysis a = make();
  return a;
}

}  // namespace catena::dynamics
