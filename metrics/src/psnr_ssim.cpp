// PSNR over RGB code values and SSIM (Wang, Bovik, Sheikh, Simoncelli, "Image
// Quality Assessment: From Error Visibility to Structural Similarity", IEEE TIP
// 2004, eq. 13 with the Gaussian window of section III-C).
#include <cmath>

#include "internal.hpp"

namespace foveate::metrics {

Map luminance_codes(const Image& image) {
  Map m = detail::luminance_linear(image);
  for (float& v : m.values) v = detail::luminance_to_code(v);
  return m;
}

double mse(const Image& reference, const Image& test) {
  detail::check_same_size(reference, test, "mse");
  const size_t n = static_cast<size_t>(reference.width) * reference.height;
  const std::uint8_t* a = reference.rgba.data();
  const std::uint8_t* b = test.rgba.data();
  std::uint64_t sum = 0;
  for (size_t i = 0; i < n; ++i, a += 4, b += 4) {
    for (int c = 0; c < 3; ++c) {
      const int d = int(a[c]) - int(b[c]);
      sum += static_cast<std::uint64_t>(d * d);
    }
  }
  return static_cast<double>(sum) / (3.0 * static_cast<double>(n));
}

double psnr_db(const Image& reference, const Image& test) {
  const double e = mse(reference, test);
  if (e == 0.0) return kInf;
  return 10.0 * std::log10(255.0 * 255.0 / e);
}

Map ssim_map(const Image& reference, const Image& test) {
  detail::check_same_size(reference, test, "ssim");
  Map x = luminance_codes(reference);
  Map y = luminance_codes(test);
  // Moments about 128 keep the squares small for float accuracy.
  const size_t n = x.values.size();
  Map xx(x.width, x.height), yy(x.width, x.height), xy(x.width, x.height);
  for (size_t i = 0; i < n; ++i) {
    const float a = x.values[i] - 128.0f, b = y.values[i] - 128.0f;
    x.values[i] = a;
    y.values[i] = b;
    xx.values[i] = a * a;
    yy.values[i] = b * b;
    xy.values[i] = a * b;
  }
  const detail::Kernel g = detail::gaussian_kernel_radius(1.5, 5);  // 11 x 11, sigma 1.5
  const Map mx = detail::filter2d(x, g, g), my = detail::filter2d(y, g, g);
  const Map sxx = detail::filter2d(xx, g, g), syy = detail::filter2d(yy, g, g),
            sxy = detail::filter2d(xy, g, g);
  constexpr double c1 = (0.01 * 255) * (0.01 * 255);
  constexpr double c2 = (0.03 * 255) * (0.03 * 255);
  Map out(x.width, x.height);
  for (size_t i = 0; i < n; ++i) {
    const double ma = double(mx.values[i]), mb = double(my.values[i]);
    const double va = double(sxx.values[i]) - ma * ma, vb = double(syy.values[i]) - mb * mb;
    const double cab = double(sxy.values[i]) - ma * mb;
    const double ua = ma + 128.0, ub = mb + 128.0;
    const double s =
        ((2.0 * ua * ub + c1) * (2.0 * cab + c2)) / ((ua * ua + ub * ub + c1) * (va + vb + c2));
    out.values[i] = static_cast<float>(s);
  }
  return out;
}

double ssim(const Image& reference, const Image& test) {
  const Map m = ssim_map(reference, test);
  double s = 0;
  for (float v : m.values) s += v;
  return s / static_cast<double>(m.values.size());
}

}  // namespace foveate::metrics
