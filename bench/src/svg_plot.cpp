#include "foveate/bench/svg_plot.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <sstream>

#include "foveate/core/parse.hpp"
#include "foveate/core/stats.hpp"

namespace foveate::bench {

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

std::string num(double v) { return format_number(v, 4); }

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
  for (double v = std::ceil(lo / step - 1e-9) * step; v <= hi + 1e-9 * span; v += step)
    t.push_back(std::fabs(v) < 1e-12 * span ? 0.0 : v);
  return t;
}

// A linear axis over the finite values, widened to nice ticks.
struct Axis {
  double lo = 0, hi = 1;
  std::vector<double> ticks;
  Axis(std::vector<double> values, bool from_zero, int target) {
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
    ticks = foveate::bench::ticks(a, b, target);
    const double step = ticks.size() > 1 ? ticks[1] - ticks[0] : b - a;
    if (!from_zero || a < 0)
      lo = std::min(a, std::floor(a / step + 1e-9) * step);
    else
      lo = 0;
    hi = std::max(b, std::ceil(b / step - 1e-9) * step);
    ticks = foveate::bench::ticks(lo, hi, target);
  }
  [[nodiscard]] double at(double v, double p0, double p1) const {
    return p0 + (v - lo) / (hi - lo) * (p1 - p0);
  }
};

std::string header(std::ostringstream& s, int w, int h, const std::string& title) {
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << w << "\" height=\"" << h
    << "\" viewBox=\"0 0 " << w << ' ' << h
    << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" "
       "fill=\"white\"/>\n<text x=\""
    << w / 2 << "\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">" << escape(title)
    << "</text>\n";
  return {};
}

// Grid lines and tick labels of an x axis (bottom) and a y axis (left).
void x_ticks(std::ostringstream& s, const std::vector<double>& t, double left, double top,
             double pw, double ph, const std::function<double(double)>& px) {
  (void)left;
  (void)pw;
  for (double v : t) {
    s << "<line x1=\"" << px(v) << "\" y1=\"" << top << "\" x2=\"" << px(v) << "\" y2=\""
      << top + ph + 4 << "\" stroke=\"#e4e4e4\"/>\n<text class=\"tick\" x=\"" << px(v) << "\" y=\""
      << top + ph + 17 << "\" text-anchor=\"middle\">" << num(v) << "</text>\n";
  }
}

void frame_and_labels(std::ostringstream& s, double left, double top, double pw, double ph,
                      int height, const std::string& x_label, const std::string& y_label) {
  s << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << pw << "\" height=\"" << ph
    << "\" fill=\"none\" stroke=\"#444\"/>\n";
  s << "<text class=\"axis-label\" x=\"" << left + pw / 2 << "\" y=\"" << height - 10
    << "\" text-anchor=\"middle\">" << escape(x_label) << "</text>\n";
  if (!y_label.empty()) {
    s << "<text class=\"axis-label\" transform=\"translate(16," << top + ph / 2
      << ") rotate(-90)\" text-anchor=\"middle\">" << escape(y_label) << "</text>\n";
  }
}
}  // namespace

