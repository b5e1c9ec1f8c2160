// Temporal stability in the periphery: the "twinkling" that sparse peripheral
// sampling produces under camera motion (Guenter et al. 2012, section 4.2),
// measured against native rendering's own frame-to-frame change.
#include <cmath>
#include <numbers>
#include <utility>

#include "internal.hpp"

namespace foveate::metrics {

FlickerTracker::FlickerTracker(Display display, double min_ecc_deg)
    : display_(std::move(display)), min_ecc_deg_(min_ecc_deg) {}

void FlickerTracker::reset() {
  prev_ref_ = {};
  prev_test_ = {};
  sum_ref_ = sum_test_ = sum_excess_ = count_ = 0;
  pairs_ = 0;
}

void FlickerTracker::add(const Image& ref, const Image& test, Vec2d gaze_px) {
  detail::check_same_size(ref, test, "flicker");
  if (display_.width_px != ref.width || display_.height_px != ref.height) {
    display_ = display_.resized(ref.width, ref.height);
  }
  Map r = luminance_codes(ref);
  Map t = luminance_codes(test);
  if (prev_ref_.width == r.width && prev_ref_.height == r.height) {
    // Compare cosines instead of angles: e > min  <=>  cos e < cos min, with
    // cos e = a.b / (|a| |b|) for the rays a (pixel) and b (gaze) of Display.
    const double f = display_.eye_distance_px();
    const double cx = 0.5 * r.width, cy = 0.5 * r.height;
    const double bx = gaze_px.x - cx, by = gaze_px.y - cy;
    const double bn = std::sqrt(bx * bx + by * by + f * f);
    const double cmin = std::cos(min_ecc_deg_ * std::numbers::pi / 180.0);
    double sr = 0, st = 0, se = 0, n = 0;
    for (int y = 0; y < r.height; ++y) {
      const double ay = y + 0.5 - cy;
      for (int x = 0; x < r.width; ++x) {
        const double ax = x + 0.5 - cx;
        const double c = (ax * bx + ay * by + f * f) / (std::sqrt(ax * ax + ay * ay + f * f) * bn);
        if (!(c < cmin)) continue;
        const size_t i = static_cast<size_t>(y) * r.width + x;
        const double dr = double(r.values[i]) - prev_ref_.values[i];
        const double dt = double(t.values[i]) - prev_test_.values[i];
        sr += std::fabs(dr);
        st += std::fabs(dt);
        se += std::fabs(dt - dr);
        n += 1;
      }
    }
    sum_ref_ += sr;
    sum_test_ += st;
    sum_excess_ += se;
    count_ += n;
    ++pairs_;
  }
  prev_ref_ = std::move(r);
  prev_test_ = std::move(t);
}

double FlickerTracker::ratio() const {
  if (pairs_ == 0 || count_ == 0) return kNaN;
  if (sum_ref_ == 0.0) return sum_test_ == 0.0 ? 1.0 : kInf;
  return sum_test_ / sum_ref_;
}

double FlickerTracker::reference_change() const { return count_ > 0 ? sum_ref_ / count_ : kNaN; }
double FlickerTracker::test_change() const { return count_ > 0 ? sum_test_ / count_ : kNaN; }
double FlickerTracker::excess_change() const { return count_ > 0 ? sum_excess_ / count_ : kNaN; }

}  // namespace foveate::metrics
