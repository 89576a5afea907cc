// Fuzzes the case-file reader and the case runner: TOML text → io::parse_case → io::run_case →
// the JSON result tree and the HTML report, as `catena run` and `catena report` do. Bad input
// must end in InputError; anything else thrown, a sanitizer report, or a result that is not
// finite without an error diagnostic is a finding (tests/fuzz/fuzz_support.hpp).
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>
#include <string_view>

#include "catena/core/error.hpp"
#include "catena/io/case_file.hpp"
#include "catena/io/case_run.hpp"
#include "catena/io/record.hpp"
#include "catena/io/report.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  catena::io::CaseFile file;
  try {
    file = catena::io::parse_case(text, "fuzz.toml");
  } catch (const catena::InputError&) {
    return 0;  // malformed TOML: the message names the line; nothing more to run
  }
  // The size parameters of every analysis table, kept small (fuzz_support.hpp: size_cap).
  for (catena::io::CaseValue& value : file.values) {
    const std::size_t dot = value.path.rfind('.');
    const std::string_view key = std::string_view(value.path).substr(dot + 1);
    value.text = catena::fuzz::clamp_size(key, value.text);
  }
  // The ring solver's defaults grow without bound with the inputs (analysis_fuzz.cpp): a ring
  // table without harmonics (or nodes, for the sweep method) is given the caps.
  for (const std::string& table : catena::io::analysis_tables(file)) {
    if (table.substr(0, table.find('-')) != "ring") continue;
    const std::string at = "analyses." + table + ".";
    auto add = [&](const char* key) {
      if (file.find(at + key) != nullptr) return;
      file.values.push_back({at + key, std::to_string(catena::fuzz::size_cap(key)),
                             catena::io::CaseValue::Type::kNumber, 0});
    };
    add("harmonics");
    const catena::io::CaseValue* method = file.find(at + "method");
    if (method != nullptr && method->text.find("sweep") != std::string::npos) add("nodes");
  }
  try {
    const catena::io::CaseRun run = catena::io::run_case(file);
    for (const catena::io::AnalysisRun& r : run.runs)
      catena::fuzz::check_record(r.record, "case analysis " + r.name);
    const std::string json = catena::io::to_json(catena::io::result_tree(run, "fuzz"));
    const std::string html = catena::io::to_html(catena::io::build_report(run, "fuzz"), "");
    if (json.empty() || html.empty()) catena::fuzz::fail("an empty JSON tree or report");
  } catch (const catena::InputError&) {
    // invalid values: every problem listed, named by case-file path
  } catch (const std::exception& e) {
    bool known = false;  // one of the case's analyses has a known defect (fuzz_support.hpp)
    for (const std::string& table : catena::io::analysis_tables(file))
      known = known || catena::fuzz::known_defect(table.substr(0, table.find('-')), e);
    if (!known) throw;  // a finding
  }
  return 0;
}
