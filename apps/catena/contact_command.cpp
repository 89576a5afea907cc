// catena contact: roller–tooth contact with axis skew (seed 001, Harshniev & Maksymovych);
// catena fretting: latent period of fretting (seed 001, Vikulov eq. 1).
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>

#include "catena/contact/chain_catalog.hpp"
#include "catena/contact/fretting.hpp"
#include "catena/contact/roller_tooth.hpp"
#include "cli_support.hpp"
#include "commands.hpp"

namespace catena::cli {
namespace {

using io::QuantityKind;
using nlohmann::ordered_json;
using namespace catena::contact;

constexpr double kArcmin = std::numbers::pi / 10800.0;

struct ContactFlags {
  std::string roller_diameter, roller_length, tooth_radius, profile = "concave", modulus = "210GPa";
  std::string poisson = "0.3", tooth_modulus, tooth_poisson, load, pitch, skew, skew_factor = "1",
              gauge_dh, gauge_base, gamma;
  std::string chain, format = "table", output, sweep, slices = "201";
};

std::optional<double> number(FlagReader& in, const std::string& flag, const std::string& text,
                             const char* expected) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (*end != '\0' || !std::isfinite(v)) {
    in.add({flag, "'" + text + "'", expected});
    return NAN;
  }
  return v;
}

struct ContactRequest {
  RollerTooth c;
  double load = 0.0;
  double pitch = 0.0;
  double skew = 0.0;         // [rad] measured
  double skew_factor = 1.0;  // K_φ
  double gamma = 0.0;
  std::optional<std::array<double, 3>> sweep;  // from, to, step [rad]
  int slices = 201;
};

ContactRequest read(const ContactFlags& f) {
  FlagReader in;
  ContactRequest r;
  std::optional<ChainDimensions> chain;
  if (!f.chain.empty()) {
    chain = iso606_chain(f.chain);
    if (!chain) {
      std::string names;
      for (const auto& n : iso606_names()) names += (names.empty() ? "" : ", ") + n;
      in.add({"--chain", f.chain, "an ISO 606 chain of the catalogue: " + names});
    }
  }
  auto length = [&](const char* flag, const std::string& text,
                    std::optional<double> fallback) -> double {
    if (!text.empty()) return in.quantity(flag, text, QuantityKind::kLength).value_or(NAN);
    if (fallback) return *fallback;
    in.add({flag, "(missing)",
            chain ? std::string("a value (the catalogue has none for ") + chain->name + ")"
                  : std::string("a value (or --chain)")});
    return NAN;
  };
  r.c.roller_diameter =
      length("--roller-diameter", f.roller_diameter, chain ? chain->roller_diameter : std::nullopt);
  r.c.roller_length =
      length("--roller-length", f.roller_length, chain ? chain->inner_width : std::nullopt);
  r.c.tooth_radius = length("--tooth-radius", f.tooth_radius, std::nullopt);
  r.pitch = length("--pitch", f.pitch, chain ? std::optional<double>(chain->pitch) : std::nullopt);
  r.c.profile = f.profile == "convex" ? Profile::kConvex : Profile::kConcave;
  const double modulus = in.quantity("--modulus", f.modulus, QuantityKind::kStress).value_or(NAN);
  const double poisson = number(in, "--poisson", f.poisson, "a number 0 ≤ ν < 0.5").value_or(0.3);
  r.c.roller = r.c.tooth = Elastic{modulus, poisson};
  if (!f.tooth_modulus.empty())
    r.c.tooth.modulus =
        in.quantity("--tooth-modulus", f.tooth_modulus, QuantityKind::kStress).value_or(NAN);
  if (!f.tooth_poisson.empty())
    r.c.tooth.poisson =
        number(in, "--tooth-poisson", f.tooth_poisson, "a number 0 ≤ ν < 0.5").value_or(0.3);
  if (f.load.empty()) {
    in.add({"--load", "(missing)", "the nominal load Q_nom on the roller"});
  } else {
    r.load = in.quantity("--load", f.load, QuantityKind::kForce).value_or(NAN);
  }
  const bool gauge = !f.gauge_dh.empty() || !f.gauge_base.empty();
  if (gauge && !f.skew.empty())
    in.add({"--skew", f.skew, "either --skew or the gauge readings, not both"});
  if (gauge) {
    const double dh = in.quantity("--skew-gauge-dh", f.gauge_dh.empty() ? "(missing)" : f.gauge_dh,
                                  QuantityKind::kLength)
                          .value_or(NAN);
    const double base =
        in.quantity("--skew-gauge-base", f.gauge_base.empty() ? "(missing)" : f.gauge_base,
                    QuantityKind::kLength)
            .value_or(NAN);
    r.skew = skew_from_gauge(dh, base);
    if (!(base > 0)) in.add({"--skew-gauge-base", f.gauge_base, "a base B > 0"});
  } else if (!f.skew.empty()) {
    r.skew = in.quantity("--skew", f.skew, QuantityKind::kAngle).value_or(NAN);
  } else if (f.sweep.empty()) {
    in.add({"--skew", "(missing)",
            "the measured skew φ (e.g. 0.7deg, 0°42'), or --skew-gauge-dh with "
            "--skew-gauge-base, or --skew-sweep (an aligned roller is --skew 0)"});
  }
  if (!f.sweep.empty() && (gauge || !f.skew.empty()))
    in.add({"--skew-sweep", f.sweep, "either a sweep or one skew (--skew or the gauge), not both"});
  r.skew_factor =
      number(in, "--skew-factor", f.skew_factor, "K_φ, a number in (0, 1]").value_or(1.0);
  if (!(r.skew_factor > 0 && r.skew_factor <= 1))
    in.add({"--skew-factor", f.skew_factor, "K_φ in (0, 1]"});
  if (!f.sweep.empty()) {
    std::array<double, 3> parts{};
    std::stringstream ss(f.sweep);
    std::string part;
    int k = 0;
    while (std::getline(ss, part, ':')) {
      if (k < 3) parts[k] = in.quantity("--skew-sweep", part, QuantityKind::kAngle).value_or(NAN);
      ++k;
    }
    constexpr double kRight = std::numbers::pi / 2;
    if (k != 3 || !(parts[2] > 0) || !(parts[1] >= parts[0]) || !(std::abs(parts[0]) < kRight) ||
        !(std::abs(parts[1]) < kRight) || (parts[1] - parts[0]) / parts[2] > 10000) {
      in.add({"--skew-sweep", f.sweep,
              "FROM:TO:STEP, three angles, -90° < FROM ≤ TO < 90°, STEP > 0, at most 10000 "
              "steps"});
    } else {
      r.sweep = parts;
    }
  }
  const auto table = skew_gamma(r.pitch);
  if (!f.gamma.empty()) {
    r.gamma = number(in, "--gamma", f.gamma, "γ ≥ 0 of eq. (2)").value_or(NAN);
    if (!(r.gamma >= 0)) in.add({"--gamma", f.gamma, "γ ≥ 0"});
  } else if (table || !std::isfinite(r.pitch)) {  // a bad pitch is reported already
    r.gamma = table.value_or(NAN);
  } else {
    in.add(
        {"--pitch", format_g(r.pitch * 1e3) + " mm",
         "a pitch of the paper's γ table (12.7, 15.875, 19.05, 25.4 mm), or γ given with --gamma "
         "(no extrapolation)"});
  }
  r.slices = in.integer("--slices", f.slices, 3).value_or(3);
  constexpr int kMaxSlices = 20001;
  constexpr double kMaxSliceWork = 2e6;  // slices × sweep points: a few seconds at most
  if (r.slices > kMaxSlices) {
    in.add({"--slices", f.slices, "3 … " + std::to_string(kMaxSlices) + " slices"});
  } else if (r.sweep &&
             r.slices * ((*r.sweep)[1] - (*r.sweep)[0]) / (*r.sweep)[2] > kMaxSliceWork) {
    in.add({"--slices", f.slices,
            "at most " + format_g(kMaxSliceWork) +
                " slices × sweep points in all: fewer slices or a "
                "coarser --skew-sweep"});
  }
  in.throw_if_any();
  in.add_model_issues(validate(r.c));
  if (!(r.load > 0)) in.add({"--load", f.load, "a load > 0"});
  if (!std::isfinite(r.skew) || std::abs(r.skew) >= std::numbers::pi / 2)
    in.add({"--skew", f.skew, "|φ| < 90°"});
  in.throw_if_any();
  return r;
}

struct ContactPoint {
  double skew, load_factor, effective_load, paper_stress, hertz_effective, slice_peak, slice_length;
};

ContactPoint evaluate(const ContactRequest& r, double skew, const SliceResult* slices) {
  ContactPoint p{};
  p.skew = skew;
  p.load_factor = load_factor(r.gamma, skew, r.skew_factor);
  p.effective_load = r.load * p.load_factor;
  p.paper_stress =
      paper_stress(p.effective_load, r.c.roller.modulus, r.c.roller_length, reduced_radius(r.c));
  p.hertz_effective = hertz(r.c, p.effective_load).peak_pressure;
  const SliceResult s =
      slices ? *slices : slice_model(r.c, r.load, skew * r.skew_factor, SliceOptions{r.slices});
  p.slice_peak = s.stress_peak;
  p.slice_length = s.loaded_length;
  return p;
}

int run_contact(const ContactFlags& f) {
  const ContactRequest r = read(f);
  std::string text;
  const HertzResult nominal = hertz(r.c, r.load);
  if (r.sweep) {
    std::vector<ContactPoint> rows;
    const auto [from, to, step] = *r.sweep;
    const int n = static_cast<int>(std::floor((to - from) / step + 1e-9)) + 1;
    for (int i = 0; i < n; ++i) rows.push_back(evaluate(r, from + i * step, nullptr));
    if (f.format == "json") {
      ordered_json j;
      auto column = [&](auto member) {
        std::vector<double> v;
        for (const auto& row : rows) v.push_back(row.*member);
        return v;
      };
      j["skew"] = column(&ContactPoint::skew);
      j["load_factor"] = column(&ContactPoint::load_factor);
      j["effective_load"] = column(&ContactPoint::effective_load);
      j["contact_stress"] = column(&ContactPoint::paper_stress);
      j["hertz_stress"] = column(&ContactPoint::hertz_effective);
      j["slice_stress_peak"] = column(&ContactPoint::slice_peak);
      j["slice_loaded_length"] = column(&ContactPoint::slice_length);
      j["units"] = {{"skew", "rad"},
                    {"load_factor", "1"},
                    {"effective_load", "N"},
                    {"contact_stress", "Pa"},
                    {"hertz_stress", "Pa"},
                    {"slice_stress_peak", "Pa"},
                    {"slice_loaded_length", "m"}};
      text = j.dump(2) + "\n";
    } else {
      const bool csv = f.format == "csv";
      std::ostringstream out;
      out << (csv ? "skew,load_factor,effective_load,contact_stress,hertz_stress,slice_stress_peak,"
                    "slice_loaded_length\n"
                  : "Catena contact: stress versus skew (seed 001 eqs. 1-3 and the slice model)\n\n"
                    "  skew [arcmin]   Q/Qnom   sigma eq.3 [MPa]  paper factor  slice peak [MPa]  "
                    "slice factor  loaded [mm]\n");
      for (const auto& p : rows) {
        if (csv) {
          out << format_g(p.skew, 12) << "," << format_g(p.load_factor, 12) << ","
              << format_g(p.effective_load, 12) << "," << format_g(p.paper_stress, 12) << ","
              << format_g(p.hertz_effective, 12) << "," << format_g(p.slice_peak, 12) << ","
              << format_g(p.slice_length, 12) << "\n";
        } else {
          char line[256];
          std::snprintf(line, sizeof line, "  %13.4g %8.4g %18.5g %13.4g %17.5g %13.4g %12.4g\n",
                        p.skew / kArcmin, p.load_factor, p.paper_stress / 1e6,
                        std::sqrt(p.load_factor), p.slice_peak / 1e6,
                        p.slice_peak / nominal.peak_pressure, p.slice_length * 1e3);
          out << line;
        }
      }
      text = out.str();
    }
  } else {
    const SliceResult s = slice_model(r.c, r.load, r.skew * r.skew_factor, SliceOptions{r.slices});
    const ContactPoint p = evaluate(r, r.skew, &s);
    const HertzResult eff = hertz(r.c, p.effective_load);
    if (f.format == "json") {
      ordered_json j;
      j["model"] = "contact.roller_tooth_skew";
      j["source"] = "001 Harshniev & Maksymovych eqs. (1)-(3); Johnson (1985) for Hertz";
      j["reduced_radius"] = reduced_radius(r.c);
      j["gamma"] = r.gamma;
      j["skew"] = r.skew;
      j["design_skew"] = r.skew * r.skew_factor;
      j["load_factor"] = p.load_factor;
      j["effective_load"] = p.effective_load;
      j["contact_stress"] = p.paper_stress;
      j["hertz_stress"] = eff.peak_pressure;
      j["hertz_stress_nominal"] = nominal.peak_pressure;
      j["half_width"] = eff.half_width;
      j["max_shear"] = eff.max_shear;
      j["max_shear_depth"] = eff.max_shear_depth;
      j["slice_model"] = {{"stress_peak", s.stress_peak},
                          {"stress_factor", s.stress_peak / nominal.peak_pressure},
                          {"loaded_length", s.loaded_length},
                          {"peak_half_width", s.peak_half_width},
                          {"approach", s.approach},
                          {"load_sum", s.load_sum},
                          {"distribution", {{"s", s.s}, {"q", s.q}}}};
      j["units"] = {{"reduced_radius", "m"},
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
                    {"q", "N/m"}};
      text = j.dump(2) + "\n";
    } else if (f.format == "csv") {
      std::ostringstream out;
      out << "s,q\n";
      for (std::size_t i = 0; i < s.s.size(); ++i)
        out << format_g(s.s[i], 12) << "," << format_g(s.q[i], 12) << "\n";
      text = out.str();
    } else {
      std::ostringstream out;
      char line[256];
      auto row = [&](const char* label, const std::string& v) {
        std::snprintf(line, sizeof line, "  %-46s %s\n", label, v.c_str());
        out << line;
      };
      out << "Catena contact: roller on sprocket tooth with axis skew (seed 001)\n\n";
      row("reduced radius rho [mm]", format_g(reduced_radius(r.c) * 1e3));
      row("skew measured / design (K_phi) [arcmin]",
          format_g(r.skew / kArcmin) + " / " + format_g(r.skew * r.skew_factor / kArcmin));
      row("gamma of eq. (2) [1/arcmin^2]", format_g(r.gamma));
      row("load factor Q_n/Q_nom (eq. 2)", format_g(p.load_factor));
      row("contact stress eq. (3), 0.418 [MPa]", format_g(p.paper_stress / 1e6));
      row("Hertz stress at Q_n / at Q_nom [MPa]",
          format_g(eff.peak_pressure / 1e6) + " / " + format_g(nominal.peak_pressure / 1e6));
      row("half-width b at Q_n [mm]", format_g(eff.half_width * 1e3));
      row("max shear 0.300 p0 at depth 0.786 b [MPa, mm]",
          format_g(eff.max_shear / 1e6) + ", " + format_g(eff.max_shear_depth * 1e3));
      row("slice model: peak stress [MPa]", format_g(s.stress_peak / 1e6));
      row("slice model: stress factor vs aligned", format_g(s.stress_peak / nominal.peak_pressure));
      row("paper: stress factor sqrt(Q_n/Q_nom)", format_g(std::sqrt(p.load_factor)));
      row("slice model: loaded length [mm]",
          format_g(s.loaded_length * 1e3) + " of " + format_g(r.c.roller_length * 1e3));
      row("slice model: loaded length / peak half-width",
          format_g(s.loaded_length / s.peak_half_width, 3) +
              (s.loaded_length < 5 * s.peak_half_width
                   ? "  (< 5: a short patch, the strip model is rough here)"
                   : ""));
      text = out.str();
    }
  }
  write_text_output(f.output, text);
  return 0;
}

struct FrettingFlags {
  std::string roughness, amplitude, load, frequency, k1, k2, format = "table", output;
};

int run_fretting(const FrettingFlags& f) {
  FlagReader in;
  Fretting m;
  auto need = [&](const char* flag, const std::string& text, QuantityKind kind) -> double {
    if (text.empty()) {
      in.add({flag, "(missing)", "a value"});
      return NAN;
    }
    return in.quantity(flag, text, kind).value_or(NAN);
  };
  m.roughness = need("--roughness", f.roughness, QuantityKind::kLength);
  m.amplitude = need("--amplitude", f.amplitude, QuantityKind::kLength);
  m.load = need("--load", f.load, QuantityKind::kForce);
  m.frequency = need("--frequency", f.frequency, QuantityKind::kFrequency);
  auto constant = [&](const char* flag, const std::string& text, const char* expected) -> double {
    if (text.empty()) {
      in.add({flag, "(missing)", expected});
      return NAN;
    }
    return number(in, flag, text, expected).value_or(NAN);
  };
  m.k1 = constant("--k1", f.k1, "K1 in s/m (SI number), empirical: no default");
  m.k2 = constant("--k2", f.k2, "K2 in s/N (SI number), empirical: no default");
  in.throw_if_any();
  in.add_model_issues(validate(m));
  in.throw_if_any();
  const double tau = latent_period(m);
  const double exponent = m.k2 * m.amplitude * m.load * m.frequency / m.roughness;
  std::string text;
  if (f.format == "json") {
    ordered_json j{{"model", "contact.fretting_latent_period"},
                   {"source", "001 Vikulov eq. (1)"},
                   {"latent_period", tau},
                   {"exponent", exponent},
                   {"cycles", tau * m.frequency},
                   {"units", {{"latent_period", "s"}, {"exponent", "1"}, {"cycles", "1"}}}};
    text = j.dump(2) + "\n";
  } else if (f.format == "csv") {
    text = "latent_period,exponent,cycles\n" + format_g(tau, 12) + "," + format_g(exponent, 12) +
           "," + format_g(tau * m.frequency, 12) + "\n";
  } else {
    text =
        "Catena fretting: latent period (seed 001, Vikulov eq. 1)\n\n  latent period tau [s]   " +
        format_g(tau) + " (" + format_g(tau / 3600) + " h, " + format_g(tau * m.frequency) +
        " cycles)\n  exponent K2 A N f / Ra  " + format_g(exponent) + "\n";
  }
  write_text_output(f.output, text);
  return 0;
}

}  // namespace

