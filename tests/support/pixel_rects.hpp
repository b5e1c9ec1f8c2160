#pragma once
// Whether a pixel lies in any of a list of rectangles (tests of covers and of
// the passes drawn over them).
#include <vector>

#include "foveate/techniques/rect_pass.hpp"

namespace foveate::test {

inline bool covered(const std::vector<tech::PixelRect>& rects, int x, int y) {
  for (const tech::PixelRect& r : rects)
    if (x >= r[0] && x < r[2] && y >= r[1] && y < r[3]) return true;
  return false;
}

}  // namespace foveate::test
