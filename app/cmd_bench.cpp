// foveate bench and foveate demo.
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "cli_util.hpp"
#include "commands.hpp"
#include "foveate/bench/report.hpp"
#include "foveate/core/error.hpp"
#include "foveate/techniques/supersampled_native.hpp"
#include "invocation.hpp"
#include "messages.hpp"
#include "output_dir.hpp"
#include "progress.hpp"
#include "session_args.hpp"

namespace foveate::app {

namespace {

struct BenchArgs {
  SessionArgs session;
  std::string techniques = join(technique_names(), ",");
  bool techniques_given = false;
  int frames = bench::BenchOptions{}.frames;
  int warmup = bench::BenchOptions{}.warmup;
  std::string sweep;
  std::string out = "bench-out";
  bool overwrite = false;
  std::string reference = "native";
  bool no_metrics = false;
  bool no_diagnostics = false;
  bool passes = false;
  std::string video;
  bool side_by_side = false;
  bool json = false;
  bool allow_fallback = false;
  std::string shard;
  std::string memory_limit;
};

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, sep)) {
    if (!item.empty()) out.push_back(item);
  }
  return out;
}

/// --sweep KEY=FROM:TO:STEP or KEY=V1,V2,...
bench::Sweep parse_sweep(const std::string& text) {
  const std::string usage =
      "KEY=FROM:TO:STEP or KEY=V1,V2,... (e.g. slope=0.015:0.035:0.005, layered.layers=2:5:1 or "
      "vrs.adapt=0,0.25,0.4)";
  const auto eq = text.find('=');
  if (eq == std::string::npos || text.find(':', eq) == std::string::npos) {
    const auto [key, values] = parse_key_values(text, "--sweep", usage);
    return bench::Sweep::of(key, values);
  }
  std::vector<std::string> parts;
  std::stringstream in(text.substr(eq + 1));
  for (std::string item; std::getline(in, item, ':');) parts.push_back(item);
  if (eq == 0 || parts.size() != 3 || text.back() == ':') {
    throw Error("--sweep: expected " + usage + ", got '" + text + "'");
  }
  double v[3];
  for (size_t i = 0; i < 3; ++i) {
    if (!parse_number(parts[i], v[i])) throw Error("--sweep: '" + parts[i] + "' is not a number");
  }
  return bench::Sweep::range(text.substr(0, eq), v[0], v[1], v[2]);
}

bench::BenchOptions to_options(const BenchArgs& a, const std::string& command) {
  bench::BenchOptions o;
  o.session = to_session_options(a.session);
  if (a.techniques_given) o.techniques = split(a.techniques, ',');
  o.params = session_params(a.session, o.techniques.value_or(technique_names()));
  o.frames = a.frames;
  o.warmup = a.warmup;
  o.image_metrics = !a.no_metrics;
  o.diagnostics = !a.no_diagnostics;
  o.reference = with_flag("--reference", [&] { return parse_reference(a.reference); });
  o.allow_fallback = a.allow_fallback;
  o.passes = a.passes;
  o.command = invocation().empty() ? command : invocation();
  o.video = a.video;
  o.side_by_side = a.side_by_side;
  if (!a.sweep.empty()) o.sweep = parse_sweep(a.sweep);
  if (!a.shard.empty()) o.shard = bench::parse_shard(a.shard);
  if (!a.memory_limit.empty())
    o.memory_limit_bytes = double(parse_byte_size(a.memory_limit, "--memory-limit"));
  bench::validate(o);
  return o;
}

void add_common(CLI::App* sub, BenchArgs& a) {
  add_session_options(sub, a.session, false, kFixedDate, true);
  sub->add_option("--techniques", a.techniques,
                  "Comma-separated techniques (native, the reference, is always measured and "
                  "reported first); by "
                  "default every technique the scene can run (lodmask needs meshes)")
      ->capture_default_str()
      ->each([&a](const std::string&) { a.techniques_given = true; });
  sub->add_option("--frames", a.frames, "Measured frames per technique")->capture_default_str();
  sub->add_option(
         "--warmup", a.warmup,
         "Warm-up frames (not measured), at least: every technique warms up as long as the slowest "
         "to settle takes (layered's half-rate layers: 3), with a note when that is longer")
      ->capture_default_str();
  sub->add_option("--out", a.out,
                  "Output directory: results.json, results.csv, results.md, report.html")
      ->capture_default_str();
  add_overwrite_flag(sub, a.overwrite);
  sub->add_option("--reference", a.reference,
                  "What the image metrics judge against: native, or ssaa[:N] = native with NxN "
                  "supersampling (default N = 4), against which native is judged too")
      ->capture_default_str();
  sub->add_flag("--no-metrics", a.no_metrics,
                "Skip the image metrics against the reference (FovVideoVDP, PSNR, SSIM, acuity "
                "error, FLIP): faster, and each frame is rendered once (a judged run times its "
                "frames in a pass that reads nothing back, then renders them again to judge "
                "them)");
  // The flag's old name, kept working.
  sub->add_flag("--no-quality", a.no_metrics)->group("");
  sub->add_flag("--no-diagnostics", a.no_diagnostics,
                "Judge by FovVideoVDP alone: skip PSNR, SSIM, the acuity error, JND, FLIP and "
                "flicker (several times faster at 1080p)");
  sub->add_flag("--json", a.json,
                "Print results.json on stdout instead of the table (the files are written too)");
  sub->add_flag("--allow-fallback", a.allow_fallback,
                "Measure even when a live gaze source (--gaze pupil) never answers: the gaze "
                "falls back to the centre (an error otherwise)");
  add_memory_limit_option(sub, a.memory_limit, "run");
  sub->add_flag("--passes", a.passes,
                "Time every pass (G-buffer, shading, temporal, composite, ...) and report where "
                "each technique's frame goes: GPU timestamp queries, or on software renderers "
                "glFinish around each pass (there every measured frame runs pass by pass, timed or "
                "not)");
  CLI::Option* video = sub->add_option(
      "--video", a.video,
      "Also write the measured frames as a video (e.g. bench.mp4): the techniques tiled left to "
      "right (two rows beyond three), H.264 (libx264) yuv420p at --fps, written atomically");
  sub->add_flag("--side-by-side", a.side_by_side,
                "In the video, native first (even when not listed) and the gaze marked on every "
                "tile")
      ->needs(video);
}

