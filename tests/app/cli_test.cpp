// The command line's own logic without a GL context: the library's fields
// written as flags, durations for people and the progress estimate.
#include <gtest/gtest.h>

#include "cli_util.hpp"
#include "foveate/bench/bench.hpp"
#include "messages.hpp"
#include "progress.hpp"

using namespace foveate;
using namespace foveate::app;

TEST(Flags, LibraryErrorsNameTheFlag) {
  EXPECT_EQ(flag_for("frame_timeout_s"), "--frame-timeout");
  EXPECT_EQ(flag_for("params"), "--param");
  EXPECT_EQ(flag_for("no_such_field"), "");
  bench::BenchOptions o;
  o.frames = 0;
  try {
    bench::validate(o);
    FAIL() << "frames 0 accepted";
  } catch (const bench::OptionError& e) {
    EXPECT_EQ(e.message(flag_for), "--frames: expected 1..100000");
  }
  EXPECT_EQ(with_flags({"{gaze} pupil: pass {allow_fallback}", {"gaze", "allow_fallback"}}),
            "--gaze pupil: pass --allow-fallback");
}

TEST(Durations, ReadLikeAClock) {
  EXPECT_EQ(format_duration(4.4), "4 s");
  EXPECT_EQ(format_duration(125), "2 min 05 s");
  EXPECT_EQ(format_duration(7300), "2 h 01 min");
}

TEST(Progress, TimeLeftWeighsEachKindOfStepByItsOwnPace) {
  // 10 frames of 1 s rendered, 2 of 10 metrics steps of 30 s done: what is
  // left is 8 slow steps (240 s) and 5 frames (5 s), not 15 steps at the
  // overall mean.
  std::vector<StepKind> k = {{"", 15, 10, 10.0}, {"metrics", 10, 2, 60.0}};
  EXPECT_DOUBLE_EQ(time_left(k), 5 * 1.0 + 8 * 30.0);
  // A kind not seen yet counts at the mean of all steps so far.
  k[1] = {"metrics", 4, 0, 0.0};
  EXPECT_DOUBLE_EQ(time_left(k), 5 * 1.0 + 4 * 1.0);
  // Done: nothing left.
  EXPECT_DOUBLE_EQ(time_left({{"", 3, 3, 9.0}}), 0.0);
}
