#include "report_media.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>

#include "cli_util.hpp"

namespace foveate::app {

std::string base64(const std::string& in) {
  static const char* t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((in.size() + 2) / 3 * 4);
  size_t i = 0;
  for (; i + 2 < in.size(); i += 3) {
    const unsigned v =
        (unsigned(uint8_t(in[i])) << 16) | (unsigned(uint8_t(in[i + 1])) << 8) | uint8_t(in[i + 2]);
    out += t[v >> 18], out += t[(v >> 12) & 63], out += t[(v >> 6) & 63], out += t[v & 63];
  }
  if (i < in.size()) {
    unsigned v = unsigned(uint8_t(in[i])) << 16;
    if (i + 1 < in.size()) v |= unsigned(uint8_t(in[i + 1])) << 8;
    out += t[v >> 18], out += t[(v >> 12) & 63];
    out += i + 1 < in.size() ? t[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

Image crop(const Image& img, int cx, int cy, int size) {
  size = std::min({size, img.width, img.height});
  const int x0 = std::clamp(cx - size / 2, 0, img.width - size);
  const int y0 = std::clamp(cy - size / 2, 0, img.height - size);
  Image out(size, size);
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) std::copy_n(img.at(x0 + x, y0 + y), 4, out.at(x, y));
  }
  return out;
}

Worst worst_window(const metrics::Map& error, const Display& display, Vec2d gaze, int size,
                   double min_ecc) {
  const int w = error.width, h = error.height;
  size = std::min({size, w, h});
  // Summed-area table of |error|.
  std::vector<double> sat(static_cast<size_t>(w + 1) * (h + 1), 0.0);
  for (int y = 0; y < h; ++y) {
    double row = 0;
    for (int x = 0; x < w; ++x) {
      row += std::fabs(double(error.at(x, y)));
      sat[static_cast<size_t>(y + 1) * (w + 1) + x + 1] =
          sat[static_cast<size_t>(y) * (w + 1) + x + 1] + row;
    }
  }
  auto sum = [&](int x0, int y0) {
    const int x1 = x0 + size, y1 = y0 + size;
    auto at = [&](int x, int y) { return sat[static_cast<size_t>(y) * (w + 1) + x]; };
    return at(x1, y1) - at(x0, y1) - at(x1, y0) + at(x0, y0);
  };
  const int step = std::max(1, size / 4);
  Worst best, best_any;
  bool found = false;
  best_any.mean_error = best.mean_error = -1;
  for (int y0 = 0;; y0 = std::min(y0 + step, h - size)) {
    for (int x0 = 0;; x0 = std::min(x0 + step, w - size)) {
      const double m = sum(x0, y0) / (double(size) * size);
      const int cx = x0 + size / 2, cy = y0 + size / 2;
      const double e = display.eccentricity_deg({cx + 0.5, cy + 0.5}, gaze);
      if (m > best_any.mean_error) best_any = {cx, cy, m, e};
      if (e >= min_ecc && m > best.mean_error) best = {cx, cy, m, e}, found = true;
      if (x0 == w - size) break;
    }
    if (y0 == h - size) break;
  }
  return found ? best : best_any;
}

std::string img_tag(const Image& img, const std::string& alt, int display_width) {
  if (img.empty()) return "<span class=missing>(no image)</span>";
  return "<img alt=\"" + alt + "\" width=\"" + std::to_string(display_width) +
         "\" src=\"data:image/png;base64," + base64(encode_png(img)) + "\">";
}

std::string bar_chart(const std::vector<std::string>& names, const std::vector<double>& a,
                      const std::vector<double>& b, const std::string& a_name,
                      const std::string& b_name, const std::string& title) {
  const int w = 720, row = 34, top = 40, left = 200;
  const int h = top + row * static_cast<int>(names.size()) + 30;
  double mx = 1e-9;
  for (double v : a) mx = std::max(mx, std::isfinite(v) ? v : 0.0);
  for (double v : b) mx = std::max(mx, std::isfinite(v) ? v : 0.0);
  const double scale = (w - left - 80) / mx;
  std::ostringstream s;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << w << "\" height=\"" << h
    << "\" font-family=\"sans-serif\" font-size=\"12\"><rect width=\"100%\" height=\"100%\" "
       "fill=\"white\"/>"
    << "<text x=\"" << w / 2 << "\" y=\"20\" text-anchor=\"middle\" font-size=\"14\">" << title
    << "</text>";
  for (size_t i = 0; i < names.size(); ++i) {
    const int y = top + row * static_cast<int>(i);
    const double va = std::isfinite(a[i]) ? a[i] : 0.0,
                 vb = i < b.size() && std::isfinite(b[i]) ? b[i] : 0.0;
    s << "<text x=\"" << left - 8 << "\" y=\"" << y + 16 << "\" text-anchor=\"end\">" << names[i]
      << "</text>";
    s << "<rect class=\"bar\" x=\"" << left << "\" y=\"" << y + 2 << "\" width=\"" << va * scale
      << "\" height=\"13\" fill=\"#1f77b4\"/><text x=\"" << left + va * scale + 4 << "\" y=\""
      << y + 13 << "\">" << fmt(va, 2) << "</text>";
    if (!b.empty()) {
      s << "<rect class=\"bar\" x=\"" << left << "\" y=\"" << y + 16 << "\" width=\"" << vb * scale
        << "\" height=\"13\" fill=\"#ff7f0e\"/><text x=\"" << left + vb * scale + 4 << "\" y=\""
        << y + 27 << "\">" << fmt(vb, 2) << "</text>";
    }
  }
  const int ly = h - 14;
  s << "<rect x=\"" << left << "\" y=\"" << ly - 9
    << "\" width=\"12\" height=\"10\" fill=\"#1f77b4\"/><text x=\"" << left + 16 << "\" y=\"" << ly
    << "\">" << a_name << "</text>";
  if (!b.empty()) {
    s << "<rect x=\"" << left + 260 << "\" y=\"" << ly - 9
      << "\" width=\"12\" height=\"10\" fill=\"#ff7f0e\"/><text x=\"" << left + 276 << "\" y=\""
      << ly << "\">" << b_name << "</text>";
  }
  s << "</svg>";
  return s.str();
}

}  // namespace foveate::app
