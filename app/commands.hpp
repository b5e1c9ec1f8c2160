#pragma once
// Each subcommand of the foveate command registers itself on the CLI11 app.
#include <CLI/CLI.hpp>

namespace foveate::app {

void register_plan(CLI::App& app);

}  // namespace foveate::app
