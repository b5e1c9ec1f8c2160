#pragma once
// layered's technique class, whose parts are spread over layered.cpp (the
// plan and each frame's layers), temporal.cpp (jitter history and the world
// points of stale layers) and composite.cpp (the layers put together).
#include <array>
#include <optional>
#include <string>

#include "foveate/core/planner.hpp"
#include "foveate/techniques/depth_regions.hpp"
#include "foveate/techniques/pass_kit.hpp"

namespace foveate::tech::layered {

inline constexpr int kMaxLayers = 6;
inline constexpr int kMaxSlots = 32;
inline constexpr GLenum kDisplayFormat = GL_RGBA16F;  // precision for the exponential blend

/// What one layer keeps from frame to frame.
struct LayerState {
  // This update's render, and the last N, one per jitter phase (layer j of
  // the array = phase j), into which it is copied after the temporal pass.
  gpu::RenderTarget spare;
  gpu::Texture ring;
  // The resolved layer (rgb, linear) and the pixel's count of consecutive
  // same-image samples (a), on the unjittered grid.
  std::array<gpu::RenderTarget, 2> display;
  int latest = 0;
  int updates = 0;  // since the rectangle last changed: the jitter phase is updates % N
  int slot_count = 0;
  bool valid = false;
  bool temporal = false;
  std::array<double, 4> rect{};  // unjittered x0, y0, w, h of the newest display
  std::array<int, 2> side{};
  Vec2d centre{};        // gaze of the newest render (GL pixels)
  double radius_px = 0;  // where the blend to the next layer starts (native pixels)
  std::optional<std::uint64_t> image_key;
  bool has_view_proj = false;
  std::array<float, 16> view_proj{};  // the scene camera of the newest render
  // The world points of the newest render (mesh scenes), to reproject the
  // layer on the frames it is not updated.
  gpu::RenderTarget positions;
  bool has_positions = false;
  gpu::RenderTarget warped;  // the display moved to this frame's camera (when stale)
  bool updated = false;      // this frame
  // The disc (screen pixels) left unshaded in the newest render, inside the
  // inner layer's radius `hole_from_px` around `hole_centre`; 0 = none.
  double hole_px = 0, hole_from_px = 0;
  Vec2d hole_centre{};
};

class Layered final : public Technique {
 public:
  Layered(const TechniqueConfig& c, const ParamValues& v);

  void reset() override {
    frames_ = 0;
    for (LayerState& st : state_) st.valid = false;
  }
  FrameStats render(Scene& scene, const FrameInput& frame, const GazeState& gaze,
                    const gpu::RenderTarget& target) override;
  // A half-rate layer is first rendered, then rendered with history to
  // reproject, then shown stale and warped: both phases, twice.
  [[nodiscard]] int settle_frames() const override { return half_rate_ ? 6 : 3; }
  std::vector<OverlayShape> overlay(const GazeState& gaze) const override;

 protected:
  std::vector<std::pair<std::string, double>> derived() const override;

 private:
  /// What every layer of one frame is rendered from.
  struct FrameFacts {
    int width = 0, height = 0;
    Vec2d gaze{};  ///< GL pixels
    std::optional<std::uint64_t> image_key;
    bool can_reproject = false;
  };
  /// Blend radius (where the coarser layer starts to show: e_i, native
  /// pixels) and the rendered half side and target side of an inner layer.
  struct InnerSize {
    double blend_from_px = 0;  ///< e_i on screen
    double half_px = 0;        ///< rendered half side, >= blend_from_px * (1 + transition)
    int side = 1;              ///< target pixels per side
  };

  /// The G-buffer's MSAA must be one this GL implementation supports.
  static void check_msaa(int samples);
  /// Temporal samples (jitter positions) per pixel of layer i.
  [[nodiscard]] int slots(size_t i) const;
  [[nodiscard]] InnerSize inner_size(size_t i, const GazeState& g) const;
  [[nodiscard]] std::string layer_label(size_t i) const;
  /// Whether layer i is rendered this frame (else shown stale).
  [[nodiscard]] bool updates_now(size_t i, const FrameInput& frame, const FrameFacts& f) const;
  /// Renders layer i; returns the fragments shaded.
  PixelCount render_layer(Scene& scene, size_t i, const GazeState& gaze, const FrameFacts& f);
  /// The layer's own pixels that the composite can show (view `v`).
  std::vector<PixelRect> shown_cover(size_t i, const View& v, bool every_frame,
                                     const FrameFacts& f);
  /// Resolves this update's samples (st.spare, taken at jittered view `jv`)
  /// with the layer's history into st.display, then files them in the ring.
  void accumulate(Scene& scene, LayerState& st, const View& jv, const std::array<double, 4>& rect,
                  int slots_i, int phase, bool same_image);
  /// Stores the world points of the layer's grid where it will be shown stale.
  void keep_positions(Scene& scene, LayerState& st, const View& jv,
                      const std::array<double, 4>& rect, bool will_be_stale);
  /// The layers, warped where stale, put together into `target`.
  void composite(Scene& scene, const gpu::RenderTarget& target);
  /// Stale layers moved to this frame's camera; each layer's texture to show.
  std::array<const gpu::Texture*, kMaxLayers> warp_stale_layers(Scene& scene);

  DepthRegions regions_;

  Display display_;
  double transition_;
  bool half_rate_, jitter_;
  int samples_;
  double history_;
  double history_screen_;
  bool reproject_;
  int msaa_;
  int layer_lod_;
  LayerPlan plan_;
  PassKit kit_;
  std::array<LayerState, kMaxLayers> state_;
  int frames_ = 0;
};

}  // namespace foveate::tech::layered
