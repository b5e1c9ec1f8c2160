// Running a benchmark in-process (the same run_bench as `foveate bench`),
// reading results back, and the techniques with their parameters.
#include <pybind11/stl.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "bench.hpp"
#include "convert.hpp"
#include "foveate/core/error.hpp"
#include "foveate/core/file.hpp"
#include "foveate/techniques/reference.hpp"
#include "session.hpp"

namespace foveate::python {

namespace {

// The app's messages name the command-line flag ("--size: ..."); here the
// same value came as a keyword argument ("size: ...").
[[noreturn]] void rethrow_for_python(const Error& e) {
  std::string msg = e.what();
  if (msg.rfind("--", 0) == 0) {
    const auto colon = msg.find(':');
    std::string flag = msg.substr(2, colon == std::string::npos ? 0 : colon - 2);
    for (char& c : flag) c = c == '-' ? '_' : c;
    if (flag == "no_metrics") flag = "metrics";
    if (colon != std::string::npos) msg = flag + msg.substr(colon);
  }
  throw Error(msg);
}

std::string size_text(py::handle size) {
  if (py::isinstance<py::str>(size)) return size.cast<std::string>();
  const Vec2d p = point_from(size, "size");
  return std::to_string(static_cast<long long>(p.x)) + "x" +
         std::to_string(static_cast<long long>(p.y));
}

std::vector<std::string> param_items(const py::dict& params) {
  std::vector<std::string> out;
  for (const auto& [k, v] : params) {
    double value = 0;
    try {
      value = v.cast<double>();
    } catch (const py::cast_error&) {
      throw py::type_error("params['" + std::string(py::str(k)) + "']: expected a number, got " +
                           std::string(py::repr(v)));
    }
    std::ostringstream s;
    s.precision(17);
    s << std::string(py::str(k)) << "=" << value;
    out.push_back(s.str());
  }
  return out;
}

py::dict run(const std::string& scene, const std::vector<std::string>& techniques, py::handle size,
             int frames, int warmup, const std::string& display, const std::string& quality,
             std::optional<double> slope, std::optional<double> margin, const py::dict& params,
             const std::string& gaze, const std::string& reference, bool metrics,
             const std::string& sweep, double fps, const std::string& out, const std::string& video,
             bool side_by_side, bool images, bool stereo, const std::string& vergence) {
  app::BenchOptions o;
  try {
    app::SessionArgs sa;
    sa.scene = scene;
    sa.size = size_text(size);
    sa.display = display;
    sa.quality = quality;
    sa.slope = slope;
    sa.margin = margin;
    sa.params = param_items(params);
    sa.gaze = gaze;
    sa.fps = fps;
    sa.stereo = stereo;
    sa.vergence = vergence;
    o.session = app::to_session_options(sa);
    o.techniques = techniques;
    for (const std::string& t : o.techniques)
      app::with_flag("--techniques", [&] { return technique_info(t); });
    o.params = app::parse_params(sa.params);
    app::validate_params(o.params, o.techniques);
    o.gaze = gaze;
    o.frames = frames;
    o.warmup = warmup;
    o.image_metrics = metrics;
    o.reference = app::with_flag("--reference", [&] { return parse_reference(reference); });
    o.out = out;
    o.progress = false;
    o.command_line = "foveate.bench (Python)";
    o.video = video;
    o.side_by_side = side_by_side;
    if (side_by_side && video.empty()) throw Error("--side-by-side: only with video=FILE");
    if (!sweep.empty()) o.sweep = app::Sweep::parse(sweep);
  } catch (const Error& e) {
    rethrow_for_python(e);
  }
  app::BenchResult r;
  {
    py::gil_scoped_release unlocked;
    try {
      r = app::run_bench(o);
      if (!out.empty()) app::write_bench_outputs(r);
    } catch (const Error& e) {
      rethrow_for_python(e);
    }
  }
  auto d = to_python(app::bench_json(r)).cast<py::dict>();
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

}  // namespace

void bind_bench(py::module_& m) {
  m.def("bench", &run, py::kw_only(), py::arg("scene") = "cheap",
        py::arg("techniques") =
            std::vector<std::string>{"native", "layered", "logpolar", "checkerboard", "inset"},
        py::arg("size") = "960x540", py::arg("frames") = 10, py::arg("warmup") = 2,
        py::arg("display") = "desktop-1080p", py::arg("quality") = "",
        py::arg("slope") = py::none(), py::arg("margin") = py::none(),
        py::arg("params") = py::dict(), py::arg("gaze") = "", py::arg("reference") = "native",
        py::arg("metrics") = true, py::arg("sweep") = "", py::arg("fps") = 60.0,
        py::arg("out") = "", py::arg("video") = "", py::arg("side_by_side") = false,
        py::arg("images") = false, py::arg("stereo") = false, py::arg("vergence") = "",
        R"(Runs `foveate bench` in this process (headless OpenGL) and returns the results
as a dict with the keys of results.json (docs/bench-json.md): "results" holds one
entry per technique (mean_ms, median_ms, speedup (mean over mean), speedup_ci95, shaded_pixels, pixel_ratio,
quality, ...). Arguments as the command's options: size "WxH" or (w, h); params
{"layers": 3} or {"layered.layers": 3}; gaze a --gaze spec ("0.3,0.4",
"synthetic:7", "trace:FILE"); reference "native" or "ssaa:4"; margin as
--margin (plan every technique for an acuity that many times finer than the
metrics'; None: each technique's own planning margin); sweep "slope=0.02:0.03:0.005" or "margin=1:2:0.5"; out a folder for results.json, .csv, .md, report.html;
video a file (.mp4) of the frames. images=True adds each technique's last frame
("image", HxWx3 uint8) and "native_image". stereo=True renders both eyes of a
stereo display (display="hmd-quest2"; size is one eye's; vergence "2" metres or
"inf"): "stereo" and each result's "eyes" hold the per-eye figures.)");
  m.def(
      "read_results",
      [](const std::string& path) {
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
      },
      py::arg("path"), "results.json of a bench run (the file or its folder) as a dict");
  m.def(
      "techniques",
      [](py::handle display, py::handle size, const AcuityModel& acuity) {
        TechniqueConfig c;
        const Vec2d sz = point_from(size, "size", {1920, 1080});
        if (!(sz.x >= 1 && sz.y >= 1 && sz.x <= 16384 && sz.y <= 16384))
          throw py::value_error("size: each side must be 1..16384");
        c.display = display_from(display, static_cast<int>(sz.x), static_cast<int>(sz.y));
        c.acuity = acuity;
        py::list out;
        for (const TechniqueInfo& t : foveate::techniques()) {
          const ParamValues values = resolve_parameters(t, c);
          py::list params;
          for (const ParamDecl& p : t.params) {
            py::dict pd;
            pd["key"] = p.key;
            pd["help"] = p.help;
            pd["unit"] = p.unit;
            pd["type"] = p.type == ParamType::Real      ? "real"
                         : p.type == ParamType::Integer ? "integer"
                                                        : "boolean";
            pd["min"] = p.min;
            pd["max"] = p.max;
            pd["default"] = values.real(p.key);
            params.append(pd);
          }
          py::dict td;
          td["name"] = t.name;
          td["summary"] = t.summary;
          td["source"] = t.source;
          td["needs_meshes"] = t.needs.meshes;
          td["params"] = params;
          out.append(td);
        }
        return out;
      },
      py::arg("display") = "desktop-1080p", py::arg("size") = py::none(),
      py::arg("acuity") = AcuityModel{},
      "Every technique with its parameters and the defaults derived for the display at `size` "
      "((w, h), default the display's own 1920x1080)");
}

}  // namespace foveate::python
