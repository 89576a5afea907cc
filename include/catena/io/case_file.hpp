// Case files: one TOML file describes a chain system and the analyses to run on it. This layer
// only reads the file into a flat list of values with their dotted paths; what the keys mean is
// decided by the program's analysis registry (apps/catena/case_command.cpp). See
// docs/case_files.md for the schema.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "catena/core/error.hpp"

namespace catena::io {

/// One leaf value of a case file.
struct CaseValue {
  enum class Type { kString, kNumber, kBoolean, kOther };
  std::string path;  ///< dotted path, e.g. "chain.pitch", "analyses.hinge.plate_radius"
  std::string text;  ///< the value as a flag would take it: "125 mm", "8", "true"
  Type type = Type::kString;
  int line = 0;  ///< 1-based line in the file
};

/// A parsed case file: its leaf values in file order and the paths of all its tables.
struct CaseFile {
  std::string name;                 ///< where it came from (file name or "built-in")
  std::string text;                 ///< the file's text, as read
  std::vector<CaseValue> values;    ///< every leaf, in file order
  std::vector<std::string> tables;  ///< every table's path, empty ones included ("analyses.hinge")

  /// The value at `path`, if the file has one.
  const CaseValue* find(std::string_view path) const;
  /// The tables directly under `parent` ("analyses" → "hinge", "contact"), in file order.
  std::vector<std::string> children(std::string_view parent) const;
};

/// Parses TOML text. A syntax error throws InputError naming name:line:column and the parser's
/// message. Numbers keep the spelling of the file where TOML allows (1.5e3 stays 1.5e3);
/// an array of tables ([[loop.segment]]) is flattened element by element with 0-based indices
/// ("loop.segment[2].length"; tables "loop.segment" and "loop.segment[2]"); other arrays are kept
/// as one kOther value (no analysis takes an array yet).
CaseFile parse_case(std::string_view text, std::string name);

/// The largest case file read [bytes]. A case is a few kilobytes; a file near this size is not
/// one (a log, an image, /dev/zero), and reading it whole would only exhaust memory.
inline constexpr std::size_t kMaxCaseFileBytes = std::size_t{16} << 20;

/// Reads and parses the case file at `path`. Throws InputError (field "CASE") for an empty path,
/// a folder, a file that cannot be read, or one larger than kMaxCaseFileBytes, naming its size
/// and the cap (a regular file's size is asked before reading; anything else is read no further
/// than the cap, so endless inputs such as /dev/zero end too).
CaseFile read_case(const std::string& path);

/// The candidate closest to `word` by edit distance, when close enough to be a likely typo
/// (distance ≤ max(2, |word|/3)); nothing otherwise.
std::optional<std::string> did_you_mean(std::string_view word,
                                        const std::vector<std::string>& candidates);

}  // namespace catena::io
