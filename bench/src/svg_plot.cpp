// Line charts and scatter plots (svg_plot.hpp); bars and boxes are in
// svg_bars.cpp.
#include "foveate/bench/svg_plot.hpp"

#include <algorithm>
#include <cmath>

#include "foveate/core/format.hpp"
#include "svg_common.hpp"

namespace foveate::bench {

using svg::Axis;
using svg::escape;
using svg::num;

namespace {

// Room right of the plot for a legend of these names (a swatch, a gap and
// the name), at most half the chart.
double legend_room(const std::vector<std::string>& names, int width, double least) {
  double widest = 0;
  for (const std::string& n : names) widest = std::max(widest, svg::text_width(n, 11));
  return std::min(0.5 * width, std::max(least, std::ceil(widest + 56)));
}

// The y axis of a line chart: linear, or powers of ten on a log scale (the
// axis then runs over log10 of the values).
Axis y_axis(const std::vector<double>& ys, const ChartOptions& o) {
  Axis ay(ys, o.y_from_zero && !o.log_y, 6);
  if (o.log_y) {
    ay.lo = std::floor(ay.lo), ay.hi = std::ceil(ay.hi);
    if (ay.hi <= ay.lo) ay.hi = ay.lo + 1;
    ay.ticks.clear();
    for (double e = ay.lo; e <= ay.hi + 1e-9; e += 1) ay.ticks.push_back(e);
  }
  return ay;
}

std::vector<std::string> y_labels(const Axis& ay, bool log_y) {
  std::vector<std::string> out;
  for (double t : ay.ticks)
    out.push_back(log_y ? format_power_of_ten(static_cast<int>(std::lround(t))) : ay.label(t));
  return out;
}

void line_series(std::ostringstream& s, const Series& se, const std::function<double(double)>& px,
                 const std::function<double(double)>& py) {
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
  if (pts.size() > 80) return;  // a dense series: the line alone
  for (const auto& [x, y] : pts) {
    s << "<circle class=\"point\" cx=\"" << px(x) << "\" cy=\"" << py(y) << "\" r=\"3\" fill=\""
      << se.color << "\"><title>" << escape(se.name) << ": " << num(x) << ", " << num(y)
      << "</title></circle>\n";
  }
}

}  // namespace

std::string svg_line_chart(const std::vector<Series>& series, const ChartOptions& o) {
  std::vector<double> xs, ys;
  auto ty = [&](double y) { return o.log_y ? std::log10(std::max(y, 1e-300)) : y; };
  std::vector<std::string> names;
  for (const Series& se : series) {
    names.push_back(se.name);
    for (size_t i = 0; i < se.x.size() && i < se.y.size(); ++i) {
      if (!std::isfinite(se.x[i]) || !std::isfinite(se.y[i])) continue;
      if (o.log_y && !(se.y[i] > 0)) continue;
      xs.push_back(se.x[i]);
      ys.push_back(ty(se.y[i]));
    }
  }
  const Axis ax(xs, false, 8);
  const Axis ay = y_axis(ys, o);
  const std::vector<std::string> labels = y_labels(ay, o.log_y);
  const double left = svg::left_margin(labels), right = legend_room(names, o.width, 120);
  const double top = 40, bottom = 55;
  const double pw = o.width - left - right, ph = o.height - top - bottom;
  auto px = [&](double x) { return ax.at(x, left, left + pw); };
  auto py = [&](double y) { return ay.at(ty(y), top + ph, top); };
  std::ostringstream s;
  svg::header(s, o.width, o.height, o.title);
  svg::x_ticks(s, ax, top, ph, px);
  svg::y_ticks(s, ay.ticks, labels, left, pw, [&](double t) { return ay.at(t, top + ph, top); });
  svg::frame_and_labels(s, left, top, pw, ph, o.height, o.x_label, o.y_label);
  int row = 0;
  s << "<g class=\"legend\">\n";
  for (const Series& se : series) {
    const double ly = top + 10 + 18 * row++;
    s << "<line x1=\"" << left + pw + 12 << "\" y1=\"" << ly << "\" x2=\"" << left + pw + 36
      << "\" y2=\"" << ly << "\" stroke=\"" << se.color << "\" stroke-width=\"2\""
      << (se.dashed ? " stroke-dasharray=\"6 4\"" : "") << "/>\n<text x=\"" << left + pw + 42
      << "\" y=\"" << ly + 4 << "\" font-size=\"11\">" << escape(se.name) << "</text>\n";
  }
  s << "</g>\n";
  for (const Series& se : series) line_series(s, se, px, py);
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
  std::vector<std::string> names;
  for (const ScatterPoint& p : points) xs.push_back(p.x), ys.push_back(p.y);
  for (const ScatterPoint& p : points) names.push_back(p.label + " *");
  const Axis ax(xs, false, 7), ay(ys, o.y_from_zero, 6);
  std::vector<std::string> labels;
  for (double t : ay.ticks) labels.push_back(ay.label(t));
  const double left = svg::left_margin(labels), right = legend_room(names, o.width, 200);
  const double top = 40, bottom = 55;
  const double pw = o.width - left - right, ph = o.height - top - bottom;
  auto px = [&](double x) { return ax.at(x, left, left + pw); };
  auto py = [&](double y) { return ay.at(y, top + ph, top); };
  std::ostringstream s;
  svg::header(s, o.width, o.height, o.title);
  svg::x_ticks(s, ax, top, ph, px);
  svg::y_ticks(s, ay.ticks, labels, left, pw, py);
  svg::frame_and_labels(s, left, top, pw, ph, o.height, o.x_label, o.y_label);
  const std::vector<size_t> front = pareto_front(points, higher_y_better);
  std::ostringstream line;
  for (size_t i : front) line << px(points[i].x) << ',' << py(points[i].y) << ' ';
  s << "<polyline class=\"pareto\" fill=\"none\" stroke=\"#888\" stroke-dasharray=\"4 3\" "
       "points=\""
    << line.str() << "\"/>\n<g class=\"legend\">\n";
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
    << "\" font-size=\"11\">* Pareto front (dashed)</text>\n</g>\n</svg>\n";
  return s.str();
}

}  // namespace foveate::bench
