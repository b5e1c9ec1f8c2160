#include "scene_warnings.hpp"

#include <cstdio>
#include <mutex>
#include <set>
#include <utility>

namespace foveate::detail {

namespace {
thread_local std::function<void(const std::string&)> t_warning_sink;
}  // namespace

ScopedSceneWarnings::ScopedSceneWarnings(std::function<void(const std::string&)> sink)
    : previous_(std::exchange(t_warning_sink, std::move(sink))) {}
ScopedSceneWarnings::~ScopedSceneWarnings() { t_warning_sink = std::move(previous_); }

void warn_once(const std::string& message) {
  static std::mutex mutex;
  static std::set<std::string> said;
  {
    std::lock_guard<std::mutex> lock(mutex);
    if (!said.insert(message).second) return;
  }
  if (t_warning_sink) {
    t_warning_sink(message);
  } else {
    std::fprintf(stderr, "foveate: warning: %s\n", message.c_str());
  }
}

}  // namespace foveate::detail
