#pragma once
// 8-bit RGBA images (sRGB-encoded, as stored in PNG), row-major, origin at the
// top-left. PNG files are read with clear errors and written atomically.
#include <cstdint>
#include <string>
#include <vector>

namespace foveate {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  ///< width * height * 4 bytes

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgba(static_cast<size_t>(w) * h * 4, 0) {}
  [[nodiscard]] bool empty() const { return width == 0 || height == 0; }
  [[nodiscard]] std::uint8_t* at(int x, int y) {
    return &rgba[(static_cast<size_t>(y) * width + x) * 4];
  }
  [[nodiscard]] const std::uint8_t* at(int x, int y) const {
    return &rgba[(static_cast<size_t>(y) * width + x) * 4];
  }
};

/// Reads a PNG (or JPEG, BMP, TGA via the same decoder) into RGBA8; throws
/// foveate::Error naming the file when it is missing, empty or corrupt.
Image read_image(const std::string& path);
/// Encodes as PNG and writes atomically (temporary file, then rename).
void write_png(const std::string& path, const Image& image);
/// Encodes as PNG in memory (e.g. to embed in an HTML report).
std::string encode_png(const Image& image);
/// Encodes as baseline JPEG (alpha dropped) in memory; quality 1..100.
std::string encode_jpeg(const Image& image, int quality = 85);
/// A box-filtered copy at most `max_width` wide (the image itself when it is
/// narrower), keeping the aspect ratio.
Image downscale(const Image& image, int max_width);

}  // namespace foveate
