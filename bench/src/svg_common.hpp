#pragma once
// What the SVG charts share (svg_plot.cpp, svg_bars.cpp): escaping, the
// estimated width of a label, nice axes and their ticks, the title, frame and
// axis labels. Charts carry their size as width/height and a viewBox, so a
// page may scale them to its width and a file keeps its size.
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace foveate::bench::svg {

std::string escape(const std::string& s);
/// A tooltip or label number: three significant digits (format_significant).
std::string num(double v);
/// About how wide `text` is at `font_px` in a sans-serif font (digits and
/// lower case average 0.56 em; a little more is reserved).
double text_width(const std::string& text, double font_px = 12.0);

/// A linear axis over the finite values, widened to nice ticks (1, 2 or 5
/// times a power of ten apart).
struct Axis {
  double lo = 0, hi = 1;
  std::vector<double> ticks;
  Axis(const std::vector<double>& values, bool from_zero, int target);
  [[nodiscard]] double at(double v, double p0, double p1) const {
    return p0 + (v - lo) / (hi - lo) * (p1 - p0);
  }
  [[nodiscard]] double step() const { return ticks.size() > 1 ? ticks[1] - ticks[0] : hi - lo; }
  /// The tick's label: decimals as the step needs (format_tick).
  [[nodiscard]] std::string label(double v) const;
};

/// The root element (width, height, viewBox), a white background and the
/// title centred at the top.
void header(std::ostringstream& s, int w, int h, const std::string& title);
/// Grid lines and tick labels (class "tick") of an x axis along the bottom.
void x_ticks(std::ostringstream& s, const Axis& axis, double top, double ph,
             const std::function<double(double)>& px);
/// The same for a y axis on the left, with the labels given.
void y_ticks(std::ostringstream& s, const std::vector<double>& ticks,
             const std::vector<std::string>& labels, double left, double pw,
             const std::function<double(double)>& py);
/// The left margin that keeps the y tick labels clear of the rotated y axis
/// title (at x = 16): the widest label, a gap and the title's room.
double left_margin(const std::vector<std::string>& labels);
/// The plot's frame and its axis titles (class "axis-label"): x below, y
/// rotated on the left when given.
void frame_and_labels(std::ostringstream& s, double left, double top, double pw, double ph,
                      int height, const std::string& x_label, const std::string& y_label);

}  // namespace foveate::bench::svg