// Runs the benchmark with a progress display unless --quiet or --json, and
// writes the report into --out.
bench::BenchResult run_and_write(const BenchArgs& a, const bench::BenchOptions& o,
                                 const char* what) {
  const OutputDirLock out_lock(a.out, "--out", a.overwrite);
  std::optional<Progress> progress;
  bench::BenchCallbacks callbacks;
  callbacks.session = session_callbacks();
  callbacks.start = [&](int steps, int metrics_steps) {
    progress.emplace("bench", "steps", steps, !quiet() && !a.json);
    progress->expect("metrics", metrics_steps);
  };
  callbacks.step = [&](const std::string& detail, const std::string& kind) {
    progress->step(detail, kind);
  };
  callbacks.finish = [&] { progress->finish(); };
  const bench::BenchResult r = bench::run_bench(o, callbacks);
  if (!quiet() && !a.json) std::cerr << what << ": writing the report" << std::endl;
  bench::write_bench_report(r, a.out);
  return r;
}

void print_summary(const bench::BenchResult& r, const BenchArgs& a) {
  // The video written (and its encoder) is a result: said even with --quiet.
  if (!r.video_summary.empty()) std::cerr << r.video_summary << "\n";
  if (a.json) {
    std::cout << bench::bench_json(r).dump(2) << '\n';
    return;
  }
  if (quiet()) {
    std::cout << bench::bench_markdown(r);
    return;
  }
  std::cout << "\n"
            << r.scene << " at " << r.options.session.size.width << 'x'
            << r.options.session.size.height << ", " << r.options.frames << " frames, renderer "
            << r.renderer << "\n\n"
            << bench::bench_markdown(r)
            << "\nreport: " << (std::filesystem::path(a.out) / "report.html").string()
            << "\nresults: " << (std::filesystem::path(a.out) / "results.json").string()
            << " (.csv, .md)\n";
}

}  // namespace

void register_bench(CLI::App& app) {
  auto a = std::make_shared<BenchArgs>();
  CLI::App* sub = app.add_subcommand(
      "bench", "Compare techniques side by side: time, pixels and image quality");
  add_common(sub, *a);
  sub->add_option("--sweep", a->sweep,
                  "Sweep KEY=FROM:TO:STEP or KEY=V1,V2,... (run in ascending order): slope (the "
                  "techniques' plan and the metrics' yardstick), margin (the plan only: see "
                  "--margin), or a technique parameter (KEY or TECHNIQUE.KEY)");
  sub->add_option("--shard", a->shard,
                  "Run job K of N (K/N): every N-th technique or swept run, native in every job "
                  "as its baseline; 'foveate merge' joins the jobs' --out folders (README: "
                  "Slurm job arrays, GNU parallel)");
  sub->callback([a] {
    const bench::BenchOptions o = to_options(*a, "foveate bench");
    print_summary(run_and_write(*a, o, "bench"), *a);
  });
}

void register_demo(CLI::App& app) {
  auto a = std::make_shared<BenchArgs>();
  // The test scene of Guenter et al. has meshes, so every technique runs on it.
  a->session.scene = "guenter";
  a->frames = 6;
  a->warmup = 2;
  a->out = "foveate-demo";
  CLI::App* sub = app.add_subcommand("demo",
                                     "A short benchmark of a built-in scene with every technique "
                                     "at acuity preset A; prints the table and the report's path");
  add_common(sub, *a);
  sub->callback([a] {
    // The options checked before the header that describes them.
    const bench::BenchOptions o = to_options(*a, "foveate demo");
    bench::validate(o);
    if (!quiet() && !a->json)
      std::cout << "foveate demo: " << a->session.scene << " scene, techniques " << a->techniques
                << ", acuity preset "
                << (a->session.acuity_preset.empty() ? "A" : a->session.acuity_preset)
                << ", display " << a->session.display << " at " << a->session.size << std::endl;
    print_summary(run_and_write(*a, o, "demo"), *a);
  });
}

const CommandRegistrar kBench(30, register_bench);
const CommandRegistrar kDemo(5, register_demo);

}  // namespace foveate::app
