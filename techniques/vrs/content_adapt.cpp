#include "content_adapt.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace foveate::tech::vrs {

namespace {

// sRGB bytes to linear light.
const std::array<float, 256>& linear_of_srgb() {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; ++i) {
      const double c = i / 255.0;
      t[size_t(i)] =
          static_cast<float>(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
    }
    return t;
  }();
  return table;
}

// Linear luminance (Rec. 709) of linear RGB.
float luminance(float r, float g, float b) { return 0.2126f * r + 0.7152f * g + 0.0722f * b; }

}  // namespace

static_assert(kShadingRates[kRefinedClass].width == 2 && kShadingRates[kRefinedClass].height == 2);
static_assert(kShadingRates[kClasses - 1].width == 4 && kShadingRates[kClasses - 1].height == 4);

bool smooth_texels(std::span<const std::uint8_t> rgba, int tw, int th, PixelRect texels,
                   double bound) {
  const auto& lin = linear_of_srgb();
  struct Texel {
    std::array<float, 3> c{};
    bool shaded = false;
  };
  const auto at = [&](int i, int j) {
    Texel t;
    if (i < 0 || j < 0 || i >= tw || j >= th) return t;
    const std::uint8_t* p = rgba.data() + (size_t(j) * size_t(tw) + size_t(i)) * 4;
    t.c = {lin[p[0]], lin[p[1]], lin[p[2]]};
    t.shaded = p[3] == 255;
    return t;
  };
  // How far `c` leaves the mean of `a` and `b`, in its luminance.
  const auto curvature = [&](const Texel& a, const Texel& c, const Texel& b) {
    if (!a.shaded || !b.shaded || !c.shaded) return 0.0;
    double most = 0.0;
    for (size_t k = 0; k < 3; ++k)
      most = std::max(most, std::abs(double(c.c[k]) - 0.5 * (double(a.c[k]) + b.c[k])));
    return most / std::max(double(luminance(c.c[0], c.c[1], c.c[2])), kSmoothDark);
  };
  if (!at(texels[0], texels[1]).shaded) return false;
  const int x1 = std::min(texels[2], tw), y1 = std::min(texels[3], th);
  for (int j = texels[1]; j < y1; ++j) {
    for (int i = texels[0]; i < x1; ++i) {
      const Texel c = at(i, j);
      if (curvature(at(i - 1, j), c, at(i + 1, j)) > bound ||
          curvature(at(i, j - 1), c, at(i, j + 1)) > bound)
        return false;
    }
  }
  return true;
}

bool adapt_refines(int k) {
  const ShadingRate r = kShadingRates[static_cast<size_t>(k)];
  return r.width == 4 || r.height == 4;
}

void ContentAdapt::reset(int gx, int gy) {
  gx_ = gx;
  gy_ = gy;
  hold_.assign(static_cast<size_t>(gx) * size_t(gy), 0);
  busy_.assign(hold_.size(), 0);
  smooth_found_.assign(hold_.size(), 0);
  coarse_.assign(hold_.size(), 0);
  coarsened_.assign(hold_.size(), 0);
}

void ContentAdapt::measure(std::span<const std::uint8_t> rgba, int tw, int th, ShadingRate rate,
                           const std::vector<std::uint8_t>& classes, int cls, bool refined_only,
                           int tile, int width, int height) {
  const auto& lin = linear_of_srgb();
  const auto at = [&](int i, int j) {
    return rgba.data() + (size_t(j) * size_t(tw) + size_t(i)) * 4;
  };
  const auto luminance_of = [&](const std::uint8_t* p) {
    return luminance(lin[p[0]], lin[p[1]], lin[p[2]]);
  };
  // Samples 4 pixels apart whatever the class, so that a tile refined to
  // 2x2 is judged as it was at 4x4.
  const int sx = std::max(1, 4 / rate.width), sy = std::max(1, 4 / rate.height);
  const auto differs = [&](const std::uint8_t* a, const std::uint8_t* b) {
    if (a[3] != 255 || b[3] != 255) return -1;  // either unshaded: no pair
    const float la = luminance_of(a), lb = luminance_of(b);
    return std::abs(la - lb) > static_cast<float>(contrast_) * std::max(la, lb) ? 1 : 0;
  };
  // `smooth` coarsens the 1x1 and 2x2 classes.
  const bool fine = (rate.width == 1 && rate.height == 1) || (rate.width == 2 && rate.height == 2);
  for (int ty = 0; ty < gy_; ++ty) {
    for (int tx = 0; tx < gx_; ++tx) {
      const size_t t = static_cast<size_t>(ty) * size_t(gx_) + size_t(tx);
      if (classes[t] != cls) continue;
      const PixelRect p = tile_pixels(tx, ty, tile, width, height);
      if (judged_smooth(t, fine)) {
        const PixelRect texels = {p[0] / rate.width, p[1] / rate.height,
                                  (p[2] - 1) / rate.width + 1, (p[3] - 1) / rate.height + 1};
        if (smooth_texels(rgba, tw, th, texels, (coarsened_[t] ? 4.0 : 1.0) * smooth_))
          smooth_found_[t] = 1;
      }
      if (refined_only && hold_[t] == 0) continue;
      int pairs = 0, differing = 0;
      for (int j = p[1] / rate.height; j <= (p[3] - 1) / rate.height && j < th; j += sy) {
        for (int i = p[0] / rate.width; i <= (p[2] - 1) / rate.width && i < tw; i += sx) {
          for (const auto [di, dj] : {std::array<int, 2>{sx, 0}, std::array<int, 2>{0, sy}}) {
            if (i + di >= tw || j + dj >= th) continue;
            const int d = differs(at(i, j), at(i + di, j + dj));
            if (d < 0) continue;
            ++pairs;
            differing += d;
          }
        }
      }
      if (share_ > 0.0 && pairs > 0 && differing >= share_ * pairs) busy_[t] = 1;
    }
  }
}

