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

namespace foveate::app {

namespace {

struct BenchArgs {
  std::string scene = "raymarch";
  std::string techniques = "native,layered,logpolar,checkerboard,inset";
  std::string size = "960x540";
  int frames = 12;
  int warmup = 2;
  std::string gaze;
  std::string camera_path;
  std::vector<std::string> channels;
  std::string quality;
  std::optional<double> slope;
  std::vector<std::string> params;
  std::string sweep;
  std::string display = "desktop-1080p";
  double fps = 60.0;
  double time = 0.0;
  std::string out = "bench-out";
  bool no_quality = false;
  bool quiet = false;
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

void parse_sweep(const std::string& text, BenchOptions& o) {
  const auto eq = text.find('=');
  const auto parts =
      eq == std::string::npos ? std::vector<std::string>{} : split(text.substr(eq + 1), ':');
  if (eq == std::string::npos || eq == 0 || parts.size() != 3) {
    throw Error(
        "--sweep: expected KEY=FROM:TO:STEP (e.g. slope=0.015:0.035:0.005 or "
        "layered.layers=2:5:1), got '" +
        text + "'");
  }
  double v[3];
  for (int i = 0; i < 3; ++i) {
    char* end = nullptr;
    v[i] = std::strtod(parts[static_cast<size_t>(i)].c_str(), &end);
    if (end != parts[static_cast<size_t>(i)].c_str() + parts[static_cast<size_t>(i)].size() ||
        !std::isfinite(v[i])) {
      throw Error("--sweep: '" + parts[static_cast<size_t>(i)] + "' is not a number");
    }
  }
  if (!(v[2] > 0) || v[1] < v[0]) throw Error("--sweep: need FROM <= TO and STEP > 0");
  if ((v[1] - v[0]) / v[2] > 50) throw Error("--sweep: at most 50 values");
  o.sweep_key = text.substr(0, eq);
  for (double x = v[0]; x <= v[1] + 1e-9 * std::max(1.0, std::fabs(v[1])); x += v[2])
    o.sweep_values.push_back(x);
  if (o.sweep_key != "slope") {
    const auto dot = o.sweep_key.find('.');
    const std::string tech = dot == std::string::npos ? "" : o.sweep_key.substr(0, dot);
    const std::string key = dot == std::string::npos ? o.sweep_key : o.sweep_key.substr(dot + 1);
    bool known = false;
    for (const TechniqueInfo& t : techniques()) {
      if (!tech.empty() && t.name != tech) continue;
      for (const ParamSpec& p : t.params) known = known || p.key == key;
    }
    if (!known)
      throw Error("--sweep: no technique has a parameter '" + o.sweep_key +
                  "' (see 'foveate techniques')");
  }
}

BenchOptions to_options(const BenchArgs& a, const std::string& command_line) {
  BenchOptions o;
  o.session.scene = a.scene;
  o.session.channels = a.channels;
  o.session.camera_path = a.camera_path;
  o.session.size = parse_size(a.size, "--size");
  o.session.display = a.display;
  o.session.acuity = acuity_from_options(a.quality, a.slope);
  if (!(a.fps > 0 && a.fps <= 10000)) throw Error("--fps: expected a positive rate");
  o.session.fps = a.fps;
  o.session.start_time = a.time;
  o.techniques = split(a.techniques, ',');
  for (const std::string& t : o.techniques) (void)technique_info(t);
  o.params = parse_params(a.params);
  validate_params(o.params, o.techniques);
  o.gaze = a.gaze;
  o.frames = a.frames;
  o.warmup = a.warmup;
  o.quality = !a.no_quality;
  o.out = a.out;
  o.progress = !a.quiet;
  o.command_line = command_line;
  if (!a.sweep.empty()) parse_sweep(a.sweep, o);
  return o;
}

void add_common(CLI::App* sub, BenchArgs& a) {
  sub->add_option("--scene", a.scene, "Built-in scene, Shadertoy .glsl file or mesh file")
      ->capture_default_str();
  sub->add_option("--techniques", a.techniques,
                  "Comma-separated techniques (native is always measured as the reference)")
      ->capture_default_str();
  sub->add_option("--size", a.size, "Render size WxH")->capture_default_str();
  sub->add_option("--frames", a.frames, "Measured frames per technique")->capture_default_str();
  sub->add_option("--warmup", a.warmup, "Warm-up frames per technique (not measured)")
      ->capture_default_str();
  sub->add_option("--gaze", a.gaze,
                  "Gaze: X,Y | fixed:X,Y | trace:FILE | synthetic[:SEED] | pupil[:HOST:PORT] | nearest; default centre");
  sub->add_option("--camera-path", a.camera_path, "Camera keyframes JSON");
  sub->add_option("--channel", a.channels,
                  "iChannel images for a Shadertoy shader (repeat, in order)");
  sub->add_option("--quality", a.quality, "Acuity preset A or B (default A)");
  sub->add_option("--slope", a.slope, "Custom MAR slope m");
  sub->add_option("--param", a.params,
                  "Technique parameter KEY=VALUE or TECHNIQUE.KEY=VALUE (repeatable)");
  sub->add_option("--display", a.display, "Display preset or JSON file")->capture_default_str();
  sub->add_option("--fps", a.fps, "Fixed clock rate (scene time of frame k = time + k / fps)")
      ->capture_default_str();
  sub->add_option("--time", a.time, "Scene time of the first frame")->capture_default_str();
  sub->add_option("--out", a.out,
                  "Output directory: results.json, results.csv, results.md, report.html")
      ->capture_default_str();
  sub->add_flag("--no-quality", a.no_quality, "Skip the image-quality metrics (faster)");
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
    const BenchResult r = run_bench(to_options(*a, cl));
    write_bench_outputs(r);
    print_summary(r);
  });
}

void register_demo(CLI::App& app) {
  auto a = std::make_shared<BenchArgs>();
  // The test scene of Guenter et al. has meshes, so every technique runs on it.
  a->scene = "guenter";
  a->techniques = "native,layered,logpolar,checkerboard,lodmask,inset";
  a->size = "1920x1080";  // the paper's display at its own resolution: about a minute here
  a->frames = 6;
  a->warmup = 2;
  a->out = "foveate-demo";
  CLI::App* sub = app.add_subcommand("demo",
                                     "A short benchmark of a built-in scene with every technique "
                                     "at quality A; prints the table and the report's path");
  add_common(sub, *a);
  sub->callback([a] {
    std::cout << "foveate demo: " << a->scene << " scene, techniques " << a->techniques
              << ", quality " << (a->quality.empty() ? "A" : a->quality) << ", display "
              << a->display << " at " << a->size << std::endl;
    const BenchResult r = run_bench(to_options(*a, "foveate demo"));
    write_bench_outputs(r);
    print_summary(r);
  });
}

const CommandRegistrar kBench(30, register_bench);
const CommandRegistrar kDemo(5, register_demo);

}  // namespace foveate::app
