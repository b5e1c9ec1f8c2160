#pragma once
// Subcommands register themselves: each cmd_*.cpp defines a static
// CommandRegistrar, and main() adds every registered command to the CLI11 app.
// Registration order is the order of the `order` values (help output order).
#include <CLI/CLI.hpp>
#include <functional>

namespace foveate::app {

using RegisterFn = std::function<void(CLI::App&)>;

struct CommandRegistrar {
  CommandRegistrar(int order, RegisterFn fn);
};

void register_all_commands(CLI::App& app);

}  // namespace foveate::app
