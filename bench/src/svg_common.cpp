// What the SVG charts share (svg_common.hpp).
#include "svg_common.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "foveate/core/format.hpp"

namespace foveate::bench::svg {

namespace {

// "Nice" tick positions covering [lo, hi].
std::vector<double> nice_ticks(double lo, double hi, int target) {
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
  for (double v = std::ceil(lo / step - 1e-9) * step; v <= hi + 1e-9 * span; v += step)
    t.push_back(std::fabs(v) < 1e-12 * span ? 0.0 : v);
  return t;
}

// The y axis title's position: its baseline at x = 16, rotated, so its glyphs
// reach about 4 px right of it.
constexpr double kYTitleX = 16;
constexpr double kYTitleRight = kYTitleX + 4;

}  // namespace

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

std::string num(double v) { return format_significant(v, 3); }

double text_width(const std::string& text, double font_px) {
  double chars = 0;
  for (unsigned char c : text) chars += (c & 0xC0) != 0x80;  // UTF-8: count code points
  return chars * 0.6 * font_px;
}

Axis::Axis(const std::vector<double>& values, bool from_zero, int target) {
  double a = std::numeric_limits<double>::infinity(), b = -a;
  for (double v : values) {
    if (!std::isfinite(v)) continue;
    a = std::min(a, v);
    b = std::max(b, v);
  }
  if (!std::isfinite(a)) a = 0, b = 1;
  if (from_zero) a = std::min(a, 0.0), b = std::max(b, 0.0);
  if (b <= a) {
    const double pad = a == 0 ? 1 : 0.05 * std::fabs(a);
    a -= pad, b += pad;
  } else if (!from_zero) {
    const double pad = 0.08 * (b - a);
    a -= pad, b += pad;
  }
  ticks = nice_ticks(a, b, target);
  const double st = ticks.size() > 1 ? ticks[1] - ticks[0] : b - a;
  if (!from_zero || a < 0)
    lo = std::min(a, std::floor(a / st + 1e-9) * st);
  else
    lo = 0;
  hi = std::max(b, std::ceil(b / st - 1e-9) * st);
  ticks = nice_ticks(lo, hi, target);
}

std::string Axis::label(double v) const { return format_tick(v, step()); }

void header(std::ostringstream& s, int w, int h, const std::string& title) {
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << w << "\" height=\"" << h
    << "\" viewBox=\"0 0 " << w << ' ' << h
    << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" "
       "fill=\"white\"/>\n<text class=\"title\" x=\""
    << w / 2 << "\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">" << escape(title)
    << "</text>\n";
}

void x_ticks(std::ostringstream& s, const Axis& axis, double top, double ph,
             const std::function<double(double)>& px) {
  for (double v : axis.ticks) {
    s << "<line x1=\"" << px(v) << "\" y1=\"" << top << "\" x2=\"" << px(v) << "\" y2=\""
      << top + ph + 4 << "\" stroke=\"#e4e4e4\"/>\n<text class=\"tick\" x=\"" << px(v) << "\" y=\""
      << top + ph + 17 << "\" text-anchor=\"middle\">" << escape(axis.label(v)) << "</text>\n";
  }
}

void y_ticks(std::ostringstream& s, const std::vector<double>& ticks,
             const std::vector<std::string>& labels, double left, double pw,
             const std::function<double(double)>& py) {
  for (size_t i = 0; i < ticks.size() && i < labels.size(); ++i) {
    const double y = py(ticks[i]);
    s << "<line x1=\"" << left - 4 << "\" y1=\"" << y << "\" x2=\"" << left + pw << "\" y2=\"" << y
      << "\" stroke=\"#e4e4e4\"/>\n<text class=\"tick\" x=\"" << left - 6 << "\" y=\"" << y + 4
      << "\" text-anchor=\"end\">" << escape(labels[i]) << "</text>\n";
  }
}

double left_margin(const std::vector<std::string>& labels) {
  double widest = 0;
  for (const std::string& l : labels) widest = std::max(widest, text_width(l));
  return std::max(70.0, std::ceil(kYTitleRight + 8 + widest + 6));
}

void frame_and_labels(std::ostringstream& s, double left, double top, double pw, double ph,
                      int height, const std::string& x_label, const std::string& y_label) {
  s << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << pw << "\" height=\"" << ph
    << "\" fill=\"none\" stroke=\"#444\"/>\n";
  s << "<text class=\"axis-label\" x=\"" << left + pw / 2 << "\" y=\"" << height - 10
    << "\" text-anchor=\"middle\">" << escape(x_label) << "</text>\n";
  if (!y_label.empty()) {
    s << "<text class=\"axis-label\" transform=\"translate(" << kYTitleX << "," << top + ph / 2
      << ") rotate(-90)\" text-anchor=\"middle\">" << escape(y_label) << "</text>\n";
  }
}

}  // namespace foveate::bench::svg
