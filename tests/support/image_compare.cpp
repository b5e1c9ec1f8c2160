#include "image_compare.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "foveate/core/error.hpp"

namespace foveate::test {

Comparison compare_images(const Image& a, const Image& b, int pixel_threshold) {
  Comparison c;
  c.size_matches = a.width == b.width && a.height == b.height;
  if (!c.size_matches) return c;
  double sum = 0;
  size_t differing = 0;
  const size_t n = static_cast<size_t>(a.width) * a.height;
  for (size_t i = 0; i < n; ++i) {
    int worst = 0;
    for (int ch = 0; ch < 3; ++ch) {
      const int e = std::abs(int(a.rgba[i * 4 + ch]) - int(b.rgba[i * 4 + ch]));
      worst = std::max(worst, e);
      sum += e;
    }
    c.max_error = std::max(c.max_error, worst);
    differing += worst > pixel_threshold ? 1 : 0;
  }
  c.mean_error = sum / (3.0 * static_cast<double>(n));
  c.fraction = static_cast<double>(differing) / static_cast<double>(n);
  return c;
}

Image difference_image(const Image& a, const Image& b) {
  Image d(a.width, a.height);
  if (a.width != b.width || a.height != b.height) return d;
  for (size_t i = 0; i < a.rgba.size(); i += 4) {
    for (int ch = 0; ch < 3; ++ch) {
      d.rgba[i + ch] = static_cast<uint8_t>(
          std::min(255, 4 * std::abs(int(a.rgba[i + ch]) - int(b.rgba[i + ch]))));
    }
    d.rgba[i + 3] = 255;
  }
  return d;
}

std::filesystem::path golden_failure_dir() {
  const char* dir_env = std::getenv("FOVEATE_TEST_OUTPUT");
  return dir_env ? std::filesystem::path(dir_env)
                 : std::filesystem::current_path() / "golden-failures";
}

std::string check_golden(const Image& actual, const std::string& reference_path,
                         const std::string& name, const Tolerance& t) {
  namespace fs = std::filesystem;
  const char* update = std::getenv("FOVEATE_UPDATE_GOLDEN");
  if (update && std::string(update) == "1") {
    write_png(reference_path, actual);
    return "";
  }
  Image expected;
  try {
    expected = read_image(reference_path);
  } catch (const Error& e) {
    return std::string("cannot read the reference: ") + e.what() +
           " (run with FOVEATE_UPDATE_GOLDEN=1 to create it)";
  }
  const Comparison c = compare_images(expected, actual, t.pixel_threshold);
  if (c.within(t)) return "";
  const fs::path dir = golden_failure_dir();
  fs::create_directories(dir);
  const std::string actual_path = (dir / (name + ".actual.png")).string();
  const std::string diff_path = (dir / (name + ".diff.png")).string();
  write_png(actual_path, actual);
  if (c.size_matches) write_png(diff_path, difference_image(expected, actual));
  std::ostringstream m;
  if (!c.size_matches) {
    m << name << ": size " << actual.width << "x" << actual.height
      << " differs from the reference's " << expected.width << "x" << expected.height;
  } else {
    m << name << ": max error " << c.max_error << " (limit " << t.max_error << "), mean "
      << c.mean_error << " (limit " << t.mean_error << "), " << 100 * c.fraction
      << " % of pixels off by more than " << t.pixel_threshold << " (limit " << 100 * t.max_fraction
      << " %)";
  }
  m << "; actual: " << actual_path << ", difference: " << diff_path;
  return m.str();
}

Comparison compare_disc(const Image& a, const Image& b, Vec2d centre, double radius,
                        int threshold) {
  Comparison c;
  c.size_matches = a.width == b.width && a.height == b.height;
  if (!c.size_matches) return c;
  double sum = 0;
  size_t n = 0, off = 0;
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      if (std::hypot(x + 0.5 - centre.x, y + 0.5 - centre.y) > radius) continue;
      int worst = 0;
      for (int ch = 0; ch < 3; ++ch) {
        const int e = std::abs(int(a.at(x, y)[ch]) - int(b.at(x, y)[ch]));
        worst = std::max(worst, e);
        sum += e;
      }
      c.max_error = std::max(c.max_error, worst);
      off += worst > threshold ? 1 : 0;
      ++n;
    }
  }
  c.mean_error = n ? sum / (3.0 * double(n)) : 0.0;
  c.fraction = n ? double(off) / double(n) : 0.0;
  return c;
}

}  // namespace foveate::test
