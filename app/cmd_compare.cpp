// foveate compare: how visible the difference of a test image or sequence
// (e.g. foveated frames) from its reference (native or supersampled frames)
// is, in FovVideoVDP's JOD, with the image diagnostics (PSNR, SSIM, acuity
// error, JND, FLIP) for single images.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "cli_util.hpp"
#include "commands.hpp"
#include "foveate/core/error.hpp"
#include "foveate/core/image.hpp"
#include "foveate/core/parse.hpp"
#include "foveate/gaze/gaze.hpp"
#include "foveate/metrics/fvvdp.hpp"
#include "foveate/metrics/metrics.hpp"
#include "photometry_flags.hpp"
#include "progress.hpp"
#include "session_args.hpp"

namespace foveate::app {

namespace {

namespace fs = std::filesystem;

struct CompareArgs {
  std::string reference;
  std::string test;
  std::string display = "desktop-1080p";
  std::string gaze;
  double fps = 60.0;
  bool no_foveation = false;
  PhotometryOverrides photometry;
  std::string acuity_preset;  ///< --acuity (--quality): "A", "B" or empty
  std::optional<double> slope;
  bool json = false;
  bool no_flip = false;
  std::string heatmap;
  double heatmap_max = 1.0;
  std::string error_heatmap;
  std::string acuity_heatmap;
  std::string jnd_heatmap;
  double error_heatmap_max = 64.0;
  double acuity_heatmap_max = 16.0;
  double jnd_heatmap_max = 4.0;
  double threshold = 1.0;
};

std::string db(double v) {
  if (std::isinf(v)) return "inf";
  if (std::isnan(v)) return "-";
  return format_fixed(v, 2);
}

std::string num(double v, int digits) { return std::isfinite(v) ? format_fixed(v, digits) : "-"; }

bool is_image_file(const fs::path& p) {
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return ext == ".png" || ext == ".jpg" || ext == ".jpeg" || ext == ".bmp" || ext == ".tga";
}

// A frame's sequence: its file name without the trailing frame number and
// extension ("frame-0007.png" -> "frame-").
std::string sequence_name(const fs::path& p) {
  std::string stem = p.stem().string();
  while (!stem.empty() && std::isdigit(static_cast<unsigned char>(stem.back()))) stem.pop_back();
  return stem;
}

// The image files of a folder sorted by name, all of one sequence: a folder
// that `render --reference` wrote holds frame-NNNN and reference-NNNN, and
// interleaving them would judge a sequence nobody rendered. There the
// frames are taken (and a note says which files are left out); any other
// mix is refused.
std::vector<std::string> folder_frames(const std::string& path) {
  std::map<std::string, std::vector<std::string>> by_sequence;
  for (const auto& e : fs::directory_iterator(path)) {
    if (e.is_regular_file() && is_image_file(e.path()))
      by_sequence[sequence_name(e.path())].push_back(e.path().string());
  }
  if (by_sequence.empty())
    throw Error(path + ": a folder without image files (PNG, JPEG, BMP, TGA)");
  // The sequences but `skip`, named with their counts.
  const auto named = [&](const std::string& skip) {
    std::string names;
    for (const auto& [name, files] : by_sequence) {
      if (name != skip)
        names += (names.empty() ? "" : ", ") + name + "* (" + std::to_string(files.size()) + ")";
    }
    return names;
  };
  std::string chosen = by_sequence.begin()->first;
  if (by_sequence.size() > 1) {
    if (!by_sequence.count("frame-")) {
      throw Error(path + ": holds image files of " + std::to_string(by_sequence.size()) +
                  " sequences (" + named("") + "); give a folder of one sequence");
    }
    chosen = "frame-";
    if (!quiet()) {
      std::cerr << "foveate: note: " << path << ": comparing its frame-* images ("
                << by_sequence[chosen].size() << "), leaving out " << named(chosen) << "\n";
    }
  }
  std::vector<std::string> files = by_sequence[chosen];
  std::sort(files.begin(), files.end());
  return files;
}

// The frames of REFERENCE and TEST: one file each, or the frames of two
// folders sorted by name, as many in each.
std::pair<std::vector<std::string>, std::vector<std::string>> frame_lists(const CompareArgs& a) {
  std::error_code ec;
  const bool ref_dir = fs::is_directory(a.reference, ec), test_dir = fs::is_directory(a.test, ec);
  if (ref_dir != test_dir) {
    throw Error(
        "give two image files or two folders of frames: " + (ref_dir ? a.reference : a.test) +
        " is a folder, " + (ref_dir ? a.test : a.reference) + " is not");
  }
  if (!ref_dir) return {{a.reference}, {a.test}};
  auto refs = folder_frames(a.reference), tests = folder_frames(a.test);
  if (refs.size() != tests.size()) {
    throw Error("the folders hold different numbers of frames: " + a.reference + " " +
                std::to_string(refs.size()) + ", " + a.test + " " + std::to_string(tests.size()));
  }
  return {refs, tests};
}

void check_same_size(const Image& ref, const Image& test, const std::string& ref_name,
                     const std::string& test_name) {
  if (ref.width != test.width || ref.height != test.height) {
    throw Error("images differ in size: " + ref_name + " is " + std::to_string(ref.width) + "x" +
                std::to_string(ref.height) + ", " + test_name + " is " +
                std::to_string(test.width) + "x" + std::to_string(test.height));
  }
}

// The gaze of every frame: a fixed point (default the centre) or a trace
// sampled at each frame's time; during a blink the last valid position holds.
class FrameGaze {
 public:
  FrameGaze(const CompareArgs& a, const Display& display) : display_(display), fps_(a.fps) {
    const int w = display.width_px, h = display.height_px;
    fixed_ = Vec2d{0.5 * w, 0.5 * h};
    if (a.gaze.rfind("trace:", 0) == 0) {
      gaze::GazeContext ctx;
      ctx.display = display;
      ctx.warn = [](const std::string& m) {
        if (!quiet()) std::cerr << "foveate compare: " << m << '\n';
      };
      source_ = gaze::make_gaze_source(a.gaze, ctx);
    } else if (!a.gaze.empty()) {
      fixed_ = parse_point(a.gaze, w, h, "--gaze");
      // A position on the images, their edges included, as render and bench
      // take it (normalized 1.0 is the right or bottom edge).
      if (!(fixed_.x >= 0 && fixed_.x <= w && fixed_.y >= 0 && fixed_.y <= h)) {
        throw Error("--gaze: '" + a.gaze + "' is (" + format_number(fixed_.x, 1) + ", " +
                    format_number(fixed_.y, 1) + ") px, outside the " + std::to_string(w) + "x" +
                    std::to_string(h) + " images (0.." + std::to_string(w) + ", 0.." +
                    std::to_string(h) + " px, or normalized 0.0..1.0)");
      }
    }
  }
  Vec2d at(int frame) {
    if (!source_) return fixed_;
    const gaze::GazeSample s = source_->sample(frame / fps_);
    if (s.valid) last_ = s.pixels(display_.width_px, display_.height_px);
    return last_.value_or(fixed_);
  }
  [[nodiscard]] std::string describe() const {
    return source_ ? source_->describe()
                   : "(" + format_fixed(fixed_.x, 1) + ", " + format_fixed(fixed_.y, 1) + ") px";
  }

