#include "foveate/bench/savings.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "foveate/core/parse.hpp"
#include "foveate/core/planner.hpp"

namespace foveate::bench {

SavingsCheck check_savings(const Display& display, const AcuityModel& acuity) {
  SavingsCheck c;
  auto bound = [&](const Display& d) {
    PlannerOptions opt;
    opt.layers = 3;
    opt.grid_step_deg = 0.1;
    return plan_layers(d, acuity, opt).pixel_ratio();
  };
  c.pixel_bound = bound(display);
  // The optical axis: the centre, but on asymmetric HMD eyes.
  const Vec2d centre = display.principal_point();
  c.centre_ppd = display.pixels_per_degree(centre, centre);
  c.nothing_to_save = c.pixel_bound < 1.2;
  if (!c.nothing_to_save) return c;
  const double eye_ppd = 1.0 / acuity.w0_deg;
  std::string note =
      "at " + std::to_string(display.width_px) + "x" + std::to_string(display.height_px) + " the " +
      display.name + " display has " + format_fixed(c.centre_ppd, 1) +
      " pixels per degree at the centre, coarser than the eye resolves (" +
      format_fixed(eye_ppd, 0) + " at the fovea) over most of the field: the planner's pixel " +
      "bound is " + format_fixed(c.pixel_bound, 2) +
      "x, so foveation has little or nothing to save";
  // The smallest common width, same aspect and field of view, that leaves
  // something to save.
  for (int width : {1280, 1920, 2560, 3840, 7680}) {
    if (width <= display.width_px) continue;
    const int height = std::max(
        1, static_cast<int>(std::lround(double(display.height_px) * width / display.width_px)));
    const double b = bound(display.resized(width, height));
    if (b >= 1.5) {
      note += "; try {size} " + std::to_string(width) + "x" + std::to_string(height) + " (bound " +
              format_fixed(b, 1) + "x)";
      break;
    }
  }
  note += " or a display with more pixels per degree or a wider field of view (e.g. hmd-quest3)";
  c.note = {note, {"size"}};
  return c;
}

}  // namespace foveate::bench
