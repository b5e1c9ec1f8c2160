// Horizontal bars, stacked bars and box plots (svg_plot.hpp): one row per
// name, the value axis along the bottom.
#include <algorithm>
#include <cmath>

#include "foveate/bench/svg_plot.hpp"
#include "foveate/core/format.hpp"
#include "foveate/core/stats.hpp"
#include "svg_common.hpp"

namespace foveate::bench {

using svg::Axis;
using svg::escape;
using svg::num;

namespace {

// Room left of the plot for the row names.
double rows_room(const std::vector<std::string>& rows) {
  double widest = 0;
  for (const std::string& r : rows) widest = std::max(widest, svg::text_width(r));
  return std::max(90.0, std::ceil(widest + 16));
}

void row_labels(std::ostringstream& s, const std::vector<std::string>& rows, double left,
                double top, double row_h) {
  for (size_t i = 0; i < rows.size(); ++i) {
    s << "<text class=\"row-label\" x=\"" << left - 8 << "\" y=\""
      << top + row_h * (double(i) + 0.5) + 4 << "\" text-anchor=\"end\">" << escape(rows[i])
      << "</text>\n";
  }
}

// One line of legend swatches (name, colour, opacity) from x = `left`, its
// text's baseline at `y`.
struct Swatch {
  std::string name, colour;
  double opacity = 1.0;
};
void swatch_legend(std::ostringstream& s, const std::vector<Swatch>& entries, double left,
                   double y) {
  s << "<g class=\"legend\">\n";
  double x = left;
  for (const Swatch& e : entries) {
    s << "<rect x=\"" << x << "\" y=\"" << y - 9 << "\" width=\"12\" height=\"10\" fill=\""
      << e.colour << "\" fill-opacity=\"" << e.opacity << "\"/><text x=\"" << x + 16 << "\" y=\""
      << y << "\" font-size=\"11\">" << escape(e.name) << "</text>\n";
    x += 34 + svg::text_width(e.name, 11);
  }
  s << "</g>\n";
}

// "1.73x" (a ratio's x set close), "2.05 ms".
std::string value_text(double v, const BarChartOptions& o) {
  const std::string n = format_significant(v, o.digits);
  if (o.unit.empty()) return n;
  return o.unit == "x" ? n + "x" : n + " " + o.unit;
}

}  // namespace

std::string svg_bar_chart(const std::vector<std::string>& rows,
                          const std::vector<BarSeries>& series, const BarChartOptions& o) {
  std::vector<double> all;
  for (const BarSeries& b : series) {
    all.insert(all.end(), b.values.begin(), b.values.end());
    all.insert(all.end(), b.lo.begin(), b.lo.end());
    all.insert(all.end(), b.hi.begin(), b.hi.end());
  }
  const Axis ax(all, o.from_zero, 7);
  const double left = rows_room(rows), right = 70, top = 40, bar = 14;
  const double row_h = std::max(24.0, bar * double(series.size()) + 10);
  const double ph = row_h * double(rows.size());
  const int legend = series.size() > 1 ? 22 : 0;
  const int height = static_cast<int>(top + ph + 45 + legend);
  const double pw = o.width - left - right;
  auto px = [&](double v) { return ax.at(std::clamp(v, ax.lo, ax.hi), left, left + pw); };
  std::ostringstream s;
  svg::header(s, o.width, height, o.title);
  svg::x_ticks(s, ax, top, ph, px);
  svg::frame_and_labels(s, left, top, pw, ph, height - legend, o.value_label, "");
  row_labels(s, rows, left, top, row_h);
  const double base = px(o.from_zero ? std::max(0.0, ax.lo) : ax.lo);
  for (size_t i = 0; i < rows.size(); ++i) {
    const double y0 = top + row_h * double(i) + (row_h - bar * double(series.size())) / 2;
    for (size_t k = 0; k < series.size(); ++k) {
      const BarSeries& b = series[k];
      if (i >= b.values.size() || !std::isfinite(b.values[i])) continue;
      const double y = y0 + bar * double(k), v = px(b.values[i]);
      const std::string& colour = i < b.colors.size() ? b.colors[i] : b.color;
      s << "<rect class=\"bar\" x=\"" << std::min(base, v) << "\" y=\"" << y + 1 << "\" width=\""
        << std::fabs(v - base) << "\" height=\"" << bar - 2 << "\" fill=\"" << colour
        << "\" fill-opacity=\"" << b.opacity << "\"><title>" << escape(rows[i]) << ", "
        << escape(b.name) << ": " << value_text(b.values[i], o) << "</title></rect>\n";
      double end = v;
      if (i < b.lo.size() && i < b.hi.size() && std::isfinite(b.lo[i]) && std::isfinite(b.hi[i])) {
        const double l = px(b.lo[i]), h = px(b.hi[i]), yc = y + bar / 2;
        s << "<path class=\"whisker\" d=\"M" << l << ' ' << yc << "H" << h << "M" << l << ' '
          << yc - 4 << "V" << yc + 4 << "M" << h << ' ' << yc - 4 << "V" << yc + 4
          << "\" stroke=\"#222\" fill=\"none\"/>\n";
        end = std::max(end, h);
      }
      s << "<text class=\"value\" x=\"" << end + 4 << "\" y=\"" << y + bar - 3
        << "\" font-size=\"11\">" << escape(value_text(b.values[i], o)) << "</text>\n";
    }
  }
  if (series.size() > 1) {
    // Series told apart by opacity when each row has its own colour.
    std::vector<Swatch> entries;
    for (const BarSeries& b : series)
      entries.push_back({b.name, b.colors.empty() ? b.color : "#555555", b.opacity});
    swatch_legend(s, entries, left, top + ph + 45 + 15);
  }
  s << "</svg>\n";
  return s.str();
}

std::string svg_stacked_bars(const std::vector<std::string>& rows,
                             const std::vector<StackSegment>& segments, const BarChartOptions& o) {
  std::vector<double> totals(rows.size(), 0.0);
  for (const StackSegment& g : segments) {
    for (size_t i = 0; i < rows.size() && i < g.values.size(); ++i)
      if (std::isfinite(g.values[i]) && g.values[i] > 0) totals[i] += g.values[i];
  }
  const Axis ax(totals, true, 7);
  const double left = rows_room(rows), right = 80, top = 40, row_h = 26;
  const double ph = row_h * double(rows.size());
  const int legend_rows = (static_cast<int>(segments.size()) + 7) / 8;  // 8 to a line
  const int legend = 22 * legend_rows;
  const int height = static_cast<int>(top + ph + 45 + legend);
  const double pw = o.width - left - right;
  auto px = [&](double v) { return ax.at(v, left, left + pw); };
  std::ostringstream s;
  svg::header(s, o.width, height, o.title);
  svg::x_ticks(s, ax, top, ph, px);
  svg::frame_and_labels(s, left, top, pw, ph, height - legend, o.value_label, "");
  row_labels(s, rows, left, top, row_h);
  for (size_t i = 0; i < rows.size(); ++i) {
    const double y = top + row_h * double(i) + 4;
    double at = 0;
    for (const StackSegment& g : segments) {
      if (i >= g.values.size() || !std::isfinite(g.values[i]) || !(g.values[i] > 0)) continue;
      s << "<rect class=\"bar\" x=\"" << px(at) << "\" y=\"" << y << "\" width=\""
        << px(at + g.values[i]) - px(at) << "\" height=\"" << row_h - 8 << "\" fill=\"" << g.color
        << "\" stroke=\"white\" stroke-width=\"0.5\"><title>" << escape(rows[i]) << ", "
        << escape(g.name) << ": " << value_text(g.values[i], o) << " ("
        << format_percent(g.values[i] / totals[i], 2) << ")</title></rect>\n";
      at += g.values[i];
    }
    s << "<text class=\"value\" x=\"" << px(at) + 4 << "\" y=\"" << y + row_h / 2
      << "\" font-size=\"11\">" << escape(value_text(totals[i], o)) << "</text>\n";
  }
  for (int line = 0; line < legend_rows; ++line) {
    std::vector<Swatch> entries;
    for (size_t k = 8 * size_t(line); k < std::min(segments.size(), 8 * size_t(line) + 8); ++k)
      entries.push_back({segments[k].name, segments[k].color});
    swatch_legend(s, entries, left, top + ph + 45 + 15 + 22 * line);
  }
  s << "</svg>\n";
  return s.str();
}

std::string svg_box_plot(const std::vector<std::string>& rows,
                         const std::vector<std::vector<double>>& values, const ChartOptions& o,
                         const std::vector<std::string>& colors) {
  std::vector<double> all;
  for (const auto& v : values) all.insert(all.end(), v.begin(), v.end());
  const Axis ax(all, o.y_from_zero, 7);
  const double left = rows_room(rows), right = 40, top = 40, row_h = 30;
  const double ph = row_h * double(rows.size());
  const int height = static_cast<int>(top + ph + 45);
  const double pw = o.width - left - right;
  auto px = [&](double v) { return ax.at(v, left, left + pw); };
  std::ostringstream s;
  svg::header(s, o.width, height, o.title);
  svg::x_ticks(s, ax, top, ph, px);
  svg::frame_and_labels(s, left, top, pw, ph, height, o.x_label, "");
  row_labels(s, rows, left, top, row_h);
  for (size_t i = 0; i < rows.size() && i < values.size(); ++i) {
    const double yc = top + row_h * (double(i) + 0.5);
    const std::vector<double>& v = values[i];
    if (v.empty()) continue;
    const std::string colour = i < colors.size() ? colors[i] : "#1f77b4";
    const double q1 = quantile(v, 0.25), q2 = quantile(v, 0.5), q3 = quantile(v, 0.75);
    const double lo = *std::min_element(v.begin(), v.end()),
                 hi = *std::max_element(v.begin(), v.end());
    s << "<path d=\"M" << px(lo) << ' ' << yc << "H" << px(q1) << "M" << px(q3) << ' ' << yc << "H"
      << px(hi) << "M" << px(lo) << ' ' << yc - 5 << "V" << yc + 5 << "M" << px(hi) << ' ' << yc - 5
      << "V" << yc + 5 << "\" stroke=\"#444\" fill=\"none\"/>\n";
    s << "<rect class=\"box\" x=\"" << px(q1) << "\" y=\"" << yc - 9 << "\" width=\""
      << std::max(1.0, px(q3) - px(q1)) << "\" height=\"18\" fill=\"" << colour
      << "\" fill-opacity=\"0.3\" stroke=\"#444\"><title>" << escape(rows[i]) << ": median "
      << num(q2) << ", quartiles " << num(q1) << "–" << num(q3) << "</title></rect>\n<line x1=\""
      << px(q2) << "\" y1=\"" << yc - 9 << "\" x2=\"" << px(q2) << "\" y2=\"" << yc + 9
      << "\" stroke=\"#222\" stroke-width=\"2\"/>\n";
    for (size_t k = 0; k < v.size(); ++k) {
      // A deterministic jitter keeps equal values apart.
      const double jitter = (double((k * 7) % 11) / 10.0 - 0.5) * 10.0;
      s << "<circle class=\"point\" cx=\"" << px(v[k]) << "\" cy=\"" << yc + jitter
        << "\" r=\"2\" fill=\"" << colour << "\" fill-opacity=\"0.8\"/>\n";
    }
  }
  s << "</svg>\n";
  return s.str();
}

}  // namespace foveate::bench