std::string svg_line_chart(const std::vector<Series>& series, const ChartOptions& o) {
  std::vector<double> xs, ys;
  auto ty = [&](double y) { return o.log_y ? std::log10(std::max(y, 1e-12)) : y; };
  for (const Series& se : series) {
    for (size_t i = 0; i < se.x.size() && i < se.y.size(); ++i) {
      if (!std::isfinite(se.x[i]) || !std::isfinite(se.y[i])) continue;
      xs.push_back(se.x[i]);
      ys.push_back(ty(se.y[i]));
    }
  }
  const Axis ax(xs, false, 8);
  Axis ay(ys, o.y_from_zero && !o.log_y, 6);
  if (o.log_y) {
    ay.lo = std::floor(ay.lo), ay.hi = std::ceil(ay.hi);
    if (ay.hi <= ay.lo) ay.hi = ay.lo + 1;
    ay.ticks.clear();
    for (double e = ay.lo; e <= ay.hi + 1e-9; e += 1) ay.ticks.push_back(e);
  }
  const double left = 70, right = 170, top = 40, bottom = 55;
  const double pw = o.width - left - right, ph = o.height - top - bottom;
  auto px = [&](double x) { return ax.at(x, left, left + pw); };
  auto py = [&](double y) { return ay.at(ty(y), top + ph, top); };
  std::ostringstream s;
  header(s, o.width, o.height, o.title);
  x_ticks(s, ax.ticks, left, top, pw, ph, px);
  for (double t : ay.ticks) {
    const double y = ay.at(t, top + ph, top);
    s << "<line x1=\"" << left - 4 << "\" y1=\"" << y << "\" x2=\"" << left + pw << "\" y2=\"" << y
      << "\" stroke=\"#e4e4e4\"/>\n<text class=\"tick\" x=\"" << left - 6 << "\" y=\"" << y + 4
      << "\" text-anchor=\"end\">" << num(o.log_y ? std::pow(10.0, t) : t) << "</text>\n";
  }
  frame_and_labels(s, left, top, pw, ph, o.height, o.x_label, o.y_label);
  int row = 0;
  for (const Series& se : series) {
    std::vector<std::pair<double, double>> pts;
    for (size_t i = 0; i < se.x.size() && i < se.y.size(); ++i) {
      if (std::isfinite(se.x[i]) && std::isfinite(se.y[i])) pts.emplace_back(se.x[i], se.y[i]);
    }
    std::stable_sort(pts.begin(), pts.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    std::ostringstream line;
    for (const auto& [x, y] : pts) line << px(x) << ',' << py(y) << ' ';
    s << "<polyline class=\"line\" fill=\"none\" stroke=\"" << se.color << "\" stroke-width=\"2\""
      << (se.dashed ? " stroke-dasharray=\"6 4\"" : "") << " points=\"" << line.str() << "\"/>\n";
    if (pts.size() <= 80) {
      for (const auto& [x, y] : pts) {
        s << "<circle class=\"point\" cx=\"" << px(x) << "\" cy=\"" << py(y) << "\" r=\"3\" fill=\""
          << se.color << "\"><title>" << escape(se.name) << ": " << num(x) << ", " << num(y)
          << "</title></circle>\n";
      }
    }
    const double ly = top + 10 + 18 * row++;
    s << "<line x1=\"" << left + pw + 12 << "\" y1=\"" << ly << "\" x2=\"" << left + pw + 36
      << "\" y2=\"" << ly << "\" stroke=\"" << se.color << "\" stroke-width=\"2\""
      << (se.dashed ? " stroke-dasharray=\"6 4\"" : "") << "/>\n<text x=\"" << left + pw + 42
      << "\" y=\"" << ly + 4 << "\">" << escape(se.name) << "</text>\n";
  }
  s << "</svg>\n";
  return s.str();
}

std::string svg_bar_chart(const std::vector<std::string>& rows,
                          const std::vector<BarSeries>& series, const BarChartOptions& o) {
  std::vector<double> all;
  for (const BarSeries& b : series) {
    all.insert(all.end(), b.values.begin(), b.values.end());
    all.insert(all.end(), b.lo.begin(), b.lo.end());
    all.insert(all.end(), b.hi.begin(), b.hi.end());
  }
  const Axis ax(all, o.from_zero, 7);
  const double left = 210, right = 60, top = 40, bar = 14;
  const double row_h = std::max(24.0, bar * double(series.size()) + 10);
  const double ph = row_h * double(rows.size());
  const int legend = series.size() > 1 ? 22 : 0;
  const int height = static_cast<int>(top + ph + 45 + legend);
  const double pw = o.width - left - right;
  auto px = [&](double v) { return ax.at(std::clamp(v, ax.lo, ax.hi), left, left + pw); };
  std::ostringstream s;
  header(s, o.width, height, o.title);
  x_ticks(s, ax.ticks, left, top, pw, ph, px);
  frame_and_labels(s, left, top, pw, ph, height - legend, o.value_label, "");
  const double base = px(o.from_zero ? std::max(0.0, ax.lo) : ax.lo);
  for (size_t i = 0; i < rows.size(); ++i) {
    const double y0 = top + row_h * double(i) + (row_h - bar * double(series.size())) / 2;
    s << "<text x=\"" << left - 8 << "\" y=\"" << top + row_h * (double(i) + 0.5) + 4
      << "\" text-anchor=\"end\">" << escape(rows[i]) << "</text>\n";
    for (size_t k = 0; k < series.size(); ++k) {
      const BarSeries& b = series[k];
      if (i >= b.values.size() || !std::isfinite(b.values[i])) continue;
      const double y = y0 + bar * double(k), v = px(b.values[i]);
      s << "<rect class=\"bar\" x=\"" << std::min(base, v) << "\" y=\"" << y + 1 << "\" width=\""
        << std::fabs(v - base) << "\" height=\"" << bar - 2 << "\" fill=\"" << b.color
        << "\"><title>" << escape(rows[i]) << ": " << num(b.values[i]) << "</title></rect>\n";
      double end = v;
      if (i < b.lo.size() && i < b.hi.size() && std::isfinite(b.lo[i]) && std::isfinite(b.hi[i])) {
        const double l = px(b.lo[i]), h = px(b.hi[i]), yc = y + bar / 2;
        s << "<path class=\"whisker\" d=\"M" << l << ' ' << yc << "H" << h << "M" << l << ' '
          << yc - 4 << "V" << yc + 4 << "M" << h << ' ' << yc - 4 << "V" << yc + 4
          << "\" stroke=\"#222\" fill=\"none\"/>\n";
        end = std::max(end, h);
      }
      s << "<text x=\"" << end + 4 << "\" y=\"" << y + bar - 3 << "\" font-size=\"11\">"
        << format_number(b.values[i], o.digits) << "</text>\n";
    }
  }
  if (series.size() > 1) {
    double x = left;
    for (const BarSeries& b : series) {
      s << "<rect x=\"" << x << "\" y=\"" << height - 16 << "\" width=\"12\" height=\"10\" fill=\""
        << b.color << "\"/><text x=\"" << x + 16 << "\" y=\"" << height - 7 << "\">"
        << escape(b.name) << "</text>\n";
      x += 30 + 7.0 * double(b.name.size());
    }
  }
  s << "</svg>\n";
  return s.str();
}

std::vector<size_t> pareto_front(const std::vector<ScatterPoint>& p, bool higher_y_better) {
  std::vector<size_t> front;
  auto better_y = [&](double a, double b) { return higher_y_better ? a > b : a < b; };
  for (size_t i = 0; i < p.size(); ++i) {
    if (!std::isfinite(p[i].x) || !std::isfinite(p[i].y)) continue;
    bool dominated = false;
    for (size_t j = 0; j < p.size() && !dominated; ++j) {
      if (j == i || !std::isfinite(p[j].x) || !std::isfinite(p[j].y)) continue;
      const bool no_worse = p[j].x >= p[i].x && !better_y(p[i].y, p[j].y);
      const bool better = p[j].x > p[i].x || better_y(p[j].y, p[i].y);
      dominated = no_worse && better;
    }
    if (!dominated) front.push_back(i);
  }
  std::sort(front.begin(), front.end(), [&](size_t a, size_t b) { return p[a].x < p[b].x; });
  return front;
}

std::string svg_scatter(const std::vector<ScatterPoint>& points, const ChartOptions& o,
                        bool higher_y_better) {
  std::vector<double> xs, ys;
  for (const ScatterPoint& p : points) xs.push_back(p.x), ys.push_back(p.y);
  const Axis ax(xs, false, 7), ay(ys, o.y_from_zero, 6);
  const double left = 70, right = 200, top = 40, bottom = 55;
  const double pw = o.width - left - right, ph = o.height - top - bottom;
  auto px = [&](double x) { return ax.at(x, left, left + pw); };
  auto py = [&](double y) { return ay.at(y, top + ph, top); };
  std::ostringstream s;
  header(s, o.width, o.height, o.title);
  x_ticks(s, ax.ticks, left, top, pw, ph, px);
  for (double t : ay.ticks) {
    s << "<line x1=\"" << left - 4 << "\" y1=\"" << py(t) << "\" x2=\"" << left + pw << "\" y2=\""
      << py(t) << "\" stroke=\"#e4e4e4\"/>\n<text class=\"tick\" x=\"" << left - 6 << "\" y=\""
      << py(t) + 4 << "\" text-anchor=\"end\">" << num(t) << "</text>\n";
  }
  frame_and_labels(s, left, top, pw, ph, o.height, o.x_label, o.y_label);
  const std::vector<size_t> front = pareto_front(points, higher_y_better);
  std::ostringstream line;
  for (size_t i : front) line << px(points[i].x) << ',' << py(points[i].y) << ' ';
  s << "<polyline class=\"pareto\" fill=\"none\" stroke=\"#888\" stroke-dasharray=\"4 3\" "
       "points=\""
    << line.str() << "\"/>\n";
  int row = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    const ScatterPoint& p = points[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
    const bool on_front = std::find(front.begin(), front.end(), i) != front.end();
    if (on_front) {
      s << "<circle class=\"pareto-point\" cx=\"" << px(p.x) << "\" cy=\"" << py(p.y)
        << "\" r=\"8\" fill=\"none\" stroke=\"#222\"/>\n";
    }
    s << "<circle class=\"point\" cx=\"" << px(p.x) << "\" cy=\"" << py(p.y)
      << "\" r=\"4.5\" fill=\"" << p.color << "\"><title>" << escape(p.label) << ": " << num(p.x)
      << ", " << num(p.y) << "</title></circle>\n";
    const double ly = top + 10 + 16 * row++;
    if (ly < top + ph) {
      s << "<circle cx=\"" << left + pw + 18 << "\" cy=\"" << ly << "\" r=\"4.5\" fill=\""
        << p.color << "\"/><text x=\"" << left + pw + 28 << "\" y=\"" << ly + 4
        << "\" font-size=\"11\">" << escape(p.label) << (on_front ? " *" : "") << "</text>\n";
    }
  }
  s << "<text x=\"" << left + pw + 12 << "\" y=\"" << top + ph + 17
    << "\" font-size=\"11\">* Pareto front (dashed)</text>\n</svg>\n";
  return s.str();
}

std::string svg_box_plot(const std::vector<std::string>& rows,
                         const std::vector<std::vector<double>>& values, const ChartOptions& o) {
  std::vector<double> all;
  for (const auto& v : values) all.insert(all.end(), v.begin(), v.end());
  const Axis ax(all, o.y_from_zero, 7);
  const double left = 210, right = 40, top = 40, row_h = 30;
  const double ph = row_h * double(rows.size());
  const int height = static_cast<int>(top + ph + 45);
  const double pw = o.width - left - right;
  auto px = [&](double v) { return ax.at(v, left, left + pw); };
  std::ostringstream s;
  header(s, o.width, height, o.title);
  x_ticks(s, ax.ticks, left, top, pw, ph, px);
  frame_and_labels(s, left, top, pw, ph, height, o.x_label, "");
  for (size_t i = 0; i < rows.size() && i < values.size(); ++i) {
    const double yc = top + row_h * (double(i) + 0.5);
    s << "<text x=\"" << left - 8 << "\" y=\"" << yc + 4 << "\" text-anchor=\"end\">"
      << escape(rows[i]) << "</text>\n";
    const std::vector<double>& v = values[i];
    if (v.empty()) continue;
    const double q1 = quantile(v, 0.25), q2 = quantile(v, 0.5), q3 = quantile(v, 0.75);
    const double lo = *std::min_element(v.begin(), v.end()),
                 hi = *std::max_element(v.begin(), v.end());
    s << "<path d=\"M" << px(lo) << ' ' << yc << "H" << px(q1) << "M" << px(q3) << ' ' << yc << "H"
      << px(hi) << "M" << px(lo) << ' ' << yc - 5 << "V" << yc + 5 << "M" << px(hi) << ' ' << yc - 5
      << "V" << yc + 5 << "\" stroke=\"#444\" fill=\"none\"/>\n";
    s << "<rect class=\"box\" x=\"" << px(q1) << "\" y=\"" << yc - 9 << "\" width=\""
      << std::max(1.0, px(q3) - px(q1))
      << "\" height=\"18\" fill=\"#c6dbef\" stroke=\"#444\"><title>" << escape(rows[i])
      << ": median " << num(q2) << ", quartiles " << num(q1) << "-" << num(q3)
      << "</title></rect>\n<line x1=\"" << px(q2) << "\" y1=\"" << yc - 9 << "\" x2=\"" << px(q2)
      << "\" y2=\"" << yc + 9 << "\" stroke=\"#08306b\" stroke-width=\"2\"/>\n";
    for (size_t k = 0; k < v.size(); ++k) {
      // A deterministic jitter keeps equal values apart.
      const double jitter = (double((k * 7) % 11) / 10.0 - 0.5) * 10.0;
      s << "<circle class=\"point\" cx=\"" << px(v[k]) << "\" cy=\"" << yc + jitter
        << "\" r=\"2\" fill=\"#d62728\" fill-opacity=\"0.7\"/>\n";
    }
  }
  s << "</svg>\n";
  return s.str();
}

}  // namespace foveate::bench
