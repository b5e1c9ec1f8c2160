#include "foveate/core/image.hpp"

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "foveate/core/error.hpp"
#include "foveate/core/file.hpp"

namespace foveate {

Image read_image(const std::string& path) {
  const std::string bytes = read_file(path, "image");
  if (bytes.empty()) throw Error(path + ": the file is empty");
  int w = 0, h = 0, n = 0;
  unsigned char* data = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()),
                                              static_cast<int>(bytes.size()), &w, &h, &n, 4);
  if (!data) throw Error(path + ": not a readable image (" + stbi_failure_reason() + ")");
  Image img(w, h);
  std::memcpy(img.rgba.data(), data, img.rgba.size());
  stbi_image_free(data);
  return img;
}

namespace {
void append(void* ctx, void* data, int size) {
  static_cast<std::string*>(ctx)->append(static_cast<const char*>(data), static_cast<size_t>(size));
}
}  // namespace

std::string encode_png(const Image& image) {
  if (image.empty()) throw Error("cannot encode an empty image");
  std::string out;
  if (!stbi_write_png_to_func(append, &out, image.width, image.height, 4, image.rgba.data(),
                              image.width * 4)) {
    throw Error("PNG encoding failed");
  }
  return out;
}

std::string encode_jpeg(const Image& image, int quality) {
  if (image.empty()) throw Error("cannot encode an empty image");
  if (quality < 1 || quality > 100)
    throw Error("JPEG quality: expected 1..100, got " + std::to_string(quality));
  std::string out;
  if (!stbi_write_jpg_to_func(append, &out, image.width, image.height, 4, image.rgba.data(),
                              quality)) {
    throw Error("JPEG encoding failed");
  }
  return out;
}

Image downscale(const Image& image, int max_width) {
  if (image.empty() || max_width < 1 || image.width <= max_width) return image;
  const int w = max_width;
  const int h = std::max(1, static_cast<int>(std::lround(double(image.height) * w / image.width)));
  Image out(w, h);
  for (int y = 0; y < h; ++y) {
    const int y0 = y * image.height / h, y1 = std::max(y0 + 1, (y + 1) * image.height / h);
    for (int x = 0; x < w; ++x) {
      const int x0 = x * image.width / w, x1 = std::max(x0 + 1, (x + 1) * image.width / w);
      unsigned sum[4] = {0, 0, 0, 0};
      for (int yy = y0; yy < y1; ++yy)
        for (int xx = x0; xx < x1; ++xx)
          for (int c = 0; c < 4; ++c) sum[c] += image.at(xx, yy)[c];
      const unsigned n = static_cast<unsigned>((x1 - x0) * (y1 - y0));
      for (int c = 0; c < 4; ++c) out.at(x, y)[c] = static_cast<std::uint8_t>((sum[c] + n / 2) / n);
    }
  }
  return out;
}

void write_png(const std::string& path, const Image& image) {
  write_file_atomic(path, encode_png(image));
}

}  // namespace foveate