 private:
  Display display_;
  double fps_;
  Vec2d fixed_{};
  std::optional<Vec2d> last_;
  std::unique_ptr<gaze::GazeSource> source_;
};

void print_fvvdp(const metrics::FvvdpResult& r) {
  std::cout << "FovVideoVDP " << format_fixed(r.jod, 4)
            << " JOD (10 = no visible difference; 1 JOD = 75 % "
            << "of observers prefer the higher)\n  "
            << (r.image
                    ? std::string("an image")
                    : std::to_string(r.frames) + " frames at " + format_fixed(r.fps, 3) + " fps")
            << ", " << (r.foveated ? "foveated" : "not foveated") << ", "
            << format_fixed(r.pixels_per_degree, 1) << " px/deg, white "
            << format_fixed(r.photometry.peak_cd_m2, 1) << " cd/m^2, black "
            << format_fixed(r.photometry.black_cd_m2(), 4) << " cd/m^2\n";
  std::printf("  %-12s %8s %9s\n", "eccentricity", "pixels", "JOD");
  for (const auto& b : r.bands) {
    const std::string range = std::isinf(b.to_deg) ? format_fixed(b.from_deg, 0) + "+ deg"
                                                   : format_fixed(b.from_deg, 0) + "-" +
                                                         format_fixed(b.to_deg, 0) + " deg";
    std::printf("  %-12s %7.1f%% %9s\n", range.c_str(), 100.0 * b.pixels_fraction,
                num(b.jod, 4).c_str());
  }
}

metrics::QualityOptions diagnostic_options(const CompareArgs& a, const Display& display) {
  metrics::QualityOptions opt;
  opt.acuity = bench::acuity_from(a.acuity_preset, a.slope);
  opt.flip = !a.no_flip;
  opt.jnd_threshold = a.threshold;
  // The JND diagnostic sees the same light as FovVideoVDP.
  opt.contrast.peak_cd_m2 = display.photometry.peak_cd_m2;
  opt.contrast.black_cd_m2 = display.photometry.black_cd_m2();
  return opt;
}

void print_diagnostics(const metrics::QualityReport& r, const metrics::QualityOptions& opt) {
  std::cout << "\ndiagnostics: acuity w(e) = " << format_fixed(opt.acuity.slope, 4) << " e + "
            << format_fixed(opt.acuity.w0_deg, 4) << " deg\n";
  if (std::isinf(r.psnr_db)) std::cout << "identical images (PSNR infinite)\n";
  std::cout << "PSNR " << db(r.psnr_db) << " dB   SSIM " << num(r.ssim, 4);
  if (opt.flip)
    std::cout << "   FLIP " << num(r.flip_mean, 4) << " (at " << format_fixed(r.flip_ppd, 1)
              << " px/deg)";
  std::cout << "\nacuity-filtered error: RMSE " << num(r.acuity_rmse, 3)
            << " (8-bit luminance codes)\nvisibility: mean " << num(r.jnd_mean, 3)
            << " JND, visible (>= " << format_fixed(r.jnd_threshold, 2) << " JND) "
            << num(100.0 * r.visible_fraction, 3) << " % of pixels (Barten CSF)\n\n";
  std::printf("%-12s %8s %9s %8s %12s %9s %9s%s\n", "eccentricity", "pixels", "PSNR dB", "SSIM",
              "acuity RMSE", "JND mean", "visible", opt.flip ? "     FLIP" : "");
  for (const metrics::BandStats& b : r.bands) {
    const std::string range = std::isinf(b.to_deg) ? format_fixed(b.from_deg, 0) + "+ deg"
                                                   : format_fixed(b.from_deg, 0) + "-" +
                                                         format_fixed(b.to_deg, 0) + " deg";
    std::printf("%-12s %7.1f%% %9s %8s %12s %9s %8s%%", range.c_str(), 100.0 * b.pixels_fraction,
                db(b.psnr_db).c_str(), num(b.ssim, 4).c_str(), num(b.acuity_rmse, 3).c_str(),
                num(b.jnd_mean, 3).c_str(), num(100.0 * b.visible_fraction, 2).c_str());
    if (opt.flip) std::printf(" %8s", num(b.flip_mean, 4).c_str());
    std::printf("\n");
  }
}

void check_args(const CompareArgs& a) {
  if (!(a.heatmap_max > 0) || !(a.error_heatmap_max > 0) || !(a.acuity_heatmap_max > 0) ||
      !(a.jnd_heatmap_max > 0)) {
    throw Error(
        "--heatmap-max / --error-heatmap-max / --acuity-heatmap-max / --jnd-heatmap-max: "
        "must be > 0");
  }
  if (!(a.threshold >= 0) || !std::isfinite(a.threshold)) {
    throw Error("--threshold: must be >= 0 JND, got " + format_number(a.threshold));
  }
  if (!std::isfinite(a.fps) || a.fps <= 4.0 || a.fps > 1000.0) {
    throw Error("--fps: must be in (4, 1000] frames per second, got " + format_number(a.fps));
  }
}

// Single images also get the image diagnostics and their heat maps.
void image_diagnostics(const CompareArgs& a, const Image& ref, const Image& test,
                       const Display& display, Vec2d gaze, nlohmann::json* j) {
  const metrics::QualityOptions opt = diagnostic_options(a, display);
  const metrics::QualityReport r = metrics::compare(ref, test, display, gaze, opt);
  if (!a.error_heatmap.empty()) {
    write_png(a.error_heatmap, metrics::error_heatmap(ref, test, a.error_heatmap_max));
  }
  if (!a.acuity_heatmap.empty()) {
    write_png(a.acuity_heatmap,
              metrics::acuity_error_heatmap(ref, test, display, gaze, opt, a.acuity_heatmap_max));
  }
  if (!a.jnd_heatmap.empty()) {
    write_png(a.jnd_heatmap,
              metrics::heatmap(metrics::jnd_map(ref, test, display, gaze, opt), a.jnd_heatmap_max));
  }
  if (j) {
    const nlohmann::json d = metrics::to_json(r);
    for (auto it = d.begin(); it != d.end(); ++it) (*j)[it.key()] = it.value();
    (*j)["acuity"] = {{"slope", opt.acuity.slope}, {"w0_deg", opt.acuity.w0_deg}};
  } else {
    print_diagnostics(r, opt);
  }
}

void run_compare(const CompareArgs& a) {
  check_args(a);
  const auto [refs, tests] = frame_lists(a);
  const bool sequence = refs.size() > 1 || fs::is_directory(a.reference);
  // The diagnostics are an image pair's: asked of a sequence, they would
  // silently not appear.
  if (sequence) {
    std::string image_only;
    const auto given = [&](bool on, const char* flag) {
      if (on) image_only += std::string(image_only.empty() ? "" : ", ") + flag;
    };
    given(!a.error_heatmap.empty(), "--error-heatmap");
    given(!a.acuity_heatmap.empty(), "--acuity-heatmap");
    given(!a.jnd_heatmap.empty(), "--jnd-heatmap");
    given(a.no_flip, "--no-flip");
    given(a.threshold != CompareArgs{}.threshold, "--threshold");
    if (!image_only.empty()) {
      throw Error(image_only + ": for an image pair; " + a.reference + " and " + a.test +
                  " are folders of frames, judged by FovVideoVDP alone (--heatmap: its worst "
                  "frame's heat map)");
    }
  }
  Image ref = read_image(refs[0]), test = read_image(tests[0]);
  check_same_size(ref, test, refs[0], tests[0]);
  // The display's field of view at the images' resolution.
  const Display display =
      with_photometry(Display::load(a.display).resized(ref.width, ref.height), a.photometry);
  FrameGaze gaze(a, display);
  metrics::FvvdpOptions options;
  options.foveated = !a.no_foveation;
  options.fps = a.fps;
  options.heatmap = !a.heatmap.empty();
  metrics::Fvvdp metric(display, options);
  // A bar only for work of a second or more (about 8 megapixels of frames).
  Progress progress("compare", "frames", static_cast<int>(refs.size()),
                    !a.json && double(refs.size()) * ref.width * ref.height >= 8e6);
  for (size_t f = 0; f < refs.size(); ++f) {
    if (f > 0) {
      ref = read_image(refs[f]);
      test = read_image(tests[f]);
      check_same_size(ref, test, refs[f], tests[f]);
      if (ref.width != display.width_px || ref.height != display.height_px) {
        throw Error("frames differ in size: " + refs[f] + " is " + std::to_string(ref.width) + "x" +
                    std::to_string(ref.height) + ", " + refs[0] + " " +
                    std::to_string(display.width_px) + "x" + std::to_string(display.height_px));
      }
    }
    metric.add(test, ref, gaze.at(static_cast<int>(f)));
    progress.step("frame " + std::to_string(f + 1));
  }
  const metrics::FvvdpResult r = metric.result();
  if (options.heatmap) {
    const Image worst_ref = read_image(refs[static_cast<size_t>(r.worst_frame)]);
    write_png(a.heatmap, metrics::fvvdp_heatmap_image(r.worst_heatmap, worst_ref, a.heatmap_max));
  }
  nlohmann::json j;
  if (a.json) {
    j["jod"] = r.jod;
    j["fvvdp"] = metrics::to_json(r);
    j["reference"] = a.reference;
    j["test"] = a.test;
    j["display"] = display;
    j["gaze"] = gaze.describe();
    if (!sequence) j["gaze_px"] = {gaze.at(0).x, gaze.at(0).y};
  } else {
    std::cout << "reference " << a.reference << "\ntest      " << a.test << "\n"
              << ref.width << 'x' << ref.height << " on display " << display.name << ", gaze "
              << gaze.describe() << "\n\n";
    print_fvvdp(r);
  }
  if (!sequence) image_diagnostics(a, ref, test, display, gaze.at(0), a.json ? &j : nullptr);
  if (a.json) {
    std::cout << j.dump(2) << '\n';
    return;
  }
  for (const std::string* f : {&a.heatmap, &a.error_heatmap, &a.acuity_heatmap, &a.jnd_heatmap}) {
    if (!f->empty()) std::cout << "wrote " << *f << '\n';
  }
}

}  // namespace

void register_compare(CLI::App& app);
const CommandRegistrar kCompare(40, register_compare);

void register_compare(CLI::App& app) {
  auto a = std::make_shared<CompareArgs>();
  CLI::App* sub = app.add_subcommand(
      "compare",
      "How visible TEST's difference from REFERENCE is: FovVideoVDP (Mantiuk et al. 2021) in JOD "
      "for an image pair or two folders of frames (a sequence), and for images PSNR, SSIM, "
      "acuity-filtered error, JND (Barten's CSF) and FLIP per eccentricity band");
  sub->add_option("reference", a->reference,
                  "Reference: an image (PNG) or a folder of frames (sorted by name)")
      ->required();
  sub->add_option("test", a->test, "Test: an image or a folder of as many frames, same size")
      ->required();
  sub->add_option("--display", a->display,
                  "Display preset (" + Display::preset_names() +
                      ") or JSON file; its field of view is kept at the images' size")
      ->capture_default_str();
  add_photometry_flags(*sub, a->photometry);
  sub->add_option("--gaze", a->gaze,
                  "Fixation: X,Y in pixels or normalized (0.5,0.5), inside the images, or "
                  "trace:FILE sampled at each frame's time (CSV, Pupil or JSON); default centre");
  sub->add_option("--fps", a->fps, "Frame rate of a sequence")->capture_default_str();
  sub->add_flag("--no-foveation", a->no_foveation,
                "Foveal sensitivity everywhere (FovVideoVDP's non-foveated mode)");
  sub->add_flag("--json", a->json,
                "Print JSON: \"jod\" at the top level, \"fvvdp\" with the details, and for images "
                "the diagnostics");
  sub->add_option("--heatmap", a->heatmap,
                  "Write FovVideoVDP's distortion map (of the worst frame of a sequence) over the "
                  "reference as a PNG: green invisible, red --heatmap-max JOD");
  sub->add_option("--heatmap-max", a->heatmap_max, "JOD at the top of the heat map's scale")
      ->capture_default_str();
  add_acuity_options(sub, a->acuity_preset, a->slope);
  sub->add_option("--threshold", a->threshold,
                  "Diagnostics: pooled visibility (JND) from which a pixel counts as visible")
      ->capture_default_str();
  sub->add_flag("--no-flip", a->no_flip, "Skip FLIP (the slowest diagnostic)");
  sub->add_option("--error-heatmap", a->error_heatmap,
                  "Images: write the per-pixel error (max over R, G, B) as a PNG heatmap");
  sub->add_option("--error-heatmap-max", a->error_heatmap_max,
                  "Error at the top of that heatmap's scale")
      ->capture_default_str();
  sub->add_option("--acuity-heatmap", a->acuity_heatmap,
                  "Images: write the acuity-filtered difference as a PNG heatmap");
  sub->add_option("--acuity-heatmap-max", a->acuity_heatmap_max,
                  "Filtered difference at the top of that heatmap's scale")
      ->capture_default_str();
  sub->add_option("--jnd-heatmap", a->jnd_heatmap,
                  "Images: write the pooled visibility of the difference (JND) as a PNG heatmap");
  sub->add_option("--jnd-heatmap-max", a->jnd_heatmap_max, "JND at the top of that heatmap's scale")
      ->capture_default_str();
  sub->callback([a] { run_compare(*a); });
}

}  // namespace foveate::app
