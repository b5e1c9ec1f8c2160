#pragma once
// Short text drawn into an image with a built-in 5x7 pixel font: the labels
// of a video's tiles and the legends of the PNG figures, which must read
// without the page or the command that made them.
#include <array>
#include <cstdint>
#include <string>

#include "foveate/core/image.hpp"

namespace foveate {

/// A font pixel's size in image pixels for a label on an image `height`
/// pixels tall: about 1/45 of it, at least 1.
int label_scale(int height);
/// Width and height in pixels of `text` drawn at `scale`, its backing box
/// included.
int label_width(const std::string& text, int scale);
int label_height(int scale);
/// Draws `text` with the box's top-left at (x, y): letters (shown in capitals),
/// digits, space and . , : ; - + = _ / ( ) % @ # ' < > ? (anything else as ?),
/// in `rgb` on a dark box so that it reads on any background; clipped to the
/// image.
void draw_label(Image& image, int x, int y, const std::string& text, int scale,
                std::array<std::uint8_t, 3> rgb = {255, 255, 255});

}  // namespace foveate
