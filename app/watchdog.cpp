#include "watchdog.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <type_traits>

#include "foveate/core/error.hpp"
#include "foveate/gpu/gl.hpp"

namespace foveate::app {

FrameWatchdog::FrameWatchdog(double timeout_s, std::string scene)
    : timeout_s_(timeout_s), scene_(std::move(scene)) {
  if (timeout_s_ > 0) thread_ = std::thread([this] { watch(); });
}

FrameWatchdog::~FrameWatchdog() {
  if (!thread_.joinable()) return;
  {
    std::lock_guard<std::mutex> lock(mu_);
    stop_ = true;
  }
  cv_.notify_all();
  thread_.join();
}

void FrameWatchdog::arm(const std::string& what, double budget_scale) {
  if (timeout_s_ <= 0) return;
  {
    std::lock_guard<std::mutex> lock(mu_);
    armed_ = true;
    what_ = what;
    budget_s_ = timeout_s_ * std::max(1.0, budget_scale);
    deadline_ = std::chrono::steady_clock::now() +
                std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                    std::chrono::duration<double>(budget_s_));
  }
  cv_.notify_all();
}

void FrameWatchdog::disarm() {
  if (timeout_s_ <= 0) return;
  std::lock_guard<std::mutex> lock(mu_);
  armed_ = false;
}

void FrameWatchdog::finish_gpu() { glFinish(); }

void FrameWatchdog::watch() {
  std::unique_lock<std::mutex> lock(mu_);
  while (!stop_) {
    if (!armed_) {
      cv_.wait(lock);
      continue;
    }
    const auto deadline = deadline_;
    if (cv_.wait_until(lock, deadline) != std::cv_status::timeout) continue;
    if (!armed_ || stop_ || deadline_ != deadline) continue;  // finished, or a new frame
    // The frame is stuck inside the GL: nothing on the main thread can return
    // from the draw, so the process ends here (buffered output first).
    std::fflush(stdout);
    std::fprintf(stderr,
                 "foveate: error: scene '%s': %s did not finish within %g s (--frame-timeout); "
                 "stopped. A GL draw cannot be interrupted, so foveate exits here; raise "
                 "--frame-timeout for a slow scene or size (0 = no limit)\n",
                 scene_.c_str(), what_.c_str(), budget_s_);
    std::fflush(stderr);
    ::_exit(1);
  }
}

double check_frame_timeout(double seconds) {
  if (!(seconds >= 0 && seconds <= 86400)) {
    char got[32];
    std::snprintf(got, sizeof got, "%g", seconds);
    throw Error(std::string("--frame-timeout: expected 0 (no limit) to 86400 seconds, got ") + got);
  }
  return seconds;
}

}  // namespace foveate::app
