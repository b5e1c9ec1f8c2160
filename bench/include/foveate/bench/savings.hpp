#pragma once
// Whether foveation has anything to save at a display's pixels per degree.
// Below about 1280x720 on a desktop display the eye resolves more than the
// screen shows over most of the field, and every technique can only lose.
#include "foveate/bench/field_text.hpp"
#include "foveate/core/acuity.hpp"
#include "foveate/core/display.hpp"

namespace foveate::bench {

/// The planner's pixel bound (3 layers, at the acuity given) and, when it is
/// below 1.2x, a note with the figure and a size or display to try.
struct SavingsCheck {
  double pixel_bound = 1.0;      ///< native / planned pixels (Guenter et al., 3 layers)
  double centre_ppd = 0.0;       ///< pixels per degree at the screen centre
  bool nothing_to_save = false;  ///< pixel_bound < 1.2
  FieldText note;                ///< empty when there is something to save; names {size}
};

/// `display` is the display at the render size (Display::resized).
SavingsCheck check_savings(const Display& display, const AcuityModel& acuity);

}  // namespace foveate::bench
