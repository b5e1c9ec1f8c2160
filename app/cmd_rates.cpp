// foveate rates: the shading-rate image the acuity model gives for a display
// and a gaze, encoded for an engine's variable-rate shading (Vulkan, D3D12 or
// GL_NV_shading_rate_image), with a preview and the fraction of the screen at
// each rate.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "cli_util.hpp"
#include "commands.hpp"
#include "foveate/core/error.hpp"
#include "foveate/core/file.hpp"
#include "foveate/core/image.hpp"
#include "foveate/core/image_text.hpp"
#include "foveate/core/shading_rate.hpp"
#include "foveate/techniques/technique.hpp"
#include "session_args.hpp"

namespace foveate::app {

namespace {

struct RatesArgs {
  std::string display = "desktop-1080p";
  std::string gaze;
  int tile = 16;
  std::string api = "vulkan";
  std::string out;
  std::string preview;
  std::string size;
  std::string acuity_preset;  ///< --acuity (--quality): "A", "B" or empty
  std::optional<double> slope;
  std::optional<double> margin;
  double latency_ms = 0.0;
  double max_saccade = 200.0;
  std::string rates;
};

// Preview colours by rate, in the order of kShadingRates.
constexpr std::uint8_t kRateColours[7][3] = {{230, 60, 60}, {240, 150, 40}, {225, 205, 50},
                                             {60, 180, 75}, {70, 190, 200}, {70, 110, 220},
                                             {150, 80, 200}};

size_t rate_index(ShadingRate r) {
  return static_cast<size_t>(std::find(kShadingRates.begin(), kShadingRates.end(), r) -
                             kShadingRates.begin());
}

std::string hex_colour(size_t i) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", kRateColours[i][0], kRateColours[i][1],
                kRateColours[i][2]);
  return buf;
}

void put(Image& img, int x, int y, const std::uint8_t* c, double a) {
  if (x < 0 || y < 0 || x >= img.width || y >= img.height) return;
  std::uint8_t* p = img.at(x, y);
  for (int k = 0; k < 3; ++k) p[k] = static_cast<std::uint8_t>(p[k] * (1.0 - a) + c[k] * a + 0.5);
  p[3] = 255;
}

// A plain grey frame, each tile tinted with its rate's colour and outlined, a
// black-and-white gaze marker, and a legend in the bottom-left corner: one
// swatch per rate, finest first, each holding a white box as wide and high as
// the rate's fragment (4 screen pixels per pixel of the fragment) and named
// above it ("2x4"), so that the picture reads without its colour table.
Image preview(const ShadingRateImage& m, Vec2d gaze) {
  Image img(m.width_px, m.height_px);
  const std::uint8_t grey[3] = {128, 128, 128}, dark[3] = {40, 40, 40}, white[3] = {255, 255, 255};
  for (int y = 0; y < img.height; ++y) {
    for (int x = 0; x < img.width; ++x) put(img, x, y, grey, 1.0);
  }
  for (int ty = 0; ty < m.tiles_y; ++ty) {
    for (int tx = 0; tx < m.tiles_x; ++tx) {
      const auto r = m.tile_rect(tx, ty);
      const std::uint8_t* c = kRateColours[rate_index(m.at(tx, ty))];
      for (int y = r[1]; y < r[3]; ++y) {
        for (int x = r[0]; x < r[2]; ++x) {
          const bool edge = x == r[0] || y == r[1];
          put(img, x, y, edge ? dark : c, edge ? 0.35 : 0.6);
        }
      }
    }
  }
  const int gx = static_cast<int>(gaze.x), gy = static_cast<int>(gaze.y);
  for (int d = -6; d <= 6; ++d) {
    for (int w = -1; w <= 1; ++w) {
      put(img, gx + d, gy + w, w == 0 ? white : dark, 1.0);
      put(img, gx + w, gy + d, w == 0 ? white : dark, 1.0);
    }
  }
  const int s = 24, pad = 4;
  for (size_t i = 0; i < kShadingRates.size(); ++i) {
    const int x0 = pad + static_cast<int>(i) * (s + pad), y0 = img.height - pad - s;
    for (int y = y0 - 1; y <= y0 + s; ++y) {
      for (int x = x0 - 1; x <= x0 + s; ++x) {
        const bool edge = x < x0 || y < y0 || x >= x0 + s || y >= y0 + s;
        put(img, x, y, edge ? dark : kRateColours[i], 1.0);
      }
    }
    draw_label(img, x0 - 1, y0 - 2 - label_height(1), kShadingRates[i].name(), 1);
    const int bw = 4 * kShadingRates[i].width, bh = 4 * kShadingRates[i].height;
    for (int y = 0; y < bh; ++y) {
      for (int x = 0; x < bw; ++x)
        put(img, x0 + (s - bw) / 2 + x, y0 + (s - bh) / 2 + y, white, 1.0);
    }
  }
  return img;
}

