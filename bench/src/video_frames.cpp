// The pictures a video shows: frames tiled side by side, the gaze marked.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "foveate/bench/video.hpp"
#include "foveate/core/error.hpp"
#include "foveate/core/image_text.hpp"
#include "foveate/core/parse.hpp"

namespace foveate::bench {

void mark_gaze(Image& image, Vec2d gaze_px) {
  if (image.empty()) return;
  // A ring that stays visible on any background: white with dark edges, and
  // a dark-edged magenta dot at the centre (the overlay's gaze colour).
  const double radius = std::max(6.0, std::min(image.width, image.height) / 24.0);
  const double half = std::max(1.0, radius / 8.0);  // half the ring's white width
  const double dot = std::max(1.5, radius / 5.0);
  const int x0 = std::max(0, static_cast<int>(std::floor(gaze_px.x - radius - half - 2)));
  const int x1 =
      std::min(image.width - 1, static_cast<int>(std::ceil(gaze_px.x + radius + half + 2)));
  const int y0 = std::max(0, static_cast<int>(std::floor(gaze_px.y - radius - half - 2)));
  const int y1 =
      std::min(image.height - 1, static_cast<int>(std::ceil(gaze_px.y + radius + half + 2)));
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const double d = std::hypot(x + 0.5 - gaze_px.x, y + 0.5 - gaze_px.y);
      const double ring = std::abs(d - radius);
      std::uint8_t* p = image.at(x, y);
      auto set = [p](std::uint8_t r, std::uint8_t g, std::uint8_t b) {
        p[0] = r;
        p[1] = g;
        p[2] = b;
        p[3] = 255;
      };
      if (ring <= half) {
        set(255, 255, 255);
      } else if (ring <= half + 1.0) {
        set(20, 20, 20);
      } else if (d <= dot) {
        set(255, 77, 204);
      } else if (d <= dot + 1.0) {
        set(20, 20, 20);
      }
    }
  }
}

void label_tile(Image& image, const std::string& name) {
  if (image.empty()) return;
  const int scale = label_scale(image.height);
  draw_label(image, 0, image.height - label_height(scale), name, scale);
}

void tile_layout(int n, int& cols, int& rows) {
  cols = n <= 3 ? n : (n + 1) / 2;
  rows = cols > 0 ? (n + cols - 1) / cols : 0;
}

std::string video_summary(const VideoWriter& v, double fps) {
  const bool h264 = v.encoder() == "libx264" || v.encoder() == "libopenh264";
  std::string s = "video: " + v.path() + ": " + std::to_string(v.frames()) + " frame(s), " +
                  std::to_string(v.padded_width()) + "x" + std::to_string(v.padded_height()) +
                  ", " + format_fixed(fps, fps == std::floor(fps) ? 0 : 3) + " fps, " +
                  (h264 ? "H.264 (" + v.encoder() + ")"
                        : v.encoder() + " (no H.264 encoder in this libavcodec)");
  if (v.padded()) s += "; padded to even width and height for yuv420p";
  return s;
}

Image tile(const std::vector<const Image*>& images) {
  if (images.empty()) throw Error("tile: no images");
  const int w = images[0]->width, h = images[0]->height;
  for (const Image* im : images) {
    if (im->width != w || im->height != h) throw Error("tile: images of different sizes");
  }
  const int n = static_cast<int>(images.size());
  int cols = 0, rows = 0;
  tile_layout(n, cols, rows);
  Image out(cols * w, rows * h);
  for (size_t i = 3; i < out.rgba.size(); i += 4) out.rgba[i] = 255;
  for (int i = 0; i < n; ++i) {
    const int ox = (i % cols) * w, oy = (i / cols) * h;
    for (int y = 0; y < h; ++y) {
      std::memcpy(out.at(ox, oy + y), images[static_cast<size_t>(i)]->at(0, y),
                  static_cast<size_t>(w) * 4);
    }
  }
  return out;
}

}  // namespace foveate::bench
