#include "rate_classes.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <string>

#include "foveate/gpu/profiler.hpp"

namespace foveate::tech::vrs {

int class_of(ShadingRate r) {
  return static_cast<int>(std::find(kShadingRates.begin(), kShadingRates.end(), r) -
                          kShadingRates.begin());
}

TileClasses tile_classes(const ShadingRateImage& m) {
  TileClasses out;
  out.of_tile.resize(m.rates.size());
  for (size_t i = 0; i < m.rates.size(); ++i) {
    const int k = class_of(m.rates[i]);
    out.of_tile[i] = static_cast<std::uint8_t>(k);
    ++out.count[static_cast<size_t>(k)];
  }
  return out;
}

std::vector<std::uint8_t> neighbourhood_classes(const std::vector<std::uint8_t>& classes, int gx,
                                                int gy) {
  static_assert(kClasses <= 8);
  std::vector<std::uint8_t> out(classes.size());
  for (int ty = 0; ty < gy; ++ty) {
    for (int tx = 0; tx < gx; ++tx) {
      unsigned bits = 0;
      for (int y = std::max(0, ty - 1); y <= std::min(gy - 1, ty + 1); ++y)
        for (int x = std::max(0, tx - 1); x <= std::min(gx - 1, tx + 1); ++x)
          bits |= 1u << classes[static_cast<size_t>(y) * size_t(gx) + size_t(x)];
      out[static_cast<size_t>(ty) * size_t(gx) + size_t(tx)] = static_cast<std::uint8_t>(bits);
    }
  }
  return out;
}

int finest_of(unsigned bits) { return std::countr_zero(bits); }

void merge_small_classes(TileClasses& classes, double min_fraction) {
  auto& count = classes.count;
  const auto least = static_cast<size_t>(std::ceil(min_fraction * double(classes.of_tile.size())));
  std::array<int, kClasses> into{};
  for (int k = 0; k < kClasses; ++k) into[size_t(k)] = k;
  for (int k = kClasses - 1; k > 0; --k) {
    const size_t n = count[size_t(k)];
    if (n == 0 || n >= least) continue;
    const ShadingRate r = kShadingRates[size_t(k)];
    int best = 0;
    for (int j = 1; j < kClasses; ++j) {
      const ShadingRate c = kShadingRates[size_t(j)];
      if (j == k || count[size_t(j)] < least || c.width > r.width || c.height > r.height) continue;
      if (c.width * c.height >
          kShadingRates[size_t(best)].width * kShadingRates[size_t(best)].height)
        best = j;
    }
    into[size_t(k)] = best;
    count[size_t(best)] += n;
    count[size_t(k)] = 0;
  }
  for (std::uint8_t& c : classes.of_tile) c = static_cast<std::uint8_t>(into[c]);
}

PixelRect tile_pixels(int tx, int ty, int tile, int width, int height) {
  return {tx * tile, ty * tile, std::min(width, (tx + 1) * tile),
          std::min(height, (ty + 1) * tile)};
}

void set_rates(const gpu::Program& p) {
  for (int k = 0; k < kClasses; ++k) {
    const ShadingRate r = kShadingRates[static_cast<size_t>(k)];
    const std::string e = "u_rates[" + std::to_string(k) + "]";
    p.set(e.c_str(), float(r.width), float(r.height));
  }
}

double native_radius(const ShadingRateImage& m, Vec2d c) {
  double r = 1e9;
  for (int ty = 0; ty < m.tiles_y; ++ty) {
    for (int tx = 0; tx < m.tiles_x; ++tx) {
      if (m.at(tx, ty) == ShadingRate{1, 1}) continue;
      const auto t = m.tile_rect(tx, ty);
      r = std::min(r, std::hypot(c.x - std::clamp(c.x, double(t[0]), double(t[2])),
                                 c.y - std::clamp(c.y, double(t[1]), double(t[3]))));
    }
  }
  return r;
}

void upload_classes(gpu::Texture& texture, std::array<int, 2>& grid, int gx, int gy,
                    const std::vector<std::uint8_t>& classes) {
  if (!texture || grid[0] != gx || grid[1] != gy) {
    texture = gpu::Texture::create_2d(GL_R8UI, gx, gy);
    texture.set_filter(GL_NEAREST, GL_NEAREST);
    grid = {gx, gy};
  }
  texture.upload(gx, gy, GL_RED_INTEGER, GL_UNSIGNED_BYTE, classes.data());
}

void copy_native_tiles(PassKit& kit, const std::vector<PixelRect>& rects,
                       const gpu::RenderTarget& src, const gpu::RenderTarget& target) {
  if (rects.empty()) return;
  if (target.color().id() != 0 && target.color().format() == src.color().format() &&
      target.width() == src.width() && target.height() == src.height()) {
    const gpu::ProfileScope timed("reconstruct_copy");
    for (const PixelRect& r : rects) {
      glCopyImageSubData(src.color().id(), GL_TEXTURE_2D, 0, r[0], r[1], 0, target.color().id(),
                         GL_TEXTURE_2D, 0, r[0], r[1], 0, r[2] - r[0], r[3] - r[1], 1);
    }
    return;
  }
  kit.rect_pass(kit.over_rects("vrs/reconstruct_copy.frag"), rects, target, {},
                [&](const gpu::Program& p, gpu::Samplers& smp) {
                  smp.bind(p, "u_src", src.color());
                  p.set("u_extent", float(src.width()), float(src.height()));
                  p.set("u_shift", 0.0f, 0.0f);  // rate 1: samples at the pixel centres
                });
}

}  // namespace foveate::tech::vrs
