#include "session_args.hpp"

#include <cmath>
#include <cstdlib>
#include <limits>

#include "foveate/bench/params_file.hpp"
#include "foveate/core/parse.hpp"
#include "foveate/gaze/gaze.hpp"
#include "foveate/scenes/scene.hpp"
#include "foveate/techniques/technique.hpp"
#include "photometry_flags.hpp"

namespace foveate::app {

bench::ParamOverrides parse_params(const std::vector<std::string>& items) {
  bench::ParamOverrides out;
  for (const std::string& item : items) {
    const auto eq = item.find('=');
    if (eq == std::string::npos || eq == 0) {
      throw Error("--param: expected KEY=VALUE or TECHNIQUE.KEY=VALUE, got '" + item + "'");
    }
    const std::string key = item.substr(0, eq), value = item.substr(eq + 1);
    char* end = nullptr;
    const double v = std::strtod(value.c_str(), &end);
    if (value.empty() || end != value.c_str() + value.size()) {
      throw Error("--param " + key + ": '" + value + "' is not a number");
    }
    out.set(key, v);
  }
  return out;
}

bench::ParamOverrides session_params(const SessionArgs& a,
                                     const std::vector<std::string>& techniques) {
  bench::ParamOverrides out;
  if (!a.params_file.empty()) {
    // A file holds values for every technique it was tuned for: those of the
    // techniques run apply.
    const bench::ParamOverrides file =
        with_flag("--params-file", [&] { return bench::read_params_file(a.params_file); });
    out = file.only(techniques);
    // A file for other techniques alone would change nothing: that is a
    // wrong file or a wrong --technique(s), not a run to make silently.
    if (!file.per_technique.empty() && out.per_technique.empty()) {
      std::vector<std::string> in_file;
      for (const auto& [technique, values] : file.per_technique) in_file.push_back(technique);
      throw Error("--params-file " + a.params_file + ": holds parameters for " +
                  join(in_file, ", ") + ", none for the techniques run (" + join(techniques, ", ") +
                  ")");
    }
  }
  const bench::ParamOverrides given = parse_params(a.params);
  // What --param says must apply to a technique run (the library names the field).
  given.validate(techniques);
  // The command line overrides the file: a key given for every technique
  // (--param KEY=V, or --margin) replaces the file's values of that key for
  // each technique, which would otherwise win as the more specific.
  const auto drop_from_file = [&](const std::string& key) {
    for (auto& [technique, values] : out.per_technique) values.erase(key);
  };
  if (a.margin) drop_from_file(kPlanMarginKey);
  if (const auto all = given.per_technique.find(""); all != given.per_technique.end()) {
    for (const auto& [key, v] : all->second) drop_from_file(key);
  }
  for (const auto& [technique, values] : given.per_technique) {
    for (const auto& [key, v] : values) out.per_technique[technique][key] = v;
  }
  return out;
}

void add_acuity_options(CLI::App* sub, std::string& preset, std::optional<double>& slope) {
  sub->add_option("--acuity,--quality", preset,
                  "Acuity preset of Guenter et al.'s user study: A (m = 0.0275) or B (m = "
                  "0.0220); default A (--quality is the same option)");
  sub->add_option("--slope", slope,
                  "Custom MAR slope m in degrees per degree of eccentricity (instead of --acuity)");
}

void add_memory_limit_option(CLI::App* sub, std::string& limit, const std::string& what) {
  sub->add_option("--memory-limit", limit,
                  "Memory the " + what +
                      "s judged at once may hold (e.g. 8G; default 70 % of what is available "
                      "at the start): FovVideoVDP keeps about 0.45 GB per " +
                      what + " at 1920x1080, and beyond the limit the " + what +
                      "s are judged in groups, one after another, each timed against its own "
                      "native (a note says so; in bench's results.json: memory_groups)");
}

namespace {

void add_scene_file_options(CLI::App* sub, SessionArgs& a) {
  sub->add_option("--camera-path", a.camera_path,
                  "Camera keyframes JSON (built-in and mesh scenes)");
  sub->add_option("--channel", a.channels,
                  "Image for iChannel0..3 of a Shadertoy shader (repeat, in order)");
  sub->add_option("--up", a.up,
                  "Up axis of a mesh file: y or z (default: the file's metadata, else y)");
  sub->add_option("--model-memory-limit", a.model_memory_limit,
                  "Refuse a mesh file whose declared size needs more memory than this to import "
                  "(e.g. 512M, 8G; default half the machine's memory)");
}

void add_plan_options(CLI::App* sub, SessionArgs& a) {
  sub->add_option("--size", a.size,
                  "Output size WxH in pixels (the display's field of view is kept; below about "
                  "1280x720 on a desktop display foveation has little to save, and a note says so)")
      ->capture_default_str();
  sub->add_option("--display", a.display,
                  "Display preset (" + Display::preset_names() +
                      ") or JSON file (its field of view is kept at --size)")
      ->capture_default_str();
  add_photometry_flags(*sub, a.photometry);
  add_acuity_options(sub, a.acuity_preset, a.slope);
  sub->add_option("--margin", a.margin,
                  "Plan every technique for an acuity this many times finer (slope and foveal "
                  "MAR divided by it, 1 to 4) than the one the metrics judge by: 1 = each "
                  "paper's plan; default: each technique's own margin, the one 'foveate tune' "
                  "chose as its fastest within 0.25 JOD of native (see 'foveate techniques'); "
                  "the same as --param margin=K");
  sub->add_option("--param", a.params,
                  "Technique parameter KEY=VALUE or TECHNIQUE.KEY=VALUE (repeatable; see "
                  "'foveate techniques')");
  sub->add_option("--params-file", a.params_file,
                  "Technique parameters from a JSON file (what 'foveate tune' writes: "
                  "params.json); --param values override it");
  sub->add_option("--gaze", a.gaze,
                  std::string("Gaze source; default the screen centre. ") + gaze::gaze_spec_help());
}

void add_clock_options(CLI::App* sub, SessionArgs& a, const char* default_date) {
  sub->add_option("--fps", a.fps, "Frame rate of the fixed clock (frame k is at time + k / fps)")
      ->capture_default_str();
  sub->add_option("--time", a.start_time_s, "Scene time of the first frame in seconds")
      ->capture_default_str();
  sub->add_flag("--strict", a.strict,
                "A gaze trace (--gaze trace:FILE) row that cannot be read is an error (default: "
                "skipped with a warning naming its line)");
  sub->add_option("--frame-timeout", a.frame_timeout,
                  "Stop with an error when a frame takes longer than this many seconds "
                  "(0 = no limit; a GL draw cannot be interrupted, so the process exits)")
      ->capture_default_str();
  sub->add_option("--date", a.date,
                  std::string("Shadertoy iDate: now (the real clock), YYYY-MM-DD or "
                              "YYYY-MM-DDTHH:MM[:SS] (a fixed start that the scene time advances); "
                              "default ") +
                      (std::string_view(default_date) == "now"
                           ? "now"
                           : std::string(default_date) + " (fixed, for reproducible frames)"));
}

void add_stereo_options(CLI::App* sub, SessionArgs& a) {
  sub->add_flag("--stereo", a.stereo,
                "Render both eyes of a stereo head-mounted display (--display " +
                    Display::preset_names(true) +
                    " or a JSON file with fov_deg and ipd_mm), side by side, the left eye on the "
                    "left; --size is one eye's, and --gaze the combined gaze (the cyclopean "
                    "eye's, its centre straight ahead)");
  sub->add_option("--vergence", a.vergence,
                  "With --stereo: the distance in metres at which both eyes' gaze converges "
                  "(default inf: parallel, each eye looking the same way)");
}

}  // namespace

void add_session_options(CLI::App* sub, SessionArgs& a, bool scene_required,
                         const char* default_date, bool stereo) {
  auto* scene = sub->add_option(
      "--scene", a.scene,
      "Built-in scene name (see 'foveate scenes'), Shadertoy .glsl file or mesh file");
  if (scene_required) {
    scene->required();
  } else {
    scene->capture_default_str();
  }
  add_plan_options(sub, a);
  add_scene_file_options(sub, a);
  add_clock_options(sub, a, default_date);
  if (stereo) add_stereo_options(sub, a);
}

bench::SessionOptions to_session_options(const SessionArgs& a, const char* default_date) {
  bench::SessionOptions o;
  o.scene_options.date = with_flag("--date", [&] {
    return parse_shadertoy_date(a.date.empty() ? std::string(default_date) : a.date);
  });
  o.scene = a.scene;
  o.scene_options.channels = a.channels;
  o.scene_options.camera_path = a.camera_path;
  o.scene_options.up = a.up;
  if (!a.model_memory_limit.empty()) {
    o.scene_options.model_memory_limit =
        parse_byte_size(a.model_memory_limit, "--model-memory-limit");
  }
  o.size = parse_size(a.size, "--size");
  o.display = a.display;
  o.photometry = a.photometry;
  o.acuity = bench::acuity_from(a.acuity_preset, a.slope);
  o.margin = a.margin;
  o.gaze = a.gaze;
  o.fps = a.fps;
  o.start_time_s = a.start_time_s;
  o.stereo = a.stereo;
  if (a.vergence == "inf") {
    o.vergence_m = std::numeric_limits<double>::infinity();
  } else if (!a.vergence.empty()) {
    double v = 0.0;
    if (!parse_number(a.vergence, v))
      throw Error("--vergence: expected a distance in metres > 0 (or inf), got '" + a.vergence +
                  "'");
    o.vergence_m = v;
  }
  o.strict_traces = a.strict;
  o.frame_timeout_s = a.frame_timeout;
  bench::validate(o);
  return o;
}

}  // namespace foveate::app
