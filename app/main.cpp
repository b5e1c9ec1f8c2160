// The foveate command: plan, render, bench and demo foveated rendering.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>

#include "commands.hpp"
#include "foveate/core/error.hpp"
#include "run_environment.hpp"

#ifndef FOVEATE_VERSION
#define FOVEATE_VERSION "unknown"
#endif

int main(int argc, char** argv) {
  CLI::App app{
      "foveate: foveated rendering driven by one acuity model, measured against native rendering"};
  foveate::app::set_invocation(argc, argv);
  app.set_version_flag("--version", std::string("foveate ") + FOVEATE_VERSION);
  app.require_subcommand(1);
  foveate::app::register_all_commands(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const foveate::Error& e) {
    std::fprintf(stderr, "foveate: error: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "foveate: internal error: %s\n", e.what());
    return 3;
  }
  return 0;
}
