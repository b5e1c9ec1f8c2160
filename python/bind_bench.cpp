// The benchmark in-process (foveate::bench, as `foveate bench` runs it),
// reading results back, and the techniques with their parameters.
#include <pybind11/stl.h>

#include <filesystem>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>

#include "convert.hpp"
#include "foveate/bench/merge.hpp"
#include "foveate/bench/report.hpp"
#include "foveate/bench/session.hpp"
#include "foveate/bench/tune.hpp"
#include "foveate/core/error.hpp"
#include "foveate/core/file.hpp"
#include "foveate/core/parse.hpp"
#include "foveate/techniques/supersampled_native.hpp"

namespace foveate::python {

namespace {

// The library's fields as this module's keyword arguments, where they differ.
std::string keyword_for(const std::string& field) {
  if (field == "image_metrics") return "metrics";
  if (field == "vergence_m") return "vergence";
  return field;
}

// Runs `fn`; an error in one of the options names the keyword argument.
template <class Fn>
auto keywords(Fn&& fn) -> decltype(fn()) {
  try {
    return fn();
  } catch (const bench::OptionError& e) {
    throw Error(e.message(keyword_for));
  }
}

PixelSize size_from(py::handle size) {
  if (py::isinstance<py::str>(size)) return parse_size(size.cast<std::string>(), "size");
  const Vec2d p = point_from(size, "size");
  return {static_cast<int>(p.x), static_cast<int>(p.y)};
}

std::optional<double> vergence_from(py::handle vergence) {
  if (vergence.is_none()) return std::nullopt;
  if (py::isinstance<py::str>(vergence) && vergence.cast<std::string>().empty())
    return std::nullopt;
  return py::float_(py::reinterpret_borrow<py::object>(vergence)).cast<double>();
}

bench::ParamOverrides params_from(const py::dict& params) {
  bench::ParamOverrides out;
  for (const auto& [k, v] : params) {
    double value = 0;
    try {
      value = v.cast<double>();
    } catch (const py::cast_error&) {
      throw py::type_error("params['" + std::string(py::str(k)) + "']: expected a number, got " +
                           std::string(py::repr(v)));
    }
    out.set(std::string(py::str(k)), value);
  }
  return out;
}

// The notes and warnings of a run (the savings note among them), kept to be
// given to Python once the run is over and the GIL is held again: as
// warnings.warn (UserWarning) and in the result's "notes".
struct Notices {
  std::vector<std::string> texts;
  bench::NoticeFn collect() {
    return [this](const bench::Notice& n) {
      if (n.kind != bench::NoticeKind::Detail) texts.push_back(n.text.render(keyword_for));
    };
  }
  py::list emit() const {
    py::list out;
    const py::object warn = py::module_::import("warnings").attr("warn");
    for (const std::string& t : texts) {
      warn(t, py::module_::import("builtins").attr("UserWarning"), 2);
      out.append(t);
    }
    return out;
  }
};

// The session's keyword arguments, shared by bench() and render(), as
// SessionOptions (an OptionError names the field).
bench::SessionOptions session_from(const std::string& scene, py::handle size,
                                   const std::string& display, const std::string& acuity_preset,
                                   const std::string& quality, std::optional<double> slope,
                                   std::optional<double> margin, const std::string& gaze,
                                   double fps, bool stereo, py::handle vergence,
                                   double frame_timeout_s) {
  bench::SessionOptions o;
  o.scene = scene;
  o.size = size_from(size);
  o.display = display;
  if (!acuity_preset.empty() && !quality.empty()) {
    throw bench::OptionError("quality", bench::FieldText{"{acuity_preset} and {quality} are one "
                                                         "option (quality its former name): give "
                                                         "one",
                                                         {"acuity_preset", "quality"}});
  }
  o.acuity = bench::acuity_from(acuity_preset.empty() ? quality : acuity_preset, slope);
  o.margin = margin;
  o.gaze = gaze;
  o.fps = fps;
  o.stereo = stereo;
  o.vergence_m = vergence_from(vergence);
  o.frame_timeout_s = frame_timeout_s;
  return o;
}

// "WxH" of a size, as the command writes its default.
std::string size_text(PixelSize s) {
  return std::to_string(s.width) + "x" + std::to_string(s.height);
}

// As the command's --out: a folder holding an earlier run's output is
// refused unless `overwrite`, which removes those files first, so that no
// folder mixes two runs' files.
void prepare_out(const std::string& out, bool overwrite) {
  if (out.empty()) return;
  const std::vector<std::string> earlier = run_outputs_in(out);
  if (earlier.empty()) return;
  const std::string which =
      std::filesystem::path(earlier.front()).filename().string() +
      (earlier.size() > 1 ? " and " + std::to_string(earlier.size() - 1) + " more" : "");
  if (!overwrite) {
    throw Error("out " + out + ": holds the output of an earlier run (" + which +
                "); pass overwrite=True to replace it (its files are removed first) or choose "
                "another folder");
  }
  for (const std::string& f : earlier) {
    std::error_code ec;
    std::filesystem::remove(f, ec);
    if (ec) throw Error(f + ": cannot remove the earlier run's file (overwrite): " + ec.message());
  }
}

bench::Sweep sweep_from(py::handle sweep) {
  if (sweep.is_none()) return {};
  const auto t = sweep.cast<py::tuple>();
  if (t.size() == 2 && !py::isinstance<py::str>(t[1]) && py::isinstance<py::iterable>(t[1])) {
    return bench::Sweep::of(t[0].cast<std::string>(), t[1].cast<std::vector<double>>());
  }
  if (t.size() != 4)
    throw py::value_error("sweep: expected (key, from, to, step) or (key, [values])");
  return bench::Sweep::range(t[0].cast<std::string>(), t[1].cast<double>(), t[2].cast<double>(),
                             t[3].cast<double>());
}

}  // namespace

namespace {

py::dict result_dict(const bench::BenchResult& r, bool images) {
  auto d = to_python(bench::bench_json(r)).cast<py::dict>();
  d["gaze_report"] = r.gaze_report;
  d["video"] = r.video_summary.empty() ? py::object(py::none()) : py::str(r.video_summary);
  if (images) {
    d["native_image"] = image_to_array(r.native_sample);
    auto results = d["results"].cast<py::list>();
    for (size_t i = 0; i < r.results.size(); ++i) {
      auto entry = results[i].cast<py::dict>();
      entry["image"] = image_to_array(r.results[i].sample);
    }
  }
  return d;
}

py::dict run(const std::string& scene, std::optional<std::vector<std::string>> techniques,
             py::handle size, int frames, int warmup, const std::string& display,
             const std::string& acuity_preset, const std::string& quality,
             std::optional<double> slope, std::optional<double> margin, const py::dict& params,
             const std::string& gaze, const std::string& reference, bool metrics, py::handle sweep,
             double fps, const std::string& out, bool overwrite, const std::string& video,
             bool side_by_side, bool images, bool stereo, py::handle vergence,
             double frame_timeout_s, const std::string& shard, double memory_limit) {
  bench::BenchOptions o;
  keywords([&] {
    o.session = session_from(scene, size, display, acuity_preset, quality, slope, margin, gaze, fps,
                             stereo, vergence, frame_timeout_s);
    o.techniques = std::move(techniques);
    o.params = params_from(params);
    o.frames = frames;
    o.warmup = warmup;
    o.image_metrics = metrics;
    o.reference = bench::for_field("reference", [&] { return parse_reference(reference); });
    o.command = "foveate.bench (Python)";
    o.video = video;
    o.side_by_side = side_by_side;
    o.sweep = sweep_from(sweep);
    if (!shard.empty()) o.shard = bench::parse_shard(shard);
    o.memory_limit_bytes = memory_limit;
    bench::validate(o);
  });
  prepare_out(out, overwrite);
  bench::BenchResult r;
  Notices notices;
  {
    py::gil_scoped_release unlocked;
    bench::BenchCallbacks callbacks;
    callbacks.session.notice = notices.collect();
    keywords([&] {
      r = bench::run_bench(o, callbacks);
      if (!out.empty()) bench::write_bench_report(r, out);
    });
  }
  py::dict d = result_dict(r, images);
  d["notes"] = notices.emit();
  return d;
}

// `foveate tune` in this process: the search, its tune.json as a dict and,
// with `out`, its files (params.json for params_file= of the command line).
py::dict tune(const std::vector<std::string>& scenes,
              std::optional<std::vector<std::string>> techniques, double bound, py::handle size,
              int frames, int warmup, const std::string& display, const std::string& acuity_preset,
              std::optional<double> slope, const std::string& gaze, const std::string& reference,
              double fps, bool grid, const std::string& out, bool overwrite, double frame_timeout_s,
              const std::string& shard, double memory_limit,
              const std::map<std::string, std::vector<double>>& values) {
  bench::TuneOptions o;
  keywords([&] {
    o.bench.session =
        session_from(scenes.empty() ? std::string() : scenes.front(), size, display, acuity_preset,
                     "", slope, std::nullopt, gaze, fps, false, py::none(), frame_timeout_s);
    o.scenes = scenes;
    o.techniques = std::move(techniques);
    o.bound_jod = bound;
    o.bench.frames = frames;
    o.bench.warmup = warmup;
    o.bench.reference = bench::for_field("reference", [&] { return parse_reference(reference); });
    o.bench.command = "foveate.tune (Python)";
    o.grid = grid;
    if (!shard.empty()) o.shard = bench::parse_shard(shard);
    o.bench.memory_limit_bytes = memory_limit;
    o.values = values;
    bench::validate(o);
  });
  prepare_out(out, overwrite);
  bench::TuneResult r;
  Notices notices;
  {
    py::gil_scoped_release unlocked;
    bench::TuneCallbacks callbacks;
    callbacks.bench.session.notice = notices.collect();
    keywords([&] {
      r = bench::run_tune(o, callbacks);
      if (!out.empty()) bench::write_tune_report(r, out);
    });
  }
  auto d = to_python(bench::tune_json(r)).cast<py::dict>();
  d["notes"] = notices.emit();
  return d;
}

// Frames of one technique, as `foveate render` renders them, read back.
py::dict render(const std::string& scene, const std::string& technique, py::handle size, int frames,
                const std::string& display, const std::string& acuity_preset,
                const std::string& quality, std::optional<double> slope,
                std::optional<double> margin, const py::dict& params, const std::string& gaze,
                double fps, bool overlay, bool stereo, py::handle vergence,
                double frame_timeout_s) {
  bench::SessionOptions o;
  bench::ParamOverrides overrides;
  keywords([&] {
    o = session_from(scene, size, display, acuity_preset, quality, slope, margin, gaze, fps, stereo,
                     vergence, frame_timeout_s);
    bench::validate(o);
    (void)bench::for_field("technique", [&] { return technique_info(technique).name; });
    overrides = params_from(params);
    overrides.validate({technique});
    if (!(frames >= 1 && frames <= 100000))
      throw bench::OptionError("frames", "expected 1..100000, got " + std::to_string(frames));
  });
  std::vector<Image> images;
  std::vector<double> shaded, native;
  std::string report;
  Notices notices;
  {
    py::gil_scoped_release unlocked;
    keywords([&] {
      bench::SessionCallbacks callbacks;
      callbacks.notice = notices.collect();
      bench::Session session(o, callbacks);
      session.set_overlay(overlay);
      bench::SessionTechnique t = session.make(technique, overrides);
      for (int k = 0; k < frames; ++k) {
        const GazeState g = session.gaze().at(session.frame_runner().frame_input(k).time_s);
        const bench::SessionFrame st =
            session.watchdog().run("frame " + std::to_string(k) + " (" + technique + ")",
                                   [&] { return session.render(t, k, g); });
        shaded.push_back(st.total.shaded_pixels);
        native.push_back(st.total.native_pixels);
        images.push_back(session.read_output());
      }
      report = session.gaze().report();
    });
  }
  py::list arrays;
  for (const Image& im : images) arrays.append(image_to_array(im));
  py::dict d;
  d["frames"] = arrays;
  d["shaded_pixels"] = shaded;
  d["native_pixels"] = native;
  d["gaze_report"] = report;
  d["notes"] = notices.emit();
  return d;
}

py::list technique_list(py::handle display, py::handle size, const AcuityModel& acuity) {
  TechniqueConfig c;
  const Vec2d sz = point_from(size, "size", {1920, 1080});
  if (!(sz.x >= 1 && sz.y >= 1 && sz.x <= 16384 && sz.y <= 16384))
    throw py::value_error("size: each side must be 1..16384");
  c.display = display_from(display, static_cast<int>(sz.x), static_cast<int>(sz.y));
  c.acuity = acuity;
  py::list out;
  for (const TechniqueInfo& t : foveate::techniques()) {
    const ParamValues values = resolve_parameters(t, c);
    py::list ps;
    for (const ParamDecl& p : t.params) {
      py::dict pd;
      pd["key"] = p.key;
      pd["help"] = p.help;
      pd["unit"] = p.unit;
      pd["type"] = param_type_name(p.type);
      pd["min"] = p.min;
      pd["max"] = p.max;
      pd["tune"] = p.tune;
      pd["allowed"] = p.allowed;
      pd["default"] = values.real(p.key);
      ps.append(pd);
    }
    py::dict td;
    td["name"] = t.name;
    td["summary"] = t.summary;
    td["source"] = t.source;
    td["needs_meshes"] = t.needs.meshes;
    td["params"] = ps;
    out.append(td);
  }
  return out;
}

// `foveate merge` in this process: the shards' files joined, written to
// `out` when given, returned as results.json or tune.json is.
py::dict merge(const std::vector<std::string>& shards, const std::string& out, bool overwrite) {
  bench::MergedShards merged;
  keywords([&] { merged = bench::merge_shard_files(shards); });
  prepare_out(out, overwrite);
  if (merged.tune) {
    if (!out.empty()) bench::write_tune_report(*merged.tune, out);
    return to_python(bench::tune_json(*merged.tune)).cast<py::dict>();
  }
  if (!out.empty()) bench::write_bench_report(*merged.bench, out);
  return result_dict(*merged.bench, false);
}

py::object read_results(const std::string& path) {
  std::error_code ec;
  const std::string file = std::filesystem::is_directory(path, ec)
                               ? (std::filesystem::path(path) / "results.json").string()
                               : path;
  const std::string text = read_file(file);
  try {
    return to_python(nlohmann::json::parse(text));
  } catch (const nlohmann::json::exception& e) {
    throw Error(file + ": not valid JSON: " + e.what());
  }
}

}  // namespace

void bind_bench(py::module_& m) {
  // The defaults are the library's, as `foveate bench` and `foveate render` take them.
  const bench::BenchOptions defaults;
  m.def("bench", &run, py::kw_only(), py::arg("scene") = defaults.session.scene,
        py::arg("techniques") = py::none(), py::arg("size") = size_text(defaults.session.size),
        py::arg("frames") = defaults.frames, py::arg("warmup") = defaults.warmup,
        py::arg("display") = defaults.session.display, py::arg("acuity_preset") = "",
        py::arg("quality") = "", py::arg("slope") = py::none(), py::arg("margin") = py::none(),
        py::arg("params") = py::dict(), py::arg("gaze") = "", py::arg("reference") = "native",
        py::arg("metrics") = defaults.image_metrics, py::arg("sweep") = py::none(),
        py::arg("fps") = defaults.session.fps, py::arg("out") = "", py::arg("overwrite") = false,
        py::arg("video") = "", py::arg("side_by_side") = false, py::arg("images") = false,
        py::arg("stereo") = false, py::arg("vergence") = py::none(),
        py::arg("frame_timeout_s") = defaults.session.frame_timeout_s, py::arg("shard") = "",
        py::arg("memory_limit") = 0.0,
        R"(Runs `foveate bench` in this process (headless OpenGL) and returns the results
as a dict with the keys of results.json (docs/bench-json.md): "results" holds one
entry per technique (mean_ms, median_ms, speedup (mean over mean), speedup_ci95,
shaded_pixels, pixel_ratio, quality, ...). techniques: a list of names; None
measures every registered technique the scene can run (the others are listed
in "skipped"). size "WxH" or (w, h); params {"layers": 3} or
{"layered.layers": 3}; gaze a --gaze spec ("0.3,0.4", "synthetic:7",
"trace:FILE"); reference "native" or "ssaa:4"; margin as --margin (plan every
technique for an acuity that many times finer than the metrics'; None: each
technique's own planning margin); acuity_preset "A" or "B" (Guenter et al.'s
presets; quality= is the same, its former name) or slope a MAR slope; sweep
(key, from, to, step) or (key, [values]), e.g. ("slope", 0.02, 0.03, 0.005),
("margin", 1, 2, 0.5) or ("vrs.adapt", [0, 0.25, 0.4]); out a folder for
results.json, .csv, .md, report.html (one holding an earlier run's output is
refused unless overwrite=True, which removes those files first); video a
file (.mp4) of the frames. shard "K/N": job K of N (every N-th run, native in
each), as --shard; merge() joins the jobs' outputs. memory_limit: bytes the
runs judged at once may hold, as --memory-limit (0: 70 % of what is available;
beyond it the runs are judged in groups, "memory_groups" in the result).
images=True adds each technique's last frame ("image", HxWx3 uint8) and
"native_image". stereo=True renders both eyes of a stereo display
(display="hmd-quest2"; size is one eye's; vergence in metres, 2 or "inf"):
"stereo" and each result's "eyes" hold the per-eye figures. frame_timeout_s:
a frame whose GPU work runs longer raises foveate.Error once it has finished
(a GL draw cannot be interrupted); 0 = no limit.)");
  m.def("render", &render, py::kw_only(), py::arg("scene") = defaults.session.scene,
        py::arg("technique") = "native", py::arg("size") = size_text(defaults.session.size),
        py::arg("frames") = 1, py::arg("display") = defaults.session.display,
        py::arg("acuity_preset") = "", py::arg("quality") = "", py::arg("slope") = py::none(),
        py::arg("margin") = py::none(), py::arg("params") = py::dict(), py::arg("gaze") = "",
        py::arg("fps") = defaults.session.fps, py::arg("overlay") = false,
        py::arg("stereo") = false, py::arg("vergence") = py::none(),
        py::arg("frame_timeout_s") = defaults.session.frame_timeout_s,
        R"(Renders frames of a scene with one technique, as `foveate render` does, and
returns a dict: "frames", a list of HxWx3 uint8 numpy arrays (stereo: both eyes
side by side); "shaded_pixels" and "native_pixels" per frame; "gaze_report";
"notes" (also given as warnings, e.g. that the size leaves foveation little
to save). Keywords as in bench(); technique one name; overlay=True draws the
technique's layers or regions and the gaze.)");
  const bench::TuneOptions tune_defaults;
  m.def("tune", &tune, py::kw_only(), py::arg("scenes") = tune_defaults.scenes,
        py::arg("techniques") = py::none(), py::arg("bound") = tune_defaults.bound_jod,
        py::arg("size") = size_text(tune_defaults.bench.session.size),
        py::arg("frames") = tune_defaults.bench.frames,
        py::arg("warmup") = tune_defaults.bench.warmup,
        py::arg("display") = tune_defaults.bench.session.display, py::arg("acuity_preset") = "",
        py::arg("slope") = py::none(), py::arg("gaze") = "", py::arg("reference") = "ssaa:4",
        py::arg("fps") = tune_defaults.bench.session.fps, py::arg("grid") = false,
        py::arg("out") = "", py::arg("overwrite") = false,
        py::arg("frame_timeout_s") = tune_defaults.bench.session.frame_timeout_s,
        py::arg("shard") = "", py::arg("memory_limit") = 0.0,
        py::arg("values") = std::map<std::string, std::vector<double>>{},
        R"(Runs `foveate tune` in this process: for every technique (techniques: a list,
None = every one but native) the fastest setting of its tuned parameters whose
FovVideoVDP JOD stays within `bound` of native's on every scene (settings within
5 % of its speed tie: the one with the most JOD, then the fewest pixels), judged against
`reference` over `frames` frames of a moving camera. Returns tune.json as a
dict: "points" (every candidate: scene, technique, params, stage, speedup,
speedup_ci95, jod, below_native, pixel_ratio, within_bound), "chosen" (technique -> parameters),
"verdict", "native_jod" per scene, "warmup_frames" (every candidate is judged on
the frames after them), and "notes". out: a folder for tune.json, tune.md,
params.json (for --params-file) and report.html, refused if it holds an earlier
run's output unless overwrite=True. grid=True evaluates the fixed grid instead
of the staged search; shard "K/N" its K-th slice of N (merge() joins them);
memory_limit as in bench(); values {"KEY" or "TECHNIQUE.KEY": [v1, v2, ...]}: the
values searched for a parameter instead of its declared ones, as --values.
Other keywords as in bench().)");
  m.def("merge", &merge, py::arg("shards"), py::kw_only(), py::arg("out") = "",
        py::arg("overwrite") = false,
        R"(Runs `foveate merge` in this process: the shards of one benchmark or one tune
run (bench(shard=...) or tune(shard=...); each its out folder or its
results.json / tune.json) joined into one result, refused for shards of
different versions or settings, a missing or repeated job, or a mix of
benchmarks and tune runs. Returns results.json or tune.json as a dict; out: a
folder for the merged files and report.)");
  m.def("read_results", &read_results, py::arg("path"),
        "results.json of a bench run (the file or its folder) as a dict");
  m.def("techniques", &technique_list, py::arg("display") = "desktop-1080p",
        py::arg("size") = py::none(), py::arg("acuity") = AcuityModel{},
        "Every technique with its parameters and the defaults derived for the display at `size` "
        "((w, h), default the display's own 1920x1080)");
}

}  // namespace foveate::python
