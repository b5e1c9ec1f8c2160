// The synthetic viewer against the main sequence it claims to follow.
#include "foveate/gaze/synthetic.hpp"

#include <gtest/gtest.h>
#include <malloc.h>

#include <cmath>

#include "foveate/core/error.hpp"

namespace foveate::gaze {
namespace {

using Kind = Movement::Kind;

TEST(MainSequence, DurationAndPeakVelocityFollowTheCitedLaws) {
  const MainSequence ms;
  // Carpenter: D = 21 ms + 2.2 ms/deg * A.
  EXPECT_NEAR(ms.duration_s(10.0), 0.043, 1e-12);
  EXPECT_NEAR(ms.duration_s(0.5), 0.0221, 1e-12);
  EXPECT_NEAR(ms.duration_s(30.0), 0.087, 1e-12);
  // Vp = 600 (1 - exp(-A / 10)).
  EXPECT_NEAR(ms.peak_velocity_deg_per_s(10.0), 600.0 * (1.0 - std::exp(-1.0)), 1e-9);
  EXPECT_NEAR(ms.peak_velocity_deg_per_s(10.0), 379.27, 0.01);
  EXPECT_NEAR(ms.amplitude_for_peak_deg(ms.peak_velocity_deg_per_s(7.0)), 7.0, 1e-9);
}

TEST(SaccadeProfile, ShapeFamilyHitsTheRequestedPeakAndIsExact) {
  // a = 2 is the minimum-jerk profile (peak 15/8 of the mean); a = 1 has peak 3/2.
  EXPECT_NEAR(profile_exponent_for_ratio(1.875), 2.0, 1e-9);
  EXPECT_NEAR(profile_exponent_for_ratio(1.5), 1.0, 1e-9);
  EXPECT_NEAR(profile_velocity(0.5, 2.0), 1.875, 1e-12);
  // I_u(2, 2) = 3u^2 - 2u^3 and I_u(3, 3) = 10u^3 - 15u^4 + 6u^5.
  for (double u : {0.1, 0.3, 0.5, 0.77, 0.95}) {
    EXPECT_NEAR(profile_position(u, 1.0), 3 * u * u - 2 * u * u * u, 1e-12) << u;
    EXPECT_NEAR(profile_position(u, 2.0),
                10 * std::pow(u, 3) - 15 * std::pow(u, 4) + 6 * std::pow(u, 5), 1e-12)
        << u;
  }
  EXPECT_EQ(profile_position(0.0, 0.4), 0.0);
  EXPECT_EQ(profile_position(1.0, 0.4), 1.0);
}

TEST(SyntheticViewer, SaccadesLastAndPeakAsTheMainSequenceSays) {
  const Display d;
  SyntheticViewer v(d, {});
  const MainSequence ms;
  int saccades = 0;
  for (const Movement& m : v.movements_until(60.0)) {
    if (m.kind != Kind::kSaccade) continue;
    ++saccades;
    const double amp = angle_between_deg(d, m.from, m.to);
    EXPECT_NEAR(m.amplitude_deg, amp, 1e-9);
    EXPECT_GE(amp, 2.0 - 1e-9);
    EXPECT_LE(amp, 25.0 + 1e-9);
    EXPECT_NEAR(m.end_s - m.start_s, 0.021 + 0.0022 * amp, 1e-9);
    // Measure the velocity along the generated path at 0.05 ms steps.
    const double dt = 5e-5;
    double peak = 0;
    GazeSample prev = v.eye(m.start_s);
    EXPECT_NEAR(prev.pos.x, m.from.x, 1e-9);
    for (double t = m.start_s + dt; t <= m.end_s; t += dt) {
      const GazeSample s = v.eye(t);
      peak = std::max(peak, angle_between_deg(d, prev.pos, s.pos) / dt);
      prev = s;
    }
    // Along a straight screen line the angular speed departs a little from
    // the profile's; within 5 % of the main sequence's peak.
    EXPECT_NEAR(peak / ms.peak_velocity_deg_per_s(amp), 1.0, 0.05) << "amplitude " << amp;
    EXPECT_NEAR(v.eye(m.end_s).pos.x, m.to.x, 1e-9);
  }
  EXPECT_GT(saccades, 80);  // about 3 per second
}

TEST(SyntheticViewer, HasFixationsMicrosaccadesPursuitAndBlinks) {
  const Display d;
  SyntheticViewer v(d, {});
  int fix = 0, micro = 0, pursuit = 0, blink = 0;
  double fix_total = 0;
  const MainSequence ms;
  for (const Movement& m : v.movements_until(120.0)) {
    switch (m.kind) {
      case Kind::kFixation:
        ++fix;
        fix_total += m.end_s - m.start_s;
        EXPECT_GE(m.end_s - m.start_s, 0.1 - 1e-12);
        break;
      case Kind::kMicrosaccade:
        ++micro;
        EXPECT_LE(m.amplitude_deg, 0.5);
        EXPECT_NEAR(m.end_s - m.start_s, ms.duration_s(m.amplitude_deg), 1e-12);
        break;
      case Kind::kPursuit: {
        ++pursuit;
        // Smooth: the eye moves at a steady 4..20 deg/s (screen-plane speed, so 15 % slack).
        const double mid = 0.5 * (m.start_s + m.end_s);
        const double speed = angle_between_deg(d, v.eye(mid).pos, v.eye(mid + 0.01).pos) / 0.01;
        EXPECT_GT(speed, 4.0 * 0.85);
        EXPECT_LT(speed, 20.0 * 1.15);
        break;
      }
      case Kind::kBlink:
        ++blink;
        EXPECT_FALSE(v.eye(0.5 * (m.start_s + m.end_s)).valid);
        EXPECT_EQ(v.eye(0.5 * (m.start_s + m.end_s)).confidence, 0.0);
        break;
      case Kind::kSaccade:
        break;
    }
  }
  EXPECT_GT(fix, 200);
  EXPECT_NEAR(fix_total / fix, 0.28, 0.05);  // the gamma mean (plus the 0.1 s floor)
  EXPECT_GT(micro, 20);
  EXPECT_GT(pursuit, 10);
  EXPECT_GT(blink, 5);
}

TEST(SyntheticViewer, DeterministicInAnyQueryOrderAndStaysOnScreen) {
  const Display d;
  SyntheticViewer a(d, {}), b(d, {});
  std::vector<GazeSample> fwd, back;
  for (int k = 0; k <= 600; ++k) fwd.push_back(a.eye(k * 0.05));
  for (int k = 600; k >= 0; --k) back.push_back(b.eye(k * 0.05));
  for (int k = 0; k <= 600; ++k) {
    EXPECT_EQ(fwd[k].pos.x, back[600 - k].pos.x);
    EXPECT_EQ(fwd[k].pos.y, back[600 - k].pos.y);
    EXPECT_GE(fwd[k].pos.x, 0.0);
    EXPECT_LE(fwd[k].pos.x, 1.0);
    EXPECT_GE(fwd[k].pos.y, 0.0);
    EXPECT_LE(fwd[k].pos.y, 1.0);
  }
}

// A render asks for the gaze frame by frame for as long as it runs: the viewer
// kept its whole history (about 30 bytes a frame at 60 fps, the RSS growth
// `scripts/soak.sh ... --gaze synthetic` showed) and now keeps the recent part.
TEST(SyntheticViewer, LongRunsUseBoundedMemoryAndStayDeterministic) {
  const Display d;
  SyntheticViewer v(d, {}), late(d, {});
  auto heap = [] {
    const struct mallinfo2 m = mallinfo2();
    return static_cast<long long>(m.uordblks + m.hblkhd);
  };
  for (int k = 0; k < 6000; ++k) (void)v.sample(k / 60.0);  // warm-up
  const long long before = heap();
  for (int k = 6000; k < 36000; ++k) (void)v.sample(k / 60.0);  // 500 s more
  const long long grown = heap() - before;
  // Pruned history: earlier times regenerate from the seed, with the same result.
  for (double t : {599.0, 3.25, 0.0, 250.5, 599.5, 12.0}) {
    EXPECT_EQ(v.eye(t).pos.x, late.eye(t).pos.x) << t;
    EXPECT_EQ(v.eye(t).pos.y, late.eye(t).pos.y) << t;
  }
  // The movement list still starts at time 0.
  const std::vector<Movement> all = v.movements_until(30.0);
  ASSERT_FALSE(all.empty());
  EXPECT_EQ(all.front().start_s, 0.0);
  EXPECT_GT(all.back().start_s, 25.0);
  if (before == 0) GTEST_SKIP() << "mallinfo2 sees no heap (a sanitizer's allocator)";
  EXPECT_LT(grown, 64 * 1024) << "30,000 frames grew the heap by " << grown << " bytes";
}

TEST(SyntheticViewer, TrackerRateLatencyAndNoise) {
  const Display d;
  SyntheticOptions o;
  o.rate_hz = 120;
  o.latency_ms = 20;
  SyntheticViewer v(d, o), eye(d, {});
  const GazeSample s = v.sample(1.0);
  const double expect_t = std::floor((1.0 - 0.020) * 120.0) / 120.0;
  EXPECT_NEAR(s.time_s, expect_t, 1e-12);
  EXPECT_EQ(s.pos.x, eye.eye(expect_t).pos.x);
  EXPECT_EQ(v.sample(1.001).time_s, s.time_s);  // same tracker sample until the next one
  o.noise_deg = 0.5;
  o.rate_hz = 0;
  o.latency_ms = 0;
  SyntheticViewer noisy(d, o);
  double sum2 = 0;
  int n = 0;
  for (int k = 0; k < 2000; ++k) {
    const double t = k * 0.01;
    const GazeSample a = noisy.sample(t), b = eye.eye(t);
    if (!a.valid) continue;
    const double e = angle_between_deg(d, a.pos, b.pos);
    sum2 += e * e;
    ++n;
  }
  // Two axes of 0.5 deg each: RMS error about 0.5 * sqrt(2).
  EXPECT_NEAR(std::sqrt(sum2 / n), 0.5 * std::sqrt(2.0), 0.05);
  EXPECT_EQ(noisy.sample(3.0).pos.x, noisy.sample(3.0).pos.x);
}

TEST(SyntheticViewer, RejectsInconsistentOptions) {
  SyntheticOptions o;
  o.saccade_min_deg = 30;
  o.saccade_max_deg = 10;
  EXPECT_THROW(SyntheticViewer(Display{}, o), Error);
}

}  // namespace
}  // namespace foveate::gaze
