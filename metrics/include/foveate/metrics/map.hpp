#pragma once
// A single-channel float image, the type every per-pixel metric returns.
#include <cstddef>
#include <limits>
#include <vector>

namespace foveate::metrics {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
inline constexpr double kInf = std::numeric_limits<double>::infinity();

/// A single-channel float image, row-major.
struct Map {
  int width = 0;
  int height = 0;
  std::vector<float> values;

  Map() = default;
  Map(int w, int h, float fill = 0.0f)
      : width(w), height(h), values(static_cast<size_t>(w) * h, fill) {}
  [[nodiscard]] float& at(int x, int y) { return values[static_cast<size_t>(y) * width + x]; }
  [[nodiscard]] float at(int x, int y) const { return values[static_cast<size_t>(y) * width + x]; }
};

}  // namespace foveate::metrics
