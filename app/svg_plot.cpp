#include "svg_plot.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace foveate::app {

namespace {
std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '&':
        out += "&amp;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string num(double v) {
  std::ostringstream s;
  s.precision(4);
  s << v;
  return s.str();
}

// "Nice" tick positions covering [lo, hi].
std::vector<double> ticks(double lo, double hi, int target) {
  const double span = hi - lo;
  if (!(span > 0)) return {lo};
  const double raw = span / target;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  double step = mag;
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    step = m * mag;
    if (step >= raw) break;
  }
  std::vector<double> t;
  for (double v = std::ceil(lo / step) * step; v <= hi + 1e-9 * span; v += step) t.push_back(v);
  return t;
}
}  // namespace

std::string svg_line_chart(const std::vector<Series>& series, const ChartOptions& o) {
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
  auto ty = [&](double y) { return o.log_y ? std::log10(std::max(y, 1e-12)) : y; };
  for (const Series& s : series) {
    for (size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
      x0 = std::min(x0, s.x[i]);
      x1 = std::max(x1, s.x[i]);
      y0 = std::min(y0, ty(s.y[i]));
      y1 = std::max(y1, ty(s.y[i]));
    }
  }
  if (!std::isfinite(x0)) x0 = 0, x1 = 1, y0 = 0, y1 = 1;
  if (x1 <= x0) x1 = x0 + 1;
  if (o.log_y) {
    y0 = std::floor(y0);
    y1 = std::ceil(y1);
  } else {
    y0 = std::min(y0, 0.0);
    y1 = y1 + 0.05 * (y1 - y0);
  }
  if (y1 <= y0) y1 = y0 + 1;
  const double left = 70, right = 170, top = 40, bottom = 55;
  const double pw = o.width - left - right, ph = o.height - top - bottom;
  auto px = [&](double x) { return left + (x - x0) / (x1 - x0) * pw; };
  auto py = [&](double y) { return top + ph - (ty(y) - y0) / (y1 - y0) * ph; };
  auto pyt = [&](double t) { return top + ph - (t - y0) / (y1 - y0) * ph; };

  std::ostringstream s;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << o.width << "\" height=\"" << o.height
    << "\" viewBox=\"0 0 " << o.width << ' ' << o.height
    << "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  s << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  s << "<text x=\"" << o.width / 2 << "\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">"
    << escape(o.title) << "</text>\n";
  for (double t : ticks(x0, x1, 8)) {
    s << "<line x1=\"" << px(t) << "\" y1=\"" << top << "\" x2=\"" << px(t) << "\" y2=\""
      << top + ph << "\" stroke=\"#e4e4e4\"/>\n<text x=\"" << px(t) << "\" y=\"" << top + ph + 16
      << "\" text-anchor=\"middle\">" << num(t) << "</text>\n";
  }
  std::vector<double> yt;
  if (o.log_y) {
    for (double e = y0; e <= y1 + 1e-9; e += 1) yt.push_back(e);
  } else {
    yt = ticks(y0, y1, 6);
  }
  for (double t : yt) {
    s << "<line x1=\"" << left << "\" y1=\"" << pyt(t) << "\" x2=\"" << left + pw << "\" y2=\""
      << pyt(t) << "\" stroke=\"#e4e4e4\"/>\n<text x=\"" << left - 6 << "\" y=\"" << pyt(t) + 4
      << "\" text-anchor=\"end\">" << num(o.log_y ? std::pow(10.0, t) : t) << "</text>\n";
  }
  s << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << pw << "\" height=\"" << ph
    << "\" fill=\"none\" stroke=\"#444\"/>\n";
  s << "<text x=\"" << left + pw / 2 << "\" y=\"" << o.height - 12 << "\" text-anchor=\"middle\">"
    << escape(o.x_label) << "</text>\n";
  s << "<text transform=\"translate(16," << top + ph / 2
    << ") rotate(-90)\" text-anchor=\"middle\">" << escape(o.y_label) << "</text>\n";
  int row = 0;
  for (const Series& se : series) {
    std::ostringstream pts;
    for (size_t i = 0; i < se.x.size() && i < se.y.size(); ++i) {
      if (std::isfinite(se.x[i]) && std::isfinite(se.y[i]))
        pts << px(se.x[i]) << ',' << py(se.y[i]) << ' ';
    }
    s << "<polyline fill=\"none\" stroke=\"" << se.color << "\" stroke-width=\"2\""
      << (se.dashed ? " stroke-dasharray=\"6 4\"" : "") << " points=\"" << pts.str() << "\"/>\n";
    const double ly = top + 10 + 18 * row++;
    s << "<line x1=\"" << left + pw + 12 << "\" y1=\"" << ly << "\" x2=\"" << left + pw + 36
      << "\" y2=\"" << ly << "\" stroke=\"" << se.color << "\" stroke-width=\"2\""
      << (se.dashed ? " stroke-dasharray=\"6 4\"" : "") << "/>\n<text x=\"" << left + pw + 42
      << "\" y=\"" << ly + 4 << "\">" << escape(se.name) << "</text>\n";
  }
  s << "</svg>\n";
  return s.str();
}

}  // namespace foveate::app
