#include "scene_warnings.hpp"

#include <cstdio>
#include <mutex>
#include <utility>

namespace foveate::detail {

namespace {
thread_local ScopedSceneWarnings* t_scope = nullptr;
}  // namespace

ScopedSceneWarnings::ScopedSceneWarnings(std::function<void(const std::string&)> sink)
    : sink_(std::move(sink)), previous_(std::exchange(t_scope, this)) {}
ScopedSceneWarnings::~ScopedSceneWarnings() { t_scope = previous_; }

void warn_once(const std::string& message) {
  if (t_scope && t_scope->sink_) {
    if (t_scope->said_.insert(message).second) t_scope->sink_(message);
    return;
  }
  static std::mutex mutex;
  static std::set<std::string> said;
  {
    const std::lock_guard<std::mutex> lock(mutex);
    if (!said.insert(message).second) return;
  }
  std::fprintf(stderr, "foveate: warning: %s\n", message.c_str());
}

}  // namespace foveate::detail
