#include "catena/contact/chain_catalog.hpp"

#include <algorithm>
#include <cctype>
#include <sstream>

namespace catena::contact {
const char* iso606_csv();  // generated from data/catalog/iso606/chains.csv (src/CMakeLists.txt)

namespace {

std::optional<double> cell(const std::string& text, double scale) {
  if (text.empty()) return std::nullopt;
  return std::stod(text) * scale;
}

// The newton per pound-force (exact, by the definitions of the pound and of g_n).
constexpr double kNewtonPerPoundForce = 4.4482216152605;

// The link's axial stiffness [N/m] from the source's stretch factor k [lbf per (in of stretch per
// ft of chain)] (README, `CALCULATORS_K`) and the pitch p [m]: the source's elongation
// l = (L/12) T/k (L, l in inches, T in lbf) is a strain T/(12 k), so EA = 12 k lbf, and one link
// (one pitch long) has k_link = EA/p.
double stretch_factor_stiffness(double k_lbf, double pitch) {
  return 12.0 * k_lbf * kNewtonPerPoundForce / pitch;
}

std::vector<ChainDimensions> load() {
  std::vector<ChainDimensions> out;
  std::istringstream in(iso606_csv());
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::vector<std::string> f;
    std::stringstream row(line);
    for (std::string c; std::getline(row, c, ',');) f.push_back(c);
    f.resize(11);
    ChainDimensions c;
    c.name = f[0];
    c.pitch = std::stod(f[1]) * 1e-3;
    c.roller_diameter = cell(f[2], 1e-3);
    c.inner_width = cell(f[3], 1e-3);
    c.pin_diameter = cell(f[4], 1e-3);
    c.plate_depth = cell(f[5], 1e-3);
    c.tensile_strength = cell(f[6], 1e3);
    c.transverse_pitch = cell(f[7], 1e-3);
    c.mass_per_metre = cell(f[8], 1.0);
    if (const auto k = cell(f[9], 1.0)) c.axial_stiffness = stretch_factor_stiffness(*k, c.pitch);
    c.source = f[10];
    out.push_back(c);
  }
  return out;
}

const std::vector<ChainDimensions>& catalogue() {
  static const std::vector<ChainDimensions> chains = load();
  return chains;
}

std::string upper(std::string s) {
  for (char& ch : s) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  return s;
}

}  // namespace

std::optional<ChainDimensions> iso606_chain(const std::string& name) {
  for (const ChainDimensions& c : catalogue()) {
    if (upper(c.name) == upper(name)) return c;
  }
  return std::nullopt;
}

std::vector<std::string> iso606_names() {
  std::vector<std::string> names;
  for (const ChainDimensions& c : catalogue()) names.push_back(c.name);
  return names;
}

}  // namespace catena::contact
