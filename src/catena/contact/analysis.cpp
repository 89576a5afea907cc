// `contact` — roller–tooth contact with axis skew (seed 001, Harshniev & Maksymovych) — and
// `fretting` — latent period of fretting (seed 001, Vikulov eq. 1) — as analyses.
#include "catena/contact/analysis.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>
#include <string>

#include "catena/contact/chain_catalog.hpp"
#include "catena/io/quantity.hpp"

namespace catena::contact {
namespace {

using analysis::format_g;
using analysis::Inputs;
using analysis::Record;
using analysis::Value;

constexpr double kArcmin = std::numbers::pi / 10800.0;
constexpr int kMaxSlices = 20001;
constexpr double kMaxSliceWork = 2e6;     // slices × sweep points: a few seconds at most
constexpr double kMaxGaugeRatio = 500.0;  // |dh/B|: φ = arctg(500) = 89.885°

// ---------------------------------------------------------------------------------------------
// contact: inputs

// The chain of --chain, when given and in the catalogue.
std::optional<ChainDimensions> chain_of(const Inputs& in) {
  if (!in.given("chain")) return std::nullopt;
  return iso606_chain(in.text("chain"));
}

// A length given, or the chain's value, or NaN.
double length_or_chain(const Inputs& in, const char* key, std::optional<double> fallback) {
  if (in.given(key)) return in.number(key);
  return fallback.value_or(NAN);
}

double pitch_of(const Inputs& in, const std::optional<ChainDimensions>& chain) {
  return length_or_chain(in, "pitch",
                         chain ? std::optional<double>(chain->pitch) : std::optional<double>());
}

// --skew-sweep FROM:TO:STEP as three angles [rad]; issues named "skew_sweep".
std::optional<std::array<double, 3>> parse_sweep(const std::string& text,
                                                 std::vector<Issue>& issues) {
  std::array<double, 3> parts{};
  std::stringstream ss(text);
  std::string part;
  int k = 0;
  while (std::getline(ss, part, ':')) {
    if (k < 3)
      parts[k] = io::parse_quantity(part, QuantityKind::kAngle, "skew_sweep", issues).value_or(NAN);
    ++k;
  }
  constexpr double kRight = std::numbers::pi / 2;
  if (k != 3 || !(parts[2] > 0) || !(parts[1] >= parts[0]) || !(std::abs(parts[0]) < kRight) ||
      !(std::abs(parts[1]) < kRight) || (parts[1] - parts[0]) / parts[2] > 10000) {
    issues.push_back({"skew_sweep", text,
                      "FROM:TO:STEP, three angles, -90° < FROM ≤ TO < 90°, STEP > 0, at most "
                      "10000 steps"});
    return std::nullopt;
  }
  return parts;
}

// The rules across inputs, in the order the command always reported problems: the chain, the
// lengths it fills (or their absence), the materials, the load, the skew (one of --skew, the
// gauge readings, a sweep), K_φ, the sweep, γ (given or from the pitch's table), the slices.
// The binder's issues about each value are put at that value's place in this order.
void check_contact(const Inputs& in, std::vector<Issue>& issues) {
  std::vector<Issue> bound = std::move(issues);
  issues.clear();
  // issues about keys the table does not have come first, as the binder found them
  for (auto it = bound.begin(); it != bound.end();) {
    bool known = false;
    for (const analysis::Parameter& p : *in.parameters()) known = known || p.name == it->field;
    if (known) {
      ++it;
    } else {
      issues.push_back(std::move(*it));
      it = bound.erase(it);
    }
  }
  // the binder's issues about `key`, here (or dropped when `keep` is false)
  auto take = [&](std::string_view key, bool keep = true) {
    for (auto it = bound.begin(); it != bound.end();) {
      if (it->field != key) {
        ++it;
        continue;
      }
      if (keep) issues.push_back(std::move(*it));
      it = bound.erase(it);
    }
  };

  const std::optional<ChainDimensions> chain = chain_of(in);
  take("chain");
  if (in.given("chain") && !chain) {
    std::string names;
    for (const auto& n : iso606_names()) names += (names.empty() ? "" : ", ") + n;
    issues.push_back({"chain", in.text("chain"), "an ISO 606 chain of the catalogue: " + names});
  }
  auto length = [&](const char* key, std::optional<double> fallback) {
    take(key);
    if (in.given(key) || fallback) return;
    issues.push_back({key, "(missing)",
                      chain
                          ? std::string("a value (the catalogue has none for ") + chain->name + ")"
                          : std::string("a value (or --chain)")});
  };
  length("roller_diameter", chain ? chain->roller_diameter : std::nullopt);
  length("roller_length", chain ? chain->inner_width : std::nullopt);
  length("tooth_radius", std::nullopt);
  length("pitch", chain ? std::optional<double>(chain->pitch) : std::nullopt);
  for (const char* key :
       {"profile", "modulus", "poisson", "tooth_modulus", "tooth_poisson", "load"})
    take(key);

  const bool gauge = in.given("skew_gauge_dh") || in.given("skew_gauge_base");
  if (gauge && in.given("skew"))
    issues.push_back({"skew", in.text("skew"), "either --skew or the gauge readings, not both"});
  if (gauge) {
    take("skew", false);  // the gauge's skew is the one read
    // one problem per reading: a missing one is named as missing, not parsed as a unit
    const bool both = in.given("skew_gauge_dh") && in.given("skew_gauge_base");
    for (const char* key : {"skew_gauge_dh", "skew_gauge_base"}) {
      take(key);
      if (!in.given(key))
        issues.push_back({key, "(missing)",
                          std::string("a length with ") +
                              (std::string_view(key) == "skew_gauge_dh" ? "--skew-gauge-base"
                                                                        : "--skew-gauge-dh") +
                              ": the gauge's two readings give φ = arctg(dh/B)"});
    }
    const double dh = in.number("skew_gauge_dh"), base = in.number("skew_gauge_base");
    if (in.given("skew_gauge_base") && std::isfinite(base) && !(base > 0)) {
      issues.push_back({"skew_gauge_base", in.text("skew_gauge_base"), "a base B > 0"});
    } else if (both && std::isfinite(dh) && std::isfinite(base) &&
               !(std::abs(dh / base) <= kMaxGaugeRatio)) {
      // φ = arctg(dh/B) reaches 90° (or dh/B overflows): the reading, not --skew, is wrong
      issues.push_back({"skew_gauge_dh", in.text("skew_gauge_dh"),
                        "a reading |dh| ≤ " + format_g(kMaxGaugeRatio) +
                            "·B = " + format_g(kMaxGaugeRatio * base * 1e3) +
                            " mm (φ = arctg(dh/B) below 89.9°)"});
    }
  } else if (in.given("skew")) {
    take("skew");
  } else if (!in.given("skew_sweep")) {
    issues.push_back({"skew", "(missing)",
                      "the measured skew φ (e.g. 0.7deg, 0°42'), or --skew-gauge-dh with "
                      "--skew-gauge-base, or --skew-sweep (an aligned roller is --skew 0)"});
  }
  if (in.given("skew_sweep") && (gauge || in.given("skew")))
    issues.push_back({"skew_sweep", in.text("skew_sweep"),
                      "either a sweep or one skew (--skew or the gauge), not both"});

  take("skew_factor");
  const double skew_factor = in.number("skew_factor");
  if (!(skew_factor > 0 && skew_factor <= 1))
    issues.push_back({"skew_factor", in.text("skew_factor"), "K_φ in (0, 1]"});

  take("skew_sweep");
  std::optional<std::array<double, 3>> sweep;
  if (in.given("skew_sweep")) sweep = parse_sweep(in.text("skew_sweep"), issues);

  take("gamma");
  const double pitch = pitch_of(in, chain);
  const auto table = skew_gamma(pitch);
  if (in.given("gamma")) {
    // the paper's γ are 0.0012–0.0023 per arcmin²; above 1 the reduced load Q(1 + γφ²)
    // overflows for extreme inputs (issue 18) long before a design could need it
    const double gamma = in.number("gamma");
    if (!(gamma >= 0)) issues.push_back({"gamma", in.text("gamma"), "γ ≥ 0"});
    if (gamma > 1)
      issues.push_back(
          {"gamma", in.text("gamma"), "γ ≤ 1 per arcmin² (the paper's are 0.0012–0.0023)"});
  } else if (!table && std::isfinite(pitch) && chain && !in.given("pitch")) {
    // a catalogued chain whose pitch the paper's table lacks: say so, name the chain
    issues.push_back(
        {"gamma", "(missing)",
         "γ of eq. (2) for " + chain->name + " (p = " + format_g(pitch * 1e3) +
             " mm): the paper measured γ only for p = 12.7, 15.875, 19.05 and 25.4 mm and "
             "Catena does not extrapolate it; give --gamma [1/arcmin²] from a source"});
  } else if (!table && std::isfinite(pitch)) {  // a bad pitch is reported already
    issues.push_back(
        {"pitch", format_g(pitch * 1e3) + " mm",
         "a pitch of the paper's γ table (12.7, 15.875, 19.05, 25.4 mm), or γ given with --gamma "
         "(no extrapolation)"});
  }

  // a chain's rollers sit one pitch apart: a roller as large as the pitch cannot be
  const double roller = length_or_chain(in, "roller_diameter",
                                        chain ? chain->roller_diameter : std::optional<double>());
  if (std::isfinite(roller) && std::isfinite(pitch) && roller > 0 && pitch > 0 && !(roller < pitch))
    issues.push_back({"roller_diameter", format_g(roller * 1e3) + " mm",
                      "a roller diameter D_p < the pitch p = " + format_g(pitch * 1e3) +
                          " mm (neighbouring rollers would overlap)"});

  take("slices");
  const int slices = in.integer("slices");
  if (slices > kMaxSlices) {
    issues.push_back(
        {"slices", in.text("slices"), "3 … " + std::to_string(kMaxSlices) + " slices"});
  } else if (sweep && slices * ((*sweep)[1] - (*sweep)[0]) / (*sweep)[2] > kMaxSliceWork) {
    issues.push_back({"slices", in.text("slices"),
                      "at most " + format_g(kMaxSliceWork) +
                          " slices × sweep points in all: fewer slices or a "
                          "coarser --skew-sweep"});
  }
  for (Issue& issue : bound) issues.push_back(std::move(issue));  // none expected
}

// ---------------------------------------------------------------------------------------------
// contact: physics

// The paper's effective load and stress at one measured skew, and the slice model at the
// design skew φ·K_φ (`slices` when already solved).
SkewPoint at_skew(const ContactAnalysis& a, double skew, const SliceResult* slices) {
  SkewPoint p;
  p.skew = skew;
  p.load_factor = load_factor(a.gamma, skew, a.skew_factor);
  p.effective_load = a.load * p.load_factor;
  p.paper_stress = paper_stress(p.effective_load, a.contact.roller.modulus, a.contact.roller_length,
                                reduced_radius(a.contact));
  p.hertz_effective = hertz(a.contact, p.effective_load).peak_pressure;
  const SliceResult s =
      slices ? *slices
             : slice_model(a.contact, a.load, skew * a.skew_factor, SliceOptions{a.slices});
  p.slice_peak = s.stress_peak;
  p.slice_length = s.loaded_length;
  return p;
}

// ---------------------------------------------------------------------------------------------
// contact: description

Value sweep_value(const ContactAnalysis& a) {
  auto column = [&](double SkewPoint::*member) {
    std::vector<double> v;
    for (const SkewPoint& row : a.rows) v.push_back(row.*member);
    return Value(v);
  };
  Value j = Value::object();
  j["skew"] = column(&SkewPoint::skew);
  j["load_factor"] = column(&SkewPoint::load_factor);
  j["effective_load"] = column(&SkewPoint::effective_load);
  j["contact_stress"] = column(&SkewPoint::paper_stress);
  j["hertz_stress"] = column(&SkewPoint::hertz_effective);
  j["slice_stress_peak"] = column(&SkewPoint::slice_peak);
  j["slice_loaded_length"] = column(&SkewPoint::slice_length);
  j["units"] = analysis::units_value({{"skew", "rad"},
                                      {"load_factor", "1"},
                                      {"effective_load", "N"},
                                      {"contact_stress", "Pa"},
                                      {"hertz_stress", "Pa"},
                                      {"slice_stress_peak", "Pa"},
                                      {"slice_loaded_length", "m"}});
  return j;
}

std::string sweep_table(const ContactAnalysis& a) {
  std::ostringstream out;
  out << "Catena contact: stress versus skew (seed 001 eqs. 1-3 and the slice model)\n\n"
         "  skew [arcmin]   Q/Qnom   sigma eq.3 [MPa]  paper factor  slice peak [MPa]  "
         "slice factor  loaded [mm]\n";
  for (const SkewPoint& p : a.rows) {
    char line[256];
    std::snprintf(line, sizeof line, "  %13.4g %8.4g %18.5g %13.4g %17.5g %13.4g %12.4g\n",
                  p.skew / kArcmin, p.load_factor, p.paper_stress / 1e6, std::sqrt(p.load_factor),
                  p.slice_peak / 1e6, p.slice_peak / a.nominal.peak_pressure, p.slice_length * 1e3);
    out << line;
  }
  return out.str();
}

Value skew_value(const ContactAnalysis& a) {
  const SliceResult& s = a.slice;
  Value j = Value::object();
  j["model"] = "contact.roller_tooth_skew";
  j["source"] = "001 Harshniev & Maksymovych eqs. (1)-(3); Johnson (1985) for Hertz";
  j["reduced_radius"] = reduced_radius(a.contact);
  j["gamma"] = a.gamma;
  j["skew"] = a.skew;
  j["design_skew"] = a.design_skew;
  j["load_factor"] = a.point.load_factor;
  j["effective_load"] = a.point.effective_load;
  j["contact_stress"] = a.point.paper_stress;
  j["hertz_stress"] = a.effective.peak_pressure;
  j["hertz_stress_nominal"] = a.nominal.peak_pressure;
  j["half_width"] = a.effective.half_width;
  j["max_shear"] = a.effective.max_shear;
  j["max_shear_depth"] = a.effective.max_shear_depth;
  j["slice_model"] =
      Value::object({{"stress_peak", s.stress_peak},
                     {"stress_factor", s.stress_peak / a.nominal.peak_pressure},
                     {"loaded_length", s.loaded_length},
                     {"peak_half_width", s.peak_half_width},
                     {"approach", s.approach},
                     {"load_sum", s.load_sum},
                     {"distribution", Value::object({{"s", Value(s.s)}, {"q", Value(s.q)}})}});
  j["diagnostics"] = analysis::diagnostics_value(a.diagnostics);
  j["units"] = analysis::units_value({{"reduced_radius", "m"},
                                      {"gamma", "1/arcmin^2"},
                                      {"skew", "rad"},
                                      {"design_skew", "rad"},
                                      {"load_factor", "1"},
                                      {"effective_load", "N"},
                                      {"contact_stress", "Pa"},
                                      {"hertz_stress", "Pa"},
                                      {"hertz_stress_nominal", "Pa"},
                                      {"half_width", "m"},
                                      {"max_shear", "Pa"},
                                      {"max_shear_depth", "m"},
                                      {"stress_peak", "Pa"},
                                      {"stress_factor", "1"},
                                      {"loaded_length", "m"},
                                      {"peak_half_width", "m"},
                                      {"approach", "m"},
                                      {"load_sum", "N"},
                                      {"s", "m"},
                                      {"q", "N/m"}});
  return j;
}

std::string skew_table(const ContactAnalysis& a) {
  const SliceResult& s = a.slice;
  const HertzResult& eff = a.effective;
  std::ostringstream out;
  char line[256];
  auto row = [&](const char* label, const std::string& v) {
    std::snprintf(line, sizeof line, "  %-46s %s\n", label, v.c_str());
    out << line;
  };
  out << "Catena contact: roller on sprocket tooth with axis skew (seed 001)\n\n";
  row("reduced radius rho [mm]", format_g(reduced_radius(a.contact) * 1e3));
  row("skew measured / design (K_phi) [arcmin]",
      format_g(a.skew / kArcmin) + " / " + format_g(a.design_skew / kArcmin));
  row("gamma of eq. (2) [1/arcmin^2]", format_g(a.gamma));
  row("load factor Q_n/Q_nom (eq. 2)", format_g(a.point.load_factor));
  row("contact stress eq. (3), 0.418 [MPa]", format_g(a.point.paper_stress / 1e6));
  row("Hertz stress at Q_n / at Q_nom [MPa]",
      format_g(eff.peak_pressure / 1e6) + " / " + format_g(a.nominal.peak_pressure / 1e6));
  row("half-width b at Q_n [mm]", format_g(eff.half_width * 1e3));
  row("max shear 0.300 p0 at depth 0.786 b [MPa, mm]",
      format_g(eff.max_shear / 1e6) + ", " + format_g(eff.max_shear_depth * 1e3));
  row("slice model: peak stress [MPa]", format_g(s.stress_peak / 1e6));
  row("slice model: stress factor vs aligned", format_g(s.stress_peak / a.nominal.peak_pressure));
  row("paper: stress factor sqrt(Q_n/Q_nom)", format_g(std::sqrt(a.point.load_factor)));
  row("slice model: loaded length [mm]",
      format_g(s.loaded_length * 1e3) + " of " + format_g(a.contact.roller_length * 1e3));
  row("slice model: loaded length / peak half-width",
      format_g(s.loaded_length / s.peak_half_width, 3) +
          (a.short_patch ? "  (< 5: a short patch, the strip model is rough here)" : ""));
  return out.str();
}

Record describe_contact(const ContactAnalysis& a, const Inputs&) {
  Record rec;
  if (a.sweep) {
    rec.data = sweep_value(a);
    rec.table = sweep_table(a);
    const Value& r = rec.data;
    for (const char* key : {"skew", "load_factor", "effective_load", "contact_stress",
                            "hertz_stress", "slice_stress_peak", "slice_loaded_length"})
      rec.columns.push_back({key, r.at(key).numbers()});
    rec.charts.push_back(analysis::series_chart(r, r, "Contact stress versus skew", "skew",
                                                {"contact_stress", "slice_stress_peak"}, "stress"));
  } else {
    rec.data = skew_value(a);
    rec.diagnostics = a.diagnostics;
    rec.table = skew_table(a);
    rec.columns = {{"s", a.slice.s}, {"q", a.slice.q}};
    const Value& r = rec.data;
    rec.charts.push_back(analysis::series_chart(r, r.at("slice_model").at("distribution"),
                                                "Slice model: load along the roller", "s", {"q"},
                                                "q"));
  }
  return rec;
}

analysis::Analysis make_contact() {
  using namespace analysis;
  using K = QuantityKind;
  Analysis a;
  a.name = "contact";
  a.command = {"contact"};
  a.title = "Roller–sprocket tooth contact with axis skew (seed 001)";
  a.help = "Roller-sprocket tooth contact with axis skew (seed 001)";
  a.seed = "001";
  a.docs = "docs/models/contact.md";
  a.chain_types = {"roller-iso606"};
  a.formats = {.table = true, .csv = true, .drawing = false};
  a.parameters = {
      text("chain", "ISO 606 chain (e.g. 12B): fills pitch, roller diameter and length"),
      quantity("roller_diameter", K::kLength, "D_p (--chain fills d1)"),
      quantity("roller_length", K::kLength, "L_p (--chain fills b1, the inner width)"),
      quantity("tooth_radius", K::kLength, "r1, flank profile radius in the contact zone"),
      quantity("pitch", K::kLength, "chain pitch, selects gamma (--chain fills p)"),
      choice("profile", {"concave", "convex"}, "tooth flank") | Default{"concave"},
      quantity("modulus", K::kStress, "E of the roller, and of the tooth") | Default{"210GPa"},
      number("poisson", "nu of the roller, and of the tooth") | Default{"0.3"},
      quantity("tooth_modulus", K::kStress, "E of the tooth (default: --modulus)"),
      number("tooth_poisson", "nu of the tooth (default: --poisson)"),
      quantity("load", K::kForce, "nominal load Q_nom on the roller") |
          Required{"the nominal load Q_nom on the roller"},
      quantity("skew", K::kAngle, "measured skew phi (0.7deg, 42arcmin, 0°42')"),
      quantity("skew_gauge_dh", K::kLength, "gauge reading dh: phi = arctg(dh/B)"),
      quantity("skew_gauge_base", K::kLength, "gauge base B"),
      text("skew_sweep", "FROM:TO:STEP, e.g. 0deg:4deg:0.1deg: table versus skew"),
      number("skew_factor", "K_phi (0.6-0.7 for a worn chain)") | Default{"1"},
      number("gamma", "gamma of eq. (2) [1/arcmin^2] for a pitch outside the paper's table"),
      integer("slices", 3, "slices of the slice model") | Default{"201"},
  };
  // the messages of unreadable numbers
  for (Parameter& p : a.parameters) {
    if (p.name == "poisson" || p.name == "tooth_poisson") p.expected = "a number 0 ≤ ν < 0.5";
    if (p.name == "skew_factor") p.expected = "K_φ, a number in (0, 1]";
    if (p.name == "gamma") p.expected = "γ ≥ 0 of eq. (2)";
  }
  a.check = check_contact;
  set_functions<ContactAnalysis>(a, contact_analysis_run, describe_contact);
  return a;
}

// ---------------------------------------------------------------------------------------------
// fretting

Record describe_fretting(const FrettingAnalysis& a, const Inputs&) {
  Record rec;
  rec.data = Value::object(
      {{"model", "contact.fretting_latent_period"},
       {"source", "001 Vikulov eq. (1)"},
       {"latent_period", a.latent_period},
       {"exponent", a.exponent},
       {"cycles", a.cycles},
       {"units",
        analysis::units_value({{"latent_period", "s"}, {"exponent", "1"}, {"cycles", "1"}})}});
  rec.table =
      "Catena fretting: latent period (seed 001, Vikulov eq. 1)\n\n  latent period tau [s]   " +
      format_g(a.latent_period) + " (" + format_g(a.latent_period / 3600) + " h, " +
      format_g(a.cycles) + " cycles)\n  exponent K2 A N f / Ra  " + format_g(a.exponent) + "\n";
  rec.columns = {
      {"latent_period", {a.latent_period}}, {"exponent", {a.exponent}}, {"cycles", {a.cycles}}};
  return rec;
}

analysis::Analysis make_fretting() {
  using namespace analysis;
  using K = QuantityKind;
  Analysis a;
  a.name = "fretting";
  a.command = {"fretting"};
  a.title = "Fretting latent period of multi-strand chain joints (seed 001)";
  a.help = "Latent period of fretting in multi-strand chain fits (seed 001)";
  a.seed = "001";
  a.docs = "docs/models/fretting.md";
  a.chain_types = {"roller-iso606"};
  a.formats = {.table = true, .csv = true, .drawing = false};
  a.parameters = {
      quantity("roughness", K::kLength, "Ra, arithmetic mean roughness (e.g. 0.8um)") | Required{},
      quantity("amplitude", K::kLength, "A, amplitude of relative slip") | Required{},
      quantity("load", K::kForce, "N, normal load") | Required{},
      quantity("frequency", K::kFrequency, "f, vibration frequency (20Hz)") | Required{},
      number("k1", "K1 [s/m], empirical") |
          Required{"K1 in s/m (SI number), empirical: no default"},
      number("k2", "K2 [s/N] < 0, empirical") |
          Required{"K2 in s/N (SI number), empirical: no default"},
  };
  set_functions<FrettingAnalysis>(a, fretting_analysis_run, describe_fretting);
  return a;
}

}  // namespace

ContactAnalysis contact_analysis_run(const analysis::Inputs& in) {
  ContactAnalysis a;
  const std::optional<ChainDimensions> chain = chain_of(in);
  a.contact.roller_diameter =
      length_or_chain(in, "roller_diameter", chain ? chain->roller_diameter : std::nullopt);
  a.contact.roller_length =
      length_or_chain(in, "roller_length", chain ? chain->inner_width : std::nullopt);
  a.contact.tooth_radius = length_or_chain(in, "tooth_radius", std::nullopt);
  a.pitch = pitch_of(in, chain);
  a.contact.profile = in.text("profile") == "convex" ? Profile::kConvex : Profile::kConcave;
  a.contact.roller = a.contact.tooth = Elastic{in.number("modulus"), in.number("poisson")};
  if (in.given("tooth_modulus")) a.contact.tooth.modulus = in.number("tooth_modulus");
  if (in.given("tooth_poisson")) a.contact.tooth.poisson = in.number("tooth_poisson");
  a.load = in.number("load");
  if (in.given("skew_gauge_dh") || in.given("skew_gauge_base")) {
    a.skew = skew_from_gauge(in.number("skew_gauge_dh"), in.number("skew_gauge_base"));
  } else if (in.given("skew")) {
    a.skew = in.number("skew");
  }
  a.skew_factor = in.number("skew_factor");
  if (in.given("skew_sweep")) {
    std::vector<Issue> issues;  // reported by check
    a.sweep = parse_sweep(in.text("skew_sweep"), issues);
  }
  a.gamma = in.given("gamma") ? in.number("gamma") : skew_gamma(a.pitch).value_or(NAN);
  a.slices = in.integer("slices");

  std::vector<Issue> issues = validate(a.contact);
  if (!(a.load > 0)) issues.push_back({"load", in.text("load"), "a load > 0"});
  if (!std::isfinite(a.skew) || std::abs(a.skew) >= std::numbers::pi / 2)
    issues.push_back({"skew", in.text("skew"), "|φ| < 90°"});
  throw_if_any(issues);

  a.nominal = hertz(a.contact, a.load);
  if (a.sweep) {
    const auto [from, to, step] = *a.sweep;
    const int n = static_cast<int>(std::floor((to - from) / step + 1e-9)) + 1;
    for (int i = 0; i < n; ++i) a.rows.push_back(at_skew(a, from + i * step, nullptr));
  } else {
    a.design_skew = a.skew * a.skew_factor;
    a.slice = slice_model(a.contact, a.load, a.design_skew, SliceOptions{a.slices});
    a.point = at_skew(a, a.skew, &a.slice);
    a.effective = hertz(a.contact, a.point.effective_load);
    a.short_patch = a.slice.loaded_length < 5 * a.slice.peak_half_width;
    if (a.short_patch) {
      const double ratio = a.slice.loaded_length / a.slice.peak_half_width;
      a.diagnostics.push_back(
          {Diagnostic::Severity::kInfo, "contact.short_patch",
           "the loaded length is " + format_g(ratio, 3) +
               " peak half-widths (< 5): a short patch, the slice (strip) model is rough here",
           ratio, 5.0});
    }
  }
  return a;
}

FrettingAnalysis fretting_analysis_run(const analysis::Inputs& in) {
  FrettingAnalysis a;
  Fretting& m = a.fretting;
  m.roughness = in.number("roughness");
  m.amplitude = in.number("amplitude");
  m.load = in.number("load");
  m.frequency = in.number("frequency");
  m.k1 = in.number("k1");
  m.k2 = in.number("k2");
  throw_if_any(validate(m));
  a.latent_period = latent_period(m);
  a.exponent = m.k2 * m.amplitude * m.load * m.frequency / m.roughness;
  a.cycles = a.latent_period * m.frequency;
  return a;
}

const analysis::Analysis& contact_analysis() {
  static const analysis::Analysis a = make_contact();
  return a;
}

const analysis::Analysis& fretting_analysis() {
  static const analysis::Analysis a = make_fretting();
  return a;
}

}  // namespace catena::contact
