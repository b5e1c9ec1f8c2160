#pragma once
// Whether foveation has anything to save at a display's pixels per degree.
// Below about 1280x720 on a desktop display the eye resolves more than the
// screen shows over most of the field, and every technique can only lose.
#include <optional>
#include <string>
#include <vector>

#include "foveate/bench/field_text.hpp"
#include "foveate/core/acuity.hpp"
#include "foveate/core/display.hpp"

namespace foveate::bench {

/// Below this pixel bound foveation has too little to save for its
/// overheads (a composite, a reconstruction, a second pass) to pay: at such
/// sizes the techniques shade about as much as native, or more.
inline constexpr double kLittleToSaveBound = 1.5;

/// The planner's pixel bound: native over planned pixels of Guenter et al.'s
/// three layers for `acuity` (0.1 deg grid); 1 when the display is too small
/// to hold the layers at all (every pixel is the fovea's).
double pixel_bound(const Display& display, const AcuityModel& acuity);

/// A technique's own planning margin (the default of its kPlanMarginKey
/// parameter; 1 for a technique without one, as native).
double own_plan_margin(const std::string& technique);
/// The margin the finest plan of a run is made at: `margin` when given,
/// else the largest own margin of `techniques` (empty: every registered
/// technique).
double strictest_plan_margin(std::optional<double> margin,
                             const std::vector<std::string>& techniques = {});

/// The planner's pixel bound at a planning margin and, when it is below
/// kLittleToSaveBound, a note with the figure and a size or display to try.
struct SavingsCheck {
  double pixel_bound = 1.0;      ///< native / planned pixels at `margin`
  double margin = 1.0;           ///< the planning margin the bound is for
  double centre_ppd = 0.0;       ///< pixels per degree at the screen centre
  bool nothing_to_save = false;  ///< pixel_bound < kLittleToSaveBound
  FieldText note;                ///< empty when there is something to save; names {size}
};

/// `display` is the display at the render size (Display::resized); the bound
/// is for the plan made for `acuity` made `margin` times finer (the
/// techniques plan for a finer acuity than the metrics judge by).
SavingsCheck check_savings(const Display& display, const AcuityModel& acuity, double margin = 1.0);

}  // namespace foveate::bench
