// The benchmark library without a GL context: options checked field by
// field, messages that name fields for each front end to spell, sweeps,
// parameter overrides, the frame orders and whether a display leaves
// anything to save.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <set>

#include "errors.hpp"
#include "foveate/bench/bench.hpp"
#include "foveate/bench/frame_order.hpp"
#include "foveate/bench/params_file.hpp"
#include "foveate/bench/report.hpp"
#include "foveate/bench/savings.hpp"
#include "foveate/bench/statistics.hpp"
#include "foveate/bench/tune.hpp"

using namespace foveate;
using namespace foveate::bench;
using foveate::test::error_of;

namespace {

// The field an OptionError names, or "no error".
std::string field_of(const std::function<void()>& fn) {
  try {
    fn();
  } catch (const OptionError& e) {
    return e.field();
  }
  return "no error";
}

}  // namespace

TEST(FieldText, EachFrontEndNamesTheFieldsItsOwnWay) {
  const FieldText t{"{gaze} x: pass {allow_fallback}; {other} stays", {"gaze", "allow_fallback"}};
  EXPECT_EQ(t.render(), "gaze x: pass allow_fallback; {other} stays");
  const auto flags = [](const std::string& f) {
    return f == "allow_fallback" ? std::string("--allow-fallback") : std::string();
  };
  EXPECT_EQ(t.render(flags), "gaze x: pass --allow-fallback; {other} stays");
  const OptionError e("frames", "expected 1..100000");
  EXPECT_EQ(std::string(e.what()), "frames: expected 1..100000");
  EXPECT_EQ(e.message([](const std::string&) { return std::string("--frames"); }),
            "--frames: expected 1..100000");
}

TEST(Options, ErrorsNameTheField) {
  BenchOptions o;
  o.frames = 0;
  EXPECT_EQ(error_of([&] { validate(o); }), "frames: expected 1..100000");
  o = {};
  o.techniques = std::vector<std::string>{};
  EXPECT_EQ(error_of([&] { validate(o); }), "techniques: give at least one technique");
  o.techniques = std::vector<std::string>{"warp"};
  EXPECT_EQ(field_of([&] { validate(o); }), "techniques");
  o = {};
  o.session.size = {0, 36};
  EXPECT_EQ(error_of([&] { validate(o); }), "size: each side must be 1..16384 pixels, got 0x36");
  o = {};
  o.session.margin = 0.5;
  EXPECT_EQ(field_of([&] { validate(o); }), "margin");
  o = {};
  o.session.frame_timeout_s = -1;
  EXPECT_EQ(error_of([&] { validate(o); }),
            "frame_timeout_s: expected 0 (no limit) to 86400 seconds, got -1");
  o = {};
  o.session.vergence_m = 2.0;
  EXPECT_EQ(error_of([&] { validate(o); }),
            "vergence_m: only with stereo (it sets where the two eyes converge)");
  o = {};
  o.reference = 4;
  o.session.stereo = true;
  EXPECT_EQ(field_of([&] { validate(o); }), "reference");
  o = {};
  o.side_by_side = true;
  EXPECT_EQ(error_of([&] { validate(o); }), "side_by_side: only with video");
  o = {};
  o.params.set("nope", 1);
  EXPECT_EQ(field_of([&] { validate(o); }), "params");
  EXPECT_EQ(error_of([] { acuity_from("A", 0.02); }),
            "acuity_preset and slope: give one, not both");
  EXPECT_EQ(field_of([] { acuity_from("Z", std::nullopt); }), "acuity_preset");
  EXPECT_EQ(acuity_from("b", std::nullopt).slope, kSlopePresetB);
}

TEST(Options, ParameterOverridesGoWhereTheyAreDeclared) {
  ParamOverrides p;
  p.set("layers", 2);
  p.set("inset.margin", 1.25);
  EXPECT_EQ(p.for_technique("layered"), (std::map<std::string, double>{{"layers", 2}}));
  EXPECT_EQ(p.for_technique("inset"), (std::map<std::string, double>{{"margin", 1.25}}));
  EXPECT_TRUE(p.for_technique("native").empty());
  EXPECT_EQ(error_of([&] {
              p.validate({"native", "inset"});
            }),
            "params layers: no such parameter in native, inset (see 'foveate techniques')");
  EXPECT_NE(
      error_of([&] { p.set("warp.layers", 1); }).find("params warp.layers: unknown technique"),
      std::string::npos);
}

