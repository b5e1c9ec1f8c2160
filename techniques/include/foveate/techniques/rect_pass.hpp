#pragma once
// Passes drawn over a list of rectangles instead of the whole screen. On
// llvmpipe a pass costs in proportion to the pixels it covers, so a pass that
// only some tiles need (a stencil mask, a reconstruction that differs per
// tile) is drawn over those tiles alone. The programs are built from
// pass_kit/rects.vert and any fragment shader; the rectangles are one instanced
// quad each, read from a storage buffer.
#include <algorithm>
#include <array>
#include <vector>

#include "foveate/gpu/gl.hpp"
#include "foveate/gpu/pass.hpp"
#include "foveate/gpu/shader.hpp"

namespace foveate::tech {

/// A rectangle of pixels [x0, x1) x [y0, y1) in GL coordinates (origin bottom-left).
using PixelRect = std::array<int, 4>;

/// A pixel coordinate (already rounded) as an int, held within a range no
/// target reaches: a gaze far off the screen gives coordinates beyond int's.
inline int pixel_index(double v) { return static_cast<int>(std::clamp(v, -1e8, 1e8)); }

class RectPass {
 public:
  /// Draws `rects` with `program` into the framebuffer that is bound, whose
  /// size is `width` x `height`, with the pass state already applied.
  void draw(const gpu::Program& program, const std::vector<PixelRect>& rects, int width,
            int height);
  /// The same into `target` with `state` (binds it and applies the state).
  void draw(const gpu::Program& program, const std::vector<PixelRect>& rects,
            const gpu::RenderTarget& target, const gpu::PassState& state);

 private:
  gpu::Buffer buffer_;
  gpu::VertexArray vao_;
};

/// Joins horizontally adjacent rectangles of a row-major tile list that share
/// their rows (fewer, longer quads; the pixels covered are the same).
std::vector<PixelRect> merge_runs(const std::vector<PixelRect>& rects);

/// The smallest rectangle holding every one of `rects`, grown by `grow`
/// pixels on each side (unclipped); {0, 0, 0, 0} when there are none.
PixelRect bounding_box(const std::vector<PixelRect>& rects, int grow = 0);

/// The parts of `rects` inside `bounds` (empty ones left out).
std::vector<PixelRect> clip_rects(const std::vector<PixelRect>& rects, const PixelRect& bounds);

/// Fewer, larger rectangles covering every pixel of `rects` (bands of rows,
/// bottom to top, as disc_rects and annulus_rects make them): a rectangle
/// takes in the one directly above it where their bounding box is no more
/// than `waste` larger than what they cover, and the box meets no other
/// rectangle of that band and no other box's columns. Passes drawn once per
/// rectangle pay a fixed cost per draw (docs/performance.md).
std::vector<PixelRect> coarsen_runs(const std::vector<PixelRect>& rects, double waste);

/// Rectangles of `band` rows each that together cover every pixel of a
/// width x height target whose centre lies within `radius_px` of (cx, cy) (GL
/// pixels): a disc's area and one pixel around it, for masks drawn over a disc.
std::vector<PixelRect> disc_rects(double cx, double cy, double radius_px, int width, int height,
                                  int band = 4);

/// Rectangles of `band` rows each that together cover every pixel of a
/// width x height target whose centre lies within `outer_px` of (cx, cy) (GL
/// pixels; infinite = the whole target) and not within `inner_px`: an annulus
/// less only the pixels that lie inside `inner_px` for every row of their
/// band (two rectangles per band where the hole cuts it).
std::vector<PixelRect> annulus_rects(double cx, double cy, double inner_px, double outer_px,
                                     int width, int height, int band = 4);

}  // namespace foveate::tech
