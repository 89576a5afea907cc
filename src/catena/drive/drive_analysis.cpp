// `drive` and `drive select` (issue 16 §3) as analyses.
#include "catena/drive/drive_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace catena::drive {
namespace {

using analysis::format_g;
using analysis::Inputs;
using analysis::Record;
using analysis::Value;

constexpr double kPi = std::numbers::pi;
constexpr double kGravity = 9.80665;  // [m/s²] standard gravity

std::string chain_names() {
  std::string names;
  for (const auto& n : contact::iso606_names()) names += (names.empty() ? "" : ", ") + n;
  return names;
}

double deg(double rad) { return rad * 180.0 / kPi; }
double rpm(double rad_per_s) { return rad_per_s * 60.0 / (2 * kPi); }

// The two tooth counts of --teeth, when both are whole numbers in range.
std::optional<std::pair<int, int>> teeth_of(const Inputs& in) {
  const std::vector<double>& z = in.list("teeth");
  if (z.size() != 2) return std::nullopt;
  for (double v : z)
    if (!(v >= kMinTeeth && v <= kMaxTeeth) || v != std::round(v)) return std::nullopt;
  return std::pair<int, int>{static_cast<int>(z[0]), static_cast<int>(z[1])};
}

bool rated(const std::optional<contact::ChainDimensions>& chain) {
  return chain && ansi_number(chain->name) && ansi_constants(*ansi_number(chain->name));
}

void positive(const Inputs& in, const char* key, const char* expected, std::vector<Issue>& issues) {
  if (in.present(key) && !(in.number(key) > 0) && std::isfinite(in.number(key)))
    issues.push_back({key, in.text(key), expected});
}

// The layout's own problems, once chain and teeth are valid: a centre distance with the pitch
// circles apart (more than r1 + r2) that needs at most kMaxLinks links (its window in mm), or a
// link count long enough to pass round both sprockets.
std::vector<Issue> layout_issues(const Inputs& in, double p, int z1, int z2) {
  const double r1 = pitch_radius(p, z1), r2 = pitch_radius(p, z2);
  if (in.given("center_distance")) {
    const double a = in.number("center_distance");
    const double longest = center_distance_formula(p, z1, z2, kMaxLinks);
    if (a > r1 + r2 && a <= longest) return {};
    return {{"center_distance", in.text("center_distance"),
             "a centre distance with the pitch circles apart that needs at most " +
                 std::to_string(kMaxLinks) +
                 " links: more than r1 + r2 = " + format_g((r1 + r2) * 1e3, 6) + " mm, at most " +
                 format_g(longest * 1e3, 6) + " mm"}};
  }
  // the least chain that passes round both pitch polygons without them touching
  const double least = links_for(p, z1, z2, r1 + r2);
  if (in.integer("links") >= least) return {};
  return {{"links", in.text("links"),
           "a chain long enough to pass round both sprockets: more than " + format_g(least, 6) +
               " links (pitch circles touching)"}};
}

const std::vector<std::string> kOrder = {
    "chain",          "teeth",   "center_distance", "links",         "speed", "power",
    "service_factor", "strands", "mass_per_metre",  "slack_tension", "slack"};

void check_drive(const Inputs& in, std::vector<Issue>& issues) {
  std::vector<Issue> added;
  std::optional<contact::ChainDimensions> chain;
  if (in.given("chain")) {
    chain = contact::iso606_chain(in.text("chain"));
    if (!chain)
      added.push_back(
          {"chain", in.text("chain"), "an ISO 606 chain of the catalogue: " + chain_names()});
  }
  if (in.present("teeth") && !teeth_of(in))
    added.push_back({"teeth", in.text("teeth"),
                     "z1,z2: the driver's and the driven sprocket's tooth counts, two whole "
                     "numbers from 3 to " +
                         std::to_string(kMaxTeeth)});
  const bool a = in.given("center_distance"), x = in.given("links");
  if (a == x)
    added.push_back({"center_distance", a ? in.text("center_distance") : "(missing)",
                     a ? "either --center-distance or --links, not both"
                       : "the centre distance a, or the link count with --links"});
  positive(in, "center_distance", "a centre distance a > 0", added);
  if (x && in.integer("links") > kMaxLinks)
    added.push_back({"links", in.text("links"), "2 … " + std::to_string(kMaxLinks) + " links"});
  positive(in, "speed", "the driver's speed n1 > 0, e.g. 1000rpm", added);
  positive(in, "power", "the transmitted power P > 0, e.g. 7.5kW", added);
  if (rated(chain) && !in.given("service_factor"))
    added.push_back({"service_factor", "(missing)",
                     "the service factor K_s ≥ 1 of the driven machine and the driver (the "
                     "rating of an " +
                         chain->name + " chain needs it; Catena has no default)"});
  if (in.given("service_factor") && !(in.number("service_factor") >= 1))
    added.push_back({"service_factor", in.text("service_factor"), "a service factor K_s ≥ 1"});
  if (rated(chain) && in.integer("strands") > 4)
    added.push_back({"strands", in.text("strands"),
                     "1 … 4 strands (the ANSI multiple-strand factors stop at 4)"});
  if (chain && !in.given("mass_per_metre") && !chain->mass_per_metre)
    added.push_back({"mass_per_metre", "(missing)",
                     "the chain's mass per metre q in kg/m: the catalogue has none for " +
                         chain->name + " yet, and the centrifugal tension q v² needs it"});
  positive(in, "mass_per_metre", "a mass per metre q > 0", added);
  positive(in, "slack_tension", "a horizontal slack-span tension H > 0", added);
  positive(in, "slack", "an extra chain length ΔL > 0 over the taut length", added);
  const auto teeth = teeth_of(in);
  const bool length = a ? in.number("center_distance") > 0 : in.integer("links") <= kMaxLinks;
  if (chain && teeth && a != x && length)
    for (Issue& i : layout_issues(in, chain->pitch, teeth->first, teeth->second))
      added.push_back(std::move(i));
  issues = analysis::in_read_order(issues, added, kOrder, [](const std::string&) { return true; });
}

Diagnostic info(std::string code, std::string message, double value = 0, double limit = 0) {
  return {Diagnostic::Severity::kInfo, std::move(code), std::move(message), value, limit};
}

}  // namespace