std::function<int()> add_contact(CLI::App& app) {
  auto f = std::make_shared<ContactFlags>();
  CLI::App* c =
      app.add_subcommand("contact", "Roller-sprocket tooth contact with axis skew (seed 001)");
  c->add_option("--roller-diameter", f->roller_diameter, "D_p (bare: mm; --chain fills d1)");
  c->add_option("--roller-length", f->roller_length,
                "L_p (bare: mm; --chain fills b1, the inner width)");
  c->add_option("--tooth-radius", f->tooth_radius,
                "r1, flank profile radius in the contact zone (bare: mm)");
  c->add_option("--profile", f->profile, "concave (default) or convex flank")
      ->check(CLI::IsMember({"concave", "convex"}));
  c->add_option("--modulus", f->modulus, "E of the roller, and of the tooth (default 210GPa)");
  c->add_option("--poisson", f->poisson, "nu (default 0.3)");
  c->add_option("--tooth-modulus", f->tooth_modulus, "E of the tooth (default: --modulus)");
  c->add_option("--tooth-poisson", f->tooth_poisson, "nu of the tooth (default: --poisson)");
  c->add_option("--load", f->load, "nominal load Q_nom on the roller (bare: N)");
  c->add_option("--pitch", f->pitch, "chain pitch, selects gamma (bare: mm; --chain fills p)");
  c->add_option("--skew", f->skew, "measured skew phi (0.7deg, 42arcmin, 0°42'; bare: degree)");
  c->add_option("--skew-factor", f->skew_factor, "K_phi (default 1; 0.6-0.7 for a worn chain)");
  c->add_option("--skew-gauge-dh", f->gauge_dh, "gauge reading dh: phi = arctg(dh/B)");
  c->add_option("--skew-gauge-base", f->gauge_base, "gauge base B");
  c->add_option("--gamma", f->gamma,
                "gamma of eq. (2) [1/arcmin^2] for a pitch outside the paper's table");
  c->add_option("--chain", f->chain,
                "ISO 606 chain (e.g. 12B): fills pitch, roller diameter and length");
  c->add_option("--skew-sweep", f->sweep, "FROM:TO:STEP, e.g. 0deg:4deg:0.1deg: table versus skew");
  c->add_option("--slices", f->slices, "slices of the slice model (default 201)");
  c->add_option("--format", f->format, "table|json|csv")
      ->check(CLI::IsMember({"table", "json", "csv"}));
  c->add_option("--output", f->output, "write the output to FILE");
  return [f]() { return run_contact(*f); };
}

std::function<int()> add_fretting(CLI::App& app) {
  auto f = std::make_shared<FrettingFlags>();
  CLI::App* c = app.add_subcommand(
      "fretting", "Latent period of fretting in multi-strand chain fits (seed 001)");
  c->add_option("--roughness", f->roughness, "Ra (e.g. 0.8um; bare: mm)");
  c->add_option("--amplitude", f->amplitude, "A, amplitude of relative slip (bare: mm)");
  c->add_option("--load", f->load, "N, normal load (bare: N)");
  c->add_option("--frequency", f->frequency, "f, vibration frequency (20Hz; bare: Hz)");
  c->add_option("--k1", f->k1, "K1 [s/m], empirical, required");
  c->add_option("--k2", f->k2, "K2 [s/N] < 0, empirical, required");
  c->add_option("--format", f->format, "table|json|csv")
      ->check(CLI::IsMember({"table", "json", "csv"}));
  c->add_option("--output", f->output, "write the output to FILE");
  return [f]() { return run_fretting(*f); };
}

}  // namespace catena::cli
