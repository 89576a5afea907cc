// The composite link (seed 002) as analyses: `ring` (the orthotropic ring on two rigid
// half-discs), `ring capacity` (eq. (9), the mass comparison) and `ring design` (sizing a
// fibre-wound link for a breaking force).
#include "catena/composite/analysis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <set>
#include <sstream>
#include <string_view>

namespace catena::composite {
namespace {

// The work of the ring solver's sizes (docs/reliability.md): the harmonics N cost 6.6 ns·N²
// and 2 kB·N (N = 40 000: 10.6 s, 31 MB max RSS; the issue's N = 200 000 took > 600 s and
// 415 MB), the sweep's nodes m 0.4 ms and 530 B a node (m = 30 000: 12 s, 16 MB).
const analysis::Work kHarmonicsWork{
    .cap = 20000, .seconds = 6.6e-9, .time_power = 2.0, .bytes = 2000.0};
const analysis::Work kNodesWork{.cap = 20000, .seconds = 400e-6, .bytes = 530.0};

using analysis::format_g;
using analysis::Inputs;
using analysis::Record;
using analysis::Value;

// The issues of one binding in the order the command has always reported them: bind reports
// every value that is missing (when required) or unreadable, in table order; a `check` moves
// them to where the value is read (`take`), between the rules it checks itself (`add`). Issues
// it does not take (values the chosen mode does not read) come first.
class Ordered {
 public:
  explicit Ordered(std::vector<Issue>& issues) : out_(issues), bound_(std::move(issues)) {
    out_.clear();
    for (const Issue& issue : bound_) reported_.insert(issue.field);
  }
  void add(Issue issue) { out_.push_back(std::move(issue)); }
  /// bind's issues about `key` (only its "(missing)" one when `only_missing`).
  void take(std::string_view key, bool only_missing = false) {
    for (auto it = bound_.begin(); it != bound_.end();) {
      if (it->field == key && (!only_missing || it->value == "(missing)")) {
        out_.push_back(std::move(*it));
        it = bound_.erase(it);
      } else {
        ++it;
      }
    }
  }
  /// `key` is absent: bind's "(missing)" issue for a required parameter, else this one.
  void missing(const Inputs& in, const std::string& key, const std::string& expected) {
    const std::size_t before = out_.size();
    take(key, true);
    if (out_.size() == before && !in.given(key)) add({key, "(missing)", expected});
  }
  /// bind could not read `key` (or found it missing).
  bool reported(const std::string& key) const { return reported_.count(key) > 0; }
  void finish() { out_.insert(out_.begin(), bound_.begin(), bound_.end()); }