DriveResult drive_run(const Inputs& in) {
  DriveResult r;
  r.chain = *contact::iso606_chain(in.text("chain"));
  const double p = r.chain.pitch;
  std::tie(r.z1, r.z2) = *teeth_of(in);
  r.strands = in.integer("strands");
  r.speed = in.number("speed");
  r.power = in.number("power");
  const int z1 = r.z1, z2 = r.z2;

  if (const std::vector<Issue> bad = layout_issues(in, p, z1, z2); !bad.empty())
    throw InputError(bad);  // (the check phase reports them with the other inputs' problems)
  if (in.given("center_distance")) {
    const double a = in.number("center_distance");
    r.given_center_distance = a;
    r.links_exact = links_for(p, z1, z2, a);
    r.links = round_up_even(*r.links_exact);
    r.diagnostics.push_back(
        info("drive.links_rounded_up",
             "X = " + format_g(*r.links_exact, 8) + " links for a = " + format_g(a * 1e3) +
                 " mm, rounded up to " + std::to_string(r.links) +
                 " (an even count needs no offset link); the centre distance is recomputed for it",
             *r.links_exact, r.links));
  } else {
    r.links = in.integer("links");
    if (r.links % 2 != 0)
      r.diagnostics.push_back({Diagnostic::Severity::kWarning, "drive.offset_link",
                               "an odd link count (" + std::to_string(r.links) +
                                   ") needs an offset (cranked) link, which weakens the chain; "
                                   "an even count avoids it",
                               static_cast<double>(r.links), 0.0});
  }
  r.center_distance_formula = center_distance_formula(p, z1, z2, r.links);
  try {
    r.exact = exact_center_distance(p, z1, z2, r.links);
  } catch (const std::domain_error& e) {
    throw InputError(
        {{"links", std::to_string(r.links), std::string("a longer chain: ") + e.what()}});
  }
  const double a = r.exact.min;
  r.chain_length = r.links * p;
  r.speed_ratio = static_cast<double>(z2) / z1;
  r.chain_speed = z1 * p * r.speed / (2 * kPi);
  r.chordal_variation = 1 - std::cos(kPi / z1);
  const double gamma = span_angle(p, z1, z2, a);
  r.wrap_driver = kPi - 2 * gamma;
  r.wrap_driven = kPi + 2 * gamma;
  r.span_length = a * std::cos(gamma);

  r.mass_per_metre = in.given("mass_per_metre") ? in.number("mass_per_metre")
                                                : *r.chain.mass_per_metre * r.strands;
  if (!in.given("mass_per_metre") && r.strands > 1)
    r.diagnostics.push_back(info("drive.mass_per_metre_strands",
                                 "q is the catalogue's single-strand value × " +
                                     std::to_string(r.strands) +
                                     " strands; give --mass-per-metre for the maker's value",
                                 r.mass_per_metre, 0));
  r.effective_tension = r.power / r.chain_speed;
  r.centrifugal_tension = r.mass_per_metre * r.chain_speed * r.chain_speed;
  const double h = in.given("slack_tension") ? in.number("slack_tension") : 0.0;
  if (in.given("slack_tension")) r.horizontal_tension = h;
  r.slack_tension = r.centrifugal_tension + h;
  r.tight_tension = r.effective_tension + r.slack_tension;
  const auto valid = [](double tension) { return std::abs(tension) <= kMaxTension; };
  const auto finite = [](double tension) { return std::isfinite(tension); };
  if (valid(r.tight_tension) && valid(r.slack_tension) && valid(r.centrifugal_tension)) {
    r.shaft = shaft_loads(p, z1, z2, a, r.tight_tension, r.slack_tension, r.centrifugal_tension);
  } else if (finite(r.tight_tension) && finite(r.slack_tension) && finite(r.centrifugal_tension)) {
    // finite tensions beyond shaft_loads' ±1e307 N (an extreme power, speed or slack tension):
    // the same formula on the tensions × 2⁻⁵ (≤ 5.6e306 N), the loads × 2⁵. Powers of two scale
    // exactly, so the bits are those of the formula on the tensions themselves where that stays
    // finite; a load beyond the largest double is +inf (the result check reports it)
    constexpr double kDown = 0x1p-5, kUp = 0x1p5;
    const ShaftLoads l = shaft_loads(p, z1, z2, a, r.tight_tension * kDown, r.slack_tension * kDown,
                                     r.centrifugal_tension * kDown);
    r.shaft = {l.driver_x * kUp, l.driver_y * kUp, l.driven_x * kUp, l.driven_y * kUp};
  } else {  // an infinite tension (the effective pull P/v or q v² overflowed): so do the loads,
            // the spans' pulls along the line of centres (+inf, or NaN for inf − inf)
    const double pull =
        (r.tight_tension - r.centrifugal_tension) + (r.slack_tension - r.centrifugal_tension);
    r.shaft = {pull, 0.0, -pull, 0.0};
  }
  const double weight = r.mass_per_metre * kGravity;
  if (r.horizontal_tension)
    r.sag_from_tension = weight * r.span_length * r.span_length / (8 * *r.horizontal_tension);
  if (in.given("slack")) {
    r.slack = in.number("slack");
    r.sag_from_slack = std::sqrt(3 * r.span_length * *r.slack / 8);
  }

  if (deg(r.wrap_driver) < 120)
    r.diagnostics.push_back({Diagnostic::Severity::kWarning, "drive.small_wrap",
                             "the chain wraps " + format_g(deg(r.wrap_driver), 4) +
                                 "° of the driver, less than the 120° Mott recommends "
                                 "(Machine Elements in Mechanical Design, §7-6)",
                             r.wrap_driver, 120 * kPi / 180});
  if (in.given("service_factor")) r.service_factor = in.number("service_factor");
  if (const auto number = ansi_number(r.chain.name)) {
    if (const auto c = ansi_constants(*number))
      r.rating = rate(*c, p, z1, rpm(r.speed), r.strands, r.power, *r.service_factor);
  }
  if (!r.rating) {
    r.diagnostics.push_back(
        {Diagnostic::Severity::kWarning, "drive.no_rating",
         "no public power-rating formula was found for " + r.chain.name +
             " (ISO 606 B series): the chain is not rated; the ANSI A-series envelopes are not "
             "applied to it",
         0, 0});
  } else if (r.rating->margin < 1) {
    r.diagnostics.push_back({Diagnostic::Severity::kInfeasible, "drive.underrated",
                             "the rated power " + format_g(r.rating->rated_power / 1e3, 4) +
                                 " kW is below the design power " +
                                 format_g(r.rating->design_power / 1e3, 4) + " kW",
                             r.rating->rated_power, r.rating->design_power});
  }
  return r;
}

