// The gaze filter's rules and the latency estimator, on hand-made samples.
#include "foveate/gaze/filter.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "foveate/core/error.hpp"
#include "foveate/gaze/latency.hpp"

namespace foveate::gaze {
namespace {

const Display kDisplay;  // desktop-1080p: about 41.4 px per degree at the centre

/// A normalized point `deg` degrees to the right of the centre.
Vec2d right_of_centre(double deg) {
  return {0.5 + kDisplay.radius_px_at(deg) / kDisplay.width_px, 0.5};
}

TEST(GazeFilter, ConfidenceGateHoldsTheLastConfidentGaze) {
  GazeFilter f({}, kDisplay);
  FilteredGaze g = f.update({0.00, {0.3, 0.3}, 0.9, true}, 0.00);
  EXPECT_TRUE(g.valid);
  EXPECT_FALSE(g.holding);
  EXPECT_DOUBLE_EQ(g.pos.x, 0.3);
  g = f.update({0.01, {0.9, 0.9}, 0.59, true}, 0.01);  // below 0.6
  EXPECT_TRUE(g.holding);
  EXPECT_DOUBLE_EQ(g.pos.x, 0.3);
  EXPECT_DOUBLE_EQ(g.sample_time_s, 0.0);
  g = f.update({0.02, {0.9, 0.9}, 0.6, true}, 0.02);  // at the threshold: accepted
  EXPECT_FALSE(g.holding);
  EXPECT_DOUBLE_EQ(g.pos.x, 0.9);
  EXPECT_EQ(f.counters().low_confidence, 1u);
  EXPECT_EQ(f.counters().accepted, 3u);
}

TEST(GazeFilter, HoldsThroughABlinkForHalfASecondThenFallsBackToTheCentre) {
  FilterOptions o;
  o.fallback_fovea_scale = 2.0;
  GazeFilter f(o, kDisplay);
  // 128 Hz: times are exact binary fractions, so the 0.5 s bound is exact too.
  const double dt = 1.0 / 128;
  for (int k = 0; k < 10; ++k) f.update({k * dt, {0.2, 0.7}, 1.0, true}, k * dt);
  FilteredGaze g;
  // Invalid samples (eye closed) until 0.5 s after the last valid one.
  for (int k = 10; k <= 9 + 64; ++k) {
    g = f.update({k * dt, {0.0, 0.0}, 0.0, false}, k * dt);
    ASSERT_TRUE(g.holding) << k;
    ASSERT_TRUE(g.valid);
    ASSERT_FALSE(g.fallback);
    ASSERT_DOUBLE_EQ(g.pos.x, 0.2);
    ASSERT_DOUBLE_EQ(g.fovea_scale, 1.0);
  }
  double t = 74 * dt;
  g = f.update({t, {0.0, 0.0}, 0.0, false}, t);
  EXPECT_TRUE(g.fallback);
  EXPECT_FALSE(g.valid);
  EXPECT_DOUBLE_EQ(g.pos.x, 0.5);
  EXPECT_DOUBLE_EQ(g.pos.y, 0.5);
  EXPECT_DOUBLE_EQ(g.fovea_scale, 2.0);
  EXPECT_EQ(f.counters().fallbacks, 1u);
  EXPECT_EQ(f.counters().hold_frames, 64u);
  // The eye is back: followed at once, wherever it is (no deadband after a loss).
  g = f.update({t + 0.01, {0.21, 0.7}, 1.0, true}, t + 0.01);
  EXPECT_FALSE(g.fallback);
  EXPECT_FALSE(g.holding);
  EXPECT_DOUBLE_EQ(g.pos.x, 0.21);
  EXPECT_DOUBLE_EQ(g.fovea_scale, 1.0);
}

TEST(GazeFilter, ASourceThatStopsDeliveringIsHeldThenDropped) {
  GazeFilter f({}, kDisplay);
  const GazeSample s{1.0, {0.4, 0.4}, 1.0, true};
  EXPECT_FALSE(f.update(s, 1.0).holding);
  EXPECT_FALSE(f.update(s, 1.05).holding);  // same sample again: not new, not stale yet
  EXPECT_TRUE(f.update(s, 1.2).holding);    // older than stale_s = 0.1
  EXPECT_TRUE(f.update(s, 1.5).valid);
  EXPECT_TRUE(f.update(s, 1.51).fallback);  // older than hold_s = 0.5
  EXPECT_EQ(f.counters().repeats, 4u);
  EXPECT_EQ(f.counters().dropped.total(), 0u);  // repeats are not duplicates
}

TEST(GazeFilter, DeadbandIgnoresJitterButFollowsRealMoves) {
  FilterOptions o;
  o.deadband_deg = 0.3;
  GazeFilter f(o, kDisplay);
  f.update({0.00, right_of_centre(0.0), 1.0, true}, 0.00);
  FilteredGaze g = f.update({0.01, right_of_centre(0.2), 1.0, true}, 0.01);  // 20 deg/s
  EXPECT_DOUBLE_EQ(g.pos.x, 0.5);
  g = f.update({0.02, right_of_centre(-0.25), 1.0, true}, 0.02);
  EXPECT_DOUBLE_EQ(g.pos.x, 0.5);
  g = f.update({0.03, right_of_centre(0.35), 1.0, true}, 0.03);  // beyond 0.3 deg of the output
  EXPECT_DOUBLE_EQ(g.pos.x, right_of_centre(0.35).x);
  EXPECT_EQ(f.counters().deadband_suppressed, 2u);
  EXPECT_EQ(f.counters().saccades, 0u);
}

/// A 10 degree main-sequence saccade from the centre to the right, sampled at 1 kHz.
std::vector<GazeSample> saccade_samples(double& duration) {
  const MainSequence ms;
  const double amp = 10.0;
  duration = ms.duration_s(amp);
  const double a = profile_exponent_for_ratio(ms.peak_velocity_deg_per_s(amp) * duration / amp);
  std::vector<GazeSample> out;
  for (int k = 0; k <= 200; ++k) {
    const double t = k * 0.001;  // the saccade runs from 0.05 s
    const double u = (t - 0.05) / duration;
    out.push_back({t, right_of_centre(amp * profile_position(u, a)), 1.0, true});
  }
  return out;
}

TEST(GazeFilter, DetectsSaccadesByVelocity) {
  double dur = 0;
  GazeFilter f({}, kDisplay);
  int saccade_frames = 0;
  double first = -1, last = -1;
  for (const GazeSample& s : saccade_samples(dur)) {
    const FilteredGaze g = f.update(s, s.time_s);
    if (g.in_saccade) {
      ++saccade_frames;
      if (first < 0) first = s.time_s;
      last = s.time_s;
    }
  }
  EXPECT_EQ(f.counters().saccades, 1u);
  // Above 100 deg/s for most of its 43 ms, none outside it.
  EXPECT_GT(first, 0.05);
  EXPECT_LT(last, 0.05 + dur + 1e-9);
  EXPECT_GT(saccade_frames, 25);
}

TEST(GazeFilter, PredictsTheLandingPointFromThePeakVelocity) {
  double dur = 0;
  FilterOptions o;
  o.predict_landing = true;
  GazeFilter f(o, kDisplay);
  const Vec2d landing = right_of_centre(10.0);
  for (const GazeSample& s : saccade_samples(dur)) {
    const FilteredGaze g = f.update(s, s.time_s);
    // Past the peak (mid-saccade) but before the end: the raw gaze is still
    // degrees short, the prediction within a degree of the landing point.
    if (s.time_s > 0.05 + 0.6 * dur && s.time_s < 0.05 + 0.7 * dur) {
      ASSERT_TRUE(g.in_saccade);
      EXPECT_GT(angle_between_deg(kDisplay, s.pos, landing), 1.5);
      EXPECT_LT(angle_between_deg(kDisplay, g.pos, landing), 1.0);
    }
  }
  // After the saccade the output settles on the landing point (no deadband lag).
  const FilteredGaze end = f.update({0.3, landing, 1.0, true}, 0.3);
  EXPECT_FALSE(end.in_saccade);
  EXPECT_LT(angle_between_deg(kDisplay, end.pos, landing), 0.02);
}

TEST(GazeFilter, BadSamplesAreDroppedCountedAndHarmless) {
  GazeFilter f({}, kDisplay);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  f.update({1.0, {0.3, 0.3}, 1.0, true}, 1.0);
  FilteredGaze g = f.update({nan, {0.9, 0.9}, 1.0, true}, 1.01);
  EXPECT_DOUBLE_EQ(g.pos.x, 0.3);
  g = f.update({1.02, {nan, 0.9}, 1.0, true}, 1.02);
  g = f.update({1.03, {0.9, std::numeric_limits<double>::infinity()}, 1.0, true}, 1.03);
  g = f.update({0.5, {0.9, 0.9}, 1.0, true}, 1.04);    // backwards
  g = f.update({1.0, {0.9, 0.9}, 1.0, true}, 1.05);    // duplicate time, new position
  g = f.update({1.06, {-0.5, 0.9}, 1.0, true}, 1.06);  // off screen
  EXPECT_DOUBLE_EQ(g.pos.x, 0.3);
  EXPECT_TRUE(g.valid);
  const DropCounts& c = f.counters().dropped;
  EXPECT_EQ(c.non_finite, 3u);
  EXPECT_EQ(c.backwards, 1u);
  EXPECT_EQ(c.duplicate, 1u);
  EXPECT_EQ(c.out_of_range, 1u);
  EXPECT_NE(f.counters().summary().find("6 dropped"), std::string::npos);
}

TEST(GazeFilter, RejectsBadOptions) {
  FilterOptions o;
  o.min_confidence = 1.5;
  EXPECT_THROW(GazeFilter(o, kDisplay), Error);
  o = {};
  o.fallback_fovea_scale = 0.5;
  EXPECT_THROW(GazeFilter(o, kDisplay), Error);
}

TEST(LatencyEstimator, PercentilesOverTheWindow) {
  LatencyEstimator e;
  for (int k = 1; k <= 100; ++k) e.record(1.0, 1.0 + k * 1e-3);  // 1..100 ms
  EXPECT_EQ(e.count(), 100u);
  EXPECT_NEAR(e.median_ms(), 50.5, 1e-9);
  EXPECT_NEAR(e.p95_ms(), 95.05, 1e-9);  // linear between closest ranks
  EXPECT_NEAR(e.max_ms(), 100.0, 1e-9);
  EXPECT_NEAR(e.worst_case_ms(), 95.05, 1e-9);
  e.record(2.0, 1.9);  // shown before it was sampled: rejected
  e.record(std::nan(""), 1.0);
  EXPECT_EQ(e.rejected(), 2u);
  EXPECT_EQ(e.count(), 100u);

  LatencyOptions small;
  small.window = 10;
  small.extra_ms = 5.0;
  LatencyEstimator w(small);
  for (int k = 1; k <= 100; ++k) w.record(0.0, k * 1e-3);
  EXPECT_EQ(w.count(), 10u);
  EXPECT_NEAR(w.median_ms(), 95.5 + 5.0, 1e-9);  // only 91..100 ms remain
}

TEST(LatencyEstimator, SkipsHeldFramesAndFeedsTheLatencyAwareFovea) {
  LatencyEstimator e;
  FilteredGaze g;
  g.valid = true;
  g.sample_time_s = 1.0;
  e.record(g, 1.04);
  g.holding = true;
  e.record(g, 1.5);
  g.holding = false;
  g.fallback = true;
  e.record(g, 2.0);
  EXPECT_EQ(e.count(), 1u);
  EXPECT_NEAR(e.worst_case_ms(), 40.0, 1e-9);
  // Swafford et al. eq. 1: F' = 2 * eye_distance_px * tan(L * S + alpha / 2) (+ borders).
  LatencyAwareFovea base;
  const LatencyAwareFovea lf = e.fovea_for(base);
  EXPECT_NEAR(lf.latency_ms, 40.0, 1e-9);
  const double deg = 3.14159265358979323846 / 180.0;
  const double expect = 2 * kDisplay.eye_distance_px() * std::tan((0.040 * 200.0 + 2.5) * deg);
  EXPECT_NEAR(lf.diameter_px(kDisplay), expect, 1e-6);
  EXPECT_NEAR(e.fovea_growth(kDisplay),
              expect / (2 * kDisplay.eye_distance_px() * std::tan(2.5 * deg)), 1e-9);
  EXPECT_GT(e.fovea_growth(kDisplay), 4.0);  // 40 ms at 200 deg/s: 8 deg of reach
  EXPECT_DOUBLE_EQ(LatencyEstimator().fovea_growth(kDisplay), 1.0);
}

}  // namespace
}  // namespace foveate::gaze
