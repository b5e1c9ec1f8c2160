#pragma once
// How techniques look in every figure: one colour per technique, the same in
// the reports, their charts, the videos and the viewer, so that a
// reader learns once that layered is blue. Built-in techniques take theirs by
// their place in the registry (native grey, layered blue, ...); a technique
// registered at run time, or a name read back from an older results.json,
// takes one from a second list chosen by its name, so it too is the same in
// every report. And the legend of a technique's overlay: what each of its
// shapes marks.
#include <cstdint>
#include <string>
#include <vector>

#include "foveate/techniques/technique.hpp"

namespace foveate {

struct Rgb8 {
  std::uint8_t r = 0, g = 0, b = 0;
  friend bool operator==(const Rgb8&, const Rgb8&) = default;
};

/// The technique's colour. `variant` > 0 shades it for the variant-th other
/// run of the same technique in one figure (a sweep's values): alternately
/// darker and lighter, further with each pair, never the base colour.
Rgb8 technique_colour(const std::string& technique, int variant = 0);
/// The same as "#rrggbb" (SVG, HTML).
std::string technique_colour_hex(const std::string& technique, int variant = 0);
/// "#rrggbb" of any colour.
std::string hex_colour(Rgb8 c);

/// The distinct entries of an overlay's legend, in drawing order: one per
/// label, colour and kind of shape. A layer's render target (a rectangle) and
/// its blend ring (a circle) share the layer's colour and differ by kind, so
/// a legend must draw each entry's swatch as its shape.
std::vector<OverlayShape> overlay_legend(const std::vector<OverlayShape>& shapes);

}  // namespace foveate
