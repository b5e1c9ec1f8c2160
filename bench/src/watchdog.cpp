#include "foveate/bench/watchdog.hpp"

#include <algorithm>
#include <cstdio>

#include "foveate/core/parse.hpp"
#include "foveate/gpu/gl.hpp"

namespace foveate::bench {

void check_frame_timeout(double seconds) {
  if (!(seconds >= 0 && seconds <= 86400)) {
    throw OptionError("frame_timeout_s",
                      "expected 0 (no limit) to 86400 seconds, got " + format_number(seconds));
  }
}

FrameWatchdog::FrameWatchdog(double timeout_s, std::string scene, FrameTimeoutFn on_timeout)
    : timeout_s_(timeout_s), scene_(std::move(scene)), on_timeout_(std::move(on_timeout)) {
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
    expired_ = false;
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

FieldText FrameWatchdog::expiry_error() const {
  return {"scene '" + scene_ + "': " + what_ + " did not finish within " +
              format_number(budget_s_) + " s ({frame_timeout_s}); stopped",
          {"frame_timeout_s"}};
}

void FrameWatchdog::throw_if_expired() {
  std::lock_guard<std::mutex> lock(mu_);
  if (!expired_) return;
  // The front end let the run go on: the frame finished late, and the run
  // ends here with the same error.
  FieldText error = expiry_error();
  error.text +=
      " once the draw returned (a GL draw cannot be interrupted); raise {frame_timeout_s} for a "
      "slow scene or size (0 = no limit)";
  throw OptionError("frame_timeout_s", error);
}

void FrameWatchdog::watch() {
  std::unique_lock<std::mutex> lock(mu_);
  while (!stop_) {
    if (!armed_ || expired_) {
      cv_.wait(lock);
      continue;
    }
    const auto deadline = deadline_;
    if (cv_.wait_until(lock, deadline) != std::cv_status::timeout) continue;
    if (!armed_ || stop_ || deadline_ != deadline) continue;
    expired_ = true;
    const FieldText error = expiry_error();
    // The frame is stuck inside the GL: the callback may end the process.
    lock.unlock();
    if (on_timeout_) on_timeout_(error);
    lock.lock();
  }
}

}  // namespace foveate::bench
