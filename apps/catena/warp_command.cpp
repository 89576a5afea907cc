// catena warp: roller warp in the vertical plane (seed 000 §1.4), swept over L1 and F.
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "catena/warp/warp.hpp"
#include "cli_support.hpp"
#include "commands.hpp"

namespace catena::cli {
namespace {

using io::QuantityKind;
using nlohmann::ordered_json;
using namespace catena::warp;

constexpr const char* kNames[4] = {"F21", "F11", "F12", "F22"};

struct WarpFlags {
  std::string heights, clearances = "0,0,0,0", stiffness, widths, exponent = "1";
  std::string diameter, modulus = "210GPa", poisson = "0.3", hinge = "sliding", r1, r2;
  std::string force, load_height, format = "table", output;
};

// A list of quantities; `count` > 0 demands that many (one value is repeated to all).
std::vector<double> list(FlagReader& in, const std::string& flag, const std::string& text,
                         QuantityKind kind, std::size_t count, const char* what) {
  if (text.empty()) {
    in.add({flag, "(missing)", what});
    return {};
  }
  std::vector<double> v;
  for (const auto& p : split_commas(text)) v.push_back(in.quantity(flag, p, kind).value_or(NAN));
  if (count > 0 && v.size() == 1) v.assign(count, v[0]);
  if (count > 0 && v.size() != count) {
    in.add({flag, text, std::string(what) + ": 1 or 4 comma-separated values"});
    return {};
  }
  return v;
}

int run_warp(const WarpFlags& f) {
  FlagReader in;
  Warp w;
  const char* four =
      "four values, bottom to top: lower outer, lower inner, upper inner, upper outer";
  const auto z = list(in, "--heights", f.heights, QuantityKind::kLength, 4, four);
  const auto c = list(in, "--clearances", f.clearances, QuantityKind::kLength, 4, four);
  const auto b = list(in, "--widths", f.widths, QuantityKind::kLength, 4, four);
  std::vector<double> k;
  if (f.stiffness.empty()) {
    in.add({"--stiffness", "(missing)", "k of R = k·g^n in SI (N/m^n), 1 or 4 values"});
  } else {
    for (const auto& p : split_commas(f.stiffness))
      k.push_back(in.required_number("--stiffness", p, "k in SI (N/m^n), a plain number"));
    if (k.size() == 1) k.assign(4, k[0]);
    if (k.size() != 4) in.add({"--stiffness", f.stiffness, "1 or 4 values"});
  }
  w.exponent = in.required_number("--exponent", f.exponent, "n in [1, 3]");
  w.roller_diameter =
      in.required_quantity("--pin-diameter", f.diameter, QuantityKind::kLength, "d of the roller");
  w.modulus = in.quantity("--modulus", f.modulus, QuantityKind::kStress).value_or(NAN);
  w.poisson = in.required_number("--poisson", f.poisson, "0 ≤ ν < 0.5");
  w.kind = f.hinge == "rolling" ? HingeKind::kRolling : HingeKind::kSliding;
  if (w.kind == HingeKind::kRolling) {
    w.r1 = in.required_quantity("--plate-radius", f.r1, QuantityKind::kLength,
                                "R1 for a rolling hinge");
    w.r2 = in.required_quantity("--roller-radius", f.r2, QuantityKind::kLength,
                                "R2 for a rolling hinge");
  }
  const auto forces = list(in, "--force", f.force, QuantityKind::kForce, 0,
                           "F, one value or a comma-separated sweep");
  const auto heights = list(in, "--load-height", f.load_height, QuantityKind::kLength, 0,
                            "L1 (from the lower outer joint's datum), one value or a sweep");
  constexpr std::size_t kMaxPoints = 100000;
  if (forces.size() * heights.size() > kMaxPoints)
    in.add({"--force",
            format_g(static_cast<double>(forces.size())) + " × " +
                format_g(static_cast<double>(heights.size())) + " points",
            "at most 100000 sweep points"});
  in.throw_if_any();
  for (std::size_t i = 0; i < 4; ++i) w.supports[i] = {z[i], c[i], k[i], b[i]};
  std::vector<Issue> issues;
  for (double F : forces)
    for (double L : heights)
      for (auto& is : validate(w, {F, L})) {
        bool seen = false;
        for (const auto& e : issues) seen |= e.field == is.field && e.value == is.value;
        if (!seen) issues.push_back(is);
      }
  // the model's field names → the flags' primary names (shared with catena hinge)
  for (Issue& is : issues) {
    if (is.field == "roller_diameter") is.field = "pin_diameter";
    if (is.field == "r1") is.field = "plate_radius";
    if (is.field == "r2") is.field = "roller_radius";
  }
  in.add_model_issues(issues);
  in.throw_if_any();

  ordered_json points = ordered_json::array(), diags = ordered_json::array();
  std::map<std::string, std::pair<std::size_t, double>> worst;  // code → (index, value/limit)
  std::ostringstream csv, table;
  csv << "force,load_height,F21,F11,F12,F22,delta21,delta11,delta12,delta22,tilt,upper_share,"
         "bending_stress,stress21,stress11,stress12,stress22,converged,iterations,residual\n";
  table << "Catena warp: roller on four joints with clearance (seed 000 §1.4; "
        << (w.kind == HingeKind::kRolling ? "rolling" : "sliding")
        << " hinge)\n\n    F [kN]  L1 [mm]  F21 [kN]  F11 [kN]  F12 [kN]  F22 [kN]  upper/lower-1  "
           "tilt [mrad]  sigma F12 [MPa]  sigma_b [MPa]\n";
  for (double F : forces)
    for (double L : heights) {
      const WarpResult r = solve(w, {F, L});
      ordered_json p;
      p["force"] = F;
      p["load_height"] = L;
      for (std::size_t i = 0; i < 4; ++i) p["joint_force"][kNames[i]] = r.force[i];
      for (std::size_t i = 0; i < 4; ++i) p["deformation"][kNames[i]] = r.deformation[i];
      for (std::size_t i = 0; i < 4; ++i) p["deflection"][kNames[i]] = r.deflection[i];
      for (std::size_t i = 0; i < 4; ++i) p["contact_stress"][kNames[i]] = r.contact_stress[i];
      p["tilt"] = r.tilt;
      p["upper_share"] = r.upper_share;
      p["moment_max"] = r.moment_max;
      p["bending_stress"] = r.bending_stress;
      p["force_residual"] = r.force_residual;
      p["moment_residual"] = r.moment_residual;
      p["solver"] = {{"converged", r.summary.converged},
                     {"iterations", r.summary.iterations},
                     {"residual", r.summary.residual},
                     {"termination", r.summary.termination}};
      points.push_back(p);
      // one diagnostic per code over the whole sweep: the point where it is worst (largest
      // value/limit), with the number of sweep points at which it fired
      for (const auto& d : r.diagnostics) {
        const double excess = d.limit > 0.0 ? d.value / d.limit : d.value;
        const auto seen = worst.find(d.code);
        if (seen != worst.end()) {
          ordered_json& e = diags[seen->second.first];
          e["points"] = e["points"].get<int>() + 1;
          if (!(excess > seen->second.second)) continue;
          seen->second.second = excess;
          e["value"] = d.value;
          e["limit"] = d.limit;
          e["force"] = F;
          e["load_height"] = L;
          continue;
        }
        worst[d.code] = {diags.size(), excess};
        diags.push_back({{"severity", to_string(d.severity)},
                         {"code", d.code},
                         {"message", d.message},
                         {"value", d.value},
                         {"limit", d.limit},
                         {"force", F},
                         {"load_height", L},
                         {"points", 1}});
      }
      csv << format_g(F, 12) << "," << format_g(L, 12);
      for (double v : r.force) csv << "," << format_g(v, 12);
      for (double v : r.deformation) csv << "," << format_g(v, 12);
      csv << "," << format_g(r.tilt, 12) << "," << format_g(r.upper_share, 12) << ","
          << format_g(r.bending_stress, 12);
      for (double v : r.contact_stress) csv << "," << format_g(v, 12);
      csv << "," << (r.summary.converged ? 1 : 0) << "," << r.summary.iterations << ","
          << format_g(r.summary.residual, 6) << "\n";
      char line[256];
      std::snprintf(line, sizeof line,
                    "  %8.4g %8.4g %9.4g %9.4g %9.4g %9.4g %14.4g %12.4g %16.4g %14.4g%s\n",
                    F / 1e3, L * 1e3, r.force[0] / 1e3, r.force[1] / 1e3, r.force[2] / 1e3,
                    r.force[3] / 1e3, r.upper_share, r.tilt * 1e3, r.contact_stress[kF12] / 1e6,
                    r.bending_stress / 1e6, r.summary.converged ? "" : "  NOT CONVERGED");
      table << line;
    }
  std::string text;
  if (f.format == "json") {
    ordered_json j;
    j["model"] = "warp.roller_four_joints";
    j["source"] =
        "000 §1.4 figs. 12-18 (reconstructed: Euler-Bernoulli roller on unilateral power-law "
        "joints, Levina & Reshetov 1971; Hertz line contact, Johnson 1985 §4.2)";
    j["hinge"] = w.kind == HingeKind::kRolling ? "rolling" : "sliding";
    j["exponent"] = w.exponent;
    j["points"] = points;
    j["units"] = {{"force", "N"},           {"load_height", "m"},    {"joint_force", "N"},
                  {"deformation", "m"},     {"deflection", "m"},     {"contact_stress", "Pa"},
                  {"tilt", "rad"},          {"upper_share", "1"},    {"moment_max", "N*m"},
                  {"bending_stress", "Pa"}, {"force_residual", "N"}, {"moment_residual", "N*m"},
                  {"residual", "N"},        {"stiffness", "N/m^n"},  {"exponent", "1"}};
    j["diagnostics"] = diags;
    text = j.dump(2) + "\n";
  } else if (f.format == "csv") {
    text = csv.str();
  } else {
    text = table.str();
  }
  write_text_output(f.output, text);
  return 0;
}

}  // namespace

std::function<int()> add_warp(CLI::App& app) {
  auto f = std::make_shared<WarpFlags>();
  CLI::App* c = app.add_subcommand(
      "warp", "Roller warp: joint forces, tilt and stresses versus L1 and F (seed 000 §1.4)");
  c->add_option("--heights", f->heights,
                "joint heights, bottom to top: lower outer, lower inner, upper inner, upper outer "
                "(e.g. 0,10mm,50mm,60mm; bare: mm)");
  c->add_option("--clearances", f->clearances, "radial clearances c_i, 1 or 4 (default 0)");
  c->add_option("--stiffness", f->stiffness, "k of R = k·g^n in SI N/m^n, 1 or 4 values");
  c->add_option("--exponent", f->exponent, "n of the joint law in [1, 3] (default 1)");
  c->add_option("--widths", f->widths, "plate thicknesses B_i, 1 or 4");
  c->add_option("--pin-diameter,--roller-diameter", f->diameter,
                "roller (pin) diameter d, as catena hinge (bare: mm)");
  c->add_option("--modulus", f->modulus, "E (default 210GPa)");
  c->add_option("--poisson", f->poisson, "nu (default 0.3)");
  c->add_option("--hinge", f->hinge, "sliding (default) or rolling")
      ->check(CLI::IsMember({"sliding", "rolling"}));
  c->add_option("--plate-radius,--r1", f->r1, "rolling hinge: plate convex radius R1 (bare: mm)");
  c->add_option("--roller-radius,--r2", f->r2,
                "rolling hinge: roller concave radius R2 > R1 (bare: mm)");
  c->add_option("--force", f->force, "tooth load F, or a comma-separated sweep (30kN,35kN,40kN)");
  c->add_option("--load-height", f->load_height, "L1, or a comma-separated sweep");
  c->add_option("--format", f->format, "table|json|csv")
      ->check(CLI::IsMember({"table", "json", "csv"}));
  c->add_option("--output", f->output, "write the output to FILE");
  return [f]() { return run_warp(*f); };
}

}  // namespace catena::cli
