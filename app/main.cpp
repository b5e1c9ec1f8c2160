// The foveate command: plan, render, bench and demo foveated rendering.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include "commands.hpp"
#include "foveate/bench/field_text.hpp"
#include "foveate/core/error.hpp"
#include "foveate/core/parse.hpp"
#include "invocation.hpp"
#include "messages.hpp"

#ifndef FOVEATE_VERSION
#define FOVEATE_VERSION "unknown"
#endif

namespace {

// "did you mean" for a misspelled option or command: the arguments left over
// against the options (or the commands) of the deepest command parsed.
void suggest(const CLI::App& app) {
  const CLI::App* at = &app;
  while (!at->get_subcommands().empty()) at = at->get_subcommands().front();
  std::vector<std::string> names;
  for (const CLI::Option* o : at->get_options()) {
    for (const std::string& n : o->get_lnames()) names.push_back("--" + n);
  }
  for (const CLI::App* sub : at->get_subcommands([](const CLI::App*) { return true; }))
    names.push_back(sub->get_name());
  for (std::string arg : app.remaining(true)) {
    arg = arg.substr(0, arg.find('='));
    const std::string best = foveate::closest_name(arg, names);
    if (best.empty()) continue;
    std::fprintf(stderr, "foveate: '%s': did you mean '%s'? (foveate%s%s --help lists them)\n",
                 arg.c_str(), best.c_str(), at == &app ? "" : " ", at->get_name().c_str());
    return;
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "foveate: foveated rendering driven by one acuity model, measured against native rendering"};
  foveate::app::set_invocation(argc, argv);
  app.set_version_flag("--version", std::string("foveate ") + FOVEATE_VERSION);
  app.require_subcommand(1);
  foveate::app::register_all_commands(app);
  // A first word that names no command (CLI11 would say only that a command
  // is required): named, with the closest command if one is close.
  if (argc > 1 && argv[1][0] != '-') {
    const std::string word = argv[1];
    std::vector<std::string> commands;
    for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
      commands.push_back(sub->get_name());
    if (std::find(commands.begin(), commands.end(), word) == commands.end()) {
      const std::string best = foveate::closest_name(word, commands);
      std::fprintf(stderr, "foveate: error: '%s' is not a command%s (foveate --help lists them)\n",
                   word.c_str(), best.empty() ? "" : ("; did you mean '" + best + "'?").c_str());
      return 2;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // CLI11 prints the message; --help and --version exit 0, every usage
    // error (unknown option, missing value, a value of the wrong type) 2.
    const int rc = app.exit(e);
    if (rc != 0) suggest(app);
    return rc == 0 ? 0 : 2;
  } catch (const foveate::bench::OptionError& e) {
    // The library names the field; the command line says the flag.
    std::fprintf(stderr, "foveate: error: %s\n", e.message(foveate::app::flag_for).c_str());
    return 1;
  } catch (const foveate::Error& e) {
    std::fprintf(stderr, "foveate: error: %s\n", e.what());
    return 1;
  } catch (const std::filesystem::filesystem_error& e) {
    // The file system refused (a read-only mount, a full disk, /proc): the
    // user's environment, not a bug.
    std::fprintf(stderr, "foveate: error: %s: %s\n",
                 e.path1().empty() ? "file system" : e.path1().c_str(), e.code().message().c_str());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "foveate: internal error: %s\n", e.what());
    return 3;
  }
  return 0;
}
