#include "foveate/bench/savings.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "foveate/core/error.hpp"
#include "foveate/core/parse.hpp"
#include "foveate/core/planner.hpp"
#include "foveate/techniques/technique.hpp"

namespace foveate::bench {

double pixel_bound(const Display& display, const AcuityModel& acuity) {
  PlannerOptions opt;
  opt.layers = 3;
  opt.grid_step_deg = 0.1;
  try {
    return plan_layers(display, acuity, opt).pixel_ratio();
  } catch (const Error&) {
    return 1.0;  // no room for the layers
  }
}

double own_plan_margin(const std::string& technique) {
  for (const ParamDecl& p : technique_info(technique).params) {
    if (p.key == kPlanMarginKey) return p.value;
  }
  return 1.0;
}

double strictest_plan_margin(std::optional<double> margin,
                             const std::vector<std::string>& techniques) {
  if (margin) return *margin;
  double m = 1.0;
  for (const std::string& t : techniques.empty() ? technique_names() : techniques)
    m = std::max(m, own_plan_margin(t));
  return m;
}

SavingsCheck check_savings(const Display& display, const AcuityModel& acuity, double margin) {
  SavingsCheck c;
  const AcuityModel planned = acuity.finer(margin);
  c.margin = margin;
  c.pixel_bound = pixel_bound(display, planned);
  // The optical axis: the centre, but on asymmetric HMD eyes.
  const Vec2d centre = display.principal_point();
  c.centre_ppd = display.pixels_per_degree(centre, centre);
  c.nothing_to_save = c.pixel_bound < kLittleToSaveBound;
  if (!c.nothing_to_save) return c;
  const double eye_ppd = 1.0 / acuity.w0_deg;
  std::string note =
      "at " + std::to_string(display.width_px) + "x" + std::to_string(display.height_px) + " the " +
      display.name + " display has " + format_fixed(c.centre_ppd, 1) +
      " pixels per degree at the centre, coarser than the eye resolves (" +
      format_fixed(eye_ppd, 0) + " at the fovea) over most of the field: the planner's pixel " +
      "bound is " + format_fixed(c.pixel_bound, 2) + "x";
  if (margin != 1.0) {
    note += " at planning margin " + format_number(margin, 2) + " (" +
            format_fixed(pixel_bound(display, acuity), 2) + "x at margin 1)";
  }
  note += ", under " + format_fixed(kLittleToSaveBound, 1) +
          "x, so foveation has little or nothing to save and a technique may shade as much as "
          "native or more";
  // The smallest common width, same aspect and field of view, that leaves
  // something to save.
  bool suggested = false;
  for (int width : {1280, 1920, 2560, 3840, 7680}) {
    if (width <= display.width_px) continue;
    const int height = std::max(
        1, static_cast<int>(std::lround(double(display.height_px) * width / display.width_px)));
    const double b = pixel_bound(display.resized(width, height), planned);
    if (b >= kLittleToSaveBound) {
      note += "; try {size} " + std::to_string(width) + "x" + std::to_string(height) + " (bound " +
              format_fixed(b, 1) + "x)";
      suggested = true;
      break;
    }
  }
  note += std::string(suggested ? " or" : "; try") +
          " a display with more pixels per degree or a wider field of view (e.g. hmd-quest3)";
  c.note = {note, {"size"}};
  return c;
}

}  // namespace foveate::bench
