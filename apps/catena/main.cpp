// catena: command-line front end. One subcommand per analysis; no physics here.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/core/progress.hpp"
#include "catena/io/atomic_file.hpp"
#include "catena/io/case_file.hpp"
#include "cli_support.hpp"
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

// The candidate closest to `word`, when it is close enough to be a misspelling ("" otherwise).
std::string closest(const std::string& word, const std::vector<std::string>& candidates) {
  return catena::io::did_you_mean(word, candidates).value_or("");
}

// After a command-line error: the subcommand or flag the user probably meant, walking the
// arguments the way the parser does (subcommands first, then each word starting with "--" that
// the innermost subcommand does not know).
void suggest(const CLI::App& app, int argc, char** argv) {
  const CLI::App* at = &app;
  for (int i = 1; i < argc; ++i) {
    const std::string word = argv[i];
    if (word.rfind("--", 0) == 0 && word.size() > 2) {
      const std::string name = word.substr(0, word.find('='));
      if (at->get_option_no_throw(name) != nullptr) continue;
      std::vector<std::string> flags;
      for (const CLI::Option* o : at->get_options())
        for (const std::string& l : o->get_lnames()) flags.push_back("--" + l);
      const std::string hint = closest(name, flags);
      if (!hint.empty()) std::cerr << "catena: '" << name << "': did you mean '" << hint << "'?\n";
      return;
    }
    if (word.empty() || word[0] == '-') continue;
    const CLI::App* next = nullptr;
    std::vector<std::string> names;
    for (const CLI::App* sub : at->get_subcommands([](const CLI::App*) { return true; })) {
      names.push_back(sub->get_name());
      if (sub->get_name() == word) next = sub;
    }
    if (next != nullptr) {
      at = next;
    } else if (at == &app) {
      // the first word names no command: the closest command, if one is close
      const std::string hint = closest(word, names);
      if (!hint.empty()) std::cerr << "catena: '" << word << "': did you mean '" << hint << "'?\n";
      return;
    }
  }
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
    if (status != 0) suggest(app, argc, argv);
    return status == 0 ? 0 : 2;
  }
  try {
    // Ctrl-C while a command runs stops it at the run's next poll (catena::Cancelled)
    const catena::cli::InterruptGuard interrupt;
    for (auto& [name, action] : actions) {
      if (app.got_subcommand(name)) return action();
    }
  } catch (const catena::Cancelled&) {
    // 128 + SIGINT, as a shell reports a command that Ctrl-C ended
    std::cerr << "catena: interrupted (Ctrl-C); nothing was written\n";
    return 130;
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
