#pragma once
// Image-quality metrics of a foveated frame against the native frame rendered
// with the same inputs. Pure C++ (no OpenGL).
//
// Conventions (see also docs in metrics/README.md):
//  * Images are 8-bit RGBA, sRGB-encoded; alpha is ignored everywhere.
//  * PSNR is over the three colour channels in 8-bit code values (peak 255).
//  * SSIM (Wang et al. 2004), the acuity-aware error and flicker work on
//    "luminance codes": CIE Y computed from the linearised sRGB channels
//    (Y = 0.2126 R + 0.7152 G + 0.0722 B), re-encoded with the sRGB curve to
//    0..255, i.e. the grey level that has the same luminance. For grey pixels
//    it equals the stored value.
//  * The acuity-aware error filters linear luminance (the eye blurs light, not
//    code values), then compares the filtered images in luminance codes.
//  * Eccentricity comes from Display::eccentricity_deg at pixel centres
//    (x + 0.5, y + 0.5) and the gaze point in pixels.
#include <cstdint>
#include <limits>
#include <nlohmann/json_fwd.hpp>
#include <vector>

#include "foveate/core/acuity.hpp"
#include "foveate/core/display.hpp"
#include "foveate/core/image.hpp"

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

struct BandStats {
  double from_deg = 0;         ///< inclusive
  double to_deg = kInf;        ///< exclusive; infinity for the outermost band
  double psnr_db = kNaN;       ///< +inf when identical inside the band; NaN when the band is empty
  double ssim = kNaN;          ///< mean of the SSIM map over the band; NaN when empty
  double pixels_fraction = 0;  ///< share of the image's pixels in the band
  double flip_mean = kNaN;     ///< mean FLIP over the band; NaN when not computed or empty
  double acuity_rmse = kNaN;   ///< acuity-filtered RMSE over the band (luminance codes)
};

struct QualityReport {
  double psnr_db = kNaN;  ///< +inf for identical images
  double ssim = kNaN;
  std::vector<BandStats> bands;
  /// RMS difference of the acuity-filtered images, in 8-bit luminance codes.
  double acuity_rmse = kNaN;
  /// Share of pixels whose acuity-filtered difference exceeds `acuity_threshold`.
  double acuity_visible_fraction = kNaN;
  double acuity_threshold = 0;  ///< the threshold used (luminance codes)
  double flip_mean = kNaN;      ///< NaN if not computed
  double flip_ppd = kNaN;       ///< pixels per degree FLIP was evaluated at (at the gaze)
  int width = 0;
  int height = 0;
};

struct QualityOptions {
  AcuityModel acuity;
  bool flip = true;
  /// Lower edges of the eccentricity bands in degrees, ascending; the last
  /// band extends to infinity. Pixels below the first edge belong to no band.
  std::vector<double> band_edges_deg{0, 5, 10, 20};
  /// A filtered difference above this many 8-bit luminance codes counts as
  /// visible (3 codes = 1.2 % of full scale; a conservative detection level).
  double visible_threshold = 3.0;
};

// ---- Whole-frame comparison -------------------------------------------------

/// Compares `test` against `reference` (same size). `display` must already have
/// the images' size (Display::resized); `gaze_px` is in pixels. Throws
/// foveate::Error when sizes differ, are empty, or the options are invalid.
QualityReport compare(const Image& reference, const Image& test, const Display& display,
                      Vec2d gaze_px, const QualityOptions& options = {});

/// The report as JSON. Non-finite numbers become null: an infinite PSNR is
/// written as "psnr_db": null with "identical": true (also per band), an
/// undefined value (empty band, FLIP not computed) as null with "identical": false.
/// The outermost band's "to_deg" is null (infinity).
nlohmann::json to_json(const QualityReport& report);

// ---- Individual metrics ------------------------------------------------------

/// Mean squared error over R, G and B in 8-bit code values.
double mse(const Image& reference, const Image& test);
/// 10 log10(255^2 / MSE); +inf for identical images.
double psnr_db(const Image& reference, const Image& test);
/// Per-pixel SSIM of the luminance codes: 11x11 Gaussian window, sigma 1.5,
/// K1 = 0.01, K2 = 0.03, L = 255 (Wang et al. 2004); edges are clamped.
Map ssim_map(const Image& reference, const Image& test);
/// Mean of ssim_map.
double ssim(const Image& reference, const Image& test);

/// Luminance codes (see top of file) of every pixel.
Map luminance_codes(const Image& image);

/// Display::eccentricity_deg of every pixel centre.
Map eccentricity_map(const Display& display, Vec2d gaze_px);

/// Standard deviation in pixels of the acuity low-pass at every pixel:
/// sigma = period / pi, with period = w(e) * ppd pixels per cycle the finest
/// resolvable detail. The Gaussian's response exp(-2 pi^2 sigma^2 f^2) is then
/// exp(-2) = 0.135 at the cutoff f = 1/period, 0.61 at half of it and
/// exp(-8) = 0.0003 at twice it.
Map acuity_sigma_map(const Display& display, Vec2d gaze_px, const AcuityModel& acuity);

/// The image's linear luminance low-passed per pixel to what the eye resolves
/// there, returned in luminance codes. Implementation: a Gaussian pyramid in
/// half-octave steps (sigma 0.5 * sqrt(2)^k px), each level kept at the coarsest
/// grid that still samples it well (grid step <= sigma), read back with bilinear
/// interpolation and blended between the two levels that bracket the pixel's
/// sigma so that the blended variance matches sigma^2.
Map acuity_filtered(const Image& image, const Display& display, Vec2d gaze_px,
                    const AcuityModel& acuity);