namespace {

Value drive_value(const DriveResult& r) {
  Value j = Value::object();
  j["model"] = "drive.two_sprocket";
  j["source"] =
      "links and centre distance: textbook formulas (e.g. Mott, Machine Elements in Mechanical "
      "Design, §7-6); exact centre distance: polygon wrap solved numerically; rating: "
      "ANSI envelopes H1, H2 as in issue 16";
  j["chain"] = r.chain.name;
  j["pitch"] = r.chain.pitch;
  j["teeth"] = Value::object({{"driver", r.z1}, {"driven", r.z2}});
  j["strands"] = r.strands;
  j["links"] = r.links;
  j["links_exact"] = r.links_exact;
  j["center_distance"] = r.exact.min;
  j["center_distance_formula"] = r.center_distance_formula;
  j["center_distance_difference"] = r.exact.min - r.center_distance_formula;
  j["center_distance_range"] = Value::object({{"min", r.exact.min}, {"max", r.exact.max}});
  j["center_distance_given"] = r.given_center_distance;
  j["chain_length"] = r.chain_length;
  j["speed_ratio"] = r.speed_ratio;
  j["chain_speed"] = r.chain_speed;
  j["chordal_variation"] = r.chordal_variation;
  j["wrap_angle"] = Value::object({{"driver", r.wrap_driver}, {"driven", r.wrap_driven}});
  j["wrap_links"] =
      Value::object({{"driver", r.exact.at_min.wrap1}, {"driven", r.exact.at_min.wrap2}});
  j["span_length"] = r.span_length;
  j["mass_per_metre"] = r.mass_per_metre;
  j["tension"] = Value::object({{"tight", r.tight_tension},
                                {"slack", r.slack_tension},
                                {"effective", r.effective_tension},
                                {"centrifugal", r.centrifugal_tension}});
  j["shaft_load"] = Value::object({{"driver", std::hypot(r.shaft.driver_x, r.shaft.driver_y)},
                                   {"driven", std::hypot(r.shaft.driven_x, r.shaft.driven_y)}});
  j["sag"] = Value::object({{"from_tension", r.sag_from_tension},
                            {"from_slack", r.sag_from_slack},
                            {"horizontal_tension", r.horizontal_tension},
                            {"slack", r.slack}});
  if (r.rating) {
    const Rating& g = *r.rating;
    j["rating"] = Value::object({{"standard", "ANSI #" + std::to_string(g.ansi)},
                                 {"plate_fatigue", g.plate_fatigue},
                                 {"roller_impact", g.roller_impact},
                                 {"strand_factor", g.strand_factor},
                                 {"rated_power", g.rated_power},
                                 {"design_power", g.design_power},
                                 {"service_factor", *r.service_factor},
                                 {"margin", g.margin}});
  }
  j["units"] = analysis::units_value({{"pitch", "m"},
                                      {"links", "1"},
                                      {"center_distance", "m"},
                                      {"center_distance_formula", "m"},
                                      {"center_distance_difference", "m"},
                                      {"center_distance_range", "m"},
                                      {"center_distance_given", "m"},
                                      {"chain_length", "m"},
                                      {"speed_ratio", "1"},
                                      {"chain_speed", "m/s"},
                                      {"chordal_variation", "1"},
                                      {"wrap_angle", "rad"},
                                      {"span_length", "m"},
                                      {"mass_per_metre", "kg/m"},
                                      {"tension", "N"},
                                      {"shaft_load", "N"},
                                      {"sag", "m"},
                                      {"horizontal_tension", "N"},
                                      {"plate_fatigue", "W"},
                                      {"roller_impact", "W"},
                                      {"rated_power", "W"},
                                      {"design_power", "W"},
                                      {"margin", "1"}});
  j["diagnostics"] = analysis::diagnostics_value(r.diagnostics);
  return j;
}

std::string drive_table(const DriveResult& r) {
  std::ostringstream t;
  auto row = [&](const std::string& name, const std::string& value) {
    char line[160];
    std::snprintf(line, sizeof line, "  %-36s %s\n", name.c_str(), value.c_str());
    t << line;
  };
  t << "Catena drive: " << r.chain.name << ", z1 = " << r.z1 << ", z2 = " << r.z2 << ", "
    << r.strands << " strand" << (r.strands > 1 ? "s" : "") << " (issue 16 §3)\n\n";
  row("links X", std::to_string(r.links) +
                     (r.links_exact ? " (" + format_g(*r.links_exact, 8) + " rounded up)" : ""));
  row("centre distance, polygon wrap [mm]", format_g(r.exact.min * 1e3, 8) + " (up to " +
                                                format_g(r.exact.max * 1e3, 8) +
                                                " over a driver pitch)");
  row("centre distance, formula [mm]", format_g(r.center_distance_formula * 1e3, 8));
  row("chain length [mm]", format_g(r.chain_length * 1e3, 8));
  row("speed ratio z2/z1", format_g(r.speed_ratio, 6));
  row("chain speed [m/s]", format_g(r.chain_speed, 6));
  row("chordal speed variation [%]", format_g(r.chordal_variation * 100, 4));
  row("wrap driver / driven [deg]",
      format_g(deg(r.wrap_driver), 5) + " / " + format_g(deg(r.wrap_driven), 5));
  row("span length [mm]", format_g(r.span_length * 1e3, 6));
  row("tension tight / slack [N]",
      format_g(r.tight_tension, 6) + " / " + format_g(r.slack_tension, 6));
  row("tension P/v, centrifugal q v^2 [N]",
      format_g(r.effective_tension, 6) + ", " + format_g(r.centrifugal_tension, 6));
  row("shaft load driver / driven [N]",
      format_g(std::hypot(r.shaft.driver_x, r.shaft.driver_y), 6) + " / " +
          format_g(std::hypot(r.shaft.driven_x, r.shaft.driven_y), 6));
  if (r.sag_from_tension) row("sag from H [mm]", format_g(*r.sag_from_tension * 1e3, 5));
  if (r.sag_from_slack) row("sag from slack [mm]", format_g(*r.sag_from_slack * 1e3, 5));
  if (r.rating) {
    const Rating& g = *r.rating;
    row("rating (ANSI #" + std::to_string(g.ansi) + ") H1 / H2 [kW]",
        format_g(g.plate_fatigue / 1e3, 5) + " / " + format_g(g.roller_impact / 1e3, 5));
    row("rated / design power [kW]",
        format_g(g.rated_power / 1e3, 5) + " / " + format_g(g.design_power / 1e3, 5));
    row("margin rated/design", format_g(g.margin, 4));
  }
  for (const Diagnostic& d : r.diagnostics)
    t << "\n  " << to_string(d.severity) << " " << d.code << ": " << d.message;
  if (!r.diagnostics.empty()) t << "\n";
  return t.str();
}

// The layout to scale: both pitch circles and centres, the chain's pins at the tightest phase
// (the spans and the wrap), the line of centres.
Drawing drive_drawing(const DriveResult& r) {
  const double p = r.chain.pitch;
  const PolygonWrap& w = r.exact.at_min;
  Drawing d;
  d.title = "Catena drive layout: " + r.chain.name + ", z1 = " + std::to_string(r.z1) +
            ", z2 = " + std::to_string(r.z2) + ", X = " + std::to_string(r.links);
  auto circle = [&](double cx, double radius, const char* layer, unsigned rgb) {
    Polyline c{layer, {}, true, 0.18, rgb};
    for (int k = 0; k < 360; ++k)
      c.points.push_back(
          {cx + radius * std::cos(2 * kPi * k / 360), radius * std::sin(2 * kPi * k / 360)});
    d.polylines.push_back(std::move(c));
  };
  circle(0, pitch_radius(p, r.z1), "PITCH_CIRCLE", 0x1f77b4);
  circle(w.center_distance, pitch_radius(p, r.z2), "PITCH_CIRCLE", 0x1f77b4);
  const double mark = 0.1 * pitch_radius(p, r.z1);
  for (double cx : {0.0, w.center_distance}) {
    d.polylines.push_back({"CENTRES", {{cx - mark, 0}, {cx + mark, 0}}, false, 0.18, 0x7f7f7f});
    d.polylines.push_back({"CENTRES", {{cx, -mark}, {cx, mark}}, false, 0.18, 0x7f7f7f});
  }
  d.polylines.push_back({"CENTRE_LINE", {{0, 0}, {w.center_distance, 0}}, false, 0.13, 0x7f7f7f});
  Polyline chain{"CHAIN", wrap_pins(w, p, r.z1, r.z2), true, 0.35, 0xd62728};
  chain.points.pop_back();  // closed: the last pin is the first
  d.polylines.push_back(std::move(chain));
  return d;
}

Record describe_drive(const DriveResult& r, const Inputs&) {
  Record rec;
  rec.data = drive_value(r);
  rec.diagnostics = r.diagnostics;
  rec.table = drive_table(r);
  rec.drawings.push_back(drive_drawing(r));
  analysis::Chart c;
  c.title = "Taut centre distance of the polygon wrap over one driver pitch";
  c.x_label = "driver phase [°]";
  c.y_label = "centre distance [mm]";
  std::vector<double> x, exact, formula;
  for (std::size_t k = 0; k < r.exact.phases.size(); ++k) {
    x.push_back(deg(r.exact.phases[k]));
    exact.push_back(r.exact.values[k] * 1e3);
    formula.push_back(r.center_distance_formula * 1e3);
  }
  c.traces.push_back({"polygon wrap", x, exact});
  c.traces.push_back({"textbook formula", x, formula});
  rec.charts.push_back(std::move(c));
  return rec;
}

// ---------------------------------------------------------------------------------------------
// drive select

const std::vector<std::string> kSelectOrder = {"power",          "speed",       "ratio",
                                               "service_factor", "max_strands", "driver_teeth"};

void check_select(const Inputs& in, std::vector<Issue>& issues) {
  std::vector<Issue> added;
  positive(in, "power", "the transmitted power P > 0, e.g. 7.5kW", added);
  positive(in, "speed", "the driver's speed n1 > 0, e.g. 1000rpm", added);
  positive(in, "ratio", "the speed ratio n1/n2 > 0", added);
  if (in.present("service_factor") && !(in.number("service_factor") >= 1))
    added.push_back({"service_factor", in.text("service_factor"), "a service factor K_s ≥ 1"});
  if (in.integer("max_strands") > 4)
    added.push_back({"max_strands", in.text("max_strands"),
                     "1 … 4 strands (the ANSI multiple-strand factors stop at 4)"});
  if (in.integer("driver_teeth") > kMaxTeeth)
    added.push_back(
        {"driver_teeth", in.text("driver_teeth"), "3 … " + std::to_string(kMaxTeeth) + " teeth"});
  issues =
      analysis::in_read_order(issues, added, kSelectOrder, [](const std::string&) { return true; });
}

}  // namespace

