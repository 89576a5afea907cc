// Binding text to an analysis' parameter table: every value a user typed (a flag's text, a case
// file's value) becomes an SI number, a whole number, a choice or a table, through the one
// quantity parser (UDUNITS-2). Every problem is collected, named by parameter key; the caller
// renames keys to what its user typed (--flag, analyses.hinge.key) and reports them all at once.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "catena/analysis/analysis.hpp"
#include "catena/core/error.hpp"
#include "catena/io/case_file.hpp"

namespace catena::io {

/// One value as a front end received it.
struct RawInput {
  enum class Type {
    kText,     ///< typed text ("64mm", "8", "tangential"), or a TOML string
    kNumber,   ///< a TOML number (its spelling in `text`)
    kBoolean,  ///< "true"/"false" (a CLI flag, a TOML boolean)
    kOther,    ///< a TOML array or other value no parameter takes
    kTable,    ///< a table of the case file (`table` holds its values)
  };
  std::string key;
  std::string text;
  Type type = Type::kText;
  std::vector<analysis::InputValue::Entry> table;  ///< kTable
  std::vector<std::string> tables;                 ///< kTable: every table's path
  std::string source;                              ///< kTable: the file
};

/// Binds `raw` to `analysis.parameters` (defaults and, with the `example` flag, example values
/// for what is absent), then applies the analysis' cross-field `check`. Appends every problem to
/// `issues`; values that could not be read are NaN (numbers) or absent.
analysis::Inputs bind(const analysis::Analysis& analysis, const std::vector<RawInput>& raw,
                      std::vector<Issue>& issues);

/// The problems of one value read on its own, as `bind` reads it (a unit, a number, a whole
/// number, a choice, the kind of value), without other values or the analysis' cross-field
/// `check`: what no other input can mend (a sweep checks its shared values with it).
std::vector<Issue> value_issues(const analysis::Parameter& parameter, const RawInput& raw);

/// The values of `file` under the table `parameter.name` ("loop." …) as the raw input of a table
/// parameter: every leaf with its path and line, every table's path, the file's name.
RawInput table_input(const CaseFile& file, const analysis::Parameter& parameter);

/// The command-line form of an analysis' inputs (long option without dashes, text) as raw
/// inputs, as `catena::run` and every sweep point take them: a table parameter's text is the TOML
/// file holding the table, read here (a file that cannot be read adds an issue naming the key and
/// the key to `unread`); a flag is a boolean; anything else is text.
std::vector<RawInput> raw_inputs(const analysis::Analysis& analysis,
                                 const std::vector<std::pair<std::string, std::string>>& inputs,
                                 std::vector<Issue>& issues, std::vector<std::string>& unread);

/// Binds `raw` to `analysis` and evaluates it, listening to `progress`; throws InputError with
/// `issues` and every binding problem (a key in `unread` is not reported again as missing).
analysis::Record bind_and_evaluate(const analysis::Analysis& analysis,
                                   const std::vector<RawInput>& raw, std::vector<Issue> issues,
                                   const std::vector<std::string>& unread,
                                   const Progress* progress);

/// The unit a bare number takes for `parameter` ("mm", "1/s"; its own `bare_unit` where set; ""
/// for plain numbers and text).
std::string bare_unit(const analysis::Parameter& parameter);

}  // namespace catena::io
