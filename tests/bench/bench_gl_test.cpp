// The benchmark and the session with GL (each run makes its own headless
// context): techniques registered at run time are benchmarked beside the
// built-in ones, sweeps apply only where the key exists, every pass is timed,
// and errors name the field of the options.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <tuple>

#include "bars_technique.hpp"
#include "errors.hpp"
#include "foveate/bench/bench.hpp"
#include "foveate/bench/merge.hpp"
#include "foveate/bench/report.hpp"
#include "foveate/bench/tune.hpp"
#include "foveate/gpu/frame.hpp"
#include "foveate/gpu/gl.hpp"
#include "foveate/gpu/profiler.hpp"
#include "native_copy.hpp"

using namespace foveate;
using namespace foveate::bench;
using foveate::test::error_of;

namespace {

BenchOptions tiny() {
  BenchOptions o;
  o.session.scene = "cheap";
  o.session.size = {64, 36};
  o.frames = 2;
  o.warmup = 1;
  o.session.gl_debug = true;
  return o;
}

// Whether `n` is a warning about the code rather than the machine: ctest
// runs tests beside each other, which a benchmark rightly reports as other
// processes sharing the CPU (busy_machine), and that is no failure.
bool code_warning(const Notice& n) {
  return n.kind == NoticeKind::Warning && n.text.render().rfind("other processes used", 0) != 0;
}

// The benchmark, failing the test on every warning it gives about the code
// (a GL error the debug context reported among them).
BenchResult run(const BenchOptions& o) {
  BenchCallbacks callbacks;
  callbacks.session.notice = [](const Notice& n) {
    if (code_warning(n)) ADD_FAILURE() << n.text.render();
  };
  return run_bench(o, callbacks);
}

std::string fresh_dir(const std::string& name) {
  const std::string dir = (std::filesystem::temp_directory_path() / name).string();
  std::filesystem::remove_all(dir);
  return dir;
}

nlohmann::json read_json(const std::string& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<std::string> measured(const BenchResult& r) {
  std::vector<std::string> names;
  for (const TechniqueResult& t : r.results) names.push_back(t.technique);
  return names;
}

}  // namespace

TEST(Bench, ARunTimeTechniqueIsBenchmarkedBesideNative) {
  test::register_bars_technique();
  const std::string out = fresh_dir("foveate-bench-bars");
  BenchOptions o = tiny();
  o.techniques = std::vector<std::string>{"native", test::kBarsTechnique};
  const BenchResult r = run(o);
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
  write_bench_report(r, out);
  EXPECT_EQ(read_json(out + "/results.json")["results"][1]["technique"], test::kBarsTechnique);
  std::filesystem::remove_all(out);
}

// A technique from outside the library (examples/bench_consumer: its own
// shader through PassKit, its copy declared a resolve pass) needs nothing
// but its registration to be listed, measured by default and reported.
TEST(Bench, AnOutsideTechniqueIsListedMeasuredByDefaultAndReported) {
  example::register_native_copy();
  const std::vector<std::string> names = technique_names();
  EXPECT_NE(std::find(names.begin(), names.end(), example::kNativeCopy), names.end());
  const std::string out = fresh_dir("foveate-bench-outside");
  BenchOptions o = tiny();
  o.frames = 1;
  o.warmup = 0;
  o.passes = true;
  const BenchResult r = run(o);  // no technique list: every one the scene can run
  const std::vector<std::string> runs = measured(r);
  EXPECT_NE(std::find(runs.begin(), runs.end(), example::kNativeCopy), runs.end());
  EXPECT_NE(std::find(runs.begin(), runs.end(), "vrs"), runs.end());
  EXPECT_EQ(std::find(runs.begin(), runs.end(), "lodmask"), runs.end());  // needs meshes
  ASSERT_EQ(r.skipped.size(), 1u);
  EXPECT_EQ(r.skipped[0].rfind("lodmask (", 0), 0u);
  write_bench_report(r, out);
  const nlohmann::json j = read_json(out + "/results.json");
  bool reported = false;
  for (const nlohmann::json& t : j["results"]) {
    if (t["technique"] != example::kNativeCopy) continue;
    reported = true;
    EXPECT_GT(t["resolve_share"].get<double>(), 0.0);  // its declared copy pass
  }
  EXPECT_TRUE(reported);
  std::ifstream html(out + "/report.html");
  const std::string page((std::istreambuf_iterator<char>(html)), std::istreambuf_iterator<char>());
  EXPECT_NE(page.find(example::kNativeCopy), std::string::npos);
  std::filesystem::remove_all(out);
}

// Native is the reference of every speedup and JOD below native: its row
// comes first whether the list names it or not, and the CSV's distance
// below native is filled.
TEST(Bench, NativeIsReportedFirstWhenNotListed) {
  BenchOptions o = tiny();
  o.techniques = std::vector<std::string>{"inset"};
  o.reference = 2;
  const BenchResult r = run(o);
  EXPECT_EQ(measured(r), (std::vector<std::string>{"native", "inset"}));
  ASSERT_TRUE(r.results[0].metrics && r.results[0].metrics->fvvdp);
  const std::string out = fresh_dir("foveate-bench-unlisted-native");
  write_bench_report(r, out);
  std::ifstream csv(out + "/results.csv");
  std::string header, native, inset;
  std::getline(csv, header);
  std::getline(csv, native);
  std::getline(csv, inset);
  EXPECT_EQ(native.rfind("native,", 0), 0u) << native;
  // technique,label,sweep_value,jod,jod_below_native,...: a number, not empty.
  std::vector<std::string> cells;
  std::stringstream row(inset);
  for (std::string c; std::getline(row, c, ',');) cells.push_back(c);
  ASSERT_GT(cells.size(), 4u);
  EXPECT_EQ(cells[0], "inset");
  EXPECT_FALSE(cells[4].empty()) << inset;
  std::filesystem::remove_all(out);
}

TEST(Bench, SweptRunsOnlyForTechniquesWithTheKey) {
  test::register_bars_technique();
  BenchOptions o = tiny();
  o.frames = 1;
  o.warmup = 0;
  o.image_metrics = false;
  o.techniques = std::vector<std::string>{"native", test::kBarsTechnique, "inset"};
  o.sweep = Sweep::range("bar_px", 0, 2, 2);
  EXPECT_EQ(measured(run(o)), (std::vector<std::string>{"native", test::kBarsTechnique,
                                                        test::kBarsTechnique, "inset"}));
}

TEST(Bench, MarginSweepsTheTechniquesPlanNotTheYardstick) {
  // sweep margin: every technique but native (which plans nothing) gets each
  // value as its planning margin, so the checkerboard's regions begin farther
  // out; the metrics keep the session's acuity (recorded once; no margin: null).
  const std::string out = fresh_dir("foveate-bench-margin");
  BenchOptions o = tiny();
  o.session.size = {640, 360};
  o.frames = 1;
  o.warmup = 0;
  o.image_metrics = false;
  o.techniques = std::vector<std::string>{"native", "checkerboard"};
  o.sweep = Sweep::range("margin", 1, 2, 1);
  const BenchResult r = run(o);
  ASSERT_EQ(r.results.size(), 3u);
  const auto r1 = [](const TechniqueResult& t) {
    for (const auto& [key, value] : t.parameters)
      if (key == "r1") return value;
    return -1.0;
  };
  TechniqueConfig c;
  c.display = Display::load("desktop-1080p").resized(640, 360);
  c.acuity = AcuityModel::preset("A");
  c.margin = 2.0;
  const ParamValues finer = resolve_parameters(technique_info("checkerboard"), c);
  EXPECT_EQ(r1(r.results[2]), finer.real("r1"));
  EXPECT_GT(r1(r.results[2]), r1(r.results[1]));
  write_bench_report(r, out);
  const nlohmann::json j = read_json(out + "/results.json");
  EXPECT_EQ(j["acuity"]["slope"], kSlopePresetA);
  EXPECT_TRUE(j["margin"].is_null());
  std::filesystem::remove_all(out);
}

TEST(Session, ErrorsNameTheField) {
  SessionOptions o;
  o.scene = "cheap";
  o.size = {32, 32};
  o.gaze = "fixed:";
  EXPECT_NE(error_of([&] { Session s(o); }).find("gaze: fixed gaze point"), std::string::npos);
  SessionOptions d = o;
  d.gaze = "";
  d.display = "nope";
  EXPECT_EQ(error_of([&] { Session s(d); }).rfind("display: ", 0), 0u);
  o.gaze = "";
  o.gl_debug = true;
  Session s(o);
  ParamOverrides nine;
  nine.set("layers", 9);
  EXPECT_NE(error_of([&] {
              s.make("layered", nine);
            }).find("params: layered parameter layers=9: out of range"),
            std::string::npos);
  EXPECT_NE(error_of([&] { s.make("lodmask", {}); }).find("needs a scene with"), std::string::npos);
  // Nothing above reached the GL wrongly, and the debug context does report
  // what does.
  EXPECT_TRUE(s.take_gl_errors().empty());
  glEnable(0x1234);
  EXPECT_EQ(s.take_gl_errors().size(), 1u);
}

// The little-to-save note is for the finest plan rendered so far: at 640x360
// vrs's (margin 1, bound 1.78x) has something to save, layered's (1.5,
// 1.15x) little, said when the first frame after making layered is
// rendered (the viewer's switch), once.
TEST(Session, TheSavingsNoteFollowsTheFinestPlanRendered) {
  SessionOptions o;
  o.scene = "cheap";
  o.size = {640, 360};
  std::vector<std::string> notes;
  SessionCallbacks callbacks;
  callbacks.notice = [&](const Notice& n) {
    if (n.kind == NoticeKind::Note) notes.push_back(n.text.render());
  };
  Session s(o, callbacks);
  const GazeState gaze{{320.0, 180.0}};
  SessionTechnique vrs = s.make("vrs", {});
  s.render(vrs, 0, gaze);
  EXPECT_TRUE(notes.empty()) << notes.front();
  SessionTechnique layered = s.make("layered", {});
  s.render(layered, 1, gaze);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("pixel bound is 1.15x at planning margin 1.5"), std::string::npos)
      << notes[0];
  s.render(layered, 2, gaze);
  s.render(vrs, 3, gaze);
  EXPECT_EQ(notes.size(), 1u);
}

