// `dynamics` — a roller-chain loop over ISO 606 sprockets in time (issue 21, Stage 3) — as an
// analysis. Its input is the [dynamics] table with [[dynamics.sprocket]] elements, so
// `catena dynamics case.toml` reads a case file's [dynamics] and ignores the rest.
//
// Without centres it sets up the drive the core's validation (6) runs (tests/validation/
// dynamics_drive_test.cpp): two equal sprockets (z even) on a horizontal line, a whole number of
// pitches apart, the chain wrapped half-way round each and straight between, every node moving at
// the driver's pitch-line speed. The centre distance is not an input: it follows from the links,
// (links − z)/2 pitches. With centre_x and centre_y on every sprocket (the free layout: any
// number of driver, driven and idler wheels), the chain starts on the belt path round the wheels'
// pitch circles (parse_layout below, dynamics/layout.hpp).
#include "catena/dynamics/analysis.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <regex>
#include <sstream>
#include <tuple>

#include "catena/contact/chain_catalog.hpp"
#include "catena/contact/roller_tooth.hpp"
#include "catena/core/progress.hpp"
#include "catena/core/round.hpp"
#include "catena/drive/sprocket.hpp"
#include "catena/dynamics/guide_hint.hpp"
#include "catena/dynamics/integrator.hpp"
#include "catena/dynamics/layout.hpp"
#include "catena/dynamics/period_means.hpp"
#include "catena/dynamics/pocket_wheel.hpp"
#include "catena/dynamics/report_charts.hpp"
#include "catena/dynamics/span_modes.hpp"
#include "catena/io/bind.hpp"
#include "catena/io/case_file.hpp"
#include "catena/io/quantity.hpp"
#include "catena/pocketwheel/geometry.hpp"