TEST(Sweep, AppliesOnlyWhereTheKeyIsDeclared) {
  const Sweep slope = Sweep::range("slope", 0.02, 0.03, 0.005);
  EXPECT_EQ(slope.values.size(), 3u);
  EXPECT_TRUE(slope.applies_to("layered"));
  const Sweep one = Sweep::range("layered.layers", 2, 4, 1);
  EXPECT_TRUE(one.applies_to("layered"));
  EXPECT_FALSE(one.applies_to("inset"));
  const Sweep margin = Sweep::range("margin", 1, 2, 1);
  EXPECT_TRUE(margin.applies_to("checkerboard"));
  EXPECT_FALSE(margin.applies_to("native"));
  // A step too small to change the value gives one value, not an endless list.
  EXPECT_EQ(Sweep::range("slope", 1e16, 1e16, 1).values.size(), 1u);
  EXPECT_EQ(error_of([] { Sweep::range("slope", 0, 1, 1e-9); }),
            "sweep slope: 1000000000 values, over the limit of 50; use a larger STEP");
  EXPECT_EQ(error_of([] { Sweep::range("slope", 1, 0, 1); }),
            "sweep: need FROM <= TO and STEP > 0");
  EXPECT_NE(error_of([] { Sweep::range("nope", 1, 2, 1); }).find("no technique has"),
            std::string::npos);
  // Every value is checked against each declaration it will be given to
  // before anything runs: one technique's at once, a shared key's against
  // the techniques run (Options.ASweepIsCheckedAgainstTheTechniquesRun).
  BenchOptions o;
  o.sweep = Sweep::range("margin", 0.5, 1, 0.5);
  EXPECT_EQ(error_of([&] { validate(o); }),
            "sweep: layered parameter margin=0.5: out of range [1, 4]");
  EXPECT_EQ(error_of([] { Sweep::range("layered.layers", 2, 3, 0.5); }),
            "sweep: layered parameter layers=2.5: must be a whole number");
}

TEST(Sweep, ListedValuesRunInAscendingOrderEachOnce) {
  const Sweep listed = Sweep::of("vrs.adapt", {0.4, 0.0, 0.25});
  EXPECT_EQ(listed.values, (std::vector<double>{0.0, 0.25, 0.4}));
  EXPECT_EQ(listed.technique, "vrs");
  EXPECT_EQ(listed.param, "adapt");
  EXPECT_TRUE(listed.applies_to("vrs"));
  EXPECT_FALSE(listed.applies_to("layered"));
  EXPECT_EQ(Sweep::of("margin", {1.5}).values, std::vector<double>{1.5});
  EXPECT_EQ(error_of([] { Sweep::of("slope", {}); }), "sweep: give at least one value");
  EXPECT_EQ(error_of([] {
              Sweep::of("margin", {1, 2, 1});
            }),
            "sweep margin: 1 is listed twice (each value runs once)");
  EXPECT_EQ(error_of([] {
              Sweep::of("slope", {0.02, std::nan("")});
            }),
            "sweep: values must be finite numbers");
  EXPECT_EQ(error_of([] {
              Sweep::of("vrs.adapt", {0.25, 2});
            }),
            "sweep: vrs parameter adapt=2: out of range [0, 1]");
  EXPECT_EQ(error_of([] { Sweep::of("slope", std::vector<double>(51, 0.02)); }),
            "sweep slope: 51 values, over the limit of 50");
  // A range whose step is below the values' precision runs each value once.
  EXPECT_EQ(Sweep::range("slope", 1e16, 1e16 + 4, 1).values.size(), 3u);
}

