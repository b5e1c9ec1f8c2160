// foveate plan: the eccentricity layers of Guenter et al. for a display and an
// acuity slope, and the field-of-view sweep behind their Figures 12 and 13.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "cli_util.hpp"
#include "commands.hpp"
#include "foveate/bench/savings.hpp"
#include "foveate/bench/svg_plot.hpp"
#include "foveate/core/error.hpp"
#include "foveate/core/file.hpp"
#include "foveate/core/parse.hpp"
#include "foveate/core/planner.hpp"
#include "foveate/techniques/technique.hpp"
#include "progress.hpp"
#include "session_args.hpp"

namespace foveate::app {

using bench::ChartOptions;
using bench::Series;
using bench::svg_line_chart;

namespace {

struct PlanArgs {
  std::string display = "desktop-1080p";
  std::string acuity_preset;  ///< --acuity (--quality): "A", "B" or empty
  std::optional<double> slope;
  std::optional<double> margin;  ///< unset: layered's own planning margin
  std::optional<int> layers;     ///< unset: layered's own with its margin, else the paper's 3
  std::string gaze;
  std::string size = kDefaultSize;
  std::optional<double> fixed_s2;
  double step = 0.05;
  int max_grid = PlannerOptions{}.max_grid_points;
  bool half_rate_weights = false;
  bool json = false;
  std::string sweep;
};

std::string sweep_csv(const std::vector<SweepRow>& rows) {
  std::ostringstream s;
  s << "fov_deg,display_width_px,native_pixels";
  for (const char* q : {"A", "B"}) {
    for (const SweepVariant& v : sweep_variants()) s << ",speedup_" << q << "_n" << v.name;
  }
  for (const char* q : {"A", "B"}) {
    for (const SweepVariant& v : sweep_variants()) s << ",pixels_" << q << "_n" << v.name;
  }
  s << '\n';
  for (const SweepRow& r : rows) {
    s << format_number(r.fov_deg) << ',' << format_number(r.display_width_px) << ','
      << format_number(r.native_pixels, 0);
    for (double x : r.speedup_a) s << ',' << format_number(x);
    for (double x : r.speedup_b) s << ',' << format_number(x);
    for (double x : r.pixels_a) s << ',' << format_number(x, 0);
    for (double x : r.pixels_b) s << ',' << format_number(x, 0);
    s << '\n';
  }
  return s.str();
}

std::string sweep_svg(const std::vector<SweepRow>& rows) {
  const char* colors[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd"};
  std::vector<Series> series;
  for (int q = 0; q < 2; ++q) {
    for (size_t v = 0; v < sweep_variants().size(); ++v) {
      Series s;
      s.name = std::string(q == 0 ? "A" : "B") + ", n=" + sweep_variants()[v].name;
      s.color = colors[v];
      s.dashed = q == 1;
      for (const SweepRow& r : rows) {
        s.x.push_back(r.fov_deg);
        s.y.push_back(q == 0 ? r.speedup_a[v] : r.speedup_b[v]);
      }
      series.push_back(std::move(s));
    }
  }
  ChartOptions o;
  o.title = "Figure 12: predicted speedup P*/P at display sharpness = foveal acuity (eq. 9)";
  o.x_label = "field of view (degrees)";
  o.y_label = "speedup (pixels), log scale";
  o.log_y = true;
  // Figure 13: rendering cost (pixels) of native and foveated rendering.
  std::vector<Series> cost;
  Series native{"native P*", "#000000", {}, {}, false};
  for (const SweepRow& r : rows) {
    native.x.push_back(r.fov_deg);
    native.y.push_back(r.native_pixels);
  }
  cost.push_back(native);
  for (size_t v = 0; v < sweep_variants().size(); ++v) {
    Series a{std::string("A, n=") + sweep_variants()[v].name, colors[v], {}, {}, false};
    for (const SweepRow& r : rows) {
      a.x.push_back(r.fov_deg);
      a.y.push_back(r.pixels_a[v]);
    }
    cost.push_back(a);
  }
  ChartOptions c;
  c.title = "Figure 13: pixels to render, native against foveated (acuity preset A)";
  c.x_label = "field of view (degrees)";
  c.y_label = "pixels per frame, log scale";
  c.log_y = true;
  std::string top = svg_line_chart(series, o), bottom = svg_line_chart(cost, c);
  bottom.replace(bottom.find("<svg "), 5, "<svg y=\"" + std::to_string(o.height) + "\" ");
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(o.width) +
         "\" height=\"" + std::to_string(o.height + c.height) + "\">\n" + top + bottom + "</svg>\n";
}

// The field-of-view sweep into a .csv or .svg file (and its rows as JSON).
void run_sweep(const PlanArgs& a) {
  const std::string ext = std::filesystem::path(a.sweep).extension().string();
  if (ext != ".csv" && ext != ".svg") {
    throw Error("--sweep: the file must end in .csv or .svg, got '" + a.sweep + "'");
  }
  // One field of view at a time, for the progress bar (the whole sweep
  // takes seconds at the default grid).
  std::vector<SweepRow> rows;
  Progress progress("plan --sweep", "fields of view", 23, !a.json);
  for (int i = 0; i <= 22; ++i) {
    const double fov = 10.0 + 5.0 * i;
    for (SweepRow& r : fov_sweep(fov, fov, 5.0, a.step, a.max_grid)) rows.push_back(std::move(r));
    progress.step(format_number(fov) + " deg");
  }
  write_file_atomic(a.sweep, ext == ".csv" ? sweep_csv(rows) : sweep_svg(rows));
  if (!a.json) {
    std::cout << "wrote " << a.sweep << " (" << rows.size() << " fields of view, 10-120 deg)\n";
    return;
  }
  nlohmann::json j = {{"file", a.sweep}, {"rows", nlohmann::json::array()}};
  for (const SweepRow& r : rows) {
    nlohmann::json row = {{"fov_deg", r.fov_deg},
                          {"display_width_px", r.display_width_px},
                          {"native_pixels", r.native_pixels}};
    for (size_t v = 0; v < sweep_variants().size(); ++v) {
      const std::string n = sweep_variants()[v].name;
      row["speedup_A_n" + n] = r.speedup_a[v];
      row["speedup_B_n" + n] = r.speedup_b[v];
      row["pixels_A_n" + n] = r.pixels_a[v];
      row["pixels_B_n" + n] = r.pixels_b[v];
    }
    j["rows"].push_back(row);
  }
  std::cout << j.dump(2) << '\n';
}

// A plan for one display and gaze, and the same display's plan without its
// lens (where it has one).
struct GazePlan {
  Display display;
  AcuityModel acuity;  ///< what the plan is judged by
  double margin = 1;   ///< the plan is made for `acuity` this many times finer
  Vec2d gaze;
  LayerPlan plan;
  std::optional<LayerPlan> without_lens;

  // Where layer i lands on the screen for this gaze (inner layers are
  // squares centred on the gaze; the outer layer is the whole screen).
  [[nodiscard]] std::array<double, 4> screen_rect(size_t i) const {
    const Layer& L = plan.layers[i];
    if (i + 1 == plan.layers.size())
      return std::array<double, 4>{0, 0, double(display.width_px), double(display.height_px)};
    const double half = 0.5 * L.width_px * L.sampling_factor;
    return std::array<double, 4>{gaze.x - half, gaze.y - half, gaze.x + half, gaze.y + half};
  }
};

GazePlan make_gaze_plan(const PlanArgs& a) {
  Display display = Display::load(a.display);
  {
    const PixelSize sz = parse_size(a.size, "--size");
    display = display.resized(sz.width, sz.height);
  }
  const AcuityModel acuity = bench::acuity_from(a.acuity_preset, a.slope);
  // The layers the layered technique renders: planned at its own margin
  // unless --margin says otherwise (1 = the paper's plan).
  if (a.margin) bench::check_margin(*a.margin);
  const double margin = a.margin.value_or(bench::own_plan_margin("layered"));
  const AcuityModel planned = acuity.finer(margin);
  note_savings(display, acuity, margin);
  // The layer count goes with the margin: layered's own with its own margin,
  // the paper's three with a margin given.
  int own_layers = 3;
  for (const ParamDecl& p : technique_info("layered").params) {
    if (p.key == "layers") own_layers = static_cast<int>(p.value);
  }
  const int layers = a.layers.value_or(a.margin ? 3 : own_layers);
  PlannerOptions opt;
  opt.layers = layers;
  opt.grid_step_deg = a.step;
  opt.fixed_s2 = a.fixed_s2;
  opt.max_grid_points = a.max_grid;
  if (a.half_rate_weights) {
    opt.weights.assign(static_cast<size_t>(layers), 0.5);
    opt.weights[0] = 1.0;
  }
  const Vec2d gaze =
      a.gaze.empty() ? display.principal_point()
                     : parse_point_on_image(a.gaze, display.width_px, display.height_px, "--gaze");
  // Through a lens the plan depends on the gaze (without --gaze: any gaze).
  if (!a.gaze.empty()) opt.gaze = gaze;
  GazePlan g{display, acuity, margin, gaze, plan_layers(display, planned, opt), std::nullopt};
  if (display.lens) {
    Display bare = display;
    bare.lens.reset();
    g.without_lens = plan_layers(bare, planned, opt);
  }
  return g;
}

void print_plan_json(const PlanArgs& a, const GazePlan& g) {
  nlohmann::json j = g.plan;
  // "acuity" is the model judged by, as in the text and in bench's
  // results.json; the plan is made for it `margin` times finer.
  j["planned_acuity"] = j["acuity"];
  j["acuity"] = {{"slope", g.acuity.slope}, {"w0_deg", g.acuity.w0_deg}};
  j["gaze_px"] = {g.gaze.x, g.gaze.y};
  j["margin"] = g.margin;
  if (g.without_lens) {
    const Oversampling o = g.display.lens_oversampling(g.gaze);
    nlohmann::json s = nlohmann::json::array();
    for (const Layer& L : g.without_lens->layers) s.push_back(L.sampling_factor);
    j["lens"] = {{"planned_for", a.gaze.empty() ? "any gaze" : "this gaze"},
                 {"oversampling_at_gaze", {{"radial", o.radial}, {"tangential", o.tangential}}},
                 {"without_lens",
                  {{"sampling_factors", s},
                   {"total_pixels", g.without_lens->total_pixels},
                   {"pixel_ratio", g.without_lens->pixel_ratio()}}}};
  }
  for (size_t i = 0; i < g.plan.layers.size(); ++i) {
    const auto r = g.screen_rect(i);
    j["layers"][i]["screen_rect_px"] = {r[0], r[1], r[2], r[3]};
  }
  std::cout << j.dump(2) << '\n';
}

void print_plan(const PlanArgs& a, const GazePlan& g) {
  const LayerPlan& plan = g.plan;
  const AcuityModel& acuity = g.acuity;
  const Display& d = plan.display;
  std::cout << "display " << d.name << ": " << d.width_px << 'x' << d.height_px;
  if (d.head_mounted()) {
    std::cout << ", head-mounted, " << format_fixed(d.horizontal_fov_deg(), 1)
              << " deg horizontal field of view\n";
  } else {
    std::cout << ", " << format_fixed(d.width_mm, 0) << " mm wide viewed from "
              << format_fixed(d.distance_mm, 0) << " mm\n";
  }
  std::cout << "  e* (half field of view) = " << format_fixed(d.half_fov_deg(), 2)
            << " deg, w* (sharpness) = " << format_fixed(d.sharpness_deg(), 4)
            << " deg, w0/w* = " << format_fixed(100.0 * acuity.w0_deg / d.sharpness_deg(), 0)
            << " %\n";
  std::cout << "acuity: w(e) = " << format_fixed(acuity.slope, 4) << " e + "
            << format_fixed(acuity.w0_deg, 4) << " deg";
  if (acuity.slope == kSlopePresetA) std::cout << " (acuity preset A)";
  if (acuity.slope == kSlopePresetB) std::cout << " (acuity preset B)";
  std::cout << "\nplanned at margin " << format_number(g.margin, 3)
            << (g.margin == 1.0 ? " (the paper's plan" : " (an acuity that many times finer")
            << (a.margin ? "; --margin)" : "; layered's own, --margin 1 gives the paper's plan)");
  std::cout << "\ngaze at (" << format_fixed(g.gaze.x, 1) << ", " << format_fixed(g.gaze.y, 1)
            << ") px\n\n";
  std::printf("%-6s %11s %11s %9s %13s %11s  %s\n", "layer", "radius deg", "radius px", "s_i",
              "target px", "pixels", "on screen (x0,y0)-(x1,y1)");
  for (size_t i = 0; i < plan.layers.size(); ++i) {
    const Layer& L = plan.layers[i];
    const auto r = g.screen_rect(i);
    const std::string sz = std::to_string(L.width_px) + "x" + std::to_string(L.height_px);
    std::printf("%-6zu %11.2f %11.1f %9.3f %13s %11.0f  (%.0f,%.0f)-(%.0f,%.0f)%s\n", i + 1,
                L.radius_deg, L.radius_px, L.sampling_factor, sz.c_str(), L.pixels, r[0], r[1],
                r[2], r[3], i + 1 == plan.layers.size() ? " whole screen" : "");
  }
  std::printf("\nnative pixels P* = %.0f, layer pixels P = %.0f\n", plan.native_pixels,
              plan.total_pixels);
  std::printf("pixel ratio P*/P = %.2fx; with outer layers at half rate = %.2fx\n",
              plan.pixel_ratio(), plan.pixel_ratio_half_rate());
  if (g.without_lens) {
    const LayerPlan& free = *g.without_lens;
    std::printf("\nthrough the lens (panel %dx%d), planned for %s: %s\n",
                g.display.lens->panel_width_px, g.display.lens->panel_height_px,
                a.gaze.empty() ? "any gaze (--gaze plans for one)" : "this gaze",
                lens_at_gaze(g.display, g.gaze).c_str());
    std::printf("without the lens:");
    for (const Layer& L : free.layers) std::printf(" s = %.3f", L.sampling_factor);
    std::printf(", P = %.0f, P*/P = %.2fx (the lens saves %.1f %% of the layer pixels)\n",
                free.total_pixels, free.pixel_ratio(),
                100.0 * (1.0 - plan.total_pixels / free.total_pixels));
  }
}

void run_plan(const PlanArgs& a) {
  if (a.max_grid < 1 || a.max_grid > 1000000) {
    throw Error("--max-grid: expected 1..1000000 candidate radii, got " +
                std::to_string(a.max_grid));
  }
  if (!a.sweep.empty()) {
    run_sweep(a);
    return;
  }
  const GazePlan g = make_gaze_plan(a);
  if (a.json) {
    print_plan_json(a, g);
  } else {
    print_plan(a, g);
  }
}

}  // namespace

void register_plan(CLI::App& app);
const CommandRegistrar kPlan(10, register_plan);

void register_plan(CLI::App& app) {
  auto a = std::make_shared<PlanArgs>();
  CLI::App* sub = app.add_subcommand(
      "plan", "Plan eccentricity layers (Guenter et al. 2012) for a display and acuity slope");
  sub->add_option("--display", a->display,
                  "Display preset (" + Display::preset_names() +
                      ") or JSON file; through a lens (hmd-rift-dk1, hmd-quest2-lens) no layer "
                      "samples finer than the panel shows")
      ->capture_default_str();
  add_acuity_options(sub, a->acuity_preset, a->slope);
  sub->add_option("--margin", a->margin,
                  "Plan for an acuity this many times finer (slope and foveal MAR divided by it, "
                  "1 to 4) than the one the plan is judged by: 1 = the paper's plan; default: "
                  "the layered technique's own planning margin (see 'foveate techniques'), so "
                  "that the plan is the one 'render --technique layered' renders (not used by "
                  "--sweep, which reproduces the paper's figures)");
  sub->add_option("--layers", a->layers,
                  "Number of layers n, 1..6; default: the layered technique's own (see 'foveate "
                  "techniques'), or with --margin the paper's 3");
  sub->add_option("--gaze", a->gaze,
                  "Gaze point X,Y in pixels or normalized (0.5,0.5); default centre (with a "
                  "lens: the plan then holds for any gaze)");
  sub->add_option("--size", a->size,
                  "Render at WxH with the display's geometry (field of view kept); render's "
                  "default")
      ->capture_default_str();
  sub->add_option("--fixed-s2", a->fixed_s2,
                  "Fix the second layer's sampling factor (the paper's 3* uses 2)");
  sub->add_option("--step", a->step, "Grid step of the radius search in degrees")
      ->capture_default_str();
  sub->add_option("--max-grid", a->max_grid,
                  "Most candidate radii (e* / --step) searched; the time grows with the square")
      ->capture_default_str();
  sub->add_flag("--half-rate-weights", a->half_rate_weights,
                "Optimise with weights 1, 1/2, 1/2, ... (outer layers at half rate)");
  sub->add_flag("--json", a->json, "Print the plan (or with --sweep, the sweep's rows) as JSON");
  sub->add_option("--sweep", a->sweep,
                  "Write the field-of-view sweep (eq. 9; Figures 12-13) to FILE.csv or FILE.svg");
  sub->callback([a] { run_plan(*a); });
}

}  // namespace foveate::app