void ContentAdapt::mark(std::span<const std::uint8_t> busy,
                        const std::vector<std::uint8_t>& classes,
                        const std::array<bool, kClasses>& measured) {
  const size_t n = std::min({busy.size(), classes.size(), busy_.size()});
  for (size_t t = 0; t < n; ++t) {
    const int k = classes[t];
    if (k >= kClasses || !measured[static_cast<size_t>(k)]) continue;
    if ((busy[t] & 2u) && judged_smooth(t, k == 0 || k == kRefinedClass)) smooth_found_[t] = 1;
    if (!adapt_refines(k) && hold_[t] == 0) continue;
    if (busy[t] & 1u) busy_[t] = 1;
  }
}

std::vector<std::uint8_t> seen_by_neighbours(const std::vector<std::uint8_t>& classes,
                                             const std::vector<std::uint8_t>& refined) {
  std::vector<std::uint8_t> seen = classes;
  if (refined.size() != seen.size()) return seen;
  for (size_t t = 0; t < seen.size(); ++t)
    if (refined[t] && seen[t] == kRefinedClass) seen[t] = static_cast<std::uint8_t>(kClasses - 1);
  return seen;
}

bool ContentAdapt::any_held() const {
  return std::any_of(hold_.begin(), hold_.end(), [](int h) { return h > 0; });
}

void ContentAdapt::settle() {
  for (size_t t = 0; t < hold_.size(); ++t) {
    if (busy_[t])
      hold_[t] = hold_frames_;
    else if (hold_[t] > 0)
      --hold_[t];
    busy_[t] = 0;
    coarse_[t] = smooth_found_[t] && hold_[t] == 0;
    smooth_found_[t] = 0;
  }
}

bool ContentAdapt::judged_smooth(size_t t, bool fine) const {
  return smooth_ > 0.0 && (coarsened_[t] || (fine && hold_[t] == 0));
}

std::vector<std::uint8_t> ContentAdapt::coarsen(TileClasses& classes) {
  std::fill(coarsened_.begin(), coarsened_.end(), std::uint8_t{0});
  if (smooth_ <= 0.0 || classes.of_tile.size() != coarse_.size()) return {};
  bool any = false;
  for (size_t t = 0; t < coarse_.size(); ++t) {
    std::uint8_t& c = classes.of_tile[t];
    // coarse_ holds no tile that adapt holds refined (settle).
    if (!coarse_[t] || (c != 0 && c != kRefinedClass)) continue;
    const std::uint8_t to = c == 0 ? kRefinedClass : std::uint8_t(kClasses - 1);
    --classes.count[c];
    c = to;
    ++classes.count[to];
    coarsened_[t] = 1;
    any = true;
  }
  if (!any) return {};
  return coarsened_;
}

std::vector<std::uint8_t> ContentAdapt::refine(TileClasses& classes) const {
  if (classes.of_tile.size() != hold_.size()) return {};
  std::vector<std::uint8_t> refined(hold_.size(), 0);
  for (size_t t = 0; t < hold_.size(); ++t) {
    std::uint8_t& c = classes.of_tile[t];
    if (hold_[t] == 0 || !adapt_refines(c)) continue;
    --classes.count[c];
    c = kRefinedClass;
    ++classes.count[kRefinedClass];
    refined[t] = 1;
  }
  return refined;
}

}  // namespace foveate::tech::vrs