// A frame past the frame timeout: the front end is told at the deadline
// (the command line ends the process there); when its callback returns, the
// run stops with an error naming the field once the frame has finished.
TEST(Session, AFrameOverTheTimeoutStopsTheRun) {
  SessionOptions o;
  o.scene = "cheap";
  o.size = {32, 32};
  o.frame_timeout_s = 0.05;
  std::atomic<bool> called = false;
  SessionCallbacks callbacks;
  callbacks.frame_timeout = [&](const FieldText&) { called = true; };
  Session s(o, callbacks);
  const std::string error = error_of([&] {
    s.watchdog().run("frame 0 (native)",
                     [] { std::this_thread::sleep_for(std::chrono::milliseconds(400)); });
  });
  EXPECT_TRUE(called);
  EXPECT_NE(error.find("frame 0 (native) did not finish within 0.05 s (frame_timeout_s)"),
            std::string::npos)
      << error;
  // The next frame runs under a fresh deadline.
  EXPECT_EQ(error_of([&] { s.watchdog().run("frame 1 (native)", [] {}); }), "no error");
}

// A run made only to settle (settle_runs) warms the benchmark up as long as
// it would if measured, so that benchmarks of different runs measure the
// same frames: native's images and JOD are those of a benchmark that
// measured it; one the scene cannot run is left out; bad ones are refused.
TEST(Bench, SettleRunsWarmUpWithoutBeingMeasured) {
  BenchOptions measured = tiny();
  measured.reference = 2;
  measured.runs = {{"inset", {}, ""}, {"layered", {{"half_rate", 1}}, ""}};
  const BenchResult a = run(measured);
  BenchOptions settled = measured;
  settled.runs = {{"inset", {}, ""}};
  settled.settle_runs = {{"layered", {{"half_rate", 1}}, ""}, {"lodmask", {}, ""}};
  const BenchResult b = run(settled);
  EXPECT_EQ(a.warmup, 6);
  EXPECT_EQ(b.warmup, 6);
  ASSERT_EQ(b.results.size(), 2u);  // native and inset: nothing else measured
  EXPECT_EQ(b.results[1].technique, "inset");
  for (size_t i = 0; i < 2; ++i) {
    ASSERT_TRUE(a.results[i].metrics && a.results[i].metrics->fvvdp);
    ASSERT_TRUE(b.results[i].metrics && b.results[i].metrics->fvvdp);
    EXPECT_EQ(a.results[i].metrics->fvvdp->jod, b.results[i].metrics->fvvdp->jod) << i;
  }
  settled.settle_runs = {};
  EXPECT_LT(run(settled).warmup, 6);  // inset alone settles sooner
  settled.settle_runs = {{"layered", {{"no_such", 1}}, ""}};
  EXPECT_NE(error_of([&] { validate(settled); }).find("settle_runs[0]: layered has no parameter"),
            std::string::npos);
}

