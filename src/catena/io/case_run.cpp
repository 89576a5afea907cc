// The case runner: one TOML case file describes a chain system; every analysis it names binds
// its [analyses.<name>] table and the shared tables straight onto that analysis' parameter table
// (the registry's), runs, and becomes part of one JSON tree or one HTML report. Nothing here
// knows a model: a model added to the registry is in case files too. Used by `catena run`,
// `catena report` and the Python module's run_case/report.
#include "catena/io/case_run.hpp"

#include <algorithm>
#include <map>
#include <set>

#include "catena/catena.hpp"
#include "catena/io/bind.hpp"
#include "catena/io/record.hpp"
#include "catena/io/sha256.hpp"

namespace catena::io {

namespace {

using analysis::Analysis;
using analysis::Parameter;
using analysis::ParameterType;
using analysis::Value;

using analysis::Value;

// The case-file schema around the analyses (docs/case_files.md).
const std::vector<std::string> kChainTypes = {"rolling-hinge", "sliding-hinge", "roller-iso606",
                                              "round-link", "composite-link"};
// Shared tables: a key there goes to every analysis that has a parameter of that name.
const std::vector<std::string> kSharedTables = {"chain", "sprocket", "loads", "material"};
// Keys of the shared tables that describe rather than feed a parameter, and renamed keys.
const std::set<std::string> kDescriptive = {"chain.type", "chain.name", "chain.description"};
const std::map<std::string, std::string> kAliases = {{"chain.designation", "chain"}};
// Options that choose output destinations: the case runner owns those.
// An analysis table's `note`: the case's words on what the run shows (the report prints them
// under the section's title); not an option of the analysis.
constexpr std::string_view kNote = "note";
const std::set<std::string> kOutputFlags = {"help", "format", "output", "csv",
                                            "svg",  "dxf",    "example"};

std::string joined(const std::vector<std::string>& items) {
  std::string s;
  for (const std::string& item : items) s += (s.empty() ? "" : ", ") + item;
  return s;
}

std::string suggest(const std::string& word, const std::vector<std::string>& candidates) {
  const auto m = did_you_mean(word, candidates);
  return m ? " (did you mean '" + *m + "'?)" : std::string();
}

// The analysis a case table names: "pocketwheel", or "pocketwheel-<label>" for one of several
// runs of it (pocketwheel-free, pocketwheel-chordal).
const Analysis* analysis_named(const std::string& name) {
  for (const Analysis* a : catena::analyses()) {
    if (a->name == name || name.rfind(a->name + "-", 0) == 0) return a;
  }
  return nullptr;
}

RawInput::Type raw_type(CaseValue::Type type) {
  switch (type) {
    case CaseValue::Type::kString:
      return RawInput::Type::kText;
    case CaseValue::Type::kNumber:
      return RawInput::Type::kNumber;
    case CaseValue::Type::kBoolean:
      return RawInput::Type::kBoolean;
    case CaseValue::Type::kOther:
      break;
  }
  return RawInput::Type::kOther;
}

// One [analyses.<name>] table bound to its analysis' parameters, ready to run.
struct Planned {
  const Analysis* analysis;
  std::string name;
  std::vector<RawInput> raw;
  std::map<std::string, std::string> path_of;  ///< parameter key → the case-file path it came from
  std::string note;                            ///< the table's `note`, for the report
};

// The file's structure: top-level keys and tables, chain.type. Returns the chain type ("" when
// missing or unknown: the problem is recorded).
std::string check_structure(const CaseFile& file, std::vector<Issue>& issues) {
  std::vector<std::string> top = {"title", "description", "chain", "sprocket", "loads", "material"};
  for (const Analysis* a : catena::analyses()) {
    for (const Parameter& p : a->parameters) {
      if (p.type == ParameterType::kTable && std::find(top.begin(), top.end(), p.name) == top.end())
        top.push_back(p.name);  // [loop]
    }
  }
  top.push_back("analyses");
  for (const CaseValue& v : file.values) {
    const std::string head = v.path.substr(0, v.path.find('.'));
    if (std::find(top.begin(), top.end(), head) == top.end())
      issues.push_back({v.path, v.text, "a known key: " + joined(top) + suggest(head, top)});
  }
  for (const std::string& t : file.tables) {
    const std::string head = t.substr(0, t.find('.'));
    if (std::find(top.begin(), top.end(), head) == top.end() && t.find('.') == std::string::npos)
      issues.push_back(
          {t, "(table)",
           "a known table: " + joined({top.begin() + 2, top.end()}) + suggest(head, top)});
  }
  const CaseValue* type = file.find("chain.type");
  if (!type) {
    issues.push_back({"chain.type", "(missing)", "one of " + joined(kChainTypes)});
    return "";
  }
  if (std::find(kChainTypes.begin(), kChainTypes.end(), type->text) == kChainTypes.end()) {
    issues.push_back({"chain.type", "'" + type->text + "'",
                      "one of " + joined(kChainTypes) + suggest(type->text, kChainTypes)});
    return "";
  }
  return type->text;
}

// Shared values, key → value; each must feed at least one analysis.
std::map<std::string, const CaseValue*> shared_values(const CaseFile& file,
                                                      std::vector<Issue>& issues) {
  std::set<std::string> any_key;
  for (const Analysis* a : catena::analyses()) {
    for (const Parameter& p : a->parameters) {
      if (!p.cli_only) any_key.insert(p.name);
    }
  }
  const std::vector<std::string> candidates(any_key.begin(), any_key.end());
  std::map<std::string, const CaseValue*> shared;
  for (const CaseValue& v : file.values) {
    const std::string head = v.path.substr(0, v.path.find('.'));
    if (std::find(kSharedTables.begin(), kSharedTables.end(), head) == kSharedTables.end())
      continue;
    if (kDescriptive.count(v.path)) continue;
    if (v.path.size() == head.size()) {  // `chain = ...` at the top: a value, not the table
      issues.push_back({v.path, v.text, "a [" + head + "] table, not a value"});
      continue;
    }
    const std::string rest = v.path.substr(head.size() + 1);
    if (rest.find('.') != std::string::npos) {
      issues.push_back({v.path, v.text, "a value directly in [" + head + "]"});
      continue;
    }
    const auto alias = kAliases.find(v.path);
    const std::string key = alias != kAliases.end() ? alias->second : rest;
    if (!any_key.count(key)) {
      issues.push_back({v.path, v.text,
                        "a key some analysis takes" + suggest(rest, candidates) +
                            " (docs/case_files.md lists them)"});
      continue;
    }
    if (shared.count(key)) {
      issues.push_back({v.path, v.text,
                        "one value per key: '" + key + "' is also given as " + shared[key]->path});
      continue;
    }
    shared[key] = &v;
  }
  return shared;
}

// The analysis' own table, then the shared values it takes, then what the chain type implies.
Planned plan(const Analysis& a, const std::string& name, const CaseFile& file,
             const std::string& chain_type, const std::map<std::string, const CaseValue*>& shared,
             std::vector<Issue>& issues) {
  Planned p{&a, name, {}, {}};
  std::vector<std::string> key_names;
  for (const Parameter& param : a.parameters) {
    if (!param.cli_only && !kOutputFlags.count(param.name)) key_names.push_back(param.name);
  }
  std::map<std::string, const CaseValue*> given;
  const std::string prefix = "analyses." + name + ".";
  for (const CaseValue& v : file.values) {
    if (v.path.rfind(prefix, 0) != 0) continue;
    const std::string key = v.path.substr(prefix.size());
    const Parameter* param = a.parameter(key);
    if (key == analysis::kAllowLarge) {  // lifts the caps of the size parameters
      p.raw.push_back({key, v.text, raw_type(v.type), {}, {}});
      p.path_of[key] = v.path;
    } else if (key == kNote) {  // the case's words on this run: the report shows them
      if (v.type == CaseValue::Type::kString)
        p.note = v.text;
      else
        issues.push_back({v.path, v.text, "a text: what this run shows, for the report"});
    } else if (kOutputFlags.count(key)) {
      issues.push_back({v.path, v.text,
                        "no output option in a case file: 'catena report' and "
                        "'catena run' choose the outputs"});
    } else if (!param || param->cli_only) {
      issues.push_back({v.path, v.text,
                        "an option of '" + name + "'" + suggest(key, key_names) +
                            " (docs/cli.md lists them; '_' for '-')"});
    } else {
      given[key] = &v;
    }
  }
  const Analysis::Variant* variant = nullptr;
  for (const auto& [variant_type, v] : a.variants) {
    if (variant_type == chain_type) variant = &v;
  }
  for (const auto& [key, v] : shared) {
    const Parameter* param = a.parameter(key);
    const bool excluded =
        variant && std::find(variant->not_shared.begin(), variant->not_shared.end(), key) !=
                       variant->not_shared.end();
    if (param && !param->cli_only && !param->not_shared && !given.count(key) && !excluded)
      given[key] = v;
  }
  for (const auto& [key, v] : given) {
    p.path_of[key] = v->path;
    p.raw.push_back({key, v->text, raw_type(v->type), {}, {}});
  }
  for (const Parameter& param : a.parameters) {
    // a table parameter reads the case file's own table ([loop] and [[loop.segment]])
    if (param.type == ParameterType::kTable) p.raw.push_back(table_input(file, param));
  }
  if (variant) {
    for (const auto& [key, value] : variant->set) {
      const Parameter* param = a.parameter(key);
      const bool is_flag = param && param->type == ParameterType::kFlag;
      p.raw.push_back(
          {key, value, is_flag ? RawInput::Type::kBoolean : RawInput::Type::kText, {}, {}});
    }
  }
  return p;
}

// Binds and runs one planned analysis; its problems are named by the case file's paths.
void run_planned(const Planned& p, CaseRun& out, std::vector<Issue>& issues,
                 const Progress* progress) {
  const std::string where = "analyses." + p.name;
  std::vector<Issue> found;
  analysis::Inputs inputs = bind(*p.analysis, p.raw, found);
  inputs.want_drawing();  // the report shows the drawing
  inputs.listen(progress);
  if (found.empty()) {
    try {
      out.runs.push_back({p.analysis, p.name, p.analysis->evaluate(inputs), p.note});
    } catch (const InputError& e) {
      found = e.issues();
    }
  }
  for (Issue issue : found) {
    // name the case-file path the value came from, or where a missing one belongs
    const auto path = p.path_of.find(issue.field);
    if (!p.analysis->renames(issue.field)) {
      // it names the case file's own path and line already
    } else if (path != p.path_of.end()) {
      issue.field = path->second;
    } else if (p.analysis->parameter(issue.field)) {
      issue.field = where + "." + issue.field;
    } else {  // a model's field: named as the command line names it
      std::string flag = "--" + issue.field;
      for (char& c : flag) c = c == '_' ? '-' : c;
      issue.field = where + " (" + flag + ")";
    }
    issues.push_back(std::move(issue));
  }
}
// The unit a bare number in the case file takes: its parameter's (or its table field's).
std::string bare_unit_at(const CaseValue& v) {
  if (v.type != CaseValue::Type::kNumber) return "";
  for (const Analysis* a : catena::analyses()) {
    if (const Parameter* field = a->table_field(v.path)) return bare_unit(*field);
  }
  const auto alias = kAliases.find(v.path);
  const std::string key =
      alias != kAliases.end() ? alias->second : v.path.substr(v.path.rfind('.') + 1);
  for (const Analysis* a : catena::analyses()) {
    if (const Parameter* p = a->parameter(key)) {
      const std::string unit = bare_unit(*p);
      if (!unit.empty()) return unit;
    }
  }
  return "";
}

}  // namespace

std::vector<std::string> analysis_tables(const CaseFile& file) { return file.children("analyses"); }

CaseInputs case_inputs(const CaseFile& file, const std::string& name, std::vector<Issue>& issues) {
  CaseInputs out;
  const std::string chain_type = check_structure(file, issues);
  const auto shared = shared_values(file, issues);
  std::vector<std::string> names;
  for (const Analysis* a : catena::analyses()) {
    if (!a->chain_types.empty()) names.push_back(a->name);
  }
  const Analysis* a = analysis_named(name);
  if (a == nullptr || a->chain_types.empty()) {
    issues.push_back({"analyses." + name, "(table)",
                      "an analysis Catena has: " + joined(names) + suggest(name, names)});
    return out;
  }
  if (!chain_type.empty() &&
      std::find(a->chain_types.begin(), a->chain_types.end(), chain_type) == a->chain_types.end()) {
    issues.push_back({"analyses." + name, "(table)",
                      "an analysis for chain.type = " + chain_type + "; '" + name +
                          "' applies to " + joined(a->chain_types)});
    return out;
  }
  Planned p = plan(*a, name, file, chain_type, shared, issues);
  out.analysis = a;
  out.raw = std::move(p.raw);
  out.path_of = std::move(p.path_of);
  return out;
}

CaseRun run_case(const CaseFile& file, const Progress* progress) {
  CaseRun out{file, sha256_hex(file.text), {}};
  std::vector<Issue> issues;
  const std::string chain_type = check_structure(file, issues);
  const auto shared = shared_values(file, issues);

  std::vector<std::string> names;
  for (const Analysis* a : catena::analyses()) {
    if (!a->chain_types.empty()) names.push_back(a->name);
  }
  const std::vector<std::string> wanted = file.children("analyses");  // in file order
  for (const CaseValue& v : file.values) {
    if (v.path.rfind("analyses.", 0) == 0 &&
        v.path.find('.', std::string("analyses.").size()) == std::string::npos)
      issues.push_back({v.path, v.text, "a table [" + v.path + "] of that analysis' options"});
  }
  if (wanted.empty() && file.find("analyses") == nullptr) {
    issues.push_back(
        {"analyses", "(missing)", "at least one [analyses.<name>] table; names: " + joined(names)});
  }
  std::vector<Planned> planned;
  for (const std::string& name : wanted) {
    const Analysis* a = analysis_named(name);
    if (a == nullptr || a->chain_types.empty()) {
      issues.push_back({"analyses." + name, "(table)",
                        "an analysis Catena has: " + joined(names) + suggest(name, names)});
      continue;
    }
    if (!chain_type.empty() && std::find(a->chain_types.begin(), a->chain_types.end(),
                                         chain_type) == a->chain_types.end()) {
      issues.push_back({"analyses." + name, "(table)",
                        "an analysis for chain.type = " + chain_type + "; '" + name +
                            "' applies to " + joined(a->chain_types)});
      continue;
    }
    planned.push_back(plan(*a, name, file, chain_type, shared, issues));
  }
  // no stop before: the analyses that could be planned run too, so that a misspelt key and a
  // wrong unit elsewhere are reported together
  for (const Planned& p : planned) run_planned(p, out, issues, progress);
  throw_if_any(issues);
  return out;
}

Value result_tree(const CaseRun& run, std::string_view version) {
  Value j = Value::object();
  j["catena_version"] = version;
  j["case"] = run.file.name;
  j["case_sha256"] = run.hash;
  const CaseValue* title = run.file.find("title");
  j["title"] = title ? title->text : run.file.name;
  Value analyses = Value::object();
  for (const AnalysisRun& r : run.runs) analyses[r.name] = r.record.data;
  j["analyses"] = std::move(analyses);
  return j;
}

std::vector<ReportSection> report_sections(const std::vector<AnalysisRun>& runs) {
  std::vector<ReportSection> sections;
  for (const AnalysisRun& r : runs) {
    std::string section_title = r.analysis->title;
    if (r.name != r.analysis->name)
      section_title += " — " + r.name.substr(r.analysis->name.size() + 1);
    sections.push_back(report_section(r.record, r.name, section_title, r.analysis->docs));
    sections.back().note = r.note;
  }
  return sections;
}

Report build_report(const CaseRun& run, std::string_view version) {
  Report report;
  const CaseValue* title = run.file.find("title");
  report.title = title ? title->text : "Catena case " + run.file.name;
  report.case_name = run.file.name;
  report.case_hash = run.hash;
  report.version = std::string(version);
  if (const CaseValue* description = run.file.find("description"))
    report.description = description->text;
  for (const CaseValue& v : run.file.values) {
    // the description and the notes are prose the report prints where they belong
    const bool prose = v.path == "description" ||
                       (v.path.rfind("analyses.", 0) == 0 && v.path.size() > kNote.size() + 1 &&
                        v.path.ends_with("." + std::string(kNote)));
    if (!prose) report.inputs.push_back({v.path, v.text, bare_unit_at(v)});
  }
  report.sections = report_sections(run.runs);
  return report;
}

}  // namespace catena::io
