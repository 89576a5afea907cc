// Runs the built catena program (path in CATENA_CLI) and captures its status, stdout, stderr.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>

#include "../read_text.hpp"

struct CliRun {
  int status = -1;
  std::string out;
  std::string err;
};

inline CliRun run(const std::string& args) {
  const auto dir = std::filesystem::temp_directory_path();
  const std::string err_path = (dir / ("catena_cli_err_" + std::to_string(::getpid()))).string();
  const std::string command = std::string(CATENA_CLI) + " " + args + " 2>" + err_path;
  CliRun r;
  FILE* pipe = ::popen(command.c_str(), "r");
  std::array<char, 4096> buffer{};
  std::size_t n = 0;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
    r.out.append(buffer.data(), n);
  const int status = ::pclose(pipe);
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.err = read_text(err_path);
  std::filesystem::remove(err_path);
  return r;
}
