// `catalog` — the ISO 606 chain catalogue as a lookup through the analysis interface.
#include "catena/contact/catalog_analysis.hpp"

#include <algorithm>
#include <cctype>
#include <sstream>

namespace catena::contact {
namespace {

using analysis::format_g;
using analysis::Inputs;
using analysis::Record;
using analysis::Value;

std::string upper(std::string s) {
  for (char& ch : s) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  return s;
}

std::string names_list() {
  std::string names;
  for (const auto& n : iso606_names()) names += (names.empty() ? "" : ", ") + n;
  return names;
}

void check_catalog(const Inputs& in, std::vector<Issue>& issues) {
  if (in.given("chain") && !iso606_chain(in.text("chain")))
    issues.push_back(
        {"chain", in.text("chain"), "an ISO 606 chain of the catalogue: " + names_list()});
  if (in.given("chain") && in.given("search"))
    issues.push_back({"search", in.text("search"), "either a chain or a search, not both"});
}

Value chain_value(const ChainDimensions& c) {
  return Value::object({{"chain", c.name},
                        {"pitch", c.pitch},
                        {"roller_diameter", Value(c.roller_diameter)},
                        {"inner_width", Value(c.inner_width)},
                        {"pin_diameter", Value(c.pin_diameter)},
                        {"plate_depth", Value(c.plate_depth)},
                        {"tensile_strength", Value(c.tensile_strength)},
                        {"transverse_pitch", Value(c.transverse_pitch)},
                        {"mass_per_metre", Value(c.mass_per_metre)},
                        {"axial_stiffness", Value(c.axial_stiffness)},
                        {"source", c.source}});
}

Value units() {
  return analysis::units_value({{"pitch", "m"},
                                {"roller_diameter", "m"},
                                {"inner_width", "m"},
                                {"pin_diameter", "m"},
                                {"plate_depth", "m"},
                                {"tensile_strength", "N"},
                                {"transverse_pitch", "m"},
                                {"mass_per_metre", "kg/m"},
                                {"axial_stiffness", "N/m"}});
}

std::string cell(const std::optional<double>& v, double scale) {
  return v ? format_g(*v * scale) : "—";
}

Record describe_catalog(const CatalogAnalysis& a, const Inputs&) {
  Record rec;
  if (a.single) {
    rec.data = chain_value(a.chains.front());
    rec.data["source_readme"] = "data/catalog/iso606/README.md";
    rec.data["units"] = units();
  } else {
    Value list = Value::array();
    for (const ChainDimensions& c : a.chains) list.push_back(chain_value(c));
    rec.data = Value::object(
        {{"chains", list}, {"source_readme", "data/catalog/iso606/README.md"}, {"units", units()}});
  }
  std::ostringstream table;
  table << "Catena catalog: ISO 606 roller chains, simplex (sources: "
           "data/catalog/iso606/README.md; — = no source found)\n\n";
  // right-aligned in `width` characters (not bytes: "—" is three)
  auto cellw = [](const std::string& text, std::size_t width) {
    std::size_t n = 0;
    for (char c : text) n += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
    return std::string(n < width ? width - n : 0, ' ') + text;
  };
  auto row = [&](const std::vector<std::string>& cells) {
    table << "  " << cells[0] << std::string(cells[0].size() < 6 ? 6 - cells[0].size() : 0, ' ');
    for (std::size_t i = 1; i + 1 < cells.size(); ++i) table << ' ' << cellw(cells[i], 9);
    table << "  " << cells.back() << '\n';
  };
  row({"chain", "p [mm]", "d1 [mm]", "b1 [mm]", "d2 [mm]", "h2 [mm]", "Fu [kN]", "pt [mm]",
       "q [kg/m]", "source"});
  std::ostringstream csv;
  csv << "chain,pitch,roller_diameter,inner_width,pin_diameter,plate_depth,tensile_strength,"
         "transverse_pitch,mass_per_metre,source\n";
  auto csv_cell = [](const std::optional<double>& v) {
    return v ? format_g(*v, 12) : std::string();
  };
  for (const ChainDimensions& c : a.chains) {
    row({c.name, format_g(c.pitch * 1e3), cell(c.roller_diameter, 1e3), cell(c.inner_width, 1e3),
         cell(c.pin_diameter, 1e3), cell(c.plate_depth, 1e3), cell(c.tensile_strength, 1e-3),
         cell(c.transverse_pitch, 1e3), cell(c.mass_per_metre, 1.0), c.source});
    csv << c.name << ',' << format_g(c.pitch, 12) << ',' << csv_cell(c.roller_diameter) << ','
        << csv_cell(c.inner_width) << ',' << csv_cell(c.pin_diameter) << ','
        << csv_cell(c.plate_depth) << ',' << csv_cell(c.tensile_strength) << ','
        << csv_cell(c.transverse_pitch) << ',' << csv_cell(c.mass_per_metre) << ',' << c.source
        << '\n';
  }
  if (a.chains.empty()) table << "  (no chain matches)\n";
  rec.table = table.str();
  rec.csv = csv.str();
  return rec;
}

analysis::Analysis make_catalog() {
  using namespace analysis;
  Analysis a;
  a.name = "catalog";
  a.command = {"catalog"};
  a.title = "ISO 606 chain catalogue: list, show, search, with sources";
  a.help =
      "the ISO 606 roller chain catalogue: all chains, one (catena catalog 12B) or a search "
      "(--search B); every cell's source in data/catalog/iso606/README.md";
  a.seed = "ISO 606";
  a.docs = "data/catalog/iso606/README.md";
  a.formats = {.table = true, .csv = true, .drawing = false};
  a.parameters = {
      text("chain", "ISO 606 chain to show (e.g. 12B; also without the flag)") | Positional{},
      text("search", "show the chains whose designation contains TEXT (e.g. B, 12)"),
  };
  a.check = check_catalog;
  set_functions<CatalogAnalysis>(a, catalog_analysis_run, describe_catalog);
  return a;
}

}  // namespace

CatalogAnalysis catalog_analysis_run(const Inputs& in) {
  CatalogAnalysis a;
  if (in.given("chain")) {
    const auto c = iso606_chain(in.text("chain"));
    if (!c)
      throw InputError(
          {{"chain", in.text("chain"), "an ISO 606 chain of the catalogue: " + names_list()}});
    a.single = true;
    a.chains.push_back(*c);
    return a;
  }
  const std::string needle = in.given("search") ? upper(in.text("search")) : "";
  for (const std::string& name : iso606_names()) {
    if (upper(name).find(needle) != std::string::npos) a.chains.push_back(*iso606_chain(name));
  }
  return a;
}

const analysis::Analysis& catalog_analysis() {
  static const analysis::Analysis a = make_catalog();
  return a;
}

}  // namespace catena::contact
