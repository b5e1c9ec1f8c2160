#include <algorithm>
#include <cmath>

#include "foveate/core/error.hpp"
#include "internal.hpp"

namespace foveate::metrics::detail {

namespace {

constexpr int kEncodeTableSize = 8192;

const std::vector<float>& encode_table() {
  static const std::vector<float> table = [] {
    std::vector<float> t(kEncodeTableSize + 2);
    for (int i = 0; i <= kEncodeTableSize + 1; ++i) {
      const double x = std::min(1.0, static_cast<double>(i) / kEncodeTableSize);
      t[i] = static_cast<float>(255.0 * linear_to_srgb(x));
    }
    return t;
  }();
  return table;
}

}  // namespace

const std::array<float, 256>& srgb_to_linear_table() {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; ++i) {
      const double c = i / 255.0;
      t[i] = static_cast<float>(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
    }
    return t;
  }();
  return table;
}

double linear_to_srgb(double x) {
  if (x <= 0.0) return 0.0;
  if (x >= 1.0) return 1.0;
  return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
}

float luminance_to_code(float linear) {
  const std::vector<float>& t = encode_table();
  const float s = std::clamp(linear, 0.0f, 1.0f) * kEncodeTableSize;
  const int i = std::min(static_cast<int>(s), kEncodeTableSize);
  const float f = s - static_cast<float>(i);
  return t[i] + f * (t[i + 1] - t[i]);
}

Map luminance_linear(const Image& image) {
  const auto& lin = srgb_to_linear_table();
  Map out(image.width, image.height);
  const size_t n = out.values.size();
  const std::uint8_t* p = image.rgba.data();
  for (size_t i = 0; i < n; ++i, p += 4) {
    out.values[i] = 0.2126f * lin[p[0]] + 0.7152f * lin[p[1]] + 0.0722f * lin[p[2]];
  }
  return out;
}

Kernel gaussian_kernel_radius(double sigma, int radius) {
  Kernel k;
  k.offset = -radius;
  k.w.resize(2 * radius + 1);
  double sum = 0;
  for (int i = -radius; i <= radius; ++i) {
    const double v = sigma > 0 ? std::exp(-0.5 * i * i / (sigma * sigma)) : (i == 0 ? 1.0 : 0.0);
    k.w[i + radius] = static_cast<float>(v);
    sum += v;
  }
  for (float& v : k.w) v = static_cast<float>(v / sum);
  return k;
}

Kernel gaussian_kernel(double sigma, bool decimate) {
  Kernel k;
  if (!decimate && sigma < 0.8) {
    const double a = 0.5 * sigma * sigma;
    k.w = {static_cast<float>(a), static_cast<float>(1.0 - 2.0 * a), static_cast<float>(a)};
    k.offset = -1;
    return k;
  }
  const int r = std::max(1, static_cast<int>(std::ceil(3.5 * sigma)));
  if (!decimate) return gaussian_kernel_radius(sigma, r);
  // Output sample i sits at input coordinate 2i + 0.5; tap n reads input
  // 2i - r + n, at distance (n - r - 0.5) from the output sample.
  k.stride = 2;
  k.offset = -r;
  k.w.resize(2 * r + 2);
  double sum = 0;
  for (int n = 0; n < 2 * r + 2; ++n) {
    const double d = n - r - 0.5;
    const double v = std::exp(-0.5 * d * d / (sigma * sigma));
    k.w[n] = static_cast<float>(v);
    sum += v;
  }
  for (float& v : k.w) v = static_cast<float>(v / sum);
  return k;
}

Map filter_rows(const Map& in, const Kernel& k) {
  const int w = in.width;
  const int ow = k.stride == 1 ? w : (w + 1) / 2;
  const int n = static_cast<int>(k.w.size());
  Map out(ow, in.height);
  // Padded row covering every input index the kernel touches.
  const int lo = k.offset;
  const int hi = k.stride * (ow - 1) + k.offset + n - 1;
  std::vector<float> pad(static_cast<size_t>(hi - lo + 1));
  const float* kw = k.w.data();
  for (int y = 0; y < in.height; ++y) {
    const float* row = &in.values[static_cast<size_t>(y) * w];
    for (int j = lo; j <= hi; ++j) pad[j - lo] = row[std::clamp(j, 0, w - 1)];
    float* o = &out.values[static_cast<size_t>(y) * ow];
    const float* p = pad.data();
    // Tap-outer loops: the inner loop runs over outputs and vectorises.
    if (k.stride == 1) {
      for (int t = 0; t < n; ++t) {
        const float c = kw[t];
        const float* q = p + t;
        for (int i = 0; i < ow; ++i) o[i] += c * q[i];
      }
    } else {
      for (int t = 0; t < n; ++t) {
        const float c = kw[t];
        const float* q = p + t;
        for (int i = 0; i < ow; ++i) o[i] += c * q[2 * i];
      }
    }
  }
  return out;
}

Map filter_cols(const Map& in, const Kernel& k) {
  const int h = in.height;
  const int w = in.width;
  const int oh = k.stride == 1 ? h : (h + 1) / 2;
  const int n = static_cast<int>(k.w.size());
  Map out(w, oh);
  for (int i = 0; i < oh; ++i) {
    float* o = &out.values[static_cast<size_t>(i) * w];
    for (int t = 0; t < n; ++t) {
      const int j = std::clamp(k.stride * i + k.offset + t, 0, h - 1);
      const float* r = &in.values[static_cast<size_t>(j) * w];
      const float c = k.w[t];
      for (int x = 0; x < w; ++x) o[x] += c * r[x];
    }
  }
  return out;
}

void check_same_size(const Image& a, const Image& b, const std::string& what) {
  if (a.empty() || b.empty()) throw Error(what + ": an image is empty");
  if (a.width != b.width || a.height != b.height) {
    throw Error(what + ": images differ in size: reference is " + std::to_string(a.width) + "x" +
                std::to_string(a.height) + ", test is " + std::to_string(b.width) + "x" +
                std::to_string(b.height));
  }
  const size_t need = static_cast<size_t>(a.width) * a.height * 4;
  if (a.rgba.size() != need || b.rgba.size() != need) {
    throw Error(what + ": image buffer does not match its size");
  }
}

}  // namespace foveate::metrics::detail
