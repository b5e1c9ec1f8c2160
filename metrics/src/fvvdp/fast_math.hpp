#pragma once
// Base-2 logarithm and exponential of floats without branches or calls, so
// that loops over planes vectorise: FovVideoVDP evaluates several powers per
// pixel and band, which through libm would dominate its time. Relative error
// below 1e-6 (tested against std::log2 / std::exp2 in FvvdpTest).
#include <bit>
#include <cstdint>

namespace foveate::metrics::fvvdp {

/// log2(x) for x > 0 (finite); inputs below 1e-30 are taken as 1e-30, so
/// that a zero gives a large negative number instead of -inf.
inline float fast_log2(float x) {
  x = x < 1e-30f ? 1e-30f : x;
  const std::uint32_t bits = std::bit_cast<std::uint32_t>(x);
  // x = m 2^e with m in [sqrt(1/2), sqrt(2)): shift the exponent boundary by
  // the mantissa bits of sqrt(1/2) (0x3f3504f3).
  const std::uint32_t shifted = bits - 0x3f3504f3u;
  const auto e = static_cast<float>(static_cast<std::int32_t>(shifted) >> 23);
  const float m = std::bit_cast<float>((shifted & 0x007fffffu) + 0x3f3504f3u);
  // log(m) = 2 atanh(t), t = (m - 1) / (m + 1) in (-0.1716, 0.1716).
  const float t = (m - 1.0f) / (m + 1.0f);
  const float t2 = t * t;
  const float series =
      t *
      (2.0f + t2 * (2.0f / 3.0f + t2 * (2.0f / 5.0f + t2 * (2.0f / 7.0f + t2 * (2.0f / 9.0f)))));
  return e + series * 1.44269504088896341f;
}

/// 2^x; 0 below -126 and clamped at 2^127.
inline float fast_exp2(float x) {
  const bool underflow = x < -126.0f;
  x = x > 127.0f ? 127.0f : (x < -126.0f ? -126.0f : x);
  // Round to the nearest integer without a call: adding 1.5 * 2^23 leaves
  // the integer part in the mantissa's low bits.
  const float rounded = (x + 12582912.0f) - 12582912.0f;
  const float f = x - rounded;  // in [-0.5, 0.5]
  const float y = f * 0.693147180559945f;
  // e^y, Taylor to the 7th power: error below 6e-9 for |y| <= 0.347.
  const float p =
      1.0f +
      y * (1.0f + y * (0.5f + y * (1.0f / 6.0f +
                                   y * (1.0f / 24.0f +
                                        y * (1.0f / 120.0f + y * (1.0f / 720.0f + y / 5040.0f))))));
  const auto exponent = static_cast<std::int32_t>(rounded) + 127;
  const float scale = std::bit_cast<float>(static_cast<std::uint32_t>(exponent) << 23);
  return underflow ? 0.0f : p * scale;
}

}  // namespace foveate::metrics::fvvdp
