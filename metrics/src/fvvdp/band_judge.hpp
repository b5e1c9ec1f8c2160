#pragma once
// One frame through FovVideoVDP's spatial part: the Laplacian pyramid of the
// temporal channels, local contrast, the contrast sensitivity, the masking
// model and the pooling over each band's pixels.
#include <array>
#include <memory>
#include <vector>

#include "foveate/metrics/fvvdp.hpp"
#include "fvvdp/csf.hpp"
#include "fvvdp/geometry.hpp"
#include "fvvdp/kernels.hpp"

namespace foveate::metrics::fvvdp {

/// The channels of one frame, all of the frame's size: test and reference of
/// the sustained channel, then (video) test and reference of the transient one.
struct FrameChannels {
  std::vector<Map> planes;  ///< 2 (image) or 4 (video)
  [[nodiscard]] int temporal_channels() const { return static_cast<int>(planes.size()) / 2; }
};

/// What one frame contributes: for every band and temporal channel the mean
/// of D^beta over the band's samples, over all of them and per eccentricity
/// band (with the number of samples there).
struct FrameDifference {
  int bands = 0;
  std::vector<std::array<double, 2>> mean;                 ///< [band][channel]
  std::vector<std::vector<std::array<double, 2>>> by_ecc;  ///< [ecc band][band][channel]
  std::vector<std::vector<double>> ecc_samples;            ///< [ecc band][band]
  Map distortion;  ///< per pixel, in JOD below 10 (when asked for)
};

class BandJudge {
 public:
  BandJudge(const Display& display, const FvvdpOptions& options, const FvvdpParameters& parameters);
  ~BandJudge();
  BandJudge(BandJudge&&) noexcept;
  [[nodiscard]] double pixels_per_degree() const { return geometry_.pixels_per_degree(); }
  [[nodiscard]] int bands() const { return bands_; }
  [[nodiscard]] FrameDifference judge(const FrameChannels& frame, Vec2d gaze_px,
                                      bool want_distortion) const;
  /// Share of the full-resolution pixels in each eccentricity band for a gaze.
  [[nodiscard]] std::vector<double> ecc_band_fractions(Vec2d gaze_px) const;

 private:
  struct Scratch;
  void update_gaze(Vec2d gaze_px) const;
  void judge_band(int band, const std::vector<const Map*>& fine,
                  const std::vector<const Map*>& coarse, int temporal_channels,
                  FrameDifference& out, Map* distortion_band) const;

  FvvdpOptions options_;
  FvvdpParameters parameters_;
  int width_ = 0, height_ = 0;
  ViewGeometry geometry_;
  int bands_ = 0;
  std::array<std::shared_ptr<const SensitivityTable>, 2> tables_;
  /// Frequency position of every sample of every band (foveated mode).
  std::vector<std::vector<AxisPosition>> rho_positions_;
  std::unique_ptr<Scratch> scratch_;
};

}  // namespace foveate::metrics::fvvdp
