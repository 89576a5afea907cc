#include "catena/io/bind.hpp"

#include <algorithm>
#include <sstream>

#include "catena/io/quantity.hpp"

namespace catena::io {

using analysis::InputValue;
using analysis::Parameter;
using analysis::ParameterType;

std::string bare_unit(const Parameter& parameter) {
  if (parameter.type != ParameterType::kQuantity) return "";
  return parameter.bare_unit.empty() ? default_unit(parameter.kind) : parameter.bare_unit;
}

RawInput table_input(const CaseFile& file, const Parameter& parameter) {
  RawInput raw;
  raw.key = parameter.name;
  raw.type = RawInput::Type::kTable;
  raw.text = "[" + parameter.name + "]";
  raw.source = file.name;
  const std::string prefix = parameter.name + ".";
  for (const CaseValue& v : file.values) {
    if (v.path.rfind(prefix, 0) != 0) continue;
    raw.table.push_back({v.path, v.text, v.line, v.type == CaseValue::Type::kString,
                         v.type == CaseValue::Type::kNumber, v.type == CaseValue::Type::kBoolean});
  }
  raw.tables = file.tables;
  return raw;
}

namespace {

std::vector<std::string> split_commas(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream ss(text);
  std::string part;
  while (std::getline(ss, part, ',')) out.push_back(part);
  return out;
}

std::string one_of(const std::vector<std::string>& choices) {
  std::string s;
  for (const std::string& c : choices) s += (s.empty() ? "" : ", ") + c;
  return "one of " + s;
}

// Parses one text of a scalar parameter into `v`.
void parse_scalar(const Parameter& p, const std::string& text, InputValue& v,
                  std::vector<Issue>& issues) {
  switch (p.type) {
    case ParameterType::kQuantity:
      v.number = parse_quantity(text, p.kind, p.name, issues).value_or(NAN);
      break;
    case ParameterType::kNumber:
      v.number = parse_number(text, p.name, p.expected.empty() ? "a number" : p.expected, issues)
                     .value_or(NAN);
      break;
    case ParameterType::kInteger:
      v.integer = parse_integer(text, p.name, p.min_integer, issues).value_or(p.min_integer);
      v.number = static_cast<double>(v.integer);
      break;
    case ParameterType::kChoice: {
      bool known = false;
      for (const std::string& c : p.choices) known = known || c == text;
      if (!known) issues.push_back({p.name, "'" + text + "'", one_of(p.choices)});
      break;
    }
    case ParameterType::kFlag:
    case ParameterType::kText:
    case ParameterType::kTable:
      break;
  }
}

}  // namespace

std::vector<Issue> value_issues(const Parameter& p, const RawInput& raw) {
  std::vector<Issue> issues;
  if (p.type == ParameterType::kFlag) {
    if (raw.type != RawInput::Type::kBoolean) issues.push_back({p.name, raw.text, "true or false"});
    return issues;
  }
  if (p.type == ParameterType::kTable) {
    if (raw.type != RawInput::Type::kTable) issues.push_back({p.name, raw.text, "a table"});
    return issues;
  }
  if (raw.type == RawInput::Type::kBoolean || raw.type == RawInput::Type::kOther ||
      raw.type == RawInput::Type::kTable) {
    const std::string unit = bare_unit(p);
    issues.push_back({p.name, raw.text,
                      "a number or a string with a unit" +
                          (unit.empty() ? std::string() : " (bare number: " + unit + ")")});
    return issues;
  }
  InputValue v;
  if (p.list) {
    for (const std::string& part : split_commas(raw.text)) parse_scalar(p, part, v, issues);
    if (raw.text.empty()) parse_scalar(p, "", v, issues);
  } else {
    parse_scalar(p, raw.text, v, issues);
  }
  return issues;
}

analysis::Inputs bind(const analysis::Analysis& a, const std::vector<RawInput>& raw,
                      std::vector<Issue>& issues) {
  analysis::Inputs in(&a.parameters);
  std::vector<const RawInput*> given(a.parameters.size(), nullptr);
  for (const RawInput& r : raw) {
    if (r.key == analysis::kAllowLarge) {  // not a parameter: lifts the caps of the sizes
      if ((r.type == RawInput::Type::kBoolean || r.type == RawInput::Type::kText) &&
          (r.text == "true" || r.text == "false"))
        in.allow_large(r.text == "true");
      else
        issues.push_back({r.key, r.text, "true or false"});
      continue;
    }
    bool found = false;
    for (std::size_t i = 0; i < a.parameters.size(); ++i) {
      if (a.parameters[i].name == r.key) {
        given[i] = &r;
        found = true;
      }
    }
    if (!found) issues.push_back({r.key, r.text, "an input of '" + a.name + "'"});
  }
  // flags first: --example decides what absent values become
  for (std::size_t i = 0; i < a.parameters.size(); ++i) {
    const Parameter& p = a.parameters[i];
    if (p.type != ParameterType::kFlag) continue;
    InputValue& v = in.set(p.name);
    if (!given[i]) continue;
    if (given[i]->type != RawInput::Type::kBoolean) {
      issues.push_back({p.name, given[i]->text, "true or false"});
      continue;
    }
    v.given = v.present = true;
    v.text = given[i]->text;
    v.flag = given[i]->text == "true";
  }
  const bool example = !a.example_doc.empty() && in.flag("example");
  for (std::size_t i = 0; i < a.parameters.size(); ++i) {
    const Parameter& p = a.parameters[i];
    if (p.type == ParameterType::kFlag) continue;
    InputValue& v = in.set(p.name);
    const RawInput* r = given[i];
    if (p.type == ParameterType::kTable) {
      if (r && r->type == RawInput::Type::kTable) {
        v.given = v.present = true;
        v.table = r->table;
        v.tables = r->tables;
        v.source = r->source;
        v.text = r->text;
      } else if (r) {
        issues.push_back({p.name, r->text, "a table"});
      } else if (p.required) {
        issues.push_back({p.name, "(missing)", p.expected.empty() ? "a table" : p.expected});
      }
      continue;
    }
    if (r && (r->type == RawInput::Type::kBoolean || r->type == RawInput::Type::kOther)) {
      const std::string unit = bare_unit(p);
      issues.push_back({p.name, r->text,
                        "a number or a string with a unit" +
                            (unit.empty() ? std::string() : " (bare number: " + unit + ")")});
      continue;
    }
    if (r) {
      v.given = true;
      v.text = r->text;
    } else if (example && !p.example.empty()) {
      v.text = p.example;
    } else if (!p.default_text.empty()) {
      v.text = p.default_text;
    } else {
      if (p.required) {
        std::string expected = p.expected.empty() ? "a value" : p.expected;
        if (!a.example_doc.empty() && !p.example.empty())
          expected += " (or --example for the paper's example)";
        issues.push_back({p.name, "(missing)", expected});
      }
      continue;
    }
    v.present = true;
    if (p.list) {
      v.parts = split_commas(v.text);
      if (v.parts.empty()) v.parts.push_back("");
      for (const std::string& part : v.parts) {
        InputValue one;
        parse_scalar(p, part, one, issues);
        v.list.push_back(one.number);
      }
      v.number = v.list.front();
    } else {
      parse_scalar(p, v.text, v, issues);
    }
  }
  for (Issue& issue : a.size_issues(in)) issues.push_back(std::move(issue));
  if (a.check) a.check(in, issues);
  return in;
}

std::vector<RawInput> raw_inputs(const analysis::Analysis& analysis,
                                 const std::vector<std::pair<std::string, std::string>>& inputs,
                                 std::vector<Issue>& issues, std::vector<std::string>& unread) {
  std::vector<RawInput> raw;
  for (const auto& [key, text] : inputs) {
    const analysis::Parameter* p = analysis.parameter(key);
    if (p != nullptr && p->type == analysis::ParameterType::kTable) {  // the file of the table
      try {
        raw.push_back(table_input(read_case(text), *p));
      } catch (const InputError& e) {
        unread.push_back(key);
        for (const Issue& issue : e.issues())
          issues.push_back({key, text,
                            "a readable TOML file with a [" + p->name + "] table (" + issue.field +
                                " = " + issue.value + ": " + issue.expected + ")"});
      }
      continue;
    }
    const bool is_flag = p != nullptr && p->type == analysis::ParameterType::kFlag;
    raw.push_back({key, text, is_flag ? RawInput::Type::kBoolean : RawInput::Type::kText, {}, {}});
  }
  return raw;
}

analysis::Record bind_and_evaluate(const analysis::Analysis& analysis,
                                   const std::vector<RawInput>& raw, std::vector<Issue> issues,
                                   const std::vector<std::string>& unread,
                                   const Progress* progress) {
  std::vector<Issue> bound;
  analysis::Inputs in = bind(analysis, raw, bound);
  in.listen(progress);
  for (Issue& issue : bound) {  // not again as missing
    if (std::find(unread.begin(), unread.end(), issue.field) == unread.end())
      issues.push_back(std::move(issue));
  }
  throw_if_any(issues);
  return analysis.evaluate(in);
}

}  // namespace catena::io