// The options' values checked, and the encoding asked for.
RateApi checked_api(const RatesArgs& a) {
  const std::string ext = std::filesystem::path(a.out).extension().string();
  if (ext != ".bin" && ext != ".json") {
    throw Error("--out: the file must end in .bin or .json, got '" + a.out + "'");
  }
  if (!a.preview.empty() && std::filesystem::path(a.preview).extension() != ".png") {
    throw Error("--preview: the file must end in .png, got '" + a.preview + "'");
  }
  if (!(a.latency_ms >= 0.0) || a.latency_ms > 10000.0) {
    throw Error("--latency-ms: expected 0..10000 milliseconds, got " +
                format_fixed(a.latency_ms, 3));
  }
  if (!(a.max_saccade >= 0.0) || a.max_saccade > 1000.0) {
    throw Error("--max-saccade: expected 0..1000 degrees per second, got " +
                format_fixed(a.max_saccade, 3));
  }
  if (!is_shading_rate_tile(a.tile)) {
    throw Error("--tile: expected " + shading_rate_tiles_text() + " pixels, got " +
                std::to_string(a.tile));
  }
  try {
    return parse_rate_api(a.api);
  } catch (const Error& e) {
    throw Error(std::string("--api: ") + e.what());
  }
}

// The rate image for the options, and what goes with it in the outputs.
struct RatesPlan {
  RateApi api{};
  ShadingRateOptions opt;
  Display display;
  AcuityModel judged;   ///< the acuity the rates are judged by
  double margin = 1.0;  ///< the planning margin
  Vec2d gaze;
  ShadingRateImage m;
  std::vector<std::uint8_t> bytes;  ///< m encoded for `api`
  /// Through a lens: the same rates without it, to show what the panel
  /// relaxed, and how many tiles it made coarser.
  std::optional<ShadingRateImage> without_lens;
  int coarser = 0;
};

RatesPlan make_rates_plan(const RatesArgs& a) {
  RatesPlan p;
  p.api = checked_api(a);
  p.opt.tile_px = a.tile;
  p.opt.origin_bottom_left = p.api == RateApi::GlNv;
  p.opt.latency_travel_deg = a.latency_ms * a.max_saccade / 1000.0;
  if (!a.rates.empty()) {
    try {
      p.opt.supported = parse_shading_rates(a.rates);
    } catch (const Error& e) {
      throw Error(std::string("--rates: ") + e.what());
    }
  }
  p.display = Display::load(a.display);
  if (!a.size.empty()) {
    const PixelSize sz = parse_size(a.size, "--size");
    p.display = p.display.resized(sz.width, sz.height);
  }
  p.judged = bench::acuity_from(a.acuity_preset, a.slope);
  // --margin, else the margin at which static rates hold parity (the vrs
  // technique plans coarser and refines by content, which a rate image
  // written once cannot).
  if (a.margin) bench::check_margin(*a.margin);
  p.margin = a.margin.value_or(kStaticRatesMargin);
  const AcuityModel acuity = p.judged.finer(p.margin);
  p.gaze = a.gaze.empty()
               ? p.display.principal_point()
               : parse_point_on_image(a.gaze, p.display.width_px, p.display.height_px, "--gaze");
  p.m = shading_rate_image(p.display, acuity, p.gaze, p.opt);
  p.bytes = p.m.encode(p.api);
  if (p.display.lens) {
    Display bare = p.display;
    bare.lens.reset();
    p.without_lens = shading_rate_image(bare, acuity, p.gaze, p.opt);
    for (size_t i = 0; i < p.m.rates.size(); ++i)
      p.coarser += p.m.rates[i].pixels() > p.without_lens->rates[i].pixels();
  }
  return p;
}

