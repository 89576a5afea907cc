// catena: command-line front end. One subcommand per analysis; no physics here.
#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>

#include "catena/core/error.hpp"
#include "catena/io/atomic_file.hpp"
#include "commands.hpp"

namespace {

// What a command printed through std::cout (--help, --version) reaches stdout only here, at the
// end: a stdout that cannot take it (/dev/full) makes the command fail, never exit 0 silently.
// Outputs written through io::write_stdout were checked already and report their own error.
int finish(int status) {
  // std::endl flushed already and failed: its errno is the one to name
  const int earlier = std::cout ? 0 : errno;
  errno = 0;
  std::cout.flush();
  const bool failed = !std::cout || std::fflush(stdout) != 0 || std::ferror(stdout);
  if (!failed || status != 0) return status;
  const int reason = errno != 0 ? errno : earlier;
  std::cerr << "catena: cannot write 'stdout': "
            << (reason != 0 ? std::strerror(reason) : "write failed") << "\n";
  return 1;
}

int run(int argc, char** argv) {
  CLI::App app{"Catena: chain conveyor and chain drive engineering toolkit"};
  app.set_version_flag("--version", std::string("catena ") + CATENA_VERSION);
  app.require_subcommand(1);
  auto actions = catena::cli::register_analyses(app);
  actions["run"] = catena::cli::add_run(app);
  actions["report"] = catena::cli::add_report(app);
  actions["sweep"] = catena::cli::add_sweep(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    // --help and --version exit 0; every other command-line error is invalid input: status 2.
    const int status = app.exit(error);
    return status == 0 ? 0 : 2;
  }
  try {
    for (auto& [name, action] : actions) {
      if (app.got_subcommand(name)) return action();
    }
  } catch (const catena::InputError& error) {
    std::cerr << "catena: " << error.what() << "\n";
    return 2;
  } catch (const catena::io::WriteError& error) {
    // The output could not be written (disk full, stdout closed): not the input's fault.
    std::cerr << "catena: " << error.what() << "\n";
    return 1;
  } catch (const std::exception& error) {
    std::cerr << "catena: internal error: " << error.what() << "\n";
    return 1;
  }
  return 1;
}

}  // namespace

int main(int argc, char** argv) { return finish(run(argc, argv)); }
