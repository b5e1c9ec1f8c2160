#pragma once
// Progress of a long command on stderr: a bar redrawn in place on a terminal,
// a plain line every tenth of the work otherwise (logs, CI); nothing with
// --quiet. The estimate of the time left is the elapsed time per step times
// the steps left, so every slow part of the work must be a step.
#include <chrono>
#include <string>

namespace foveate::app {

class Progress {
 public:
  /// `what` names the work in plain lines ("render", "bench"); `unit` the
  /// steps ("frames"). Enabled unless --quiet, or when `enabled` is false.
  Progress(std::string what, std::string unit, int total, bool enabled = true);
  /// One step done; `detail` says what it was (shown on a terminal).
  void step(const std::string& detail = {});
  /// Ends the bar's line on a terminal (called by the last step too).
  void finish();
  [[nodiscard]] int done() const { return done_; }
  [[nodiscard]] int total() const { return total_; }

 private:
  std::string what_, unit_;
  int total_, done_ = 0;
  bool enabled_, tty_, finished_ = false;
  std::chrono::steady_clock::time_point t0_;
};

}  // namespace foveate::app