namespace catena::dynamics {
namespace {

using analysis::format_g;
using analysis::InputValue;
using analysis::Parameter;
using analysis::ParameterType;
using analysis::Record;
using analysis::times_text;
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

// Where a catalogue axial stiffness comes from (data/catalog/iso606/README.md, CALCULATORS_K),
// and what it is worth: the help says the quality, the diagnostic both, the JSON the source.
constexpr const char* kCatalogueStiffnessSource =
    "ISO 606 catalogue (data/catalog/iso606/README.md, CALCULATORS_K): EA = 12 k lbf from a "
    "third party's stretch factor k, \"interpolated from a data from Tsubaki\" (which chart is "
    "not stated); k_link = EA/p";
constexpr const char* kCatalogueStiffnessQuality =
    "a secondary source: an order of magnitude, not a design value";

std::vector<Parameter> table_fields() {
  using analysis::number;
  using analysis::quantity;
  using analysis::text;
  return {
      text("chain",
           "ISO 606 designation (\"12B\"): pitch, roller, width and mass from the "
           "catalogue, and for 08A … 32A (no pitch given) the axial stiffness"),
      quantity("pitch", K::kLength, "pitch p (overrides the catalogue's)"),
      quantity("mass_per_metre", K::kMassPerLength, "chain mass per metre q"),
      quantity("roller_diameter", K::kLength, "roller diameter d1"),
      quantity("inner_width", K::kLength, "inner width b1"),
      number("links",
             "links in the closed loop, an integer z + 2m with m >= 2, at most 10000; with "
             "centres: optional, a count the belt path fits (default: the nearest that fits)"),
      quantity("axial_stiffness", K::kForcePerLength,
               std::string("axial stiffness k of one link [N/m] (default with chain = 08A … 32A "
                           "and no pitch given: the catalogue's, ") +
                   kCatalogueStiffnessQuality + "; required otherwise)"),
      number("axial_damping", "axial damping c of one link [N s/m], >= 0 (default 0)"),
      quantity("pretension", K::kForce, "the loop's tension at rest, >= 0 (default 0)"),
      quantity("contact_stiffness", K::kForcePerLength,
               "roller-seat penalty k_c [N/m] (default: the Hertz line contact's secant "
               "stiffness at the expected load)"),
      number("contact_damping", "roller-seat damping c_c [N s/m], >= 0"),
      number("seat_friction",
             "Coulomb friction coefficient mu of the roller-seat contact in [0, 1] (default 0)"),
      quantity("duration", K::kTime, "simulated time, > 0"),
      quantity("step", K::kTime, "time step h, > 0"),
      quantity("output_interval", K::kTime,
               "sampling interval of the series, rounded to whole steps (default: every step)"),
      number("theta", "theta of the integrator in [0.5, 1] (default 0.6; drives need >= 0.6)"),
      quantity("spectrum_start", K::kTime,
               "the report's span-tension spectrum from this time to the end, in [0, duration - "
               "15 output intervals] (at least 16 samples; default: half the duration)"),
      number("gravity",
             "true (9.80665 m/s^2), false, or g in [0, 100] m/s^2, downward (-y; default: none)"),
      text("work_balance",
           "true to add the run's work balance to the summary: input, friction, link and "
           "contact dampers, numerical (default false)"),
      // hinge friction (docs/models/dynamics.md, "Hinges")
      text("hinge", "frictionless, sliding or rolling (default frictionless)"),
      text("slack_spans",
           "with centres, a chain longer than the belt path: lowest (default; the slack sags in "
           "the span facing down) or all (shared by every span between two wheels inside the "
           "loop, in proportion to their lengths)"),
      number("hinge_friction", "sliding: pin friction coefficient mu in [0, 1]"),
      quantity("pin_diameter", K::kLength,
               "sliding: pin diameter d2, > 0 and < p/2 (default: the ISO 606 catalogue's)"),
      number("rolling_resistance", "rolling: rolling-resistance coefficient c_r in [0, 0.1]"),
      quantity("plate_radius", K::kLength, "rolling: the plate's working arc R1, > 0"),
      quantity("face_radius", K::kLength,
               "rolling: the roller's concave face R2 > R1 (default: a flat face)"),
      quantity("hinge_band", K::kAngularSpeed,
               "rate band of the regularised hinge friction, in (0, 100] rad/s (default 5 rad/s)"),
      number("hinge_stick_stiffness",
             "with friction on (hinge sliding or rolling): the stick law's spring k_t [N m/rad] "
             "in each hinge, >= 0: a hinge holds until the spring's torque reaches the friction "
             "torque (default 0: the regularised friction, which creeps inside its rate band)"),
      number("hinge_stick_damping",
             "a damper c_t [N m s/rad] beside the hinges' stick spring, >= 0, with "
             "hinge_stick_stiffness (default 0)"),
      text("pin_load",
           "with friction on (hinge sliding or rolling): the hinges' pin load, mean (of the "
           "two links' tensions, the default) or pin_link (the outer link's; links alternate, "
           "link 0 outer; an even count); refused with hinge = frictionless"),
      text("positions",
           "true to add every node's x and y at each output sample to the JSON (default false; "
           "at most 500000 node-samples)"),
      // the seats' elastic law (docs/models/dynamics.md, "Contact law")
      text("contact_law",
           "the ISO seats' elastic law: linear (the penalty contact_stiffness, the default) or "
           "line (the Hertz line contact's approach law, followed in load, on the seats and "
           "the guides' rails; contact_stiffness, given or the Hertz default, is then a "
           "take-up's stops' penalty; not with wheel = \"pocket\")"),
      // the contacts' elastic force over a step (docs/models/dynamics.md, "Sprockets: the
      // discrete gradient")
      text("discrete_gradient",
           "true or false: the ISO seats', the pocket wheels' pockets' and the guides' rails' "
           "elastic force as the discrete gradient of the contact's energy over each step "
           "(conserving, for theta = 0.5, on ISO seats and rails, whose dampers it takes over "
           "the step too; with wheel = \"pocket\" the tension-only links' force and damper too) "
           "instead of at the theta point (default true with contact_law = \"line\", false "
           "with \"linear\" and with wheel = \"pocket\")"),
      // the round-link chain on pocket wheels (docs/models/dynamics.md, "Pocket wheel")
      text("wheel",
           "iso606 (roller chain on ISO 606 sprockets, the default) or pocket (round-link chain "
           "on pocket wheels, seed 003: pitch = the link's inner length t, wire_diameter d, "
           "teeth = pockets z)"),
      quantity("wire_diameter", K::kLength,
               "pocket: the links' wire diameter d, in (0, (pitch - pretension/axial_stiffness "
               "- 1e-06 m)/2] (a link holds its two neighbours' wires; catena pocketwheel's --wire "
               "takes (0, pitch/2])"),
      quantity("pocket_clearance", K::kLength,
               "pocket: a joint's free play about its pocket's vertex, in (0, 0.1 pitch] "
               "(default 0.1 mm)"),
      quantity("pocket_mouth", K::kLength,
               "pocket: the pockets' mouth ramp w, in [0, pocket_clearance] (default 0: the sharp "
               "mouth; not with pocket_release = true)"),
      text("pocket_release",
           "pocket: true to let a joint leaving its pocket go continuously over the release band "
           "(default false: the sharp mouth's cut; not with pocket_mouth > 0)")};
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
      quantity("stick_stiffness", K::kForcePerLength,
               "the stick law's tangential spring k_t [N/m], >= 0: a roller holds until its "
               "force reaches mu times the normal force (default 0: the regularised friction, "
               "which creeps at rest)"),
      number("stick_damping",
             "a damper c_t [N s/m] beside the stick law's spring, >= 0, with stick_stiffness "
             "(default 0)"),
      quantity("load_per_metre", K::kMassPerLength,
               "conveyed material riding on the chain along the rail, kg/m in [0, " +
                   check::format_si(kMaxRailLoad, "") +
                   "] (default 0; its weight needs gravity and must press the chain onto the "
                   "rail: straight, x1 > x0; arc, the carrying side facing up over the whole arc)"),
      text("load_inertia",
           "true: the load's mass moves with the chain, material arriving at rest on the rail's "
           "entry is caught (a force q_L v^2 there) and leaves at its exit with the chain's "
           "speed (default false: weight only; only with load_per_metre > 0)"),
      quantity("load_speed", K::kSpeed,
               "with load_inertia = true: the speed the material arrives with (a chute or "
               "feeder), along the rail from (x0, y0) to (x1, y1), on an arc counter-clockwise "
               "(from start_angle to end_angle); negative the other way; in [-100, 100] m/s "
               "(default 0: it arrives at rest)"),
      quantity("contact_stiffness", K::kForcePerLength,
               "roller-rail penalty [N/m] (default: dynamics.contact_stiffness; not with "
               "contact_law = \"line\": the rail then follows the line law)"),
      quantity("rail_modulus", K::kStress,
               "contact_law = \"line\": the rail's Young's modulus, in [0.1, 1000] GPa (default "
               "210 GPa, steel as the rollers; UHMW-PE 0.5-1 GPa)"),
      number("rail_poisson",
             "contact_law = \"line\": the rail's Poisson's ratio, in [0, 0.5) (default 0.3)"),
      number("contact_damping",
             "roller-rail damping [N s/m], >= 0 (default: dynamics.contact_damping)"),
      quantity("lead_in_radius", K::kLength,
               "straight or arc: a lead-in, the surface radius of an arc tangent to the rail at "
               "its end and bending away from the rollers, > 0 (on an arc with the rollers "
               "outside, below its radius; default: none, the rail's end is square)"),
      quantity("lead_in_angle", K::kAngle,
               "straight or arc: the lead-in arc's sweep, in [0.1, 90] deg (default 30 deg; with "
               "lead_in_radius; on an arc its lead-ins fit between the arc's ends)"),
      text("lead_in_end",
           "straight or arc: where the lead-ins go: start (at x0, y0; an arc's start_angle), end "
           "(at x1, y1; its end_angle) or both (default both; with lead_in_radius)")};
}

std::vector<Parameter> sprocket_fields() {
  using analysis::number;
  using analysis::quantity;
  using analysis::text;
  return {
      number("teeth",
             "number of teeth z, an integer in [8, 150] (even for two wheels without centres)"),
      text("role", "driver, driven or idler (idler: with centres only)"),
      text("side",
           "the side of the chain the wheel runs on: inside (default; the loop wraps it) or "
           "outside (on the back of the chain, a serpentine path, the wheel turning clockwise; "
           "any wheel of the free layout, the rows then listed counter-clockwise round the "
           "loop)"),
      quantity("speed", K::kAngularSpeed,
               "driver: speed, > 0 (counter-clockwise; clockwise on side = \"outside\")"),
      number("inertia", "driven or idler: moment of inertia J [kg m^2], > 0"),
      number("load_torque", "driven: load torque T_L [N m], >= 0"),
      quantity("centre_x", K::kLength,
               "the wheel's centre, x (given on every sprocket or none: without centres, two "
               "equal wheels on a line)"),
      quantity("centre_y", K::kLength, "the wheel's centre, y (y up)"),
      // the take-up (docs/models/dynamics.md, "Take-up"): an idler's or a driven wheel's centre
      // on a slide
      quantity("takeup_force", K::kForce,
               "idler or driven: the take-up's force along its slide, in [0, 1e6] N (with "
               "takeup_stiffness: the spring's preload at the start; > 0 without it)"),
      quantity(
          "takeup_direction", K::kAngle,
          "idler or driven: the slide's direction the force pushes along, counter-clockwise from "
          "+x, in [-360, 360] deg"),
      quantity("takeup_stiffness", K::kForcePerLength,
               "idler or driven: the take-up spring's stiffness, in [0, 1e9] N/m (default 0: a "
               "constant force)"),
      number("takeup_damping",
             "idler or driven: the slide's damper [N s/m], in [0, 1e6] (default 0)"),
      number(
          "takeup_mass",
          "idler or driven: the sliding mass [kg], in (0, 1000] (default 2 J / R^2, the idler as a "
          "disc of its pitch radius)"),
      quantity("takeup_travel_min", K::kLength,
               "take-up: the slide's end stop behind the start, in [-10, 0] m (default: none)"),
      quantity("takeup_travel_max", K::kLength,
               "take-up: the slide's end stop ahead of the start, along takeup_direction, in "
               "[0, 10] m (default: none)"),
      quantity("takeup_lost_force", K::kForce,
               "take-up: the chain's force on the wheel at or below which the wheel counts as "
               "without the chain (dynamics.takeup_lost_chain), in [0, 1e6] N (default: 1 % of "
               "takeup_force, at most 1 N)"),
      quantity("takeup_lost_time", K::kTime,
               "take-up: how long that force must stay there for the warning, in [0, 1000] s "
               "(default 10 ms)"),
      number("seat_friction",
             "Coulomb mu of this wheel's roller-seat contact in [0, 1] (default: "
             "dynamics.seat_friction)")};
}

const Parameter& table_parameter() {
  static const Parameter p = [] {
    Parameter t;
    t.name = "dynamics";
    t.type = ParameterType::kTable;
    t.doc =
        "TOML file with a [dynamics] table and two or more [[dynamics.sprocket]] tables (a case "
        "file works); in a case file, its own [dynamics] table";
    t.required = true;
    t.expected =
        "a [dynamics] table (chain, links unless a free layout chooses it, axial_stiffness "
        "unless chain is 08A … 32A and no pitch is given, contact_damping, duration, step; with "
        "wheel = \"pocket\" pitch, wire_diameter and mass_per_metre instead of chain, and "
        "contact_stiffness, which the ISO 606 seats default to the Hertz stiffness at the expected "
        "load) and two or more [[dynamics.sprocket]] tables (docs/models/dynamics.md)";
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
  std::optional<double> teeth, speed, inertia, load_torque, centre_x, centre_y;
  std::optional<double> takeup_force, takeup_direction, takeup_stiffness, takeup_damping,
      takeup_mass, takeup_travel_min, takeup_travel_max;
  std::optional<double> takeup_lost_force, takeup_lost_time;  // the lost-chain warning's
  std::optional<double> seat_friction;  // this wheel's μ, overriding dynamics.seat_friction
  std::string role;
  bool has_role = false;
  std::string side = "inside";      // inside or outside (the back of the chain)
  std::map<std::string, int> seen;  // every key given (read or not) → its line
};

// One wheel of the free layout (every sprocket with a centre).
struct LayoutWheel {
  std::string role;   // driver, driven or idler
  bool back = false;  // side = "outside": on the back of the chain
  int teeth = 0;
  double x = NAN, y = NAN;
  double speed = NAN, inertia = NAN, load = 0.0;
  // an idler's take-up (docs/models/dynamics.md, "Take-up"); mass NAN: the default 2 J / R²
  bool takeup = false;
  double takeup_force = 0.0, takeup_direction = 0.0, takeup_stiffness = 0.0;
  double takeup_damping = 0.0, takeup_mass = NAN;
  // the slide's end stops [m] (±infinity: none)
  double takeup_travel_min = -INFINITY, takeup_travel_max = INFINITY;
  // the lost-chain warning's zero [N] (NAN: the default, min(1 N, 1 % of F₀)) and time [s]
  double takeup_lost_force = NAN, takeup_lost_time = 0.010;
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
  // axial_stiffness omitted: the catalogue row's (contact::ChainDimensions::axial_stiffness)
  bool catalogue_stiffness = false;
  double contact_stiffness = NAN, contact_damping = NAN;
  double seat_friction = 0.0;  // μ of the roller-seat contact
  // wheel = "pocket": a round-link chain (pitch t, wire d) on two equal pocket wheels
  bool pocket = false;
  double wire = NAN, clearance = NAN;
  // the pockets' mouth ramp w [m] (0: the sharp mouth) and release (Sprocket::pocket_mouth,
  // pocket_release; docs/models/dynamics.md, "Pocket wheel: the mouth's ramp", "unwinding")
  double mouth = 0.0;
  bool release = false;
  double pocket_radius = NAN, pocket_angle = NAN;  // R and δ1 of seed 003
  // per sprocket (in the input's order, the model's): its own μ, NaN = seat_friction
  std::vector<double> wheel_friction;
  double duration = NAN, step = NAN, interval = NAN, theta = 0.6;
  double spectrum_start = NAN;  // [s] the report's spectrum window's start (NAN: the half)
  int teeth = 0;
  std::size_t driver = 0, driven = 1;
  double speed = NAN, inertia = NAN, load = 0.0;
  double gravity = 0.0;       // [m/s²] downward (−y)
  std::vector<Guide> guides;  // [[dynamics.guide]]
  // each of `guides` as a message names it: guide[i] as the file numbers it, a lead-in arc (laid
  // after the guides as given) as the lead-in at its rail's start or end
  std::vector<std::string> guide_names;
  // the guides as given (read whole) are guides[0, given_guides), the lead-in arcs follow; each
  // one's lead_in_angle [rad] (NaN: it has no lead-in)
  std::size_t given_guides = 0;
  std::vector<double> lead_in_angles;
  // each lead-in arc's (guides[given_guides + k]) rail, an index into guides, and whether it is
  // laid at the rail's start (per arc, for the run's message; parse's LeadInRail, per rail, is not
  // kept)
  std::vector<std::pair<std::size_t, bool>> lead_in_rails;
  bool work_balance = false;  // summary.work_balance in the output
  // the free layout (docs/models/dynamics.md, "Command"): every sprocket with its centre; empty
  // `wheels` for the two equal wheels on a line
  std::vector<LayoutWheel> wheels;
  std::vector<Circle> circles;  // the pitch circles
  BeltPath path;                // the belt path round them
  LoopPlacement placement;      // the nodes on it
  double laid_pitch = NAN;      // [m] the links' chord as laid: the pitch on the line
  BeltPath laid;                // a start with slack: the path with its slack span sagging
  double slack = 0.0;           // [m] the chain's length beyond the path's (a start with slack)
  // `links` omitted: the count taken (the fitting count nearest the path's length in pitches)
  // and the slack it implies, N (p − h) [m] with h the chord the taut loop is laid at (negative:
  // the chain is shorter than the loop and laid stretched, h > p)
  bool links_fitted = false;
  double fitted_slack = 0.0;
  bool slack_all = false;  // slack_spans = "all": the slack shared by every span that sags
  std::vector<std::size_t> slack_pieces;  // a start with slack: the sagging pieces of `laid`
  std::vector<double> tip;             // a start with slack: each wheel's tip radius d_a,max/2 [m]
  std::vector<int> layout_teeth;       // the free layout: each wheel's teeth
  std::vector<double> seat_clearance;  // the free layout: each wheel's seat clearance ri − d1/2 [m]
  // a given `links` refused as too long for the slack to sag: the issue (its text rebuilt with
  // the limit over the guides once they are read) and what it was built from
  struct SlackRefusal {
    std::size_t issue = 0;
    std::string why;  // the counts that fit
    int chosen = 0;
    double over = 0.0;
    std::vector<std::size_t> pieces;
    std::string blocked;
  };
  std::optional<SlackRefusal> slack_refusal;
  bool layout() const { return !wheels.empty(); }
  std::string hinge = "frictionless";  // frictionless, sliding or rolling
  HingeFriction hinge_law;             // arm 0 when frictionless
  bool positions = false;              // positions {x, y} in the output
  // contact_law = "line": the ISO seats follow the Hertz line contact's approach law
  bool line_law = false;
  // discrete_gradient: the seats' and rails' elastic force over the step (default: line_law)
  bool discrete_gradient = false;
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
    const double delta = contact::slice_approach(seat_line_contact(probe, width), load / width);
    return delta > 0.0 && std::isfinite(delta) ? load / delta : NAN;
  } catch (const InputError&) {
    return NAN;
  }
}

// The bounds on the scales of the inputs (docs/models/dynamics.md, "The inputs' bounds"): each
// refuses, before anything runs, a value at which the steps were measured to stop converging,
// with a margin, and names the keys it depends on. m = q p is a node's mass (a link's), θh the
// implicit part of the step.
// the links' stiffness and damping over a step against a node's mass, k (θh)² / m and c θh / m:
// the steps of the 12B example stopped converging at about 1.5e8 (k) and 8e7 (c)
constexpr double kMaxLinkRatio = 1e6;
// the seats' and the rails' penalty over a step, k_c (θh)² / m: the 12B example stopped at about
// 4.5e4 at 0.1 ms and 4.9e3 at 1 ms, while a 06B ran at 1.9e4 at 1 ms: no one ratio separates
// them, so the bound catches only the absurd
constexpr double kMaxContactRatio = 5e5;
// the seats' and the rails' damper over a step, c_c θh / m: the 12B stopped at about 250 at 0.1 ms,
// a 06B ran at 130 at 1 ms; the bound catches only the absurd
constexpr double kMaxContactDampingRatio = 5e3;
// the hinges' stick spring over a step against a node's mass, k_t (θh)² / (m p²) (the middle node
// of a straight pair turns the hinge by 2/p per metre, so it feels about 4θ k_t/p²): with the
// line search's crossing cut (Integrator::step) the 12B's steps stopped converging from 28.5 at
// 0.2 ms (30 ran), 40 at 0.1 ms (38 ran) and 63 at 0.05 ms (52 and 84 ran); without it from 21,
// 25 and 29. No one ratio separates them. Above the warning ratio (half the lowest failure) a run
// is warned; above the bound (every 12B run from 100 down to 40 at 0.1 ms stopped, one at 84 ran
// at 0.05 ms) it is refused
constexpr double kHingeStickWarnRatio = 14, kMaxHingeStickRatio = 100;
// the chain's travel in a step, ω R h, in pitches: stopped at about 1.1 pitches (a round-link
// chain on pocket wheels, whose links seat with a jump, at 0.13: kMaxPocketTravel)
constexpr double kMaxTravel = 0.25, kMaxPocketTravel = 0.025;
// a driven wheel's load: its tension T_L/R stretches a link by at most this part of the pitch
// (as the pretension's bound)
constexpr double kMaxStretch = 0.1;
// a wheel's inertia against the chain's own about its axis, M R² (M = q 2πR, the chain on one round
// of the wheel's pitch circle)
constexpr double kMinInertiaRatio = 1e-3, kMaxInertiaRatio = 1e6;
constexpr double kMinStep = 1e-9;         // [s]
constexpr double kMaxMassPerMetre = 1e4;  // [kg/m]

// The pitch radius of a wheel of z teeth (a pocket wheel: its pocket radius R).
double pitch_radius(const Setup& s, int teeth) {
  if (s.pocket) return s.pocket_radius;
  return teeth >= 3 ? 0.5 * s.pitch / std::sin(kPi / teeth) : NAN;
}

// What the bounds over a step compare, for their messages.
constexpr const char* kLinkScale =
    " (the link's spring or damper over a step against a node's mass; a smaller step allows more)";
constexpr const char* kContactScale =
    " (the seat's or rail's spring or damper over a step against a roller's mass; a smaller step "
    "allows more)";

using check::down_to;  // (a limit named so that the value named is inside)

// x rounded up to `digits` significant digits (a lower limit named so that the value named is
// inside).
double up_to(double x, int digits) {
  if (!(x > 0.0) || !std::isfinite(x)) return x;
  const double unit = std::pow(10.0, std::floor(std::log10(x)) - (digits - 1));
  return std::ceil(x / unit * (1.0 - 1e-12)) * unit;
}

// A rail's square end as the messages name it, the start's check's and the run's (docs/cli.md,
// "dynamics.guide"): its end's keys and point, "(x1, y1) (150, 30.77) mm", and the lead-in's keys
// that close it, "(lead_in_radius, lead_in_end = \"end\" or \"both\")".
std::string square_end_name(const Guide& rail, const SquareEnd& end) {
  const bool arc = rail.kind == Guide::Kind::kArc;
  return (arc ? std::string(end.at_start ? "start_angle" : "end_angle")
              : std::string(end.at_start ? "(x0, y0)" : "(x1, y1)")) +
         " (" + format_g(end.x * 1e3, 4) + ", " + format_g(end.y * 1e3, 4) + ") mm";
}
// A lead-in as the messages name it, by its rail ("guide[0]" at parse, "dynamics.guide[0]" in
// the run's): "the lead-in at the end of guide[0]".
std::string lead_in_name(bool at_start, const std::string& rail) {
  return "the lead-in at the " + std::string(at_start ? "start" : "end") + " of " + rail;
}
std::string square_end_lead_in(const SquareEnd& end) {
  return std::string("(lead_in_radius, lead_in_end = \"") + (end.at_start ? "start" : "end") +
         "\" or \"both\")";
}

// A rail's end joined to an arc smaller than the roller (layout.hpp, SquareEnd::from), crossed G
// below the line of its rollers, past the arc's centre (R + r), as the start's check and the run
// name it: what it is ("under the lead-in at the end of dynamics.guide[0] (lead_in_radius 0.3 mm,
// lead_in_angle 30 deg), whose contact ends 6.335 mm below the line of the rail's rollers at the
// arc's centre (lead_in_radius + roller radius), where the chain runs onto it") and the remedy. A
// roller running parallel to the rail at G passes under the centre and meets the rail's end; with
// a lead-in of radius R' it meets the arc's roller line within its sweep α, clearing its far end
// too, exactly when (R' + r)(1 − cos α) >= G (lead_in_clear_radius; R' >= G − r at 90°, the least
// of any sweep): G > R + r, so no sweep at the lead-in's radius does. A hand-laid arc is named by
// its guide, its remedy the same clearance at its own sweep, capped at a quarter turn (past it the
// roller meets the arc's roller line within 90° already: G − r). G rounded up, the radii from it
// rounded up.
struct UnderArc {
  std::string what, remedy;
};
// The clearance of a lead-in for a roller parallel to the rail G [mm] below its roller line (roller
// radius r [m]), named by a rail's own end under a small lead-in and by a lead-in's far end.
std::string lead_in_clears_text(double r, double G) {
  return "give that end a lead-in a roller running parallel to the rail there clears, "
         "(lead_in_radius + roller radius " +
         format_g(r * 1e3, 4) + " mm) (1 - cos lead_in_angle) >= " + format_g(G, 4) + " mm";
}
UnderArc under_arc_text(const Setup& s, const SquareEnd& end, double g, const std::string& rail) {
  const Guide& arc = s.guides[end.under];
  const double R = arc.radius, r = arc.roller_radius;
  auto mm = [](double v) { return format_g(v * 1e3, 4) + " mm"; };
  const double G = up_to(g * 1e3, 4);  // [mm]
  const double least = up_to(G - r * 1e3, 3);
  const std::string centre = "whose contact ends " + mm(R + r) +
                             " below the line of the rail's rollers at the arc's centre (";
  if (end.under < s.given_guides) {
    const double sweep = std::min(std::abs(arc.end_angle - arc.start_angle), kPi / 2.0);
    const double at_sweep = up_to(lead_in_clear_radius(sweep, r * 1e3, G), 3);  // [mm]
    const std::string deg = format_g(sweep * 180.0 / kPi, 4);
    return {"under the arc dynamics." + s.guide_names[end.under] + " (radius " + mm(R) +
                ", less than the roller radius " + mm(r) + ") joined to it, " + centre +
                "radius + roller radius), where the chain runs onto it",
            "give that arc a radius a roller running parallel to the rail there clears, (radius "
            "+ roller radius " +
                mm(r) + ") (1 - cos sweep) >= " + format_g(G, 4) + " mm, at its sweep " + deg +
                " deg (end_angle - start_angle, a quarter turn at most counted): radius >= " +
                format_g(at_sweep, 3) + " mm" +
                (sweep < kPi / 2.0
                     ? ", or at a sweep of 90 deg, radius >= " + format_g(least, 3) + " mm"
                     : std::string())};
  }
  const bool at_start = s.lead_in_rails[end.under - s.given_guides].second;
  const double a = arc.end_angle - arc.start_angle;
  const double radius = up_to(lead_in_clear_radius(a, r * 1e3, G), 3);  // [mm]
  return {"under " + lead_in_name(at_start, rail) + " (lead_in_radius " + mm(R) +
              ", lead_in_angle " + format_g(a * 180.0 / kPi, 4) + " deg), " + centre +
              "lead_in_radius + roller radius), where the chain runs onto it",
          lead_in_clears_text(r, G) + ", which no lead_in_angle meets at its lead_in_radius " +
              mm(R) + ": at its lead_in_angle " + format_g(a * 180.0 / kPi, 4) +
              " deg, lead_in_radius >= " + format_g(radius, 3) +
              " mm, or at lead_in_angle 90 deg, lead_in_radius >= " + format_g(least, 3) +
              " mm (lead_in_end = \"" + (at_start ? "start" : "end") + "\" or \"both\")"};
}

// The most a stiffness (power 2) or a damping (power 1) over a step may be, `ratio` m/(θh)^power,
// and the text naming it and the keys it follows from.
std::string scale_bound(const Setup& s, double ratio, int power, const char* unit, double& most) {
  const double m = s.mass_per_metre * s.pitch;
  const double th = s.theta * s.step;
  most = ratio * m / std::pow(th, power);
  return "at most " + format_g(ratio, 3) + " m/(theta step)" + (power == 2 ? "^2" : "") + " = " +
         format_g(down_to(most, 4), 4) + " " + unit +
         ", m = mass_per_metre x pitch = " + format_g(m, 4) + " kg, theta " + format_g(s.theta, 4) +
         ", step " + format_g(s.step, 4) + " s";
}

// The hinges' stick spring's bound over a step (kHingeStickWarnRatio, kMaxHingeStickRatio),
// `ratio` m p²/(θh)² [N m/rad]: scale_bound's stiffness m/(θh)² felt at a link's end (k_t/p²),
// times p².
double hinge_stick_bound(const Setup& s, double ratio) {
  const double th = s.theta * s.step;
  return ratio * s.mass_per_metre * s.pitch * s.pitch * s.pitch / (th * th);
}

// Whether the mass, the pitch, the step and theta the bounds over a step follow from are valid.
bool scales_known(const Setup& s) {
  auto valid = [](double x) { return x > 0.0 && std::isfinite(x); };
  return valid(s.mass_per_metre) && s.mass_per_metre <= kMaxMassPerMetre && valid(s.pitch) &&
         valid(s.step) && s.step >= kMinStep && s.theta >= 0.5 && s.theta <= 1.0;
}

// A round link's wire against its jam (docs/models/dynamics.md, "Tension-only links: the jam"):
// the upright link's jam, d, lies at most ε (Model::link_smoothing) below its rest length
// t − pretension/k − d, the model's own bound (Model::jam_length_bound, validated), i.e.
// 2d ≤ t − pretension/k − ε: a link's inner length holds its two neighbours' wires. Out of it the
// wire is named with that bound, and the pretension where it is what refuses the wire. The wire
// and the pitch are valid; an invalid pretension or stiffness (named already) counts as none.
template <class At>
void check_wire_fits_its_jam(const Setup& s, const At& at, std::vector<Issue>& issues) {
  auto shown = [](double x) { return format_g(x, 6); };
  const bool pretension = s.pretension > 0.0 && std::isfinite(s.pretension) && s.stiffness > 0.0 &&
                          std::isfinite(s.stiffness) && s.pretension / s.stiffness < 0.1 * s.pitch;
  auto fits = [&](double rest) {  // as run() builds the model
    Model chain;
    chain.pitch = rest;
    chain.alternation = s.wire;
    return s.wire <= chain.jam_length_bound(1);
  };
  const double eps = Model{}.link_smoothing;
  const double rest = pretension ? s.pitch - s.pretension / s.stiffness : s.pitch;
  if (fits(rest)) return;
  std::string why = std::string("in (0, (pitch") +
                    (pretension ? " - pretension/axial_stiffness" : "") + " - " + shown(eps) +
                    " m)/2] = (0, " + shown(0.5 * (rest - eps)) +
                    "] m (a round link's inner length holds its two neighbours' wires: its jam, "
                    "at d, at most the links' " +
                    shown(eps) + " m smoothing below its rest length" +
                    (pretension ? " pitch - pretension/axial_stiffness - d)" : " pitch - d)");
  if (pretension && fits(s.pitch))
    why += "; " + at("pretension") + " = " + shown(s.pretension) +
           " N shortens the links by pretension/axial_stiffness = " +
           shown(s.pretension / s.stiffness) + " m: without it the bound is " +
           shown(0.5 * (s.pitch - eps)) + " m";
  issues.push_back({at("wire_diameter"), shown(s.wire), why});
}

// The seats' contact bounds (kMaxContactRatio, kMaxContactDampingRatio; the scales known): a
// penalty `stiffness` [N/m] (its value shown with `note`) or a damper `damping` [N s/m] above its
// bound named at its field, with the bound and the keys it follows from; NaN is not checked. The
// [dynamics] table's and each guide's own.
void check_contact(const Setup& s, const std::string& stiffness_at, double stiffness,
                   const std::string& note, const std::string& damping_at, double damping,
                   std::vector<Issue>& issues) {
  auto shown = [](double x) { return format_g(x, 6); };
  double most = NAN;
  std::string why = scale_bound(s, kMaxContactRatio, 2, "N/m", most);
  if (stiffness > most && std::isfinite(stiffness))
    issues.push_back({stiffness_at, shown(stiffness) + " N/m" + note, why + kContactScale});
  why = scale_bound(s, kMaxContactDampingRatio, 1, "N s/m", most);
  if (damping > most && std::isfinite(damping))
    issues.push_back({damping_at, shown(damping) + " N s/m", why + kContactScale});
}

// The bounds of the scales (kMaxLinkRatio ...): every value out of them named, with the bound it
// breaks and the keys the bound follows from. `at` names a [dynamics] key, `step_at` the step's
// source (the table's key or the command line's --step).
template <class At>
void check_scales(const Setup& s, const std::vector<SprocketInput>& wheels, const At& at,
                  const std::string& step_at, std::vector<Issue>& issues) {
  auto shown = [](double x) { return format_g(x, 6); };
  auto valid = [](double x) { return x > 0.0 && std::isfinite(x); };
  if (valid(s.mass_per_metre) && s.mass_per_metre > kMaxMassPerMetre)
    issues.push_back(
        {at("mass_per_metre"), shown(s.mass_per_metre) + " kg/m",
         "in (0, " + shown(kMaxMassPerMetre) + "] kg/m (above every roller and round-link chain)"});
  if (valid(s.step) && s.step < kMinStep)
    issues.push_back({step_at, shown(s.step) + " s", "at least " + shown(kMinStep) + " s"});
  double most = NAN;
  if (scales_known(s)) {
    const std::string link = kLinkScale;
    std::string why = scale_bound(s, kMaxLinkRatio, 2, "N/m", most);
    if (valid(s.stiffness) && s.stiffness > most)
      issues.push_back({at("axial_stiffness"),
                        shown(s.stiffness) + " N/m" +
                            (s.catalogue_stiffness ? " (the catalogue's, " + s.chain + ")" : ""),
                        why + link});
    why = scale_bound(s, kMaxLinkRatio, 1, "N s/m", most);
    if (s.damping > most && std::isfinite(s.damping))
      issues.push_back({at("axial_damping"), shown(s.damping) + " N s/m", why + link});
    check_contact(s, at("contact_stiffness"), s.contact_stiffness,
                  s.hertz_stiffness ? " (the Hertz default)" : "", at("contact_damping"),
                  s.contact_damping, issues);
  }
  // the wheels: the driver's speed, the driven wheels' loads, the inertias
  auto field = [&](std::size_t i, const std::string& key) {
    const auto it = wheels[i].seen.find(key);
    const int l = it == wheels[i].seen.end() ? wheels[i].line : it->second;
    return "dynamics.sprocket[" + std::to_string(i) + "]." + key +
           (l ? " (line " + std::to_string(l) + ")" : "");
  };
  for (std::size_t i = 0; i < wheels.size(); ++i) {
    const SprocketInput& w = wheels[i];
    const bool driver = w.has_role && w.role == "driver";
    const bool driven = w.has_role && w.role == "driven";
    const int teeth = s.layout() ? s.wheels[i].teeth : s.teeth;
    const double r = pitch_radius(s, teeth);
    if (!valid(r) || !valid(s.pitch)) continue;
    const double speed = w.speed.value_or(NAN);
    const double travel = s.pocket ? kMaxPocketTravel : kMaxTravel;
    if (driver && valid(speed) && valid(s.step) && speed * r * s.step > travel * s.pitch) {
      const double fastest = travel * s.pitch / (r * s.step);
      issues.push_back(
          {field(i, "speed"), shown(speed) + " rad/s",
           "at most " + format_g(down_to(fastest, 4), 4) + " rad/s at step " + format_g(s.step, 4) +
               " s, or a step of at most " +
               format_g(down_to(travel * s.pitch / (r * speed), 4), 4) +
               " s at this speed (the chain travels at most " +
               (s.pocket ? "a fortieth of a pitch a step on pocket wheels: speed x R x step <= "
                           "pitch/40"
                         : "a quarter pitch a step: speed x R x step <= pitch/4") +
               ", R the driver's pitch radius " + format_g(r, 4) + " m)"});
    }
    const double load = w.load_torque.value_or(NAN);
    if (driven && valid(s.stiffness) && load > kMaxStretch * s.stiffness * s.pitch * r &&
        std::isfinite(load))
      issues.push_back({field(i, "load_torque"), shown(load) + " N m",
                        "at most 0.1 axial_stiffness x pitch x R = " +
                            format_g(down_to(kMaxStretch * s.stiffness * s.pitch * r, 4), 4) +
                            " N m (its tension load_torque/R stretches a link by under 10 % of "
                            "the pitch; R the wheel's pitch radius " +
                            format_g(r, 4) + " m)"});
    const double inertia = w.inertia.value_or(NAN);
    // the chain one round of the wheel's pitch circle holds, M = q 2 pi R: the seats against the
    // wheel within a step set the failures, not the loop's length
    const double chain = s.mass_per_metre * 2.0 * kPi * r;
    if (s.mass_per_metre <= kMaxMassPerMetre && (driven || (s.layout() && w.role == "idler")) &&
        valid(inertia) && valid(chain)) {
      const double own = chain * r * r;
      if (inertia < kMinInertiaRatio * own || inertia > kMaxInertiaRatio * own)
        issues.push_back(
            {field(i, "inertia"), shown(inertia) + " kg m^2",
             "in [" + format_g(up_to(kMinInertiaRatio * own, 4), 4) + ", " +
                 format_g(down_to(kMaxInertiaRatio * own, 4), 4) + "] kg m^2: " +
                 format_g(kMinInertiaRatio, 3) + " to " + format_g(kMaxInertiaRatio, 3) +
                 " times the chain's own about the wheel, M R^2 = " + format_g(own, 4) +
                 " kg m^2 (M = mass_per_metre x 2 pi R = " + format_g(chain, 4) +
                 " kg, the chain on one round of its pitch circle, R its pitch radius " +
                 format_g(r, 4) + " m)"});
    }
  }
}

bool is_integer(double x) { return std::isfinite(x) && x == std::floor(x); }

constexpr std::size_t kMaxWheels = 20;  // sprockets of the free layout
// the distances the lead-in check may measure (docs/models/dynamics.md, "Lead-ins")
constexpr double kMaxLeadInWork = 5e8;
// the path's samples the check of the rails against the starting path may visit (docs/models/
// dynamics.md, "Guides against the starting path")
constexpr double kMaxRailCutWork = 2e7;
constexpr int kMinWrapTeeth = 3;  // a wheel's wrap, in teeth (docs/models/dynamics.md)

constexpr const char* kTakeupKeys[] = {
    "takeup_force",      "takeup_direction",  "takeup_stiffness",  "takeup_damping",  "takeup_mass",
    "takeup_travel_min", "takeup_travel_max", "takeup_lost_force", "takeup_lost_time"};
// the keys that make a take-up (the others tune it and need it)
constexpr std::size_t kTakeupSlideKeys = 7;

// `side` on a wheel that cannot be on the back of the chain (without centres: the two-wheel line):
// "outside" refused; "inside" (the default) is accepted anywhere.
template <class Field>
void refuse_back(const SprocketInput& w, const Field& field, std::vector<Issue>& issues) {
  if (w.seen.count("side") && w.side == "outside")
    issues.push_back({field("side"), "'outside'",
                      "inside: only a wheel of the free layout (centres on every sprocket) runs "
                      "on the back of the chain"});
}

// A take-up's keys on a driver (or without centres): refused, each.
template <class Field>
void refuse_takeup(const SprocketInput& w, const Field& field, std::vector<Issue>& issues) {
  for (const char* key : kTakeupKeys)
    if (w.seen.count(key))
      issues.push_back({field(key), "(given)",
                        "a take-up only on an idler or a driven wheel of the free layout (role = "
                        "\"idler\" or \"driven\", centres on every sprocket)"});
}

// A take-up on an idler or a driven wheel (docs/models/dynamics.md, "Take-up"): none when no
// takeup_* key is given;
// else takeup_direction and takeup_force required, every value in its range.
template <class Field>
void parse_takeup(const SprocketInput& w, const Field& field, LayoutWheel& lw,
                  std::vector<Issue>& issues) {
  bool any = false;
  for (std::size_t k = 0; k < kTakeupSlideKeys; ++k) any = any || w.seen.count(kTakeupKeys[k]) > 0;
  if (!any) {
    for (const char* key : {"takeup_lost_force", "takeup_lost_time"})
      if (w.seen.count(key))
        issues.push_back({field(key), "(given)",
                          "only on a wheel with a take-up (takeup_force and takeup_direction)"});
    return;
  }
  auto shown = [](double x) { return format_g(x, 6); };
  bool ok = true;
  auto ranged = [&](const char* key, const std::optional<double>& v, double lo, double hi,
                    bool open_lo, const std::string& range, bool required, double& out) {
    if (!v) {
      if (required && !w.seen.count(key)) issues.push_back({field(key), "(missing)", range});
      if (required || w.seen.count(key)) ok = false;  // missing, or given but unreadable
      return;
    }
    if (!std::isfinite(*v) || (open_lo ? !(*v > lo) : !(*v >= lo)) || !(*v <= hi)) {
      issues.push_back({field(key), shown(*v), range});
      ok = false;
      return;
    }
    out = *v;
  };
  ranged("takeup_direction", w.takeup_direction, -2.0 * kPi, 2.0 * kPi, false,
         "the slide's direction, in [-360, 360] deg", true, lw.takeup_direction);
  ranged("takeup_stiffness", w.takeup_stiffness, 0.0, 1e9, false, "in [0, 1e9] N/m", false,
         lw.takeup_stiffness);
  const bool spring = lw.takeup_stiffness > 0.0;
  ranged("takeup_force", w.takeup_force, 0.0, 1e6, !spring,
         spring ? "the spring's preload, in [0, 1e6] N" : "in (0, 1e6] N (a constant force)", true,
         lw.takeup_force);
  ranged("takeup_damping", w.takeup_damping, 0.0, 1e6, false, "in [0, 1e6] N s/m", false,
         lw.takeup_damping);
  ranged("takeup_mass", w.takeup_mass, 0.0, 1000.0, true, "in (0, 1000] kg", false, lw.takeup_mass);
  ranged("takeup_travel_min", w.takeup_travel_min, -10.0, 0.0, false,
         "the end stop behind the start, in [-10, 0] m", false, lw.takeup_travel_min);
  ranged("takeup_travel_max", w.takeup_travel_max, 0.0, 10.0, false,
         "the end stop ahead of the start, in [0, 10] m", false, lw.takeup_travel_max);
  ranged("takeup_lost_force", w.takeup_lost_force, 0.0, 1e6, false,
         "the lost-chain warning's zero, in [0, 1e6] N", false, lw.takeup_lost_force);
  ranged("takeup_lost_time", w.takeup_lost_time, 0.0, 1000.0, false,
         "the lost-chain warning's time, in [0, 1000] s", false, lw.takeup_lost_time);
  lw.takeup = ok;
}

// "slack span sprocket[a] -> sprocket[b]" or "slack spans ..., ..." for the sagging pieces.
std::string span_names(const BeltPath& path, const std::vector<std::size_t>& pieces) {
  std::string out = pieces.size() == 1 ? "slack span " : "slack spans ";
  for (std::size_t i = 0; i < pieces.size(); ++i)
    out += (i ? ", sprocket[" : "sprocket[") + std::to_string(path.pieces[pieces[i]].wheel) +
           "] -> sprocket[" + std::to_string(path.pieces[pieces[i]].next) + "]";
  return out;
}

// The most slack the spans `pieces` can share (in proportion to their lengths), every sag clear
// of everything, the other sags and `guides` included (`sag_spans_limit`).
double slack_limit(const Setup& s, const std::vector<std::size_t>& pieces,
                   const std::vector<double>& tip, const std::vector<Guide>& guides) {
  return sag_spans_limit(s.path, pieces, s.circles, tip, guides, s.roller, s.pitch);
}

// Whether `links` links start with their slack sagging in `pieces`: laid (every link one pitch),
// every wrapped roller within its seat's clearance, every sag clear of everything (`guides`
// too). `laid` and `blocked` (what a sag runs into) are set on the way.
bool slack_starts(const Setup& s, const std::vector<std::size_t>& pieces, int links,
                  const std::vector<double>& tip, const std::vector<Guide>& guides,
                  LoopPlacement& placement, BeltPath& laid, std::string& blocked) {
  blocked.clear();
  placement = place_slack_loop(s.path, s.circles, s.layout_teeth, links, s.pitch, laid, pieces);
  if (placement.s.empty()) return false;
  for (std::size_t w = 0; w < s.circles.size(); ++w)
    if (!(placement.wrapped[w] > 0 && placement.seat_offset[w] <= s.seat_clearance[w]))
      return false;
  for (const std::size_t k : pieces) {
    blocked = sag_obstacle(laid, k, s.circles, tip, guides, s.roller, s.pitch);
    if (!blocked.empty()) return false;
  }
  return true;
}

// The most links that start with their slack sagging in `pieces` (`slack_starts`, the guides
// included), 0 if none. A start at N links sags by more than N p less the path's length, so no
// count beyond the path's length plus `most` (the slack limit) and the band below the half circle
// starts (a pitch for one span; for more, a pitch a span or their kinks' band, sag_spans_band, if
// wider: within it a count laid as arcs may take more than `most`, which is cut there where the
// tangent lay a count may take instead is not clear); the counts below it are
// tried downwards (`longest_count`: not by bisection, the counts that start need not be an
// interval; after kLongestCountScan counts without a start the rest is bisected, bounded work).
LongestCount longest_slack_links(const Setup& s, const std::vector<std::size_t>& pieces,
                                 double most, const std::vector<double>& tip,
                                 const std::vector<Guide>& guides) {
  LoopPlacement placement;
  BeltPath laid;
  std::string blocked;
  auto starts = [&](int n) {
    return n >= 3 && n <= 10000 &&
           slack_starts(s, pieces, n, tip, guides, placement, laid, blocked);
  };
  int lo = static_cast<int>(std::floor(s.path.length / s.pitch));
  if (lo * s.pitch > s.path.length) --lo;  // lo: the last count not beyond the path
  const double band = pieces.size() > 1 ? sag_spans_band(s.path, pieces, s.pitch) / s.pitch : 1.0;
  // (band <= 4 a span, kink_link_extra; clamped to the counts' cap before the cast all the same)
  const int reach = std::max(static_cast<int>(pieces.size()),
                             static_cast<int>(std::ceil(std::min(band, 10000.0))));
  const int hi =
      std::min(10000, static_cast<int>(std::floor((s.path.length + most) / s.pitch)) + reach);
  return longest_count(lo, hi, starts);
}

// The end of a slack refusal: the most links that start with the slack in `pieces`, and, when
// the count given (`given`) is not above it, that no start was found at exactly that count.
std::string links_that_start_text(const Setup& s, const std::vector<std::size_t>& pieces,
                                  double most, const std::vector<Guide>& guides, int given) {
  return links_that_start_phrase(longest_slack_links(s, pieces, most, s.tip, guides), given);
}

// The slack spans `pieces` named in a refusal: "the sagging span", or "spans" for more than one.
std::string sagging_named(const std::vector<std::size_t>& pieces) {
  return pieces.size() == 1 ? "the sagging span" : "the sagging spans";
}

// What a refused slack is measured by, like with like: the sag's extra length e (the arcs' length
// beyond their chords) the spans `pieces` take at most (`most`, with `guides`), against the e the
// count given needs (`laid_slack_extra`: the lay laid, else the solve's), and apart from them N p
// less the path's length, the chain's own extra (less than e, said only when that e was found: a
// link's chord spans a little more than a pitch of a curved path). Ends with "(here ...", for the
// caller to close.
std::string slack_measure_text(const Setup& s, const std::vector<std::size_t>& pieces, double most,
                               bool half_circle, const std::vector<Guide>& guides, int given) {
  auto shown = [](double x) { return format_g(x, 6); };
  auto mm = [](double x) { return format_g(x * 1e3, 6) + " mm"; };
  const double over = given * s.pitch - s.path.length;
  const double need = laid_slack_extra(s.path, s.circles, s.layout_teeth, given, s.pitch, pieces);
  const double spans = span_chords(s.path, pieces);
  const double half = (0.5 * kPi - 1.0) * spans;
  // beyond the half circle the spans hang as catenaries (when they can: a run travelling
  // towards +x, whose outward side is down), up to kCatenaryMostExtra chords of extra
  const bool hangs = !sag_spans(s.path, pieces, half * (1.0 + 1e-9)).pieces.empty();
  // with more than one span the limit may be cut within the band below the half circle (from
  // the spans' kinks, sag_spans_band) by the tangent lay a count there may take; one laid as arcs
  // may still start up to the arcs' own limit, said with it (below the band only the arcs are
  // checked: there the limit is theirs; 1e-5 of the chords: the limit is bisected to 1e-6 of them)
  const bool several = pieces.size() > 1;
  const double band = several ? sag_spans_band(s.path, pieces, s.pitch) : 0.0;
  const double arcs =
      several && most >= half - band - 1e-5 * spans && most < half
          ? sag_spans_arcs_limit(s.path, pieces, s.circles, s.tip, guides, s.roller, s.pitch)
          : 0.0;
  const bool arcs_beyond = arcs > most + 1e-6 * spans;
  const std::string count = std::to_string(given) + " links";
  // beyond the half circle a span laid tangent to its wheels cuts their wraps short: e is the
  // path's extra, the sag's length beyond its chord less those cuts
  const bool one = pieces.size() == 1;
  const std::string e_means =
      hangs ? (one ? "the sag's length beyond its chord, less what it cuts off the wraps"
                   : "the sags' length beyond their chords, less what they cut off the wraps")
            : (one ? "the arc's length beyond its chord" : "the arcs' length beyond their chords");
  return "a chain longer than the path, its " + span_names(s.path, pieces) +
         " sagging by an extra length e (" + e_means + ") of at most about " + mm(most) + " (" +
         shown(most / s.path.length * 100.0) + " % of the path" +
         (arcs_beyond ? "; laid as circular arcs, as a count within " + mm(band) +
                            " below the half circle may be, up to about " + mm(arcs)
                      : "") +
         "), the most " + (one ? "it" : "they") + " can sag by as circular arcs" +
         (half_circle ? " of at most a half circle" : "") +
         (hangs ? " and, beyond a half circle, catenaries of an e of at most " +
                      format_g(kCatenaryMostExtra, 6) + " times " +
                      (one ? "the chord" : "their chords")
                : "") +
         " clear of every other wheel's teeth and the other spans" +
         (guides.empty() ? "" : " and the guides") + " (here " + count +
         (need == INFINITY && hangs
              ? " need an e beyond the longest catenary's " + mm(kCatenaryMostExtra * spans)
          : need == INFINITY    ? " need an e beyond the half circle's " + mm(half)
          : std::isfinite(need) ? " need e = " + mm(need)
                                : " need an e that was not found") +
         "; their N p less the path's length is " + mm(over) + " (" +
         shown(over / s.path.length * 100.0) + " %)" +
         (std::isfinite(need)
              ? ", less than e: a link's chord spans a little more than a pitch of a curved path"
              : "");
}

// A guide named in a message (`sag_obstacle` names s.guides[k] as guide[k]): as the file
// numbers it, a lead-in arc as the lead-in of its rail.
std::string guide_named(const Setup& s, const std::string& blocked) {
  if (blocked.rfind("guide[", 0) != 0 || blocked.back() != ']') return blocked;
  const std::string digits = blocked.substr(6, blocked.size() - 7);
  if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos) return blocked;
  const std::size_t k = std::stoul(digits);
  return k < s.guide_names.size() ? s.guide_names[k] : blocked;
}

// The refusal of a count too long for its slack to sag (`dynamics.links`'s expected text after
// the counts that fit): the most slack the spans take, with `guides` (none before they are read),
// the most links that start so, and what the sag of the count given runs into.
std::string slack_refusal_text(const Setup& s, const Setup::SlackRefusal& r,
                               const std::vector<Guide>& guides) {
  const double most = slack_limit(s, r.pieces, s.tip, guides);
  return r.why + "; or " + slack_measure_text(s, r.pieces, most, true, guides, r.chosen) +
         (r.blocked.empty()
              ? ""
              : "; " + sagging_named(r.pieces) + " would run into " + guide_named(s, r.blocked)) +
         "): " + links_that_start_text(s, r.pieces, most, guides, r.chosen);
}