namespace {

// Native, noting for each frame it renders (warm-up and measured) its index,
// how many frames this instance rendered before it, and whether the frame
// runs under a pass profiler that waits for every pass.
class PassProbe final : public Technique {
 public:
  static inline std::vector<bool> pass_by_pass;
  static inline std::vector<int> frames, ages;
  static void clear() {
    pass_by_pass.clear();
    frames.clear();
    ages.clear();
  }
  PassProbe(const TechniqueConfig& c, const ParamValues&) : native_(make_technique("native", c)) {}
  FrameStats render(Scene& scene, const FrameInput& frame, const GazeState& gaze,
                    const gpu::RenderTarget& target) override {
    const gpu::PassProfiler* p = gpu::PassProfiler::current();
    pass_by_pass.push_back(p && p->clock() == gpu::PassProfiler::Clock::Finish);
    frames.push_back(frame.frame);
    ages.push_back(age_++);
    return native_->render(scene, frame, gaze, target);
  }
  std::vector<OverlayShape> overlay(const GazeState&) const override { return {}; }

 private:
  std::unique_ptr<Technique> native_;
  int age_ = 0;
};

void register_pass_probe() {
  for (const TechniqueInfo& t : techniques()) {
    if (t.name == "test-pass-probe") return;
  }
  TechniqueInfo t;
  t.name = "test-pass-probe";
  t.summary = "native, noting whether each frame runs pass by pass";
  t.source = "foveate's tests";
  t.make = construct<PassProbe>();
  register_technique(std::move(t));
}

}  // namespace

// On a renderer without GPU timers (llvmpipe) every measured frame and the
// last warm-up frame run pass by pass with or without --passes: pipelined, a
// frame's time depended on the technique rendered before it. With GPU timers
// no frame waits for its passes, --passes or not.
TEST(Bench, SoftwareRenderersRunMeasuredFramesPassByPass) {
  register_pass_probe();
  BenchOptions o = tiny();
  o.techniques = std::vector<std::string>{"native", "test-pass-probe"};
  o.image_metrics = false;
  o.frames = 2;
  o.warmup = 1;
  for (bool passes : {false, true}) {
    SCOPED_TRACE(passes ? "--passes" : "no --passes");
    o.passes = passes;
    PassProbe::clear();
    const BenchResult r = run(o);
    const bool software = !gpu::FrameTimer::gpu_timer_meaningful(r.renderer);
    EXPECT_EQ(r.environment.pass_by_pass, software);
    EXPECT_FALSE(r.environment.timed_apart);  // nothing judged: one pass
    // The warm-up's frames before its last are pipelined everywhere.
    std::vector<bool> expected(static_cast<size_t>(r.warmup + o.frames), software);
    std::fill_n(expected.begin(), r.warmup - 1, false);
    EXPECT_EQ(PassProbe::pass_by_pass, expected);
    EXPECT_EQ(r.results[1].passes.empty(), !passes);
    const std::string out = fresh_dir("foveate-bench-pass-by-pass");
    write_bench_report(r, out);
    const nlohmann::json j = read_json(out + "/results.json");
    EXPECT_EQ(j["environment"]["pass_by_pass"].get<bool>(), software);
    EXPECT_EQ(read_bench_results(j, out).environment.pass_by_pass, software);
    std::filesystem::remove_all(out);
  }
}

