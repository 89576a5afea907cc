// One subcommand per analysis, built from its parameter table: a flag per parameter, the output
// options the analysis offers, and one action — bind, run, describe, write. Nothing here knows
// a model.
#include <CLI/CLI.hpp>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>

#include "catena/catena.hpp"
#include "catena/io/bind.hpp"
#include "catena/io/case_file.hpp"
#include "catena/io/drawing.hpp"
#include "catena/io/quantity.hpp"
#include "catena/io/record.hpp"
#include "cli_support.hpp"
#include "commands.hpp"

namespace catena::cli {
namespace {

using analysis::Parameter;
using analysis::ParameterType;

std::string flag_of(const std::string& key) {
  std::string flag = "--" + key;
  for (char& c : flag) c = c == '_' ? '-' : c;
  return flag;
}

// A model's and the binder's issues name parameter keys; the user typed flags.
std::vector<Issue> as_flags(const analysis::Analysis& a, std::vector<Issue> issues) {
  for (Issue& issue : issues) {
    const Parameter* p = a.parameter(issue.field);
    // an optional table is a --flag FILE here (a required one is the positional FILE)
    const bool optional_table = p && p->type == ParameterType::kTable && !p->required;
    if (a.renames(issue.field) || optional_table) issue.field = flag_of(issue.field);
  }
  return issues;
}

std::string help_of(const Parameter& p) {
  std::string help = p.doc;
  std::string notes;
  auto note = [&](const std::string& n) { notes += (notes.empty() ? "" : "; ") + n; };
  if (p.type == ParameterType::kQuantity) {
    note(std::string(kind_name(p.kind)) + ", bare number: " + io::default_unit(p.kind));
  }
  if (p.list) note("comma-separated list");
  if (p.required) note("required");
  if (!p.default_text.empty()) note("default " + p.default_text);
  if (!p.choices.empty()) {
    std::string c;
    for (const std::string& each : p.choices) c += (c.empty() ? "" : "|") + each;
    note(c);
  }
  return notes.empty() ? help : help + " (" + notes + ")";
}

struct State {
  std::map<std::string, std::string> texts;
  std::map<std::string, bool> flags;
  std::string format, output, csv, svg, dxf;
  bool allow_large = false;
};

// The case file's chain.type, when it has one.
std::optional<io::CaseValue> chain_type_of(const io::CaseFile& file) {
  const io::CaseValue* v = file.find("chain.type");
  if (v == nullptr) return std::nullopt;
  return *v;
}

// Adds the values the case file's chain type implies for the analysis (its Variant's `set`),
// unless one of them was given as a flag (the command line wins: the file's type is not read);
// a chain type the analysis does not take is an issue.
void apply_variant(const analysis::Analysis& a, const State& state, const io::CaseValue& type,
                   std::vector<io::RawInput>& raw, std::vector<Issue>& issues) {
  if (a.variants.empty()) return;
  // a flag of the variant's given on the command line wins: the file's type is not read
  for (const auto& [name, v] : a.variants) {
    for (const auto& [key, value] : v.set) {
      const auto given = state.texts.find(key);
      if (given != state.texts.end() && !given->second.empty()) return;
      const auto flag = state.flags.find(key);
      if (flag != state.flags.end() && flag->second) return;
    }
  }
  const std::string where = type.path + " (line " + std::to_string(type.line) + ")";
  const analysis::Analysis::Variant* variant = nullptr;
  std::string types;
  for (const auto& [name, v] : a.variants) {
    if (name == type.text && type.type == io::CaseValue::Type::kString) variant = &v;
    types += (types.empty() ? "" : ", ") + name;
  }
  if (variant == nullptr) {
    issues.push_back(
        {where, "'" + type.text + "'", "a chain type '" + a.name + "' takes: " + types});
    return;
  }
  for (const auto& [key, value] : variant->set) {
    const Parameter* param = a.parameter(key);
    const bool is_flag = param && param->type == ParameterType::kFlag;
    raw.push_back(
        {key, value, is_flag ? io::RawInput::Type::kBoolean : io::RawInput::Type::kText, {}, {}});
  }
}

}  // namespace

CLI::App* analysis_app(CLI::App& root, const analysis::Analysis& a) {
  CLI::App* parent = &root;
  for (std::size_t i = 0; i + 1 < a.command.size(); ++i)
    parent = parent->get_subcommand(a.command[i]);
  return parent->add_subcommand(a.command.back(), a.help.empty() ? a.title : a.help);
}

std::function<int()> add_analysis(CLI::App& root, const analysis::Analysis& a) {
  auto state = std::make_shared<State>();
  CLI::App* cmd = analysis_app(root, a);
  for (const Parameter& p : a.parameters) {
    std::string names = flag_of(p.name);
    if (p.positional) names = p.name + "," + names;  // also without the flag
    for (const std::string& alias : p.aliases) {
      names += ',';
      names += flag_of(alias);
    }
    if (p.type == ParameterType::kFlag) {
      cmd->add_flag(names, state->flags[p.name], p.doc);
      continue;
    }
    if (p.type == ParameterType::kTable) {  // a TOML file holding the table
      if (p.required) {
        cmd->add_option("FILE", state->texts[p.name], p.doc)->required();
      } else {  // an optional table: --name FILE
        cmd->add_option(names, state->texts[p.name], p.doc)->type_name("FILE");
      }
      continue;
    }
    CLI::Option* o = cmd->add_option(names, state->texts[p.name], help_of(p));
    if (!p.choices.empty()) o->check(CLI::IsMember(p.choices));
  }
  if (a.has_size_caps()) {
    cmd->add_flag("--allow-large", state->allow_large,
                  "run sizes (points, harmonics, nodes, count, slices) above their caps; "
                  "docs/reliability.md lists the caps and estimates");
  }
  std::vector<std::string> formats;
  if (a.formats.table) formats.push_back("table");
  formats.push_back("json");
  if (a.formats.csv) formats.push_back("csv");
  state->format = formats.front();
  std::string format_help;
  for (const std::string& f : formats) format_help += (format_help.empty() ? "" : "|") + f;
  cmd->add_option("--format", state->format,
                  "output: " + format_help + " (default " + formats.front() + ")")
      ->check(CLI::IsMember(formats));
  cmd->add_option("-o,--output", state->output, "write the output to FILE instead of stdout");
  if (a.formats.csv) cmd->add_option("--csv", state->csv, "also write the series as CSV to FILE");
  if (a.formats.drawing) {
    cmd->add_option("--svg", state->svg, "the drawing as SVG (mm)");
    cmd->add_option("--dxf", state->dxf, "the same drawing as DXF (R12, mm)");
  }
  return [state, &a, cmd]() {
    // A command below another (hinge sweep) also takes what its parent parsed before the
    // command's own name (`catena hinge --teeth 8 sweep`), unless given again after it.
    CLI::App* parent = a.command.size() > 1 ? cmd->get_parent() : nullptr;
    auto from_parent = [&](const std::string& name) -> const CLI::Option* {
      const CLI::Option* own = cmd->get_option_no_throw(name);
      if (parent == nullptr || own == nullptr || own->count() > 0) return nullptr;
      const CLI::Option* o = parent->get_option_no_throw(name);
      return o != nullptr && o->count() > 0 ? o : nullptr;
    };
    for (const Parameter& p : a.parameters) {
      if (const CLI::Option* o = from_parent(flag_of(p.name))) {
        if (p.type == ParameterType::kFlag) {
          state->flags[p.name] = true;
        } else if (!o->results().empty()) {
          state->texts[p.name] = o->results().back();
        }
      }
    }
    for (auto [name, text] :
         {std::pair{"--format", &state->format}, std::pair{"--output", &state->output},
          std::pair{"--csv", &state->csv}, std::pair{"--svg", &state->svg},
          std::pair{"--dxf", &state->dxf}}) {
      const CLI::Option* o = from_parent(name);
      if (o != nullptr && !o->results().empty()) *text = o->results().back();
    }
    if (const CLI::Option* o = from_parent("--allow-large")) state->allow_large = o->count() > 0;
    std::vector<io::RawInput> raw;
    std::optional<io::CaseValue> case_type;  // the positional case file's chain.type
    if (state->allow_large)
      raw.push_back(
          {std::string(analysis::kAllowLarge), "true", io::RawInput::Type::kBoolean, {}, {}});
    for (const Parameter& p : a.parameters) {
      if (p.type == ParameterType::kFlag) {
        if (state->flags[p.name])
          raw.push_back({p.name, "true", io::RawInput::Type::kBoolean, {}, {}});
      } else if (p.type == ParameterType::kTable) {
        const std::string& path = state->texts[p.name];
        if (!p.required && path.empty()) continue;  // an optional table not given
        std::ifstream in(path, std::ios::binary);
        if (!in)
          throw InputError({{p.required ? std::string("FILE") : flag_of(p.name), path,
                             "a readable TOML file with a [" + p.name + "] table"}});
        std::stringstream text;
        text << in.rdbuf();
        const io::CaseFile file = io::parse_case(text.str(), path);
        if (p.required) case_type = chain_type_of(file);
        raw.push_back(io::table_input(file, p));
      } else if (!state->texts[p.name].empty()) {
        raw.push_back({p.name, state->texts[p.name], io::RawInput::Type::kText, {}, {}});
      }
    }
    std::vector<Issue> issues;
    // the case file's chain.type chooses the analysis' variant, as `catena run` does, unless a
    // flag of the variant's (--chain-type) was given
    if (case_type) apply_variant(a, *state, *case_type, raw, issues);
    analysis::Inputs inputs = io::bind(a, raw, issues);
    throw_if_any(as_flags(a, std::move(issues)));
    inputs.want_drawing(!state->svg.empty() || !state->dxf.empty());
    analysis::Record record;
    {
      // progress on a terminal, and Ctrl-C, for the run (not for the writing that follows)
      ProgressBar bar;
      std::string label;
      for (const std::string& word : a.command) label += (label.empty() ? "" : " ") + word;
      const Progress progress = listen(bar, label);
      inputs.listen(&progress);
      try {
        record = a.evaluate(inputs);
      } catch (const InputError& error) {
        throw InputError(as_flags(a, error.issues()));
      }
      inputs.listen(nullptr);
    }
    std::string text;
    if (state->format == "json") {
      text = io::to_json(record.data);
    } else if (state->format == "csv") {
      text = record.csv.empty() ? io::to_csv(record.columns) : record.csv;
    } else {
      text = record.table;
    }
    // Everything is computed before anything is written, and written all or nothing.
    Outputs outputs;
    if (!state->svg.empty() || !state->dxf.empty()) {
      if (record.drawings.empty()) {
        throw InputError(
            {{state->svg.empty() ? "--dxf" : "--svg", "given", record.drawing_unavailable}});
      }
      if (!state->svg.empty())
        outputs.add("--svg", state->svg, io::to_svg(record.drawings.front()));
      if (!state->dxf.empty())
        outputs.add("--dxf", state->dxf, io::to_dxf(record.drawings.front()));
    }
    if (!state->csv.empty())
      outputs.add("--csv", state->csv,
                  record.csv.empty() ? io::to_csv(record.columns) : record.csv);
    if (!state->output.empty()) outputs.add("--output", state->output, text);
    outputs.commit(state->output.empty() ? text : "");
    if (!state->csv.empty()) std::cerr << "catena: wrote the series to " << state->csv << "\n";
    // An error diagnostic (a result that is not finite, a solve that did not converge) is named
    // on stderr too: the text table and CSV do not carry diagnostics, and a reader of them must
    // not take inf or nan for an answer. The exit status stays 0: the analysis ran, and its
    // diagnostics are part of the output (docs/cli.md).
    report_errors(record.diagnostics, "");
    return 0;
  };
}

std::map<std::string, std::function<int()>> register_analyses(CLI::App& app) {
  std::map<std::string, std::function<int()>> actions;
  // one below another (hinge sweep) runs when its own name was parsed, else its parent's action
  std::map<std::string, std::vector<std::pair<CLI::App*, std::function<int()>>>> children;
  for (const analysis::Analysis* a : catena::analyses()) {
    std::function<int()> action = add_analysis(app, *a);
    if (a->command.size() == 1) {
      actions[a->command.front()] = std::move(action);
      continue;
    }
    CLI::App* sub = app.get_subcommand(a->command.front());
    for (std::size_t i = 1; i < a->command.size(); ++i) sub = sub->get_subcommand(a->command[i]);
    children[a->command.front()].push_back({sub, std::move(action)});
  }
  for (auto& [name, subs] : children) {
    actions[name] = [own = actions[name], subs = subs]() {
      for (const auto& [sub, action] : subs) {
        if (sub->parsed()) return action();
      }
      return own();
    };
  }
  return actions;
}

}  // namespace catena::cli