nlohmann::json rates_json(const RatesPlan& p) {
  const ShadingRateImage& m = p.m;
  nlohmann::json j;
  j["size"] = {m.width_px, m.height_px};
  j["tile"] = m.tile_px;
  j["tiles"] = {m.tiles_x, m.tiles_y};
  j["api"] = rate_api_name(p.api);
  j["row_order"] = m.origin_bottom_left ? "bottom-to-top" : "top-to-bottom";
  j["display"] = p.display;
  j["gaze_px"] = {p.gaze.x, p.gaze.y};
  j["acuity"] = {{"slope", p.judged.slope}, {"w0_deg", p.judged.w0_deg}};
  j["margin"] = p.margin;
  j["latency_margin_deg"] = p.opt.latency_travel_deg;
  nlohmann::json legend = nlohmann::json::array();
  for (ShadingRate r : p.opt.supported) {
    nlohmann::json e = {{"rate", r.name()},
                        {"value", encode_shading_rate(r, p.api)},
                        {"fraction", m.fraction(r)},
                        {"colour", hex_colour(rate_index(r))}};
    if (p.api == RateApi::GlNv) e["gl_enum"] = gl_nv_palette()[rate_index(r)];
    legend.push_back(e);
  }
  j["legend"] = legend;
  nlohmann::json grid = nlohmann::json::array();
  for (int ty = 0; ty < m.tiles_y; ++ty) {
    nlohmann::json row = nlohmann::json::array();
    for (int tx = 0; tx < m.tiles_x; ++tx) row.push_back(p.bytes[size_t(ty) * m.tiles_x + tx]);
    grid.push_back(row);
  }
  j["grid"] = grid;
  j["shaded_samples"] = m.shaded_samples();
  j["pixel_ratio"] = m.pixel_ratio();
  if (p.without_lens) {
    const Oversampling o = p.display.lens_oversampling(p.gaze);
    j["lens"] = {{"oversampling_at_gaze", {{"radial", o.radial}, {"tangential", o.tangential}}},
                 {"tiles_coarser_than_without_lens", p.coarser},
                 {"pixel_ratio_without_lens", p.without_lens->pixel_ratio()}};
  }
  return j;
}

void print_rates(const RatesArgs& a, const RatesPlan& p) {
  const ShadingRateImage& m = p.m;
  std::cout << "display " << p.display.name << " " << p.display.width_px << 'x'
            << p.display.height_px << ", gaze (" << format_fixed(p.gaze.x, 1) << ", "
            << format_fixed(p.gaze.y, 1)
            << ") px, acuity w(e) = " << format_fixed(p.judged.slope, 4) << " e + "
            << format_fixed(p.judged.w0_deg, 4) << " deg planned with margin "
            << format_fixed(p.margin, 3);
  if (p.opt.latency_travel_deg > 0.0) {
    std::cout << ", latency margin " << format_fixed(p.opt.latency_travel_deg, 2) << " deg";
  }
  std::cout << "\n"
            << m.tiles_x << 'x' << m.tiles_y << " tiles of " << m.tile_px << " px, "
            << rate_api_name(p.api) << " encoding, rows "
            << (m.origin_bottom_left ? "bottom-to-top" : "top-to-bottom") << "\n\n";
  std::printf("%-5s %6s %10s\n", "rate", "value", "pixels");
  for (ShadingRate r : p.opt.supported) {
    std::printf("%-5s %6d %9.1f%%\n", r.name().c_str(), encode_shading_rate(r, p.api),
                100.0 * m.fraction(r));
  }
  std::printf("\nshaded samples / native pixels = %.4f (%.2fx fewer invocations)\n",
              m.pixel_ratio(), 1.0 / m.pixel_ratio());
  if (p.without_lens) {
    std::printf("through the lens: %s; %d tiles coarser than without the lens (%.4f without it)\n",
                lens_at_gaze(p.display, p.gaze).c_str(), p.coarser, p.without_lens->pixel_ratio());
  }
  std::cout << "wrote " << a.out;
  if (!a.preview.empty()) std::cout << " and " << a.preview;
  std::cout << '\n';
}