SelectResult drive_select_run(const Inputs& in) {
  SelectResult s;
  s.power = in.number("power");
  s.speed = in.number("speed");
  s.ratio = in.number("ratio");
  s.service_factor = in.number("service_factor");
  s.max_strands = in.integer("max_strands");
  s.driver_teeth = in.integer("driver_teeth");
  s.driven_teeth = static_cast<int>(std::lround(s.driver_teeth * s.ratio));
  s.design_power = s.power * s.service_factor;
  std::vector<contact::ChainDimensions> chains;
  std::string unrated;
  for (const std::string& name : contact::iso606_names()) {
    const auto c = contact::iso606_chain(name);
    if (rated(c))
      chains.push_back(*c);
    else
      unrated += (unrated.empty() ? "" : ", ") + name;
  }
  std::stable_sort(chains.begin(), chains.end(),
                   [](const auto& a, const auto& b) { return a.pitch < b.pitch; });
  for (const contact::ChainDimensions& c : chains) {
    const AnsiConstants k = *ansi_constants(*ansi_number(c.name));
    for (int n = 1; n <= s.max_strands; ++n) {
      const Rating g = rate(k, c.pitch, s.driver_teeth, rpm(s.speed), n, s.power, s.service_factor);
      if (g.margin >= 1) s.candidates.push_back({c.name, c.pitch, n, g});
    }
  }
  if (!unrated.empty())
    s.diagnostics.push_back({Diagnostic::Severity::kInfo, "drive.select.unrated",
                             "not considered, no public power-rating formula was found for "
                             "them (ISO 606 B series): " +
                                 unrated,
                             0, 0});
  if (s.candidates.empty())
    s.diagnostics.push_back({Diagnostic::Severity::kInfeasible, "drive.select.none",
                             "no catalogued A-series chain of up to " +
                                 std::to_string(s.max_strands) + " strands carries " +
                                 format_g(s.design_power / 1e3, 4) + " kW at " +
                                 format_g(rpm(s.speed), 5) + " rpm",
                             s.design_power, 0});
  return s;
}

