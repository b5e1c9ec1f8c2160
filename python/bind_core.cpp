// The acuity model, displays, the layer planner and the other papers' models.
#include <pybind11/stl.h>

#include <nlohmann/json.hpp>
#include <sstream>

#include "convert.hpp"
#include "foveate/core/acuity.hpp"
#include "foveate/core/display.hpp"
#include "foveate/core/error.hpp"
#include "foveate/core/models.hpp"
#include "foveate/core/planner.hpp"

namespace foveate::python {

namespace {

py::tuple xy(Vec2d p) { return py::make_tuple(p.x, p.y); }

template <class T>
py::object as_dict(const T& value) {
  nlohmann::json j;
  to_json(j, value);
  return to_python(j);
}

void bind_acuity(py::module_& m) {
  m.attr("SLOPE_PRESET_A") = kSlopePresetA;
  m.attr("SLOPE_PRESET_B") = kSlopePresetB;
  // The presets' former names.
  m.attr("SLOPE_QUALITY_A") = kSlopePresetA;
  m.attr("SLOPE_QUALITY_B") = kSlopePresetB;
  m.attr("FOVEAL_MAR_DEG") = kFovealMarDeg;
  py::class_<AcuityModel>(m, "AcuityModel",
                          "The MAR model of Guenter et al. 2012, eq. 1: w(e) = slope * e + w0_deg "
                          "(degrees per cycle, e in degrees).")
      .def(py::init([](double slope, double w0_deg) {
             AcuityModel a = AcuityModel::with_slope(slope);
             if (!(w0_deg > 0 && w0_deg < 1)) throw Error("w0_deg: must be in (0, 1) degrees");
             a.w0_deg = w0_deg;
             return a;
           }),
           py::arg("slope") = kSlopePresetA, py::arg("w0_deg") = kFovealMarDeg)
      .def_readonly("slope", &AcuityModel::slope)
      .def_readonly("w0_deg", &AcuityModel::w0_deg)
      .def("mar_deg", py::vectorize(&AcuityModel::mar_deg), py::arg("eccentricity_deg"),
           "MAR in degrees per cycle at eccentricity e (degrees); numbers or numpy arrays.")
      .def("eccentricity_for_mar", py::vectorize(&AcuityModel::eccentricity_for_mar),
           py::arg("mar_deg"), "The eccentricity at which the MAR reaches w (0 when w <= w0).")
      .def_static("preset", &AcuityModel::preset, py::arg("name"),
                  "Acuity preset 'A' (slope 0.0275) or 'B' (0.0220) of Guenter et al.'s user "
                  "study")
      .def_static("quality", &AcuityModel::preset, py::arg("name"),
                  "preset's former name: AcuityModel.preset(name)")
      .def_static("with_slope", &AcuityModel::with_slope, py::arg("slope"))
      .def("__repr__", [](const AcuityModel& a) {
        std::ostringstream s;
        s << "AcuityModel(slope=" << a.slope << ", w0_deg=" << a.w0_deg << ")";
        return s.str();
      });
}

void bind_display(py::module_& m) {
  py::class_<Display>(m, "Display",
                      "A flat display viewed from a point on its central normal (resolution, "
                      "physical width and viewing distance) or a head-mounted display (per-eye "
                      "resolution and horizontal field of view).")
      .def(py::init([](const std::string& name, int width_px, int height_px, double width_mm,
                       double distance_mm, double fov_h_deg) {
             Display d;
             d.name = name;
             d.width_px = width_px;
             d.height_px = height_px;
             d.width_mm = width_mm;
             d.distance_mm = distance_mm;
             d.fov_h_deg = fov_h_deg;
             d.validate();
             return d;
           }),
           py::arg("name") = "custom", py::arg("width_px") = 1920, py::arg("height_px") = 1080,
           py::arg("width_mm") = 510.0, py::arg("distance_mm") = 590.0, py::arg("fov_h_deg") = 0.0)
      .def_readonly("name", &Display::name)
      .def_readonly("width_px", &Display::width_px)
      .def_readonly("height_px", &Display::height_px)
      .def_readonly("width_mm", &Display::width_mm)
      .def_readonly("distance_mm", &Display::distance_mm)
      .def_readonly("fov_h_deg", &Display::fov_h_deg)
      .def_property_readonly("head_mounted", &Display::head_mounted)
      .def_property_readonly("stereo", &Display::stereo,
                             "Whether it is one eye of a stereo headset (fov_deg and ipd_mm)")
      .def_readonly("ipd_mm", &Display::ipd_mm)
      .def(
          "principal_point",
          [](const Display& d) {
            const Vec2d p = d.principal_point();
            return py::make_tuple(p.x, p.y);
          },
          "Where the eye's optical axis meets the image (x, y) in pixels: the centre unless "
          "the four per-eye angles say otherwise")
      .def("eye_distance_px", &Display::eye_distance_px)
      .def("pixels_per_mm", &Display::pixels_per_mm)
      .def("long_axis_px", &Display::long_axis_px)
      .def("aspect", &Display::aspect)
      .def("half_fov_deg", &Display::half_fov_deg, "e*: half the field of view (eq. 6), degrees")
      .def("sharpness_deg", &Display::sharpness_deg, "w*: one cycle at the centre (eq. 7)")
      .def(
          "eccentricity_deg",
          [](const Display& d, py::handle pixel, py::handle gaze) {
            return d.eccentricity_deg(point_from(pixel, "pixel"), point_from(gaze, "gaze"));
          },
          py::arg("pixel"), py::arg("gaze"),
          "Angle (degrees) between the rays to `pixel` and to `gaze`, both (x, y) in pixels")
      .def(
          "pixels_per_degree",
          [](const Display& d, py::handle pixel, py::handle gaze) {
            return d.pixels_per_degree(point_from(pixel, "pixel"), point_from(gaze, "gaze"));
          },
          py::arg("pixel"), py::arg("gaze"))
      .def("radius_px_at", &Display::radius_px_at, py::arg("eccentricity_deg"))
      .def("resized", &Display::resized, py::arg("width"), py::arg("height"),
           "The same display (field of view) at another resolution")
      .def("to_dict", [](const Display& d) { return as_dict(d); })
      .def_static("presets", &Display::presets,
                  "desktop-1080p, desktop-27-4k, hmd-quest3, hmd-quest2, hmd-pimax-crystal")
      .def_static("load", &Display::load, py::arg("name_or_path"),
                  "A preset by name or a display JSON file")
      .def_static(
          "from_dict",
          [](py::handle d) { return Display::from_json(to_json_value(d, "display"), "display"); },
          py::arg("d"),
          "From a dict like {'width_px': 2560, 'height_px': 1440, 'width_mm': 597, "
          "'distance_mm': 650} or {'width_px': 2064, 'height_px': 2208, 'fov_h_deg': 104}")
      .def("__repr__", [](const Display& d) {
        return "Display('" + d.name + "', " + std::to_string(d.width_px) + "x" +
               std::to_string(d.height_px) + ")";
      });
}

void bind_planner(py::module_& m) {
  py::class_<Layer>(m, "Layer", "One eccentricity layer of a plan")
      .def_readonly("radius_deg", &Layer::radius_deg)
      .def_readonly("radius_px", &Layer::radius_px)
      .def_readonly("sampling_factor", &Layer::sampling_factor)
      .def_readonly("width_px", &Layer::width_px)
      .def_readonly("height_px", &Layer::height_px)
      .def_readonly("pixels", &Layer::pixels)
      .def("__repr__", [](const Layer& l) {
        std::ostringstream s;
        s << "Layer(radius_deg=" << l.radius_deg << ", sampling_factor=" << l.sampling_factor
          << ", " << l.width_px << "x" << l.height_px << ")";
        return s.str();
      });
  py::class_<LayerPlan>(m, "LayerPlan", "The layers of Guenter et al.'s planner")
      .def_readonly("display", &LayerPlan::display)
      .def_readonly("acuity", &LayerPlan::acuity)
      .def_readonly("layers", &LayerPlan::layers)
      .def_readonly("native_pixels", &LayerPlan::native_pixels)
      .def_readonly("total_pixels", &LayerPlan::total_pixels)
      .def_readonly("total_pixels_half_rate", &LayerPlan::total_pixels_half_rate)
      .def("pixel_ratio", &LayerPlan::pixel_ratio, "P* / P")
      .def("pixel_ratio_half_rate", &LayerPlan::pixel_ratio_half_rate,
           "P* / P with the outer layers at half rate (how the paper counts 13.3x)")
      .def("to_dict", [](const LayerPlan& p) { return as_dict(p); });
  m.def(
      "plan_layers",
      [](py::handle display, const AcuityModel& acuity, int layers, double grid_step_deg,
         std::vector<double> weights, std::optional<double> fixed_s2) {
        PlannerOptions o;
        o.layers = layers;
        o.grid_step_deg = grid_step_deg;
        o.weights = std::move(weights);
        o.fixed_s2 = fixed_s2;
        return plan_layers(display_from(display), acuity, o);
      },
      py::arg("display") = "desktop-1080p", py::arg("acuity") = AcuityModel{},
      py::arg("layers") = 3, py::arg("grid_step_deg") = 0.05,
      py::arg("weights") = std::vector<double>{}, py::arg("fixed_s2") = py::none(),
      "The layer radii and sampling factors that minimise the pixel count (eq. 2-5, 8)");
  m.def(
      "sampling_factor_at",
      [](double e, const AcuityModel& acuity, py::handle display) {
        return sampling_factor_at(e, acuity, display_from(display));
      },
      py::arg("eccentricity_deg"), py::arg("acuity") = AcuityModel{},
      py::arg("display") = "desktop-1080p", "s for a layer just outside eccentricity e (eq. 2)");
  m.def(
      "fov_sweep",
      [](double from, double to, double step, double grid) {
        py::list out;
        for (const SweepRow& r : fov_sweep(from, to, step, grid)) {
          py::dict row;
          row["fov_deg"] = r.fov_deg;
          row["display_width_px"] = r.display_width_px;
          row["native_pixels"] = r.native_pixels;
          py::dict a, b;
          for (size_t i = 0; i < sweep_variants().size(); ++i) {
            a[sweep_variants()[i].name] = r.speedup_a[i];
            b[sweep_variants()[i].name] = r.speedup_b[i];
          }
          row["speedup_a"] = a;
          row["speedup_b"] = b;
          out.append(row);
        }
        return out;
      },
      py::arg("fov_from_deg") = 10.0, py::arg("fov_to_deg") = 120.0, py::arg("fov_step_deg") = 5.0,
      py::arg("grid_step_deg") = 0.05,
      "Figures 12-13 of Guenter et al.: predicted speedup against field of view per variant "
      "('2', '3', '4', '3*' layers) for acuity presets A and B");
}

void bind_models(py::module_& m) {
  py::class_<LatencyAwareFovea>(m, "LatencyAwareFovea",
                                "Swafford et al. 2015, eq. 1: the foveal diameter grown by latency")
      .def(py::init([](double latency_ms, double max_saccade_deg_per_s, double fovea_deg,
                       double blend_border_px, double error_px) {
             LatencyAwareFovea f{latency_ms, max_saccade_deg_per_s, fovea_deg, blend_border_px,
                                 error_px};
             f.validate();
             return f;
           }),
           py::arg("latency_ms") = 0.0, py::arg("max_saccade_deg_per_s") = 200.0,
           py::arg("fovea_deg") = 5.0, py::arg("blend_border_px") = 0.0, py::arg("error_px") = 0.0)
      .def_readonly("latency_ms", &LatencyAwareFovea::latency_ms)
      .def_readonly("max_saccade_deg_per_s", &LatencyAwareFovea::max_saccade_deg_per_s)
      .def_readonly("fovea_deg", &LatencyAwareFovea::fovea_deg)
      .def(
          "diameter_px",
          [](const LatencyAwareFovea& f, py::handle d) { return f.diameter_px(display_from(d)); },
          py::arg("display") = "desktop-1080p")
      .def(
          "diameter_deg",
          [](const LatencyAwareFovea& f, py::handle d) { return f.diameter_deg(display_from(d)); },
          py::arg("display") = "desktop-1080p");

  py::class_<KernelLogPolar>(m, "KernelLogPolar",
                             "Meng et al. 2018: the kernel log-polar mapping (sigma, alpha)")
      .def(py::init([](double w, double h, double sigma, double alpha) {
             KernelLogPolar k{w, h, sigma, alpha};
             k.validate();
             return k;
           }),
           py::arg("screen_w") = 1920.0, py::arg("screen_h") = 1080.0, py::arg("sigma") = 1.8,
           py::arg("alpha") = 4.0)
      .def_readonly("sigma", &KernelLogPolar::sigma)
      .def_readonly("alpha", &KernelLogPolar::alpha)
      .def_property_readonly("buffer_w", &KernelLogPolar::buffer_w)
      .def_property_readonly("buffer_h", &KernelLogPolar::buffer_h)
      .def("log_extent", &KernelLogPolar::log_extent)
      .def(
          "to_buffer",
          [](const KernelLogPolar& k, py::handle s, py::handle g) {
            return xy(k.to_buffer(point_from(s, "screen"), point_from(g, "gaze")));
          },
          py::arg("screen"), py::arg("gaze"))
      .def(
          "to_screen",
          [](const KernelLogPolar& k, py::handle b, py::handle g) {
            return xy(k.to_screen(point_from(b, "buffer"), point_from(g, "gaze")));
          },
          py::arg("buffer"), py::arg("gaze"));

  py::class_<CheckerboardPattern>(m, "CheckerboardPattern",
                                  "Silvera 2022: quads dropped per region of a checkerboard mask")
      .def_readonly("block", &CheckerboardPattern::block)
      .def_readonly("thresholds_px", &CheckerboardPattern::thresholds_px)
      .def_static("from_fractions", &CheckerboardPattern::from_fractions, py::arg("block"),
                  py::arg("width"), py::arg("height"),
                  py::arg("fractions") = std::array<double, 3>{0.10, 0.25, 0.40})
      .def_static(
          "from_acuity",
          [](int block, py::handle display, const AcuityModel& acuity) {
            return CheckerboardPattern::from_acuity(block, display_from(display), acuity);
          },
          py::arg("block"), py::arg("display") = "desktop-1080p", py::arg("acuity") = AcuityModel{})
      .def(
          "region",
          [](const CheckerboardPattern& c, py::handle p, py::handle g) {
            return c.region(point_from(p, "pixel"), point_from(g, "gaze"));
          },
          py::arg("pixel"), py::arg("gaze"))
      .def(
          "kept",
          [](const CheckerboardPattern& c, py::handle p, py::handle g) {
            return c.kept(point_from(p, "pixel"), point_from(g, "gaze"));
          },
          py::arg("pixel"), py::arg("gaze"))
      .def(
          "tile_distance",
          [](const CheckerboardPattern& c, py::handle p, py::handle g) {
            return c.tile_distance(point_from(p, "pixel"), point_from(g, "gaze"));
          },
          py::arg("pixel"), py::arg("gaze"));
  m.def("checkerboard_sampling_factor", &checkerboard_sampling_factor, py::arg("region"));
  m.def("checkerboard_gap_px", &checkerboard_gap_px, py::arg("region"), py::arg("block"));
  m.def(
      "mar_px_at",
      [](py::handle display, const AcuityModel& acuity, double e) {
        return mar_px_at(display_from(display), acuity, e);
      },
      py::arg("display"), py::arg("acuity"), py::arg("eccentricity_deg"),
      "The MAR in pixels at eccentricity e for a gaze at the display centre");
}

}  // namespace

void bind_core(py::module_& m) {
  bind_acuity(m);
  bind_display(m);
  bind_planner(m);
  bind_models(m);
}

}  // namespace foveate::python
