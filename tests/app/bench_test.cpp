// The benchmark and the session as the command runs them, driven from a
// test: a technique registered at run time is benchmarked beside native,
// sweeps are parsed once and apply only where the key exists.
#include "bench.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "bars_technique.hpp"
#include "errors.hpp"

using namespace foveate;
using foveate::test::error_of;
using namespace foveate::app;

namespace {

BenchOptions tiny(const std::string& out) {
  BenchOptions o;
  o.session.scene = "cheap";
  o.session.size = {64, 36};
  o.frames = 2;
  o.warmup = 1;
  o.progress = false;
  o.out = out;
  return o;
}

}  // namespace

TEST(Bench, ARunTimeTechniqueIsBenchmarkedBesideNative) {
  test::register_bars_technique();
  const std::string out = (std::filesystem::temp_directory_path() / "foveate-app-bench").string();
  std::filesystem::remove_all(out);
  BenchOptions o = tiny(out);
  o.techniques = {"native", test::kBarsTechnique};
  const BenchResult r = run_bench(o);
  ASSERT_EQ(r.results.size(), 2u);
  const TechniqueResult& bars = r.results[1];
  EXPECT_EQ(bars.technique, test::kBarsTechnique);
  EXPECT_EQ(bars.parameters, (std::vector<std::pair<std::string, double>>{{"bar_px", 1.0}}));
  EXPECT_EQ(bars.frame_ms.size(), 2u);
  EXPECT_EQ(bars.shaded_pixels, 64.0 * 36.0);
  ASSERT_TRUE(bars.metrics.has_value());
  EXPECT_EQ(bars.metrics->frames, 2);
  // Two black rows of 64 differ from native; the rest is identical.
  EXPECT_LT(bars.metrics->mean.psnr_db, 40.0);
  EXPECT_FALSE(r.results[0].metrics.has_value());  // native is the reference
  write_bench_outputs(r);
  std::ifstream in(out + "/results.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j["results"][1]["technique"], test::kBarsTechnique);
  std::filesystem::remove_all(out);
}

TEST(Bench, SweepsApplyOnlyWhereTheKeyIsDeclared) {
  test::register_bars_technique();
  const Sweep s = Sweep::parse("bar_px=1:3:1");
  EXPECT_EQ(s.values, (std::vector<double>{1, 2, 3}));
  EXPECT_TRUE(s.applies_to(test::kBarsTechnique));
  EXPECT_FALSE(s.applies_to("layered"));  // no such key: run once, not once per value
  EXPECT_FALSE(s.applies_to("native"));
  const Sweep slope = Sweep::parse("slope=0.02:0.03:0.005");
  EXPECT_EQ(slope.values.size(), 3u);
  EXPECT_TRUE(slope.applies_to("layered"));
  const Sweep one = Sweep::parse("layered.layers=2:4:1");
  EXPECT_TRUE(one.applies_to("layered"));
  EXPECT_FALSE(one.applies_to("inset"));
  // A step too small to change the value gives one value, not an endless list.
  EXPECT_EQ(Sweep::parse("slope=1e16:1e16:1").values.size(), 1u);
  EXPECT_EQ(error_of([] { Sweep::parse("slope=0:1:1e-9"); }),
            "--sweep slope=0:1:1e-9: 1000000000 values, over the limit of 50; use a larger STEP");
  EXPECT_EQ(error_of([] { Sweep::parse("slope=1e16:2e16:1"); }),
            "--sweep slope=1e16:2e16:1: 10000000000000000 values, over the limit of 50; use a "
            "larger STEP");
  EXPECT_NE(error_of([] { Sweep::parse("nope=1:2:1"); }).find("no technique has"),
            std::string::npos);
  EXPECT_NE(error_of([] { Sweep::parse("slope=1:2"); }).find("KEY=FROM:TO:STEP"),
            std::string::npos);
}

TEST(Bench, SweptRunsOnlyForTechniquesWithTheKey) {
  test::register_bars_technique();
  BenchOptions o = tiny("");
  o.frames = 1;
  o.warmup = 0;
  o.image_metrics = false;
  o.techniques = {"native", test::kBarsTechnique, "inset"};
  o.sweep = Sweep::parse("bar_px=0:2:2");
  const BenchResult r = run_bench(o);
  std::vector<std::string> runs;
  for (const TechniqueResult& t : r.results) runs.push_back(t.technique);
  EXPECT_EQ(runs, (std::vector<std::string>{"native", test::kBarsTechnique, test::kBarsTechnique,
                                            "inset"}));
}

TEST(Session, ErrorsNameTheFlag) {
  SessionOptions o;
  o.scene = "cheap";
  o.size = {32, 32};
  EXPECT_NE(error_of([&] { Session s(o, "fixed:"); }).find("--gaze: fixed gaze point"),
            std::string::npos);
  SessionOptions d = o;
  d.display = "nope";
  EXPECT_NE(error_of([&] { Session s(d, ""); }).find("--display: "), std::string::npos);
  Session s(o, "");
  EXPECT_NE(error_of([&] {
              s.make("layered", parse_params({"layers=9"}));
            }).find("--param: layered parameter layers=9: out of range"),
            std::string::npos);
  EXPECT_NE(error_of([&] { s.make("lodmask", {}); }).find("needs a scene with"), std::string::npos);
}