TEST(FrameOrder, VariesWhatEachTechniqueFollows) {
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

TEST(Statistics, PassTimesAddUpToTheFrame) {
  std::vector<gpu::PassTime> sums;
  add_pass_times(sums, {{"shade", 5.0}, {"composite", 2.0}}, 10.0);
  add_pass_times(sums, {{"composite", 1.0}, {"warp", 1.0}}, 4.0);
  ASSERT_EQ(sums.size(), 4u);
  EXPECT_EQ(sums[0].name, "shade");
  EXPECT_EQ(sums[1].ms, 3.0);
  EXPECT_EQ(sums[2].name, "warp");
  EXPECT_EQ(sums[3].name, "other");
  EXPECT_EQ(sums[3].ms, 5.0);
  const auto [lo, hi] = speedup_interval({10, 10, 10}, {5, 5, 5});
  EXPECT_DOUBLE_EQ(lo, 2.0);
  EXPECT_DOUBLE_EQ(hi, 2.0);
}

TEST(Savings, SmallRendersOfTheDesktopDisplayHaveNothingToSave) {
  const Display d = Display::load("desktop-1080p");
  const AcuityModel a = AcuityModel::preset("A");
  const SavingsCheck small = check_savings(d.resized(320, 180), a);
  EXPECT_TRUE(small.nothing_to_save);
  EXPECT_LT(small.pixel_bound, 1.2);
  EXPECT_NEAR(small.centre_ppd, 6.5, 0.1);  // a sixth of the paper's ~39 px/deg
  const std::string note = small.note.render();
  EXPECT_NE(note.find("320x180"), std::string::npos);
  EXPECT_NE(note.find("try size 1280x720"), std::string::npos) << note;
  const SavingsCheck full = check_savings(d.resized(1920, 1080), a);
  EXPECT_FALSE(full.nothing_to_save);
  EXPECT_NEAR(full.pixel_bound, 8.49, 0.1);  // plan's 3 layers at full rate
  EXPECT_TRUE(full.note.text.empty());
}

// At 960x540 and 640x360 the desktop display leaves too little to save for
// the techniques' own plans (checkerboard shaded 100 %, layered ran 0.39x at
// 960x540): the note is given below kLittleToSaveBound at the finest plan the
// techniques make by default (the strictest own margin: lodmask's and
// marwarp's 2), not only near 1x. At 1280x720 that plan's bound is 1.79x.
TEST(Savings, TheNoteIsGivenUnderTheClearThresholdAtTheTechniquesOwnPlans) {
  const Display d = Display::load("desktop-1080p");
  const AcuityModel a = AcuityModel::preset("A");
  const double margin = strictest_plan_margin(std::nullopt);
  EXPECT_DOUBLE_EQ(margin, 2.0);
  EXPECT_DOUBLE_EQ(own_plan_margin("layered"), 1.5);
  EXPECT_DOUBLE_EQ(own_plan_margin("native"), 1.0);
  EXPECT_DOUBLE_EQ(strictest_plan_margin(1.25), 1.25);
  for (const auto& [w, h] : {std::pair{960, 540}, std::pair{640, 360}}) {
    const SavingsCheck c = check_savings(d.resized(w, h), a, margin);
    EXPECT_TRUE(c.nothing_to_save) << w << "x" << h << ": bound " << c.pixel_bound;
    const std::string note = c.note.render();
    EXPECT_NE(note.find("at planning margin 2 ("), std::string::npos) << note;
    EXPECT_NE(note.find("under 1.5x"), std::string::npos) << note;
    EXPECT_NE(note.find("try size 1280x720"), std::string::npos) << note;
  }
  EXPECT_FALSE(check_savings(d.resized(1920, 1080), a, margin).nothing_to_save);
  EXPECT_FALSE(check_savings(d.resized(1280, 720), a, margin).nothing_to_save);
  EXPECT_FALSE(check_savings(d.resized(960, 540), a, 1.0).nothing_to_save);  // the papers' plans
  // A display too small to plan layers on (0.1 deg across) has nothing to
  // save: a note, not an error.
  Display narrow = d;
  narrow.width_mm = 2;
  const SavingsCheck tiny = check_savings(narrow, a);
  EXPECT_TRUE(tiny.nothing_to_save);
  EXPECT_DOUBLE_EQ(tiny.pixel_bound, 1.0);
}

TEST(Savings, AWideFieldSavesEvenAtModestSizes) {
  const Display quest = Display::load("hmd-quest3").resized(640, 684);
  EXPECT_FALSE(check_savings(quest, AcuityModel::preset("A")).nothing_to_save);
}

// A parameters file: checked against the declarations, errors that name the
// file and the entry; explicit runs and shards checked like other options.
TEST(ParamsFile, ReadBackAndErrorsNameTheEntry) {
  const std::string dir = testing::TempDir();
  const std::string path = dir + "/foveate-params-test.json";
  write_params_file(path, {{"layered", {{"margin", 1.25}, {"half_rate", 0}}}}, "test");
  const ParamOverrides p = read_params_file(path);
  EXPECT_EQ(p.per_technique.at("layered").at("margin"), 1.25);
  EXPECT_EQ(p.per_technique.at("layered").at("half_rate"), 0.0);
  const auto with = [&](const std::string& text) {
    const std::string f = dir + "/foveate-params-bad.json";
    FILE* out = std::fopen(f.c_str(), "w");
    std::fputs(text.c_str(), out);
    std::fclose(out);
    return error_of([&] { (void)read_params_file(f); });
  };
  const std::string head = R"({"schema": "foveate-params/1", "techniques": )";
  EXPECT_NE(with(head + R"({"nope": {}}})").find("techniques.nope"), std::string::npos);
  EXPECT_NE(with(head + R"({"layered": {"colour": 1}}})").find("techniques.layered.colour"),
            std::string::npos);
  EXPECT_NE(with(head + R"({"layered": {"margin": 9}}})").find("outside [1, 4]"),
            std::string::npos);
  EXPECT_NE(with(R"({"schema": "x", "techniques": {}})").find("schema"), std::string::npos);
  EXPECT_NE(with("{").find("foveate-params-bad.json"), std::string::npos);
}

TEST(Options, RunsAndShardsAreChecked) {
  BenchOptions o;
  o.runs = {{"layered", {{"colour", 1.0}}, ""}};
  EXPECT_EQ(field_of([&] { validate(o); }), "runs");
  o.runs = {{"layered", {{"margin", 1.5}}, ""}};
  EXPECT_EQ(field_of([&] { validate(o); }), "no error");
  EXPECT_EQ(run_spec_label(o.runs[0]), "layered {margin=1.5}");
  o.techniques = std::vector<std::string>{"layered"};
  EXPECT_EQ(field_of([&] { validate(o); }), "runs");  // runs or techniques, not both
  o = {};
  o.shard = {2, 2};
  EXPECT_EQ(field_of([&] { validate(o); }), "shard");
  TuneOptions t;
  t.bound_jod = 0;
  EXPECT_EQ(field_of([&] { validate(t); }), "bound_jod");
  t = {};
  t.techniques = std::vector<std::string>{"native"};
  EXPECT_EQ(field_of([&] { validate(t); }), "techniques");
}

// A technique or scene given twice would be run (or searched, judged) twice
// and reported twice under one name: refused, naming the list and the name.
TEST(Options, ATechniqueOrSceneListedTwiceIsRefused) {
  BenchOptions o;
  o.techniques = std::vector<std::string>{"inset", "layered", "inset"};
  const auto flags = [](const std::string& f) { return "--" + f; };
  try {
    validate(o);
    ADD_FAILURE() << "no error";
  } catch (const OptionError& e) {
    EXPECT_EQ(e.field(), "techniques");
    EXPECT_EQ(e.message(flags),
              "--techniques: 'inset' is listed twice (each runs once; compare settings of one "
              "technique with --sweep)");
  }
  o.techniques = std::vector<std::string>{"native", "native"};
  EXPECT_EQ(field_of([&] { validate(o); }), "techniques");
  o.techniques = std::vector<std::string>{"native", "inset", "layered"};
  EXPECT_EQ(field_of([&] { validate(o); }), "no error");
  TuneOptions t;
  t.scenes = {"guenter", "raymarch", "guenter"};
  EXPECT_EQ(error_of([&] { validate(t); }),
            "scenes: 'guenter' is listed twice (each scene is judged once)");
  t.scenes = {"guenter", "raymarch"};
  t.techniques = std::vector<std::string>{"vrs", "vrs"};
  EXPECT_EQ(error_of([&] { validate(t); }),
            "techniques: 'vrs' is listed twice (each is searched once)");
  t.techniques = std::vector<std::string>{"vrs", "inset"};
  EXPECT_EQ(field_of([&] { validate(t); }), "no error");
}

// tune's values: each list checked as a sweep's, against the techniques
// searched; errors name the field and the key.
TEST(Options, TuneValuesAreCheckedAgainstTheTechniquesSearched) {
  TuneOptions t;
  t.techniques = std::vector<std::string>{"inset", "vrs"};
  t.values = {{"margin", {2, 1}}, {"vrs.adapt", {0.3, 0.4}}, {"inset.scale", {0.5}}};
  EXPECT_EQ(field_of([&] { validate(t); }), "no error");
  // A parameter that is declared but not searched by default may be.
  t.values = {{"vrs.fixed", {0, 1}}};
  EXPECT_EQ(field_of([&] { validate(t); }), "no error");
  t.values = {{"layered.layers", {2, 3}}};
  EXPECT_EQ(
      error_of([&] { validate(t); }),
      "values layered.layers: none of techniques has that parameter (see 'foveate techniques')");
  t.values = {{"vrs.adapt", {0.4, 0.4}}};
  EXPECT_EQ(error_of([&] { validate(t); }),
            "values vrs.adapt: 0.4 is listed twice (each value runs once)");
  t.values = {{"vrs.adapt", {1.5}}};
  EXPECT_EQ(error_of([&] { validate(t); }), "values: vrs parameter adapt=1.5: out of range [0, 1]");
  t.values = {{"vrs.adapt", {}}};
  EXPECT_EQ(error_of([&] { validate(t); }), "values: give at least one value");
  t.values = {{"nope", {1}}};
  EXPECT_EQ(field_of([&] { validate(t); }), "values");
  t.values = {{"slope", {0.02}}};
  EXPECT_EQ(error_of([&] { validate(t); }),
            "values: slope: the metrics' acuity, not a technique's parameter (tune plans every "
            "technique for it; search the planning margin instead)");
  // A margin every searched technique refuses is blamed on one of them.
  t.techniques = std::vector<std::string>{"inset"};
  t.values = {{"margin", {9}}};
  EXPECT_EQ(error_of([&] { validate(t); }),
            "values: inset parameter margin=9: out of range [1, 4]");
}

// A sweep must repeat a run that the benchmark makes, and its values are
// judged by the techniques it runs: a key no listed technique has would
// measure one run labelled with a value never given to it.
TEST(Options, ASweepIsCheckedAgainstTheTechniquesRun) {
  BenchOptions o;
  o.techniques = std::vector<std::string>{"logpolar"};
  o.sweep = Sweep::of("layered.layers", {1, 2, 3});
  EXPECT_EQ(error_of([&] { validate(o); }),
            "sweep layered.layers: none of techniques has that parameter (see 'foveate "
            "techniques')");
  // inset takes a scale of 0.5, checkerboard (which also declares `scale`,
  // as a whole number) is not run: no error.
  o.techniques = std::vector<std::string>{"native", "inset"};
  o.sweep = Sweep::of("scale", {0.5, 0.6});
  EXPECT_EQ(field_of([&] { validate(o); }), "no error");
  o.techniques = std::vector<std::string>{"checkerboard"};
  EXPECT_EQ(error_of([&] { validate(o); }),
            "sweep: checkerboard parameter scale=0.5: must be a whole number");
  // The slope changes every technique.
  o.sweep = Sweep::range("slope", 0.02, 0.03, 0.01);
  EXPECT_EQ(field_of([&] { validate(o); }), "no error");
  // Every technique's margin swept beside the session's margin: one of them
  // would not be what results.json says; one technique's margin swept
  // beside it (for the others) is a run of its own.
  o.techniques = std::vector<std::string>{"native", "inset"};
  o.session.margin = 1.5;
  o.sweep = Sweep::of("margin", {1, 2});
  EXPECT_EQ(error_of([&] { validate(o); }),
            "sweep margin and margin: the sweep sets each run's margin; give one of them");
  o.sweep = Sweep::of("inset.margin", {1, 2});
  EXPECT_EQ(field_of([&] { validate(o); }), "no error");
}

// Runs that would hold more memory together than the limit are judged in
// groups, each with native: at most (limit / one run's bytes) runs at once.
// A limit that holds not even native and one run, or a video (every run's
// frames tiled) that would need groups, is refused naming the field.
TEST(Options, RunsBeyondTheMemoryLimitAreJudgedInGroups) {
  BenchOptions o;
  o.session.size = {1920, 1080};
  o.frames = 8;
  o.techniques = std::vector<std::string>{"layered", "inset", "vrs", "marwarp", "checkerboard"};
  // FovVideoVDP's state (150 bytes a pixel and 8 per frame its filters
  // reach: 9 frames here) and 30 for the technique.
  const double per_run = judged_run_bytes(o);
  EXPECT_DOUBLE_EQ(per_run, 1920.0 * 1080.0 * (150.0 + 8.0 * 9.0 + 30.0));
  EXPECT_EQ(judging_groups(o, 0.0), 1);             // no limit
  EXPECT_EQ(judging_groups(o, 6.0 * per_run), 1);   // native and 5 runs fit
  EXPECT_EQ(judging_groups(o, 5.99 * per_run), 2);  // 4 at a time: 4 + 1
  EXPECT_EQ(judging_groups(o, 3.0 * per_run), 3);   // 2 at a time: 2 + 2 + 1
  EXPECT_EQ(judging_groups(o, 2.0 * per_run), 5);   // 1 at a time
  EXPECT_EQ(field_of([&] { (void)judging_groups(o, 1.99 * per_run); }), "memory_limit");
  // A sweep counts each value; a shard only its own runs (3 of 5 here).
  o.sweep = Sweep::range("margin", 1.0, 3.0, 1.0);
  EXPECT_EQ(judging_groups(o, 2.0 * per_run), 15);
  o.shard = {0, 5};
  EXPECT_EQ(judging_groups(o, 2.0 * per_run), 3);
  o.shard = {};
  o.sweep = {};
  // Stereo: four series of one eye's size, two views rendered.
  BenchOptions stereo = o;
  stereo.session.stereo = true;
  EXPECT_DOUBLE_EQ(judged_run_bytes(stereo), 1920.0 * 1080.0 * (4.0 * (150.0 + 72.0) + 60.0));
  // Without image metrics nothing is judged: one group whatever the limit.
  BenchOptions plain = o;
  plain.image_metrics = false;
  EXPECT_EQ(judged_run_bytes(plain), 0.0);
  EXPECT_EQ(judging_groups(plain, 1.0), 1);
  o.video = "bench.mp4";
  EXPECT_EQ(judging_groups(o, 6.0 * per_run), 1);
  EXPECT_EQ(field_of([&] { (void)judging_groups(o, 3.0 * per_run); }), "video");
  o.video.clear();
  o.memory_limit_bytes = -1.0;
  EXPECT_EQ(field_of([&] { validate(o); }), "memory_limit");
  o.memory_limit_bytes = 0.0;
  o.group = {1, 1};
  EXPECT_EQ(field_of([&] { validate(o); }), "group");
  // The machine says how much it has.
  EXPECT_GT(available_memory_bytes(), 0.0);
}

// The table and results.json say which runs had little to save (†) and which
// frames ran in the gaze's fallback (‡), so that no figure silently measures
// a fallback.
TEST(Report, MarksRunsWithLittleToSaveAndFramesInFallback) {
  BenchResult b;
  b.options.frames = 6;
  b.options.session.size = {64, 36};
  b.techniques = {"native", "layered"};
  TechniqueResult native, layered;
  native.technique = "native";
  layered.technique = "layered";
  b.results = {native, layered};
  const std::string plain = bench_markdown(b);
  EXPECT_EQ(plain.find("†"), std::string::npos) << plain;
  EXPECT_EQ(plain.find("‡"), std::string::npos) << plain;
  b.savings.nothing_to_save = true;
  b.savings.pixel_bound = 1.04;
  b.savings.margin = 2;
  b.fallback_frames = {3, 4, 5};
  const std::string md = bench_markdown(b);
  EXPECT_NE(md.find("| native ‡ |"), std::string::npos) << md;
  EXPECT_NE(md.find("| layered † ‡ |"), std::string::npos) << md;
  EXPECT_NE(md.find("† Little to save: at 64x36 the planner's pixel bound is 1.04x (planning "
                    "margin 2), under 1.5x"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("‡ Gaze fallback: 3 of 6 measured frames (3, 4, 5, counted from 0)"),
            std::string::npos)
      << md;
  BenchResult runs_only = b;
  runs_only.results.clear();
  const nlohmann::json j = bench_json(runs_only);
  EXPECT_EQ(j["gaze_fallback_frames"], nlohmann::json({3, 4, 5}));
  EXPECT_EQ(j["savings"]["little_to_save"], true);
  EXPECT_DOUBLE_EQ(j["savings"]["pixel_bound"].get<double>(), 1.04);
}

// tune's stage 3 (no GL: points written by hand). From the best point
// (margin 2), stage 2 found two changes that kept the bound and gained speed
// (transition, layers), and one that raised JOD at a cost (half_rate 0); a
// fourth change (jitter) did neither.
TEST(Tune, CombinesTheChangesThatPaidAndSpendsQualityOnCoarserPlans) {
  const auto point = [](std::map<std::string, double> params, double speedup, double jod) {
    TunePoint p;
    p.scene = "guenter";
    p.technique = "layered";
    p.params = std::move(params);
    p.stage = 2;
    p.speedup = speedup;
    p.jod = jod;
    p.within_bound = jod >= 9.5;
    return p;
  };
  const TunePoint best = point({{"margin", 2.0}, {"half_rate", 1.0}}, 1.5, 9.55);
  const std::vector<std::pair<std::string, std::vector<double>>> axes = {
      {"margin", {1.0, 1.25, 1.5, 2.0, 2.5, 3.0}},
      {"transition", {0.1, 0.2, 0.4}},
      {"layers", {2, 3}},
      {"half_rate", {0, 1}},
      {"jitter", {0, 1}}};
  const std::vector<TunePoint> stage2 = {
      point({{"margin", 2.0}, {"half_rate", 1.0}, {"transition", 0.1}}, 1.6, 9.52),
      point({{"margin", 2.0}, {"half_rate", 1.0}, {"transition", 0.4}}, 1.55, 9.56),
      point({{"margin", 2.0}, {"half_rate", 1.0}, {"layers", 3}}, 1.7, 9.50),
      // Faster, but over the bound: not combined.
      point({{"margin", 2.0}, {"half_rate", 1.0}, {"jitter", 0}}, 1.9, 9.40),
      // Slower and better by 0.15 JOD (half rate at its default, 0: absent).
      point({{"margin", 2.0}}, 1.2, 9.70),
      // Another margin: not a single change of the best point.
      point({{"margin", 1.5}, {"half_rate", 1.0}, {"transition", 0.1}}, 2.5, 9.6)};
  const std::vector<std::map<std::string, double>> c = tune_combinations(stage2, best, axes);
  ASSERT_EQ(c.size(), 4u);
  // The fastest speed-gaining value of each parameter, together.
  EXPECT_EQ(c[0], (std::map<std::string, double>{
                      {"margin", 2.0}, {"half_rate", 1.0}, {"transition", 0.1}, {"layers", 3}}));
  // The JOD-raising change at every margin below 2, the nearest first.
  EXPECT_EQ(c[1], (std::map<std::string, double>{{"margin", 1.5}}));
  EXPECT_EQ(c[2], (std::map<std::string, double>{{"margin", 1.25}}));
  EXPECT_EQ(c[3], (std::map<std::string, double>{{"margin", 1.0}}));
  // Nothing paid: nothing to combine. At the lowest margin there is no
  // coarser plan to spend quality on.
  EXPECT_TRUE(tune_combinations({}, best, axes).empty());
  TunePoint lowest = best;
  lowest.params["margin"] = 1.0;
  EXPECT_TRUE(tune_combinations({point({{"margin", 1.0}}, 1.2, 9.70)}, lowest, axes).empty());
}

// tune's stages 2 and 3 start from stage 1's best point, even where a
// change of stage 2 is faster within the bound (no GL: points written by
// hand, from inset's run of 2026-11-27 on guenter). Stage 3 combined the
// changes on the faster point before, of which the JOD-raising change
// (scale 0.65) was no single change, so it was never tried at coarser plans.
TEST(Tune, StageThreeCombinesOnThePointStageTwoChanged) {
  const auto point = [](std::map<std::string, double> params, int stage, double speedup,
                        double jod) {
    TunePoint p;
    p.scene = "guenter";
    p.technique = "inset";
    p.params = std::move(params);
    p.stage = stage;
    p.speedup = speedup;
    p.jod = jod;
    p.within_bound = jod >= 9.541;
    p.below_native = 9.791 - jod;
    return p;
  };
  std::vector<TunePoint> points = {point({{"margin", 1.5}}, 1, 2.02, 9.527),
                                   point({{"margin", 2.0}}, 1, 1.71, 9.589),
                                   point({{"margin", 3.0}}, 1, 1.18, 9.68),
                                   point({{"margin", 2.0}, {"scale", 0.65}}, 2, 1.52, 9.716),
                                   point({{"margin", 2.0}, {"border", 0.1}}, 2, 1.78, 9.582)};
  // Another scene's and another technique's points do not count.
  points.push_back(point({{"margin", 1.0}}, 1, 3.0, 9.7));
  points.back().scene = "raymarch";
  points.push_back(point({{"margin", 1.0}}, 1, 3.0, 9.7));
  points.back().technique = "vrs";
  const TunePoint* any = tune_best_point(points, "guenter", "inset");
  const TunePoint* base = tune_best_point(points, "guenter", "inset", 1);
  ASSERT_TRUE(any && base);
  EXPECT_EQ(any->params.at("border"), 0.1);  // the fastest within the bound
  EXPECT_EQ(base->params, (std::map<std::string, double>{{"margin", 2.0}}));
  std::vector<TunePoint> stage2;
  for (const TunePoint& p : points) {
    if (p.stage == 2) stage2.push_back(p);
  }
  const std::vector<std::pair<std::string, std::vector<double>>> axes = {
      {"margin", {1.0, 1.25, 1.5, 2.0, 2.5, 3.0}},
      {"scale", {0.35, 0.5, 0.65}},
      {"border", {0.1, 0.2, 0.4}}};
  using P = std::map<std::string, double>;
  EXPECT_EQ(tune_combinations(stage2, *base, axes),
            (std::vector<P>{{{"margin", 1.5}, {"scale", 0.65}},
                            {{"margin", 1.25}, {"scale", 0.65}},
                            {{"margin", 1.0}, {"scale", 0.65}}}));
  // From the faster point nothing is a single change: nothing to try.
  EXPECT_TRUE(tune_combinations(stage2, *any, axes).empty());
  // No point of the stage asked for: none.
  EXPECT_EQ(tune_best_point(points, "guenter", "inset", 3), nullptr);
  // None within the bound: the closest to it.
  for (TunePoint& p : points) p.within_bound = false;
  EXPECT_EQ(tune_best_point(points, "guenter", "inset", 1)->params.at("margin"), 3.0);
}

// tune's choice (no GL: points written by hand, from the run of 2026-11-27
// evening on two scenes): the fastest within the bound, but settings within
// 5 % of its speed tie, and of those the most JOD wins, then the fewest
// pixels.
TEST(Tune, SettingsWithinTheTimingNoiseAreChosenByJodThenPixels) {
  TuneResult r;
  r.options.bound_jod = 0.25;
  const auto add = [&](const std::string& t, std::map<std::string, double> params,
                       const std::string& scene, double speedup, double below, double pixels) {
    TunePoint p;
    p.scene = scene;
    p.technique = t;
    p.params = std::move(params);
    p.speedup = speedup;
    p.below_native = below;
    p.jod = 9.8 - below;
    p.pixel_ratio = pixels;
    p.within_bound = below <= 0.25;
    r.points.push_back(p);
  };
  // marwarp: sharpening is 1 % faster by noise at the same pixels and loses
  // 0.02 JOD: the plain setting.
  add("marwarp", {{"margin", 2.0}, {"sharpen", 0.12}}, "guenter", 1.92, 0.244, 0.195);
  add("marwarp", {{"margin", 2.0}, {"sharpen", 0.12}}, "raymarch", 3.69, 0.131, 0.175);
  add("marwarp", {{"margin", 2.0}}, "guenter", 1.90, 0.223, 0.195);
  add("marwarp", {{"margin", 2.0}}, "raymarch", 3.69, 0.127, 0.175);
  // checkerboard: three blends within 0.002 JOD: the fewest pixels.
  add("checkerboard", {{"margin", 1.0}, {"blend", 0.4}}, "guenter", 1.85, 0.228, 0.295);
  add("checkerboard", {{"margin", 1.0}, {"blend", 0.4}}, "raymarch", 3.06, 0.103, 0.295);
  add("checkerboard", {{"margin", 1.0}}, "guenter", 1.81, 0.229, 0.288);
  add("checkerboard", {{"margin", 1.0}}, "raymarch", 3.20, 0.103, 0.288);
  add("checkerboard", {{"margin", 1.0}, {"blend", 0.1}}, "guenter", 1.90, 0.230, 0.285);
  add("checkerboard", {{"margin", 1.0}, {"blend", 0.1}}, "raymarch", 3.14, 0.102, 0.285);
  // vrs: 10 % faster is beyond the noise: the faster, though it keeps less.
  add("vrs", {{"margin", 1.25}}, "guenter", 2.0, 0.24, 0.18);
  add("vrs", {{"margin", 1.25}}, "raymarch", 4.0, 0.12, 0.18);
  add("vrs", {{"margin", 1.5}}, "guenter", 1.8, 0.20, 0.20);
  add("vrs", {{"margin", 1.5}}, "raymarch", 3.65, 0.09, 0.20);
  // A faster setting over the bound never ties.
  add("vrs", {{"margin", 1.0}}, "guenter", 2.0, 0.30, 0.14);
  add("vrs", {{"margin", 1.0}}, "raymarch", 4.1, 0.15, 0.14);
  choose_parameters(r);
  using P = std::map<std::string, double>;
  EXPECT_EQ(r.chosen.at("marwarp"), (P{{"margin", 2.0}}));
  EXPECT_EQ(r.chosen.at("checkerboard"), (P{{"margin", 1.0}, {"blend", 0.1}}));
  EXPECT_EQ(r.chosen.at("vrs"), (P{{"margin", 1.25}}));
  // Slowed by 10 %, blend 0.1 no longer ties: of the two that do, the plain
  // setting shades fewer pixels.
  for (TunePoint& p : r.points) {
    if (p.technique == "checkerboard" && p.params.count("blend") && p.params.at("blend") == 0.1)
      p.speedup *= 0.9;
  }
  choose_parameters(r);
  EXPECT_EQ(r.chosen.at("checkerboard"), (P{{"margin", 1.0}}));
}

// tune's stage 5 (no GL: points written by hand): the settings timed again
// side by side are the best one and the next within the bound on every scene
// whose speed (geometric mean over the scenes) is at least 0.85 of the
// best's, at most three.
TEST(Tune, TimesAgainTheSettingsTheChoiceFallsBetween) {
  TuneResult r;
  const auto add = [&](std::map<std::string, double> params, const std::string& scene,
                       double speedup, bool within) {
    TunePoint p;
    p.scene = scene;
    p.technique = "vrs";
    p.params = std::move(params);
    p.speedup = speedup;
    p.within_bound = within;
    p.below_native = within ? 0.2 : 0.3;
    r.points.push_back(p);
  };
  using P = std::map<std::string, double>;
  const P best = {{"margin", 1.25}}, tile = {{"margin", 1.25}, {"tile", 8}},
          third = {{"margin", 1.25}, {"min_class", 0.05}}, fourth = {{"margin", 1.5}},
          slow = {{"margin", 2}}, over = {{"margin", 1}}, one_scene = {{"margin", 3}};
  add(best, "guenter", 2.0, true);  // geometric mean 2.83
  add(best, "raymarch", 4.0, true);
  add(tile, "guenter", 1.9, true);  // 2.72
  add(tile, "raymarch", 3.9, true);
  add(third, "guenter", 1.8, true);  // 2.61
  add(third, "raymarch", 3.8, true);
  add(fourth, "guenter", 1.8, true);  // 2.55: within the share, beyond the three
  add(fourth, "raymarch", 3.6, true);
  add(slow, "guenter", 1.6, true);  // 2.19: below 0.85 of the best's speed
  add(slow, "raymarch", 3.0, true);
  add(over, "guenter", 2.4, false);  // fastest, but over the bound on one scene
  add(over, "raymarch", 5.0, true);
  add(one_scene, "raymarch", 10.0, true);  // not judged on every scene
  EXPECT_EQ(tune_contenders(r, "vrs"), (std::vector<P>{best, tile, third}));
  // One setting alone has nothing to be compared with.
  r.points.erase(
      std::remove_if(r.points.begin(), r.points.end(),
                     [&](const TunePoint& p) { return p.params != best && p.params != slow; }),
      r.points.end());
  EXPECT_TRUE(tune_contenders(r, "vrs").empty());
  EXPECT_TRUE(tune_contenders(r, "marwarp").empty());
}