// The free layout: every [[dynamics.sprocket]] with its centre (docs/models/dynamics.md,
// "Command"). Reports every problem of the wheels at once; the geometry (overlaps, the belt path,
// each wheel's wrap, the links that fit) once every wheel's teeth and centre and the chain's
// dimensions are valid. `links` is NAN when not given (or unreadable: `links_given`).
void parse_layout(const std::vector<SprocketInput>& wheels, double links,
                  const std::string& links_at, bool links_given, Setup& s,
                  std::vector<Issue>& issues) {
  auto shown = [](double x) { return format_g(x, 6); };
  auto mm = [](double x) { return format_g(x * 1e3, 6) + " mm"; };
  if (wheels.size() < 2 || wheels.size() > kMaxWheels)
    issues.push_back({"dynamics.sprocket", std::to_string(wheels.size()) + " sprockets",
                      "2 to " + std::to_string(kMaxWheels) + " [[dynamics.sprocket]] tables"});
  bool geometry = s.pitch > 0.0 && s.roller > 0.0 && s.width > 0.0 && wheels.size() >= 2 &&
                  wheels.size() <= kMaxWheels;
  int drivers = 0;
  s.wheels.assign(wheels.size(), {});
  for (std::size_t i = 0; i < wheels.size(); ++i) {
    const SprocketInput& w = wheels[i];
    LayoutWheel& lw = s.wheels[i];
    const std::string base = "dynamics.sprocket[" + std::to_string(i) + "].";
    auto field = [&](const std::string& key) {
      const auto it = w.seen.find(key);
      const int l = it == w.seen.end() ? w.line : it->second;
      return base + key + (l ? " (line " + std::to_string(l) + ")" : "");
    };
    if (!w.teeth) {
      if (!w.seen.count("teeth"))
        issues.push_back({field("teeth"), "(missing)", "an integer in [8, 150]"});
      geometry = false;
    } else if (!is_integer(*w.teeth) || *w.teeth < 8 || *w.teeth > 150) {
      issues.push_back({field("teeth"), shown(*w.teeth), "an integer in [8, 150]"});
      geometry = false;
    } else {
      lw.teeth = static_cast<int>(*w.teeth);
    }
    for (const char* key : {"centre_x", "centre_y"}) {
      const std::optional<double>& c = std::string(key) == "centre_x" ? w.centre_x : w.centre_y;
      if (!c) {
        if (!w.seen.count(key))
          issues.push_back({field(key), "(missing)",
                            std::string("the centre's ") + (key[7] == 'x' ? "x" : "y") +
                                ", e.g. \"0 mm\" (centres on every sprocket or on none)"});
        geometry = false;
      } else if (!std::isfinite(*c) || std::abs(*c) > 1000.0) {
        issues.push_back({field(key), shown(*c), "in [-1000, 1000] m"});
        geometry = false;
      }
    }
    lw.x = w.centre_x.value_or(NAN);
    lw.y = w.centre_y.value_or(NAN);
    lw.role = w.role;
    if (!w.has_role) {
      issues.push_back({field("role"), "(missing)", "driver, driven or idler"});
      continue;
    }
    if (w.role == "driver") refuse_takeup(w, field, issues);
    // any wheel of the free layout may run on the back of the chain (turning clockwise)
    lw.back = w.side == "outside";
    if (w.role == "driver") {
      ++drivers;
      s.driver = i;
      if (!w.speed) {
        if (!w.seen.count("speed"))
          issues.push_back({field("speed"), "(missing)", "the driver's speed, e.g. \"13 rad/s\""});
      } else if (!(*w.speed > 0.0 && std::isfinite(*w.speed))) {
        issues.push_back({field("speed"), shown(*w.speed),
                          w.side == "outside" ? "> 0 (its magnitude: the wheel turns clockwise)"
                                              : "> 0 (counter-clockwise)"});
      } else {
        lw.speed = *w.speed;
        s.speed = *w.speed;
      }
      for (const char* key : {"inertia", "load_torque"})
        if (w.seen.count(key))
          issues.push_back({field(key), "(given)",
                            "no inertia or load_torque on a driver (its speed is prescribed)"});
      continue;
    }
    if (w.role != "driven" && w.role != "idler") continue;  // reported where it was read
    const bool idler = w.role == "idler";
    if (!w.inertia) {
      if (!w.seen.count("inertia"))
        issues.push_back({field("inertia"), "(missing)", "the moment of inertia J > 0 [kg m^2]"});
    } else if (!(*w.inertia > 0.0 && std::isfinite(*w.inertia))) {
      issues.push_back({field("inertia"), shown(*w.inertia), "> 0 [kg m^2]"});
    } else {
      lw.inertia = *w.inertia;
    }
    if (idler && w.seen.count("load_torque")) {
      issues.push_back({field("load_torque"), w.load_torque ? shown(*w.load_torque) : "(given)",
                        "no load_torque on an idler (a free wheel; role = \"driven\" carries a "
                        "load)"});
    } else if (w.load_torque && !(*w.load_torque >= 0.0 && std::isfinite(*w.load_torque))) {
      issues.push_back({field("load_torque"), shown(*w.load_torque), ">= 0 [N m]"});
    } else if (w.load_torque) {
      lw.load = *w.load_torque;
    }
    if (w.seen.count("speed"))
      issues.push_back({field("speed"), w.speed ? shown(*w.speed) : "(given)",
                        std::string("no speed on a") + (idler ? "n idler" : " driven wheel") +
                            " (it follows from the chain)"});
    parse_takeup(w, field, lw, issues);  // an idler's or a driven wheel's
  }
  if (drivers != 1)
    issues.push_back({"dynamics.sprocket", std::to_string(drivers) + " driver(s)",
                      "exactly one sprocket with role = \"driver\""});
  if (links_given && !std::isnan(links) && (!is_integer(links) || links < 3 || links > 10000)) {
    issues.push_back({links_at, shown(links), "an integer in [3, 10000]"});
    geometry = false;
  }
  if (!geometry) return;

  // the wheels' pitch circles, seat clearances and tip circles (ISO 606, catena::drive)
  const std::size_t n = wheels.size();
  std::vector<double> tip(n), clearance(n);
  s.circles.assign(n, {});
  std::vector<int> teeth(n);
  for (std::size_t i = 0; i < n; ++i) {
    const LayoutWheel& lw = s.wheels[i];
    try {
      const drive::Sprocket iso = drive::sprocket({.pitch = s.pitch,
                                                   .roller_diameter = s.roller,
                                                   .inner_width = s.width,
                                                   .teeth = lw.teeth});
      s.circles[i] = {lw.x, lw.y, 0.5 * iso.pitch_diameter, lw.back};
      tip[i] = 0.5 * iso.tip_diameter_max;
      clearance[i] = iso.min_gap.seating_radius - 0.5 * s.roller;
      teeth[i] = lw.teeth;
    } catch (const InputError& e) {
      for (const Issue& issue : e.issues())
        issues.push_back(
            {"dynamics.sprocket[" + std::to_string(i) + "].teeth (" + issue.field + ")",
             issue.value, issue.expected});
      return;
    }
  }
  auto centre_field = [&](std::size_t i) {
    const auto it = wheels[i].seen.find("centre_x");
    return "dynamics.sprocket[" + std::to_string(i) + "].centre_x" +
           (it == wheels[i].seen.end() ? "" : " (line " + std::to_string(it->second) + ")");
  };
  auto centre_value = [&](std::size_t i) {
    return "(" + mm(s.circles[i].x) + ", " + mm(s.circles[i].y) + ")";
  };
  bool apart = true;
  for (std::size_t j = 1; j < n; ++j) {
    for (std::size_t i = 0; i < j; ++i) {
      const double d = std::hypot(s.circles[j].x - s.circles[i].x, s.circles[j].y - s.circles[i].y);
      if (d >= tip[i] + tip[j]) continue;
      apart = false;
      issues.push_back(
          {centre_field(j), centre_value(j),
           std::string(d == 0.0 ? "a centre other than" : "clear of") + " sprocket[" +
               std::to_string(i) + "]: at least d_a,max/2 + d_a,max/2 = " + mm(tip[i] + tip[j]) +
               " from its centre (the tip circles must not overlap; here " + mm(d) + ")"});
    }
  }
  if (!apart) return;
  s.path = belt_path(s.circles, 0);
  for (const std::size_t i : s.path.unwrapped)
    issues.push_back({centre_field(i), centre_value(i),
                      "on the convex hull of the pitch circles, wrapped once: the chain runs "
                      "round the wheels' hull (this wheel is inside it, only touches it or is met "
                      "twice)"});
  for (const BeltPath::Fault& f : s.path.faults)
    issues.push_back(f.wheel < n
                         ? Issue{centre_field(f.wheel), centre_value(f.wheel), f.why}
                         : Issue{"dynamics.sprocket", std::to_string(n) + " sprockets", f.why});
  if (!s.path.unwrapped.empty() || !s.path.faults.empty()) return;
  // a serpentine path's spans pass wheels other than their two on either side: each must clear
  // their teeth by the roller (the hull's spans have every other wheel on their inside)
  if (std::any_of(s.wheels.begin(), s.wheels.end(), [](const LayoutWheel& w) { return w.back; })) {
    bool clear = true;
    for (const PathPiece& q : s.path.pieces) {
      if (q.arc) continue;
      for (std::size_t w = 0; w < n; ++w) {
        if (w == q.wheel || w == q.next) continue;
        const double ux = q.x1 - q.x0, uy = q.y1 - q.y0, cx = s.circles[w].x - q.x0,
                     cy = s.circles[w].y - q.y0;
        const double t = std::clamp((cx * ux + cy * uy) / (ux * ux + uy * uy), 0.0, 1.0);
        const double gap = std::hypot(cx - t * ux, cy - t * uy);
        const double least = tip[w] + 0.5 * s.roller;
        if (gap >= least) continue;
        clear = false;
        issues.push_back(
            {centre_field(w), centre_value(w),
             "a centre clear of the span sprocket[" + std::to_string(q.wheel) + "] -> sprocket[" +
                 std::to_string(q.next) + "]: at least d_a,max/2 + d1/2 = " + mm(least) +
                 " from its line (the span's rollers must pass the teeth; here " + mm(gap) + ")"});
      }
    }
    if (!clear) return;
  }
  bool wrapped = true;
  for (const PathPiece& q : s.path.pieces) {
    if (!q.arc) continue;
    const double least = kMinWrapTeeth * 2.0 * kPi / teeth[q.wheel];
    if (std::abs(q.to - q.from) >= least) continue;
    wrapped = false;
    issues.push_back({centre_field(q.wheel), centre_value(q.wheel),
                      "a centre where the chain wraps at least " + std::to_string(kMinWrapTeeth) +
                          " teeth of the wheel (" + shown(least * 180.0 / kPi) + " deg; here " +
                          shown(std::abs(q.to - q.from) * 180.0 / kPi) + " deg)"});
  }
  if (!wrapped) return;
  // a take-up pushes its idler against the chain: its slide must point out of the loop, along
  // the wrap's outward bisector (the chain's resultant on the idler points the other way); one
  // pointing into the loop would push the idler off the chain, nothing holding it
  for (const PathPiece& q : s.path.pieces) {
    if (!q.arc || !s.wheels[q.wheel].takeup) continue;
    const double mid = 0.5 * (q.from + q.to), e = s.wheels[q.wheel].takeup_direction;
    const double along = std::cos(e - mid);
    if (along > 0.0) continue;
    const auto it = wheels[q.wheel].seen.find("takeup_direction");
    issues.push_back(
        {"dynamics.sprocket[" + std::to_string(q.wheel) + "].takeup_direction" +
             (it == wheels[q.wheel].seen.end() ? "" : " (line " + std::to_string(it->second) + ")"),
         shown(e * 180.0 / kPi) + " deg",
         "a slide that pushes the idler into the chain: within 90 deg of the wrap's outward "
         "bisector, " +
             shown(std::remainder(mid, 2.0 * kPi) * 180.0 / kPi) + " deg"});
  }

  // the links: a count whose chord closes the loop with every wrapped roller within its seat's
  // clearance of the seat centre (the start then presses no roller into a tooth, as on the line)
  const double f = path_links(s.path, s.pitch);
  if (!(f >= 3.0 && f <= 10000.0)) {
    issues.push_back({links_given ? links_at : "dynamics.links", mm(s.path.length),
                      "a belt path of 3 to 10000 links (here " + shown(f) +
                          " pitches round the pitch circles; move the centres)"});
    return;
  }
  auto fits = [&](int count, LoopPlacement& out) {
    if (count < 3 || count > 10000) return false;
    out = place_loop(s.path, s.circles, teeth, count, s.pitch);
    if (out.s.empty()) return false;
    for (std::size_t w = 0; w < n; ++w)
      if (!(out.wrapped[w] > 0 && out.seat_offset[w] <= clearance[w])) return false;
    return true;
  };
  std::vector<int> fitting;
  LoopPlacement trial;
  for (int count = static_cast<int>(std::floor(f)) - 3; count <= static_cast<int>(std::ceil(f)) + 3;
       ++count)
    if (fits(count, trial)) fitting.push_back(count);
  const int nearest = static_cast<int>(std::lround(f));
  std::string why = "a count the belt path fits: the path round the pitch circles is " +
                    mm(s.path.length) + ", " + format_g(f, 6) + " links of the pitch; ";
  const std::string gap = format_g(clearance[0] * 1e6, 3) + " um";  // 0.005 d1 on every wheel
  if (!fitting.empty()) {
    why += "links that fit (every wrapped roller within its seat's clearance ri - d1/2 = " + gap +
           "): " + std::to_string(fitting.front()) +
           (fitting.size() > 1 ? " to " + std::to_string(fitting.back()) : "");
  } else {
    why += "none fits within the seats' clearance ri - d1/2 = " + gap + ": " +
           (f > nearest ? "shorten" : "lengthen") + " the path by about " +
           mm(std::abs(nearest - f) * s.pitch) + " to " + std::to_string(nearest) +
           " links (e.g. move a wheel's centre)";
  }
  int chosen = 0;
  if (links_given) {
    if (std::isnan(links)) return;  // unreadable: reported
    chosen = static_cast<int>(links);
    if (std::find(fitting.begin(), fitting.end(), chosen) == fitting.end() &&
        !fits(chosen, trial)) {
      // longer than the path: a start with slack, its slack span sagging (every link one pitch)
      // as a circular arc of at most a half circle (beyond: a catenary), clear of every other
      // wheel's teeth and of the other spans (of the guides: checked in parse() once they are read)
      const double over = chosen * s.pitch - s.path.length;
      const std::size_t k = slack_span(s.path);
      const std::vector<std::size_t> pieces = k >= s.path.pieces.size() ? std::vector<std::size_t>{}
                                              : s.slack_all             ? sagging_spans(s.path)
                                                            : std::vector<std::size_t>{k};
      std::string blocked;  // what the sagging span would run into
      s.tip = tip;
      s.layout_teeth = teeth;
      s.seat_clearance = clearance;
      if (over > 0.0 && !pieces.empty()) {
        BeltPath laid;
        LoopPlacement sagging;
        if (slack_starts(s, pieces, chosen, tip, {}, sagging, laid, blocked)) {
          s.placement = sagging;
          s.laid = laid;
          s.links = chosen;
          s.laid_pitch = sagging.spacing;
          s.slack = over;
          s.slack_pieces = pieces;
          return;
        }
      }
      if (over > 0.0 && k >= s.path.pieces.size()) {
        why +=
            "; or a chain longer than the path, which starts with its slack sagging in a span "
            "(here " +
            mm(over) +
            "; but no span sags: every span touches a wheel on the back of the "
            "chain)";
      } else if (over > 0.0) {
        // the limit without the guides for now: parse() names it again once they are read
        const Setup::SlackRefusal refusal{issues.size(), why, chosen, over, pieces, blocked};
        s.slack_refusal = refusal;
        why = slack_refusal_text(s, refusal, {});
      }
      issues.push_back({links_at, std::to_string(chosen), why});
      return;
    }
  } else {
    if (fitting.empty()) {
      issues.push_back({"dynamics.links", "(missing)", why});
      return;
    }
    chosen = *std::min_element(fitting.begin(), fitting.end(),
                               [&](int a, int b) { return std::abs(a - f) < std::abs(b - f); });
  }
  fits(chosen, s.placement);
  s.links = chosen;
  s.laid_pitch = s.placement.spacing;
  if (!links_given) {
    s.links_fitted = true;
    // the chain's length beyond the taut loop's: N links of the pitch against N chords h
    s.fitted_slack = chosen * (s.pitch - s.placement.spacing);
  }
}

