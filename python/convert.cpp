#include "convert.hpp"

#include <cmath>
#include <cstring>
#include <sstream>

#include "foveate/core/error.hpp"

namespace foveate::python {

py::object to_python(const nlohmann::json& j) {
  switch (j.type()) {
    case nlohmann::json::value_t::null:
    case nlohmann::json::value_t::discarded:
      return py::none();
    case nlohmann::json::value_t::boolean:
      return py::bool_(j.get<bool>());
    case nlohmann::json::value_t::number_integer:
      return py::int_(j.get<std::int64_t>());
    case nlohmann::json::value_t::number_unsigned:
      return py::int_(j.get<std::uint64_t>());
    case nlohmann::json::value_t::number_float:
      return py::float_(j.get<double>());
    case nlohmann::json::value_t::string:
      return py::str(j.get<std::string>());
    case nlohmann::json::value_t::array: {
      py::list out;
      for (const nlohmann::json& v : j) out.append(to_python(v));
      return out;
    }
    case nlohmann::json::value_t::object: {
      py::dict out;
      for (const auto& [k, v] : j.items()) out[py::str(k)] = to_python(v);
      return out;
    }
    case nlohmann::json::value_t::binary:
      break;
  }
  throw Error("internal: binary JSON value");
}

nlohmann::json to_json_value(const py::handle& obj, const std::string& what) {
  std::string text;
  try {
    text = py::module_::import("json").attr("dumps")(obj).cast<std::string>();
  } catch (const py::error_already_set& e) {
    throw py::type_error(what + ": not representable as JSON: " + std::string(e.what()));
  }
  return nlohmann::json::parse(text);
}

namespace {

std::string shape_text(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) s += (i ? ", " : "") + std::to_string(a.shape(i));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

}  // namespace

Image image_from_array(const py::handle& obj, const std::string& what) {
  if (!py::isinstance<py::array>(obj)) {
    throw py::type_error(what + ": expected a numpy array of shape (H, W, 3) or (H, W, 4), got " +
                         std::string(py::str(py::type::handle_of(obj).attr("__name__"))));
  }
  const auto a = py::reinterpret_borrow<py::array>(obj);
  if (a.ndim() != 3 || (a.shape(2) != 3 && a.shape(2) != 4) || a.shape(0) < 1 || a.shape(1) < 1) {
    throw py::value_error(what + ": expected shape (H, W, 3) or (H, W, 4) (sRGB), got " +
                          shape_text(a));
  }
  const char kind = a.dtype().kind();
  const bool u8 = kind == 'u' && a.dtype().itemsize() == 1;
  if (!u8 && kind != 'f') {
    throw py::type_error(what + ": expected dtype uint8 (0..255) or float (0..1), got " +
                         std::string(py::str(a.dtype())));
  }
  const auto h = static_cast<int>(a.shape(0)), w = static_cast<int>(a.shape(1));
  const auto c = static_cast<size_t>(a.shape(2));
  Image img(w, h);
  const size_t n = static_cast<size_t>(w) * h;
  if (u8) {
    const auto v = py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>::ensure(a);
    const std::uint8_t* p = v.data();
    for (size_t i = 0; i < n; ++i) {
      for (size_t k = 0; k < 3; ++k) img.rgba[i * 4 + k] = p[i * c + k];
      img.rgba[i * 4 + 3] = 255;
    }
  } else {
    const auto v = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
    const double* p = v.data();
    for (size_t i = 0; i < n; ++i) {
      for (size_t k = 0; k < 3; ++k) {
        const double x = p[i * c + k];
        if (!(x >= 0.0 && x <= 1.0)) {
          std::ostringstream s;
          s << what << ": float values must be sRGB in [0, 1], got " << x << " at [" << i / w
            << ", " << i % w << ", " << k << "] (uint8 arrays hold 0..255)";
          throw py::value_error(s.str());
        }
        img.rgba[i * 4 + k] = static_cast<std::uint8_t>(std::lround(x * 255.0));
      }
      img.rgba[i * 4 + 3] = 255;
    }
  }
  return img;
}

py::array_t<std::uint8_t> image_to_array(const Image& image) {
  py::array_t<std::uint8_t> out({image.height, image.width, 3});
  std::uint8_t* p = out.mutable_data();
  const size_t n = static_cast<size_t>(image.width) * image.height;
  for (size_t i = 0; i < n; ++i) {
    for (size_t k = 0; k < 3; ++k) p[i * 3 + k] = image.rgba[i * 4 + k];
  }
  return out;
}

py::array_t<float> map_to_array(const metrics::Map& map) {
  py::array_t<float> out({map.height, map.width});
  std::memcpy(out.mutable_data(), map.values.data(), map.values.size() * sizeof(float));
  return out;
}

Display display_from(const py::handle& obj, int width, int height) {
  Display d;
  if (obj.is_none()) {
    d = Display::load("desktop-1080p");
  } else if (py::isinstance<py::str>(obj)) {
    d = Display::load(obj.cast<std::string>());
  } else if (py::isinstance<Display>(obj)) {
    d = obj.cast<Display>();
    d.validate();
  } else {
    throw py::type_error("display: expected a foveate.Display or a preset name / JSON path, got " +
                         std::string(py::str(py::type::handle_of(obj).attr("__name__"))));
  }
  if (width > 0 && height > 0 && (d.width_px != width || d.height_px != height))
    d = d.resized(width, height);
  return d;
}

Vec2d point_from(const py::handle& obj, const std::string& what, Vec2d fallback) {
  if (obj.is_none()) return fallback;
  if (!py::isinstance<py::sequence>(obj) || py::isinstance<py::str>(obj) || py::len(obj) != 2) {
    throw py::type_error(what + ": expected (x, y), got " + std::string(py::repr(obj)));
  }
  const auto s = py::reinterpret_borrow<py::sequence>(obj);
  Vec2d p;
  try {
    p = {s[0].cast<double>(), s[1].cast<double>()};
  } catch (const py::cast_error&) {
    throw py::type_error(what + ": expected two numbers, got " + std::string(py::repr(obj)));
  }
  if (!std::isfinite(p.x) || !std::isfinite(p.y))
    throw py::value_error(what + ": coordinates must be finite");
  return p;
}

}  // namespace foveate::python
