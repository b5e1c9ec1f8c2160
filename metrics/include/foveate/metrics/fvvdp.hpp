#pragma once
// FovVideoVDP: the visible-difference predictor for wide field-of-view video
// of R. K. Mantiuk, G. Denes, A. Chapiro, A. Kaplanyan, G. Rufo, R. Bachy,
// T. Lian and A. Patney, "FovVideoVDP: A visible difference predictor for wide
// field-of-view video", ACM Transactions on Graphics 40(4), article 49, 2021;
// version 1.2 of the metric with its published calibration (parameters
// 1.2.3 of 20/11/2021). It predicts how a test video (or image) differs from
// its reference for a viewer of a given display, in JOD: 10 means no visible
// difference, and between two results one JOD apart 75 % of observers
// prefer the higher. metrics/README.md describes the model.
//
// Frames are streamed: a sequence is fed frame by frame and only the 250 ms
// the temporal filters reach back are kept, so memory is bounded by the
// window, not by the length of the sequence.
#include <limits>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <vector>

#include "foveate/core/display.hpp"
#include "foveate/core/image.hpp"
#include "foveate/metrics/map.hpp"

namespace foveate::metrics {

struct FvvdpOptions {
  /// Sensitivity falls with eccentricity from the gaze (the foveated mode of
  /// the metric); false: foveal sensitivity everywhere.
  bool foveated = true;
  /// Frame rate of a sequence. A single frame is judged as an image.
  double fps = 60.0;
  /// Lower edges of the eccentricity bands (degrees from the gaze, ascending)
  /// of FvvdpResult::bands; the last band extends to infinity.
  std::vector<double> band_edges_deg{0, 5, 10, 20};
  /// Keep the distortion maps (FvvdpResult::heatmap and worst_heatmap);
  /// Fvvdp::set_heatmap changes it between frames.
  bool heatmap = false;
};

/// The quality of one eccentricity band: the JOD the whole sequence would
/// get were every part of the image as different as this band (the spatial
/// pooling is restricted to the band's pixels on every pyramid level).
struct FvvdpBand {
  double from_deg = 0;                                      ///< inclusive
  double to_deg = std::numeric_limits<double>::infinity();  ///< exclusive
  double jod = std::numeric_limits<double>::quiet_NaN();    ///< NaN when the band is empty
  double pixels_fraction = 0;  ///< share of the image's pixels in the band (full resolution)
};

struct FvvdpResult {
  double jod = std::numeric_limits<double>::quiet_NaN();
  int frames = 0;
  bool image = false;  ///< one frame, judged as an image (no temporal channels)
  double fps = 0;      ///< the sequence's frame rate (0 for an image)
  bool foveated = true;
  double pixels_per_degree = 0;  ///< at the display's centre, as the metric uses it
  Photometry photometry;         ///< the display's, as the metric used it
  std::vector<FvvdpBand> bands;
  /// The JOD each frame would get on its own (its pooled difference through
  /// the same mapping); the sequence's JOD comes from their mean difference.
  std::vector<double> frame_jod;
  /// With FvvdpOptions::heatmap: the distortion at every pixel in JOD below
  /// 10 (0 = invisible, 1 = one JOD), averaged over the frames judged with
  /// it, and the map of the one of them with the largest difference
  /// (worst_frame); empty when no frame was.
  Map heatmap;
  Map worst_heatmap;
  int worst_frame = -1;
};

/// The metric's parameters: the published calibration (FovVideoVDP 1.2,
/// parameters 1.2.3). Exposed so that tests and curious users can see them;
/// change them only to study the model.
struct FvvdpParameters {
  double mask_p = 2.4;                ///< exponent of the excitation of the masking model
  double mask_c = -0.973838;          ///< log10 of the masking signal's coefficient (k)
  double mask_q_sustained = 2.43685;  ///< exponent of the inhibition, sustained channel
  double mask_q_transient = 4.946;    ///< exponent of the inhibition, transient channel
  double w_transient = 0.25;          ///< weight of the transient channel
  double beta = 1.52134;              ///< spatial pooling exponent
  double beta_t = 1.0;                ///< pooling over frames
  double beta_tch = 0.666092;         ///< pooling over the temporal channels
  double beta_sch = 1.0;              ///< pooling over the spatial bands
  double sustained_sigma = 0.5;       ///< sustained temporal filter, eq. 3
  double sustained_beta = 0.06;       ///< sustained temporal filter, eq. 3 (seconds)
  double csf_sigma = -1.5;            ///< stimulus size: 1.5 cycles of each band's frequency
  double sensitivity_correction_db = 16.2596;  ///< 20 log10 of the CSF's gain
  double jod_a = -0.0161713;                   ///< JOD regression, eq. 19: alpha
  double log_jod_exp = -0.2280;                ///< JOD regression, eq. 19: log10 of beta
  double k_cm = 0.604562;                      ///< effect of cortical magnification, eq. 11
  double transient_omega_hz = 5.0;  ///< temporal frequency the transient channel's CSF uses
};

/// Streams a test sequence and its reference through FovVideoVDP.
class Fvvdp {
 public:
  /// `display` must have the frames' size (Display::resized); its geometry
  /// gives the pixels per degree at every pixel and its photometry the light.
  /// Throws foveate::Error when the options or the display are invalid.
  explicit Fvvdp(const Display& display, FvvdpOptions options = {},
                 FvvdpParameters parameters = {});
  ~Fvvdp();
  Fvvdp(const Fvvdp&) = delete;
  Fvvdp& operator=(const Fvvdp&) = delete;
  Fvvdp(Fvvdp&&) noexcept;
  Fvvdp& operator=(Fvvdp&&) noexcept;