// A roller chain's path at the start (docs/models/dynamics.md, "Command"), which its guides'
// lead-ins are checked against: the free layout's (with its sagging spans on a start with slack),
// or that of the two equal wheels on a line as the run lays them (their centres m pitches apart,
// m = (N − z)/2); empty when the geometry is not known, and on pocket wheels (they take no guides:
// parse refuses them, and with no roller none of their rails is placed).
BeltPath starting_path(const Setup& s) {
  if (s.layout()) return s.slack > 0.0 ? s.laid : s.path;
  const int z = s.teeth;
  if (s.pocket || z < 3 || !(s.pitch > 0.0) || !std::isfinite(s.pitch)) return {};
  const int m = (s.links - z) / 2;
  const double radius = pitch_radius(s, z);
  if (m < 1 || !(radius > 0.0) || !std::isfinite(radius)) return {};
  return belt_path({{0.0, 0.0, radius}, {m * s.pitch, 0.0, radius}}, 0);
}

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
  std::string hinge = "frictionless";
  bool hinge_known = true;
  PinLoad pin_load = PinLoad::kMean;  // pin_load = "pin_link": the outer link's tension
  bool pin_load_bad = false;          // a pin_load value refused (not quoted again below)
  bool slack_all = false;             // slack_spans = "all"
  bool slack_spans_bad = false;       // a slack_spans value refused (not quoted again below)
  bool positions = false;
  std::string wheel = "iso606";
  bool line_law = false;                  // contact_law = "line"
  std::optional<bool> discrete_gradient;  // given, else the law's default
  std::optional<bool> pocket_release;     // given (with wheel = "pocket" only)
  // a [dynamics] key that is true or false: its line kept, `out` set, or the value refused
  auto read_flag = [&](const Entry& v, const std::string& key, auto& out) {
    line[key] = v.line;
    if (v.is_boolean)
      out = v.text == "true";
    else
      issues.push_back({where(v), "'" + v.text + "'", "true or false"});
  };
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
      if (key == "lead_in_end") {
        if (!v.is_string || (v.text != "start" && v.text != "end" && v.text != "both"))
          issues.push_back({where(v), "'" + v.text + "'", "start, end or both"});
        else
          g.text[key] = v.text;
        continue;
      }
      if (key == "inside" || key == "load_inertia") {
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
        issues.push_back({where(v), v.text,
                          "a key of a sprocket: teeth, role, speed, inertia, load_torque, "
                          "centre_x, centre_y, takeup_force, takeup_direction, "
                          "takeup_stiffness, takeup_damping, takeup_mass, takeup_travel_min, "
                          "takeup_travel_max, takeup_lost_force, takeup_lost_time, "
                          "seat_friction, side"});
        continue;
      }
      w.seen[key] = v.line;
      if (key == "side") {
        w.side = v.text;
        if (!v.is_string || (v.text != "inside" && v.text != "outside"))
          issues.push_back({where(v), "'" + v.text + "'", "inside or outside"});
        continue;
      }
      if (key == "role") {
        w.role = v.text;
        w.has_role = true;
        if (!v.is_string || (v.text != "driver" && v.text != "driven" && v.text != "idler"))
          issues.push_back({where(v), "'" + v.text + "'", "driver, driven or idler"});
        continue;
      }
      const auto x = read(v, *k->second, issues);
      if (!x) continue;
      if (key == "teeth") w.teeth = *x;
      if (key == "speed") w.speed = *x;
      if (key == "inertia") w.inertia = *x;
      if (key == "load_torque") w.load_torque = *x;
      if (key == "centre_x") w.centre_x = *x;
      if (key == "centre_y") w.centre_y = *x;
      if (key == "takeup_force") w.takeup_force = *x;
      if (key == "takeup_direction") w.takeup_direction = *x;
      if (key == "takeup_stiffness") w.takeup_stiffness = *x;
      if (key == "takeup_damping") w.takeup_damping = *x;
      if (key == "takeup_mass") w.takeup_mass = *x;
      if (key == "takeup_travel_min") w.takeup_travel_min = *x;
      if (key == "takeup_travel_max") w.takeup_travel_max = *x;
      if (key == "takeup_lost_force") w.takeup_lost_force = *x;
      if (key == "takeup_lost_time") w.takeup_lost_time = *x;
      if (key == "seat_friction") w.seat_friction = *x;
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
      read_flag(v, key, work_balance);
      continue;
    }
    if (key == "slack_spans") {
      line[key] = v.line;
      if (v.is_string && (v.text == "lowest" || v.text == "all"))
        slack_all = v.text == "all";
      else {
        issues.push_back({where(v), "'" + v.text + "'", "lowest or all"});
        slack_spans_bad = true;
      }
      continue;
    }
    if (key == "hinge") {
      line[key] = v.line;
      if (v.is_string && (v.text == "frictionless" || v.text == "sliding" || v.text == "rolling")) {
        hinge = v.text;
      } else {
        hinge_known = false;
        issues.push_back({where(v), "'" + v.text + "'", "frictionless, sliding or rolling"});
      }
      continue;
    }
    if (key == "pin_load") {
      line[key] = v.line;
      if (v.is_string && (v.text == "mean" || v.text == "pin_link"))
        pin_load = v.text == "pin_link" ? PinLoad::kPinLink : PinLoad::kMean;
      else {
        issues.push_back({where(v), "'" + v.text + "'", "mean or pin_link"});
        pin_load_bad = true;
      }
      continue;
    }
    if (key == "contact_law") {
      line[key] = v.line;
      if (v.is_string && (v.text == "linear" || v.text == "line"))
        line_law = v.text == "line";
      else
        issues.push_back({where(v), "'" + v.text + "'", "linear or line"});
      continue;
    }
    if (key == "wheel") {
      line[key] = v.line;
      if (v.is_string && (v.text == "iso606" || v.text == "pocket"))
        wheel = v.text;
      else
        issues.push_back({where(v), "'" + v.text + "'", "iso606 or pocket"});
      continue;
    }
    if (key == "discrete_gradient") {
      read_flag(v, key, discrete_gradient);
      continue;
    }
    if (key == "pocket_release") {
      read_flag(v, key, pocket_release);
      continue;
    }
    if (key == "positions") {
      read_flag(v, key, positions);
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
  s.pocket = wheel == "pocket";
  s.line_law = line_law;
  if (line_law && s.pocket)
    issues.push_back({at("contact_law"), "'line'",
                      "linear with wheel = \"pocket\" (the line law is the roller in an ISO "
                      "seat; a round link's joint in its pocket keeps the penalty)"});
  // with wheel = "pocket" the pockets' discrete gradient (default false: the line law is refused)
  s.discrete_gradient = discrete_gradient.value_or(line_law);
  // a round-link chain on pocket wheels: no catalogue, no roller; the keys of the roller chain
  // and the parts not built for a pocket are refused, each by name
  if (s.pocket) {
    const std::string why = " with wheel = \"pocket\"";
    for (const char* key : {"chain", "roller_diameter", "inner_width"})
      if (line.count(key))
        issues.push_back({at(key), key == std::string("chain") ? "'" + chain + "'" : "(given)",
                          std::string("no ") + key + why +
                              " (a round-link chain: pitch = t, wire_diameter = d)"});
    if (line.count("hinge") && hinge != "frictionless")
      issues.push_back({at("hinge"), "'" + hinge + "'",
                        "frictionless" + why + " (the round links' joint friction is not built)"});
    hinge = "frictionless";  // a sliding or rolling one is reported: its keys are not asked for
    if (!guides.empty())
      issues.push_back({"dynamics.guide", std::to_string(guides.size()) + " guide(s)",
                        "no [[dynamics.guide]]" + why +
                            " (where a rail carries a round link's joints is not built)"});
    has_chain = false;  // reported; the catalogue is not consulted
  } else {
    for (const char* key :
         {"wire_diameter", "pocket_clearance", "pocket_mouth", "pocket_release"}) {
      if (!line.count(key)) continue;
      std::string given = value.count(key) ? shown(value[key]) : "(given)";
      if (key == std::string("pocket_release") && pocket_release)
        given = *pocket_release ? "true" : "false";
      issues.push_back({at(key), given, "only with wheel = \"pocket\""});
    }
  }
  // the case file's chain.type (or --chain-type) and the wheel agree: a round-link chain runs on
  // pocket wheels, a roller chain on ISO 606 sprockets; neither is implied
  // (docs/models/dynamics.md)
  if (in.present("chain_type")) {
    const std::string type = in.at("chain_type").text;
    const std::string given = line.count("wheel") ? "'" + wheel + "'" : "(missing)";
    if (type == "round-link" && !s.pocket)
      issues.push_back({at("wheel"), given,
                        "\"pocket\" with chain.type = \"round-link\" (a round-link chain runs "
                        "on pocket wheels: wheel = \"pocket\", pitch = t, wire_diameter = d)"});
    if (type == "roller-iso606" && s.pocket)
      issues.push_back({at("wheel"), given,
                        "\"iso606\" or omitted with chain.type = \"roller-iso606\" (pocket "
                        "wheels carry a round-link chain: chain.type = \"round-link\")"});
  }
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
  s.pitch = chain_value(
      "pitch", row_found ? std::optional(row_found->pitch) : std::nullopt,
      s.pocket ? "the link's inner length t, e.g. \"64 mm\"" : "the pitch p, e.g. \"19.05 mm\"");
  s.mass_per_metre =
      chain_value("mass_per_metre", row_found ? row_found->mass_per_metre : std::nullopt,
                  "the chain's mass per metre, e.g. \"1.25 kg/m\"");
  if (!s.pocket) {
    s.roller = chain_value("roller_diameter", row_found ? row_found->roller_diameter : std::nullopt,
                           "the roller diameter d1, e.g. \"12.07 mm\"");
    s.width = chain_value("inner_width", row_found ? row_found->inner_width : std::nullopt,
                          "the inner width b1, e.g. \"11.68 mm\"");
  }
  for (const char* key : {"pitch", "mass_per_metre", "roller_diameter", "inner_width"}) {
    if (value.count(key) && !(value[key] > 0.0) && (!s.pocket || key[0] == 'p' || key[0] == 'm'))
      issues.push_back({at(key), shown(value[key]), "> 0"});
  }
  if (s.pocket) {
    if (value.count("wire_diameter")) {
      s.wire = value["wire_diameter"];
      // its upper bound, the jam's, is checked below with the pretension
      if (!(s.wire > 0.0 && std::isfinite(s.wire)))
        issues.push_back({at("wire_diameter"), shown(s.wire), "> 0"});
    } else if (!line.count("wire_diameter")) {
      issues.push_back({"dynamics.wire_diameter", "(missing)",
                        "the links' wire diameter d with wheel = \"pocket\", e.g. \"18 mm\""});
    }
    s.clearance = value.count("pocket_clearance")  ? value["pocket_clearance"]
                  : line.count("pocket_clearance") ? NAN
                                                   : 1e-4;
    if (value.count("pocket_clearance") && !(s.clearance > 0.0 && std::isfinite(s.clearance) &&
                                             !(s.pitch > 0.0 && s.clearance > 0.1 * s.pitch)))
      issues.push_back(
          {at("pocket_clearance"), shown(s.clearance),
           "in (0, 0.1 pitch]" +
               (s.pitch > 0.0 ? " = (0, " + shown(0.1 * s.pitch) + "] m" : std::string())});
    // the mouth's ramp within the clearance (the model's range: pocket_issues), and not with the
    // release, which replaces the sharp mouth's cut the ramp smooths
    s.release = pocket_release.value_or(false);
    if (value.count("pocket_mouth")) {
      s.mouth = value["pocket_mouth"];
      const bool clearance_known = s.clearance > 0.0 && std::isfinite(s.clearance);
      if (!(s.mouth >= 0.0 && std::isfinite(s.mouth) &&
            !(clearance_known && s.mouth > s.clearance)))
        issues.push_back(
            {at("pocket_mouth"), shown(s.mouth),
             "in [0, pocket_clearance]" +
                 (clearance_known ? " = [0, " + shown(s.clearance) + "] m" : std::string()) +
                 " (the mouth's ramp; 0 the sharp mouth)"});
      else if (s.mouth > 0.0 && s.release)
        issues.push_back(
            {at("pocket_mouth"), shown(s.mouth),
             "0 while " + at("pocket_release") +
                 " is true: the ramp is the sharp mouth's option, the release replaces "
                 "the mouth's cut; a ramp in [0, pocket_clearance]" +
                 (clearance_known ? " = [0, " + shown(s.clearance) + "] m" : std::string()) +
                 " needs pocket_release = false"});
    }
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
  // a centre on any sprocket makes the free layout, where the links are optional (the count the
  // belt path fits)
  const bool layout =
      !s.pocket && std::any_of(wheels.begin(), wheels.end(), [](const SprocketInput& w) {
        return w.seen.count("centre_x") || w.seen.count("centre_y");
      });
  for (std::size_t i = 0; s.pocket && i < wheels.size(); ++i) {
    for (const char* key : {"centre_x", "centre_y"}) {
      const auto it = wheels[i].seen.find(key);
      if (it != wheels[i].seen.end())
        issues.push_back({"dynamics.sprocket[" + std::to_string(i) + "]." + key + " (line " +
                              std::to_string(it->second) + ")",
                          "(given)",
                          "no centres with wheel = \"pocket\" (two equal pocket wheels on a "
                          "line; the free layout of pocket wheels is not built)"});
    }
  }
  const double links = layout ? optional("links", NAN)
                              : required("links", "the number of links in the loop, an integer");
  // axial_stiffness omitted: the catalogue row's where it has one (the A series, a secondary
  // source: data/catalog/iso606/README.md, CALCULATORS_K) and the row's pitch is the chain's;
  // missing otherwise, naming the rows that have one (a pitch given makes another chain: the
  // row's k = EA/p is for its own pitch)
  const bool pitch_given = value.count("pitch") || line.count("pitch");
  if (!value.count("axial_stiffness") && !line.count("axial_stiffness") && row_found &&
      row_found->axial_stiffness && !pitch_given) {
    s.stiffness = *row_found->axial_stiffness;
    s.catalogue_stiffness = true;
  } else {
    std::string what = "the axial stiffness k of one link, e.g. \"5e7 N/m\"";
    if (!s.pocket && row_found && row_found->axial_stiffness) {  // with pitch given
      what += " (the catalogue's k for " + row_found->name + " is for its own pitch " +
              format_g(row_found->pitch * 1e3) +
              " mm; a pitch given makes another chain, whose k the catalogue does not know)";
    } else if (!s.pocket) {
      std::string rows;
      for (const std::string& name : contact::iso606_names())
        if (contact::iso606_chain(name)->axial_stiffness) rows += (rows.empty() ? "" : ", ") + name;
      what += row_found ? " (the catalogue has no axial stiffness for " + row_found->name +
                              "; it has one for " + rows + ")"
                        : " (or chain = an ISO 606 designation that has it: " + rows + ")";
    }
    s.stiffness = required("axial_stiffness", what.c_str());
  }
  s.contact_stiffness = s.pocket ? required("contact_stiffness",
                                            "the joint-pocket penalty k_c with wheel = \"pocket\" "
                                            "(no Hertz default), e.g. \"1e8 N/m\"")
                                 : optional("contact_stiffness", NAN);  // omitted: Hertz below
  s.hertz_stiffness = !s.pocket && !line.count("contact_stiffness");
  s.contact_damping = required("contact_damping", "the roller-seat damping c_c [N s/m], e.g. 800");
  s.duration = required("duration", "the simulated time, e.g. \"0.5 s\"");
  s.step = required("step", "the time step h, e.g. \"0.1 ms\"");
  s.damping = optional("axial_damping", 0.0);
  s.pretension = optional("pretension", 0.0);
  s.theta = optional("theta", 0.6);
  s.seat_friction = optional("seat_friction", 0.0);
  // the command line's --duration and --step override the table's
  if (in.present("duration")) s.duration = in.number("duration");
  if (in.present("step")) s.step = in.number("step");
  s.interval = optional("output_interval", s.step);
  s.spectrum_start = optional("spectrum_start", NAN);

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
  if (!std::isnan(s.seat_friction) && !(s.seat_friction >= 0.0 && s.seat_friction <= 1.0))
    issues.push_back({at("seat_friction"), shown(s.seat_friction), "in [0, 1]"});
  s.wheel_friction.assign(wheels.size(), NAN);
  for (std::size_t i = 0; i < wheels.size(); ++i) {
    const SprocketInput& w = wheels[i];
    if (!w.seat_friction) continue;
    if (*w.seat_friction >= 0.0 && *w.seat_friction <= 1.0) {
      s.wheel_friction[i] = *w.seat_friction;
      continue;
    }
    const auto it = w.seen.find("seat_friction");
    const int l = it == w.seen.end() ? w.line : it->second;
    issues.push_back({"dynamics.sprocket[" + std::to_string(i) + "].seat_friction" +
                          (l ? " (line " + std::to_string(l) + ")" : ""),
                      shown(*w.seat_friction),
                      "in [0, 1] (this wheel's, overriding dynamics.seat_friction)"});
  }
  if (!std::isnan(s.pretension) && !std::isnan(s.stiffness) && s.stiffness > 0 &&
      !std::isnan(s.pitch) && s.pretension / s.stiffness >= 0.1 * s.pitch)
    issues.push_back({at("pretension"), shown(s.pretension),
                      "below 0.1 k p = " + shown(0.1 * s.stiffness * s.pitch) +
                          " N (a stretch under 10 % of the pitch)"});
  if (s.pocket && s.wire > 0.0 && std::isfinite(s.wire) && s.pitch > 0.0 && std::isfinite(s.pitch))
    check_wire_fits_its_jam(s, at, issues);

  // the sprockets: exactly two, one driver and one driven, equal and even teeth
  if (!layout && wheels.size() != 2) {
    issues.push_back({"dynamics.sprocket", std::to_string(wheels.size()) + " sprockets",
                      "two [[dynamics.sprocket]] tables, one driver and one driven, or centre_x "
                      "and centre_y on every sprocket for any other layout "
                      "(docs/models/dynamics.md)"});
  }
  int drivers = 0, driven = 0;
  std::vector<int> teeth(wheels.size(), 0);
  for (std::size_t i = 0; !layout && i < wheels.size(); ++i) {
    const SprocketInput& w = wheels[i];
    const std::string base = "dynamics.sprocket[" + std::to_string(i) + "].";
    const std::string l = w.line ? " (line " + std::to_string(w.line) + ")" : "";
    // a pocket wheel: z pockets of lying links (2z joints a turn); z even so that half a turn
    // takes a vertex to a vertex
    const int lowest = s.pocket ? 4 : 8;
    const std::string range = "an even integer in [" + std::to_string(lowest) + ", 150]";
    refuse_takeup(
        w, [&](const std::string& key) { return base + key + l; }, issues);
    refuse_back(
        w, [&](const std::string& key) { return base + key + l; }, issues);
    if (!w.teeth) {
      issues.push_back({base + "teeth" + l, "(missing)", range});
    } else if (!is_integer(*w.teeth) || *w.teeth < lowest || *w.teeth > 150 ||
               static_cast<long>(*w.teeth) % 2 != 0) {
      issues.push_back({base + "teeth" + l, shown(*w.teeth), range});
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
    } else if (w.role == "idler") {
      issues.push_back({base + "role" + l, "'idler'",
                        "driver or driven (an idler needs centre_x and centre_y on every "
                        "sprocket)"});
    }
  }
  s.slack_all = slack_all;
  if (!layout && line.count("slack_spans") && !slack_spans_bad)
    issues.push_back({at("slack_spans"), slack_all ? "'all'" : "'lowest'",
                      "no slack_spans without centres (the two-wheel line starts taut)"});
  if (layout) parse_layout(wheels, links, at("links"), line.count("links") > 0, s, issues);
  if (!layout && wheels.size() == 2) {
    if (drivers != 1 || driven != 1)
      issues.push_back(
          {"dynamics.sprocket",
           std::to_string(drivers) + " driver(s), " + std::to_string(driven) + " driven",
           "one driver and one driven"});
    if (teeth[0] && teeth[1] && teeth[0] != teeth[1])
      issues.push_back({"dynamics.sprocket[1].teeth", std::to_string(teeth[1]),
                        "equal to sprocket[0].teeth = " + std::to_string(teeth[0]) +
                            " (unequal wheels need centre_x and centre_y on every sprocket)"});
    s.teeth = teeth[0] && teeth[0] == teeth[1] ? teeth[0] : 0;
  }
  // the pocket wheel's geometry (seed 003 eqs. (6)-(7)) once t, d and z are valid; delta1 below
  // 60 deg for the pocket's mouth to hold the crank (docs/models/dynamics.md, "Pocket wheel")
  if (s.pocket && s.teeth && s.pitch > 0.0 && s.wire > 0.0 && s.wire <= 0.5 * s.pitch) {
    const pocketwheel::WheelGeometry g =
        pocketwheel::wheel_geometry({.pitch = s.pitch, .wire = s.wire, .teeth = s.teeth});
    s.pocket_radius = g.pitch_radius;
    s.pocket_angle = g.delta1;
    if (!(g.delta1 < kPi / 3.0))
      issues.push_back({"dynamics.sprocket[0].teeth", std::to_string(s.teeth),
                        "an even z whose pocket angle delta1 < 60 deg (here " +
                            format_g(g.delta1 * 180.0 / kPi, 4) +
                            " deg: more pockets, or a thinner wire)"});
  }
  if (s.pocket && !std::isnan(links)) {
    // z links round each half-wrapped wheel, 2m on each straight span (2m t between centres)
    if (!is_integer(links) || links < 1 || links > 10000) {
      issues.push_back({at("links"), shown(links), "an integer 2z + 4m in [2z + 4, 10000]"});
    } else {
      s.links = static_cast<int>(links);
      if (s.teeth && (s.links - 2 * s.teeth < 4 || (s.links - 2 * s.teeth) % 4 != 0))
        issues.push_back({at("links"), std::to_string(s.links),
                          "2z + 4m with m >= 1 (2m links, 2m t between the centres): " +
                              std::to_string(2 * s.teeth + 4) + ", " +
                              std::to_string(2 * s.teeth + 8) +
                              ", ... (z = " + std::to_string(s.teeth) + ")"});
    }
  }
  if (!s.pocket && !layout && !std::isnan(links)) {
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
  // (in the free layout: the pretension plus every driven wheel's load over its pitch radius;
  // the seat's form, and so the stiffness, does not depend on the teeth)
  int probe_teeth = s.layout() ? 0 : s.teeth;
  double driven_pull = 0.0;  // [N] Σ T_L/R
  if (s.layout()) {
    probe_teeth = s.wheels.empty() ? 0 : s.wheels.front().teeth;
    for (const LayoutWheel& w : s.wheels) {
      if (w.teeth < 3) probe_teeth = 0;  // already reported
      if (w.role == "driven" && w.teeth >= 3)
        driven_pull += w.load / (0.5 * s.pitch / std::sin(kPi / w.teeth));
    }
  } else if (s.teeth) {
    driven_pull = s.load / (0.5 * s.pitch / std::sin(kPi / s.teeth));
  }
  const bool loads_known = !s.pocket && probe_teeth && s.pitch > 0.0 && s.roller > 0.0 &&
                           s.width > 0.0 && s.pretension >= 0.0 && s.load >= 0.0;
  if (loads_known && (s.hertz_stiffness || s.line_law))
    s.expected_load = driven_pull + s.pretension;
  if (s.hertz_stiffness && loads_known) {
    s.contact_stiffness = s.expected_load > 0.0 ? hertz_seat_stiffness(s.pitch, s.roller, s.width,
                                                                       probe_teeth, s.expected_load)
                                                : NAN;
    // with the line law the penalty is the take-up's stops' only, not the seats' or the rails'
    const std::string what =
        s.line_law ? "the penalty of a take-up's end stops with contact_law = \"line\" (the "
                     "seats and the guides' rails follow the load)"
                   : "the roller-seat penalty k_c";
    if (std::isnan(s.contact_stiffness))
      issues.push_back({"dynamics.contact_stiffness", "(missing)",
                        what +
                            ", e.g. \"2e8 N/m\" (the Hertz default needs an expected seat load "
                            "load_torque/R + pretension > 0 that the line contact's approach law "
                            "covers; here " +
                            shown(s.expected_load) + " N)"});
  }
  // contact_law = "line": the expected seat load within the law's range (the cap, cap_load);
  // a load the Hertz default could not take is reported above
  if (s.line_law && loads_known && s.expected_load > 0.0 &&
      !(s.hertz_stiffness && std::isnan(s.contact_stiffness))) {
    const Sprocket probe =
        iso606_sprocket(s.pitch, s.roller, s.width, probe_teeth, 0.0, 0.0, 1.0, 0.0);
    const double cap =
        s.width * contact::line_approach(seat_line_contact(probe, s.width)).cap_load();
    if (!(s.expected_load < cap))
      issues.push_back({at("contact_law"), "'line'",
                        "a seat load load_torque/R + pretension below the line law's "
                        "cap " +
                            format_g(cap * 1e-3, 3) + " kN (b = 4R_ref/e^1.5; here " +
                            format_g(s.expected_load * 1e-3, 3) +
                            " kN), or contact_law = \"linear\""});
  }
  check_scales(s, wheels, at, in.present("step") ? std::string("step") : at("step"), issues);
  s.gravity = gravity;
  s.work_balance = work_balance;
  // hinge friction: each kind's keys, required or defaulted, the other kinds' keys refused
  s.hinge = hinge;
  {
    const std::vector<std::string> sliding_keys{"hinge_friction", "pin_diameter"};
    const std::vector<std::string> rolling_keys{"rolling_resistance", "plate_radius",
                                                "face_radius"};
    auto refuse = [&](const std::vector<std::string>& keys, const char* kind) {
      for (const std::string& key : keys)
        if (line.count(key))
          issues.push_back(
              {at(key), value.count(key) ? shown(value[key]) : "(given)",
               std::string("only with hinge = \"") + kind + "\" (here hinge = \"" + hinge + "\")"});
    };
    if (hinge_known && hinge != "sliding") refuse(sliding_keys, "sliding");
    if (hinge_known && hinge != "rolling") refuse(rolling_keys, "rolling");
    if (hinge_known && hinge == "frictionless" && line.count("hinge_band"))
      issues.push_back({at("hinge_band"),
                        value.count("hinge_band") ? shown(value["hinge_band"]) : "(given)",
                        "only with hinge = \"sliding\" or \"rolling\""});
    if (hinge_known && hinge == "frictionless" && line.count("pin_load") && !pin_load_bad)
      issues.push_back({at("pin_load"), pin_load == PinLoad::kPinLink ? "'pin_link'" : "'mean'",
                        "only with hinge = \"sliding\" or \"rolling\""});
    s.hinge_law.pin_load = pin_load;
    const double band = optional("hinge_band", 5.0);
    if (!std::isnan(band) && !(band > 0.0 && band <= 100.0))
      issues.push_back({at("hinge_band"), shown(band), "in (0, 100] rad/s"});
    s.hinge_law.rate_band = band;
    double arm = 0.0;
    std::string arm_key;
    if (hinge == "sliding") {
      const double mu = required("hinge_friction", "the pin friction coefficient mu in [0, 1]");
      if (!std::isnan(mu) && !(mu >= 0.0 && mu <= 1.0))
        issues.push_back({at("hinge_friction"), shown(mu), "in [0, 1]"});
      double d2 = NAN;
      if (value.count("pin_diameter")) {
        d2 = value["pin_diameter"];
      } else if (row_found && row_found->pin_diameter) {
        d2 = *row_found->pin_diameter;
      } else if (!line.count("pin_diameter") && !(has_chain && !row_found)) {
        issues.push_back({"dynamics.pin_diameter", "(missing)",
                          "the pin diameter d2, e.g. \"5.72 mm\" (or chain = an ISO 606 "
                          "designation that has it)"});
      }
      if (!std::isnan(d2) && !(d2 > 0.0 && std::isfinite(d2) && !(d2 >= 0.5 * s.pitch)))
        issues.push_back({at("pin_diameter"), shown(d2),
                          "> 0 and < p/2" + (std::isnan(s.pitch) ? std::string()
                                                                 : " = " + shown(0.5 * s.pitch))});
      arm = mu * d2 / 2;  // μ r
      arm_key = "hinge_friction";
    } else if (hinge == "rolling") {
      const double cr = required("rolling_resistance",
                                 "the rolling-resistance coefficient c_r in [0, 0.1], e.g. 0.001");
      if (!std::isnan(cr) && !(cr >= 0.0 && cr <= 0.1))
        issues.push_back({at("rolling_resistance"), shown(cr), "in [0, 0.1]"});
      const double r1 = required("plate_radius", "the plate's working arc R1, e.g. \"15 mm\"");
      if (!std::isnan(r1) && !(r1 > 0.0 && std::isfinite(r1)))
        issues.push_back({at("plate_radius"), shown(r1), "> 0"});
      const double r2 = optional("face_radius", INFINITY);
      if (value.count("face_radius") && !std::isnan(r1) && !(r2 > r1 && std::isfinite(r2)))
        issues.push_back({at("face_radius"), shown(r2),
                          "> plate_radius = " + shown(r1) + " (or omitted: a flat face)"});
      arm = rolling_hinge_arm(cr, r1, r2);  // c_r R*
      arm_key = "rolling_resistance";
    }
    if (std::isfinite(arm) && std::isfinite(s.pitch) && arm >= 0.5 * s.pitch)
      issues.push_back(
          {at(arm_key), shown(arm),
           "a friction arm (mu r or c_r R*) below p/2 = " + shown(0.5 * s.pitch) + " m"});
    s.hinge_law.arm = arm;
    // the stick law (docs/models/dynamics.md, "Hinges: sticking"): with friction on, a spring of
    // finite k_t ≥ 0 below the step's bound (a spring k_t/p² at a link's end, as a contact's),
    // its damper with the spring only
    {
      const char* stiffness_key = "hinge_stick_stiffness";
      const char* damping_key = "hinge_stick_damping";
      if (hinge_known && hinge == "frictionless") {
        for (const char* key : {stiffness_key, damping_key})
          if (line.count(key))
            issues.push_back({at(key), value.count(key) ? shown(value[key]) : "(given)",
                              "only with hinge = \"sliding\" or \"rolling\""});
      }
      const double kt = optional(stiffness_key, 0.0), ct = optional(damping_key, 0.0);
      if (!std::isnan(kt) && !(kt >= 0.0 && std::isfinite(kt))) {
        issues.push_back({at(stiffness_key), shown(kt), "a finite value >= 0 N m/rad"});
      } else if (kt > 0.0 && hinge != "frictionless" && std::isfinite(arm) && !(arm > 0.0)) {
        issues.push_back({at(stiffness_key), shown(kt),
                          "0 with no hinge friction (" + arm_key + " = 0: nothing to stick with)"});
      } else if (kt > 0.0 && scales_known(s)) {
        const double most = hinge_stick_bound(s, kMaxHingeStickRatio);
        if (kt > most)
          issues.push_back({at(stiffness_key), shown(kt) + " N m/rad",
                            "at most " + format_g(kMaxHingeStickRatio, 3) +
                                " m p^2/(theta step)^2 = " + format_g(down_to(most, 4), 4) +
                                " N m/rad (the middle node of a straight pair feels about " +
                                "4 theta k_t/p^2), m = mass_per_metre x pitch = " +
                                format_g(s.mass_per_metre * s.pitch, 4) + " kg, pitch " +
                                format_g(s.pitch, 4) + " m, theta " + format_g(s.theta, 4) +
                                ", step " + format_g(s.step, 4) +
                                " s (a smaller step allows more)"});
      }
      if (!std::isnan(ct) && !(ct >= 0.0 && std::isfinite(ct))) {
        issues.push_back({at(damping_key), shown(ct), "a finite value >= 0 N m s/rad"});
      } else if (ct > 0.0 && !(kt > 0.0) && !(hinge_known && hinge == "frictionless")) {
        issues.push_back({at(damping_key), shown(ct),
                          "0 without hinge_stick_stiffness (the damper sits beside the spring)"});
      } else if (ct > 0.0 && scales_known(s)) {
        // as the seats' damper (kMaxContactDampingRatio), felt as c_t/p^2 at a link's end
        double most = NAN;
        const std::string why = scale_bound(s, kMaxContactDampingRatio, 1, "N s/m", most);
        if (ct > most * s.pitch * s.pitch)
          issues.push_back({at(damping_key), shown(ct) + " N m s/rad",
                            "at most " + format_g(down_to(most * s.pitch * s.pitch, 4), 4) +
                                " N m s/rad: c_t/p^2 (the damper felt at a link's end) " + why +
                                " (a smaller step allows more)"});
      }
      if (hinge != "frictionless" && kt > 0.0 && std::isfinite(kt)) {
        s.hinge_law.stick_stiffness = kt;
        s.hinge_law.stick_damping = ct >= 0.0 && std::isfinite(ct) ? ct : 0.0;
      }
    }
    // the pin link's load round an odd loop: the model's rule (validate_pin_links, the friction
    // on), named at the case's links field; a count the layout chose is said to be its choice
    if (s.links > 0 && std::isfinite(arm)) {
      for (Issue issue : validate_pin_links(s.hinge_law, static_cast<std::size_t>(s.links), true)) {
        issue.field = at("links");
        if (s.links_fitted)
          issue.expected +=
              "; here the count is the layout's choice (links omitted): give an "
              "even links";
        issues.push_back(issue);
      }
    }
  }
  s.positions = positions;
  // the guides: kind and its geometry, all present; then the core's checks (named per field)
  std::vector<Guide> lead_arcs;
  std::vector<std::string> lead_names;
  // each rail's lead-in, checked against the chain's path and the other guides once every guide
  // is read: the rail's index in s.guides, its arcs' first index in lead_arcs and their count
  struct LeadInRail {
    std::string field;
    std::size_t file = 0, rail = 0, first = 0, count = 0;
    bool placed = false;  // the rail was read whole (else its problems are named already)
    LeadIn lead;
  };
  std::vector<LeadInRail> lead_rails;
  // each rail as given, read whole and passing the core's checks: checked against the chain's
  // starting path once every guide is read (its name with the table's line, its index in s.guides)
  std::vector<std::pair<std::string, std::size_t>> given_rails;
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
    // the rail's own penalty and damper, when given: the bounds of the seats' (the table's are
    // checked with the scales)
    if (scales_known(s))
      check_contact(
          s, field("contact_stiffness"),
          g.value.count("contact_stiffness") && !s.line_law ? guide.contact_stiffness : NAN, "",
          field("contact_damping"), g.value.count("contact_damping") ? guide.contact_damping : NAN,
          issues);
    guide.friction = get("friction", 0.0);
    guide.friction_band = get("friction_band", 1e-3);
    guide.load_per_metre = get("load_per_metre", 0.0);
    const auto inertia = g.text.find("load_inertia");
    guide.load_inertia = inertia != g.text.end() && inertia->second == "true";
    guide.load_speed = get("load_speed", 0.0);
    guide.stick_stiffness = get("stick_stiffness", 0.0);
    // the rail's elastic law: with contact_law = "line" the seats' line law on the rail's
    // curvature and material (docs/models/dynamics.md, "Guides: the line law"), which replaces
    // the penalty as on the seats; the material serves that law only
    guide.rail.modulus = get("rail_modulus", guide.rail.modulus);
    guide.rail.poisson = get("rail_poisson", guide.rail.poisson);
    if (s.line_law) {
      if (g.seen.count("contact_stiffness"))
        issues.push_back({field("contact_stiffness"), "(given)",
                          "no contact_stiffness on a guide with contact_law = \"line\": the rail "
                          "follows the line law as the seats do (a softer rail: rail_modulus), or "
                          "contact_law = \"linear\" for the penalty"});
      if (s.width > 0.0 && s.roller > 0.0) use_line_law(guide, s.width);
    }
    guide.discrete_gradient = s.discrete_gradient;  // one key for the seats and the rails
    if (!s.line_law) {
      for (const char* key : {"rail_modulus", "rail_poisson"})
        if (g.seen.count(key))
          issues.push_back({field(key), "(given)",
                            std::string("no ") + key +
                                " with contact_law = \"linear\" (the rail's material serves "
                                "the line law only: contact_law = \"line\")"});
    }
    guide.stick_damping = get("stick_damping", 0.0);
    // the stick spring and its damper sit in the rail's Newton block beside its penalty and
    // damper: their bounds
    if (scales_known(s) && (g.value.count("stick_stiffness") || g.value.count("stick_damping")))
      check_contact(s, field("stick_stiffness"),
                    g.value.count("stick_stiffness") ? guide.stick_stiffness : NAN, "",
                    field("stick_damping"),
                    g.value.count("stick_damping") ? guide.stick_damping : NAN, issues);
    // a load's weight is q_L g: without gravity it would do nothing, silently
    if (guide.load_per_metre > 0.0 && !(s.gravity > 0.0))
      issues.push_back({field("load_per_metre"), shown(guide.load_per_metre) + " kg/m",
                        "0 without gravity (a load's weight is q_L g: set dynamics.gravity)"});
    bool readable = true;
    for (const auto& [key, at_line] : g.seen)
      if (key != "kind" && key != "inside" && key != "load_inertia" &&
          key.rfind("lead_in_", 0) != 0 && !g.value.count(key))
        readable = false;  // the rail's own values (an unreadable lead-in value is the lead-in's)
    // a lead-in (a straight rail's or an arc's): its values' checks, named per field, with the
    // rail's
    std::vector<Guide> lead_ins;
    bool lead_ins_at_start = false;
    double lead_angle = NAN;
    if ((g.seen.count("lead_in_angle") || g.seen.count("lead_in_end")) &&
        !g.seen.count("lead_in_radius")) {
      issues.push_back({field("lead_in_radius"), "(missing)",
                        "a lead-in's radius, > 0 m (lead_in_angle and lead_in_end set a lead-in's "
                        "sweep and ends)"});
    }
    if (g.seen.count("lead_in_radius")) {
      LeadIn lead;
      lead.radius = get("lead_in_radius", NAN);
      lead.angle = get("lead_in_angle", 30.0 * std::numbers::pi / 180.0);
      lead_angle = lead.angle;
      const auto ends = g.text.find("lead_in_end");
      const std::string which = ends == g.text.end() ? "both" : ends->second;
      lead.at_start = which != "end";
      lead.at_end = which != "start";
      // a lead_in_end not read (named when read) leaves the ends unknown: no check on the rail
      // or the path from a guessed count
      const bool ends_known = !g.seen.count("lead_in_end") || ends != g.text.end();
      const std::vector<Issue> lead_issues = validate(lead);
      for (const Issue& issue : lead_issues) {
        if (!g.value.count(issue.field)) continue;  // not read: reported already
        issues.push_back({field(issue.field), issue.value, issue.expected});
      }
      // on an arc rail whose own values are read whole (else they are named, and no lead-in is
      // laid): its radius and the room between its ends (validate(LeadIn, Guide)), named whether
      // or not the user wrote the lead-in's sweep
      bool on_rail = true;  // no problem of the lead-in on this rail
      if (lead_issues.empty() && readable && complete && ends_known)
        for (const Issue& issue : validate(lead, guide)) {
          issues.push_back({field(issue.field), issue.value, issue.expected});
          on_rail = false;
        }
      // the bound (docs/models/dynamics.md, "Lead-ins"): a closed chain of length N p spans no
      // chord longer than N p / 2 (the way back is at least as long), so an arc whose chord
      // 2 R sin(α/2) is longer cannot be a run of this chain: at most R = N p / (4 sin(α/2))
      const double chain_length = s.links * s.pitch;
      bool bounded = false;  // within the bound (then checked against the path below)
      if (lead_issues.empty() && on_rail && chain_length > 0.0 && std::isfinite(chain_length)) {
        const double most = chain_length / (4.0 * std::sin(0.5 * lead.angle));
        bounded = !(lead.radius > most);
        if (!bounded)
          issues.push_back(
              {field("lead_in_radius"), shown(lead.radius) + " m",
               "a lead-in radius 0 < R <= " + format_g(down_to(most, 4), 4) +
                   " m at lead_in_angle " + format_g(lead.angle * 180.0 / std::numbers::pi, 4) +
                   " deg: its arc's chord 2 R sin(angle/2) at most half the chain's length, N p/2 "
                   "= " +
                   format_g(0.5 * chain_length, 4) +
                   " m (a closed loop spans no longer chord: the way back is as long)"});
      }
      if (ends_known) lead_ins = lead_in_arcs(guide, lead);
      lead_ins_at_start = lead.at_start;
      if (!lead_ins.empty() && bounded)
        lead_rails.push_back({field("lead_in_radius"), i, 0, 0, 0, false, lead});
    }
    if (!readable || !(s.roller > 0.0) || std::isnan(guide.contact_stiffness) ||
        std::isnan(guide.contact_damping))
      continue;  // already reported
    // the core's checks of the values given (a missing one is reported above)
    Model probe;
    probe.guides = {guide};
    probe.gravity_y = -s.gravity;  // a load must press the chain onto its rail: n·g < 0
    if (s.pitch > 0.0) probe.pitch = s.pitch;  // a loaded arc's rollers' line: at least a pitch
    const bool weightless = guide.load_per_metre > 0.0 && !(s.gravity > 0.0);
    const std::vector<Issue> found = validate(probe);
    const bool rail_valid = std::none_of(found.begin(), found.end(), [](const Issue& x) {
      return x.field.rfind("guide[0].", 0) == 0;
    });
    const bool bad_material = std::any_of(found.begin(), found.end(), [](const Issue& x) {
      return x.field == "guide[0].rail_modulus" || x.field == "guide[0].rail_poisson";
    });
    for (const Issue& issue : found) {
      if (issue.field.rfind("guide[0].", 0) != 0) continue;
      const std::string key = issue.field.substr(9);
      // a valid load without gravity is reported above: the core's n·g < 0 is that one again
      if (key == "load_per_metre" && weightless && guide.load_per_metre <= kMaxRailLoad) continue;
      // the line law's constants (use_line_law) come from the rail's material and curvature:
      // impossible ones are named on the arc's radius (a rail material in range and a roller
      // give finite constants; a material out of range is named itself, with these its result)
      if (key == "line" || key == "line_width" || key == "line_cap_depth") {
        if (bad_material) continue;
        const bool arc = guide.kind == Guide::Kind::kArc;
        issues.push_back(
            {field(arc ? "radius" : "rail_modulus"),
             arc ? check::format_si(guide.radius, "m") : check::format_si(guide.rail.modulus, "Pa"),
             std::string(arc ? "a radius" : "a rail") + " giving the line law finite constants (" +
                 key + ": " + issue.expected + ")"});
        continue;
      }
      const bool given = key == "end" ? complete : g.seen.count(key) > 0;
      const bool derived = key == "roller_radius" || key == "contact_smoothing";
      if (!given && !derived) continue;
      issues.push_back({field(key == "end" ? "x1" : key), issue.value, issue.expected});
    }
    if (complete) {
      if (!lead_rails.empty() && lead_rails.back().file == i) {
        lead_rails.back().rail = s.guides.size();
        lead_rails.back().first = lead_arcs.size();
        lead_rails.back().count = lead_ins.size();
        lead_rails.back().placed = true;
      }
      if (rail_valid)
        given_rails.emplace_back("dynamics.guide[" + std::to_string(i) + "]" + l, s.guides.size());
      s.guides.push_back(guide);
      s.guide_names.push_back("guide[" + std::to_string(i) + "]");
      s.lead_in_angles.push_back(lead_angle);
      lead_arcs.insert(lead_arcs.end(), lead_ins.begin(), lead_ins.end());
      // lead_in_arcs lays the start's arc before the end's
      for (std::size_t k = 0; k < lead_ins.size(); ++k) {
        const bool start = k == 0 && lead_ins_at_start;
        s.lead_in_rails.emplace_back(s.guides.size() - 1, start);
        lead_names.push_back(lead_in_name(start, "guide[" + std::to_string(i) + "]"));
      }
    }
  }
  // the lead-in arcs after the guides as given (which keep their numbers)
  const std::size_t given_guides = s.guides.size();
  s.given_guides = given_guides;
  s.guides.insert(s.guides.end(), lead_arcs.begin(), lead_arcs.end());
  s.guide_names.insert(s.guide_names.end(), lead_names.begin(), lead_names.end());
  // a lead-in's arcs clear of the chain's path and of the other guides (docs/models/dynamics.md,
  // "Lead-ins"): refused naming what they run into and the largest radius (and sweep) that clears
  const BeltPath chain_path =
      lead_rails.empty() && given_rails.empty() ? BeltPath{} : starting_path(s);
  // a rail carries the chain on its rollers' side: the starting path may lie in its contact no
  // deeper than its surface (docs/models/dynamics.md, "Guides against the starting path"); a
  // path that crosses the rail or lies in it is refused naming where, how deep and what clears it
  // its work bounded (docs/models/dynamics.md, "Guides against the starting path"): the path's
  // samples it visits for each rail, at most kMaxRailCutWork in all
  double rail_work = 0.0;
  for (const auto& given : given_rails)
    rail_work += rail_cut_work(chain_path, s.guides[given.second]);
  if (rail_work > kMaxRailCutWork)
    issues.push_back({"dynamics.guide",
                      std::to_string(given_rails.size()) + " rails, " + format_g(rail_work, 3) +
                          " samples of the chain's starting path to check against them",
                      "at most " + format_g(kMaxRailCutWork, 3) +
                          " (the path's samples, an eighth of a roller radius apart, within each "
                          "rail's box): fewer or shorter rails, or fewer links"});
  for (const auto& [name, index] : given_rails) {
    if (rail_work > kMaxRailCutWork) break;
    const Guide& rail = s.guides[index];
    const RailCut cut = rail_cut(chain_path, rail);
    if (cut.piece.empty()) continue;
    const bool arc = rail.kind == Guide::Kind::kArc;
    const double deg = 180.0 / std::numbers::pi;
    const double r = rail.roller_radius;
    auto mm = [](double v) { return format_g(v * 1e3, 4) + " mm"; };
    std::string where =
        arc ? format_g((rail.start_angle + cut.along) * deg, 4) + " deg round its centre"
            : mm(cut.along) + " along it from (x0, y0)";
    // the rail's part from `from` to `to` along it, as its keys
    auto part = [&](double from, double to) -> std::string {
      if (!std::isfinite(from) || !(to > from)) return {};
      if (arc) {
        // rounded inwards to 0.01 deg: a part of a clear part is clear
        const double a0 = std::ceil((rail.start_angle + from) * deg * 100.0) / 100.0;
        const double a1 = std::floor((rail.start_angle + to) * deg * 100.0) / 100.0;
        if (!(a1 > a0)) return {};
        return "start_angle >= " + format_g(a0, 6) + " deg and end_angle <= " + format_g(a1, 6) +
               " deg";
      }
      // its ends rounded inwards along it to 1 µm, then each coordinate to 1 µm (well within
      // the sample's reach it is trimmed by)
      const double f = std::ceil(from * 1e6) / 1e6, t = std::floor(to * 1e6) / 1e6;
      if (!(t > f)) return {};
      const GuideFrame u = guide_frame(rail);
      auto key_mm = [](double v) {
        char text[64];
        std::snprintf(text, sizeof text, "\"%.3f mm\"", v * 1e3);
        return std::string(text);
      };
      return "x0 = " + key_mm(rail.x0 + f * u.ux) + ", y0 = " + key_mm(rail.y0 + f * u.uy) +
             ", x1 = " + key_mm(rail.x0 + t * u.ux) + ", y1 = " + key_mm(rail.y0 + t * u.uy);
    };
    // the rail moved by `by` away from its rollers' side
    auto move = [&](double by) -> std::string {
      if (!std::isfinite(by)) return {};
      const double shift = up_to(by, 4);
      if (!arc)
        return "the rail moved " + mm(shift) +
               " away from its rollers' side (along its right-hand normal)";
      // an arc's radius moved by it, to the shift's fourth digit (outwards from the chain)
      const double unit = std::pow(10.0, std::floor(std::log10(shift)) - 3.0);
      const double moved = rail.inside ? std::ceil((rail.radius + shift) / unit) * unit
                                       : std::floor((rail.radius - shift) / unit) * unit;
      const int digits =
          static_cast<int>(std::floor(std::log10(moved)) - std::floor(std::log10(unit))) + 1;
      return std::string(rail.inside ? "radius >= " : "radius <= ") +
             format_g(moved, std::max(digits, 1)) + " m (its surface " + mm(shift) +
             " farther from the chain)";
    };
    auto either = [](const std::string& a, const std::string& b) {
      return a.empty() ? b : b.empty() ? a : a + ", or " + b;
    };
    const std::string passes = either(part(cut.clear_from, cut.clear_to), move(cut.shift));
    const std::string touches = either(part(cut.touch_from, cut.touch_to), move(cut.touching));
    std::string remedy =
        passes.empty() ? "no part of it nor a move within a roller's diameter clears it"
                       : passes +
                             " clears this check only (the rollers may still lie up to the roller "
                             "radius into its surface, which need not run, and is refused at an "
                             "entry end without a lead-in: give that end one)";
    if (!touches.empty())
      remedy += "; clear of its contact (its surface at most touching the rollers): " + touches +
                " (with a lead-in at an entry end that has none: a bare entry end near the path "
                "may stop the run)";
    issues.push_back(
        {name, cut.piece + " " + mm(cut.depth - r) + " past its surface at " + where,
         "a rail the chain's starting path lies on, not across or in: in its contact (between "
         "its ends, within a roller's diameter of its surface) no roller's centre past its "
         "surface, at most the roller radius (" +
             mm(r) + ") into it (here " + cut.piece + " at (" + format_g(cut.x * 1e3, 4) + ", " +
             format_g(cut.y * 1e3, 4) + ") mm, " + mm(cut.depth) + " in): " + remedy});
  }
  // a rail's square end may hold the starting path no deeper than its contact's ramp ε: a roller
  // crossing it deeper takes that depth's force at once (docs/models/dynamics.md, "Guides against
  // the starting path: the square ends"). This catches the start's worst case only: a bare entry
  // end near the path may stop a step at a roller's entry at any depth, so the message names the
  // lead-in, the one remedy that runs, not a move
  if (rail_work <= kMaxRailCutWork && !given_rails.empty() && !chain_path.pieces.empty()) {
    std::vector<std::size_t> rails;
    for (const auto& given : given_rails) rails.push_back(given.second);
    for (const SquareEnd& end : square_ends(chain_path, s.guides, rails)) {
      const Guide& rail = s.guides[rails[end.rail]];
      if (!(end.depth > rail.contact_smoothing)) continue;
      auto mm = [](double v) { return format_g(v * 1e3, 4) + " mm"; };
      if (end.under != SIZE_MAX) {
        // its end under an arc smaller than the roller: square past the arc's centre only
        const std::string& name = given_rails[end.rail].first;
        const UnderArc u =
            under_arc_text(s, end, end.depth, "dynamics." + s.guide_names[rails[end.rail]]);
        issues.push_back(
            {name,
             "its end at " + square_end_name(rail, end) + " " + u.what +
                 ", the chain's starting path crossing it " + mm(end.depth) +
                 " into its contact, past that centre",
             "a rail's end the starting path crosses no deeper than the arc joined to it covers, "
             "its centre (" +
                 mm(end.from) +
                 "): deeper, the arc has no contact and the roller is struck by the rail's end's "
                 "force at once" +
                 (rail.line_law
                      ? std::string()
                      : " (here " + format_g(rail.contact_stiffness * end.depth, 3) + " N)") +
                 ", on which a step need not converge however small; " + u.remedy});
        continue;
      }
      issues.push_back(
          {given_rails[end.rail].first,
           "its square end at " + square_end_name(rail, end) + ", where the chain runs onto it, " +
               "the chain's starting path crossing it " + mm(end.depth) + " into its contact",
           "an entry end without a lead-in the starting path crosses at most its contact's ramp (" +
               mm(rail.contact_smoothing) +
               ") deep: a roller crossing it deeper is struck by that depth's force at once" +
               (rail.line_law
                    ? std::string()
                    : " (here " + format_g(rail.contact_stiffness * end.depth, 3) + " N)") +
               ", on which a step need not converge however small; give it a lead-in " +
               square_end_lead_in(end) +
               ", the only remedy: a bare entry end near the chain's path may "
               "stop the run at a roller's entry whatever its depth, clear of the rollers or "
               "pressed in"});
    }
  }
  // the check's work bounded (docs/models/dynamics.md, "Lead-ins"): the distances it may measure,
  // each arc's check repeated by the bisections, at most kMaxLeadInWork
  // a rail's arcs are not checked against the rail itself nor its own arcs
  auto own_guides = [&](const LeadInRail& lr) {
    std::vector<std::size_t> skip{lr.rail};
    for (std::size_t k = 0; k < lr.count; ++k) skip.push_back(given_guides + lr.first + k);
    return skip;
  };
  double lead_work = 0.0;
  for (const LeadInRail& lr : lead_rails) {
    if (chain_path.pieces.empty() || !lr.placed) continue;
    const std::vector<std::size_t> skip = own_guides(lr);
    for (std::size_t k = 0; k < lr.count; ++k)
      lead_work += kLeadInPasses * lead_in_work(chain_path, s.guides[lr.rail],
                                                s.guides[given_guides + lr.first + k], s.guides,
                                                skip, s.roller);
  }
  if (lead_work > kMaxLeadInWork)
    issues.push_back({"dynamics.guide",
                      std::to_string(lead_arcs.size()) + " lead-in arcs, " +
                          format_g(lead_work, 3) + " distances to check",
                      "at most " + format_g(kMaxLeadInWork, 3) +
                          " (the arcs' samples, a quarter roller apart, times the chain's path "
                          "pieces and guides within a roller radius of each arc, times " +
                          format_g(kLeadInPasses, 3) +
                          " for the largest clear radius and sweep): fewer or shorter lead-ins, or "
                          "the guides farther apart"});
  for (const LeadInRail& lr : lead_rails) {
    if (chain_path.pieces.empty() || lead_work > kMaxLeadInWork) break;
    if (!lr.placed) continue;
    const Guide& rail = s.guides[lr.rail];
    const std::vector<std::size_t> skip = own_guides(lr);
    std::string runs_into;
    for (std::size_t k = 0; k < lr.count; ++k) {
      const std::size_t arc = given_guides + lr.first + k;
      const std::string blocked =
          lead_in_obstacle(chain_path, rail, s.guides[arc], s.guides, skip, s.roller);
      if (blocked.empty()) continue;
      runs_into += std::string(runs_into.empty() ? "" : "; ") + s.guide_names[arc] +
                   " would run into " + guide_named(s, blocked);
    }
    if (runs_into.empty()) continue;
    const LeadInLimit most = lead_in_limit(chain_path, rail, lr.lead, s.guides, skip, s.roller);
    constexpr double kLeastAngle = 0.1 * std::numbers::pi / 180.0;  // validate(LeadIn)'s
    const double deg = 180.0 / std::numbers::pi;
    const std::string angle = format_g(lr.lead.angle * deg, 4) + " deg";
    const double radius = down_to(most.radius, 4);
    const double sweep = down_to(most.angle * deg, 4);
    issues.push_back(
        {lr.field, shown(lr.lead.radius) + " m",
         (radius > 0.0
              ? "a lead-in radius 0 < R <= " + format_g(radius, 4) + " m at lead_in_angle " + angle
              : "no lead-in radius at lead_in_angle " + angle) +
             (most.angle >= kLeastAngle
                  ? " (or lead_in_angle <= " + format_g(sweep, 4) + " deg at this radius)"
                  : "") +
             ": its arcs a roller radius (" + format_g(0.5 * s.roller * 1e3, 4) +
             " mm) clear of the chain's path round the wheels and of the other guides (here " +
             runs_into + ")"});
  }
  // a start with slack: the sagging span must clear the guides too (docs/models/dynamics.md,
  // "A start with slack")
  if (s.slack > 0.0 && !s.guides.empty()) {
    std::string blocked;
    for (std::size_t i = 0; blocked.empty() && i < s.slack_pieces.size(); ++i)
      blocked =
          sag_obstacle(s.laid, s.slack_pieces[i], s.circles, s.tip, s.guides, s.roller, s.pitch);
    if (!blocked.empty()) {
      const double most = slack_limit(s, s.slack_pieces, s.tip, s.guides);
      issues.push_back(
          {at("links"), std::to_string(s.links),
           slack_measure_text(s, s.slack_pieces, most, false, s.guides, s.links) + "; " +
               sagging_named(s.slack_pieces) + " would run into " + guide_named(s, blocked) +
               "): " + links_that_start_text(s, s.slack_pieces, most, s.guides, s.links)});
    }
  }
  // a count refused in parse_layout as too long for its slack: its limit named again with the
  // guides, so that the count it names starts (the first text left them out)
  if (s.slack_refusal && !s.guides.empty() && s.slack_refusal->issue < issues.size()) {
    Setup::SlackRefusal& r = *s.slack_refusal;
    if (r.blocked.empty()) {
      // what the count given runs into, the guides included, where its sag can be laid
      LoopPlacement sagging;
      BeltPath laid;
      std::string blocked;
      slack_starts(s, r.pieces, r.chosen, s.tip, s.guides, sagging, laid, blocked);
      r.blocked = blocked;
    }
    issues[r.issue].expected = slack_refusal_text(s, r, s.guides);
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
  // the report's spectrum window (docs/models/dynamics.md, "Report"): at least 16 samples
  if (value.count("spectrum_start") && s.duration > 0.0 && std::isfinite(s.duration) &&
      s.step > 0.0 && std::isfinite(s.step) && s.interval > 0.0 && std::isfinite(s.interval)) {
    const double every = std::max(1.0, std::round(s.interval / s.step));
    // the last sample's time: the run samples every `every` steps of its round(T/h)
    const double last = std::floor(std::round(s.duration / s.step) / every) * every * s.step;
    const double latest = last - 15.0 * every * s.step;
    if (!(s.spectrum_start >= 0.0 && s.spectrum_start <= latest + 1e-9 * s.step))
      issues.push_back({at("spectrum_start"), shown(s.spectrum_start),
                        latest >= 0.0 ? "in [0, " + shown(latest) +
                                            "] s (the window needs at least 16 samples: the "
                                            "duration less 15 output intervals)"
                                      : "none: the run has fewer than 16 samples, no spectrum "
                                        "(lengthen the run or shorten output_interval)"});
  }
  throw_if_any(issues);
  return s;
}

struct Series {
  std::vector<double> angle, speed, torque;
};

// One take-up's series (docs/models/dynamics.md, "Take-up"): the slide's displacement s along
// its direction, its speed, and the take-up's force F₀ − k_t s − c_t ṡ on the slide.
struct TakeupSeries {
  std::size_t wheel = 0;
  std::vector<double> position, speed, force;
  // the end stops (index 0: travel_min, 1: travel_max): the first time the slide was past the
  // end (NAN: never), the steps it spent there and its greatest penetration
  double stop_first[2] = {NAN, NAN};
  double stop_steps[2] = {0.0, 0.0};  // in grid steps, a sub-step its share
  double stop_depth[2] = {0.0, 0.0};
  // the chain lost (its force on the wheel at most lost_force): since when (NAN: in contact),
  // and every stretch longer than the wheel's takeup_lost_time as {start, length}
  double lost_since = NAN;
  std::vector<std::pair<double, double>> lost;
};

// What counts as "zero" for the chain's force on a take-up's wheel when the run says the wheel
// lost the chain: the case's takeup_lost_force, by default at most 1 % of the take-up's preload
// F₀ and at most 1 N (exactly 0, no roller touching, when F₀ = 0); how long it must stay there
// is the case's takeup_lost_time (default 10 ms). docs/models/dynamics.md, "Take-up".
double takeup_lost_force(const LayoutWheel& w) {
  return std::isnan(w.takeup_lost_force) ? std::min(1.0, 0.01 * w.takeup_force)
                                         : w.takeup_lost_force;
}

struct Result {
  Setup setup;
  std::vector<TakeupSeries> takeup;  // one per take-up, in wheel order
  double takeup_damper_work = 0.0;   // the take-ups' dampers (≤ 0; 0 without take-ups)
  std::vector<double> time;
  std::vector<Series> sprocket;           // 2
  std::vector<std::vector<double>> span;  // upper, lower
  // positions = true: every node's x and y at each sample, [sample][node]
  std::vector<std::vector<double>> node_x, node_y;
  int steps = 0;
  double wall_time = 0.0, energy_drift = 0.0, max_penetration = 0.0;
  double friction_work = 0.0;
  double seat_friction_work = 0.0;  // the seats' friction (0 unless seat_friction > 0)
  double hinge_work = 0.0;          // the hinges' friction (≤ 0)
  double load_work = 0.0;           // the rails' loads (0 without load_per_metre)
  // the load's catch and discharge (≤ 0 at rest; 0 without load_inertia) and the arriving
  // material's kinetic energy, part of the catch (≥ 0; 0 without load_speed)
  double load_catch_work = 0.0, load_discharge_work = 0.0, load_arrival_work = 0.0;
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
  const Sprocket wheel = at_slide(model.sprockets[w], s.slide[w]);  // a take-up's where it is
  double sum = 0.0;
  for (std::size_t i = 0; i < s.nodes(); ++i)
    sum += wheel_contact(wheel, s.x[i], s.y[i], s.vx[i] - s.slide_speed[w] * wheel.takeup_dx,
                         s.vy[i] - s.slide_speed[w] * wheel.takeup_dy, s.angle[w], s.speed[w],
                         held_pocket(s, i, w))
               .torque;  // the ISO seat or the pocket
  return sum;
}

// "driver", "driven" or "idler": sprocket w's role.
std::string role_of(const Setup& d, std::size_t w) {
  if (d.layout()) return d.wheels[w].role;
  return w == d.driver ? "driver" : "driven";
}

// Sprocket w's seat friction: its own `seat_friction`, or the [dynamics] one.
double wheel_mu(const Setup& d, std::size_t w) {
  return w < d.wheel_friction.size() && !std::isnan(d.wheel_friction[w]) ? d.wheel_friction[w]
                                                                         : d.seat_friction;
}
// Some sprocket given its own seat_friction.
bool per_wheel_friction(const Setup& d) {
  for (const double mu : d.wheel_friction)
    if (!std::isnan(mu)) return true;
  return false;
}
// Some guide carrying a load (load_per_metre > 0).
bool any_rail_load(const Setup& d) {
  return std::any_of(d.guides.begin(), d.guides.end(),
                     [](const Guide& g) { return g.load_per_metre > 0.0; });
}

// Some wheel with seat friction: the outputs then carry its work.
bool any_seat_friction(const Setup& d) {
  for (std::size_t w = 0; w < d.wheel_friction.size(); ++w)
    if (wheel_mu(d, w) > 0.0) return true;
  return d.seat_friction > 0.0;
}

// contact_law = "line": the ISO seats' line law, the roller d1 in the seat over the inner width b1
void set_seat_law(const Setup& d, Sprocket& s) {
  if (d.line_law) use_line_law(s, d.width);
  s.discrete_gradient = d.discrete_gradient;  // discrete_gradient: over the step
}

// The free layout's wheels at their centres, and the loop's start on the belt path: every node
// at the driver's pitch-line speed, each wheel at that speed over its pitch radius (the driver at
// exactly its own).
std::vector<Sprocket> layout_sprockets(const Setup& d) {
  std::vector<Sprocket> wheels;
  for (const LayoutWheel& w : d.wheels) {
    Sprocket s = iso606_sprocket(d.pitch, d.roller, d.width, w.teeth, w.x, w.y, d.contact_stiffness,
                                 d.contact_damping);
    set_seat_law(d, s);
    s.friction = wheel_mu(d, wheels.size());
    // a wheel on the back of the chain turns clockwise: the driver's speed and the driven
    // wheel's load (against its turning) change sign
    const double sense = w.back ? -1.0 : 1.0;
    if (w.role == "driver") {
      s.driver = true;
      s.speed = sense * w.speed;
    } else {
      s.inertia = w.inertia;
      s.load_torque = sense * w.load;
    }
    if (w.takeup) {
      s.takeup = true;
      s.takeup_dx = std::cos(w.takeup_direction);
      s.takeup_dy = std::sin(w.takeup_direction);
      s.takeup_force = w.takeup_force;
      s.takeup_stiffness = w.takeup_stiffness;
      s.takeup_damping = w.takeup_damping;
      s.takeup_travel_min = w.takeup_travel_min;
      s.takeup_travel_max = w.takeup_travel_max;
      // the idler as a uniform disc of its pitch radius: J = m R²/2
      s.takeup_mass = std::isnan(w.takeup_mass)
                          ? 2.0 * w.inertia / (s.pitch_radius * s.pitch_radius)
                          : w.takeup_mass;
    }
    wheels.push_back(s);
  }
  return wheels;
}

State layout_state(const Setup& d) {
  const double v = d.speed * d.circles[d.driver].radius;
  State s = loop_state(d.slack > 0.0 ? d.laid : d.path, d.circles, d.placement, v);
  s.speed[d.driver] = d.wheels[d.driver].back ? -d.speed : d.speed;
  return s;
}

// The free layout's straight spans in the belt path's order: span k leaves wheel `from` and
// arrives on wheel `to`; the one arriving on the driver is tight, the one leaving it slack.
struct LayoutSpan {
  std::size_t index = 0, from = 0, to = 0;
  std::string name, side;
};
std::vector<LayoutSpan> layout_spans(const Setup& d) {
  std::vector<LayoutSpan> spans;
  for (const PathPiece& q : d.path.pieces) {
    if (q.arc) continue;
    LayoutSpan sp;
    sp.index = spans.size();
    sp.from = q.wheel;
    sp.to = q.next;
    sp.name = "sprocket " + std::to_string(q.wheel) + " -> sprocket " + std::to_string(q.next);
    sp.side = q.next == d.driver ? "tight" : q.wheel == d.driver ? "slack" : "intermediate";
    spans.push_back(sp);
  }
  return spans;
}

// The link whose middle is nearest the middle of each straight span of the belt path.
void nearest_span_links(const Setup& d, const State& s, std::vector<std::size_t>& link) {
  const std::size_t n = s.nodes();
  std::size_t k = 0;
  for (const PathPiece& q : d.path.pieces) {
    if (q.arc) continue;
    const double mx = 0.5 * (q.x0 + q.x1), my = 0.5 * (q.y0 + q.y1);
    double gap = INFINITY;
    for (std::size_t j = 0; j < n; ++j) {
      const std::size_t e = (j + 1) % n;
      const double g = std::hypot(0.5 * (s.x[j] + s.x[e]) - mx, 0.5 * (s.y[j] + s.y[e]) - my);
      if (g < gap) gap = g, link[k] = j;
    }
    ++k;
  }
}

// The round-link loop on two equal pocket wheels of z pockets (docs/models/dynamics.md,
// "Command"): wheel 0 at the origin, wheel 1 at (2m t, 0); the joints on the wheels at the
// vertices of seed 003's polygon (sides t + d and t - d from a vertex at the top or bottom),
// z links round each half-wrapped wheel, 2m on each straight span at y = +-R, every node at the
// wheels' pitch-line speed (counter-clockwise). Node 0 is at wheel 0's top vertex and link 0 is
// a t + d link (Model::alternation).
State pocket_loop(const Setup& d, int m) {
  const int z = d.teeth;
  const double r = d.pocket_radius, d1 = d.pocket_angle, d2 = 2 * kPi / z - d1;
  const double v = d.speed * r, centre = 2 * m * d.pitch;
  State s(static_cast<std::size_t>(2 * z + 4 * m), 2);
  std::size_t i = 0;
  auto put = [&](double x, double y, double vx, double vy) {
    s.x[i] = x;
    s.y[i] = y;
    s.vx[i] = vx;
    s.vy[i] = vy;
    ++i;
  };
  auto wrap = [&](double cx, double start) {  // z + 1 joints, the last one shared with the span
    double polar = start;
    for (int k = 0; k <= z; ++k) {
      put(cx + r * std::cos(polar), r * std::sin(polar), -v * std::sin(polar), v * std::cos(polar));
      polar += k % 2 == 0 ? d1 : d2;
    }
  };
  auto span = [&](double x0, double y, double dir) {  // the 2m - 1 inner joints of a span
    double x = x0;
    for (int j = 1; j < 2 * m; ++j) {
      x += dir * (j % 2 == 1 ? d.pitch + d.wire : d.pitch - d.wire);
      put(x, y, dir * v, 0.0);
    }
  };
  wrap(0.0, kPi / 2);
  span(0.0, -r, 1.0);
  wrap(centre, -kPi / 2);
  span(centre, r, -1.0);
  s.angle = {kPi / 2, -kPi / 2};
  s.speed = {d.speed, d.speed};
  return s;
}

// A pocket wheel's outline for the animation: its joint polygon on the pitch circle (vertex 0
// on +x at angle 0, as the sprockets' seat 0), closed.
std::vector<std::pair<double, double>> pocket_outline(const Setup& d) {
  std::vector<std::pair<double, double>> line;
  const double tau = 2 * kPi / d.teeth;
  for (int k = 0; k <= d.teeth; ++k) {
    for (double a : {k * tau, k * tau + d.pocket_angle}) {
      line.emplace_back(d.pocket_radius * std::cos(a), d.pocket_radius * std::sin(a));
      if (k == d.teeth) break;
    }
  }
  return line;
}

// The series' sampling: every `output_every` steps, output_interval rounded to whole steps (at
// least one) — the run's recording and the summary's sample interval read it.
int output_every(const Setup& d) {
  return std::max(1, static_cast<int>(std::lround(d.interval / d.step)));
}

// A failed step whose roller crosses a rail's square end deeper than the contact's ramp ε
// (docs/models/dynamics.md, "Guides against the starting path: the square ends", the run's
// diagnostic): the guide as the case file counts it, the end, the node, its depth and the remedy,
// the lead-in; none when no roller does (the step failed elsewhere: dynamics.not_converged).
// Every guide is checked: a rail as given has the ends no guide closes, a lead-in arc (laid after
// them) its far end, its near end joining its rail's ("A lead-in's own far end"). The move judged
// runs from x - h v to x + h v: the last converged step's, back-extrapolated, and the failed one's
// predictor, since a roller struck in one step may fail the next; the strike named
// coincides with the failure, which it need not have caused.
std::optional<Diagnostic> bare_end_struck(const Setup& d, const State& s,
                                          const std::string& failed) {
  std::vector<std::size_t> rails;
  for (std::size_t g = 0; g < d.guides.size(); ++g) rails.push_back(g);
  const std::vector<SquareEnd> ends = square_ends(BeltPath{}, d.guides, rails);
  std::vector<double> back_x(s.x.size()), back_y(s.y.size());
  for (std::size_t i = 0; i < back_x.size() && i < s.vx.size(); ++i)
    back_x[i] = s.x[i] - d.step * s.vx[i];
  for (std::size_t i = 0; i < back_y.size() && i < s.vy.size(); ++i)
    back_y[i] = s.y[i] - d.step * s.vy[i];
  const std::optional<EndStrike> hit =
      square_end_strike(ends, d.guides, rails, back_x, back_y, s.vx, s.vy, 2.0 * d.step);
  if (!hit) return std::nullopt;
  const SquareEnd& end = ends[hit->end];
  const std::size_t index = rails[end.rail];
  const Guide& rail = d.guides[index];
  auto mm = [](double v) { return format_g(v * 1e3, 4) + " mm"; };
  const std::string struck = failed + ": node " + std::to_string(hit->node) + " crosses ";
  const std::string ramp = "deeper than its contact's ramp (" + mm(rail.contact_smoothing) +
                           "): the roller is struck by that depth's force at once, on which a "
                           "step need not converge however small; the run stopped there. ";
  if (index >= d.given_guides) {
    // a lead-in arc's own far end (its near end joins its rail's): the lead-in named by its rail,
    // the exact clearance (R + r)(1 − cos α) >= G of a roller parallel to the end's tangent at
    // the depth G it has there (layout.hpp, lead_in_rail_depth), G rounded up and the radius at
    // its sweep, the sweep at its radius, from it rounded up; none when a parallel roller cannot
    // cross that face (lead_in_parallel_strike: a quarter turn, whose remedy is its own values)
    const auto [of, at_start] = d.lead_in_rails[index - d.given_guides];  // laid with the arcs
    const double R = rail.radius, r = rail.roller_radius, a = rail.end_angle - rail.start_angle;
    const double G = up_to(lead_in_rail_depth(R, a, r, hit->depth) * 1e3, 4);  // [mm]
    const double radius = up_to(lead_in_clear_radius(a, r * 1e3, G), 3);       // [mm]
    // (G < R + r before rounding, within the face's reach: the sweep at most a quarter turn)
    const double below = std::min(G, (R + r) * 1e3);
    const double angle = up_to(lead_in_clear_angle(R * 1e3, r * 1e3, below) * 180.0 / kPi, 3);
    const std::string end_word = at_start ? "start" : "end";
    const std::string remedy =
        lead_in_parallel_strike(R, a, r, hit->depth)
            ? ": at its lead_in_angle " + format_g(a * 180.0 / kPi, 4) +
                  " deg, lead_in_radius >= " + format_g(radius, 3) +
                  " mm, or at its lead_in_radius " + mm(R) +
                  ", lead_in_angle >= " + format_g(angle, 3) + " deg (lead_in_end = \"" + end_word +
                  "\" or \"both\"; "
            : ", which this lead-in meets already: its far end's face runs parallel to the rail, "
              "so the roller crossed it moving across the rail, and no value is named; move the "
              "rail clear of the chain there (";
    return Diagnostic{
        Diagnostic::Severity::kError,
        "dynamics.bare_rail_end",
        struck + "the far end of " + lead_in_name(at_start, "dynamics." + d.guide_names[of]) +
            " (lead_in_radius " + mm(R) + ", lead_in_angle " + format_g(a * 180.0 / kPi, 4) +
            " deg) at (" + format_g(end.x * 1e3, 4) + ", " + format_g(end.y * 1e3, 4) +
            ") mm, where it runs onto the lead-in, " + mm(hit->depth) + " into its contact, " +
            ramp + "There the roller lies " + format_g(G, 4) +
            " mm below the line of the rail's rollers at its end, along its tangent; " +
            lead_in_clears_text(r, G) + remedy +
            "a bare entry end near the chain's path may stop the run at any depth)",
        hit->depth,
        rail.contact_smoothing,
        "m"};
  }
  if (end.under != SIZE_MAX) {
    // its end under an arc smaller than the roller, struck past the arc's centre: the limit that
    // centre's depth
    const UnderArc u = under_arc_text(d, end, hit->depth, "dynamics." + d.guide_names[index]);
    return Diagnostic{
        Diagnostic::Severity::kError,
        "dynamics.bare_rail_end",
        struck + "the end of dynamics." + d.guide_names[index] + " at " +
            square_end_name(rail, end) + " " + u.what + ", " + mm(hit->depth) +
            " into its contact, past that centre, where the arc has no contact: the roller is "
            "struck by the rail's end's force at once, on which a step need not converge however "
            "small; the run stopped there: " +
            u.remedy +
            ", or move the rail clear of the chain there (a bare entry end near the chain's path "
            "may stop the run at any depth)",
        hit->depth,
        end.from,
        "m"};
  }
  // a lead-in's arc ends R (1 − cos α) below the end's tangent: deeper than the roller at the
  // rail's own lead_in_angle, else the default 30° (docs/cli.md, lead_in_angle), from
  // R = g / (1 − cos α), named rounded up: a sufficient radius, not the least (a roller on a path
  // parallel to the tangent clears the arc's end from g <= (R + r)(1 − cos α))
  const double own = index < d.lead_in_angles.size() ? d.lead_in_angles[index] : NAN;
  const double angle = std::isnan(own) ? kPi / 6.0 : own;
  const double radius = up_to(hit->depth / (1.0 - std::cos(angle)) * 1e3, 3);
  const std::string at_angle =
      std::isnan(own) ? std::string("at the default 30 deg")
                      : "at its lead_in_angle " + format_g(own * 180.0 / kPi, 4) + " deg";
  return Diagnostic{
      Diagnostic::Severity::kError,
      "dynamics.bare_rail_end",
      struck + "the square end of dynamics." + d.guide_names[index] + " at " +
          square_end_name(rail, end) + ", where it runs onto the rail, " + mm(hit->depth) +
          " into its contact, " + ramp + "Give that end a lead-in " + square_end_lead_in(end) +
          " whose arc ends deeper below the surface than the roller, "
          "lead_in_radius (1 - cos lead_in_angle) > " +
          format_g(up_to(hit->depth * 1e3, 4), 4) + " mm (" + at_angle +
          ", lead_in_radius >= " + format_g(radius, 3) + " mm" +
          "), or move the rail clear of the chain there (a bare entry end near the chain's path "
          "may stop the run at any depth: the lead-in is the remedy that runs)",
      hit->depth,
      rail.contact_smoothing,
      "m"};
}

// A failed step retaken as two half-steps, recursively (docs/models/dynamics.md, "Integrator: a
// failed step retaken as half-steps"): the sub-steps h/2 … h/2^kRetakeLevels, each with its own
// integrator (made at the first retake; its predictor history and kept factors are its own, and
// the run's integrator meets the retaken step's end at a time its history is not of: it starts
// the next step from constant velocity with fresh factors). At most 2 + 4 + … + 2^L = 30 step
// solves for one failed step at L = 4.
constexpr int kRetakeLevels = 4;
// After a retake the run goes on at the smallest sub-step it took, whole grid steps of them, and
// doubles it back after this many grid steps at it without a failed solve (docs/models/
// dynamics.md, "Integrator: the sub-step size kept").
constexpr int kGrowSteps = 4;

// What the sub-steps of a retaken step add up to, as the run's loop adds up a step's: the
// driver's and the loads' work −T Δψ per sub-step, each wheel's applied torque weighted by its
// share of h (the sample's mean torque stays the mean over time), the deepest penetration, and
// the deepest level reached; each converged sub-step's end for the take-ups' watch (kept only
// once the whole grid step is: a retake that fails leaves no event), and the step solves tried
// and failed.
struct Retake {
  double work = 0.0;
  std::vector<double> torque;  // Σ (h_i / h) τ_i per wheel
  double max_penetration = 0.0;
  int level = 0;
  // per converged sub-step (a run with a take-up only): its end time, its size, the take-ups'
  // slides and the chain's force on each wheel there
  struct Sub {
    double time, size;
    std::vector<double> slide, wheel_force;
  };
  bool watch = false;
  std::vector<Sub> subs;  // the first n_subs hold this grid step's (the rest: kept storage)
  std::size_t n_subs = 0;
  int solves = 0, failed = 0;
  std::optional<StepReport> failure;  // the first failed solve's (its Newton text)
  std::vector<double> angle0;         // scratch: a sub-step's start angles
  // Empties it for a new grid step, keeping every array's storage (no allocation per step).
  void reset() {
    work = 0.0;
    std::fill(torque.begin(), torque.end(), 0.0);
    max_penetration = 0.0;
    level = 0;
    n_subs = 0;
    solves = failed = 0;
    failure.reset();
  }
};

// A step's (or a retaken step's sub-step's) accounting, the same for both: the driver's (θ-point)
// torque and the loads' work −T Δψ over it (angle0 the wheels' angles at its start), returned,
// and each wheel's applied torque times `weight`, its share of the grid step (1 for a whole step:
// exact), added to `applied`.
double step_accounting(const Model& model, std::size_t driver, const std::vector<double>& angle0,
                       const State& s, const std::vector<double>& torque, double weight,
                       std::vector<double>& applied) {
  const std::size_t nw = model.sprockets.size();
  double dw = -torque[driver] * (s.angle[driver] - angle0[driver]);
  for (std::size_t w = 0; w < nw; ++w)
    if (w != driver) dw -= model.sprockets[w].load_torque * (s.angle[w] - angle0[w]);
  for (std::size_t w = 0; w < nw; ++w) applied[w] += weight * torque[w];
  return dw;
}

// Two steps of h / 2^level from s, or below `from` each half split at once (a grid step taken
// whole as sub-steps of h / 2^from); each failed one split again down to `floor`: true when all
// converged, s then at their end; false leaves s partly advanced (the caller restores it).
bool retake_halves(const Model& model, const Setup& d, std::vector<std::optional<Integrator>>& sub,
                   State& s, int level, int from, int floor, Retake& acc) {
  const double scale = 1.0 / static_cast<double>(1 << level);  // a power of 2: exact
  std::vector<double>& angle0 = acc.angle0;  // free again once a solve is accounted or failed
  for (int half = 0; half < 2; ++half) {
    if (level < from) {
      if (!retake_halves(model, d, sub, s, level + 1, from, floor, acc)) return false;
      continue;
    }
    std::optional<Integrator>& integ = sub[static_cast<std::size_t>(level - 1)];
    if (!integ) integ.emplace(model, IntegratorOptions{.step = d.step * scale, .theta = d.theta});
    std::copy(s.angle.begin(), s.angle.end(), angle0.begin());
    const StepReport rep = integ->step(model, s);
    ++acc.solves;
    if (!rep.converged) {  // the state is as it was: split this half again, down to the floor
      ++acc.failed;
      if (!acc.failure) acc.failure = rep;
      if (level == floor || !retake_halves(model, d, sub, s, level + 1, level + 1, floor, acc))
        return false;
      continue;
    }
    acc.level = std::max(acc.level, level);
    acc.max_penetration = std::max(acc.max_penetration, rep.max_penetration);
    acc.work +=
        step_accounting(model, d.driver, angle0, s, integ->applied_torque(), scale, acc.torque);
    if (acc.watch) {
      if (acc.n_subs == acc.subs.size()) acc.subs.emplace_back();
      Retake::Sub& e = acc.subs[acc.n_subs++];
      e.time = s.time;
      e.size = d.step * scale;
      e.slide.assign(s.slide.begin(), s.slide.end());
      const std::vector<double>& force = integ->applied_wheel_force();
      e.wheel_force.assign(force.begin(), force.end());
    }
  }
  return true;
}

// The guard on energy from nothing: the numerical term's bound in multiples of the energy the run
// has received (docs/models/dynamics.md, "Integrator: the guard on energy from nothing").
constexpr double kEnergyGainBound = 2.0;
static_assert(kEnergyGainBound > 1.0,
              "the guard's message words its bound as \"more than N times\"");
// The guard's stride: at most one energy evaluation every this many steps (and the last step).
constexpr int kGuardSteps = 10;

Result run(const analysis::Inputs& in) {
  Result out;
  out.setup = parse(in);
  const Setup& d = out.setup;
  const int z = d.teeth;
  // the span's pitches (ISO) or its pairs of links (pocket: 2m links between the wheels)
  const int m = d.pocket ? (d.links - 2 * z) / 4 : (d.links - z) / 2;
  const auto n = static_cast<std::size_t>(d.links);
  const double rest = (d.layout() ? d.laid_pitch : d.pitch) - d.pretension / d.stiffness;
  Model model =
      uniform_chain(n, true, rest, d.mass_per_metre * d.pitch, d.stiffness, d.damping, false);
  if (d.pocket) {
    model.alternation = d.wire;
    // round links: the next link slides inside the ring, no compression (docs/models/dynamics.md,
    // "Tension-only links")
    model.links_carry_compression = false;
    // discrete_gradient: the links' force over the step too ("Tension-only links: the discrete
    // gradient")
    model.links_discrete_gradient = d.discrete_gradient;
    // the jam ("Tension-only links: the jam"): a t − d link pushes once its neighbours' wires meet
    // inside it, its joints d apart. A t + d link is one link's own two tips, rigid: bilateral
    // ("The flat links")
    model.link_jam_length = {0.0, d.wire};
    model.link_bilateral = {true, false};
  }
  const double centre = (d.pocket ? 2 * m : m) * d.pitch;
  std::vector<Sprocket> wheels;
  if (d.layout()) wheels = layout_sprockets(d);
  for (std::size_t w = 0; !d.layout() && w < 2; ++w) {
    Sprocket s = d.pocket ? pocket_wheel(d.pitch, d.wire, z, w == 0 ? 0.0 : centre, 0.0,
                                         d.clearance, d.contact_stiffness, d.contact_damping)
                          : iso606_sprocket(d.pitch, d.roller, d.width, z, w == 0 ? 0.0 : centre,
                                            0.0, d.contact_stiffness, d.contact_damping);
    set_seat_law(d, s);  // on a pocket wheel its discrete gradient alone (line law refused)
    if (d.pocket) {      // the mouth's ramp and the release (0 and false: the sharp mouth)
      s.pocket_mouth = d.mouth;
      s.pocket_release = d.release;
    }
    s.friction = wheel_mu(d, w);
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
  model.hinge = d.hinge_law;
  State s = d.layout() ? layout_state(d)
            : d.pocket ? pocket_loop(d, m)
                       : two_sprocket_loop(z, m, d.pitch, wheels[0].pitch_radius, d.speed);
  const std::size_t nw = wheels.size();
  // A roller that starts inside a rail is moved out along the rail's normal to touch it (the
  // spans start straight at the wheels' pitch-line height; a guide may sit a little higher): the
  // guides in order, each node against the guides near it, O(N + G + pairs)
  const std::vector<LiftConflict> conflicts = lift_onto_guides(
      model.guides, std::span<double>(s.x.data(), n), std::span<double>(s.y.data(), n));
  // two rails whose lifts disagree (docs/models/dynamics.md, "Guides against the starting path:
  // several rails"): one issue per pair and kind, its nodes counted, the deepest named
  std::vector<Issue> lift_issues;
  {
    std::map<std::tuple<std::size_t, std::size_t, bool>, std::pair<std::size_t, LiftConflict>>
        pairs;
    for (const LiftConflict& c : conflicts) {
      auto [it, fresh] = pairs.try_emplace({c.first, c.second, c.through}, 0, c);
      ++it->second.first;
      if (!fresh && c.depth > it->second.second.depth) it->second.second = c;
    }
    auto name = [&](std::size_t g) {
      return g < d.guide_names.size() ? d.guide_names[g] : "guide[" + std::to_string(g) + "]";
    };
    for (const auto& [key, found] : pairs) {
      const LiftConflict& c = found.second;
      const std::string nodes =
          std::to_string(found.first) + (found.first == 1 ? " node" : " nodes");
      lift_issues.push_back(
          {"dynamics.guide",
           nodes + " of the chain's start lifted onto " + name(c.first) +
               (c.through          ? " then lay behind the surface of "
                : found.first == 1 ? " is left inside the contact of "
                                   : " are left inside the contact of ") +
               name(c.second) + " (node " + std::to_string(c.node) + " " +
               format_g(c.depth * 1e3, 4) + " mm deep in it, of the roller radius " +
               format_g(model.guides[c.second].roller_radius * 1e3, 4) + " mm)",
           std::string("guides whose lifts of the starting path agree: a roller one lifts ") +
               (c.through ? "may not land past another's surface (it would be pulled through it)"
                          : "may not be left in another's contact") +
               "; move one of the two so that the rollers the first lifts lie on the free side of "
               "the second or clear of it"});
    }
  }
  // reported with the start's other problems, one list
  for (Issue& issue : validate(model, s)) lift_issues.push_back(std::move(issue));
  throw_if_any(lift_issues);

  Integrator integ(model, {.step = d.step, .theta = d.theta});
  std::vector<double> tension(model.links());
  out.sprocket.resize(nw);
  out.span.resize(d.layout() ? nw : 2);  // the layout: one per straight span of the belt path
  std::vector<std::size_t> span_link(out.span.size(), 0);
  for (std::size_t w = 0; w < nw; ++w)
    if (wheels[w].takeup) out.takeup.push_back({.wheel = w});
  std::vector<double> applied(nw, 0.0);  // Σ of the steps' applied torques since the last sample
  int since = 0;                         // steps since the last sample
  auto sample = [&] {
    out.time.push_back(s.time);
    for (std::size_t w = 0; w < nw; ++w) {
      out.sprocket[w].angle.push_back(s.angle[w]);
      out.sprocket[w].speed.push_back(s.speed[w]);
      // the mean of the torque the steps since the last sample applied (at each step's θ point):
      // over every sample the wheel's torque balance holds; at t = 0, before any step, the
      // contact torque of the initial state
      out.sprocket[w].torque.push_back(since == 0 ? chain_torque(model, s, w) : applied[w] / since);
      applied[w] = 0.0;
    }
    for (TakeupSeries& tu : out.takeup) {
      const Sprocket& wh = model.sprockets[tu.wheel];
      const double sl = s.slide[tu.wheel], v = s.slide_speed[tu.wheel];
      tu.position.push_back(sl);
      tu.speed.push_back(v);
      tu.force.push_back(wh.takeup_force - wh.takeup_stiffness * sl - wh.takeup_damping * v);
    }
    link_tensions(model, s, tension);
    if (d.positions) {
      out.node_x.push_back(s.x);
      out.node_y.push_back(s.y);
    }
    if (d.layout()) {
      nearest_span_links(d, s, span_link);
      for (std::size_t k = 0; k < span_link.size(); ++k)
        out.span[k].push_back(tension[span_link[k]]);
      since = 0;
      return;
    }
    const auto [top, bottom] = span_middle_links(s, centre);
    out.span[0].push_back(tension[top]);
    out.span[1].push_back(tension[bottom]);
    since = 0;
  };
  const int steps = static_cast<int>(std::lround(d.duration / d.step));
  const int every = output_every(d);
  // the report's animation: frames every `frame_every` steps (docs/models/dynamics.md, Report)
  std::size_t drawn = 0;
  for (std::size_t w = 0; w < nw; ++w) {
    out.outlines.push_back({"sprocket " + std::to_string(w) + " (" + role_of(d, w) + ")",
                            wheels[w].centre_x, wheels[w].centre_y,
                            d.pocket
                                ? pocket_outline(d)
                                : sprocket_outline(d.pitch, d.roller, d.width, wheels[w].teeth)});
    drawn += out.outlines.back().outline.size() + 1;
  }
  for (const Guide& g : d.guides) {
    out.guides.push_back(guide_polyline(g));
    drawn += out.guides.back().size();
  }
  const std::size_t frames = frame_count(n, drawn);
  const int frame_every = std::max(
      1, static_cast<int>(std::ceil(static_cast<double>(steps) / static_cast<double>(frames - 1))));
  // each frame with the wheels' centres where they are (a take-up's moves with its slide)
  auto snapshot = [&] {
    LoopFrame f{s.time, s.x, s.y, s.angle, {}, {}};
    for (std::size_t w = 0; w < nw; ++w) {
      const Sprocket at = at_slide(wheels[w], s.slide[w]);
      f.centre_x.push_back(at.centre_x);
      f.centre_y.push_back(at.centre_y);
    }
    out.frames.push_back(std::move(f));
  };
  // after each step, and each sub-step of a step taken as sub-steps (its end `time`, its `size`):
  // a take-up's slide past an end of its travel, and its wheel without the chain's force
  // (docs/models/dynamics.md, "Take-up"), for the diagnostics after the run; the time at the end
  // counted in grid steps (a sub-step its share: a power of 2, exact)
  auto watch_takeups = [&](double time, double size, const std::vector<double>& slide,
                           const std::vector<double>& wheel_force) {
    for (TakeupSeries& tu : out.takeup) {
      const Sprocket& wh = wheels[tu.wheel];
      const double sl = slide[tu.wheel];
      const double past[2] = {wh.takeup_travel_min - sl, sl - wh.takeup_travel_max};
      for (int e = 0; e < 2; ++e) {
        if (!(past[e] > 0.0)) continue;
        if (std::isnan(tu.stop_first[e])) tu.stop_first[e] = time;
        tu.stop_steps[e] += size / d.step;
        tu.stop_depth[e] = std::max(tu.stop_depth[e], past[e]);
      }
      const LayoutWheel& lw = d.wheels[tu.wheel];
      const bool lost = wheel_force[tu.wheel] <= takeup_lost_force(lw);
      if (lost && std::isnan(tu.lost_since)) tu.lost_since = time - size;
      if (!lost && !std::isnan(tu.lost_since)) {
        if (time - size - tu.lost_since > lw.takeup_lost_time)
          tu.lost.push_back({tu.lost_since, time - size - tu.lost_since});
        tu.lost_since = NAN;
      }
    }
  };
  snapshot();
  const Energy start_energy = energy(model, s);
  const double e0 = start_energy.total();
  // the work the driver puts in and the load takes out over each step: the driver's applied
  // (θ-point) torque and the load torque times the angles the wheels turned
  double work = 0.0;
  // the work balance at the state s of total energy `total` (summary.work_balance): the drift,
  // E − E₀ less the work of the driver, the loads and the model's friction and rails' loads, and
  // returned, the numerical term, the drift less the dampers' work (the end's summary and the
  // guard below: one computation)
  const bool rail_load = any_rail_load(d), load_inertia = any_load_inertia(d.guides);
  auto balance = [&](double total, double& drift) {
    drift = total - e0 - work - s.friction_work - s.seat_friction_work - s.hinge_work;
    if (rail_load) drift -= s.load_work;  // a run without a load computes as before
    if (load_inertia) drift -= s.load_catch_work + s.load_discharge_work;
    double numerical = drift - s.damper_work - s.contact_damping_work;
    if (!out.takeup.empty()) numerical -= s.takeup_damper_work;  // likewise without a take-up
    return numerical;
  };
  // The guard on energy from nothing (docs/models/dynamics.md, "Integrator: the guard on energy
  // from nothing"): the run has received the start's kinetic and elastic energy K₀ + V₀, the
  // potential energy released since (gravity's, the loads', the take-ups' force's) and the work
  // put in by the driver and the loads; a numerical term N (the balance's energy from nothing)
  // larger than twice all of it is a loop holding more energy from nothing than it was ever
  // given, a run that diverges (the θ point's one-step gains at a coarse step's start measured up
  // to 1.8 times it): an error that stops it there, with the output up to there as after a failed
  // step. Checked at the samples below (the energy is not otherwise computed during a run).
  const double start_motion = start_energy.kinetic + start_energy.elastic;
  EnergyScratch energy_scratch;  // the hints kept from sample to sample (their grids built once)
  // checked at the samples at least kGuardSteps steps apart (the smallest multiple of the output
  // interval that is) and at the last step: an energy evaluation costs a third of a step on the
  // 12B example, whose every step is a sample; a diverging run's gain grows by orders within such
  // a stretch (the θ = ½ take-up: 2 to 3.9 times what it received in 3 steps)
  const int guard_every = every * ((kGuardSteps + every - 1) / every);
  const auto guard_due = [&](int step) { return step % guard_every == 0 || step == steps; };
  auto gained = [&](int step) {
    const Energy now = energy(model, s, energy_scratch);
    double drift = 0.0;
    const double numerical = balance(now.total(), drift);
    const double released = std::max(0.0, start_energy.potential - now.potential);
    const double received = start_motion + released + std::max(0.0, work);
    if (!(numerical > kEnergyGainBound * received)) return false;
    // a roller crossing a rail's square end gains its contact's energy as it strikes: the strike
    // is named as before, at the step that fails on it (dynamics.bare_rail_end)
    if (bare_end_struck(d, s, std::string())) return false;
    std::string advice = "a smaller step";
    if (d.theta < 1.0) advice = "theta nearer 1, " + advice;
    if (!d.discrete_gradient) advice += ", or discrete_gradient = true";
    out.diagnostics.push_back(
        {Diagnostic::Severity::kError, "dynamics.energy_gain",
         "step " + std::to_string(step) + " (t = " + format_g(s.time, 6) +
             " s): the work balance's numerical term, energy gained from nothing, is " +
             format_g(numerical, 4) + " J, more than " + times_text(kEnergyGainBound) + " the " +
             format_g(received, 4) +
             " J the run has received (the start's kinetic and elastic energy " +
             format_g(start_motion, 4) + " J, the potential energy released " +
             format_g(released, 4) + " J, the work put in by the driver and the loads " +
             format_g(work, 4) + " J); the loop's kinetic energy is " + format_g(now.kinetic, 4) +
             " J: the run diverges and stopped there (try " + advice + ")",
         numerical, kEnergyGainBound * received, "J"});
    return true;
  };
  sample();
  const auto started = std::chrono::steady_clock::now();
  ProgressLoop loop(static_cast<std::size_t>(steps), "steps");
  std::vector<double> angle0(nw);
  // the failed steps retaken as half-steps: their integrators, how many, the first's step and the
  // deepest level; the size the run goes on at after a retake (docs/models/dynamics.md,
  // "Integrator: the sub-step size kept"), h / 2^level, doubled back after kGrowSteps grid steps
  // at it without a failure; the grid steps taken whole at a kept size, and every sub-step solve
  // and every failed solve (full steps' too)
  std::vector<std::optional<Integrator>> sub(kRetakeLevels);
  int retaken = 0, first_retaken = 0, deepest = 0;
  int level = 0, clean = 0, kept_steps = 0;
  long sub_solves = 0, failed_solves = 0;
  // scratch kept across grid steps (no allocation per step): the retake's accounting and the
  // state at the start of a grid step taken as sub-steps
  Retake acc{.torque = std::vector<double>(nw, 0.0),
             .watch = !out.takeup.empty(),
             .angle0 = std::vector<double>(nw)};
  State start;
  // grid step k + 1 done, whole or as sub-steps, its accounting added: its sample, the guard's
  // check, its frame and the progress; true when the guard stops the run there
  auto grid_step_end = [&](int k) {
    ++since;
    if ((k + 1) % every == 0) sample();
    if (guard_due(k + 1) && gained(k + 1)) return true;
    if ((k + 1) % frame_every == 0) snapshot();
    loop.step(static_cast<std::size_t>(k + 1));
    return false;
  };
  // grid step k + 1 ended by its sub-steps (from `start`): the grid's time, as a step would have
  // set it, and its accounting theirs; true when the guard stops the run there
  auto substeps_end = [&](int k) {
    // the grid's time, and the last sub-step's integrator's history moved to it (their summed
    // time may differ from it by rounding: the next grid step's sub-steps keep their predictor)
    const double summed = s.time;
    s.time = start.time + d.step;
    for (std::optional<Integrator>& integ_k : sub)
      if (integ_k) integ_k->retime(summed, s.time);
    out.max_penetration = std::max(out.max_penetration, acc.max_penetration);
    ++out.steps;
    work += acc.work;
    for (std::size_t w = 0; w < nw; ++w) applied[w] += acc.torque[w];
    for (std::size_t i = 0; i < acc.n_subs; ++i) {  // the last one named at the grid's time
      const Retake::Sub& e = acc.subs[i];
      watch_takeups(i + 1 == acc.n_subs ? s.time : e.time, e.size, e.slide, e.wheel_force);
    }
    return grid_step_end(k);
  };
  for (int k = 0; k < steps; ++k) {
    // the step at the run's size: whole at h, or (after a retake) as 2^level sub-steps
    StepReport rep;
    if (level == 0) {
      std::copy(s.angle.begin(), s.angle.end(), angle0.begin());
      rep = integ.step(model, s);
      if (!rep.converged) ++failed_solves;
    } else {
      start = s;
      acc.reset();
      const bool whole = retake_halves(model, d, sub, s, 1, level, level, acc);
      sub_solves += acc.solves;
      failed_solves += acc.failed;
      if (whole) {
        ++kept_steps;
        if (++clean == kGrowSteps) {
          --level;
          clean = 0;
        }
        if (substeps_end(k)) break;
        continue;
      }
      s = start;
      rep = *acc.failure;
    }
    if (!rep.converged) {
      const int n_sub = 1 << level;
      const std::string failed =
          "step " + std::to_string(k + 1) + " (t = " + format_g(s.time + d.step, 6) +
          " s) did not converge" +
          (level > 0 ? " as sub-steps of step/" + std::to_string(n_sub) : std::string()) + " in " +
          newton_iterations_text(rep, integ.options().max_iterations);
      // a roller struck at a rail's square end over the full step stops the run as it did
      // before the retakes, judged first so that the strike is named: the half-steps can
      // converge through it, and their result would be a roller struck through a square end
      if (std::optional<Diagnostic> struck = bare_end_struck(d, s, failed)) {
        out.max_penetration = std::max(out.max_penetration, rep.max_penetration);
        out.diagnostics.push_back(std::move(*struck));
        break;
      }
      // the step again from its start as two halves of the size that failed (each split again
      // down to h/16): the grid's step k + 1 when they converge, the run going on at the
      // smallest size they took
      start = s;
      acc.reset();
      const bool whole = level < kRetakeLevels &&
                         retake_halves(model, d, sub, s, 1, level + 1, kRetakeLevels, acc);
      sub_solves += acc.solves;
      failed_solves += acc.failed;
      if (whole) {
        if (retaken++ == 0) first_retaken = k + 1;
        deepest = std::max(deepest, acc.level);
        level = acc.level;
        clean = 0;
        if (substeps_end(k)) break;
        continue;
      }
      s = start;  // the run's end as if the step had failed without the retake
      out.max_penetration = std::max(out.max_penetration, rep.max_penetration);
      out.diagnostics.push_back(
          {Diagnostic::Severity::kError, "dynamics.not_converged",
           failed +
               (level < kRetakeLevels
                    ? "; also retaken from its start as half-steps down to step/" +
                          std::to_string(1 << kRetakeLevels) + ", which failed too"
                    : std::string(", the retakes' floor")) +
               "; the run stopped there (try a smaller step or theta nearer 1" +
               (d.hinge_law.stick_stiffness > 0.0 ? ", or a smaller hinge_stick_stiffness" : "") +
               ")",
           s.time + d.step, d.duration});
      break;
    }
    out.max_penetration = std::max(out.max_penetration, rep.max_penetration);
    ++out.steps;
    work += step_accounting(model, d.driver, angle0, s, integ.applied_torque(), 1.0, applied);
    watch_takeups(s.time, d.step, s.slide, integ.applied_wheel_force());
    if (grid_step_end(k)) break;
  }
  out.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  // the guides' friction work is 0 without guides: the drift is then the same number as before
  out.friction_work = s.friction_work;
  out.seat_friction_work = s.seat_friction_work;
  // likewise the hinges' friction work (0 without hinge friction)
  out.hinge_work = s.hinge_work;
  // the rails' loads' work, the load's catch and discharge, the dampers' and the take-ups'
  // dampers' (each 0 in a run without it); the numerical term: what the model's dissipation does
  // not account for, the θ-method and the contacts' penalty (evaluated at the θ point, not by a
  // discrete gradient)
  out.numerical_work = balance(energy(model, s).total(), out.energy_drift);
  if (rail_load) out.load_work = s.load_work;
  if (load_inertia) {
    out.load_catch_work = s.load_catch_work;
    out.load_arrival_work = s.load_arrival_work;
    out.load_discharge_work = s.load_discharge_work;
  }
  out.input_work = work;
  out.damper_work = s.damper_work;
  out.contact_damping_work = s.contact_damping_work;
  if (!out.takeup.empty()) out.takeup_damper_work = s.takeup_damper_work;
  for (TakeupSeries& tu : out.takeup) {
    const Sprocket& wh = wheels[tu.wheel];
    const LayoutWheel& lw = d.wheels[tu.wheel];
    const std::string who = "the take-up of sprocket " + std::to_string(tu.wheel);
    if (!std::isnan(tu.lost_since) && s.time - tu.lost_since > lw.takeup_lost_time)
      tu.lost.push_back({tu.lost_since, s.time - tu.lost_since});  // lost to the run's end
    for (int e = 0; e < 2; ++e) {
      if (std::isnan(tu.stop_first[e])) continue;
      const double bound = e == 0 ? wh.takeup_travel_min : wh.takeup_travel_max;
      out.diagnostics.push_back(
          {Diagnostic::Severity::kWarning, "dynamics.takeup_at_travel_end",
           who + " reached its " + (e == 0 ? "takeup_travel_min" : "takeup_travel_max") + " = " +
               format_g(bound, 6) + " m at t = " + format_g(tu.stop_first[e], 6) +
               " s: the end stop held the slide for " + format_g(tu.stop_steps[e] * d.step, 6) +
               " s in all, at most " + format_g(tu.stop_depth[e], 3) +
               " m past the end; the take-up's force does not set the chain's tension there",
           tu.stop_first[e], bound});
    }
    if (!tu.lost.empty()) {
      double longest = 0.0;
      for (const auto& [from, length] : tu.lost) longest = std::max(longest, length);
      out.diagnostics.push_back(
          {Diagnostic::Severity::kWarning, "dynamics.takeup_lost_chain",
           "sprocket " + std::to_string(tu.wheel) +
               " lost the chain on its take-up (the chain's force on the wheel at most " +
               format_g(takeup_lost_force(lw), 4) + " N) for longer than " +
               format_g(lw.takeup_lost_time * 1e3, 3) + " ms " + std::to_string(tu.lost.size()) +
               " time(s), first at t = " + format_g(tu.lost.front().first, 6) + " s for " +
               format_g(tu.lost.front().second, 4) + " s, the longest " + format_g(longest, 4) +
               " s",
           tu.lost.front().first, lw.takeup_lost_time});
    }
  }
  // the steps retaken as half-steps (docs/models/dynamics.md, "Integrator: a failed step retaken
  // as half-steps"): only when there were some
  if (retaken > 0) {
    const double smallest = d.step / static_cast<double>(1 << deepest);
    out.diagnostics.push_back(
        {Diagnostic::Severity::kWarning, "dynamics.steps_retaken",
         std::to_string(retaken) + (retaken == 1 ? " step" : " steps") +
             " of step = " + format_g(d.step * 1e3, 4) +
             " ms did not converge and were retaken from their start as two half-steps (each "
             "split again where it failed, down to step/" +
             std::to_string(1 << kRetakeLevels) + "): the smallest sub-step " +
             format_g(smallest * 1e3, 4) + " ms, the first at step " +
             std::to_string(first_retaken) + " (t = " + format_g(first_retaken * d.step, 6) +
             " s). A retaken step is one step of the output; a smaller step may not need them. "
             "After a retake the run went on at the smallest sub-step it took, doubled back "
             "after " +
             std::to_string(kGrowSteps) +
             " steps at it without a failure (a step failing at its kept size retaken from "
             "there, not tried at the sizes above it, and counted among the steps retaken): " +
             std::to_string(kept_steps) + " more " + (kept_steps == 1 ? "step" : "steps") +
             " taken as sub-steps, " + std::to_string(sub_solves) + " sub-step solves and " +
             std::to_string(failed_solves) + " failed solves in all",
         smallest, d.step, "s"});
  }
  // the mouth's ramp past its fold-free step (docs/models/dynamics.md, "Pocket wheel: the ramp's
  // fold"): a joint's step residual M/(hθ) (u − x₀ − h v₀) − h F(x₀ + θ(u − x₀)) has the
  // Jacobian M/(hθ) + hθ K, K = −∂F/∂q ≥ −κ over the ramp, which stays positive definite while
  // κ < M/(θh)², i.e. h < √(M/κ)/θ, M the joint's mass
  if (d.pocket && d.mouth > 0.0 && !model.sprockets.empty()) {
    const double kappa = pocket_ramp_softening(model.sprockets.front());
    const double mass = d.mass_per_metre * d.pitch;
    const double bound = std::sqrt(mass / kappa) / d.theta;
    const double held = mass / (d.theta * d.theta * d.step * d.step);
    if (d.step > bound)
      out.diagnostics.push_back(
          {Diagnostic::Severity::kWarning, "dynamics.pocket_mouth_fold",
           "pocket_mouth = " + format_g(d.mouth * 1e3, 4) +
               " mm with step = " + format_g(d.step * 1e3, 4) +
               " ms: the mouth's ramp softens a joint by up to " + format_g(kappa, 3) +
               " N/m (the largest eigenvalue of the contact's -d2E/dq2 over the ramp), more than "
               "the joint's m/(theta step)^2 = " +
               format_g(held, 3) +
               " N/m: a step there may have no solution near its start (a fold) and is then "
               "retaken as half-steps (dynamics.steps_retaken); below " +
               format_g(down_to(bound * 1e3, 3), 3) +
               " ms a single joint's step cannot fold on the ramp (docs/models/dynamics.md, "
               "\"Pocket wheel: the ramp's fold\")",
           d.step, bound, "s"});
  }
  // a joint deeper than the pocket's clearance c: the validations' joints stay within 0.56 c
  // (docs/models/dynamics.md, "Pocket wheel: the body between the pockets")
  if (d.pocket && out.max_penetration > d.clearance)
    out.diagnostics.push_back(
        {Diagnostic::Severity::kWarning, "dynamics.pocket_penetration_deep",
         "a joint went " + format_g(out.max_penetration * 1e3, 4) +
             " mm deep into its pocket's wall or the wheel's body, more than the pocket "
             "clearance " +
             format_g(d.clearance * 1e3, 4) +
             " mm: the penalty contact_stiffness is too soft for the load, or the chain came "
             "back onto the wheel off its pockets (a free end or slack side whipping); the "
             "forces and tensions around it are not to be trusted",
         out.max_penetration, d.clearance, "m"});
  // the stick spring past the ratio at which some measured runs stopped (kHingeStickWarnRatio)
  if (d.hinge_law.stick_stiffness > 0.0) {
    const double warn = hinge_stick_bound(d, kHingeStickWarnRatio);
    if (d.hinge_law.stick_stiffness > warn)
      out.diagnostics.push_back(
          {Diagnostic::Severity::kWarning, "dynamics.hinge_stick_stiffness_high",
           "hinge_stick_stiffness = " + format_g(d.hinge_law.stick_stiffness, 4) + " N m/rad > " +
               format_g(down_to(warn, 4), 4) + " N m/rad = " + format_g(kHingeStickWarnRatio, 3) +
               " m p^2/(theta step)^2: runs stopped converging from about twice that "
               "(docs/models/dynamics.md, \"Hinges: sticking\"); a smaller step allows more",
           d.hinge_law.stick_stiffness, warn, "N m/rad"});
  }
  // with the discrete gradient (the seats' elastic force and damper over the step) drives close
  // their work balance at θ = ½, damped or not (docs, "Sprockets: the discrete gradient"); on
  // pocket wheels the energy jumps are taken over the step too, the mouth's spread over a band
  // (the tension-only links are in: "Tension-only links: the discrete gradient"), and the pocket
  // example at ½ undamped stops ("Pocket wheel: the discrete gradient")
  if (d.theta < 0.6) {
    const char* why =
        !d.discrete_gradient ? " < 0.6: drives with roller-seat contact diverged below 0.6 "
                               "(docs/models/dynamics.md)"
        : d.pocket
            ? " < 0.6: with discrete_gradient = true the pockets' and the links' force is "
              "taken over the step, and the pockets' energy jumps too (the mouth's spread over "
              "a band), but pocket-wheel runs below 0.6 may stop (docs/models/dynamics.md, "
              "\"Pocket wheel: the discrete gradient\")"
            : " < 0.6: with discrete_gradient = true drives with roller-seat contact, damped or "
              "not, keep their work balance down to 0.5 (the seats' elastic force and damper "
              "taken over the step; docs/models/dynamics.md, \"Sprockets: the discrete "
              "gradient\")";
    out.diagnostics.push_back({Diagnostic::Severity::kWarning, "dynamics.theta_below_0_6",
                               "theta = " + format_g(d.theta, 4) + why, d.theta, 0.6});
  }
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
  if (w.first >= w.last) {  // no sample in the window (only t = 0, or samples too sparse)
    w.first = time.size() - 1;
    w.last = time.size();
    w.start = w.end = t_end;
    w.periods = 0;  // the last sample alone, not a mean over periods
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

// The scatter of a series' means over the window's tooth periods (docs/models/dynamics.md,
// "Pocket wheel: the example's means"): the mean over each whole period (t_s + iT, t_s + (i+1)T]
// of the window, and from them (period_means.hpp) their sample standard deviation s and the
// standard error of the window's mean, s/√n inflated for the means' serial correlation (AR(1),
// its lag-1 autocorrelation estimated from 10 periods on; fewer are taken as independent). A
// loop whose response repeats with the tooth period has s ≈ 0; the pocket-wheel example's is
// chaotic (a change of 1e-9 in the pretension grows to the full scatter within 0.4 s) and its
// period means scatter by 10-22 % of the mean. Fewer than 2 whole periods give no estimate
// (periods = 0), nor does a window one of whose periods holds fewer than 2 samples (`sparse`: a
// coarse output_interval; a period's "mean" would be one instantaneous sample).
struct PeriodSpread {
  bool sparse = false;
  PeriodMeansError e;
};

PeriodSpread period_spread(const std::vector<double>& time, const std::vector<double>& x,
                           const Window& w, double period) {
  PeriodSpread p;
  if (w.periods < 2) return p;
  std::vector<double> sum(static_cast<std::size_t>(w.periods), 0.0);
  std::vector<int> count(sum.size(), 0);
  for (std::size_t k = w.first; k < w.last; ++k) {
    // sample k in (t_s + iT, t_s + (i+1)T]: i = ⌈(t − t_s)/T⌉ − 1, clamped to the window
    const double i = std::ceil((time[k] - w.start) / period) - 1.0;
    const std::size_t at =
        static_cast<std::size_t>(std::clamp(i, 0.0, static_cast<double>(w.periods - 1)));
    sum[at] += x[k];
    ++count[at];
  }
  if (*std::min_element(count.begin(), count.end()) < 2) {
    p.sparse = true;
    return p;
  }
  std::vector<double> means;
  for (std::size_t i = 0; i < sum.size(); ++i) means.push_back(sum[i] / count[i]);
  p.e = period_means_error(means);
  return p;
}

// The relative standard error above which a pocket-wheel run's mean span tensions are reported
// as not settled: the issue's 1 % (docs/models/dynamics.md, "Pocket wheel: the example's means").
constexpr double kSettledMeans = 0.01;

Record describe(const Result& r, const analysis::Inputs&) {
  const Setup& d = r.setup;
  Record rec;
  rec.diagnostics = r.diagnostics;
  if (d.catalogue_stiffness)
    rec.diagnostics.push_back(
        {Diagnostic::Severity::kInfo, "dynamics.axial_stiffness_from_catalogue",
         "axial_stiffness omitted: k = " + format_g(d.stiffness, 4) + " N/m per link, " + d.chain +
             "'s from the " + kCatalogueStiffnessSource + " (" + kCatalogueStiffnessQuality +
             "; single strand, no load range, no second source to check it against); give "
             "axial_stiffness for a measured one",
         d.stiffness, 0.0, "N/m"});
  const double simulated = r.steps * d.step;
  const double rtf = r.wall_time > 0.0 ? simulated / r.wall_time : 0.0;
  Value j = Value::object();
  j["model"] = "dynamics.chain_loop";
  j["source"] = std::string(
                    "implicit midpoint / theta-method with the discrete energy-momentum gradient "
                    "(Simo & Tarnow ") +
                (d.pocket ? "1992), round-link chain on pocket wheels at seed 003's joint polygon "
                            "(docs/models/dynamics.md)"
                          : "1992), ISO 606 sprocket seats (docs/models/dynamics.md)");
  if (!d.chain.empty()) j["chain"] = d.chain;
  j["pitch"] = d.pitch;
  j["links"] = d.links;
  if (d.layout()) {
    // the free layout: the belt path's length and the links' chord as laid (no single z or
    // centre distance)
    j["path_length"] = d.path.length;
    j["laid_pitch"] = d.laid_pitch;
    if (d.slack > 0.0) j["slack"] = d.slack;  // a start with slack only
    if (d.links_fitted) {
      // `links` omitted: the count the command took and the slack it implies
      j["links_chosen"] = d.links;
      j["links_slack"] = d.fitted_slack;
    }
  } else {
    j["teeth"] = d.teeth;
    j["centre_distance"] =
        d.pocket ? (d.links - 2 * d.teeth) / 4 * 2 * d.pitch : (d.links - d.teeth) / 2 * d.pitch;
  }
  j["theta"] = d.theta;
  j["time"] = r.time;
  Value wheels = Value::array();
  for (std::size_t w = 0; w < r.sprocket.size(); ++w) {
    Value wheel = d.layout() ? Value::object({{"role", d.wheels[w].role},
                                              {"teeth", d.wheels[w].teeth},
                                              {"centre_x", d.wheels[w].x},
                                              {"centre_y", d.wheels[w].y},
                                              {"angle", r.sprocket[w].angle},
                                              {"speed", r.sprocket[w].speed},
                                              {"torque", r.sprocket[w].torque}})
                             : Value::object({{"role", w == d.driver ? "driver" : "driven"},
                                              {"angle", r.sprocket[w].angle},
                                              {"speed", r.sprocket[w].speed},
                                              {"torque", r.sprocket[w].torque}});
    // a wheel's own seat friction, only when some wheel was given one
    if (per_wheel_friction(d)) wheel["seat_friction"] = wheel_mu(d, w);
    // the side, only on a wheel on the back of the chain (a serpentine path)
    if (d.layout() && d.wheels[w].back) wheel["side"] = "outside";
    wheels.push_back(std::move(wheel));
  }
  j["sprocket"] = wheels;
  // the driver turns counter-clockwise: the driver at x = 0 pulls the upper span
  const bool upper_tight = d.driver == 0;
  Value spans = Value::array();
  if (d.layout()) {
    for (const LayoutSpan& sp : layout_spans(d))
      spans.push_back(Value::object({{"name", sp.name},
                                     {"from", static_cast<int>(sp.from)},
                                     {"to", static_cast<int>(sp.to)},
                                     {"side", sp.side},
                                     {"tension", r.span[sp.index]}}));
  } else {
    spans.push_back(Value::object(
        {{"name", "upper"}, {"side", upper_tight ? "tight" : "slack"}, {"tension", r.span[0]}}));
    spans.push_back(Value::object(
        {{"name", "lower"}, {"side", upper_tight ? "slack" : "tight"}, {"tension", r.span[1]}}));
  }
  j["span"] = spans;
  j["summary"] = Value::object({{"steps", r.steps},
                                {"step", d.step},
                                {"wall_time", r.wall_time},
                                {"real_time_factor", rtf},
                                {"energy_drift", r.energy_drift},
                                {"max_penetration", r.max_penetration}});
  // gravity and guides add fields only when given: a run without them prints what it did before
  if (d.gravity > 0.0) j["gravity"] = d.gravity;
  // a round-link chain on pocket wheels (wheel = "pocket"): its wheel and chain
  if (d.pocket) {
    j["wheel"] = "pocket";
    j["wire_diameter"] = d.wire;
    j["pocket_clearance"] = d.clearance;
    // the mouth's ramp and the release only when not the sharp mouth's defaults (0, false)
    if (d.mouth > 0.0) j["pocket_mouth"] = d.mouth;
    if (d.release) j["pocket_release"] = true;
    j["pitch_radius"] = d.pocket_radius;
    j["pocket_angle"] = d.pocket_angle;
  }
  // the seats' law only when not the linear one
  if (d.line_law) j["contact_law"] = "line";
  // the discrete gradient only when not the law's default
  // echoed whenever it is not the penalty's default or the line law runs (whose default is true)
  if (d.discrete_gradient || d.line_law) j["discrete_gradient"] = d.discrete_gradient;
  // contact_stiffness omitted: the Hertz default used and its linearisation load
  if (d.hertz_stiffness) {
    j["contact_stiffness"] = d.contact_stiffness;
    j["contact_load"] = d.expected_load;
  }
  // axial_stiffness omitted: the catalogue's value used and where it comes from
  if (d.catalogue_stiffness) {
    j["axial_stiffness"] = d.stiffness;
    j["axial_stiffness_source"] = kCatalogueStiffnessSource;
  }
  if (!d.guides.empty()) {
    j["guides"] = static_cast<int>(d.guides.size());
    j["summary"]["friction_work"] = r.friction_work;
  }
  // seat friction likewise (opt-in: seat_friction > 0 on some wheel)
  if (any_seat_friction(d)) {
    j["seat_friction"] = d.seat_friction;
    j["summary"]["seat_friction_work"] = r.seat_friction_work;
  }
  // opt-in (work_balance = true): without it the output is what it was
  // hinge friction adds fields only when it is on: a frictionless run prints what it did before
  const bool hinge_on = d.hinge != "frictionless";
  if (hinge_on) {
    j["hinge"] = d.hinge;
    j["hinge_arm"] = d.hinge_law.arm;
    j["hinge_band"] = d.hinge_law.rate_band;
    // the pin link's load only: a run with the mean prints what it did before
    if (d.hinge_law.pin_load == PinLoad::kPinLink) j["hinge_pin_load"] = "pin_link";
    // the stick law only: a run with the regularised law prints what it did before
    if (d.hinge_law.sticks()) {
      j["hinge_stick_stiffness"] = d.hinge_law.stick_stiffness;
      j["hinge_stick_damping"] = d.hinge_law.stick_damping;
    }
    j["summary"]["hinge_friction_work"] = r.hinge_work;
  }
  if (d.work_balance) {
    j["summary"]["work_balance"] = Value::object({{"input", r.input_work},
                                                  {"friction", r.friction_work},
                                                  {"link_dampers", r.damper_work},
                                                  {"contact_dampers", r.contact_damping_work},
                                                  {"numerical", r.numerical_work}});
    if (any_seat_friction(d)) j["summary"]["work_balance"]["seat_friction"] = r.seat_friction_work;
    if (hinge_on) j["summary"]["work_balance"]["hinge_friction"] = r.hinge_work;
    if (!r.takeup.empty()) j["summary"]["work_balance"]["takeup_dampers"] = r.takeup_damper_work;
    if (any_rail_load(d)) j["summary"]["work_balance"]["loads"] = r.load_work;
    if (any_load_inertia(d.guides)) {
      j["summary"]["work_balance"]["load_catch"] = r.load_catch_work;
      // the part of load_catch the arriving material brings (its loss is load_catch less it)
      j["summary"]["work_balance"]["load_arrival"] = r.load_arrival_work;
      j["summary"]["work_balance"]["load_discharge"] = r.load_discharge_work;
    }
  }
  // take-ups add fields only when given: takeup[k] {sprocket, position, slide_speed, force}
  if (!r.takeup.empty()) {
    Value tus = Value::array();
    for (const TakeupSeries& tu : r.takeup) {
      const LayoutWheel& lw = d.wheels[tu.wheel];
      Value o = Value::object({{"sprocket", static_cast<int>(tu.wheel)},
                               {"direction", lw.takeup_direction},
                               {"preload", lw.takeup_force},
                               {"stiffness", lw.takeup_stiffness},
                               {"damping", lw.takeup_damping},
                               {"position", tu.position},
                               {"slide_speed", tu.speed},
                               {"force", tu.force}});
      // the end stops, when given (a case without them prints what it did before)
      if (std::isfinite(lw.takeup_travel_min)) o["travel_min"] = lw.takeup_travel_min;
      if (std::isfinite(lw.takeup_travel_max)) o["travel_max"] = lw.takeup_travel_max;
      tus.push_back(std::move(o));
    }
    j["takeup"] = tus;
  }
  // the scalar summaries a sweep takes as columns (objects, not arrays: arrays are series to a
  // sweep): each sprocket's mean speed and torque, each span's mean, least and greatest tension,
  // over the window of summary_window(), all added after the fields above
  const int driver_teeth = d.layout() ? d.wheels[d.driver].teeth : d.teeth;
  const double period = 2 * kPi / (driver_teeth * d.speed);
  const Window win = summary_window(r.time, period);
  const double output_sample = output_every(d) * d.step;  // the series' sampling interval
  j["summary"]["window_start"] = win.start;
  j["summary"]["window_end"] = win.end;
  j["summary"]["window_periods"] = win.periods;
  j["summary"]["window_samples"] = static_cast<long long>(win.last - win.first);
  for (std::size_t w = 0; w < r.sprocket.size(); ++w) {
    j["summary"]["sprocket_" + std::to_string(w)] =
        Value::object({{"mean_speed", window_stats(r.sprocket[w].speed, win).mean},
                       {"mean_torque", window_stats(r.sprocket[w].torque, win).mean}});
  }
  // each span's first natural frequencies at its mean tension and the chain's mean speed
  // (span_modes.hpp): the two-wheel loop's spans are the centre distance long, a free layout's
  // its belt path's straight pieces (in the order of its spans)
  std::vector<double> span_length;
  if (d.layout()) {
    for (const PathPiece& q : d.path.pieces)
      if (!q.arc) span_length.push_back(std::hypot(q.x1 - q.x0, q.y1 - q.y0));
  } else {
    span_length.assign(r.span.size(), d.pocket ? (d.links - 2 * d.teeth) / 4 * 2 * d.pitch
                                               : (d.links - d.teeth) / 2 * d.pitch);
  }
  // the links a turn of the driver draws: z (a pocket wheel: 2z, two joints a pocket)
  const int links_a_turn = d.pocket ? 2 * driver_teeth : driver_teeth;
  const double chain_speed = links_a_turn * d.pitch / (2 * kPi) *
                             std::abs(window_stats(r.sprocket[d.driver].speed, win).mean);
  // With take-ups, the spans also at the settled layout (docs/models/dynamics.md, "Span
  // frequencies"): each take-up's wheel at its slide's mean over the window, the belt path
  // round the circles there (empty: not the same path, its spans are not these)
  std::vector<double> settled_length;
  if (d.layout() && !r.takeup.empty()) {
    std::vector<Circle> circles = d.circles;
    for (const TakeupSeries& tu : r.takeup) {
      const double mean = window_stats(tu.position, win).mean;
      circles[tu.wheel].x += mean * std::cos(d.wheels[tu.wheel].takeup_direction);
      circles[tu.wheel].y += mean * std::sin(d.wheels[tu.wheel].takeup_direction);
    }
    const BeltPath settled = belt_path(circles, 0);
    for (const PathPiece& q : settled.pieces)
      if (!q.arc) settled_length.push_back(std::hypot(q.x1 - q.x0, q.y1 - q.y0));
    if (!settled.unwrapped.empty() || !settled.faults.empty() || settled.order != d.path.order ||
        settled_length.size() != span_length.size())
      settled_length.clear();
  }
  std::vector<SpanFrequencies> span_f;  // also marked on the report's spectrum
  // a pocket's spans: each one's mean and the means' error (the warning below); unestimated:
  // a span's error not estimated, sparse: why
  std::vector<double> pocket_mean;
  std::vector<PeriodMeansError> pocket_error;
  bool unestimated = false, sparse = false;
  for (std::size_t k = 0; k < r.span.size(); ++k) {
    const Stats t = window_stats(r.span[k], win);
    const SpanFrequencies f = span_frequencies(span_length[k], t.mean, d.mass_per_metre,
                                               chain_speed, d.stiffness, d.pitch);
    Value& summary = j["summary"]["span_" + std::to_string(k)];
    summary =
        Value::object({{"mean_tension", t.mean}, {"min_tension", t.min}, {"max_tension", t.max}});
    // a pocket wheel's loop: how far the window's mean is from settled (new fields, a pocket
    // only: every other run prints what it did before)
    if (d.pocket) {
      const PeriodSpread ps = period_spread(r.time, r.span[k], win, period);
      const PeriodMeansError& e = ps.e;
      // fewer than 2 whole periods: null (the fields kept, as a span's frequencies a short run
      // has not), the warning below saying why; the correlation also null below
      // kCorrelationMinPeriods periods (the means taken as independent)
      const bool estimated = e.periods >= 2 && std::isfinite(e.error) && std::isfinite(e.sd);
      summary["mean_tension_error"] = estimated ? Value(e.error) : Value();
      summary["period_tension_sd"] = estimated ? Value(e.sd) : Value();
      summary["period_correlation"] =
          estimated && std::isfinite(e.correlation) ? Value(e.correlation) : Value();
      summary["effective_periods"] = estimated ? Value(e.effective_periods) : Value();
      if (!estimated) {
        unestimated = true;
        sparse = sparse || ps.sparse;
      }
      pocket_mean.push_back(t.mean);
      pocket_error.push_back(e);
    }
    // a span on guides is not free: its frequencies are not these
    if (!d.guides.empty()) continue;
    // a frequency the span has not (no tension over the window, or a span under a pitch) is
    // null, an absent value, with the warning below saying why: never NaN, which would read as
    // a result the model failed to compute
    auto frequency = [](double hz) { return std::isfinite(hz) ? Value(hz) : Value(); };
    summary["transverse_frequency"] = frequency(f.transverse);
    summary["longitudinal_frequency"] = frequency(f.longitudinal);
    if (!settled_length.empty()) {  // new fields beside the start layout's (a take-up only)
      const SpanFrequencies fs = span_frequencies(settled_length[k], t.mean, d.mass_per_metre,
                                                  chain_speed, d.stiffness, d.pitch);
      summary["settled_length"] = settled_length[k];
      summary["settled_transverse_frequency"] = frequency(fs.transverse);
      summary["settled_longitudinal_frequency"] = frequency(fs.longitudinal);
    }
    span_f.push_back(f);
    const double qv2 = d.mass_per_metre * chain_speed * chain_speed;
    const bool no_frequency = !std::isfinite(f.transverse) || !std::isfinite(f.longitudinal);
    if ((no_frequency || f.transverse == 0.0) && win.periods == 0 && span_length[k] >= d.pitch &&
        !(t.mean > qv2)) {
      // the run is too short: its summary window (the second half) holds no whole tooth period
      // of the driver, so the span's mean tension is that of the start-up, not of the drive.
      // The window ends at the last output sample: the shortest run whose last sample is two
      // tooth periods in, a whole number of output intervals (one more when 2T is a whole
      // number of them: the samples' times carry round-off, and the last must be past 2T)
      const double shortest = (std::floor(2 * period / output_sample) + 1.0) * output_sample;
      rec.diagnostics.push_back(
          {Diagnostic::Severity::kWarning, "dynamics.span_frequencies_unmeasured",
           "span " + std::to_string(k) + ": no natural frequencies (" +
               (no_frequency ? "null" : "transverse 0") + "): the run of " +
               format_g(simulated, 4) +
               " s (dynamics.duration) is too short to measure them; over its " +
               "second half, less than one tooth period of the driver (" + format_g(period, 4) +
               " s), the span's mean tension is " + format_g(t.mean, 4) +
               " N (a free span's frequencies need more than q v^2 = " + format_g(qv2, 4) +
               " N); a duration of at least " + format_g(shortest, 4) +
               " s (two tooth periods: one whole period after the start-up half) measures them",
           simulated, shortest});
    } else if (no_frequency)
      rec.diagnostics.push_back(
          {Diagnostic::Severity::kWarning, "dynamics.span_frequencies_undefined",
           "span " + std::to_string(k) + " (" + format_g(span_length[k], 4) + " m, mean tension " +
               format_g(t.mean, 4) +
               " N): no natural frequencies (they need a span of at least one pitch, " +
               format_g(d.pitch, 4) + " m, in tension)",
           t.mean, 0.0});
    else if (f.transverse == 0.0)
      rec.diagnostics.push_back(
          {Diagnostic::Severity::kWarning, "dynamics.span_without_transverse_stiffness",
           "span " + std::to_string(k) + ": its mean tension " + format_g(t.mean, 4) +
               " N is not above q v^2 = " + format_g(qv2, 4) +
               " N at the chain's speed: the span has no transverse natural frequency (it runs "
               "at or above the speed of its transverse waves)",
           t.mean, qv2});
  }
  // a pocket wheel's means not settled to kSettledMeans: say so, and the duration that would
  // (periods_to_settle, the window half the run). The errors are measured against the largest
  // span mean tension (the tight span's: the loop's working tension, what the chain is sized
  // by), not each span's own: a slack span's mean of a few newtons would make its relative
  // error, and the duration asked for, as large as one likes
  double scale = -std::numeric_limits<double>::infinity();
  std::size_t scale_span = 0;
  for (std::size_t k = 0; k < pocket_mean.size(); ++k)
    if (pocket_mean[k] > scale) {
      scale = pocket_mean[k];
      scale_span = k;
    }
  const bool unscaled = d.pocket && !unestimated && !(scale > 0.0 && std::isfinite(scale));
  double worst_error = 0.0, worst_sd = 0.0, settle = 0.0;  // error, s over the scale; periods
  double worst_rho = 0.0, fewest_effective = 0.0;          // the correlation's effect, if any
  bool correlated = false;  // every span's correlation estimated (else all taken independent)
  if (d.pocket && !unestimated && !unscaled) {
    correlated = true;
    fewest_effective = std::numeric_limits<double>::infinity();
    for (const PeriodMeansError& e : pocket_error) {
      worst_error = std::max(worst_error, e.error / scale);
      worst_sd = std::max(worst_sd, e.sd / scale);
      settle = std::max(settle, periods_to_settle(e, scale, kSettledMeans));
      correlated = correlated && std::isfinite(e.correlation);
      if (std::isfinite(e.correlation)) worst_rho = std::max(worst_rho, e.correlation);
      fewest_effective = std::min(fewest_effective, e.effective_periods);
    }
  }
  if (d.pocket && (unestimated || unscaled || worst_error > kSettledMeans)) {
    const double simulated_end = r.time.back();
    std::string message;
    if (sparse) {
      message = "the mean span tensions' uncertainty is not estimated: each of the window's " +
                std::to_string(win.periods) + " tooth periods (" + format_g(period, 4) +
                " s) needs at least 2 output samples; dynamics.output_interval = " +
                format_g(output_sample, 4) + " s, at most " + format_g(0.5 * period, 4) +
                " s (half a tooth period) gives them";
    } else if (unscaled) {
      message =
          "the mean span tensions' uncertainty is not measured against a tension: no span's "
          "mean tension over the window is positive (the largest, span " +
          std::to_string(scale_span) + "'s, is " + format_g(scale, 4) + " N)";
    } else if (!unestimated) {
      const double n = std::ceil(settle);
      const std::string correlation =
          correlated ? "allowing for the periods' lag-1 autocorrelation, up to " +
                           format_g(worst_rho, 2) + ": at least " + format_g(fewest_effective, 3) +
                           " effective periods of " + std::to_string(win.periods)
                     : "the periods' means taken as independent: " + std::to_string(win.periods) +
                           " periods are too few to estimate their correlation, at least " +
                           std::to_string(kCorrelationMinPeriods);
      message = "the mean span tensions over the window's " + std::to_string(win.periods) +
                " tooth periods are uncertain by up to " + format_g(100 * worst_error, 2) +
                " % of the largest span mean tension (span " + std::to_string(scale_span) + "'s, " +
                format_g(scale, 4) + " N; one standard error, " + correlation +
                "); the periods' means scatter by up to " + format_g(100 * worst_sd, 2) +
                " % of it (the loop's response does not repeat with the tooth period); "
                "dynamics.duration = " +
                format_g(simulated_end, 4) + " s; about " + format_g(2 * n * period, 3) + " s (" +
                format_g(n, 4) + " periods in the window) would settle them to " +
                format_g(100 * kSettledMeans, 2) + " %" +
                (correlated ? std::string()
                            : std::string(" (a rough figure: the scatter is estimated from ") +
                                  std::to_string(win.periods) +
                                  " periods only, and a longer run may scatter more)");
    } else {
      message = "the window holds " + std::to_string(win.periods) +
                " whole tooth period(s): the mean span tensions' uncertainty needs at least 2 "
                "(dynamics.duration = " +
                format_g(simulated_end, 4) + " s; more than " + format_g(4 * period, 3) + " s)";
    }
    rec.diagnostics.push_back({Diagnostic::Severity::kWarning, "dynamics.means_not_settled",
                               message, unestimated || unscaled ? 0.0 : worst_error,
                               kSettledMeans});
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
  j["diagnostics"] = analysis::diagnostics_value(rec.diagnostics);
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
  if (d.pocket)
    for (const char* key : {"wire_diameter", "pocket_clearance", "pitch_radius", "pocket_angle"})
      j["units"][key] = key == std::string("pocket_angle") ? "rad" : "m";
  if (d.pocket && d.mouth > 0.0) j["units"]["pocket_mouth"] = "m";
  if (d.layout())
    for (const char* key : {"path_length", "laid_pitch", "centre_x", "centre_y"})
      j["units"][key] = "m";
  if (d.slack > 0.0) j["units"]["slack"] = "m";
  if (d.links_fitted) j["units"]["links_slack"] = "m";
  if (d.hertz_stiffness) {
    j["units"]["contact_stiffness"] = "N/m";
    j["units"]["contact_load"] = "N";
  }
  if (d.catalogue_stiffness) j["units"]["axial_stiffness"] = "N/m";
  if (!d.guides.empty()) j["units"]["friction_work"] = "J";
  if (any_seat_friction(d)) j["units"]["seat_friction_work"] = "J";
  if (d.work_balance) j["units"]["work_balance"] = "J";
  if (!r.takeup.empty()) {
    j["units"]["direction"] = "rad";
    j["units"]["preload"] = "N";
    j["units"]["stiffness"] = "N/m";
    j["units"]["damping"] = "N s/m";
    j["units"]["position"] = "m";
    j["units"]["slide_speed"] = "m/s";
    j["units"]["force"] = "N";
    for (const TakeupSeries& tu : r.takeup) {
      if (std::isfinite(d.wheels[tu.wheel].takeup_travel_min)) j["units"]["travel_min"] = "m";
      if (std::isfinite(d.wheels[tu.wheel].takeup_travel_max)) j["units"]["travel_max"] = "m";
    }
  }
  if (hinge_on) {
    j["units"]["hinge_arm"] = "m";
    j["units"]["hinge_band"] = "rad/s";
    j["units"]["hinge_friction_work"] = "J";
    if (d.hinge_law.sticks()) {
      j["units"]["hinge_stick_stiffness"] = "N m/rad";
      j["units"]["hinge_stick_damping"] = "N m s/rad";
    }
  }
  for (const char* key : {"window_start", "window_end"}) j["units"][key] = "s";
  if (d.positions) {
    j["units"]["x"] = "m";
    j["units"]["y"] = "m";
  }
  j["units"]["mean_speed"] = "rad/s";
  j["units"]["mean_torque"] = "N m";
  for (const char* key : {"mean_tension", "min_tension", "max_tension"}) j["units"][key] = "N";
  if (d.pocket) {
    for (const char* key : {"mean_tension_error", "period_tension_sd"}) j["units"][key] = "N";
    for (const char* key : {"period_correlation", "effective_periods"}) j["units"][key] = "1";
  }
  if (d.guides.empty())
    for (const char* key : {"transverse_frequency", "longitudinal_frequency"})
      j["units"][key] = "Hz";
  if (d.guides.empty() && !settled_length.empty()) {
    j["units"]["settled_length"] = "m";
    for (const char* key : {"settled_transverse_frequency", "settled_longitudinal_frequency"})
      j["units"][key] = "Hz";
  }
  rec.data = std::move(j);

  std::ostringstream csv;
  if (d.layout()) {
    csv << "time";
    for (std::size_t w = 0; w < r.sprocket.size(); ++w)
      csv << ",angle_" << w << ",speed_" << w << ",torque_" << w;
    for (const LayoutSpan& sp : layout_spans(d)) csv << ",tension_" << sp.from << "_" << sp.to;
    // a take-up's series after the spans, named as in the JSON's takeup[k] with its wheel
    for (const TakeupSeries& tu : r.takeup)
      csv << ",position_" << tu.wheel << ",slide_speed_" << tu.wheel << ",force_" << tu.wheel;
    csv << "\n";
    for (std::size_t k = 0; k < r.time.size(); ++k) {
      csv << format_g(r.time[k], 12);
      for (const Series& w : r.sprocket)
        csv << "," << format_g(w.angle[k], 12) << "," << format_g(w.speed[k], 12) << ","
            << format_g(w.torque[k], 12);
      for (const std::vector<double>& t : r.span) csv << "," << format_g(t[k], 12);
      for (const TakeupSeries& tu : r.takeup)
        csv << "," << format_g(tu.position[k], 12) << "," << format_g(tu.speed[k], 12) << ","
            << format_g(tu.force[k], 12);
      csv << "\n";
    }
  } else {
    csv << "time,angle_0,speed_0,torque_0,angle_1,speed_1,torque_1,tension_upper,tension_lower\n";
  }
  for (std::size_t k = 0; !d.layout() && k < r.time.size(); ++k) {
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
  if (d.layout()) {
    t << "Catena dynamics: chain loop over " << d.wheels.size()
      << " sprockets in time (issue 21)\n\n"
      << "  " << (d.chain.empty() ? "chain" : d.chain) << ", " << d.links << " links";
    // `links` omitted: the JSON's links_chosen and links_slack, named as the JSON names them
    if (d.links_fitted)
      t << " (links_chosen " << d.links << ", the count the path fits; links_slack "
        << format_g(d.fitted_slack * 1e3, 4) << " mm)";
    t << ", belt path " << format_g(d.path.length * 1e3, 6) << " mm (links laid at "
      << format_g(d.laid_pitch * 1e3, 7) << " mm";
    if (d.slack > 0.0) {
      t << ", " << format_g(d.slack * 1e3, 6) << " mm of slack sagging in the span"
        << (d.slack_pieces.size() > 1 ? "s" : "");
      for (std::size_t i = 0; i < d.slack_pieces.size(); ++i)
        t << (i ? ", sprocket " : " sprocket ") << d.path.pieces[d.slack_pieces[i]].wheel
          << " -> sprocket " << d.path.pieces[d.slack_pieces[i]].next;
    }
    t << "), theta " << format_g(d.theta, 3);
  } else {
    t << "Catena dynamics: chain loop over two sprockets in time (issue 21)\n\n"
      << "  " << (d.chain.empty() ? "chain" : d.chain) << ", " << d.links
      << " links, z = " << d.teeth << " / " << d.teeth << ", centre distance "
      << format_g(
             (d.pocket ? (d.links - 2 * d.teeth) / 4 * 2 : (d.links - d.teeth) / 2) * d.pitch * 1e3,
             5)
      << " mm, theta " << format_g(d.theta, 3);
    if (d.pocket)
      t << "\n  round-link chain " << format_g(d.wire * 1e3, 4) << " x "
        << format_g(d.pitch * 1e3, 4) << " mm on pocket wheels (seed 003): R "
        << format_g(d.pocket_radius * 1e3, 6) << " mm, delta1 "
        << format_g(d.pocket_angle * 180.0 / kPi, 5) << " deg";
  }
  t << "\n  " << r.steps << " steps of " << format_g(d.step * 1e3, 4) << " ms ("
    << format_g(simulated, 5) << " s) in " << fixed(r.wall_time, 3)
    << " s wall time, real-time factor " << format_g(rtf, 3) << "\n\n"
    << "  means over the second half of the run:\n";
  for (std::size_t w = 0; w < r.sprocket.size(); ++w) {
    t << "    sprocket " << w << " (" << role_of(d, w);
    if (d.layout()) t << ", z = " << d.wheels[w].teeth;
    if (d.layout() && d.wheels[w].back) t << ", on the back of the chain";
    t << ")  speed " << format_g(late_mean(r.sprocket[w].speed), 6) << " rad/s, chain torque "
      << format_g(late_mean(r.sprocket[w].torque), 5) << " N m\n";
  }
  if (d.layout()) {
    for (const LayoutSpan& sp : layout_spans(d))
      t << "    span " << sp.from << " -> " << sp.to << " (" << sp.side << ") tension "
        << format_g(late_mean(r.span[sp.index]), 5) << " N\n";
  } else {
    t << "    upper span tension " << format_g(late_mean(r.span[0]), 5) << " N ("
      << (upper_tight ? "tight" : "slack") << "), lower " << format_g(late_mean(r.span[1]), 5)
      << " N\n";
  }
  t << "  energy drift " << format_g(r.energy_drift, 4) << " J, deepest "
    << (d.pocket ? "joint" : "roller") << " penetration " << format_g(r.max_penetration * 1e6, 4)
    << " um\n";
  if (d.gravity > 0.0 || !d.guides.empty())
    t << "  gravity " << format_g(d.gravity, 6) << " m/s^2, " << d.guides.size()
      << " guide(s), friction work " << format_g(r.friction_work, 5) << " J\n";
  if (d.work_balance)
    t << "  work balance: input " << format_g(r.input_work, 5) << " J, friction "
      << format_g(r.friction_work, 5) << " J, link dampers " << format_g(r.damper_work, 5)
      << " J, contact dampers " << format_g(r.contact_damping_work, 5) << " J, "
      << (r.takeup.empty() ? std::string()
                           : "take-up dampers " + format_g(r.takeup_damper_work, 5) + " J, ")
      << (any_rail_load(d) ? "loads " + format_g(r.load_work, 5) + " J, " : std::string())
      << (any_load_inertia(d.guides)
              ? "load catch " + format_g(r.load_catch_work, 5) + " J (arrival " +
                    format_g(r.load_arrival_work, 5) + " J), load discharge " +
                    format_g(r.load_discharge_work, 5) + " J, "
              : std::string())
      << "numerical " << format_g(r.numerical_work, 4) << " J\n";
  if (any_seat_friction(d)) {
    t << "  seat friction ";
    if (per_wheel_friction(d)) {
      t << "per wheel";
      for (std::size_t w = 0; w < d.wheel_friction.size(); ++w)
        t << " " << format_g(wheel_mu(d, w), 4);
    } else {
      t << format_g(d.seat_friction, 4);
    }
    t << ", its work " << format_g(r.seat_friction_work, 5) << " J\n";
  }
  if (hinge_on)
    t << "  hinges " << d.hinge << ": friction arm " << format_g(d.hinge_law.arm * 1e3, 4)
      << " mm, rate band " << format_g(d.hinge_law.rate_band, 3) << " rad/s"
      << (d.hinge_law.pin_load == PinLoad::kPinLink ? ", pin load the pin link's" : "")
      << (d.hinge_law.sticks()
              ? ", stick spring " + format_g(d.hinge_law.stick_stiffness, 4) + " N m/rad" +
                    (d.hinge_law.stick_damping > 0.0
                         ? " and damper " + format_g(d.hinge_law.stick_damping, 4) + " N m s/rad"
                         : std::string())
              : std::string())
      << ", friction work " << format_g(r.hinge_work, 5) << " J\n";
  for (const Diagnostic& diag : rec.diagnostics)
    t << "  " << to_string(diag.severity) << ": " << diag.message << "\n";
  rec.table = t.str();

  ReportInput report{.time = r.time,
                     .teeth = d.layout() ? d.wheels[d.driver].teeth : d.teeth,
                     .driver_speed = d.speed,
                     .spectrum_start = d.spectrum_start};
  for (std::size_t w = 0; w < r.sprocket.size(); ++w) {
    const std::string name = "sprocket " + std::to_string(w) + " (" + role_of(d, w) + ")";
    report.speed.push_back({name, r.sprocket[w].speed});
    report.torque.push_back({name, r.sprocket[w].torque});
  }
  if (d.layout()) {
    for (const LayoutSpan& sp : layout_spans(d))
      report.span.push_back({"span " + std::to_string(sp.from) + " -> " + std::to_string(sp.to) +
                                 " (" + sp.side + ")",
                             r.span[sp.index]});
  } else {
    report.span.push_back({upper_tight ? "upper span (tight)" : "upper span (slack)", r.span[0]});
    report.span.push_back({upper_tight ? "lower span (slack)" : "lower span (tight)", r.span[1]});
  }
  // each span's first transverse frequency and twice it (a transverse vibration stretches the
  // span twice a cycle), and its first longitudinal one, where the spectrum reaches them
  for (std::size_t k = 0; k < span_f.size(); ++k) {
    const std::string& name = report.span[k].name;
    char text[160];
    if (span_f[k].transverse > 0.0) {
      std::snprintf(text, sizeof text, "%s: transverse f1 = %.4g Hz", name.c_str(),
                    span_f[k].transverse);
      report.span_markers.push_back({span_f[k].transverse, text});
      std::snprintf(text, sizeof text, "%s: 2 f1 = %.4g Hz", name.c_str(),
                    2 * span_f[k].transverse);
      report.span_markers.push_back({2 * span_f[k].transverse, text});
    }
    std::snprintf(text, sizeof text, "%s: longitudinal f1 = %.4g Hz", name.c_str(),
                  span_f[k].longitudinal);
    report.span_markers.push_back({span_f[k].longitudinal, text});
  }
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
  a.chain_types = {"roller-iso606", "round-link"};  // round-link: wheel = "pocket"
  a.formats = {.table = true, .csv = true, .drawing = false};
  using analysis::quantity;
  Parameter chain_type = analysis::choice(
      "chain_type", {"roller-iso606", "round-link"},
      "the chain's type, which dynamics.wheel must agree with: round-link needs wheel = pocket, "
      "roller-iso606 refuses it (case files: from chain.type)");
  chain_type.cli_only = true;  // a case file's chain.type chooses it (the variants below)
  a.parameters = {
      table_parameter(),
      quantity("duration", K::kTime, "simulated time (overrides dynamics.duration)") |
          analysis::NotShared{},
      quantity("step", K::kTime, "time step h (overrides dynamics.step)") | analysis::NotShared{},
      chain_type};
  // a case file's chain.type sets it (the variants): the wheel must agree with it
  a.variants = {{"roller-iso606", {{{"chain_type", "roller-iso606"}}, {}}},
                {"round-link", {{{"chain_type", "round-link"}}, {}}}};
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