// Where every frame is judged, the frames are timed in a pass that reads
// nothing back (on llvmpipe a frame after a read-back and the judging ran up
// to 12 % slower, the cheaper techniques' the most), then rendered again from
// the start, untimed, to be judged: the images, JOD and pixel counts are
// those of a run that judged as it timed, since every technique starts again
// (layered's jittered history and vrs's rates refined from the last frame
// would otherwise go on from where the timed pass left them).
TEST(Bench, JudgedRunsTimeTheFramesInAPassOfTheirOwn) {
  register_pass_probe();
  BenchOptions o = tiny();
  o.techniques = std::vector<std::string>{"native", "test-pass-probe"};
  o.frames = 3;
  o.warmup = 2;
  PassProbe::clear();
  const BenchResult r = run(o);
  EXPECT_TRUE(r.environment.timed_apart);
  const bool software = !gpu::FrameTimer::gpu_timer_meaningful(r.renderer);
  const int n = r.warmup + o.frames;
  std::vector<int> frames;
  for (int pass = 0; pass < 2; ++pass) {
    for (int f = 0; f < n; ++f) frames.push_back(f);
  }
  EXPECT_EQ(PassProbe::frames, frames);
  // Made anew for the image pass: its second instance has rendered nothing
  // before frame 0, as the first had.
  EXPECT_EQ(PassProbe::ages, frames);
  // The image pass is not timed: none of its frames waits for its passes.
  std::vector<bool> by_pass(static_cast<size_t>(2 * n), false);
  std::fill(by_pass.begin() + r.warmup - 1, by_pass.begin() + n, software);
  EXPECT_EQ(PassProbe::pass_by_pass, by_pass);
  const std::string out = fresh_dir("foveate-bench-timed-apart");
  write_bench_report(r, out);
  const nlohmann::json j = read_json(out + "/results.json");
  EXPECT_TRUE(j["environment"]["timed_apart"].get<bool>());
  EXPECT_TRUE(read_bench_results(j, out).environment.timed_apart);
  std::filesystem::remove_all(out);
  // Asked not to (tune's search): judged between the timed renders, one pass.
  o.time_apart = false;
  PassProbe::clear();
  const BenchResult one = run(o);
  EXPECT_FALSE(one.environment.timed_apart);
  EXPECT_EQ(PassProbe::frames, std::vector<int>(frames.begin(), frames.begin() + n));
  EXPECT_TRUE(one.results[1].metrics && one.results[1].metrics->fvvdp);  // judged all the same

  // Judged apart, each technique's last frame is the one a run that read it
  // between its timed renders shows.
  BenchOptions judged = tiny();
  judged.session.scene = "guenter";
  judged.session.size = {160, 90};
  judged.techniques = std::vector<std::string>{"native", "layered", "vrs"};
  judged.params.per_technique["vrs"]["adapt"] = 0.05;
  judged.frames = 4;
  BenchOptions timed_only = judged;
  timed_only.image_metrics = false;
  const BenchResult a = run(judged);
  const BenchResult b = run(timed_only);
  EXPECT_TRUE(a.environment.timed_apart);
  EXPECT_FALSE(b.environment.timed_apart);
  ASSERT_EQ(a.results.size(), 3u);
  ASSERT_EQ(b.results.size(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    SCOPED_TRACE(a.results[i].technique);
    const Image& x = a.results[i].sample;
    const Image& y = b.results[i].sample;
    ASSERT_EQ(x.width, y.width);
    ASSERT_EQ(x.height, y.height);
    EXPECT_EQ(x.rgba, y.rgba);
    EXPECT_EQ(a.results[i].shaded_pixels, b.results[i].shaded_pixels);
  }
}

// Every pass a technique runs is timed, the rest of the frame is "other",
// and the parts add up to the frame; the warm-up lasts as long as the
// slowest-settling technique needs; results.json says where it ran.
TEST(Bench, PassesAddUpToTheFrameAndTheRunIsRecorded) {
  const std::string out = fresh_dir("foveate-bench-passes");
  BenchOptions o = tiny();
  o.session.scene = "guenter";  // a G-buffer prepass
  o.techniques = std::vector<std::string>{"native", "layered", "checkerboard"};
  o.passes = true;
  o.image_metrics = false;
  o.frames = 3;
  o.params.set("layered.half_rate", 1);
  const BenchResult r = run(o);
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
    // Where passes are bracketed with glFinish (software renderers), a pass
    // left out of the scopes would show as "other". On a GPU the passes are
    // timed by timestamp queries, which do not see the CPU's work between
    // them: on an H100 "other" (driver submission, query reads) is 58 % of
    // checkerboard's 0.7 ms frame at this size, so it is not held there.
    if (!gpu::FrameTimer::gpu_timer_meaningful(r.renderer)) {
      EXPECT_LT(t.passes.back().ms, 0.5 * t.mean_ms) << "untimed work in " << t.technique;
    }
  }
  auto has = [](const TechniqueResult& t, const std::string& name) {
    return std::any_of(t.passes.begin(), t.passes.end(),
                       [&](const gpu::PassTime& p) { return p.name == name; });
  };
  EXPECT_TRUE(has(r.results[1], "composite"));
  EXPECT_TRUE(has(r.results[2], "reconstruct_packed"));
  EXPECT_FALSE(has(r.results[0], "composite"));
  write_bench_report(r, out);
  const nlohmann::json j = read_json(out + "/results.json");
  EXPECT_EQ(j["warmup"], 6);
  const nlohmann::json& env = j["environment"];
  EXPECT_FALSE(env["renderer"].get<std::string>().empty());
  EXPECT_FALSE(env["foveate_version"].get<std::string>().empty());
  EXPECT_EQ(env["date_utc"].get<std::string>().size(), 20u);  // 2026-11-22T20:30:42Z
  EXPECT_GE(env["cpu_cores"].get<int>(), 1);
  EXPECT_EQ(env["load_average_start"].size(), 3u);
  // A run this short is under the 4 s of CPU time the share needs: null,
  // not a guess; a longer one's lies in 0..1.
  const nlohmann::json& others = env.at("others_cpu_share");
  if (!others.is_null()) {
    EXPECT_GE(others.get<double>(), 0.0);
    EXPECT_LE(others.get<double>(), 1.0);
  }
  const nlohmann::json& layered = j["results"][1];
  ASSERT_TRUE(layered["passes"].is_array());
  const double share = layered["resolve_share"].get<double>();
  EXPECT_GT(share, 0.0);
  EXPECT_LT(share, 1.0);
  EXPECT_TRUE(j["results"][0]["passes"].is_array());
  EXPECT_EQ(j["results"][0]["resolve_share"], 0.0);  // native declares no resolve pass
  // Measured while other processes took 40 % of the CPU: every report says
  // its times are inflated; a share not told says nothing.
  const auto said = [&](const std::string& file, const std::string& what) {
    std::ifstream in(out + "/" + file);
    const std::string text{std::istreambuf_iterator<char>(in), {}};
    return text.find(what) != std::string::npos;
  };
  if (others.is_null()) {
    EXPECT_FALSE(said("results.md", "other processes used"));
  }
  BenchResult shared = r;
  shared.environment.others_cpu_share = 0.4;
  write_bench_report(shared, out);
  EXPECT_DOUBLE_EQ(read_json(out + "/results.json")["environment"]["others_cpu_share"], 0.4);
  EXPECT_TRUE(said("results.md", "Warning: other processes used 40 % of the CPU during this run"));
  EXPECT_TRUE(said("report.html", "Other processes used 40 % of the CPU during this run"));
  std::filesystem::remove_all(out);
}

