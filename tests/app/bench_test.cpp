// The benchmark and the session as the command runs them, driven from a
// test: a technique registered at run time is benchmarked beside native,
// sweeps are parsed once and apply only where the key exists.
#include "bench.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

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

TEST(Bench, InterleavedOrdersVaryWhatEachTechniqueFollows) {
  // Seven techniques over sixteen frames, as the README's tables: every
  // frame renders each technique once, and each technique follows several
  // others over the run (a fixed rotation gave each one predecessor only).
  const auto orders = interleaved_orders(7, 16);
  ASSERT_EQ(orders.size(), 16u);
  std::vector<std::set<size_t>> before(7);
  std::set<size_t> first;
  for (const auto& order : orders) {
    ASSERT_EQ(order.size(), 7u);
    EXPECT_EQ(std::set<size_t>(order.begin(), order.end()).size(), 7u);
    first.insert(order[0]);
    for (size_t i = 1; i < order.size(); ++i) before[order[i]].insert(order[i - 1]);
  }
  for (size_t t = 0; t < 7; ++t) EXPECT_GE(before[t].size(), 3u) << "technique " << t;
  EXPECT_GE(first.size(), 4u);
  EXPECT_EQ(interleaved_orders(7, 16), orders);  // the same sequence every run
  EXPECT_EQ(interleaved_orders(1, 3), (std::vector<std::vector<size_t>>(3, {0})));
  EXPECT_TRUE(interleaved_orders(4, 0).empty());
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

TEST(Bench, MarginSweepsTheTechniquesPlanNotTheYardstick) {
  // --sweep margin=...: every technique but native (which plans nothing)
  // gets each value as its planning margin, so the checkerboard's regions
  // begin farther out; the metrics keep the session's acuity (recorded
  // once; no --margin: null).
  const Sweep m = Sweep::parse("margin=1:2:1");
  EXPECT_TRUE(m.applies_to("checkerboard"));
  EXPECT_FALSE(m.applies_to("native"));
  // Every value is checked against each declaration before anything runs.
  EXPECT_EQ(error_of([] { Sweep::parse("margin=0.5:1:0.5"); }),
            "--sweep: layered parameter margin=0.5: out of range [1, 4]");
  EXPECT_EQ(error_of([] { Sweep::parse("layered.layers=2:3:0.5"); }),
            "--sweep: layered parameter layers=2.5: must be a whole number");
  const std::string out = (std::filesystem::temp_directory_path() / "foveate-app-margin").string();
  std::filesystem::remove_all(out);
  BenchOptions o = tiny(out);
  o.session.size = {640, 360};
  o.frames = 1;
  o.warmup = 0;
  o.image_metrics = false;
  o.techniques = {"native", "checkerboard"};
  o.sweep = m;
  const BenchResult r = run_bench(o);
  ASSERT_EQ(r.results.size(), 3u);
  const auto r1 = [](const TechniqueResult& t) {
    for (const auto& [key, value] : t.parameters)
      if (key == "r1") return value;
    return -1.0;
  };
  TechniqueConfig c;
  c.display = Display::load("desktop-1080p").resized(640, 360);
  c.acuity = AcuityModel::quality("A");
  c.margin = 2.0;
  const ParamValues finer = resolve_parameters(technique_info("checkerboard"), c);
  EXPECT_EQ(r1(r.results[2]), finer.real("r1"));
  EXPECT_GT(r1(r.results[2]), r1(r.results[1]));
  write_bench_outputs(r);
  std::ifstream in(out + "/results.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j["acuity"]["slope"], kSlopeQualityA);
  EXPECT_TRUE(j["margin"].is_null());
  std::filesystem::remove_all(out);
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

// --passes: every pass a technique runs is timed, the rest of the frame is
// "other", and the parts add up to the frame; the warm-up lasts as long as
// the slowest-settling technique needs; results.json says where it ran.
TEST(Bench, PassesAddUpToTheFrameAndTheRunIsRecorded) {
  const std::string out =
      (std::filesystem::temp_directory_path() / "foveate-app-bench-passes").string();
  std::filesystem::remove_all(out);
  BenchOptions o = tiny(out);
  o.session.scene = "guenter";  // a G-buffer prepass
  o.techniques = {"native", "layered", "checkerboard"};
  o.passes = true;
  o.image_metrics = false;
  o.frames = 3;
  const BenchResult r = run_bench(o);
  // layered settles in 6 frames with half-rate layers (asked for 1).
  EXPECT_EQ(r.warmup, 6);
  ASSERT_EQ(r.results.size(), 3u);
  for (const TechniqueResult& t : r.results) {
    SCOPED_TRACE(t.technique);
    ASSERT_GE(t.passes.size(), 3u);
    EXPECT_EQ(t.passes.back().name, "other");
    double sum = 0;
    bool gbuffer = false, shade = false;
    for (const gpu::PassTime& p : t.passes) {
      EXPECT_GE(p.ms, 0.0);
      sum += p.ms;
      gbuffer = gbuffer || p.name == "gbuffer";
      shade = shade || p.name == "shade";
    }
    EXPECT_TRUE(gbuffer);
    EXPECT_TRUE(shade);
    // "other" is the frame's time outside every pass, so the parts add up to
    // the frame by construction; what can fail is that the timed passes
    // cover the frame: a pass left out of the scopes would show as "other".
    EXPECT_NEAR(sum, t.mean_ms, 1e-6 * t.mean_ms + 1e-9);
    EXPECT_LT(t.passes.back().ms, 0.5 * t.mean_ms) << "untimed work in " << t.technique;
  }
  auto has = [](const TechniqueResult& t, const std::string& name) {
    for (const gpu::PassTime& p : t.passes)
      if (p.name == name) return true;
    return false;
  };
  EXPECT_TRUE(has(r.results[1], "composite"));
  EXPECT_TRUE(has(r.results[2], "reconstruct"));
  EXPECT_FALSE(has(r.results[0], "composite"));
  write_bench_outputs(r);
  std::ifstream in(out + "/results.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j["warmup"], 6);
  const nlohmann::json& env = j["environment"];
  EXPECT_FALSE(env["renderer"].get<std::string>().empty());
  EXPECT_FALSE(env["foveate_version"].get<std::string>().empty());
  EXPECT_EQ(env["date_utc"].get<std::string>().size(), 20u);  // 2026-11-22T20:30:42Z
  EXPECT_GE(env["cpu_cores"].get<int>(), 1);
  EXPECT_EQ(env["load_average_start"].size(), 3u);
  const nlohmann::json& layered = j["results"][1];
  ASSERT_TRUE(layered["passes"].is_array());
  const double share = layered["resolve_share"].get<double>();
  EXPECT_GT(share, 0.0);
  EXPECT_LT(share, 1.0);
  EXPECT_TRUE(j["results"][0]["passes"].is_array());
  std::filesystem::remove_all(out);
}
