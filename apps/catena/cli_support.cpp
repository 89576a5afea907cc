#include "cli_support.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>

namespace catena::cli {

void write_text_output(const std::string& output, const std::string& text) {
  Outputs outputs;
  if (!output.empty()) outputs.add("--output", output, text);
  outputs.commit(output.empty() ? text : "");
}

void Outputs::add(std::string flag, std::string path, std::string content) {
  files_.push_back({std::move(flag), std::move(path), std::move(content), {}});
}

void Outputs::commit(const std::string& stdout_text) {
  namespace fs = std::filesystem;
  auto discard = [&] {
    for (File& f : files_) {
      std::error_code ignored;
      if (!f.temporary.empty()) fs::remove(f.temporary, ignored);
    }
  };
  std::random_device random;
  for (File& f : files_) {
    f.temporary = f.path + ".tmp" + std::to_string(random());
    std::ofstream out(f.temporary, std::ios::binary | std::ios::trunc);
    out.write(f.content.data(), static_cast<std::streamsize>(f.content.size()));
    out.close();
    if (!out) {
      const std::string reason = std::strerror(errno);
      discard();
      throw InputError(
          {{f.flag, f.path, "a writable file path (" + reason + "); nothing was written"}});
    }
  }
  for (File& f : files_) {
    std::error_code error;
    fs::rename(f.temporary, f.path, error);
    if (error) {
      discard();
      throw InputError({{f.flag, f.path, "a writable file path (" + error.message() + ")"}});
    }
    f.temporary.clear();
  }
  if (!stdout_text.empty()) std::cout << stdout_text << std::flush;
}

}  // namespace catena::cli