namespace {

Record describe_select(const SelectResult& s, const Inputs&) {
  Record rec;
  Value list = Value::array();
  analysis::Grid grid;
  grid.title = "Chains that carry the design power (smallest pitch first)";
  grid.columns = {"chain", "strands", "pitch [mm]", "H1 [kW]", "H2 [kW]", "rated [kW]", "margin"};
  for (const Candidate& c : s.candidates) {
    list.push_back(Value::object({{"chain", c.chain},
                                  {"standard", "ANSI #" + std::to_string(c.rating.ansi)},
                                  {"strands", c.strands},
                                  {"pitch", c.pitch},
                                  {"plate_fatigue", c.rating.plate_fatigue},
                                  {"roller_impact", c.rating.roller_impact},
                                  {"strand_factor", c.rating.strand_factor},
                                  {"rated_power", c.rating.rated_power},
                                  {"margin", c.rating.margin}}));
    grid.rows.push_back({c.chain, std::to_string(c.strands), format_g(c.pitch * 1e3, 5),
                         format_g(c.rating.plate_fatigue / 1e3, 4),
                         format_g(c.rating.roller_impact / 1e3, 4),
                         format_g(c.rating.rated_power / 1e3, 4), format_g(c.rating.margin, 4)});
  }
  Value j = Value::object();
  j["model"] = "drive.select";
  j["source"] = "ANSI envelopes H1, H2 and strand factors as in issue 16 (A-series chains)";
  j["power"] = s.power;
  j["speed"] = s.speed;
  j["ratio"] = s.ratio;
  j["driver_teeth"] = s.driver_teeth;
  j["driven_teeth"] = s.driven_teeth;
  j["service_factor"] = s.service_factor;
  j["design_power"] = s.design_power;
  j["candidates"] = std::move(list);
  j["units"] = analysis::units_value({{"power", "W"},
                                      {"speed", "rad/s"},
                                      {"ratio", "1"},
                                      {"design_power", "W"},
                                      {"pitch", "m"},
                                      {"plate_fatigue", "W"},
                                      {"roller_impact", "W"},
                                      {"rated_power", "W"},
                                      {"margin", "1"}});
  j["diagnostics"] = analysis::diagnostics_value(s.diagnostics);
  rec.data = std::move(j);
  rec.diagnostics = s.diagnostics;
  std::ostringstream t;
  t << "Catena drive select: " << format_g(s.power / 1e3, 5) << " kW x K_s "
    << format_g(s.service_factor, 4) << " = " << format_g(s.design_power / 1e3, 5)
    << " kW design power at " << format_g(rpm(s.speed), 6) << " rpm, z1 = " << s.driver_teeth
    << ", z2 = " << s.driven_teeth << "\n\n";
  char line[160];
  std::snprintf(line, sizeof line, "  %-6s %7s %10s %9s %9s %10s %7s\n", "chain", "strands",
                "pitch[mm]", "H1[kW]", "H2[kW]", "rated[kW]", "margin");
  t << line;
  for (const auto& row : grid.rows) {
    std::snprintf(line, sizeof line, "  %-6s %7s %10s %9s %9s %10s %7s\n", row[0].c_str(),
                  row[1].c_str(), row[2].c_str(), row[3].c_str(), row[4].c_str(), row[5].c_str(),
                  row[6].c_str());
    t << line;
  }
  for (const Diagnostic& d : s.diagnostics)
    t << "\n  " << to_string(d.severity) << " " << d.code << ": " << d.message;
  if (!s.diagnostics.empty()) t << "\n";
  rec.table = t.str();
  rec.grids.push_back(std::move(grid));
  return rec;
}

analysis::Analysis make_drive() {
  using namespace analysis;
  using K = QuantityKind;
  Analysis a;
  a.name = "drive";
  a.command = {"drive"};
  a.title = "Two-sprocket roller-chain drive: layout, loads and rating (issue 16 §3)";
  a.help =
      "Two-sprocket roller-chain drive: links, centre distance (textbook and exact polygon "
      "wrap), speeds, wrap, tensions, shaft loads, sag, ANSI rating; 'drive select' to choose "
      "a chain";
  a.seed = "issue 16 §3";
  a.docs = "docs/models/drive.md";
  a.chain_types = {"roller-iso606"};
  a.formats = {.table = true, .csv = false, .drawing = true};
  a.parameters = {
      text("chain", "ISO 606 chain of the catalogue (e.g. 08A, 12B)") |
          Required{"an ISO 606 chain of the catalogue"},
      integer("teeth", 3, "z1,z2: driver and driven tooth counts") | ListOf{} | NotShared{} |
          Required{"z1,z2: the driver's and the driven sprocket's tooth counts"},
      quantity("center_distance", K::kLength,
               "centre distance a wanted (the link count is rounded up to even); or --links"),
      integer("links", 2, "link count X (odd: an offset link); or --center-distance"),
      quantity("speed", K::kAngularSpeed,
               "driver speed n1, e.g. 1000rpm (a bare number is rad/s)") |
          Required{"the driver's speed n1, e.g. 1000rpm"},
      quantity("power", K::kPower, "transmitted power P") |
          Required{"the transmitted power P, e.g. 7.5kW"},
      number("service_factor", "K_s ≥ 1; required when the chain is rated (A series)"),
      integer("strands", 1, "strands k (rating: 1 … 4)") | Default{"1"},
      quantity("mass_per_metre", K::kMassPerLength,
               "chain mass per metre q, all strands (default: the catalogue's × strands)"),
      quantity("slack_tension", K::kForce,
               "horizontal tension H of the slack span for its sag f = q g l²/(8H)"),
      quantity("slack", K::kLength,
               "chain length ΔL beyond the taut length, for the sag f ≈ √(3 l ΔL / 8)"),
  };
  a.check = check_drive;
  set_functions<DriveResult>(a, drive_run, describe_drive);
  return a;
}

analysis::Analysis make_select() {
  using namespace analysis;
  using K = QuantityKind;
  Analysis a;
  a.name = "drive_select";
  a.command = {"drive", "select"};
  a.title = "Roller-chain selection: every chain and strand count that carries the design power";
  a.help =
      "every catalogued A-series chain and strand count that carries P × K_s, smallest "
      "pitch first, with the margin";
  a.seed = "issue 16 §3";
  a.docs = "docs/models/drive.md";
  a.chain_types = {"roller-iso606"};
  a.formats = {.table = true, .csv = false, .drawing = false};
  a.parameters = {
      quantity("power", K::kPower, "transmitted power P") |
          Required{"the transmitted power P, e.g. 7.5kW"},
      quantity("speed", K::kAngularSpeed,
               "driver speed n1, e.g. 1000rpm (a bare number is rad/s)") |
          Required{"the driver's speed n1, e.g. 1000rpm"},
      [] {
        Parameter p = number("ratio", "speed ratio n1/n2 = z2/z1") | Required{"n1/n2 > 0"};
        p.expected = "a speed ratio n1/n2 > 0";
        return p;
      }(),
      [] {
        Parameter p = number("service_factor", "K_s ≥ 1 (no default)") |
                      Required{"the service factor K_s ≥ 1 (Catena has no default)"};
        return p;
      }(),
      integer("max_strands", 1, "strand counts tried: 1 … this (at most 4)") | Default{"3"},
      integer("driver_teeth", 3, "driver tooth count N1 of the rating") | Default{"17"},
  };
  a.check = check_select;
  set_functions<SelectResult>(a, drive_select_run, describe_select);
  return a;
}

}  // namespace

const analysis::Analysis& drive_analysis() {
  static const analysis::Analysis a = make_drive();
  return a;
}

const analysis::Analysis& drive_select_analysis() {
  static const analysis::Analysis a = make_select();
  return a;
}

}  // namespace catena::drive
