#pragma once
// The warnings a scene gives while it loads (SceneOptions::warning).
#include <functional>
#include <string>

namespace foveate::detail {

/// A warning of the scene being loaded, once per distinct message per
/// process, to the SceneOptions::warning load_scene was given (stderr when
/// none; ScopedSceneWarnings).
void warn_once(const std::string& message);

/// While it lives, warn_once on this thread goes to `sink` (when set).
class ScopedSceneWarnings {
 public:
  explicit ScopedSceneWarnings(std::function<void(const std::string&)> sink);
  ~ScopedSceneWarnings();
  ScopedSceneWarnings(const ScopedSceneWarnings&) = delete;
  ScopedSceneWarnings& operator=(const ScopedSceneWarnings&) = delete;

 private:
  std::function<void(const std::string&)> previous_;
};

}  // namespace foveate::detail
