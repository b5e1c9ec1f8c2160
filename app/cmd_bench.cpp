// foveate bench and foveate demo.
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

#include "bench.hpp"
#include "cli_util.hpp"
#include "commands.hpp"
#include "foveate/core/error.hpp"
#include "foveate/techniques/reference.hpp"
#include "output_dir.hpp"

namespace foveate::app {

namespace {

struct BenchArgs {
  SessionArgs session;
  std::string techniques = "native,layered,logpolar,checkerboard,inset";
  int frames = 12;
  int warmup = 2;
  std::string sweep;
  std::string out = "bench-out";
  std::string reference = "native";
  bool no_metrics = false;
  bool quiet = false;
  BenchArgs() { session.size = "960x540"; }
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

BenchOptions to_options(const BenchArgs& a, const std::string& command_line) {
  BenchOptions o;
  o.session = to_session_options(a.session);
  o.techniques = split(a.techniques, ',');
  for (const std::string& t : o.techniques)
    with_flag("--techniques", [&] { return technique_info(t); });
  o.params = parse_params(a.session.params);
  validate_params(o.params, o.techniques);
  o.gaze = a.session.gaze;
  o.frames = a.frames;
  o.warmup = a.warmup;
  o.image_metrics = !a.no_metrics;
  o.reference = with_flag("--reference", [&] { return parse_reference(a.reference); });
  o.out = a.out;
  o.progress = !a.quiet;
  o.command_line = command_line;
  if (!a.sweep.empty()) o.sweep = Sweep::parse(a.sweep);
  return o;
}

void add_common(CLI::App* sub, BenchArgs& a) {
  add_session_options(sub, a.session);
  sub->add_option("--techniques", a.techniques,
                  "Comma-separated techniques (native is always measured as the reference)")
      ->capture_default_str();
  sub->add_option("--frames", a.frames, "Measured frames per technique")->capture_default_str();
  sub->add_option("--warmup", a.warmup, "Warm-up frames per technique (not measured)")
      ->capture_default_str();
  sub->add_option("--out", a.out,
                  "Output directory: results.json, results.csv, results.md, report.html")
      ->capture_default_str();
  sub->add_option("--reference", a.reference,
                  "What the image metrics judge against: native, or ssaa[:N] = native with NxN "
                  "supersampling (default N = 4), against which native is judged too")
      ->capture_default_str();
  sub->add_flag("--no-metrics", a.no_metrics,
                "Skip the image metrics against native (PSNR, SSIM, acuity error, FLIP; faster)");
  // The flag's old name, kept working.
  sub->add_flag("--no-quality", a.no_metrics)->group("");
  sub->add_flag("--quiet", a.quiet, "No progress output");
}

void print_summary(const BenchResult& r) {
  std::cout << "\n"
            << r.scene << " at " << r.options.session.size.width << 'x'
            << r.options.session.size.height << ", " << r.options.frames << " frames, renderer "
            << r.renderer << "\n\n"
            << bench_markdown(r)
            << "\nreport: " << (std::filesystem::path(r.options.out) / "report.html").string()
            << "\nresults: " << (std::filesystem::path(r.options.out) / "results.json").string()
            << " (.csv, .md)\n";
}

}  // namespace

void register_bench(CLI::App& app) {
  auto a = std::make_shared<BenchArgs>();
  CLI::App* sub = app.add_subcommand(
      "bench", "Compare techniques side by side: time, pixels and image quality");
  add_common(sub, *a);
  sub->add_option("--sweep", a->sweep, "Sweep KEY=FROM:TO:STEP (slope, or a technique parameter)");
  sub->callback([a, &app] {
    std::string cl = "foveate bench";
    for (const auto& s : app.remaining()) cl += " " + s;
    const BenchOptions o = to_options(*a, cl);
    const OutputDirLock out_lock(o.out, "--out");
    const BenchResult r = run_bench(o);
    write_bench_outputs(r);
    print_summary(r);
  });
}

void register_demo(CLI::App& app) {
  auto a = std::make_shared<BenchArgs>();
  // The test scene of Guenter et al. has meshes, so every technique runs on it.
  a->session.scene = "guenter";
  a->techniques = "native,layered,logpolar,checkerboard,lodmask,inset";
  a->session.size = "1920x1080";  // the paper's display at its own resolution: about a minute here
  a->frames = 6;
  a->warmup = 2;
  a->out = "foveate-demo";
  CLI::App* sub = app.add_subcommand("demo",
                                     "A short benchmark of a built-in scene with every technique "
                                     "at quality A; prints the table and the report's path");
  add_common(sub, *a);
  sub->callback([a] {
    std::cout << "foveate demo: " << a->session.scene << " scene, techniques " << a->techniques
              << ", quality " << (a->session.quality.empty() ? "A" : a->session.quality)
              << ", display " << a->session.display << " at " << a->session.size << std::endl;
    const BenchOptions o = to_options(*a, "foveate demo");
    const OutputDirLock out_lock(o.out, "--out");
    const BenchResult r = run_bench(o);
    write_bench_outputs(r);
    print_summary(r);
  });
}

const CommandRegistrar kBench(30, register_bench);
const CommandRegistrar kDemo(5, register_demo);

}  // namespace foveate::app
