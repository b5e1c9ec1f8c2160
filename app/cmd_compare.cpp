// foveate compare: image-quality metrics of a test image (e.g. a foveated
// frame) against a reference (the native frame rendered with the same inputs).
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "cli_util.hpp"
#include "commands.hpp"
#include "foveate/core/error.hpp"
#include "foveate/core/image.hpp"
#include "foveate/core/parse.hpp"
#include "foveate/metrics/metrics.hpp"
#include "progress.hpp"
#include "session_args.hpp"

namespace foveate::app {

namespace {

struct CompareArgs {
  std::string reference;
  std::string test;
  std::string display = "desktop-1080p";
  std::string gaze;
  std::string quality;
  std::optional<double> slope;
  bool json = false;
  bool no_flip = false;
  std::string heatmap;
  std::string acuity_heatmap;
  std::string jnd_heatmap;
  double heatmap_max = 64.0;
  double acuity_heatmap_max = 16.0;
  double jnd_heatmap_max = 4.0;
  double threshold = 1.0;
  double peak = 100.0;
};

std::string db(double v) {
  if (std::isinf(v)) return "inf";
  if (std::isnan(v)) return "-";
  return format_fixed(v, 2);
}

std::string num(double v, int digits) { return std::isfinite(v) ? format_fixed(v, digits) : "-"; }

void run_compare(const CompareArgs& a) {
  const Image ref = read_image(a.reference);
  const Image test = read_image(a.test);
  if (ref.width != test.width || ref.height != test.height) {
    throw Error("images differ in size: " + a.reference + " is " + std::to_string(ref.width) + "x" +
                std::to_string(ref.height) + ", " + a.test + " is " + std::to_string(test.width) +
                "x" + std::to_string(test.height));
  }
  if (!(a.heatmap_max > 0) || !(a.acuity_heatmap_max > 0) || !(a.jnd_heatmap_max > 0)) {
    throw Error("--heatmap-max / --acuity-heatmap-max / --jnd-heatmap-max: must be > 0");
  }
  if (!(a.threshold >= 0) || !std::isfinite(a.threshold)) {
    throw Error("--threshold: must be >= 0 JND, got " + format_number(a.threshold));
  }
  metrics::QualityOptions opt;
  if (!(a.peak > opt.contrast.black_cd_m2) || !std::isfinite(a.peak)) {
    throw Error("--peak-luminance: must be above the black level (" +
                format_number(opt.contrast.black_cd_m2) + " cd/m^2), got " + format_number(a.peak));
  }
  // The display's field of view at the images' resolution.
  const Display display = Display::load(a.display).resized(ref.width, ref.height);
  const Vec2d gaze = a.gaze.empty() ? Vec2d{0.5 * ref.width, 0.5 * ref.height}
                                    : parse_point(a.gaze, ref.width, ref.height, "--gaze");
  if (!(gaze.x >= 0 && gaze.x < ref.width && gaze.y >= 0 && gaze.y < ref.height)) {
    throw Error("--gaze: '" + a.gaze + "' is (" + format_number(gaze.x, 1) + ", " +
                format_number(gaze.y, 1) + ") px, outside the " + std::to_string(ref.width) + "x" +
                std::to_string(ref.height) + " images (pixels 0.." + std::to_string(ref.width - 1) +
                ", 0.." + std::to_string(ref.height - 1) + ", or normalized 0.0..1.0)");
  }
  opt.acuity = bench::acuity_from(a.quality, a.slope);
  opt.flip = !a.no_flip;
  opt.jnd_threshold = a.threshold;
  opt.contrast.peak_cd_m2 = a.peak;
  const int steps = 1 + !a.heatmap.empty() + !a.acuity_heatmap.empty() + !a.jnd_heatmap.empty();
  // Only worth a bar where it takes a while (a megapixel and more).
  Progress progress("compare", "steps", steps, !a.json && double(ref.width) * ref.height >= 1e6);
  const metrics::QualityReport r = metrics::compare(ref, test, display, gaze, opt);
  progress.step("metrics");

  if (!a.heatmap.empty()) {
    write_png(a.heatmap, metrics::error_heatmap(ref, test, a.heatmap_max));
    progress.step("heat map");
  }
  if (!a.acuity_heatmap.empty()) {
    write_png(a.acuity_heatmap,
              metrics::acuity_error_heatmap(ref, test, display, gaze, opt, a.acuity_heatmap_max));
    progress.step("acuity heat map");
  }
  if (!a.jnd_heatmap.empty()) {
    write_png(a.jnd_heatmap,
              metrics::heatmap(metrics::jnd_map(ref, test, display, gaze, opt), a.jnd_heatmap_max));
    progress.step("JND heat map");
  }

  if (a.json) {
    nlohmann::json j = metrics::to_json(r);
    j["reference"] = a.reference;
    j["test"] = a.test;
    j["display"] = display;
    j["gaze_px"] = {gaze.x, gaze.y};
    j["acuity"] = {{"slope", opt.acuity.slope}, {"w0_deg", opt.acuity.w0_deg}};
    std::cout << j.dump(2) << '\n';
    return;
  }

  std::cout << "reference " << a.reference << "\ntest      " << a.test << "\n";
  std::cout << ref.width << 'x' << ref.height << " on display " << display.name << ", gaze ("
            << format_fixed(gaze.x, 1) << ", " << format_fixed(gaze.y, 1)
            << ") px, acuity w(e) = " << format_fixed(opt.acuity.slope, 4) << " e + "
            << format_fixed(opt.acuity.w0_deg, 4) << " deg\n\n";
  if (std::isinf(r.psnr_db)) std::cout << "identical images (PSNR infinite)\n";
  std::cout << "PSNR " << db(r.psnr_db) << " dB   SSIM " << num(r.ssim, 4);
  if (opt.flip)
    std::cout << "   FLIP " << num(r.flip_mean, 4) << " (at " << format_fixed(r.flip_ppd, 1)
              << " px/deg)";
  std::cout << "\nacuity-filtered error: RMSE " << num(r.acuity_rmse, 3)
            << " (8-bit luminance codes)\nvisibility: mean " << num(r.jnd_mean, 3)
            << " JND, visible (>= " << format_fixed(r.jnd_threshold, 2) << " JND) "
            << num(100.0 * r.visible_fraction, 3) << " % of pixels (Barten CSF, white "
            << format_fixed(opt.contrast.peak_cd_m2, 0) << " cd/m^2)\n\n";
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
  if (!a.heatmap.empty()) std::cout << "\nwrote " << a.heatmap << '\n';
  if (!a.acuity_heatmap.empty()) std::cout << "wrote " << a.acuity_heatmap << '\n';
  if (!a.jnd_heatmap.empty()) std::cout << "wrote " << a.jnd_heatmap << '\n';
}

}  // namespace

void register_compare(CLI::App& app);
const CommandRegistrar kCompare(40, register_compare);

void register_compare(CLI::App& app) {
  auto a = std::make_shared<CompareArgs>();
  CLI::App* sub = app.add_subcommand(
      "compare",
      "Image-quality metrics of TEST against REFERENCE: PSNR, SSIM, per eccentricity band, "
      "acuity-filtered error, visibility in JND (Barten's CSF) and FLIP");
  sub->add_option("reference", a->reference, "Reference image (the native frame), PNG")->required();
  sub->add_option("test", a->test, "Test image (e.g. the foveated frame), same size")->required();
  sub->add_option("--display", a->display,
                  "Display preset (" + Display::preset_names() +
                      ") or JSON file; its field of view is kept at the images' size")
      ->capture_default_str();
  sub->add_option("--gaze", a->gaze,
                  "Gaze point X,Y in pixels or normalized (0.5,0.5), inside the images; default "
                  "centre");
  add_acuity_options(sub, a->quality, a->slope);
  sub->add_option("--threshold", a->threshold,
                  "Pooled visibility (JND) from which a pixel counts as visibly different")
      ->capture_default_str();
  sub->add_option("--peak-luminance", a->peak,
                  "Luminance of the display's white in cd/m^2 (the contrast sensitivity depends "
                  "on it)")
      ->capture_default_str();
  sub->add_flag("--no-flip", a->no_flip, "Skip FLIP (the slowest metric)");
  sub->add_flag("--json", a->json,
                "Print the report as JSON (infinite PSNR is null with \"identical\": true)");
  sub->add_option("--heatmap", a->heatmap,
                  "Write the per-pixel error (max over R, G, B) as a PNG heatmap");
  sub->add_option("--heatmap-max", a->heatmap_max, "Error at the top of the heatmap's scale")
      ->capture_default_str();
  sub->add_option("--acuity-heatmap", a->acuity_heatmap,
                  "Write the acuity-filtered difference as a PNG heatmap");
  sub->add_option("--acuity-heatmap-max", a->acuity_heatmap_max,
                  "Filtered difference at the top of that heatmap's scale")
      ->capture_default_str();
  sub->add_option("--jnd-heatmap", a->jnd_heatmap,
                  "Write the pooled visibility of the difference (JND) as a PNG heatmap");
  sub->add_option("--jnd-heatmap-max", a->jnd_heatmap_max, "JND at the top of that heatmap's scale")
      ->capture_default_str();
  sub->callback([a] { run_compare(*a); });
}

}  // namespace foveate::app