// FovVideoVDP judges every run over the measured frames: against the
// supersampled reference native gets a JOD of its own, each run's JOD equals
// the metric fed the same frames, and the reports lead with it.
TEST(Bench, FovVideoVdpJudgesEveryRunAgainstTheReference) {
  test::register_bars_technique();
  const std::string out = fresh_dir("foveate-bench-jod");
  BenchOptions o = tiny();
  o.session.size = {96, 54};
  o.frames = 3;
  o.reference = 2;
  o.techniques = std::vector<std::string>{"native", test::kBarsTechnique};
  const BenchResult r = run(o);
  ASSERT_EQ(r.results.size(), 2u);
  for (const TechniqueResult& t : r.results) {
    ASSERT_TRUE(t.metrics && t.metrics->fvvdp) << t.technique;
    EXPECT_EQ(t.metrics->fvvdp->frames, 3);
    EXPECT_FALSE(t.metrics->fvvdp->image);
    EXPECT_EQ(t.metrics->fvvdp->fps, o.session.fps);
    EXPECT_LT(t.metrics->fvvdp->jod, 10.0);
    EXPECT_FALSE(t.fvvdp_heatmap.empty());
  }
  // Black bars on top of native: further from the reference than native.
  EXPECT_LT(r.results[1].metrics->fvvdp->jod, r.results[0].metrics->fvvdp->jod);
  write_bench_report(r, out);
  const nlohmann::json j = read_json(out + "/results.json");
  for (size_t i = 0; i < 2; ++i) {
    const nlohmann::json& q = j["results"][i]["quality"];
    EXPECT_EQ(q["jod"].get<double>(), r.results[i].metrics->fvvdp->jod);
    EXPECT_EQ(q["fvvdp"]["bands"].size(), 4u);
    EXPECT_EQ(q["fvvdp"]["frame_jod"].size(), 3u);
  }
  std::ifstream md(out + "/results.md");
  std::string line;
  std::getline(md, line);
  EXPECT_EQ(line.rfind("| technique | JOD | below native |", 0), 0u) << line;
  std::ifstream html(out + "/report.html");
  const std::string page((std::istreambuf_iterator<char>(html)), std::istreambuf_iterator<char>());
  EXPECT_NE(page.find("id=\"chart-jod\""), std::string::npos);
  EXPECT_NE(page.find("Where the difference is visible"), std::string::npos);
  std::filesystem::remove_all(out);
}

namespace {

// Native and three techniques judged against a 2x2 supersampled reference.
BenchOptions four_runs_judged() {
  BenchOptions o = tiny();
  o.session.size = {96, 54};
  o.reference = 2;
  o.techniques = std::vector<std::string>{"native", "layered", "inset", "checkerboard"};
  return o;
}

// The same runs in the same order with the same pixels and JOD (timings
// aside: each measured against its own native, so not compared).
void expect_same_runs(const BenchResult& whole, const BenchResult& parts) {
  ASSERT_EQ(parts.results.size(), whole.results.size());
  for (size_t i = 0; i < whole.results.size(); ++i) {
    const TechniqueResult &a = whole.results[i], &b = parts.results[i];
    EXPECT_EQ(a.technique, b.technique);
    EXPECT_EQ(a.run_index, b.run_index);
    EXPECT_EQ(a.shaded_pixels, b.shaded_pixels);
    ASSERT_TRUE(a.metrics && b.metrics && a.metrics->fvvdp && b.metrics->fvvdp);
    EXPECT_DOUBLE_EQ(a.metrics->fvvdp->jod, b.metrics->fvvdp->jod) << a.technique;
  }
}

}  // namespace

