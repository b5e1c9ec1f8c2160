#pragma once
// The warnings a scene gives while it loads (SceneOptions::warning).
#include <functional>
#include <set>
#include <string>

namespace foveate::detail {

/// A warning of the scene being loaded: once per distinct message per load,
/// to the SceneOptions::warning load_scene was given (ScopedSceneWarnings).
/// Outside a load with a sink it goes to stderr, once per process: nothing
/// else would tell repeated loads apart.
void warn_once(const std::string& message);

/// While it lives, warn_once on this thread goes to `sink` (when set), each
/// distinct message once: a load says each problem once, and each load says
/// it again (a second Python render of the same file has it in its notes).
class ScopedSceneWarnings {
 public:
  explicit ScopedSceneWarnings(std::function<void(const std::string&)> sink);
  ~ScopedSceneWarnings();
  ScopedSceneWarnings(const ScopedSceneWarnings&) = delete;
  ScopedSceneWarnings& operator=(const ScopedSceneWarnings&) = delete;

 private:
  friend void warn_once(const std::string& message);
  std::function<void(const std::string&)> sink_;
  std::set<std::string> said_;
  ScopedSceneWarnings* previous_ = nullptr;
};

}  // namespace foveate::detail
