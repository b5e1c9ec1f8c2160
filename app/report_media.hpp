#pragma once
// What the HTML report draws with: images embedded as data URIs, crops, the
// window where an error map is largest, and bar charts.
#include <string>
#include <vector>

#include "foveate/core/display.hpp"
#include "foveate/core/image.hpp"
#include "foveate/metrics/metrics.hpp"

namespace foveate::app {

std::string base64(const std::string& in);
/// A size x size crop centred at (cx, cy), kept inside the image.
Image crop(const Image& img, int cx, int cy, int size);

/// The window of size x size (centre returned) whose mean |acuity error| is
/// largest among those centred at least `min_ecc` degrees from the gaze (or,
/// when none is, anywhere), on a grid of size / 4; and that mean.
struct Worst {
  int x = 0, y = 0;
  double mean_error = 0;
  double ecc_deg = 0;
};
Worst worst_window(const metrics::Map& error, const Display& display, Vec2d gaze, int size,
                   double min_ecc);

/// An <img> with the PNG inline.
std::string img_tag(const Image& img, const std::string& alt, int display_width);
/// Horizontal bars: `a` (and `b` beside it when not empty) per name, as SVG.
std::string bar_chart(const std::vector<std::string>& names, const std::vector<double>& a,
                      const std::vector<double>& b, const std::string& a_name,
                      const std::string& b_name, const std::string& title);

}  // namespace foveate::app
