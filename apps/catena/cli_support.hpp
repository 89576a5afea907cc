// Output destinations shared by the subcommands: files written all or nothing, stdout last.
#pragma once

#include <string>
#include <vector>

#include "catena/core/error.hpp"

namespace catena::cli {

/// The outputs of one command, written all or nothing: every file goes to a temporary beside its
/// target first; only when all are written are they renamed into place. Then the text meant for
/// stdout is printed (when no --output file took it). An unwritable path, or two outputs to one
/// file, is invalid input; a write that fails once started (disk full) throws io::WriteError.
class Outputs {
 public:
  /// `flag` names the option the path came from, for the error message.
  void add(std::string flag, std::string path, std::string content);
  /// An input of the command (the case file) that no output may replace; `flag` names it.
  void keep(std::string flag, std::string path);
  /// Writes everything; `stdout_text` goes to stdout unless empty.
  void commit(const std::string& stdout_text = "");

 private:
  struct File {
    std::string flag, path, content;
  };
  std::vector<File> files_, kept_;
};

/// A command's text output: to the --output FILE when one is given, else to stdout. A
/// `case_path` (the file the command read) is kept: an --output onto it is refused.
void write_text_output(const std::string& output, const std::string& text,
                       const std::string& case_path = "");

}  // namespace catena::cli
