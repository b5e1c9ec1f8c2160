#pragma once
// Progress of a long command on stderr: a bar redrawn in place on a terminal,
// a plain line every tenth of the work otherwise (logs, CI); nothing with
// --quiet, and nothing for work done within a second (kQuietSeconds; with
// --verbose every step is shown). The estimate of the time left is the elapsed time per step times
// the steps left, so every slow part of the work must be a step.
#include <chrono>
#include <string>
#include <vector>

namespace foveate::app {

/// Steps of one kind: how many are expected, how many are done and the
/// seconds they took.
struct StepKind {
  std::string name;
  int expected = 0, done = 0;
  double seconds = 0;
};
/// The time left: for every kind, the steps left times its mean time per step
/// (a kind not yet seen counts at the mean of all steps so far).
double time_left(const std::vector<StepKind>& kinds);

/// Work that ends within this many seconds shows no progress at all.
inline constexpr double kQuietSeconds = 1.0;

class Progress {
 public:
  /// `what` names the work in plain lines ("render", "bench"); `unit` the
  /// steps ("frames"). Enabled unless --quiet, or when `enabled` is false.
  Progress(std::string what, std::string unit, int total, bool enabled = true);
  /// Steps of different cost (rendering, metrics): `count` of the total are
  /// of `kind`. The time left is then the sum over kinds of the steps left
  /// times that kind's mean time per step so far.
  void expect(const std::string& kind, int count);
  /// One step done; `detail` says what it was (shown on a terminal), `kind`
  /// which of the expected kinds it was (empty: the rest).
  void step(const std::string& detail = {}, const std::string& kind = {});
  /// Seconds left by the estimate above.
  [[nodiscard]] double seconds_left() const;
  /// Ends the bar's line on a terminal (called by the last step too).
  void finish();
  [[nodiscard]] int done() const { return done_; }
  [[nodiscard]] int total() const { return total_; }

 private:
  std::string what_, unit_;
  int total_, done_ = 0;
  bool enabled_, tty_, finished_ = false;
  bool shown_ = false;  ///< a line or the bar was printed
  std::chrono::steady_clock::time_point t0_, last_;
  std::vector<StepKind> kinds_;  ///< the first is "" (the rest of the total)
};

}  // namespace foveate::app