/// acuity_filtered(reference) - acuity_filtered(test) at every pixel (codes).
Map acuity_difference(const Image& reference, const Image& test, const Display& display,
                      Vec2d gaze_px, const AcuityModel& acuity);

/// Per-pixel LDR-FLIP (Andersson et al. 2020, "FLIP: A Difference Evaluator
/// for Alternating Images") in [0, 1] at `pixels_per_degree`.
Map flip_map(const Image& reference, const Image& test, double pixels_per_degree);

/// Band index of every pixel (0..edges-1), or 255 for pixels below the first edge.
std::vector<std::uint8_t> band_indices(const Map& eccentricity, const std::vector<double>& edges);

// ---- Temporal stability ------------------------------------------------------

/// Peripheral flicker: feed consecutive frames of native (`ref`) and of the
/// technique (`test`) rendered with the same camera. Over the pixels beyond
/// `min_ecc_deg` (current frame's gaze), the mean absolute frame-to-frame change
/// of the luminance codes is accumulated for both; ratio() = test / reference
/// (1 = as stable as native, above 1 = the periphery twinkles).
class FlickerTracker {
 public:
  /// The display is resized to the frames' size when it differs (same field of view).
  explicit FlickerTracker(Display display = {}, double min_ecc_deg = 10.0);
  void add(const Image& ref, const Image& test, Vec2d gaze_px);
  /// test change / reference change over all frame pairs. NaN before two
  /// frames; 1 when neither changed; +inf when only the test changed.
  [[nodiscard]] double ratio() const;
  /// Mean absolute frame-to-frame change per peripheral pixel (luminance codes).
  [[nodiscard]] double reference_change() const;
  [[nodiscard]] double test_change() const;
  /// Mean |test change - reference change|: temporal change native does not have.
  [[nodiscard]] double excess_change() const;
  [[nodiscard]] int frame_pairs() const { return pairs_; }
  void reset();

 private:
  Display display_;
  double min_ecc_deg_;
  Map prev_ref_, prev_test_;
  double sum_ref_ = 0, sum_test_ = 0, sum_excess_ = 0;
  double count_ = 0;
  int pairs_ = 0;
};

// ---- Over a sequence of frames -----------------------------------------------

/// Peripheral flicker over a sequence (the figures of FlickerTracker).
struct FlickerSummary {
  double ratio = kNaN;             ///< test_change / reference_change (FlickerTracker::ratio)
  double reference_change = kNaN;  ///< native's mean |frame-to-frame change| (luminance codes)
  double test_change = kNaN;       ///< the same for the test frames
  int frame_pairs = 0;             ///< consecutive frame pairs measured
};

/// Quality of a sequence of test frames against their reference frames.
struct QualitySummary {
  int frames = 0;            ///< frames compared
  int identical_frames = 0;  ///< frames identical to their reference (infinite PSNR)
  /// Every number of QualityReport, over the image and per band, averaged over
  /// the frames: the mean of the finite per-frame values, +inf when there were
  /// none but some were +inf (PSNR of frames all identical, in the image or in
  /// the band), NaN when none was defined. PSNR is thereby averaged in dB over
  /// the frames that differ. width, height, acuity_threshold and the band
  /// edges are the frames' own (the same in every frame).
  QualityReport mean;
  FlickerSummary flicker;
};

/// The quality of a sequence: every frame is compared with compare() and fed
/// to a FlickerTracker; summary() averages the reports over the frames.
class QualitySeries {
 public:
  /// `display` must have the frames' size (Display::resized). Throws
  /// foveate::Error when the options are invalid.
  explicit QualitySeries(Display display, QualityOptions options = {},
                         double flicker_min_ecc_deg = 10.0);
  /// One frame: the reference image and the test image, rendered with the same
  /// inputs, and the gaze in pixels. Throws like compare().
  void add(const Image& reference, const Image& test, Vec2d gaze_px);
  [[nodiscard]] QualitySummary summary() const;
  /// The per-frame reports, in the order added.
  [[nodiscard]] const std::vector<QualityReport>& reports() const { return reports_; }
  [[nodiscard]] int frames() const { return static_cast<int>(reports_.size()); }
  [[nodiscard]] const Display& display() const { return display_; }
  [[nodiscard]] const QualityOptions& options() const { return options_; }

 private:
  Display display_;
  QualityOptions options_;
  std::vector<QualityReport> reports_;
  FlickerTracker flicker_;
};

/// The summary as JSON: to_json(summary.mean) (same keys and conventions as a
/// single report; "identical" is true when every frame was identical) plus
/// "frames", "identical_frames", "flicker_ratio", "flicker_reference_change"
/// and "flicker_test_change". Non-finite numbers are null.
nlohmann::json to_json(const QualitySummary& summary);

// ---- Pictures for reports ----------------------------------------------------

/// Colour for t in [0, 1] on the heat scale (black, purple, red, orange, pale yellow).
void heat_color(double t, std::uint8_t rgb[3]);
/// Per-pixel maximum absolute channel difference (8-bit codes); `max_error`
/// maps to the top of the colour scale.
Image error_heatmap(const Image& reference, const Image& test, double max_error);
/// |acuity_difference| on the same colour scale.
Image acuity_error_heatmap(const Image& reference, const Image& test, const Display& display,
                           Vec2d gaze_px, const QualityOptions& options = {},
                           double max_error = 16.0);
/// Any map on the colour scale: value / max_value clamped to [0, 1].
Image heatmap(const Map& values, double max_value);

}  // namespace foveate::metrics
