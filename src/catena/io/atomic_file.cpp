#include "catena/io/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>
#include <utility>

namespace catena::io {

namespace fs = std::filesystem;

WriteError::WriteError(std::string path, std::string reason, bool opening)
    : std::runtime_error("cannot write '" + path + "': " + reason),
      path_(std::move(path)),
      reason_(std::move(reason)),
      opening_(opening) {}

std::string output_target(const std::string& path) {
  if (path.empty()) return path;
  std::error_code error;
  fs::path p = fs::absolute(path, error);
  if (error) return path;
  // Follow a chain of links by hand: weakly_canonical leaves a dangling link unresolved, and
  // writing through it must create its target, not replace the link.
  for (int hops = 0; hops < 40 && fs::is_symlink(p, error); ++hops) {
    const fs::path next = fs::read_symlink(p, error);
    if (error) break;
    p = next.is_absolute() ? next : p.parent_path() / next;
  }
  const fs::path normal = fs::weakly_canonical(p, error);
  return (error ? p.lexically_normal() : normal).string();
}

StagedFile::StagedFile(const std::string& path) : path_(path), target_(output_target(path)) {
  if (path.empty()) throw WriteError(path, "the path is empty", true);
  struct stat st {};
  // A link that output_target could not resolve (a loop, or more than 40 links deep): writing
  // the temporary beside it and renaming would replace the link with a regular file.
  if (::lstat(target_.c_str(), &st) == 0 && S_ISLNK(st.st_mode))
    throw WriteError(path, "its symbolic links do not end in a file (a loop?)", true);
  const bool exists = ::stat(target_.c_str(), &st) == 0;
  if (exists && S_ISDIR(st.st_mode)) throw WriteError(path, "it is a folder", true);
  if (exists && !S_ISREG(st.st_mode)) {
    // A device or a FIFO: nothing can be renamed onto it, so it is written directly.
    fd_ = ::open(target_.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd_ < 0) throw WriteError(path, std::strerror(errno), true);
    return;
  }
  const fs::path target(target_);
  std::random_device random;
  for (int attempt = 0; attempt < 8 && fd_ < 0; ++attempt) {
    temporary_ =
        (target.parent_path() / (target.filename().string() + ".tmp" + std::to_string(random())))
            .string();
    fd_ = ::open(temporary_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd_ < 0 && errno != EEXIST) break;
  }
  if (fd_ < 0) {
    const std::string reason = std::strerror(errno);
    temporary_.clear();
    throw WriteError(path, reason, true);
  }
  // A replaced file keeps its permissions.
  if (exists) (void)::fchmod(fd_, st.st_mode & 07777);
}

StagedFile::StagedFile(StagedFile&& other) noexcept
    : path_(std::move(other.path_)),
      target_(std::move(other.target_)),
      temporary_(std::exchange(other.temporary_, {})),
      fd_(std::exchange(other.fd_, -1)) {}

StagedFile::~StagedFile() { discard(); }

void StagedFile::write(std::string_view content) {
  const char* data = content.data();
  std::size_t left = content.size();
  while (left > 0) {
    const ssize_t n = ::write(fd_, data, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const std::string reason = n < 0 ? std::strerror(errno) : "nothing was written";
      discard();
      throw WriteError(path_, reason, false);
    }
    data += n;
    left -= static_cast<std::size_t>(n);
  }
  // The data on the disk before the rename makes it visible: without this, a crash (or a
  // file system that reports a full disk only when it writes back, such as NFS) could leave
  // an empty or short file where the old one was. A device is not synced (it cannot be).
  if (!temporary_.empty() && ::fsync(fd_) != 0) {
    const std::string reason = std::strerror(errno);
    discard();
    throw WriteError(path_, reason, false);
  }
  const int fd = std::exchange(fd_, -1);
  if (::close(fd) != 0) {
    const std::string reason = std::strerror(errno);
    discard();
    throw WriteError(path_, reason, false);
  }
}

void StagedFile::commit() {
  if (fd_ >= 0) write({});
  if (temporary_.empty()) return;  // a device, written directly
  std::error_code error;
  fs::rename(temporary_, target_, error);
  if (error) {
    discard();
    throw WriteError(path_, error.message(), false);
  }
  temporary_.clear();
}

void StagedFile::discard() noexcept {
  if (fd_ >= 0) {
    ::close(fd_);
    fd_ = -1;
  }
  if (!temporary_.empty()) {
    std::error_code ignored;
    fs::remove(temporary_, ignored);
    temporary_.clear();
  }
}

void write_file_atomic(const std::string& path, std::string_view content) {
  StagedFile file(path);
  file.write(content);
  file.commit();
}

bool same_file(const std::string& a, const std::string& b) {
  if (output_target(a) == output_target(b)) return true;
  std::error_code error;  // a file that does not exist yet is no other one
  return fs::equivalent(a, b, error) && !error;
}

void write_stdout(std::string_view text) {
  errno = 0;
  const bool written = std::fwrite(text.data(), 1, text.size(), stdout) == text.size();
  if (std::fflush(stdout) != 0 || !written || std::ferror(stdout)) {
    const std::string reason = errno != 0 ? std::strerror(errno) : "write failed";
    std::clearerr(stdout);
    throw WriteError("stdout", reason, false);
  }
}

}  // namespace catena::io
