// Gaze specs, the simple sources and the shared sample validator.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>

#include "foveate/core/error.hpp"
#include "foveate/gaze/gaze.hpp"
#include "foveate/gaze/tracker.hpp"

namespace foveate::gaze {
namespace {

GazeContext ctx_1080p() {
  GazeContext c;
  c.display = Display{};  // desktop-1080p
  return c;
}

std::string error_of(const std::string& spec, const GazeContext& ctx) {
  try {
    make_gaze_source(spec, ctx);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(GazeSample, PixelsScaleTheNormalizedPosition) {
  const GazeSample s{0.0, {0.25, 0.75}, 1.0, true};
  const Vec2d p = s.pixels(640, 360);
  EXPECT_DOUBLE_EQ(p.x, 160.0);
  EXPECT_DOUBLE_EQ(p.y, 270.0);
}

TEST(GazeSpec, FixedInPixelsAndNormalized) {
  const GazeContext c = ctx_1080p();
  auto px = make_gaze_source("fixed:480,270", c);
  GazeSample s = px->sample(2.0);
  EXPECT_DOUBLE_EQ(s.pos.x, 0.25);
  EXPECT_DOUBLE_EQ(s.pos.y, 0.25);
  EXPECT_DOUBLE_EQ(s.time_s, 2.0);
  EXPECT_TRUE(s.valid);
  s = make_gaze_source("fixed:0.3,0.6", c)->sample(0);
  EXPECT_DOUBLE_EQ(s.pos.x, 0.3);
  EXPECT_DOUBLE_EQ(s.pos.y, 0.6);
  // "1,1" has no decimal point: pixels.
  s = make_gaze_source("fixed:1,1", c)->sample(0);
  EXPECT_DOUBLE_EQ(s.pos.x, 1.0 / 1920);
  // A bare X,Y is a fixed point too.
  s = make_gaze_source("960,540", c)->sample(0);
  EXPECT_DOUBLE_EQ(s.pos.x, 0.5);
}

TEST(GazeSpec, BadSpecsAreClearErrors) {
  const GazeContext c = ctx_1080p();
  EXPECT_NE(error_of("", c).find("empty"), std::string::npos);
  EXPECT_NE(error_of("fixed:", c).find("X,Y"), std::string::npos);
  EXPECT_NE(error_of("fixed:abc", c).find("X,Y"), std::string::npos);
  EXPECT_NE(error_of("fixed:1e9,1", c).find("far off screen"), std::string::npos);
  EXPECT_NE(error_of("synthetic:-1", c).find("seed"), std::string::npos);
  EXPECT_NE(error_of("synthetic:x", c).find("seed"), std::string::npos);
  EXPECT_NE(error_of("pupil:host:0", c).find("port"), std::string::npos);
  EXPECT_NE(error_of("trace:", c).find("file"), std::string::npos);
  EXPECT_NE(error_of("trace:/nonexistent/gaze.csv", c).find("/nonexistent/gaze.csv"),
            std::string::npos);
  EXPECT_NE(error_of("eyeball", c).find("unknown source 'eyeball'"), std::string::npos);
  EXPECT_EQ(error_of("mouse", c), "gaze source mouse needs a window (foveate view)");
  EXPECT_NE(error_of("nearest", c).find("objects"), std::string::npos);
}

// A fixed gaze off the image would measure a technique's fallback: refused,
// when the source is made and before (check_gaze_spec, which bench::validate uses).
TEST(GazeSpec, FixedPointOffTheImageIsRefused) {
  const GazeContext c = ctx_1080p();
  const std::string e = error_of("5000,100", c);
  EXPECT_NE(e.find("'5000,100' is (5000, 100) px, outside the 1920x1080 image"), std::string::npos)
      << e;
  EXPECT_NE(error_of("fixed:1.5,0.5", c).find("1.5 is outside 0.0..1.0"), std::string::npos);
  EXPECT_NE(error_of("synthtic", c).find("did you mean 'synthetic'?"), std::string::npos);
  EXPECT_THROW(check_gaze_spec("5000,100", 1280, 720), Error);
  EXPECT_THROW(check_gaze_spec("fixed:-3,10", 1280, 720), Error);
  EXPECT_NO_THROW(check_gaze_spec("1280,720", 1280, 720));
  EXPECT_NO_THROW(check_gaze_spec("synthetic:3", 1280, 720));
  EXPECT_NO_THROW(check_gaze_spec("", 1280, 720));
}

// A source whose gaze goes off the image (within what the filter accepts).
class WanderingSource final : public GazeSource {
 public:
  GazeSample sample(double t_s) override {
    const bool off = t_s >= 0.5;
    return {t_s, {off ? 1.1 : 0.5, 0.5}, 1.0, true};
  }
  std::string describe() const override { return "wandering"; }
};

TEST(GazeTracker, CountsAndReportsFramesOffTheImage) {
  GazeTracker tracker(std::make_unique<WanderingSource>(), Display{});
  int off = 0;
  for (int k = 0; k < 10; ++k) {
    (void)tracker.at(k / 10.0);
    off += tracker.last_off_image() ? 1 : 0;
  }
  EXPECT_EQ(off, 5);
  EXPECT_EQ(tracker.counts().off_image, 5);
  EXPECT_EQ(tracker.counts().frames, 10);
  EXPECT_NE(tracker.report().find("5 off the image"), std::string::npos) << tracker.report();
}

TEST(GazeSpec, SyntheticSeedsAreDeterministic) {
  const GazeContext c = ctx_1080p();
  auto a = make_gaze_source("synthetic:7", c);
  auto b = make_gaze_source("synthetic:7", c);
  auto d = make_gaze_source("synthetic:8", c);
  bool differs = false;
  for (int k = 0; k < 300; ++k) {
    const double t = k / 60.0;
    const GazeSample sa = a->sample(t), sb = b->sample(t), sd = d->sample(t);
    EXPECT_EQ(sa.pos.x, sb.pos.x);
    EXPECT_EQ(sa.pos.y, sb.pos.y);
    EXPECT_EQ(sa.valid, sb.valid);
    differs = differs || sa.pos.x != sd.pos.x;
  }
  EXPECT_TRUE(differs);
  EXPECT_NE(a->describe().find("seed 7"), std::string::npos);
}

TEST(GazeSpec, MouseFollowsTheWindowAndIsInvalidOutsideIt) {
  GazeContext c = ctx_1080p();
  std::optional<Vec2d> mouse = Vec2d{0.1, 0.9};
  c.mouse = [&] { return mouse; };
  auto src = make_gaze_source("mouse", c);
  GazeSample s = src->sample(1.0);
  EXPECT_TRUE(s.valid);
  EXPECT_DOUBLE_EQ(s.pos.x, 0.1);
  mouse.reset();
  s = src->sample(1.1);
  EXPECT_FALSE(s.valid);
  EXPECT_DOUBLE_EQ(s.pos.y, 0.9);  // where it was last seen
}

TEST(GazeSpec, NearestObjectPursuesAndSaccadesOnTheMainSequence) {
  GazeContext c = ctx_1080p();
  // One object moving slowly right; at t = 1 a different object becomes nearest.
  c.objects = [](double t) {
    if (t < 1.0) return std::vector<Vec2d>{{0.3 + 0.01 * t, 0.5}, {0.9, 0.9}};
    return std::vector<Vec2d>{{0.7, 0.5}};
  };
  auto src = make_gaze_source("nearest", c);
  EXPECT_DOUBLE_EQ(src->sample(0.0).pos.x, 0.3);
  EXPECT_DOUBLE_EQ(src->sample(0.5).pos.x, 0.305);  // pursuit
  const Vec2d from = src->sample(0.99).pos;
  const double amp = angle_between_deg(c.display, from, {0.7, 0.5});
  const double dur = 0.021 + 0.0022 * amp;  // Carpenter's D = 21 ms + 2.2 ms/deg
  src->sample(1.0);                         // the saccade starts
  const GazeSample mid = src->sample(1.0 + 0.5 * dur);
  EXPECT_NEAR(mid.pos.x, 0.5 * (from.x + 0.7), 1e-6);  // symmetric profile: halfway at D/2
  EXPECT_LT(src->sample(1.0 + 0.9 * dur).pos.x, 0.7);
  EXPECT_DOUBLE_EQ(src->sample(1.0 + dur + 1e-6).pos.x, 0.7);  // landed
  // No objects: it stays where it is.
  c.objects = [](double) { return std::vector<Vec2d>{}; };
  EXPECT_DOUBLE_EQ(make_gaze_source("nearest", c)->sample(0).pos.x, 0.5);
}

TEST(SampleValidator, DropsAndCountsEachKindOfBadSample) {
  SampleValidator v(0.25);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(v.accept({1.0, {0.5, 0.5}, 1.0, true}));
  EXPECT_EQ(v.check({nan, {0.5, 0.5}, 1.0, true}), DropReason::kNonFinite);
  EXPECT_EQ(v.check({2.0, {inf, 0.5}, 1.0, true}), DropReason::kNonFinite);
  EXPECT_EQ(v.check({2.0, {0.5, 0.5}, nan, true}), DropReason::kNonFinite);
  EXPECT_EQ(v.check({2.0, {1.3, 0.5}, 1.0, true}), DropReason::kOutOfRange);
  EXPECT_EQ(v.check({2.0, {0.5, -0.26}, 1.0, true}), DropReason::kOutOfRange);
  EXPECT_EQ(v.check({2.0, {0.5, 0.5}, 1.01, true}), DropReason::kOutOfRange);
  EXPECT_EQ(v.check({0.5, {0.5, 0.5}, 1.0, true}), DropReason::kBackwards);
  EXPECT_EQ(v.check({1.0, {0.6, 0.5}, 1.0, true}), DropReason::kDuplicate);
  // Slightly off screen is allowed (within the off-screen limit); drops never advance the clock.
  EXPECT_TRUE(v.accept({1.5, {1.2, -0.2}, 0.0, false}));
  EXPECT_EQ(v.accepted(), 2u);
  const DropCounts& c = v.counts();
  EXPECT_EQ(c.non_finite, 3u);
  EXPECT_EQ(c.out_of_range, 3u);
  EXPECT_EQ(c.backwards, 1u);
  EXPECT_EQ(c.duplicate, 1u);
  EXPECT_EQ(c.total(), 8u);
  EXPECT_EQ(c.summary(),
            "8 dropped (3 non-finite, 3 out-of-range, 1 backwards in time, 1 duplicate time)");
  v.reset_clock();
  EXPECT_TRUE(v.accept({0.1, {0.5, 0.5}, 1.0, true}));  // a restarted tracker's clock
}

TEST(Geometry, AngleBetweenIsTheDisplayEccentricity) {
  const Display d;
  // Centre to the right edge: the half field of view.
  EXPECT_NEAR(angle_between_deg(d, {0.5, 0.5}, {1.0, 0.5}), d.half_fov_deg(), 1e-9);
  EXPECT_DOUBLE_EQ(angle_between_deg(d, {0.2, 0.3}, {0.2, 0.3}), 0.0);
}

}  // namespace
}  // namespace foveate::gaze
