#pragma once
// What the HTML report draws with: images embedded as data URIs, crops, the
// window where an error map is largest, and bar charts.
#include <string>
#include <vector>

#include "foveate/core/display.hpp"
#include "foveate/core/image.hpp"
#include "foveate/metrics/metrics.hpp"
#include "foveate/techniques/technique.hpp"

namespace foveate::bench {

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

/// An <img> with the image inline as PNG (lossless: a crop or heat map shows
/// the technique's own pixels, not a codec's), first downscaled to at most
/// `max_width` pixels (0 = as it is).
std::string img_tag(const Image& img, const std::string& alt, int display_width, int max_width = 0);
/// The heat maps' colour scale (metrics::heat_color) as an SVG bar with ticks
/// from 0 to `max` in `unit`; `id` names its gradient, unique in the page.
std::string colour_bar(double max, const std::string& unit, const std::string& id, int width = 240);
/// The frame with the technique's overlay shapes (layer or region borders,
/// the gaze) drawn over it as SVG, `display_width` wide, and below it the
/// legend: one entry per label, colour and shape (overlay_legend), its swatch
/// drawn as that shape.
std::string overlay_figure(const Image& frame, const std::vector<OverlayShape>& shapes,
                           const std::string& alt, int display_width);

}  // namespace foveate::bench
