// Output files are written whole or not at all: a temporary file beside the target, then rename.
// Every write, flush, close and the rename is checked; a failure is an error naming the path.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace catena::io {

/// An output that could not be written. `opening()` tells a path that cannot be written at all
/// (a missing folder, no permission, a folder where a file is due: the user's input is wrong)
/// from a write that failed once started (disk full, I/O error: the environment failed).
class WriteError : public std::runtime_error {
 public:
  WriteError(std::string path, std::string reason, bool opening);
  const std::string& path() const { return path_; }
  const std::string& reason() const { return reason_; }
  bool opening() const { return opening_; }

 private:
  std::string path_, reason_;
  bool opening_;
};

/// The file that writing `path` changes: a symbolic link is followed to its final target (the
/// link itself is kept), and the result is absolute and normal, so two outputs to one file can
/// be recognised whatever their spelling.
std::string output_target(const std::string& path);

/// Whether writing `a` and writing `b` change the same file: the same target after links are
/// followed, or two names (hard links) of one existing file.
bool same_file(const std::string& a, const std::string& b);

/// One output file, written whole or not at all. A regular file (or a new one) is written to a
/// temporary beside its target and renamed into place by commit(); a symbolic link is followed,
/// so its target is replaced and the link stays a link; a path that is not a regular file (a
/// character device such as /dev/null or /dev/full, a FIFO) is written directly, since nothing
/// can be renamed onto it; a link that ends in no file (a loop) is refused. The temporary is
/// synced to the disk before the rename. Throws WriteError on every failure; an uncommitted
/// temporary is removed on destruction.
class StagedFile {
 public:
  /// Opens the temporary (or the device). Throws WriteError with opening() = true.
  explicit StagedFile(const std::string& path);
  StagedFile(const StagedFile&) = delete;
  StagedFile& operator=(const StagedFile&) = delete;
  StagedFile(StagedFile&& other) noexcept;
  StagedFile& operator=(StagedFile&&) = delete;
  ~StagedFile();

  /// Writes all of `content` and closes the file; a short write, a failed close: WriteError.
  void write(std::string_view content);
  /// Renames the temporary onto the target (nothing for a device). Throws WriteError.
  void commit();
  /// Removes the temporary if it has not been committed.
  void discard() noexcept;

 private:
  std::string path_, target_, temporary_;
  int fd_ = -1;
};

/// Writes `content` to `path` atomically (StagedFile). Throws WriteError naming the path on
/// failure; the target is then left as it was.
void write_file_atomic(const std::string& path, std::string_view content);

/// Writes `text` to stdout and flushes it. Throws WriteError ("stdout") when it cannot, e.g.
/// when stdout is /dev/full or a closed pipe.
void write_stdout(std::string_view text);

}  // namespace catena::io