 private:
  std::vector<Issue>& out_;
  std::vector<Issue> bound_;
  std::set<std::string, std::less<>> reported_;
};

// A value that was given and could be read.
std::optional<double> readable(const Inputs& in, std::string_view key) {
  const auto v = in.optional(key);
  if (v && std::isnan(*v)) return std::nullopt;
  return v;
}

// Model issues for values that were read: a NaN stands for a value already reported as missing
// or unreadable, so its model issue would repeat it.
void add_read_model_issues(Ordered& out, const std::vector<Issue>& model) {
  for (const Issue& i : model)
    if (i.value.rfind("nan", 0) != 0 && i.value.rfind("-nan", 0) != 0) out.add(i);
}

// =============================================================================================
// ring

Ring ring_of(const Inputs& in) {
  Ring ring;
  ring.inner_radius = in.number("inner_radius");
  ring.outer_radius = in.number("outer_radius");
  ring.thickness = in.number("thickness");
  ring.E_r = in.number("E_r");
  ring.E_phi = in.number("E_phi");
  ring.G = in.number("G");
  ring.nu_phi_r = in.number("nu_phi_r");
  ring.gap = in.number("gap");
  return ring;
}

Options options_of(const Inputs& in) {
  Options o;
  o.method = in.text("method") == "sweep" ? Method::kSweep : Method::kExact;
  o.unilateral = in.flag("unilateral");
  if (in.given("harmonics")) o.harmonics = in.integer("harmonics");
  if (in.given("nodes")) o.nodes = in.integer("nodes");
  o.points = in.integer("points");
  return o;
}

// --nodes belongs to the sweep; and the model's checks, so that every problem is reported at
// once (a value that could not be read has been reported already).
void ring_check(const Inputs& in, std::vector<Issue>& issues) {
  Ordered out(issues);
  for (const char* key : {"inner_radius", "outer_radius", "thickness", "E_r", "E_phi", "G",
                          "nu_phi_r", "gap", "harmonics", "nodes", "points"})
    out.take(key);
  const Options o = options_of(in);
  if (in.given("nodes") && o.method != Method::kSweep)
    out.add({"nodes", in.text("nodes"), "only with --method sweep (the exact solver has no grid)"});
  const Ring ring = ring_of(in);
  const std::map<std::string, double> read_values = {{"inner_radius", ring.inner_radius},
                                                     {"outer_radius", ring.outer_radius},
                                                     {"thickness", ring.thickness},
                                                     {"E_r", ring.E_r},
                                                     {"E_phi", ring.E_phi},
                                                     {"G", ring.G},
                                                     {"nu_phi_r", ring.nu_phi_r},
                                                     {"gap", ring.gap}};
  for (const Issue& is : validate(ring)) {
    const auto it = read_values.find(is.field);
    if (it != read_values.end() && std::isnan(it->second)) continue;
    out.add(is);
  }
  for (const Issue& is : validate(o)) {
    if ((is.field == "harmonics" || is.field == "nodes" || is.field == "points") &&
        out.reported(is.field))
      continue;
    out.add(is);
  }
  out.finish();
}

Value section(const Result& r, const std::vector<double>& sr, const std::vector<double>& sp,
              const std::vector<double>& tau) {
  return Value::object({{"r", r.r}, {"sigma_r", sr}, {"sigma_phi", sp}, {"tau", tau}});
}

Value matrix(const std::vector<std::vector<double>>& rows) {
  Value out = Value::array();
  for (const auto& row : rows) out.push_back(Value(row));
  return out;
}

Value ring_value(const RingAnalysis& a) {
  const Result& r = a.result;
  Value j = Value::object();
  j["model"] = "composite.orthotropic_ring";
  j["source"] =
      "002 eqs. (1)-(8): cylindrically orthotropic ring, plane stress, stretched by two rigid "
      "smooth half-discs; inner condition U_r = Delta*|cos phi|, tau = 0 (the paper's G0 = 2/pi "
      "reading), outer edge free; even-harmonic Fourier series";
  j["load"] = r.load;
  j["mean_stress"] = r.mean_stress;
  j["sections"]["0"] = section(r, r.sigma_r_0, r.sigma_phi_0, r.tau_0);
  j["sections"]["90"] = section(r, r.sigma_r_90, r.sigma_phi_90, r.tau_90);
  j["contact"] = Value::object({{"phi", r.contact_phi},
                                {"pressure", r.contact_pressure},
                                {"angle", r.contact_angle},
                                {"unilateral", a.options.unilateral},
                                {"iterations", r.contact_iterations}});
  j["stress_concentration"] = r.stress_concentration;
  j["corner"] = Value::object(
      {{"r", a.ring.inner_radius},
       {"phi", 0.5 * std::numbers::pi},
       {"sigma_phi", r.corner_sigma_phi},
       {"harmonics", r.summary.harmonics},
       {"note", "singular where the half-discs meet: grows with the harmonic count"}});
  if (a.field)
    j["field"] = Value::object({{"r", r.r},
                                {"phi", r.contact_phi},
                                {"sigma_r", matrix(r.field_sigma_r)},
                                {"sigma_phi", matrix(r.field_sigma_phi)},
                                {"tau", matrix(r.field_tau)},
                                {"layout", "[phi index][r index]"}});
  j["max_shear"] =
      Value::object({{"tau", r.max_shear}, {"r", r.max_shear_r}, {"phi", r.max_shear_phi}});
  j["sum_sigma_r"] = r.sum_sigma_r;
  j["load_contact"] = r.load_contact;
  j["summary"] = Value::object({{"method", r.summary.method},
                                {"harmonics", r.summary.harmonics},
                                {"nodes", r.summary.nodes},
                                {"fallbacks", r.summary.fallbacks},
                                {"truncation_change", r.summary.truncation_change},
                                {"richardson_error", r.summary.richardson_error},
                                {"equilibrium_residual", a.equilibrium_residual}});
  j["diagnostics"] = analysis::diagnostics_value(r.diagnostics);
  j["units"] = analysis::units_value({{"load", "N"},
                                      {"mean_stress", "Pa"},
                                      {"r", "m"},
                                      {"sigma_r", "Pa"},
                                      {"sigma_phi", "Pa"},
                                      {"tau", "Pa"},
                                      {"phi", "rad"},
                                      {"pressure", "Pa"},
                                      {"angle", "rad"},
                                      {"stress_concentration", "1"},
                                      {"sum_sigma_r", "1"},
                                      {"load_contact", "N"},
                                      {"truncation_change", "1"},
                                      {"richardson_error", "1"}});
  return j;
}

std::string ring_table(const RingAnalysis& a) {
  const Result& r = a.result;
  constexpr double kDeg = 180.0 / std::numbers::pi;
  std::ostringstream t;
  char line[1024];
  t << "Catena ring: orthotropic link on two rigid half-discs (seed 002; " << r.summary.method
    << " solver, " << r.summary.harmonics << " harmonics"
    << (r.summary.nodes > 0 ? ", " + std::to_string(r.summary.nodes) + " intervals" : "")
    << (a.options.unilateral ? ", unilateral contact" : ", bilateral contact") << ")\n\n";
  std::snprintf(line, sizeof line,
                "  load P              %10.5g kN   (from the contact: %.5g kN)\n"
                "  mean stress         %10.5g MPa  (P / 2(r2 - r1)t)\n"
                "  stress conc. K      %10.5g      (max sigma_phi at 90 deg, r >= r1 + 5%%)\n"
                "  corner sigma_phi    %10.5g MPa  (r1, 90 deg; grows with harmonics)\n"
                "  max |tau|           %10.5g MPa  at r = %.4g mm, phi = %.3g deg\n"
                "  sum sigma~_r        %10.5g      (eq. 9)\n"
                "  contact angle       %10.5g deg\n"
                "  truncation change   %10.3g      (N/2 -> N)\n",
                r.load / 1e3, r.load_contact / 1e3, r.mean_stress / 1e6, r.stress_concentration,
                r.corner_sigma_phi / 1e6, std::abs(r.max_shear) / 1e6, r.max_shear_r * 1e3,
                r.max_shear_phi * kDeg, r.sum_sigma_r, r.contact_angle * kDeg,
                r.summary.truncation_change);
  t << line;
  if (r.summary.nodes > 0) {
    std::snprintf(line, sizeof line, "  Richardson error    %10.3g      (of mean stress)\n",
                  r.summary.richardson_error);
    t << line;
  }
  t << "\n   r [mm]   sigma_r(0) sigma_phi(0)  sigma_r(90) sigma_phi(90)   [MPa]\n";
  for (std::size_t i = 0; i < r.r.size(); ++i) {
    std::snprintf(line, sizeof line, "  %7.4f %12.5g %12.5g %12.5g %12.5g\n", r.r[i] * 1e3,
                  r.sigma_r_0[i] / 1e6, r.sigma_phi_0[i] / 1e6, r.sigma_r_90[i] / 1e6,
                  r.sigma_phi_90[i] / 1e6);
    t << line;
  }
  for (const auto& d : r.diagnostics)
    t << "\n  " << to_string(d.severity) << " " << d.code << ": " << d.message;
  t << "\n";
  return t.str();
}

Record ring_describe(const RingAnalysis& a, const Inputs&) {
  const Result& r = a.result;
  Record rec;
  rec.data = ring_value(a);
  rec.diagnostics = r.diagnostics;
  rec.table = ring_table(a);
  rec.columns = {
      {"r", r.r},          {"sigma_r_0", r.sigma_r_0},   {"sigma_phi_0", r.sigma_phi_0},
      {"tau_0", r.tau_0},  {"sigma_r_90", r.sigma_r_90}, {"sigma_phi_90", r.sigma_phi_90},
      {"tau_90", r.tau_90}};
  // hoop stress across the two sections, and the contact pressure along the pin
  analysis::Chart c;
  c.title = "Hoop stress across the sections phi = 0 and phi = 90 deg";
  c.x_label = "r [mm]";
  c.y_label = "sigma_phi [MPa]";
  for (const auto& [key, sigma_phi] :
       {std::pair{"0", &r.sigma_phi_0}, std::pair{"90", &r.sigma_phi_90}}) {
    std::vector<double> x, y;
    for (double v : r.r) x.push_back(v * 1e3);
    for (double v : *sigma_phi) y.push_back(v * 1e-6);
    c.traces.push_back({std::string("phi = ") + key + " deg", x, y});
  }
  rec.charts.push_back(c);
  analysis::Chart p;
  p.title = "Contact pressure on the pin";
  p.x_label = "phi [deg]";
  p.y_label = "pressure [MPa]";
  std::vector<double> x, y;
  for (double v : r.contact_phi) x.push_back(v * 180.0 / std::numbers::pi);
  for (double v : r.contact_pressure) y.push_back(v * 1e-6);
  p.traces.push_back({"pressure", x, y});
  rec.charts.push_back(p);
  return rec;
}

analysis::Analysis make_ring() {
  using namespace analysis;
  using K = QuantityKind;
  Analysis a;
  a.name = "ring";
  a.command = {"ring"};
  a.title = "Fibre-reinforced polymer link: orthotropic ring on two rigid half-discs (seed 002)";
  a.help = a.title;
  a.seed = "002";
  a.docs = "docs/models/composite.md";
  a.chain_types = {"composite-link"};
  a.formats = {.table = true, .csv = true, .drawing = false};
  a.parameters = {
      quantity("inner_radius", K::kLength, "r1, the pin's (half-discs') radius") |
          Required{"r1, the pin's (half-discs') radius"},
      quantity("outer_radius", K::kLength, "r2 > r1, the ring's outer radius") |
          Required{"r2 > r1, the ring's outer radius"},
      quantity("thickness", K::kLength, "t, the ring's thickness (plane stress)") |
          Required{"t, the ring's thickness (plane stress)"},
      quantity("E_r", K::kStress, "radial Young's modulus E_r") |
          Required{"radial Young's modulus"},
      quantity("E_phi", K::kStress, "hoop (fibre) Young's modulus E_phi") |
          Required{"hoop (fibre) Young's modulus"},
      quantity("G", K::kStress, "in-plane shear modulus G_rphi") |
          Required{"in-plane shear modulus G_rphi"},
      number("nu_phi_r", "nu_phi_r = -eps_r/eps_phi under pure hoop stress") |
          Required{"nu_phi_r = -eps_r/eps_phi under pure hoop stress, a plain number"},
      quantity("gap", K::kLength, "the full opening 2*delta between the half-discs") |
          Required{"the full opening 2*delta between the half-discs"},
      integer("harmonics", 0,
              "highest even harmonic N (default 2*ceil(100/(1 - r1/r2)), at least 40)") |
          kHarmonicsWork,
      integer("nodes", 0, "sweep intervals m (default: h*N/alpha <= 0.1)") | kNodesWork,
      integer("points", 0, "output radii from r1 to r2, odd") | Default{"41"},
      choice("method", {"exact", "sweep"}, "exact (powers r^lambda) or sweep (the paper's)") |
          Default{"exact"},
      flag("unilateral", "let the ring separate where the half-disc would pull on it"),
      flag("field", "JSON: add the stresses over the quarter ring (91 angles x the output radii)"),
  };
  a.check = ring_check;
  set_functions<RingAnalysis>(a, ring_analysis_run, ring_describe);
  return a;
}

// =============================================================================================
// ring capacity

constexpr const char* kSource =
    "seed 002 eq. (9) and its example; micromechanics: rule of mixtures, Halpin-Tsai "
    "(Halpin & Kardos 1976; Jones, Mechanics of Composite Materials, 2nd ed. 1999, sec. 3.3-3.4)";

const std::vector<std::string> kRingKeys = {"E_r",      "E_phi",        "G",
                                            "nu_phi_r", "inner_radius", "outer_radius"};
const std::vector<std::string> kEq9Keys = {"alpha", "sum_sigma_r", "k_max"};

// The ring's elastic constants and radii given: α, Σσ̃_r and K come from a ring analysis.
bool analysed(const Inputs& in) {
  return std::any_of(kRingKeys.begin(), kRingKeys.end(),
                     [&](const std::string& key) { return in.given(key); });
}

// The ring the analysed mode solves: K and Σσ̃_r do not depend on t or the opening (linear
// problem), so both are fixed.
Ring capacity_ring(const Inputs& in) {
  Ring ring;
  ring.E_r = in.number("E_r");
  ring.E_phi = in.number("E_phi");
  ring.G = in.number("G");
  ring.nu_phi_r = in.number("nu_phi_r");
  ring.inner_radius = in.number("inner_radius");
  ring.outer_radius = in.number("outer_radius");
  ring.thickness = 1e-3;
  ring.gap = 1e-3 * ring.inner_radius;
  return ring;
}

// Issues are reported in the order the values are read: the mode's inputs, the strength, the
// area or load, the masses, then the model's checks.
void capacity_check(const Inputs& in, std::vector<Issue>& issues) {
  Ordered out(issues);
  const bool ring_mode = analysed(in);
  Options options;
  if (ring_mode) {
    for (const std::string& key : kEq9Keys)
      if (in.given(key))
        out.add({key, in.text(key),
                 "not with the elastic constants (α, Σσ̃_r and K then come from the ring "
                 "analysis)"});
    for (const std::string& key : kRingKeys)
      out.missing(in, key, "required with the ring's elastic constants");
    for (const std::string& key : kRingKeys) out.take(key);
    if (in.given("harmonics")) {
      out.take("harmonics");
      if (!out.reported("harmonics")) options.harmonics = in.integer("harmonics");
    }
  } else {
    for (const std::string& key : kEq9Keys)
      out.missing(in, key, "required (or give the ring's elastic constants and radii instead)");
    for (const std::string& key : kEq9Keys) out.take(key);
  }
  out.missing(in, "fibre_strength", "σ^a, the reinforcement's strength");
  out.take("fibre_strength");
  if (in.given("fibre_area") == in.given("load"))
    out.add({"fibre_area", in.given("fibre_area") ? in.text("fibre_area") : "(missing)",
             "exactly one of --fibre-area (gives P_max) and --load (gives the area)"});
  for (const char* key : {"fibre_area", "load", "steel_mass", "link_mass"}) out.take(key);
  const auto fibre_area = readable(in, "fibre_area");
  const auto load = readable(in, "load");
  const auto steel_mass = readable(in, "steel_mass");
  const auto link_mass = readable(in, "link_mass");
  if (steel_mass.has_value() != link_mass.has_value())
    out.add({steel_mass ? "link_mass" : "steel_mass", "(missing)",
             "--steel-mass and --link-mass go together (mass comparison)"});
  for (const auto& [key, v] :
       {std::pair{"steel_mass", steel_mass}, std::pair{"link_mass", link_mass}})
    if (v && !(*v > 0)) out.add({key, format_g(*v) + " kg", "a mass > 0 kg"});
  std::vector<Issue> model;
  if (ring_mode) {
    model = validate(capacity_ring(in));
    for (auto& i : validate(options)) model.push_back(i);
    check::finite_positive(model, "fibre_strength", in.number("fibre_strength"), "Pa");
  } else {
    Eq9 e;
    e.alpha = in.number("alpha");
    e.sum_sigma_r = in.number("sum_sigma_r");
    e.k_max = in.number("k_max");
    e.fibre_strength = in.number("fibre_strength");
    model = validate(e);
  }
  if (fibre_area) check::finite_positive(model, "fibre_area", *fibre_area, "m^2");
  if (load) check::finite_positive(model, "load", *load, "N");
  add_read_model_issues(out, model);
  out.finish();
}

Value capacity_value(const CapacityAnalysis& a) {
  const Eq9& e = a.eq9;
  Value j = Value::object();
  j["model"] = "composite.ring_capacity";
  j["source"] = kSource;
  j["mode"] = a.analysed ? "analysed" : "coefficients";
  j["alpha"] = e.alpha;
  j["sum_sigma_r"] = e.sum_sigma_r;
  j["k_max"] = e.k_max;
  j["fibre_strength"] = e.fibre_strength;
  j["fibre_area"] = a.fibre_area;
  j["load"] = a.load;
  j["eq9_factor"] = a.eq9_factor;
  j["load_concentration"] = a.load_concentration;
  j["load_uniform"] = a.load_uniform;
  j["consistent_sum_sigma_r"] = a.consistent_sum_sigma_r;
  if (a.analysed) {
    j["ring_sum_sigma_r"] = a.ring_sum_sigma_r;
    j["summary"] = Value::object({{"method", a.summary.method},
                                  {"harmonics", a.summary.harmonics},
                                  {"truncation_change", a.summary.truncation_change}});
  }
  if (a.steel_mass) {
    j["mass"] = Value::object({{"link", *a.link_mass},
                               {"steel", *a.steel_mass},
                               {"ratio", *a.steel_mass / *a.link_mass}});
  }
  j["units"] = analysis::units_value({{"alpha", "1"},
                                      {"sum_sigma_r", "1"},
                                      {"k_max", "1"},
                                      {"fibre_strength", "Pa"},
                                      {"fibre_area", "m^2"},
                                      {"load", "N"},
                                      {"eq9_factor", "1"},
                                      {"load_concentration", "N"},
                                      {"load_uniform", "N"},
                                      {"consistent_sum_sigma_r", "1"},
                                      {"ring_sum_sigma_r", "1"},
                                      {"mass", "kg"}});
  j["diagnostics"] = analysis::diagnostics_value(a.diagnostics);
  return j;
}

std::string capacity_table(const CapacityAnalysis& a) {
  const Eq9& e = a.eq9;
  std::ostringstream t;
  t << "Catena ring capacity: eq. (9) of seed 002, P = Σσ̃_r/(α(1−α)K)·2Fσ^a\n\n";
  t << "  alpha = r1/r2            " << format_g(e.alpha, 5) << "\n";
  t << "  sum sigma_r              " << format_g(e.sum_sigma_r, 5)
    << (a.analysed ? "  (α(1−α): the normalisation that makes (9) = 2Fσ^a/K)" : "") << "\n";
  if (a.analysed)
    t << "  ring's own sum sigma_r   " << format_g(a.ring_sum_sigma_r, 5) << "  ((1−α)/α)\n";
  t << "  K max                    " << format_g(e.k_max, 5) << "\n";
  t << "  fibre strength [MPa]     " << format_g(e.fibre_strength / 1e6, 6) << "\n";
  t << "  fibre area F [mm^2]      " << format_g(a.fibre_area * 1e6, 5)
    << (a.area_given ? "" : "  (sized)") << "\n";
  t << "  P max, eq. (9) [N]       " << format_g(a.load, 6) << "\n";
  t << "  2Fσ^a/K [N]              " << format_g(a.load_concentration, 6) << "\n";
  t << "  2Fσ^a [N]                " << format_g(a.load_uniform, 6) << "\n";
  if (a.steel_mass)
    t << "  mass: link " << format_g(*a.link_mass, 4) << " kg, steel " << format_g(*a.steel_mass, 4)
      << " kg, steel/link " << format_g(*a.steel_mass / *a.link_mass, 4) << "\n";
  for (const auto& d : a.diagnostics)
    t << "\n  " << to_string(d.severity) << ": " << d.message << "\n";
  return t.str();
}

Record capacity_describe(const CapacityAnalysis& a, const Inputs&) {
  Record rec;
  rec.data = capacity_value(a);
  rec.diagnostics = a.diagnostics;
  rec.table = capacity_table(a);
  return rec;
}

analysis::Analysis make_capacity() {
  using namespace analysis;
  using K = QuantityKind;
  Analysis a;
  a.name = "ring_capacity";
  a.command = {"ring", "capacity"};
  a.title = "Link capacity by eq. (9) of seed 002, and the mass comparison";
  a.help = a.title;
  a.seed = "002";
  a.docs = "docs/models/composite_capacity.md";
  a.chain_types = {"composite-link"};
  a.formats = {.table = true, .csv = false, .drawing = false};
  a.parameters = {
      number("alpha", "alpha = r1/r2 of eq. (9)") | Expects{"0 < α < 1"},
      number("sum_sigma_r", "Σσ̃_r of eq. (9) (the paper's normalisation)") |
          Expects{"a number > 0"},
      number("k_max", "K_σ^max of eq. (9)") | Expects{"a number ≥ 1"},
      quantity("fibre_strength", K::kStress, "σ^a, reinforcement strength") |
          Required{"σ^a, the reinforcement's strength"},
      quantity("fibre_area", K::kArea, "F, reinforcement area; or --load"),
      quantity("load", K::kForce, "P to size F for; or --fibre-area"),
      quantity("E_r", K::kStress, "instead of --alpha/--sum-sigma-r/--k-max: radial modulus"),
      quantity("E_phi", K::kStress, "hoop (fibre) modulus"),
      quantity("G", K::kStress, "shear modulus G_rφ"),
      number("nu_phi_r", "−ε_r/ε_φ under hoop stress") | Expects{"a ratio ≥ 0"},
      quantity("inner_radius", K::kLength, "r1"),
      quantity("outer_radius", K::kLength, "r2"),
      integer("harmonics", 2, "ring solver harmonics (default: converged)") | kHarmonicsWork,
      quantity("steel_mass", K::kMass, "steel link mass for the comparison"),
      quantity("link_mass", K::kMass, "composite link mass for the comparison"),
  };
  a.check = capacity_check;
  set_functions<CapacityAnalysis>(a, ring_capacity_analysis_run, capacity_describe);
  return a;
}

// =============================================================================================
// ring design

const std::vector<std::pair<std::string, std::string>> kDesignRequired = {
    {"load", "the required breaking force"},
    {"fibre_modulus", "required"},
    {"fibre_poisson", "required"},
    {"fibre_strength", "required"},
    {"fibre_density", "required"},
    {"matrix_modulus", "required"},
    {"matrix_poisson", "required"},
    {"matrix_density", "required"},
    {"fibre_fraction", "required"},
    {"thickness", "t, the band width (r2 follows from it)"},
    {"pitch", "p, the pin centre distance"}};

bool steel_given(const Inputs& in) {
  return in.given("steel_strength") || in.given("steel_thickness");
}

DesignInput design_input(const Inputs& in, bool harmonics_read) {
  DesignInput d;
  d.load = in.number("load");
  d.fibre.modulus = in.number("fibre_modulus");
  d.fibre.poisson = in.number("fibre_poisson");
  d.fibre.strength = in.number("fibre_strength");
  d.fibre.density = in.number("fibre_density");
  d.matrix.modulus = in.number("matrix_modulus");
  d.matrix.poisson = in.number("matrix_poisson");
  d.matrix.density = in.number("matrix_density");
  d.fibre_fraction = in.number("fibre_fraction");
  d.thickness = in.number("thickness");
  d.pitch = in.number("pitch");
  d.insert_density = in.number("insert_density");
  if (in.given("alpha")) d.alphas = in.list("alpha");
  if (steel_given(in)) {
    d.steel_strength = in.number("steel_strength");
    d.steel_thickness = in.number("steel_thickness");
    d.steel_density = in.number("steel_density");
  }
  if (in.given("harmonics") && harmonics_read) d.analysis.harmonics = in.integer("harmonics");
  return d;
}

// Every missing input first, then the values that could not be read, then the model's checks.
void design_check(const Inputs& in, std::vector<Issue>& issues) {
  Ordered out(issues);
  for (const auto& [key, expected] : kDesignRequired) out.missing(in, key, expected);
  for (const auto& [key, expected] : kDesignRequired) out.take(key);
  out.take("insert_density");
  out.take("alpha");
  if (steel_given(in)) {
    out.missing(in, "steel_strength", "with --steel-thickness");
    out.missing(in, "steel_thickness", "with --steel-strength");
    for (const char* key : {"steel_strength", "steel_thickness", "steel_density"}) out.take(key);
  }
  if (in.given("harmonics")) out.take("harmonics");
  add_read_model_issues(out, validate(design_input(in, !out.reported("harmonics"))));
  out.finish();
}

Value design_value(const DesignAnalysis& a) {
  const DesignInput& d = a.input;
  const Design& out = a.design;
  const Lamina& l = out.lamina;
  Value j = Value::object();
  j["model"] = "composite.ring_design";
  j["source"] = kSource;
  j["load"] = d.load;
  j["lamina"] = Value::object({{"fibre_fraction", l.fibre_fraction},
                               {"E_phi", l.E_phi},
                               {"E_r", l.E_r},
                               {"G", l.G},
                               {"nu_phi_r", l.nu_phi_r},
                               {"strength", l.strength},
                               {"density", l.density}});
  auto point = [&](const DesignPoint& p) {
    return Value::object(
        {{"alpha", p.alpha},
         {"k", p.k},
         {"sum_sigma_r", p.sum_sigma_r},
         {"inner_radius", p.inner_radius},
         {"outer_radius", p.outer_radius},
         {"thickness", d.thickness},
         {"leg_area", p.leg_area},
         {"fibre_area", p.fibre_area},
         {"mass", Value::object(
                      {{"band", p.mass.band}, {"insert", p.mass.insert}, {"total", p.mass.total}})},
         {"feasible", p.feasible}});
  };
  j["design"] = point(out.scan[out.best]);
  Value scan = Value::array();
  for (const auto& p : out.scan) scan.push_back(point(p));
  j["scan"] = std::move(scan);
  if (out.has_steel)
    j["steel"] = Value::object({{"net_area", out.steel.net_area},
                                {"width", out.steel.width},
                                {"thickness", d.steel_thickness},
                                {"face_area", out.steel.face_area},
                                {"mass", out.steel.mass},
                                {"mass_ratio", out.mass_ratio}});
  j["units"] = analysis::units_value(
      {{"load", "N"},      {"E_phi", "Pa"},       {"E_r", "Pa"},         {"G", "Pa"},
       {"strength", "Pa"}, {"density", "kg/m^3"}, {"inner_radius", "m"}, {"outer_radius", "m"},
       {"thickness", "m"}, {"leg_area", "m^2"},   {"fibre_area", "m^2"}, {"net_area", "m^2"},
       {"width", "m"},     {"face_area", "m^2"},  {"mass", "kg"},        {"alpha", "1"},
       {"k", "1"},         {"sum_sigma_r", "1"},  {"mass_ratio", "1"},   {"fibre_fraction", "1"},
       {"nu_phi_r", "1"}});
  j["diagnostics"] = analysis::diagnostics_value(out.diagnostics);
  return j;
}

std::string design_table(const DesignAnalysis& a) {
  const DesignInput& d = a.input;
  const Design& out = a.design;
  const Lamina& l = out.lamina;
  std::ostringstream t;
  t << "Catena ring design: fibre-wound link for P = " << format_g(d.load, 6) << " N\n\n";
  t << "  ring constants (V_f " << format_g(l.fibre_fraction, 3) << "): E_phi "
    << format_g(l.E_phi / 1e9, 4) << " GPa, E_r " << format_g(l.E_r / 1e9, 4) << " GPa, G "
    << format_g(l.G / 1e9, 4) << " GPa, nu_phi_r " << format_g(l.nu_phi_r, 3) << ", hoop strength "
    << format_g(l.strength / 1e6, 5) << " MPa, density " << format_g(l.density, 5) << " kg/m^3\n\n";
  t << "   alpha      K   r1 [mm]   r2 [mm]  A leg [mm^2]  F fibre [mm^2]  mass [g]\n";
  for (std::size_t i = 0; i < out.scan.size(); ++i) {
    const auto& p = out.scan[i];
    char line[200];
    std::snprintf(line, sizeof line, "  %6.3f %6.3f %9.4g %9.4g %13.4g %15.4g %9.4g%s\n", p.alpha,
                  p.k, p.inner_radius * 1e3, p.outer_radius * 1e3, p.leg_area * 1e6,
                  p.fibre_area * 1e6, p.mass.total * 1e3,
                  !p.feasible     ? "  pins overlap (p <= 2 r1)"
                  : i == out.best ? "  <- lightest"
                                  : "");
    t << line;
  }
  if (out.has_steel)
    t << "\n  steel plate: width " << format_g(out.steel.width * 1e3, 4) << " mm, thickness "
      << format_g(d.steel_thickness * 1e3, 4) << " mm, mass " << format_g(out.steel.mass * 1e3, 4)
      << " g; steel/composite " << format_g(out.mass_ratio, 4) << "\n";
  for (const auto& dg : out.diagnostics)
    t << "\n  " << to_string(dg.severity) << ": " << dg.message << "\n";
  return t.str();
}

Record design_describe(const DesignAnalysis& a, const Inputs&) {
  Record rec;
  rec.data = design_value(a);
  rec.diagnostics = a.design.diagnostics;
  rec.table = design_table(a);
  return rec;
}

analysis::Analysis make_design() {
  using namespace analysis;
  using K = QuantityKind;
  Analysis a;
  a.name = "ring_design";
  a.command = {"ring", "design"};
  a.title = "Size a fibre-wound link (r1, r2, mass) for a breaking force; steel comparison";
  a.help = a.title;
  a.seed = "002";
  a.docs = "docs/models/composite_capacity.md";
  a.chain_types = {"composite-link"};
  a.formats = {.table = true, .csv = false, .drawing = false};
  // Plain numbers that are required say "0 ≤ ν < 0.5" when unreadable and "required" when
  // missing: their missing issue comes from the check.
  a.parameters = {
      quantity("load", K::kForce, "required breaking force P") |
          Required{"the required breaking force"},
      quantity("fibre_modulus", K::kStress, "E_f, e.g. 72.4GPa") | Required{"required"},
      number("fibre_poisson", "ν_f (required)") | Expects{"0 ≤ ν < 0.5"},
      quantity("fibre_strength", K::kStress, "σ_f") | Required{"required"},
      quantity("fibre_density", K::kDensity, "ρ_f, e.g. 2.56g/cm^3") | Required{"required"},
      quantity("matrix_modulus", K::kStress, "E_m") | Required{"required"},
      number("matrix_poisson", "ν_m (required)") | Expects{"0 ≤ ν < 0.5"},
      quantity("matrix_density", K::kDensity, "ρ_m") | Required{"required"},
      number("fibre_fraction", "V_f (required)") | Expects{"0 < V_f ≤ 0.9069"},
      quantity("thickness", K::kLength, "t, band width; r2 follows") |
          Required{"t, the band width (r2 follows from it)"},
      quantity("pitch", K::kLength, "p, pin centre distance") |
          Required{"p, the pin centre distance"},
      quantity("insert_density", K::kDensity, "polyamide insert") | Default{"1130"},
      number("alpha", "r1/r2, one or a comma list (default 0.30..0.90 by 0.05)") |
          Expects{"0.05 ≤ α ≤ 0.95, or a comma list"} | ListOf{},
      quantity("steel_strength", K::kStress, "steel plate σ_B for the comparison"),
      quantity("steel_thickness", K::kLength, "steel plate thickness"),
      quantity("steel_density", K::kDensity, "steel plate density") | Default{"7850"},
      integer("harmonics", 2, "ring solver harmonics (default: converged)") | kHarmonicsWork,
  };
  a.check = design_check;
  set_functions<DesignAnalysis>(a, ring_design_analysis_run, design_describe);
  return a;
}

}  // namespace

// =============================================================================================

RingAnalysis ring_analysis_run(const analysis::Inputs& in) {
  RingAnalysis a;
  a.ring = ring_of(in);
  a.options = options_of(in);
  a.field = in.flag("field");
  a.result = analyse(a.ring, a.options);
  const Result& r = a.result;
  a.equilibrium_residual = std::abs(r.load - r.load_contact) / std::max(std::abs(r.load), 1e-300);
  return a;
}

CapacityAnalysis ring_capacity_analysis_run(const analysis::Inputs& in) {
  CapacityAnalysis a;
  a.analysed = analysed(in);
  Eq9& e = a.eq9;
  if (a.analysed) {
    const Ring ring = capacity_ring(in);
    Options options;
    if (in.given("harmonics")) options.harmonics = in.integer("harmonics");
    const Result res = analyse(ring, options);
    e.alpha = ring.inner_radius / ring.outer_radius;
    e.k_max = res.stress_concentration;
    e.sum_sigma_r = consistent_sum_sigma_r(e.alpha);
    a.ring_sum_sigma_r = res.sum_sigma_r;
    a.diagnostics = res.diagnostics;
    a.summary = res.summary;
  } else {
    e.alpha = in.number("alpha");
    e.sum_sigma_r = in.number("sum_sigma_r");
    e.k_max = in.number("k_max");
  }
  e.fibre_strength = in.number("fibre_strength");
  a.area_given = in.present("fibre_area");
  if (a.area_given == in.present("load"))
    throw InputError({{"fibre_area", a.area_given ? in.text("fibre_area") : "(missing)",
                       "exactly one of --fibre-area (gives P_max) and --load (gives the area)"}});
  if (in.present("steel_mass")) a.steel_mass = in.number("steel_mass");
  if (in.present("link_mass")) a.link_mass = in.number("link_mass");
  a.eq9_factor = eq9_factor(e);
  a.fibre_area = a.area_given ? in.number("fibre_area") : area_for_load(e, in.number("load"));
  a.load = capacity(e, a.fibre_area);
  a.load_concentration = capacity_from_concentration(a.fibre_area, e.fibre_strength, e.k_max);
  a.load_uniform = 2.0 * a.fibre_area * e.fibre_strength;
  a.consistent_sum_sigma_r = consistent_sum_sigma_r(e.alpha);
  if (a.eq9_factor > 1.0)
    a.diagnostics.push_back(
        {Diagnostic::Severity::kWarning, "ring.capacity.eq9_above_uniform_strength",
         "eq. (9) gives more than the uniform-stress strength 2Fσ^a: Σσ̃_r/(α(1−α)K) "
         "> 1 (value: that factor); check the normalisation of Σσ̃_r (with the mean "
         "stress of catena ring it is (1−α)/α and does not belong in eq. (9))",
         a.eq9_factor, 1.0});
  else if (a.eq9_factor * e.k_max > 1.0 + 1e-9)
    a.diagnostics.push_back(
        {Diagnostic::Severity::kInfo, "ring.capacity.eq9_above_concentration_capacity",
         "eq. (9) exceeds the capacity from the stress concentration, 2Fσ^a/K, by the "
         "factor Σσ̃_r/(α(1−α)); they agree when Σσ̃_r = α(1−α) (value: Σσ̃_r, limit: "
         "α(1−α))",
         e.sum_sigma_r, a.consistent_sum_sigma_r});
  return a;
}

DesignAnalysis ring_design_analysis_run(const analysis::Inputs& in) {
  DesignAnalysis a;
  a.input = design_input(in, true);
  a.design = design(a.input);
  return a;
}

const analysis::Analysis& ring_analysis() {
  static const analysis::Analysis a = make_ring();
  return a;
}

const analysis::Analysis& ring_capacity_analysis() {
  static const analysis::Analysis a = make_capacity();
  return a;
}

const analysis::Analysis& ring_design_analysis() {
  static const analysis::Analysis a = make_design();
  return a;
}

}  // namespace catena::composite
