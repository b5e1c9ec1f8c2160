#include "progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

#include "cli_util.hpp"

namespace foveate::app {

Progress::Progress(std::string what, std::string unit, int total, bool enabled)
    : what_(std::move(what)),
      unit_(std::move(unit)),
      total_(std::max(total, 0)),
      enabled_(enabled && !quiet()),
      tty_(isatty(2) != 0),
      t0_(std::chrono::steady_clock::now()),
      last_(t0_) {
  kinds_.push_back({"", total_, 0, 0.0});
}

void Progress::expect(const std::string& kind, int count) {
  kinds_.push_back({kind, count, 0, 0.0});
  kinds_[0].expected -= count;
}

double time_left(const std::vector<StepKind>& kinds) {
  double total_s = 0;
  int total_n = 0;
  for (const StepKind& k : kinds) total_s += k.seconds, total_n += k.done;
  const double overall = total_n > 0 ? total_s / total_n : 0.0;
  double left = 0;
  for (const StepKind& k : kinds) {
    const double per = k.done > 0 ? k.seconds / k.done : overall;
    left += per * std::max(k.expected - k.done, 0);
  }
  return left;
}

double Progress::seconds_left() const { return time_left(kinds_); }

void Progress::step(const std::string& detail, const std::string& kind) {
  ++done_;
  const auto now = std::chrono::steady_clock::now();
  StepKind* k = &kinds_[0];
  for (StepKind& c : kinds_)
    if (c.name == kind) k = &c;
  ++k->done;
  k->seconds += std::chrono::duration<double>(now - last_).count();
  last_ = now;
  if (!enabled_ || finished_) return;
  const double el = std::chrono::duration<double>(now - t0_).count();
  // Work done within a second needs no progress (--verbose asks for every step).
  if (el < kQuietSeconds && !verbose()) return;
  shown_ = true;
  const double left = seconds_left();
  const int percent = total_ > 0 ? std::min(100, 100 * done_ / total_) : 100;
  if (tty_) {
    const int width = 30, filled = total_ > 0 ? std::min(width, width * done_ / total_) : width;
    std::fprintf(stderr, "\r%s [%s%s] %3d%% %d/%d  %s left  %-28.28s", what_.c_str(),
                 std::string(size_t(filled), '#').c_str(),
                 std::string(size_t(width - filled), '.').c_str(), percent, done_, total_,
                 format_duration(left).c_str(), detail.c_str());
  } else if (done_ < total_ && (verbose() || done_ % std::max(1, total_ / 10) == 0)) {
    std::fprintf(stderr, "%s: %d/%d %s, %s elapsed, about %s left\n", what_.c_str(), done_, total_,
                 unit_.c_str(), format_duration(el).c_str(), format_duration(left).c_str());
  }
  if (done_ >= total_) {
    finish();
  } else {
    std::fflush(stderr);
  }
}

void Progress::finish() {
  if (!enabled_ || finished_) return;
  finished_ = true;
  const double el = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
  if (!shown_ && el < kQuietSeconds) return;
  if (tty_ && shown_) std::fprintf(stderr, "\n");
  std::fprintf(stderr, "%s: %d/%d %s done in %s\n", what_.c_str(), done_, total_, unit_.c_str(),
               format_duration(el).c_str());
  std::fflush(stderr);
}

}  // namespace foveate::app
