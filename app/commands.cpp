#include "commands.hpp"

#include <algorithm>
#include <utility>
#include <vector>

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
}

}  // namespace foveate::app