// A benchmark split into shards, merged, measures the same runs in the same
// order with the same pixels and JOD as one unsharded run (timings aside);
// merging refuses shards of other settings, repeated or missing shards.
TEST(Bench, ShardsMergedEqualOneRun) {
  const BenchOptions o = four_runs_judged();
  const BenchResult whole = run(o);
  std::vector<BenchResult> shards;
  std::vector<std::string> names;
  for (int k : {1, 0}) {  // the order given does not matter
    BenchOptions s = o;
    s.shard = {k, 2};
    const std::string dir = fresh_dir("foveate-bench-shard-" + std::to_string(k));
    write_bench_report(run(s), dir);
    shards.push_back(read_bench_results(read_json(dir + "/results.json"), dir));
    names.push_back(dir);
    std::filesystem::remove_all(dir);
  }
  EXPECT_EQ(shards[0].results.size(), 2u);  // native and checkerboard (run 3 of 3)
  const BenchResult merged = merge_shards(shards, names);
  expect_same_runs(whole, merged);
  const std::string out = fresh_dir("foveate-bench-merged");
  write_bench_report(merged, out);
  EXPECT_EQ(read_json(out + "/results.json")["shard"]["merged"].get<int>(), 2);
  std::filesystem::remove_all(out);
  // One shard measured beside other work (its share read back from its
  // results.json): the merged result carries the largest share, so its
  // reports warn.
  std::vector<BenchResult> busy = shards;
  busy[1].environment.others_cpu_share = 0.5;
  EXPECT_EQ(merge_shards(busy, names).environment.others_cpu_share, 0.5);
  const std::string busy_dir = fresh_dir("foveate-bench-shard-busy");
  write_bench_report(busy[1], busy_dir);
  EXPECT_EQ(read_bench_results(read_json(busy_dir + "/results.json"), busy_dir)
                .environment.others_cpu_share,
            0.5);
  std::filesystem::remove_all(busy_dir);
  // Refusals.
  EXPECT_NE(error_of([&] {
              (void)merge_shards({shards[0]}, {names[0]});
            }).find("shard 1 of 2 is not given"),
            std::string::npos);
  EXPECT_NE(error_of([&] {
              (void)merge_shards({shards[0], shards[0]}, {"a", "b"});
            }).find("given twice"),
            std::string::npos);
  BenchOptions fewer = o;
  fewer.frames = 1;
  fewer.shard = {0, 2};
  const std::string dir = fresh_dir("foveate-bench-shard-other");
  write_bench_report(run(fewer), dir);
  const BenchResult other = read_bench_results(read_json(dir + "/results.json"), dir);
  std::filesystem::remove_all(dir);
  EXPECT_NE(error_of([&] {
              (void)merge_shards({other, shards[0]}, {"a", "b"});
            }).find("other settings"),
            std::string::npos);
  // A shard run under a variable that chooses other passes.
  BenchResult forced = shards[1];
  forced.environment.variables["FOVEATE_EDGES"] = "readback";
  EXPECT_NE(error_of([&] {
              (void)merge_shards({shards[0], forced}, {"a", "b"});
            }).find("b: run with FOVEATE_EDGES=readback, but a with none set"),
            std::string::npos);
}

// A run under FOVEATE_EDGES (or FOVEATE_EGL) says so in results.json, and
// reads back with it.
TEST(Bench, ResultsNameTheVariablesThatChoseWhatRan) {
  BenchOptions o = tiny();
  o.techniques = std::vector<std::string>{"native", "vrs"};
  o.image_metrics = false;
  const char* before = std::getenv("FOVEATE_EDGES");
  const std::string kept = before ? before : "";
  ::setenv("FOVEATE_EDGES", "indirect", 1);
  const BenchResult r = run(o);
  if (before)
    ::setenv("FOVEATE_EDGES", kept.c_str(), 1);
  else
    ::unsetenv("FOVEATE_EDGES");
  EXPECT_EQ(r.environment.variables.at("FOVEATE_EDGES"), "indirect");
  const std::string out = fresh_dir("foveate-bench-variables");
  write_bench_report(r, out);
  const nlohmann::json j = read_json(out + "/results.json");
  EXPECT_EQ(j["environment"]["variables"]["FOVEATE_EDGES"], "indirect");
  EXPECT_EQ(read_bench_results(j, out).environment.variables, r.environment.variables);
  std::filesystem::remove_all(out);
}

