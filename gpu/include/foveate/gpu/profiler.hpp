#pragma once
// Time per pass: where a technique's frame goes. A PassProfiler is made
// current for a frame; techniques open a ProfileScope around each pass (the
// scope does nothing when no profiler is current, so it costs nothing in an
// application). On software renderers (llvmpipe) GPU timer queries are
// meaningless, so each pass is bracketed with glFinish and timed with a
// steady clock; on a real GPU GL_TIMESTAMP queries are read back when the
// frame ends, and the pipeline is not drained between passes.
#include <chrono>
#include <string>
#include <vector>

#include "foveate/gpu/gl.hpp"

namespace foveate::gpu {

struct PassTime {
  std::string name;
  double ms = 0.0;  ///< summed over the frame's passes of this name
};

class PassProfiler {
 public:
  enum class Clock { Finish, TimerQuery };
  /// `Finish` on software renderers, `TimerQuery` where queries are meaningful.
  static Clock clock_for_current_renderer();
  explicit PassProfiler(Clock clock = clock_for_current_renderer());
  PassProfiler(const PassProfiler&) = delete;
  PassProfiler& operator=(const PassProfiler&) = delete;
  ~PassProfiler();

  /// Starts a frame and makes this profiler current (scopes report to it).
  void begin_frame();
  /// Ends the frame: resolves the queries, and makes no profiler current.
  /// Returns the frame's passes in first-seen order, time summed by name.
  const std::vector<PassTime>& end_frame();
  [[nodiscard]] Clock clock() const { return clock_; }

  /// The profiler of the frame in progress, or null.
  static PassProfiler* current();

  void begin(const char* name);
  void end();

 private:
  struct Open {
    std::string name;
    std::chrono::steady_clock::time_point t0;
    size_t query = 0;  ///< index of the begin timestamp (TimerQuery)
  };
  GLuint timestamp_query();
  Clock clock_;
  int depth_ = 0;  ///< nested scopes are folded into the outermost
  Open open_;
  std::vector<GLuint> queries_;  ///< timestamp pairs of this frame
  size_t used_ = 0;
  std::vector<std::pair<std::string, std::pair<size_t, size_t>>> pending_;  ///< name, queries
  std::vector<PassTime> frame_;
};

/// Times the enclosed GL work as pass `name` of the current profiler.
class ProfileScope {
 public:
  explicit ProfileScope(const char* name) : profiler_(PassProfiler::current()) {
    if (profiler_) profiler_->begin(name);
  }
  ~ProfileScope() {
    if (profiler_) profiler_->end();
  }
  ProfileScope(const ProfileScope&) = delete;
  ProfileScope& operator=(const ProfileScope&) = delete;

 private:
  PassProfiler* profiler_;
};

}  // namespace foveate::gpu
