// foveate tune: the fastest parameters of every technique within a JOD bound
// of native's, on the scenes given (the search: foveate/bench/tune.hpp).
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>

#include "cli_util.hpp"
#include "commands.hpp"
#include "foveate/bench/tune.hpp"
#include "foveate/core/error.hpp"
#include "foveate/techniques/supersampled_native.hpp"
#include "invocation.hpp"
#include "messages.hpp"
#include "output_dir.hpp"
#include "photometry_flags.hpp"
#include "progress.hpp"
#include "session_args.hpp"

namespace foveate::app {

namespace {

struct TuneArgs {
  std::string scenes = "guenter,raymarch";
  std::string techniques;
  double bound = 0.25;
  std::string size = kDefaultSize;
  std::string display = bench::SessionOptions{}.display;
  PhotometryOverrides photometry;
  std::string acuity_preset;
  std::optional<double> slope;
  std::string gaze;
  double fps = bench::SessionOptions{}.fps;
  int frames = bench::TuneOptions::default_bench().frames;
  int warmup = bench::TuneOptions::default_bench().warmup;
  std::string reference = "ssaa:4";
  bool grid = false;
  std::vector<std::string> values;
  std::string shard;
  std::string memory_limit;
  std::string out = "tune-out";
  bool overwrite = false;
  bool json = false;
};

std::vector<std::string> split_list(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');) {
    if (!item.empty()) out.push_back(item);
  }
  return out;
}

bench::TuneOptions to_options(const TuneArgs& a) {
  bench::TuneOptions o;
  o.scenes = split_list(a.scenes);
  if (!a.techniques.empty()) o.techniques = split_list(a.techniques);
  o.bound_jod = a.bound;
  bench::SessionOptions& s = o.bench.session;
  s.size = parse_size(a.size, "--size");
  s.display = a.display;
  s.photometry = a.photometry;
  s.acuity = bench::acuity_from(a.acuity_preset, a.slope);
  s.gaze = a.gaze;
  s.fps = a.fps;
  o.bench.frames = a.frames;
  o.bench.warmup = a.warmup;
  o.bench.reference = with_flag("--reference", [&] { return parse_reference(a.reference); });
  o.bench.command = invocation();
  o.grid = a.grid;
  for (const std::string& v : a.values) {
    auto [key, list] = parse_key_values(v, "--values", "KEY=V1,V2,... (e.g. vrs.adapt=0.3,0.4)");
    if (!o.values.emplace(key, std::move(list)).second)
      throw Error("--values: " + key + " is given twice (one list per parameter)");
  }
  if (!a.shard.empty()) o.shard = bench::parse_shard(a.shard);
  if (!a.memory_limit.empty())
    o.bench.memory_limit_bytes = double(parse_byte_size(a.memory_limit, "--memory-limit"));
  bench::validate(o);
  return o;
}

void run(const TuneArgs& a) {
  const bench::TuneOptions o = to_options(a);
  const OutputDirLock out_lock(a.out, "--out", a.overwrite);
  std::optional<Progress> progress;
  // Each stage is a benchmark of its own, whose progress counts its own
  // steps and time: the label says which one, lest its time left read as
  // the whole search's.
  std::string label = "tune";
  bench::TuneCallbacks c;
  c.bench.session = session_callbacks();
  c.stage = [&](const std::string& scene, int stage, int candidates) {
    label = "tune (" + scene + ", stage " + std::to_string(stage) + ")";
    if (!quiet() && !a.json) {
      // Stage 5 times again settings already measured (tune.hpp).
      std::cerr << "tune: " << scene << ", stage " << stage << ": " << candidates
                << (candidates == 1 ? " candidate" : " candidates")
                << (stage == 5 ? " timed again side by side" : "") << " beside native" << std::endl;
    }
  };
  c.bench.start = [&](int steps, int metrics_steps) {
    progress.emplace(label, "steps", steps, !quiet() && !a.json);
    progress->expect("metrics", metrics_steps);
  };
  c.bench.step = [&](const std::string& d, const std::string& k) { progress->step(d, k); };
  c.bench.finish = [&] { progress->finish(); };
  const bench::TuneResult r = bench::run_tune(o, c);
  bench::write_tune_report(r, a.out);
  if (a.json) {
    std::cout << bench::tune_json(r).dump(2) << '\n';
    return;
  }
  std::cout << bench::tune_markdown(r);
  if (!quiet()) {
    const std::filesystem::path d(a.out);
    std::cout << "\nparameters: " << (d / "params.json").string()
              << " (--params-file for render, bench and view)\nreport: "
              << (d / "report.html").string() << "\n";
  }
}

}  // namespace

