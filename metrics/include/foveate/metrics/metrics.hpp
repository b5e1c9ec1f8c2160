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
//  * The acuity-aware error splits linear luminance (the eye blurs light, not
//    code values) into half-octave bands, keeps at every pixel the bands the
//    eye resolves at its eccentricity, and compares the reconstructions in
//    luminance codes. The same bands, as local band-limited contrast weighted
//    by Barten's contrast sensitivity, give the visibility in JND units.
//  * Eccentricity comes from Display::eccentricity_deg at pixel centres
//    (x + 0.5, y + 0.5) and the gaze point in pixels.
#include <cstdint>
#include <limits>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <utility>
#include <vector>

#include "foveate/core/acuity.hpp"
#include "foveate/core/display.hpp"
#include "foveate/core/image.hpp"
#include "foveate/metrics/fvvdp.hpp"
#include "foveate/metrics/map.hpp"

namespace foveate::metrics {

struct BandStats {
  double from_deg = 0;         ///< inclusive
  double to_deg = kInf;        ///< exclusive; infinity for the outermost band
  double psnr_db = kNaN;       ///< +inf when identical inside the band; NaN when the band is empty
  double ssim = kNaN;          ///< mean of the SSIM map over the band; NaN when empty
  double pixels_fraction = 0;  ///< share of the image's pixels in the band
  double flip_mean = kNaN;     ///< mean FLIP over the band; NaN when not computed or empty
  double acuity_rmse = kNaN;   ///< acuity-filtered RMSE over the band (luminance codes)
  double jnd_mean = kNaN;      ///< mean pooled JND over the band
  double visible_fraction = kNaN;  ///< share of the band's pixels with pooled JND >= the threshold
  /// Mean linear luminance of the test over the reference's (1 = as bright;
  /// filtering in sRGB codes darkens a high-contrast periphery)
  double luminance_ratio = kNaN;
};

/// The acuity error and the JND against eccentricity, in bins of equal width:
/// bin i holds the pixels with eccentricity in [i bin_deg, (i + 1) bin_deg).
/// The vectors reach the bin of the largest eccentricity in the image; a bin
/// without pixels is NaN (0 in pixels_fraction).
struct EccentricityProfile {
  double bin_deg = 1.0;
  std::vector<double> pixels_fraction;  ///< share of the image's pixels in the bin
  std::vector<double> acuity_rmse;      ///< RMS acuity-filtered difference (luminance codes)
  std::vector<double> jnd_mean;         ///< mean pooled JND
};

/// How luminance differences become JNDs: the display's luminance and the
/// parameters of Barten's contrast sensitivity function (metrics/README.md).
struct ContrastModel {
  double peak_cd_m2 = 100.0;  ///< luminance of white (code 255), cd/m^2
  /// Luminance of black, including reflected ambient light, cd/m^2 (> 0): the
  /// display shows L = black + (peak - black) Y for linear luminance Y.
  double black_cd_m2 = 0.5;
  double field_deg = 10.0;    ///< X of Barten's CSF: the angular size of the field
  double pooling_beta = 4.0;  ///< Minkowski exponent of the pooling over bands
};

struct QualityReport {
  double psnr_db = kNaN;  ///< +inf for identical images
  double ssim = kNaN;
  std::vector<BandStats> bands;
  /// RMS difference of the acuity-filtered images, in 8-bit luminance codes.
  double acuity_rmse = kNaN;
  /// Mean pooled JND (jnd_map) over the image.
  double jnd_mean = kNaN;
  /// Share of pixels whose pooled JND is at least `jnd_threshold`.
  double visible_fraction = kNaN;
  /// Mean linear luminance of the test over the reference's.
  double luminance_ratio = kNaN;
  double jnd_threshold = 1.0;  ///< the threshold used (JND)
  double flip_mean = kNaN;     ///< NaN if not computed
  double flip_ppd = kNaN;      ///< pixels per degree FLIP was evaluated at (at the gaze)
  EccentricityProfile profile;
  ContrastModel contrast;  ///< the model the JNDs were computed with
  int width = 0;
  int height = 0;
};

struct QualityOptions {
  AcuityModel acuity;
  ContrastModel contrast;
  bool flip = true;
  /// Lower edges of the eccentricity bands in degrees, ascending; the last
  /// band extends to infinity. Pixels below the first edge belong to no band.
  std::vector<double> band_edges_deg{0, 5, 10, 20};
  /// Width of the bins of QualityReport::profile, degrees.
  double profile_bin_deg = 1.0;
  /// A pixel whose pooled JND reaches this counts as visibly different.
  double jnd_threshold = 1.0;
  /// QualitySeries also judges the sequence with FovVideoVDP (compare() does
  /// not: it judges one frame). Its eccentricity bands are band_edges_deg.
  bool fvvdp = true;
  FvvdpOptions fvvdp_options;
  /// QualitySeries: the per-frame measures (compare()) and flicker besides
  /// FovVideoVDP; off, FovVideoVDP alone (the summary's other figures stay NaN).
  bool diagnostics = true;
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
/// The outermost band's "to_deg" is null (infinity). Keys: see
/// docs/bench-json.md ("jnd_mean", "visible_fraction", "jnd_threshold",
/// "contrast_model", "eccentricity_profile" besides the older ones).
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

/// The finest detail the eye resolves at every pixel, as a frequency in cycles
/// per pixel: f_c = 1 / (w(e) ppd), w(e) = m e + w0 degrees per cycle (Guenter
/// et al. 2012, eq. 1) and ppd the display's pixels per degree at the pixel.
Map acuity_cutoff_map(const Display& display, Vec2d gaze_px, const AcuityModel& acuity);

/// The acuity filter's response to a grating of `frequency` at a pixel whose
/// cutoff is `cutoff`, both in cycles per pixel (the filter's ladder of
/// half-octave steps is fixed in cycles per pixel; where the cutoff falls
/// between two steps sets the value within these ranges): 1 below
/// 0.595 cutoff, >= 0.965 at 0.7 cutoff, 0.36..0.64 at the cutoff, <= 0.049 at
/// 1.4 cutoff, 0 from 1.68 cutoff (metrics/README.md). Throws unless cutoff > 0.
double acuity_response(double frequency, double cutoff);

/// The image's linear luminance low-passed per pixel to what the eye resolves
/// there (acuity_response at the pixel's acuity_cutoff_map), returned in
/// luminance codes. Implementation: a pyramid of half-octave bands (isotropic
/// low-passes by FFT on grids halved with a half-band filter), weighted per
/// pixel and summed; see metrics/README.md.
Map acuity_filtered(const Image& image, const Display& display, Vec2d gaze_px,
                    const AcuityModel& acuity);
/// acuity_filtered(reference) - acuity_filtered(test) at every pixel (codes).
Map acuity_difference(const Image& reference, const Image& test, const Display& display,
                      Vec2d gaze_px, const AcuityModel& acuity);

/// Barten's simplified contrast sensitivity function (P. G. J. Barten, "Contrast
/// Sensitivity of the Human Eye and Its Effects on Image Quality", 1999):
///   S(u) = a u exp(-b u) sqrt(1 + c exp(b u)),
///   a = 540 (1 + 0.7 / L)^-0.2 / (1 + 12 / (X (1 + u / 3)^2)),
///   b = 0.3 (1 + 100 / L)^0.15, c = 0.06,
/// u in cycles per degree, L the adapting luminance in cd/m^2, X the field
/// size in degrees. 1 / S is the threshold (Michelson) contrast. 0 for u <= 0.
double barten_csf(double u_cpd, double luminance_cd_m2, double field_deg);

/// Pooled visibility of the difference at every pixel in JND units: the
/// difference of the images' local band-limited contrasts (Peli 1990) in every
/// band of the acuity pyramid, times barten_csf at the band's centre frequency
/// and the local adapting luminance, weighted by the band's acuity weight and
/// pooled over bands with a Minkowski sum (ContrastModel::pooling_beta). A
/// grating of contrast 1 / S(u) gives 1. Identical images give exactly 0.
Map jnd_map(const Image& reference, const Image& test, const Display& display, Vec2d gaze_px,
            const QualityOptions& options = {});

/// Per-pixel LDR-FLIP (Andersson et al. 2020, "FLIP: A Difference Evaluator
/// for Alternating Images") in [0, 1] at `pixels_per_degree`.
Map flip_map(const Image& reference, const Image& test, double pixels_per_degree);

/// Band index of every pixel (0..edges-1), or 255 for pixels below the first edge.
std::vector<std::uint8_t> band_indices(const Map& eccentricity, const std::vector<double>& edges);

// ---- Temporal stability ------------------------------------------------------

/// Frame-to-frame change over one eccentricity band (luminance codes per pixel).
struct FlickerBand {
  double from_deg = 0;             ///< inclusive
  double to_deg = kInf;            ///< exclusive; infinity for the outermost band
  double reference_change = kNaN;  ///< mean |frame-to-frame change| of the reference frames
  double test_change = kNaN;       ///< the same for the test frames
  /// test_change in the last frame pair only: with a static camera, whether
  /// the technique has settled by the end of the sequence.
  double test_change_last = kNaN;
  double excess_change = kNaN;  ///< mean |test change - reference change| per pixel
  /// test_change / reference_change: 1 when neither changed, +inf when only the test did.
  double ratio = kNaN;
};

/// Temporal stability: feed consecutive frames of the reference (`ref`) and of
/// the technique (`test`) rendered with the same camera. Per eccentricity band
/// (current frame's gaze) and over the pixels beyond `min_ecc_deg`, the mean
/// absolute frame-to-frame change of the luminance codes is accumulated for
/// both. With a moving camera ratio() = test / reference says how much more
/// the technique flickers than the reference (1 = as stable); with a static
/// camera the test's change itself is the convergence of the technique (0 once
/// it has settled).
class FlickerTracker {
 public:
  /// The display is resized to the frames' size when it differs (same field
  /// of view). `band_edges_deg`: lower edges of the bands, ascending.
  explicit FlickerTracker(Display display = {}, double min_ecc_deg = 10.0,
                          std::vector<double> band_edges_deg = {0, 5, 10, 20});
  /// `stream`: frames of several views (a stereo pair's eyes) pooled in one
  /// tracker: each frame is compared with the last frame of its own stream.
  void add(const Image& ref, const Image& test, Vec2d gaze_px, int stream = 0);
  /// Beyond min_ecc_deg: test change / reference change over all frame pairs.
  /// NaN before two frames; 1 when neither changed; +inf when only the test changed.
  [[nodiscard]] double ratio() const;
  /// Mean absolute frame-to-frame change per peripheral pixel (luminance codes).
  [[nodiscard]] double reference_change() const;
  [[nodiscard]] double test_change() const;
  /// Mean |test change - reference change|: temporal change the reference does not have.
  [[nodiscard]] double excess_change() const;
  /// The same figures per eccentricity band (NaN where a band had no pixels).
  [[nodiscard]] std::vector<FlickerBand> bands() const;
  [[nodiscard]] int frame_pairs() const { return pairs_; }
  void reset();

