// Fuzzes every registered analysis through catena::run, the entry point of the command line,
// case files, Python and sweeps. Structure-aware, so that mutations reach the models and not only
// the parser: the input is lines of text,
//
//   line 1             the analysis: its name, or any other text (a hash of it picks one)
//   key=value          a parameter: its key, or any other text (a hash picks one of the
//                      analysis' parameters); the value is the rest of the line
//   key                a parameter without a value: "true" (flags), "" for the others
//
// A table parameter (loop's [loop]) takes the rest of the input as the TOML file that holds it,
// written to a temporary file whose path is the value, as on the command line. Size parameters
// are clamped (fuzz_support.hpp). Findings: anything thrown but InputError, a sanitizer report,
// a result that is not finite without an error diagnostic.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "catena/analysis/analysis.hpp"
#include "catena/catena.hpp"
#include "catena/core/error.hpp"
#include "catena/io/record.hpp"
#include "fuzz_support.hpp"

namespace {

std::size_t hash(std::string_view text) {
  std::size_t h = 0;
  for (const char c : text) h = h * 31 + static_cast<unsigned char>(c);
  return h;
}

// The file a table parameter's text is written to; one per process.
const std::string& table_path() {
  static const std::string path =
      "/tmp/catena-fuzz-table-" + std::to_string(static_cast<long>(getpid())) + ".toml";
  return path;
}

void write_file(const std::string& path, std::string_view text) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (f == nullptr) catena::fuzz::fail("cannot write " + path);
  const bool written = std::fwrite(text.data(), 1, text.size(), f) == text.size();
  if (std::fclose(f) != 0 || !written) catena::fuzz::fail("cannot write " + path);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string_view rest(reinterpret_cast<const char*>(data), size);
  auto next_line = [&rest]() {
    const std::size_t end = rest.find('\n');
    const std::string_view line = rest.substr(0, end);
    rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 1);
    return line;
  };

  const std::vector<const catena::analysis::Analysis*>& all = catena::analyses();
  const std::string_view first = next_line();
  const catena::analysis::Analysis* analysis = catena::find_analysis(first);
  if (analysis == nullptr) analysis = all[hash(first) % all.size()];
  const std::vector<catena::analysis::Parameter>& parameters = analysis->parameters;
  if (parameters.empty()) catena::fuzz::fail(analysis->name + " has no parameters");

  std::vector<std::pair<std::string, std::string>> inputs;
  while (!rest.empty()) {
    const std::string_view line = next_line();
    const std::size_t eq = line.find('=');
    const std::string_view key_text = line.substr(0, eq);
    const catena::analysis::Parameter* p = analysis->parameter(key_text);
    if (p == nullptr) p = &parameters[hash(key_text) % parameters.size()];
    if (p->type == catena::analysis::ParameterType::kTable) {
      // the value and everything after it: the TOML file holding the table
      const std::string_view value =
          eq == std::string_view::npos ? std::string_view() : line.substr(eq + 1);
      write_file(table_path(), std::string(value) + (rest.empty() ? "" : "\n") + std::string(rest));
      inputs.emplace_back(p->name, table_path());
      break;
    }
    std::string value = eq == std::string_view::npos
                            ? (p->type == catena::analysis::ParameterType::kFlag ? "true" : "")
                            : std::string(line.substr(eq + 1));
    inputs.emplace_back(p->name, catena::fuzz::clamp_size(p->name, value));
  }

  // The ring solver's own defaults grow without bound with the inputs (harmonics
  // 2·ceil(100/(1 − r1/r2)), sweep nodes ∝ harmonics·r2/r1): without a value given, the harness
  // gives the caps, so that a ring of r1 → r2 or r1 → 0 does not run for minutes.
  if (analysis->name == "ring") {
    bool harmonics = false, nodes = false, sweep = false;
    for (const auto& [key, value] : inputs) {
      harmonics = harmonics || key == "harmonics";
      nodes = nodes || key == "nodes";
      sweep = sweep || (key == "method" && value.find("sweep") != std::string::npos);
    }
    if (!harmonics)
      inputs.emplace_back("harmonics", std::to_string(catena::fuzz::size_cap("harmonics")));
    if (sweep && !nodes)
      inputs.emplace_back("nodes", std::to_string(catena::fuzz::size_cap("nodes")));
  }

  try {
    const catena::analysis::Record record = catena::run(analysis->name, inputs);
    catena::fuzz::check_record(record, analysis->name);
    // the writers every front end uses
    if (catena::io::to_json(record.data).empty()) catena::fuzz::fail("an empty JSON result");
    if (!record.columns.empty()) (void)catena::io::to_csv(record.columns);
  } catch (const catena::InputError&) {
    // invalid input: every problem listed, named by parameter key
  } catch (const std::exception& e) {
    if (!catena::fuzz::known_defect(analysis->name, e)) throw;  // a finding
  }
  return 0;
}
