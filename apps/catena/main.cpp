// catena: command-line front end. One subcommand per analysis; no physics here.
#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>

#include "catena/core/error.hpp"
#include "commands.hpp"

int main(int argc, char** argv) {
  CLI::App app{"Catena: chain conveyor and chain drive engineering toolkit"};
  app.set_version_flag("--version", std::string("catena ") + CATENA_VERSION);
  app.require_subcommand(1);
  auto pocketwheel = catena::cli::add_pocketwheel(app);
  auto hinge = catena::cli::add_hinge(app);
  auto contact = catena::cli::add_contact(app);
  auto fretting = catena::cli::add_fretting(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    // --help and --version exit 0; every other command-line error is invalid input: status 2.
    const int status = app.exit(error);
    return status == 0 ? 0 : 2;
  }
  try {
    if (app.got_subcommand("pocketwheel")) return pocketwheel();
    if (app.got_subcommand("hinge")) return hinge();
    if (app.got_subcommand("contact")) return contact();
    if (app.got_subcommand("fretting")) return fretting();
  } catch (const catena::InputError& error) {
    std::cerr << "catena: " << error.what() << "\n";
    return 2;
  } catch (const std::exception& error) {
    std::cerr << "catena: internal error: " << error.what() << "\n";
    return 1;
  }
  return 1;
}
