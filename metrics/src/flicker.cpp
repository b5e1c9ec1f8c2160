// Temporal stability per eccentricity band: the "twinkling" that sparse
// peripheral sampling produces under camera motion (Guenter et al. 2012,
// section 4.2), measured against the reference's own frame-to-frame change,
// and, with a static camera, how far a temporally accumulating technique is
// from having converged.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "foveate/core/error.hpp"
#include "internal.hpp"

namespace foveate::metrics {

FlickerTracker::FlickerTracker(Display display, double min_ecc_deg,
                               std::vector<double> band_edges_deg)
    : display_(std::move(display)),
      min_ecc_deg_(min_ecc_deg),
      edges_(std::move(band_edges_deg)),
      bands_(edges_.size()) {
  for (size_t i = 0; i < edges_.size(); ++i) {
    if (!std::isfinite(edges_[i]) || edges_[i] < 0.0 || (i > 0 && edges_[i] <= edges_[i - 1])) {
      throw Error("flicker: band edges must be finite, >= 0 and ascending");
    }
  }
}

void FlickerTracker::reset() {
  prev_.clear();
  periphery_ = {};
  std::fill(bands_.begin(), bands_.end(), Sums{});
  pairs_ = 0;
}

void FlickerTracker::add(const Image& ref, const Image& test, Vec2d gaze_px, int stream) {
  detail::check_same_size(ref, test, "flicker");
  if (stream < 0 || stream > 15) throw Error("flicker: stream must be 0..15");
  if (prev_.size() <= static_cast<size_t>(stream)) prev_.resize(static_cast<size_t>(stream) + 1);
  Map& prev_ref = prev_[static_cast<size_t>(stream)].first;
  Map& prev_test = prev_[static_cast<size_t>(stream)].second;
  if (display_.width_px != ref.width || display_.height_px != ref.height) {
    display_ = display_.resized(ref.width, ref.height);
  }
  Map r = luminance_codes(ref);
  Map t = luminance_codes(test);
  if (prev_ref.width == r.width && prev_ref.height == r.height) {
    // Compare cosines instead of angles: e > a  <=>  cos e < cos a, with
    // cos e = a.b / (|a| |b|) for the rays a (pixel) and b (gaze) of Display.
    const double f = display_.eye_distance_px();
    // Rays from the eye on the principal point's normal (the image centre
    // unless a head-mounted eye's four angles put its axis elsewhere).
    const Vec2d axis = display_.principal_point();
    const double cx = axis.x, cy = axis.y;
    const double bx = gaze_px.x - cx, by = gaze_px.y - cy;
    const double bn = std::sqrt(bx * bx + by * by + f * f);
    const double deg = std::numbers::pi / 180.0;
    const double cmin = std::cos(min_ecc_deg_ * deg);
    // Band k holds cos e in (cos edge_(k+1), cos edge_k]; edges beyond 180
    // degrees never match.
    std::vector<double> cedge(edges_.size());
    for (size_t k = 0; k < edges_.size(); ++k) {
      cedge[k] = edges_[k] >= 180.0 ? -2.0 : std::cos(edges_[k] * deg);
    }
    Sums per;
    std::vector<Sums> band(edges_.size());
    for (int y = 0; y < r.height; ++y) {
      const double ay = y + 0.5 - cy;
      for (int x = 0; x < r.width; ++x) {
        const double ax = x + 0.5 - cx;
        const double c = std::min(
            1.0, (ax * bx + ay * by + f * f) / (std::sqrt(ax * ax + ay * ay + f * f) * bn));
        const size_t i = static_cast<size_t>(y) * r.width + x;
        const double dr = double(r.values[i]) - prev_ref.values[i];
        const double dt = double(t.values[i]) - prev_test.values[i];
        const double ar = std::fabs(dr), at = std::fabs(dt), ae = std::fabs(dt - dr);
        if (c < cmin) {
          per.ref += ar, per.test += at, per.excess += ae, per.count += 1;
        }
        // The last band whose lower edge the pixel reaches.
        int k = -1;
        while (k + 1 < static_cast<int>(cedge.size()) && !(c > cedge[k + 1])) ++k;
        if (k >= 0) {
          Sums& b = band[k];
          b.ref += ar, b.test += at, b.excess += ae, b.count += 1;
        }
      }
    }
    auto accumulate = [](Sums& total, const Sums& frame) {
      total.ref += frame.ref;
      total.test += frame.test;
      total.excess += frame.excess;
      total.count += frame.count;
      total.last_test = frame.test;
      total.last_count = frame.count;
    };
    accumulate(periphery_, per);
    for (size_t k = 0; k < band.size(); ++k) accumulate(bands_[k], band[k]);
    ++pairs_;
  }
  prev_ref = std::move(r);
  prev_test = std::move(t);
}

namespace {

double ratio_of(double test, double ref, double count) {
  if (count == 0) return kNaN;
  if (ref == 0.0) return test == 0.0 ? 1.0 : kInf;
  return test / ref;
}

}  // namespace

double FlickerTracker::ratio() const {
  if (pairs_ == 0) return kNaN;
  return ratio_of(periphery_.test, periphery_.ref, periphery_.count);
}

double FlickerTracker::reference_change() const {
  return periphery_.count > 0 ? periphery_.ref / periphery_.count : kNaN;
}
double FlickerTracker::test_change() const {
  return periphery_.count > 0 ? periphery_.test / periphery_.count : kNaN;
}
double FlickerTracker::excess_change() const {
  return periphery_.count > 0 ? periphery_.excess / periphery_.count : kNaN;
}

std::vector<FlickerBand> FlickerTracker::bands() const {
  std::vector<FlickerBand> out;
  for (size_t k = 0; k < bands_.size(); ++k) {
    const Sums& s = bands_[k];
    FlickerBand b;
    b.from_deg = edges_[k];
    b.to_deg = k + 1 < edges_.size() ? edges_[k + 1] : kInf;
    if (s.count > 0) {
      b.reference_change = s.ref / s.count;
      b.test_change = s.test / s.count;
      b.excess_change = s.excess / s.count;
      b.ratio = ratio_of(s.test, s.ref, s.count);
    }
    if (s.last_count > 0) b.test_change_last = s.last_test / s.last_count;
    out.push_back(b);
  }
  return out;
}

}  // namespace foveate::metrics
