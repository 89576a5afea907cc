// `sprocket` — the ISO 606 sprocket tooth form — as an analysis.
#include "catena/drive/analysis.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

#include "catena/contact/chain_catalog.hpp"

namespace catena::drive {
namespace {

using analysis::format_g;
using analysis::Inputs;
using analysis::Record;
using analysis::Value;

constexpr double kTwelveSeven = 12.7e-3;  // [m] the pitch above which bf1 = 0.95 b1

std::optional<contact::ChainDimensions> chain_of(const Inputs& in) {
  if (!in.given("chain")) return std::nullopt;
  return contact::iso606_chain(in.text("chain"));
}

// A length given, or the catalogue's, or nothing.
std::optional<double> length(const Inputs& in, const char* key, std::optional<double> fallback) {
  if (in.given(key)) return in.number(key);
  return fallback;
}

void check_sprocket(const Inputs& in, std::vector<Issue>& issues) {
  const auto chain = chain_of(in);
  if (in.given("chain") && !chain) {
    std::string names;
    for (const auto& n : contact::iso606_names()) names += (names.empty() ? "" : ", ") + n;
    issues.push_back({"chain", in.text("chain"), "an ISO 606 chain of the catalogue: " + names});
    return;  // the lengths it would fill are not missing
  }
  auto need = [&](const char* key, std::optional<double> fallback) {
    if (in.given(key) || fallback) return;
    issues.push_back({key, "(missing)",
                      chain
                          ? std::string("a value (the catalogue has none for ") + chain->name + ")"
                          : std::string("a value (or --chain)")});
  };
  need("pitch", chain ? std::optional<double>(chain->pitch) : std::nullopt);
  need("roller_diameter", chain ? chain->roller_diameter : std::nullopt);
  need("inner_width", chain ? chain->inner_width : std::nullopt);
}

std::string mm(double v) { return format_g(v * 1e3); }
std::string deg(double v) { return format_g(v * 180 / std::numbers::pi); }

Value min_max(double lo, double hi) { return Value::object({{"min", lo}, {"max", hi}}); }

Value form_value(const GapForm& f) {
  return Value::object({{"seating_radius", f.seating_radius},
                        {"seating_angle", f.seating_angle},
                        {"flank_radius", f.flank_radius},
                        {"flank_meeting_diameter", f.flank_meeting_diameter},
                        {"outline_tip_diameter", f.outline_tip_diameter},
                        {"flanks_meet_below_tip", f.flanks_meet_below_tip}});
}

Value sprocket_value(const SprocketAnalysis& a) {
  const Sprocket& s = a.sprocket;
  const SprocketInput& in = s.input;
  Value j = Value::object();
  j["model"] = "drive.sprocket_iso606";
  j["source"] = "ISO 606 tooth-gap form (docs/models/sprocket.md)";
  j["chain"] = a.chain.empty() ? Value() : Value(a.chain);
  j["pitch"] = in.pitch;
  j["roller_diameter"] = in.roller_diameter;
  j["inner_width"] = in.inner_width;
  j["teeth"] = in.teeth;
  j["strands"] = in.strands;
  j["transverse_pitch"] = Value(in.transverse_pitch);
  j["pitch_diameter"] = s.pitch_diameter;
  j["root_diameter"] = s.root_diameter;
  j["seat_diameter"] = min_max(s.seat_diameter_min, s.seat_diameter_max);
  j["tip_diameter"] = min_max(s.tip_diameter_min, s.tip_diameter_max);
  j["seating_radius"] = min_max(s.seating_radius_min, s.seating_radius_max);
  j["seating_angle"] = min_max(s.seating_angle_min, s.seating_angle_max);
  j["flank_radius"] = min_max(s.flank_radius_min, s.flank_radius_max);
  j["tooth_width"] = Value(s.tooth_width);
  j["strand_width"] = Value(s.strand_width);
  j["side_radius"] = s.side_radius;
  j["side_relief"] = min_max(s.side_relief_min, s.side_relief_max);
  j["measurement_over_pins"] = s.measurement_over_pins;
  j["forms"] =
      Value::object({{"min_gap", form_value(s.min_gap)}, {"max_gap", form_value(s.max_gap)}});
  j["diagnostics"] = analysis::diagnostics_value(a.diagnostics);
  j["units"] = analysis::units_value({{"pitch", "m"},
                                      {"roller_diameter", "m"},
                                      {"inner_width", "m"},
                                      {"teeth", "1"},
                                      {"strands", "1"},
                                      {"transverse_pitch", "m"},
                                      {"pitch_diameter", "m"},
                                      {"root_diameter", "m"},
                                      {"seat_diameter", "m"},
                                      {"tip_diameter", "m"},
                                      {"seating_radius", "m"},
                                      {"seating_angle", "rad"},
                                      {"flank_radius", "m"},
                                      {"tooth_width", "m"},
                                      {"strand_width", "m"},
                                      {"side_radius", "m"},
                                      {"side_relief", "m"},
                                      {"measurement_over_pins", "m"},
                                      {"flank_meeting_diameter", "m"},
                                      {"outline_tip_diameter", "m"}});
  return j;
}

std::string sprocket_table(const SprocketAnalysis& a) {
  const Sprocket& s = a.sprocket;
  std::ostringstream out;
  auto row = [&](const std::string& label, const std::string& v) {
    // padded by characters, not bytes ("…" is three bytes)
    std::size_t width = 0;
    for (char c : label) width += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
    out << "  " << label << std::string(width < 48 ? 48 - width : 1, ' ') << v << "\n";
  };
  auto range = [&](double lo, double hi, std::string (*f)(double)) {
    return f(lo) + " … " + f(hi);
  };
  out << "Catena sprocket: ISO 606 tooth form, "
      << (a.chain.empty() ? std::string("p ") + mm(s.input.pitch) + " mm" : a.chain) << ", z "
      << s.input.teeth
      << (s.input.strands > 1 ? ", " + std::to_string(s.input.strands) + " strands" : "") << "\n\n";
  row("pitch diameter d [mm]", mm(s.pitch_diameter));
  row("root diameter df = d - d1 [mm]", mm(s.root_diameter));
  row("seat diameter d - 2 ri, min … max [mm]",
      range(s.seat_diameter_min, s.seat_diameter_max, mm));
  row("tip diameter da, min … max [mm]", range(s.tip_diameter_min, s.tip_diameter_max, mm));
  row("seating radius ri, min … max [mm]", range(s.seating_radius_min, s.seating_radius_max, mm));
  row("seating angle alpha, min … max [deg]", range(s.seating_angle_min, s.seating_angle_max, deg));
  row("flank radius re, min … max [mm]", range(s.flank_radius_min, s.flank_radius_max, mm));
  row("tooth width bf1 [mm]", s.tooth_width ? mm(*s.tooth_width) : "— (see diagnostics)");
  if (s.input.strands > 1)
    row("width over the strands bf [mm]",
        s.strand_width ? mm(*s.strand_width) : "— (see diagnostics)");
  row("tooth side radius rx [mm]", mm(s.side_radius));
  row("side relief ba, min … max [mm]", range(s.side_relief_min, s.side_relief_max, mm));
  row("measurement over pins MR [mm]", mm(s.measurement_over_pins));
  row("min gap form: flanks meet at / outline tip [mm]",
      mm(s.min_gap.flank_meeting_diameter) + " / " + mm(s.min_gap.outline_tip_diameter));
  row("max gap form: flanks meet at / outline tip [mm]",
      mm(s.max_gap.flank_meeting_diameter) + " / " + mm(s.max_gap.outline_tip_diameter));
  for (const Diagnostic& d : a.diagnostics)
    out << "\n  " << to_string(d.severity) << " " << d.code << ": " << d.message;
  if (!a.diagnostics.empty()) out << "\n";
  return out.str();
}

Polyline circle(const char* layer, double radius, unsigned rgb, double width) {
  Polyline p{layer, {}, true, width, rgb};
  constexpr int kPoints = 720;
  for (int i = 0; i < kPoints; ++i) {
    const double t = 2 * std::numbers::pi * i / kPoints;
    p.points.emplace_back(radius * std::cos(t), radius * std::sin(t));
  }
  return p;
}

Record describe_sprocket(const SprocketAnalysis& a, const Inputs&) {
  Record rec;
  rec.data = sprocket_value(a);
  rec.diagnostics = a.diagnostics;
  rec.table = sprocket_table(a);
  const Sprocket& s = a.sprocket;
  auto optional = [](const std::optional<double>& v) { return v.value_or(NAN); };
  rec.columns = {
      {"teeth", {static_cast<double>(s.input.teeth)}},
      {"pitch_diameter", {s.pitch_diameter}},
      {"root_diameter", {s.root_diameter}},
      {"seat_diameter_min", {s.seat_diameter_min}},
      {"seat_diameter_max", {s.seat_diameter_max}},
      {"tip_diameter_min", {s.tip_diameter_min}},
      {"tip_diameter_max", {s.tip_diameter_max}},
      {"seating_radius_min", {s.seating_radius_min}},
      {"seating_radius_max", {s.seating_radius_max}},
      {"seating_angle_min", {s.seating_angle_min}},
      {"seating_angle_max", {s.seating_angle_max}},
      {"flank_radius_min", {s.flank_radius_min}},
      {"flank_radius_max", {s.flank_radius_max}},
      {"tooth_width", {optional(s.tooth_width)}, 12, true},
      {"strand_width", {optional(s.strand_width)}, 12, true},
      {"side_radius", {s.side_radius}},
      {"measurement_over_pins", {s.measurement_over_pins}},
      {"min_gap_outline_tip_diameter", {s.min_gap.outline_tip_diameter}},
      {"max_gap_outline_tip_diameter", {s.max_gap.outline_tip_diameter}},
  };
  rec.drawings.push_back(sprocket_drawing(s));
  return rec;
}

analysis::Analysis make_sprocket() {
  using namespace analysis;
  using K = QuantityKind;
  Analysis a;
  a.name = "sprocket";
  a.command = {"sprocket"};
  a.title = "Sprocket tooth form to ISO 606: diameters, gap forms, width, drawing";
  a.help =
      "ISO 606 sprocket tooth form: pitch, root, seat and tip diameters, the minimum and "
      "maximum tooth-gap forms, tooth width, measurement over pins; --svg/--dxf draw both forms";
  a.seed = "ISO 606";
  a.docs = "docs/models/sprocket.md";
  a.chain_types = {"roller-iso606"};
  a.formats = {.table = true, .csv = true, .drawing = true};
  a.parameters = {
      text("chain", "ISO 606 chain (e.g. 12B): fills p, d1, b1 (and pt where catalogued)"),
      quantity("pitch", K::kLength, "chain pitch p (--chain fills it)"),
      quantity("roller_diameter", K::kLength, "roller diameter d1 (--chain fills it)"),
      quantity("inner_width", K::kLength, "inner width b1 (--chain fills it)"),
      integer("teeth", 1, "tooth count z, 6 … 500") | Required{"the tooth count z (6 … 500)"},
      integer("strands", 1, "strands k of the chain, 1 … 8") | Default{"1"},
      quantity("transverse_pitch", K::kLength,
               "transverse pitch pt of a multi-strand chain (--chain fills it where catalogued)"),
      quantity("tooth_width", K::kLength,
               "tooth width bf1, given (default 0.95 b1 for one strand and p > 12.7 mm)"),
  };
  a.check = check_sprocket;
  set_functions<SprocketAnalysis>(a, sprocket_analysis_run, describe_sprocket);
  return a;
}

}  // namespace

Drawing sprocket_drawing(const Sprocket& s) {
  Drawing d;
  d.title = "Catena sprocket (ISO 606), z " + std::to_string(s.input.teeth);
  d.polylines.push_back(circle("PITCH_CIRCLE", s.pitch_diameter / 2, 0x1f77b4, 0.18));
  d.polylines.push_back(circle("ROOT_CIRCLE", s.root_diameter / 2, 0x2ca02c, 0.18));
  d.polylines.push_back({"OUTLINE_MIN_GAP", tooth_outline(s, s.min_gap), true, 0.35, 0x000000});
  d.polylines.push_back({"OUTLINE_MAX_GAP", tooth_outline(s, s.max_gap), true, 0.35, 0xd62728});
  return d;
}

SprocketAnalysis sprocket_analysis_run(const Inputs& in) {
  SprocketAnalysis a;
  const auto chain = chain_of(in);
  if (chain) a.chain = chain->name;
  SprocketInput si;
  si.pitch =
      length(in, "pitch", chain ? std::optional<double>(chain->pitch) : std::nullopt).value_or(NAN);
  si.roller_diameter =
      length(in, "roller_diameter", chain ? chain->roller_diameter : std::nullopt).value_or(NAN);
  si.inner_width =
      length(in, "inner_width", chain ? chain->inner_width : std::nullopt).value_or(NAN);
  si.teeth = in.integer("teeth");
  si.strands = in.integer("strands");
  si.transverse_pitch =
      length(in, "transverse_pitch", chain ? chain->transverse_pitch : std::nullopt);
  if (in.given("tooth_width")) si.tooth_width = in.number("tooth_width");
  a.sprocket = sprocket(si);
  const Sprocket& s = a.sprocket;

  using Sev = Diagnostic::Severity;
  if (!si.tooth_width && si.strands == 1 && !(si.pitch > kTwelveSeven))
    a.diagnostics.push_back(
        {Sev::kInfo, "sprocket.tooth_width_unsourced",
         "tooth width bf1 not computed: 0.95 b1 holds for one strand and p > 12.7 mm; the "
         "standard's factor for p ≤ 12.7 mm was not found in a source Catena can cite: give "
         "--tooth-width",
         si.pitch, kTwelveSeven});
  if (!si.tooth_width && si.strands > 1)
    a.diagnostics.push_back(
        {Sev::kInfo, "sprocket.tooth_width_unsourced",
         "tooth width bf1 not computed: the standard's factor for multi-strand chains was not "
         "found in a source Catena can cite (0.95 b1 is the one-strand factor): give "
         "--tooth-width",
         static_cast<double>(si.strands), 1.0});
  if (si.strands > 1 && !si.transverse_pitch)
    a.diagnostics.push_back({Sev::kInfo, "sprocket.transverse_pitch_missing",
                             "width over the strands not computed: no transverse pitch pt "
                             "(the catalogue has none for this chain): give --transverse-pitch",
                             static_cast<double>(si.strands), 1.0});
  for (const auto& [name, f] :
       {std::pair{"minimum", &s.min_gap}, std::pair{"maximum", &s.max_gap}}) {
    if (f->flanks_meet_below_tip)
      a.diagnostics.push_back({Sev::kInfo, "sprocket.flanks_meet_below_tip",
                               std::string("the flanks of the ") + name + " gap form meet at Ø" +
                                   mm(f->flank_meeting_diameter) + " mm, below da,max " +
                                   mm(s.tip_diameter_max) + " mm: its outline ends there",
                               f->flank_meeting_diameter, s.tip_diameter_max});
    if (f->flank_meeting_diameter < s.tip_diameter_min)
      a.diagnostics.push_back(
          {Sev::kWarning, "sprocket.tip_below_minimum",
           std::string("the flanks of the ") + name + " gap form meet at Ø" +
               mm(f->flank_meeting_diameter) + " mm, below da,min " + mm(s.tip_diameter_min) +
               " mm: that form cannot have the standard's smallest tip diameter",
           f->flank_meeting_diameter, s.tip_diameter_min});
  }
  return a;
}

const analysis::Analysis& sprocket_analysis() {
  static const analysis::Analysis a = make_sprocket();
  return a;
}

}  // namespace catena::drive
