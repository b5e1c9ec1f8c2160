#pragma once
// Small SVG chart writers (no dependencies) for the planner sweep and the
// benchmark reports: every chart has a title (class "title"), ticks on its
// axes (class "tick"), axis titles with units (class "axis-label"), its data
// (class "bar", "point" or "box") and, with several series, a legend (class
// "legend"). Numbers are written with a few significant digits
// (core/format.hpp); y tick labels never run into the y axis title.
#include <string>
#include <vector>

namespace foveate::bench {

struct Series {
  std::string name{};
  std::string color{};
  std::vector<double> x{};
  std::vector<double> y{};
  bool dashed = false;
};

struct ChartOptions {
  std::string title{};
  std::string x_label{};  ///< with the unit, e.g. "eccentricity (degrees)"
  std::string y_label{};
  bool log_y = false;
  int width = 1000;
  int height = 460;
  bool y_from_zero = true;  ///< false: the y axis spans the data (e.g. SSIM near 1)
};

/// Lines through each series' points sorted by x, a marker on every point
/// (class "point"), ticks on both axes (class "tick"), a legend.
std::string svg_line_chart(const std::vector<Series>& series, const ChartOptions& options);

/// Horizontal bars, one row per name, with an axis of ticks and units below.
struct BarSeries {
  std::string name{};
  std::string color{};
  std::vector<double> values{};       ///< one per row; NaN leaves the row empty
  std::vector<double> lo{}, hi{};     ///< whiskers (e.g. a 95 % interval); empty = none
  std::vector<std::string> colors{};  ///< per row (a technique's own); empty = `color` for all
  double opacity = 1.0;               ///< < 1: a paler bar (e.g. a bound beside the measure)
};
struct BarChartOptions {
  std::string title{};
  std::string value_label{};  ///< the axis, with its unit
  bool from_zero = true;      ///< false: the axis spans the data (SSIM 0.92 vs 0.95)
  int width = 1000;
  int digits = 3;      ///< significant digits of the value printed at each bar's end
  std::string unit{};  ///< after that value ("x", "ms"); empty = none
};
std::string svg_bar_chart(const std::vector<std::string>& rows,
                          const std::vector<BarSeries>& series, const BarChartOptions& options);

/// One marker per point (class "point"); the points on the Pareto front
/// (no other point is both faster and better) joined by a line (class
/// "pareto") and ringed. `higher_y_better` says which way quality points.
struct ScatterPoint {
  std::string label{};
  std::string color{};
  double x = 0, y = 0;
};
std::string svg_scatter(const std::vector<ScatterPoint>& points, const ChartOptions& options,
                        bool higher_y_better);
/// Indices of the points on the Pareto front (higher x better; y as said),
/// sorted by x.
std::vector<size_t> pareto_front(const std::vector<ScatterPoint>& points, bool higher_y_better);

/// Box plots (median, quartiles, whiskers to the extremes; class "box") with
/// every value drawn as a dot over them (class "point"), one row per name.
/// `colors`: each row's (a technique's own); empty = one blue for all.
std::string svg_box_plot(const std::vector<std::string>& rows,
                         const std::vector<std::vector<double>>& values,
                         const ChartOptions& options, const std::vector<std::string>& colors = {});

/// Horizontal stacked bars, one row per name, each made of the segments in
/// order (e.g. a frame's passes), each segment one colour with a legend entry;
/// the row's total printed at its end. NaN or 0 leaves a segment out.
struct StackSegment {
  std::string name{};
  std::string color{};
  std::vector<double> values{};  ///< one per row
};
std::string svg_stacked_bars(const std::vector<std::string>& rows,
                             const std::vector<StackSegment>& segments,
                             const BarChartOptions& options);

}  // namespace foveate::bench
