#include "foveate/core/image.hpp"

#include <png.h>
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>

#include "foveate/core/error.hpp"
#include "foveate/core/file.hpp"

namespace foveate {

namespace {

bool is_png(const std::string& bytes) {
  return bytes.size() >= 8 && std::memcmp(bytes.data(), "\x89PNG\r\n\x1a\n", 8) == 0;
}

// 8-bit PNG through libpng's simplified API: faster than stb_image, which
// matters where sequences of frames are read (compare, the metrics). 16-bit PNGs go to stb_image, which keeps their values' top byte
// (libpng would take them as linear light).
std::optional<Image> read_png(const std::string& path, const std::string& bytes) {
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&png, bytes.data(), bytes.size())) {
    throw Error(path + ": not a readable PNG (" + png.message + ")");
  }
  if (png.format & PNG_FORMAT_FLAG_LINEAR) {
    png_image_free(&png);
    return std::nullopt;
  }
  png.format = PNG_FORMAT_RGBA;
  if (png.width == 0 || png.height == 0 || png.width > 65536 || png.height > 65536) {
    png_image_free(&png);
    throw Error(path + ": a PNG of " + std::to_string(png.width) + "x" +
                std::to_string(png.height) + " pixels (at most 65536 on each side)");
  }
  Image img(static_cast<int>(png.width), static_cast<int>(png.height));
  if (!png_image_finish_read(&png, nullptr, img.rgba.data(), 0, nullptr)) {
    const std::string why = png.message;
    png_image_free(&png);
    throw Error(path + ": not a readable PNG (" + why + ")");
  }
  return img;
}

}  // namespace

Image read_image(const std::string& path) {
  const std::string bytes = read_file(path, "image");
  if (bytes.empty()) throw Error(path + ": the file is empty");
  if (is_png(bytes)) {
    if (std::optional<Image> img = read_png(path, bytes)) return std::move(*img);
  }
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

namespace {

void append_png(png_structp png, png_bytep data, png_size_t size) {
  static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<const char*>(data), size);
}
void flush_png(png_structp) {}

// libpng reports errors by longjmp; nothing with a destructor lives in this
// frame after setjmp, so the jump skips no cleanup.
bool write_png_rows(const Image& image, bool opaque, std::string& out) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  if (!png) return false;
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_set_write_fn(png, &out, append_png, flush_png);
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width),
               static_cast<png_uint_32>(image.height), 8,
               opaque ? PNG_COLOR_TYPE_RGB : PNG_COLOR_TYPE_RGB_ALPHA, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
  png_set_compression_level(png, 1);
  png_write_info(png, info);
  if (opaque) png_set_filler(png, 0, PNG_FILLER_AFTER);  // drop the alpha bytes
  for (int y = 0; y < image.height; ++y) {
    png_write_row(png, const_cast<png_bytep>(image.at(0, y)));
  }
  png_write_end(png, info);
  png_destroy_write_struct(&png, &info);
  return true;
}

}  // namespace

// The sub filter and fast deflate: far faster than stb_image_write per frame,
// and smaller files, which decode faster too (the Paeth filter that a
// thorough encoder picks is the slowest part of decoding).
std::string encode_png(const Image& image) {
  if (image.empty()) throw Error("cannot encode an empty image");
  bool opaque = true;
  for (size_t i = 3; i < image.rgba.size() && opaque; i += 4) opaque = image.rgba[i] == 255;
  std::string out;
  if (!write_png_rows(image, opaque, out)) throw Error("PNG encoding failed");
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
