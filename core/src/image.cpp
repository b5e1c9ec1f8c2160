#include "foveate/core/image.hpp"

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

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

void write_png(const std::string& path, const Image& image) {
  write_file_atomic(path, encode_png(image));
}

}  // namespace foveate