// Runs that do not fit the memory limit together are judged in groups, one
// after another, each with native: the same runs in the same order with the
// same pixels and JOD as all at once (timings aside), results.json says how
// many groups, and what every group notes is said once.
TEST(Bench, GroupsBeyondTheMemoryLimitEqualOneRun) {
  const BenchOptions o = four_runs_judged();
  const BenchResult whole = run(o);
  EXPECT_EQ(whole.memory_groups, 1);
  BenchOptions grouped = o;
  grouped.memory_limit_bytes = 2.5 * judged_run_bytes(o);  // native and one run at a time
  std::vector<std::string> notes;
  BenchCallbacks callbacks;
  callbacks.session.notice = [&](const Notice& n) {
    if (code_warning(n)) ADD_FAILURE() << n.text.render();
    if (n.kind != NoticeKind::Warning || code_warning(n)) notes.push_back(n.text.render());
  };
  int starts = 0, finishes = 0;
  callbacks.start = [&](int, int) { ++starts; };
  callbacks.finish = [&] { ++finishes; };
  const BenchResult r = run_bench(grouped, callbacks);
  EXPECT_EQ(r.memory_groups, 3);
  EXPECT_EQ(starts, 1);
  EXPECT_EQ(finishes, 1);
  expect_same_runs(whole, r);
  EXPECT_EQ(r.techniques, whole.techniques);
  // The grouping note, then each note of the set-up (the size's little to
  // save) once, not once per group.
  ASSERT_FALSE(notes.empty());
  EXPECT_NE(notes[0].find("judged in 3 groups"), std::string::npos) << notes[0];
  for (size_t i = 0; i < notes.size(); ++i)
    for (size_t j = i + 1; j < notes.size(); ++j) EXPECT_NE(notes[i], notes[j]);
  const std::string out = fresh_dir("foveate-bench-groups");
  write_bench_report(r, out);
  EXPECT_EQ(read_json(out + "/results.json")["memory_groups"].get<int>(), 3);
  EXPECT_EQ(read_bench_results(read_json(out + "/results.json"), out).memory_groups, 3);
  std::filesystem::remove_all(out);
}

// tune: every margin evaluated beside native; the choice is the fastest
// setting within the bound (or one within 5 % of its speed that keeps more
// JOD), its parameters a file that a benchmark takes.
namespace {

// tune on `cheap` at 96x54 against a 2x2 reference: each test's run.
TuneOptions small_tune(std::vector<std::string> techniques) {
  TuneOptions o;
  o.bench = tiny();
  o.bench.session.size = {96, 54};
  o.bench.reference = 2;
  o.bench.diagnostics = false;
  o.scenes = {"cheap"};
  o.techniques = std::move(techniques);
  return o;
}

}  // namespace

// A search in which nothing can run (lodmask needs meshes) is an error that
// names the technique, the scene and why, not an empty choice.
TEST(Tune, NothingThatCanRunIsAnError) {
  const TuneOptions o = small_tune({"lodmask"});
  std::string field = "no error", e;
  try {
    (void)run_tune(o);
  } catch (const OptionError& x) {
    field = x.field();
    e = x.what();
  }
  EXPECT_EQ(field, "techniques");
  EXPECT_EQ(e.rfind("techniques: none of the techniques searched can run on scenes: lodmask on "
                    "cheap (",
                    0),
            0u)
      << e;
}

TEST(Tune, ChoosesTheFastestSettingWithinTheBound) {
  TuneOptions o = small_tune({"layered", "inset"});
  o.bound_jod = 0.5;
  const TuneResult r = run_tune(o);
  EXPECT_TRUE(r.native_jod.count("cheap"));
  for (const std::string t : {"layered", "inset"}) {
    // Every margin with the other parameters at their defaults (stage 1,
    // some of them timed again in stage 5).
    int margins = 0;
    for (const TunePoint& p : r.points) {
      if (p.technique == t && p.params.size() == 1 && p.params.count("margin")) ++margins;
      EXPECT_EQ(p.within_bound, p.below_native <= 0.5);
    }
    EXPECT_EQ(margins, 6) << t;
    ASSERT_TRUE(r.chosen.count(t)) << t;
    // No evaluated setting within the bound is faster than the chosen one
    // by more than the 5 % within which speeds tie (and JOD decides:
    // Tune.SettingsWithinTheTimingNoiseAreChosenByJodThenPixels).
    const TunePoint* chosen = nullptr;
    for (const TunePoint& p : r.points) {
      if (p.technique == t && p.params == r.chosen.at(t)) chosen = &p;
    }
    ASSERT_NE(chosen, nullptr);
    if (chosen->within_bound) {
      for (const TunePoint& p : r.points) {
        if (p.technique == t && p.within_bound) {
          EXPECT_LE((1.0 - kTuneSpeedTie) * p.speedup, chosen->speedup + 1e-12);
        }
      }
    }
  }
  // The settings the choice fell between were timed again side by side
  // (stage 5): two or three per technique, within the bound, their earlier
  // points replaced (one point per setting and scene). Which settings those
  // are depends on the speeds measured (here, where foveation saves nothing
  // at 96x54, every margin is within the bound at about the same speed, but
  // a loaded machine can put one setting more than 15 % ahead of the rest):
  // Tune.TimesAgainTheSettingsTheChoiceFallsBetween checks the rule.
  std::set<std::tuple<std::string, std::string, std::map<std::string, double>>> keys;
  std::map<std::string, int> retimed;
  for (const TunePoint& p : r.points) {
    EXPECT_TRUE(keys.insert({p.scene, p.technique, p.params}).second) << p.technique;
    if (p.stage == 5) {
      ++retimed[p.technique];
      EXPECT_TRUE(p.within_bound) << p.technique;
    }
  }
  // Every benchmark warmed up alike: as long as layered's half rate (a tuned
  // value) needs, though stage 1 runs none with it.
  EXPECT_EQ(r.warmup, 6);
  for (const auto& [t, n] : retimed) {
    EXPECT_GE(n, 2) << t;
    EXPECT_LE(n, 3) << t;
  }
  const std::string out = fresh_dir("foveate-tune");
  write_tune_report(r, out);
  const ParamOverrides params = read_params_file(out + "/params.json");
  EXPECT_EQ(params.per_technique.at("layered"), r.chosen.at("layered"));
  const nlohmann::json j = read_json(out + "/tune.json");
  EXPECT_EQ(j["schema"], kTuneSchema);
  const TuneResult back = read_tune_results(j, out);
  ASSERT_EQ(back.points.size(), r.points.size());
  // Each point carries its benchmark's 95 % interval of the speedup, around
  // the speedup, through tune.json and into tune.md's fronts.
  for (size_t i = 0; i < r.points.size(); ++i) {
    const TunePoint& p = r.points[i];
    EXPECT_GT(p.speedup_lo, 0.0) << p.technique;
    EXPECT_LE(p.speedup_lo, p.speedup) << p.technique;
    EXPECT_GE(p.speedup_hi, p.speedup) << p.technique;
    EXPECT_DOUBLE_EQ(back.points[i].speedup_lo, p.speedup_lo);
    EXPECT_DOUBLE_EQ(back.points[i].speedup_hi, p.speedup_hi);
  }
  const std::string md = read_text(out + "/tune.md");
  EXPECT_NE(md.find("| speedup (95 % CI) |"), std::string::npos);
  const TunePoint front = tune_front(r, "cheap", "inset").front();
  char interval[64];
  std::snprintf(interval, sizeof interval, "x (%.2f-%.2f) |", front.speedup_lo, front.speedup_hi);
  EXPECT_NE(md.find(interval), std::string::npos) << md;
  // A benchmark with the chosen parameters.
  // The file holds inset's values too: a benchmark takes those of the
  // techniques it runs (a value for one not run is an error, not ignored).
  BenchOptions b = tiny();
  b.techniques = std::vector<std::string>{"native", "layered"};
  b.params = params.only(*b.techniques);
  const BenchResult with_params = run(b);
  for (const auto& chosen : r.chosen.at("layered")) {
    const auto& ps = with_params.results[1].parameters;
    const auto it = std::find_if(ps.begin(), ps.end(),
                                 [&](const auto& kv) { return kv.first == chosen.first; });
    ASSERT_NE(it, ps.end());
    EXPECT_EQ(it->second, chosen.second);
  }
  std::filesystem::remove_all(out);
}