void register_tune(CLI::App& app);
const CommandRegistrar kTune(31, register_tune);

void register_tune(CLI::App& app) {
  auto a = std::make_shared<TuneArgs>();
  CLI::App* sub = app.add_subcommand(
      "tune",
      "Search every technique's tuned parameters (its planning margin first) for the fastest "
      "setting whose FovVideoVDP JOD stays within --bound of native's on every scene (settings "
      "within 5 % of its speed tie: the most JOD, then the fewest pixels); writes params.json "
      "for --params-file");
  sub->add_option("--scenes", a->scenes, "Comma-separated scenes to tune on")
      ->capture_default_str();
  sub->add_option("--techniques", a->techniques,
                  "Comma-separated techniques (default: every technique but native; each scene "
                  "leaves out those it cannot run)");
  sub->add_option("--bound", a->bound,
                  "How far below native's JOD a setting may be (JOD; 0.25 = 57 % of observers "
                  "prefer native)")
      ->capture_default_str();
  sub->add_option("--size", a->size, "Output size WxH")->capture_default_str();
  sub->add_option("--display", a->display,
                  "Display preset (" + Display::preset_names() + ") or JSON file")
      ->capture_default_str();
  add_photometry_flags(*sub, a->photometry);
  add_acuity_options(sub, a->acuity_preset, a->slope);
  sub->add_option("--gaze", a->gaze, "Gaze source (default the centre)");
  sub->add_option("--fps", a->fps, "Frame rate of the fixed clock")->capture_default_str();
  sub->add_option("--frames", a->frames, "Measured frames per candidate (a moving camera)")
      ->capture_default_str();
  sub->add_option("--warmup", a->warmup,
                  "Warm-up frames per candidate, at least: every candidate warms up as long as the "
                  "slowest to settle takes, so that all are measured on the same frames (a note "
                  "says so; tune.md names them)")
      ->capture_default_str();
  sub->add_option("--reference", a->reference,
                  "What JOD is judged against: ssaa[:N] (native with NxN supersampling) or native")
      ->capture_default_str();
  sub->add_flag("--grid", a->grid,
                "Evaluate the fixed grid (every margin crossed with one other parameter changed "
                "at a time) instead of the staged search, as shards do");
  sub->add_option("--values", a->values,
                  "KEY=V1,V2,...: the values to search for a parameter instead of those it "
                  "declares ('foveate techniques' lists them; KEY for every technique that has "
                  "it, TECHNIQUE.KEY for one; a parameter not searched by default becomes "
                  "searched); repeat the flag for more parameters");
  sub->add_option("--shard", a->shard,
                  "Run job K of N (K/N) of a fixed grid of candidates; 'foveate merge' joins the "
                  "jobs' --out folders");
  add_memory_limit_option(sub, a->memory_limit, "candidate");
  sub->add_option("--out", a->out, "Output folder: tune.json, tune.md, params.json, report.html")
      ->capture_default_str();
  add_overwrite_flag(sub, a->overwrite);
  sub->add_flag("--json", a->json, "Print tune.json instead of the tables");
  sub->callback([a] { run(*a); });
}

}  // namespace foveate::app