  /// One frame of 8-bit sRGB-encoded pixels (alpha ignored), shown through the
  /// display's photometry, and the gaze in pixels (origin top-left; pixel
  /// centres at +0.5) that the foveated mode measures eccentricity from.
  /// Throws foveate::Error when a size differs from the display's.
  void add(const Image& test, const Image& reference, Vec2d gaze_px);
  /// The same for frames already in absolute luminance (cd/m^2).
  void add_luminance(const Map& test_cd_m2, const Map& reference_cd_m2, Vec2d gaze_px);
  /// The result so far; a single frame is judged as an image. Throws
  /// foveate::Error before the first frame.
  [[nodiscard]] FvvdpResult result() const;
  [[nodiscard]] int frames() const;
  /// Whether the coming frames keep their distortion maps (e.g. the last only).
  void set_heatmap(bool on);
  /// Whether frames of this size can be judged (at least 4 pixels on each side).
  static bool fits(int width, int height) { return width >= 4 && height >= 4; }
  /// Pixels per degree at the display's centre (the metric's band frequencies).
  [[nodiscard]] double pixels_per_degree() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

/// The result as JSON: "metric" (name and version), "jod", "frames", "image",
/// "fps", "foveated", "pixels_per_degree", "photometry" (with the derived
/// "black_cd_m2"), "bands" ("from_deg", "to_deg" (null: infinity), "jod" (null:
/// empty), "pixels_fraction") and "frame_jod". The heat maps are not included.
nlohmann::json to_json(const FvvdpResult& result);

/// One image pair (judged as an image).
FvvdpResult fvvdp_image(const Image& test, const Image& reference, const Display& display,
                        Vec2d gaze_px, const FvvdpOptions& options = {});

/// Luminance in cd/m^2 of every pixel of an sRGB image on the display: Y of
/// linear sRGB (Rec. 709 primaries) through Photometry.
Map display_luminance(const Image& image, const Photometry& photometry);
/// The same into `out`, reusing its storage.
void display_luminance(const Image& image, const Photometry& photometry, Map& out);

/// The metric's mapping from a pooled difference Q to JOD (eq. 19 of the
/// paper): 10 - (|a|^(1/b) Q)^b, b = 10^log_jod_exp.
double fvvdp_jod_from_difference(double q, const FvvdpParameters& parameters = {});

/// A distortion map (FvvdpResult::heatmap) as a picture: the reference in grey,
/// tinted green where the difference is invisible and through yellow to red
/// where it reaches `max_jod` JOD.
Image fvvdp_heatmap_image(const Map& distortion, const Image& reference, double max_jod = 1.0);

}  // namespace foveate::metrics