 private:
  struct Sums {
    double ref = 0, test = 0, excess = 0, count = 0;
    double last_test = 0, last_count = 0;
  };
  Display display_;
  double min_ecc_deg_;
  std::vector<double> edges_;
  std::vector<std::pair<Map, Map>> prev_;  ///< per stream: the last reference and test frames
  Sums periphery_;
  std::vector<Sums> bands_;
  int pairs_ = 0;
};

// ---- Over a sequence of frames -----------------------------------------------

/// Frame-to-frame change over a sequence (the figures of FlickerTracker).
struct FlickerSummary {
  double ratio = kNaN;             ///< beyond 10 degrees: test_change / reference_change
  double reference_change = kNaN;  ///< reference's mean |frame-to-frame change| (luminance codes)
  double test_change = kNaN;       ///< the same for the test frames
  int frame_pairs = 0;             ///< consecutive frame pairs measured
  std::vector<FlickerBand> bands;  ///< per eccentricity band (QualityOptions::band_edges_deg)
};

/// Quality of a sequence of test frames against their reference frames.
struct QualitySummary {
  int frames = 0;  ///< frames compared
  /// False when QualityOptions::diagnostics was off: only FovVideoVDP was
  /// measured, `mean` and `flicker` hold nothing (to_json leaves them out).
  bool diagnostics = true;
  int identical_frames = 0;  ///< frames identical to their reference (infinite PSNR)
  /// Every number of QualityReport, over the image and per band, averaged over
  /// the frames: the mean of the finite per-frame values, +inf when there were
  /// none but some were +inf (PSNR of frames all identical, in the image or in
  /// the band), NaN when none was defined. PSNR is thereby averaged in dB over
  /// the frames that differ. The profile's bins are averaged the same way,
  /// bin by bin. width, height, jnd_threshold, the contrast model and the band
  /// edges are the frames' own (the same in every frame).
  QualityReport mean;
  FlickerSummary flicker;
  /// FovVideoVDP over the sequence (QualityOptions::fvvdp); with several
  /// streams (a stereo pair's eyes), the stream with the lowest JOD, and each
  /// stream's in `fvvdp_streams`.
  std::optional<FvvdpResult> fvvdp;
  std::vector<FvvdpResult> fvvdp_streams;
};

/// The quality of a sequence: every frame is compared with compare() and fed
/// to a FlickerTracker (with the options' bands); summary() averages the
/// reports over the frames. The reference may be native or a supersampled
/// frame; with a static camera the flicker figures measure convergence.
class QualitySeries {
 public:
  /// `display` must have the frames' size (Display::resized). Throws
  /// foveate::Error when the options are invalid.
  explicit QualitySeries(Display display, QualityOptions options = {},
                         double flicker_min_ecc_deg = 10.0);
  /// One frame: the reference image and the test image, rendered with the same
  /// inputs, and the gaze in pixels. Throws like compare(). Frames of
  /// several views (a stereo pair's eyes, the right one mirrored into the
  /// left's geometry) are pooled in one series with a `stream` each: the
  /// temporal figures compare each frame with the last of its own stream.
  void add(const Image& reference, const Image& test, Vec2d gaze_px, int stream = 0);
  /// Whether FovVideoVDP keeps the distortion maps of the coming frames.
  void set_fvvdp_heatmap(bool on);
  [[nodiscard]] QualitySummary summary() const;
  /// The per-frame reports, in the order added.
  [[nodiscard]] const std::vector<QualityReport>& reports() const { return reports_; }
  [[nodiscard]] int frames() const { return frames_; }
  [[nodiscard]] const Display& display() const { return display_; }
  [[nodiscard]] const QualityOptions& options() const { return options_; }
  /// About how many bytes a series holds at most while judging `frames`
  /// frames of one stream at width x height with `options`: FovVideoVDP's
  /// frames within its temporal filters' reach (test and reference) and
  /// its per-pixel tables and pyramids. Measured (docs/performance.md), not
  /// exact: for planning how many series fit in memory at once.
  [[nodiscard]] static double memory_estimate(int width, int height, int frames,
                                              const QualityOptions& options);

 private:
  Display display_;
  QualityOptions options_;
  std::vector<QualityReport> reports_;
  int frames_ = 0;
  FlickerTracker flicker_;
  std::vector<std::shared_ptr<Fvvdp>> fvvdp_;  ///< per stream
  bool fvvdp_heatmap_ = false;
};

/// The summary as JSON: to_json(summary.mean) (same keys and conventions as a
/// single report; "identical" is true when every frame was identical) plus
/// "frames", "identical_frames", "flicker_ratio", "flicker_reference_change",
/// "flicker_test_change" and "flicker_bands" (one object per band:
/// "from_deg", "to_deg", "reference_change", "test_change",
/// "test_change_last", "excess_change", "ratio"). Non-finite numbers are null.
/// With FovVideoVDP: "jod" (the sequence's JOD) and "fvvdp" (to_json of its
/// result; stereo: "fvvdp_streams" too); "jod" is null without it.
nlohmann::json to_json(const QualitySummary& summary);
/// What to_json wrote, read back (nulls become NaN, or +inf where to_json
/// writes infinity as null); images and heat maps are not in the JSON.
QualitySummary quality_summary_from_json(const nlohmann::json& j);
FvvdpResult fvvdp_result_from_json(const nlohmann::json& j);

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
