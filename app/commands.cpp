#include "commands.hpp"

#include <algorithm>
#include <functional>
#include <utility>
#include <vector>

#include "cli_util.hpp"

namespace foveate::app {

namespace {
std::vector<std::pair<int, RegisterFn>>& registry() {
  static std::vector<std::pair<int, RegisterFn>> r;
  return r;
}
}  // namespace

CommandRegistrar::CommandRegistrar(int order, RegisterFn fn) {
  registry().emplace_back(order, std::move(fn));
}

void register_all_commands(CLI::App& app) {
  auto& r = registry();
  std::stable_sort(r.begin(), r.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  for (auto& [order, fn] : r) fn(app);
  // --quiet and --verbose on every command that runs (not on groups like gaze).
  std::function<void(CLI::App*)> add = [&](CLI::App* sub) {
    const auto children = sub->get_subcommands([](CLI::App*) { return true; });
    if (!children.empty()) {
      for (CLI::App* c : children) add(c);
      return;
    }
    sub->add_flag_callback(
        "--quiet", [] { verbosity() = Verbosity::Quiet; },
        "Only the results: no progress, notes or warnings on stderr (errors still)");
    sub->add_flag_callback(
        "--verbose", [] { verbosity() = Verbosity::Verbose; },
        "More on stderr: the renderer, display and gaze source, a progress line per step");
  };
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) add(sub);
}

}  // namespace foveate::app
