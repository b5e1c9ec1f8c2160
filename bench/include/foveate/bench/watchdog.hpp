#pragma once
// A frame whose GPU work runs past its budget stops the run with an error
// naming the scene and the frame. A GL draw cannot be interrupted (on
// llvmpipe the rasterizer threads run it to the end; on a GPU the driver
// does), so the check is a watchdog thread: when a frame is still unfinished
// at its deadline it calls the front end's timeout callback, which may end
// the process (the command line does); otherwise the frame's run() throws an
// OptionError of "frame_timeout_s" once the draw has returned. On a real GPU
// a draw that runs longer than the driver's own limit (Windows TDR: 2 s;
// Linux amdgpu and i915: about 10 s) makes the driver reset the GPU first.
#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <type_traits>

#include "foveate/bench/field_text.hpp"

namespace foveate::bench {

/// The default frame timeout in seconds: generous (a 1080p frame of the
/// slowest built-in scene takes about a second on llvmpipe).
inline constexpr double kDefaultFrameTimeoutS = 10.0;

/// Called on the watchdog's thread when a frame runs past its deadline,
/// with the error (which names {frame_timeout_s}); the frame's draw is
/// still running.
using FrameTimeoutFn = std::function<void(const FieldText& error)>;

/// Throws an OptionError of "frame_timeout_s" unless `seconds` is 0 (no
/// limit) or a number of seconds up to a day.
void check_frame_timeout(double seconds);

class FrameWatchdog {
 public:
  /// `timeout_s` 0 turns the watchdog off; `scene` names the scene in the error.
  FrameWatchdog(double timeout_s, std::string scene, FrameTimeoutFn on_timeout = {});
  ~FrameWatchdog();
  FrameWatchdog(const FrameWatchdog&) = delete;
  FrameWatchdog& operator=(const FrameWatchdog&) = delete;

  /// Runs `fn` (which draws one frame) and waits for its GPU work (glFinish)
  /// under a deadline of timeout x `budget_scale` (a supersampled reference of
  /// N x N samples gets N^2). `what` names the frame ("frame 3 (layered)").
  template <class Fn>
  auto run(const std::string& what, Fn&& fn, double budget_scale = 1.0) -> decltype(fn()) {
    arm(what, budget_scale);
    struct Disarm {
      FrameWatchdog* w;
      ~Disarm() { w->disarm(); }
    } guard{this};
    if constexpr (std::is_void_v<decltype(fn())>) {
      fn();
      finish_gpu();
      throw_if_expired();
    } else {
      auto result = fn();
      finish_gpu();
      throw_if_expired();
      return result;
    }
  }
  [[nodiscard]] double timeout_s() const { return timeout_s_; }

 private:
  void arm(const std::string& what, double budget_scale);
  void disarm();
  static void finish_gpu();
  void throw_if_expired();
  void watch();
  [[nodiscard]] FieldText expiry_error() const;

  double timeout_s_;
  std::string scene_;
  FrameTimeoutFn on_timeout_;
  std::mutex mu_;
  std::condition_variable cv_;
  bool armed_ = false;
  bool stop_ = false;
  bool expired_ = false;
  std::string what_;
  double budget_s_ = 0;
  std::chrono::steady_clock::time_point deadline_;
  std::thread thread_;
};

}  // namespace foveate::bench