// Values given for a parameter replace those it declares, in every stage,
// and make a parameter searched that is not by default; the record says so.
TEST(Tune, SearchesTheValuesGivenInsteadOfTheDeclaredOnes) {
  TuneOptions o = small_tune({"inset"});
  o.values = {{"margin", {2, 1}}, {"inset.scale", {0.45}}, {"latency_ms", {20}}};
  const TuneResult r = run_tune(o);
  std::set<double> margins, scales;
  bool latency = false;
  for (const TunePoint& p : r.points) {
    ASSERT_EQ(p.technique, "inset");
    if (p.params.count("margin")) margins.insert(p.params.at("margin"));
    if (p.params.count("scale")) scales.insert(p.params.at("scale"));
    for (const char* k : {"scale", "latency_ms"}) {
      // Searched one at a time from stage 1's best margin.
      if (p.params.count(k) && p.stage == 2) {
        EXPECT_EQ(p.params.size(), 2u) << k;
      }
    }
    latency = latency || p.params.count("latency_ms");
  }
  EXPECT_EQ(margins, (std::set<double>{1, 2}));
  EXPECT_EQ(scales, std::set<double>{0.45});
  EXPECT_TRUE(latency);
  EXPECT_EQ(r.options.values.at("margin"), (std::vector<double>{1, 2}));  // ascending
  EXPECT_NE(tune_markdown(r).find("Values searched instead of the declared ones: "
                                  "inset.scale=0.45 latency_ms=20 margin=1,2."),
            std::string::npos);
  // The values are part of the settings shards of one run must share.
  const std::string dir = fresh_dir("foveate-tune-values");
  write_tune_report(r, dir);
  const TuneResult back = read_tune_results(read_json(dir + "/tune.json"), dir);
  EXPECT_EQ(back.options.values, r.options.values);
  TuneOptions other = o;
  other.values.erase("latency_ms");
  EXPECT_NE(back.settings_key, tune_settings_key(other));
  EXPECT_EQ(back.settings_key, tune_settings_key(r.options));
  std::filesystem::remove_all(dir);
}

// A tune grid split into shards and merged evaluates the same candidates
// with the same JOD as the grid in one run.
TEST(Tune, ShardsMergedEqualTheGrid) {
  TuneOptions o = small_tune({"inset"});
  o.grid = true;
  const TuneResult whole = run_tune(o);
  std::vector<TuneResult> shards;
  for (int k = 0; k < 3; ++k) {
    TuneOptions s = o;
    s.shard = {k, 3};
    const std::string dir = fresh_dir("foveate-tune-shard-" + std::to_string(k));
    write_tune_report(run_tune(s), dir);
    shards.push_back(read_tune_results(read_json(dir + "/tune.json"), dir));
    std::filesystem::remove_all(dir);
  }
  const TuneResult merged = merge_tune_shards(shards, {"a", "b", "c"});
  ASSERT_EQ(merged.points.size(), whole.points.size());
  for (const TunePoint& p : whole.points) {
    const auto it = std::find_if(
        merged.points.begin(), merged.points.end(),
        [&](const TunePoint& q) { return q.technique == p.technique && q.params == p.params; });
    ASSERT_NE(it, merged.points.end());
    EXPECT_DOUBLE_EQ(it->jod, p.jod);
  }
  EXPECT_EQ(error_of([&] {
              (void)merge_tune_shards({shards[0], shards[1]}, {"a", "b"});
            }),
            "a: one of 3 shards, and shard 3 of 3 is not given: every shard's results are "
            "needed to join them");
  EXPECT_NE(error_of([&] {
              (void)merge_tune_shards({shards[1]}, {"b"});
            }).find("shards 1, 3 of 3 are not given"),
            std::string::npos);
}