void run_rates(const RatesArgs& a) {
  const RatesPlan p = make_rates_plan(a);
  // Both files or neither: the preview first, removed again (where this run
  // made it) if the rates cannot be written, so that a failed run leaves no
  // rates file that a later step would take for this one's.
  const bool had_preview = !a.preview.empty() && std::filesystem::exists(a.preview);
  if (!a.preview.empty()) write_png(a.preview, preview(p.m, p.gaze));
  try {
    if (std::filesystem::path(a.out).extension() == ".bin") {
      write_file_atomic(
          a.out, std::string_view(reinterpret_cast<const char*>(p.bytes.data()), p.bytes.size()));
    } else {
      write_file_atomic(a.out, rates_json(p).dump(1) + "\n");
    }
  } catch (...) {
    std::error_code ignored;
    if (!a.preview.empty() && !had_preview) std::filesystem::remove(a.preview, ignored);
    throw;
  }
  print_rates(a, p);
}

}  // namespace

void register_rates(CLI::App& app);
const CommandRegistrar kRates(15, register_rates);

void register_rates(CLI::App& app) {
  auto a = std::make_shared<RatesArgs>();
  CLI::App* sub = app.add_subcommand(
      "rates", "Write the shading-rate image (variable-rate shading) the acuity model gives");
  sub->add_option("--display", a->display,
                  "Display preset (" + Display::preset_names() +
                      ") or JSON file; through a lens (hmd-rift-dk1, hmd-quest2-lens) no tile is "
                      "shaded finer than the panel shows")
      ->capture_default_str();
  sub->add_option("--gaze", a->gaze,
                  "Gaze point X,Y in pixels or normalized (0.5,0.5); default centre");
  sub->add_option("--tile", a->tile, "Tile size in pixels: " + shading_rate_tiles_text())
      ->capture_default_str();
  sub->add_option("--api", a->api,
                  "Encoding: vulkan (attachment texels), d3d12 (D3D12_SHADING_RATE) or gl-nv "
                  "(palette indices, rows bottom-to-top)")
      ->capture_default_str();
  sub->add_option("--out", a->out, "Output: FILE.bin (one byte per tile) or FILE.json")->required();
  sub->add_option("--preview", a->preview, "Also write a PNG: a colour per rate and a legend");
  sub->add_option("--size", a->size, "Render at WxH with the display's geometry (field of view)");
  add_acuity_options(sub, a->acuity_preset, a->slope);
  sub->add_option("--margin", a->margin,
                  "Plan for an acuity this many times finer (1 to 4; 1 = two samples per MAR "
                  "cycle of the model itself); default 1.5, where the model's rates alone stay "
                  "within 0.25 JOD of native on the built-in scenes (the vrs technique plans at "
                  "1 and refines busy tiles frame by frame, which a rate image written once "
                  "cannot)");
  sub->add_option("--latency-ms", a->latency_ms,
                  "Gaze latency: the fovea grows by latency x --max-saccade degrees")
      ->capture_default_str();
  sub->add_option("--max-saccade", a->max_saccade, "Fastest eye movement, degrees per second")
      ->capture_default_str();
  sub->add_option("--rates", a->rates,
                  "Rates the GPU supports, e.g. 1x1,2x2,4x4 (must include 1x1); default all "
                  "of 1x1,1x2,2x1,2x2,2x4,4x2,4x4");
  sub->callback([a] { run_rates(*a); });
}

}  // namespace foveate::app
