#include "cli_support.hpp"

#include <filesystem>
#include <system_error>

#include "catena/io/atomic_file.hpp"

namespace catena::cli {

namespace fs = std::filesystem;

void write_text_output(const std::string& output, const std::string& text,
                       const std::string& case_path) {
  Outputs outputs;
  if (!case_path.empty()) outputs.keep("CASE", case_path);
  if (!output.empty()) outputs.add("--output", output, text);
  outputs.commit(output.empty() ? text : "");
}

void Outputs::keep(std::string flag, std::string path) {
  kept_.push_back({std::move(flag), std::move(path), {}});
}

void Outputs::add(std::string flag, std::string path, std::string content) {
  // Two outputs to one file would leave only the last one there, while both are reported
  // written: refuse them, whatever the spelling of the path (links followed, hard links too).
  // An output onto the command's own input would replace what the user wrote.
  for (const File& f : kept_) {
    if (io::same_file(f.path, path))
      throw InputError({{flag, path,
                         "a file other than " + f.flag + " " + f.path +
                             " (the input read; writing it would replace it)"}});
  }
  // A character device (/dev/null) holds no content to be wrong: it takes any number.
  std::error_code error;
  const bool device = fs::is_character_file(io::output_target(path), error);
  for (const File& f : files_) {
    if (device || !io::same_file(f.path, path)) continue;
    const std::string target = io::output_target(path), other = io::output_target(f.path);
    const std::string both =
        target == other ? "both name " + target : other + " and " + target + " are one file";
    throw InputError(
        {{flag, path,
          "a file other than " + f.flag + "'s (" + both + "): each output needs its own file"}});
  }
  files_.push_back({std::move(flag), std::move(path), std::move(content)});
}

void Outputs::commit(const std::string& stdout_text) {
  // Open every file first (a path that cannot be written is the user's input: nothing is
  // written then), write them, and only when all are written rename them into place.
  std::vector<io::StagedFile> staged;
  staged.reserve(files_.size());
  for (const File& f : files_) {
    try {
      staged.emplace_back(f.path);
    } catch (const io::WriteError& error) {
      throw InputError(
          {{f.flag, f.path, "a writable file path (" + error.reason() + "); nothing was written"}});
    }
  }
  for (std::size_t i = 0; i < files_.size(); ++i) staged[i].write(files_[i].content);
  for (io::StagedFile& file : staged) file.commit();
  if (!stdout_text.empty()) io::write_stdout(stdout_text);
}

}  // namespace catena::cli
