#include "report_media.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <sstream>

#include "foveate/core/format.hpp"
#include "foveate/core/parse.hpp"
#include "foveate/techniques/palette.hpp"

namespace foveate::bench {

namespace {

std::string shape_colour(const OverlayShape& o) {
  char colour[32];
  std::snprintf(colour, sizeof colour, "rgb(%d,%d,%d)", int(std::lround(o.r * 255)),
                int(std::lround(o.g * 255)), int(std::lround(o.b * 255)));
  return colour;
}

}  // namespace

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

std::string img_tag(const Image& img, const std::string& alt, int display_width, int max_width) {
  if (img.empty()) return "<span class=missing>(no image)</span>";
  const Image small = max_width > 0 ? downscale(img, max_width) : img;
  return "<img alt=\"" + alt + "\" width=\"" + std::to_string(display_width) +
         "\" src=\"data:image/png;base64," + base64(encode_png(small)) + "\">";
}

std::string colour_bar(double max, const std::string& unit, const std::string& id, int width) {
  std::ostringstream s;
  const int h = 44, left = 10, bar_w = width - 20;
  s << "<svg class=\"colourbar\" xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width
    << "\" height=\"" << h
    << "\" font-family=\"sans-serif\" font-size=\"11\"><defs><linearGradient id=\"" << id << "\">";
  for (int i = 0; i <= 8; ++i) {
    std::uint8_t c[3];
    metrics::heat_color(i / 8.0, c);
    s << "<stop offset=\"" << i / 8.0 << "\" stop-color=\"rgb(" << int(c[0]) << ',' << int(c[1])
      << ',' << int(c[2]) << ")\"/>";
  }
  s << "</linearGradient></defs><rect x=\"" << left << "\" y=\"2\" width=\"" << bar_w
    << "\" height=\"12\" fill=\"url(#" << id << ")\" stroke=\"#444\"/>";
  for (int i = 0; i <= 4; ++i) {
    const double x = left + bar_w * i / 4.0;
    s << "<line x1=\"" << x << "\" y1=\"14\" x2=\"" << x << "\" y2=\"18\" stroke=\"#444\"/><text "
      << "class=\"tick\" x=\"" << x << "\" y=\"29\" text-anchor=\"middle\">"
      << format_significant(max * i / 4.0, 2) << (i == 4 ? "+" : "") << "</text>";
  }
  s << "<text x=\"" << width / 2 << "\" y=\"" << h - 3 << "\" text-anchor=\"middle\">" << unit
    << "</text></svg>";
  return s.str();
}

std::string overlay_figure(const Image& frame, const std::vector<OverlayShape>& shapes,
                           const std::string& alt, int display_width) {
  if (frame.empty()) return "<span class=missing>(no image)</span>";
  const int w = frame.width, h = frame.height;
  const Image small = downscale(frame, display_width);
  std::ostringstream s;
  s << "<svg class=\"overlay\" xmlns=\"http://www.w3.org/2000/svg\" width=\"" << display_width
    << "\" height=\"" << display_width * h / std::max(w, 1) << "\" viewBox=\"0 0 " << w << ' ' << h
    << "\"><title>" << alt << "</title><image width=\"" << w << "\" height=\"" << h
    << "\" href=\"data:image/png;base64," << base64(encode_png(small)) << "\"/>";
  const double stroke = std::max(1.5, w / 240.0);  // about 2 px on the page
  for (const OverlayShape& o : shapes) {
    const std::string colour = shape_colour(o);
    if (o.kind == OverlayShape::Kind::Rect) {
      s << "<rect class=\"shape\" x=\"" << o.x << "\" y=\"" << o.y << "\" width=\"" << o.w
        << "\" height=\"" << o.h << "\"";
    } else {
      s << "<circle class=\"shape\" cx=\"" << o.x << "\" cy=\"" << o.y << "\" r=\""
        << (o.kind == OverlayShape::Kind::Dot ? std::max(o.w, 2 * stroke) : o.w) << "\"";
    }
    s << (o.kind == OverlayShape::Kind::Dot
              ? " fill=\"" + colour + "\""
              : " fill=\"none\" stroke=\"" + colour + "\" stroke-width=\"" +
                    format_fixed(stroke, 1) + "\"")
      << "/>";
  }
  s << "</svg><ul class=\"legend\">";
  for (const OverlayShape& o : overlay_legend(shapes)) {
    // The swatch is the shape itself: a layer's target (a rectangle) and its
    // blend ring (a circle) share a colour.
    const std::string colour = shape_colour(o);
    s << "<li><svg class=\"swatch\" width=\"16\" height=\"12\">";
    if (o.kind == OverlayShape::Kind::Rect) {
      s << "<rect x=\"1.5\" y=\"1.5\" width=\"13\" height=\"9\" fill=\"none\" stroke=\"" << colour
        << "\" stroke-width=\"2\"/>";
    } else if (o.kind == OverlayShape::Kind::Circle) {
      s << "<circle cx=\"8\" cy=\"6\" r=\"4.5\" fill=\"none\" stroke=\"" << colour
        << "\" stroke-width=\"2\"/>";
    } else {
      s << "<circle cx=\"8\" cy=\"6\" r=\"3.5\" fill=\"" << colour << "\"/>";
    }
    s << "</svg>" << (o.label.empty() ? "(unlabelled)" : o.label) << "</li>";
  }
  s << "</ul>";
  return s.str();
}

}  // namespace foveate::bench
