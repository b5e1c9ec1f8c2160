#pragma once
// Conversions between foveate's types and Python's: JSON values to Python
// objects, numpy arrays to images (with clear errors for a wrong shape or
// dtype), maps and images back to numpy, displays and points from Python.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "foveate/core/display.hpp"
#include "foveate/core/image.hpp"
#include "foveate/metrics/metrics.hpp"

namespace foveate::python {

namespace py = pybind11;

/// A JSON value as the Python object json.loads would give.
py::object to_python(const nlohmann::json& j);
/// A Python value (dict, list, numbers, strings) as JSON, through json.dumps.
nlohmann::json to_json_value(const py::handle& obj, const std::string& what);

/// An HxWx3 or HxWx4 numpy array of sRGB values, uint8 (0..255) or float
/// (0..1), as an RGBA image. Raises TypeError / ValueError naming `what`.
Image image_from_array(const py::handle& array, const std::string& what);
/// An image as an HxWx3 uint8 array (alpha dropped).
py::array_t<std::uint8_t> image_to_array(const Image& image);
/// A map as an HxW float32 array.
py::array_t<float> map_to_array(const metrics::Map& map);

/// A Display, or a preset name / JSON path as a str; resized to width x
/// height (same field of view) when both are > 0 and differ.
Display display_from(const py::handle& obj, int width = 0, int height = 0);
/// (x, y) from any sequence of two numbers; None gives `fallback`.
Vec2d point_from(const py::handle& obj, const std::string& what, Vec2d fallback = {});

/// Binds everything below into `m`, with foveate.Error.
void bind_module(py::module_& m);
void bind_core(py::module_& m);
void bind_metrics(py::module_& m);
void bind_bench(py::module_& m);

}  // namespace foveate::python
