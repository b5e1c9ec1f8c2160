// The image metrics on numpy arrays: HxWx3 (or HxWx4, alpha ignored) sRGB,
// uint8 0..255 or float 0..1. Functions that need the geometry take a
// display (resized to the images' size, same field of view) and a gaze in
// pixels (None = the image centre).
#include <pybind11/stl.h>

#include <nlohmann/json.hpp>

#include "convert.hpp"
#include "foveate/core/error.hpp"
#include "foveate/metrics/fvvdp.hpp"
#include "foveate/metrics/metrics.hpp"

namespace foveate::python {

namespace {

struct Pair {
  Image reference, test;
};

Pair images(py::handle reference, py::handle test) {
  Pair p{image_from_array(reference, "reference"), image_from_array(test, "test")};
  if (p.reference.width != p.test.width || p.reference.height != p.test.height) {
    throw py::value_error("test: shape (" + std::to_string(p.test.height) + ", " +
                          std::to_string(p.test.width) + ") differs from the reference's (" +
                          std::to_string(p.reference.height) + ", " +
                          std::to_string(p.reference.width) + ")");
  }
  return p;
}

Vec2d gaze_of(py::handle gaze, const Image& image) {
  return point_from(gaze, "gaze", {image.width / 2.0, image.height / 2.0});
}

metrics::QualityOptions quality_options(const AcuityModel& acuity, bool flip,
                                        std::vector<double> edges) {
  metrics::QualityOptions o;
  o.acuity = acuity;
  o.flip = flip;
  o.band_edges_deg = std::move(edges);
  return o;
}

// The frames of an image (HxWxC) or a sequence (FxHxWxC) array.
std::vector<Image> frames_of(py::handle array, const std::string& what) {
  const auto a = py::array::ensure(array);
  if (!a) throw py::type_error(what + ": expected a numpy array");
  if (a.ndim() == 3) return {image_from_array(a, what)};
  if (a.ndim() != 4) {
    throw py::value_error(what +
                          ": expected HxWx3 or HxWx4 (an image) or FxHxWx3 or FxHxWx4 "
                          "(a sequence), got " +
                          std::to_string(a.ndim()) + " dimensions");
  }
  std::vector<Image> out;
  for (py::ssize_t f = 0; f < a.shape(0); ++f) {
    out.push_back(image_from_array(a[py::int_(f)], what + "[" + std::to_string(f) + "]"));
  }
  return out;
}

py::dict fvvdp(py::handle test, py::handle reference, py::handle display, py::handle gaze,
               double fps, bool foveated, bool heatmap, std::vector<double> band_edges_deg) {
  const std::vector<Image> tests = frames_of(test, "test"),
                           refs = frames_of(reference, "reference");
  if (tests.size() != refs.size()) {
    throw py::value_error("test has " + std::to_string(tests.size()) + " frames, reference " +
                          std::to_string(refs.size()));
  }
  const Image& first = refs[0];
  for (size_t f = 0; f < tests.size(); ++f) {
    for (const Image* img : {&tests[f], &refs[f]}) {
      if (img->width != first.width || img->height != first.height) {
        throw py::value_error(
            "frame " + std::to_string(f) + ": shape (" + std::to_string(img->height) + ", " +
            std::to_string(img->width) + ") differs from the reference's first frame's (" +
            std::to_string(first.height) + ", " + std::to_string(first.width) + ")");
      }
    }
  }
  // The gaze: None (the centre), one point, or one point per frame.
  std::vector<Vec2d> gazes;
  const Vec2d centre{first.width / 2.0, first.height / 2.0};
  const auto points = py::array::ensure(gaze);
  if (!gaze.is_none() && points && points.ndim() == 2) {
    if (static_cast<size_t>(points.shape(0)) != tests.size() || points.shape(1) != 2) {
      throw py::value_error("gaze: expected (x, y) or an array of shape (" +
                            std::to_string(tests.size()) + ", 2), one point per frame");
    }
    for (py::ssize_t f = 0; f < points.shape(0); ++f) {
      gazes.push_back(point_from(points[py::int_(f)], "gaze[" + std::to_string(f) + "]"));
    }
  } else {
    gazes.assign(tests.size(), point_from(gaze, "gaze", centre));
  }
  metrics::FvvdpOptions o;
  o.fps = fps;
  o.foveated = foveated;
  o.heatmap = heatmap;
  o.band_edges_deg = std::move(band_edges_deg);
  metrics::Fvvdp metric(display_from(display, first.width, first.height), o);
  for (size_t f = 0; f < tests.size(); ++f) metric.add(tests[f], refs[f], gazes[f]);
  const metrics::FvvdpResult r = metric.result();
  py::dict out = to_python(metrics::to_json(r));
  if (heatmap) {
    out["heatmap"] = map_to_array(r.heatmap);
    out["worst_heatmap"] = map_to_array(r.worst_heatmap);
    out["worst_frame"] = r.worst_frame;
  }
  return out;
}

// Per-pixel and whole-image measures of two images: MSE, PSNR, SSIM and its
// map, luminance codes.
void bind_pixel_metrics(py::module_& m) {
  m.def(
      "mse",
      [](py::handle r, py::handle t) {
        const Pair p = images(r, t);
        return metrics::mse(p.reference, p.test);
      },
      py::arg("reference"), py::arg("test"), "Mean squared error over R, G, B in 8-bit codes");
  m.def(
      "psnr",
      [](py::handle r, py::handle t) {
        const Pair p = images(r, t);
        return metrics::psnr_db(p.reference, p.test);
      },
      py::arg("reference"), py::arg("test"), "PSNR in dB (inf for identical images)");
  m.def(
      "ssim",
      [](py::handle r, py::handle t) {
        const Pair p = images(r, t);
        return metrics::ssim(p.reference, p.test);
      },
      py::arg("reference"), py::arg("test"),
      "Mean SSIM of the luminance codes (Wang et al. 2004: 11x11 Gaussian, sigma 1.5)");
  m.def(
      "ssim_map",
      [](py::handle r, py::handle t) {
        const Pair p = images(r, t);
        return map_to_array(metrics::ssim_map(p.reference, p.test));
      },
      py::arg("reference"), py::arg("test"), "Per-pixel SSIM, HxW float32");
  m.def(
      "luminance_codes",
      [](py::handle img) {
        return map_to_array(metrics::luminance_codes(image_from_array(img, "image")));
      },
      py::arg("image"), "CIE Y re-encoded with the sRGB curve to 0..255, HxW float32");
}

// Maps and models of what the eye sees: eccentricity, the acuity filter, JND,
// FLIP, Barten's CSF.
void bind_perception(py::module_& m) {
  m.def(
      "eccentricity_map",
      [](py::handle display, int width, int height, py::handle gaze) {
        if (width < 1 || height < 1) throw py::value_error("width, height: must be >= 1");
        const Vec2d g = point_from(gaze, "gaze", {width / 2.0, height / 2.0});
        return map_to_array(metrics::eccentricity_map(display_from(display, width, height), g));
      },
      py::arg("display"), py::arg("width"), py::arg("height"), py::arg("gaze") = py::none(),
      "Eccentricity (degrees) of every pixel centre, HxW float32");
  m.def(
      "acuity_filtered",
      [](py::handle img, py::handle display, py::handle gaze, const AcuityModel& acuity) {
        const Image i = image_from_array(img, "image");
        return map_to_array(metrics::acuity_filtered(i, display_from(display, i.width, i.height),
                                                     gaze_of(gaze, i), acuity));
      },
      py::arg("image"), py::arg("display") = "desktop-1080p", py::arg("gaze") = py::none(),
      py::arg("acuity") = AcuityModel{},
      "The image's luminance low-passed per pixel to what the eye resolves there (codes)");
  m.def(
      "acuity_difference",
      [](py::handle r, py::handle t, py::handle display, py::handle gaze,
         const AcuityModel& acuity) {
        const Pair p = images(r, t);
        return map_to_array(metrics::acuity_difference(
            p.reference, p.test, display_from(display, p.test.width, p.test.height),
            gaze_of(gaze, p.test), acuity));
      },
      py::arg("reference"), py::arg("test"), py::arg("display") = "desktop-1080p",
      py::arg("gaze") = py::none(), py::arg("acuity") = AcuityModel{},
      "acuity_filtered(reference) - acuity_filtered(test), HxW float32 (codes)");
  m.def(
      "jnd_map",
      [](py::handle r, py::handle t, py::handle display, py::handle gaze,
         const AcuityModel& acuity) {
        const Pair p = images(r, t);
        return map_to_array(metrics::jnd_map(
            p.reference, p.test, display_from(display, p.test.width, p.test.height),
            gaze_of(gaze, p.test), quality_options(acuity, false, {0, 5, 10, 20})));
      },
      py::arg("reference"), py::arg("test"), py::arg("display") = "desktop-1080p",
      py::arg("gaze") = py::none(), py::arg("acuity") = AcuityModel{},
      "Visibility of the difference in JND (Barten's CSF on band-limited contrast), HxW");
  m.def(
      "flip_map",
      [](py::handle r, py::handle t, double ppd) {
        if (!(ppd > 0)) throw py::value_error("pixels_per_degree: must be > 0");
        const Pair p = images(r, t);
        return map_to_array(metrics::flip_map(p.reference, p.test, ppd));
      },
      py::arg("reference"), py::arg("test"), py::arg("pixels_per_degree"),
      "Per-pixel LDR-FLIP in [0, 1]");
  m.def("barten_csf", py::vectorize(&metrics::barten_csf), py::arg("u_cpd"),
        py::arg("luminance_cd_m2") = 100.0, py::arg("field_deg") = 10.0,
        "Barten's contrast sensitivity at u cycles per degree");
  m.def("acuity_response", &metrics::acuity_response, py::arg("frequency"), py::arg("cutoff"),
        "The acuity filter's response to a grating (both in cycles per pixel)");
}

}  // namespace

void bind_metrics(py::module_& m) {
  m.def("fvvdp", &fvvdp, py::arg("test"), py::arg("reference"),
        py::arg("display") = "desktop-1080p", py::arg("gaze") = py::none(), py::arg("fps") = 60.0,
        py::arg("foveated") = true, py::arg("heatmap") = false,
        py::arg("band_edges_deg") = std::vector<double>{0, 5, 10, 20},
        "FovVideoVDP (Mantiuk et al. 2021, v1.2): how visible test's difference from reference "
        "is, in JOD (10 = none; 1 JOD apart = 75 % prefer the higher). test and reference: "
        "HxWx3/4 images or FxHxWx3/4 sequences (uint8 sRGB or float 0..1); display: a Display "
        "or preset name (its photometry and field of view, resized to the frames); gaze: None "
        "(centre), (x, y) in pixels, or an (F, 2) array per frame; fps: the sequence's frame "
        "rate. Returns a dict: 'jod', 'bands' (JOD per eccentricity band), 'frame_jod', "
        "'photometry', ... and with heatmap=True the distortion maps (HxW float32, JOD).");
  bind_pixel_metrics(m);
  bind_perception(m);
  m.def(
      "compare",
      [](py::handle r, py::handle t, py::handle display, py::handle gaze, const AcuityModel& acuity,
         bool flip, std::vector<double> band_edges_deg) {
        const Pair p = images(r, t);
        const metrics::QualityReport q = metrics::compare(
            p.reference, p.test, display_from(display, p.test.width, p.test.height),
            gaze_of(gaze, p.test), quality_options(acuity, flip, std::move(band_edges_deg)));
        return to_python(metrics::to_json(q));
      },
      py::arg("reference"), py::arg("test"), py::arg("display") = "desktop-1080p",
      py::arg("gaze") = py::none(), py::arg("acuity") = AcuityModel{}, py::arg("flip") = true,
      py::arg("band_edges_deg") = std::vector<double>{0, 5, 10, 20},
      "Every metric of `foveate compare` as a dict (keys: docs/bench-json.md): psnr_db, ssim, "
      "acuity_rmse, jnd_mean, visible_fraction, luminance_ratio, flip_mean, bands, "
      "eccentricity_profile, ... (null where undefined, psnr_db null with identical true)");
}

}  // namespace foveate::python
