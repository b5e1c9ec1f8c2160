#pragma once
// Shading-rate images from the acuity model, for variable-rate shading (VRS):
// one rate per screen tile (1x1 .. 4x4 pixels per fragment shader invocation),
// recomputed from the gaze every frame, encoded for Vulkan
// (VK_KHR_fragment_shading_rate attachments), D3D12 (D3D12_SHADING_RATE) and
// OpenGL (GL_NV_shading_rate_image palette indices).
//
// When a rate "meets the MAR". The project's convention, shared by the layer
// planner and the checkerboard pattern, is two samples per resolvable cycle:
// the planner's sampling factor is s = w(e) / w*, with w* the angle of two
// native pixels (one cycle), so a layer pixel may subtend up to w(e) / 2; the
// checkerboard lets a gap of g pixels begin where the MAR spans at least 2 g
// pixels. Here likewise: a rate of rw x rh pixels is allowed in a tile when
//     rw * alpha_x <= w(e) / 2   and   rh * alpha_y <= w(e) / 2,
// where w(e) = m e + w0 is the MAR (degrees per cycle) at the eccentricity e
// of the tile's point nearest the gaze (the smallest angle from the gaze of
// any point of the tile: on a flat panel the point nearest in pixels, on a
// wide head-mounted field of view not always), less the latency travel (not below 0),
// and alpha_x, alpha_y are the exact angles one pixel step along x and along y
// subtends at the eye, taken at the tile's point where they are largest. On a
// flat image plane a pixel subtends less off the display centre, and less
// along the direction away from it, so away from the centre a horizontal step
// and a vertical step differ and anisotropic rates (2x1, 4x2, ...) can win.
// Through a lens (Display::lens, lens.hpp) the spacing may also be as coarse
// as one panel pixel where that is coarser than half the MAR (two samples per
// cycle the eye resolves or the panel shows): a spacing k along x at a point
// whose direction from the lens axis makes angle phi with x spans
// k sqrt(cos^2 phi / m_r^2 + sin^2 phi / m_t^2) panel pixels (m_r, m_t: buffer
// pixels per panel pixel radially and across), bounded over the tile by the
// least m_r, m_t of its view angles and its largest |cos phi|, |sin phi|.
// The chosen rate is the supported one with the fewest invocations (largest
// rw * rh) that is allowed; ties go to the rate with more headroom. 1x1 is
// always allowed (it is native).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "foveate/core/acuity.hpp"
#include "foveate/core/display.hpp"

namespace foveate {

/// Pixels covered by one fragment shader invocation: width x height, each 1, 2 or 4.
struct ShadingRate {
  int width = 1;
  int height = 1;
  friend bool operator==(ShadingRate a, ShadingRate b) = default;
  [[nodiscard]] int pixels() const { return width * height; }
  [[nodiscard]] std::string name() const;  ///< "2x4"
};

/// The rates of D3D12 tier 2 and of most Vulkan implementations, finest first.
inline constexpr std::array<ShadingRate, 7> kShadingRates = {
    ShadingRate{1, 1}, ShadingRate{1, 2}, ShadingRate{2, 1}, ShadingRate{2, 2},
    ShadingRate{2, 4}, ShadingRate{4, 2}, ShadingRate{4, 4}};

/// The planning margin at which the model's rates alone, as an engine ships
/// one image per gaze, stay within 0.25 JOD of native on the built-in scenes
/// at 1920x1080 (`foveate tune` on vrs without its content-adaptive rates:
/// docs/fidelity.md). What `foveate rates` plans by default; the vrs
/// technique plans coarser (margin 1) and refines busy tiles frame by frame.
inline constexpr double kStaticRatesMargin = 1.5;

/// "1x1", "2x4", ...: one of kShadingRates; throws foveate::Error otherwise.
ShadingRate parse_shading_rate(const std::string& text);
/// A comma-separated list of rates ("1x1,2x2,4x4"); must contain 1x1, no repeats.
std::vector<ShadingRate> parse_shading_rates(const std::string& text);

enum class RateApi { Vulkan, D3D12, GlNv };
/// "vulkan", "d3d12" or "gl-nv"; throws foveate::Error otherwise.
RateApi parse_rate_api(const std::string& text);
const char* rate_api_name(RateApi api);

/// The byte an API's shading-rate image holds for `rate`:
/// - Vulkan: the attachment texel value of VK_KHR_fragment_shading_rate
///   (Vulkan spec, "Attachment Fragment Shading Rate"): log2(width) << 2 |
///   log2(height), the same bits as the SPIR-V FragmentShadingRate flags
///   (Vertical2Pixels 1, Vertical4Pixels 2, Horizontal2Pixels 4, Horizontal4Pixels 8).
/// - D3D12: the D3D12_SHADING_RATE value (d3d12.h, "D3D12_SHADING_RATE
///   enumeration"): 1X1 0x0, 1X2 0x1, 2X1 0x4, 2X2 0x5, 2X4 0x6, 4X2 0x9, 4X4 0xa
///   (the same encoding as Vulkan's).
/// - GL_NV_shading_rate_image: an index into the palette of gl_nv_palette().
std::uint8_t encode_shading_rate(ShadingRate rate, RateApi api);
/// The palette the gl-nv bytes index, to pass to glShadingRateImagePaletteNV:
/// entry i is the GL_SHADING_RATE_* enum of kShadingRates[i]
/// (NV_shading_rate_image, "New Tokens"): 1_INVOCATION_PER_PIXEL 0x9565,
/// PER_1X2_PIXELS 0x9566, PER_2X1 0x9567, PER_2X2 0x9568, PER_2X4 0x9569,
/// PER_4X2 0x956A, PER_4X4 0x956B.
const std::array<unsigned, 7>& gl_nv_palette();

/// The tile sizes shading-rate images come in (Vulkan's and D3D12's
/// attachment texel sizes in common use; GL_NV_shading_rate_image's is 16).
inline constexpr std::array<int, 3> kShadingRateTiles = {8, 16, 32};
/// Whether `px` is one of kShadingRateTiles.
bool is_shading_rate_tile(int px);
/// kShadingRateTiles in words, for help and errors: "8, 16 or 32".
std::string shading_rate_tiles_text();

struct ShadingRateOptions {
  int tile_px = 16;                 ///< one of kShadingRateTiles
  double latency_travel_deg = 0.0;  ///< subtracted from every tile's eccentricity
  /// >= 1: every tile's eccentricity is divided by it first (a gaze tracker's
  /// fallback widens every fovea by this factor).
  double fovea_scale = 1.0;
  std::vector<ShadingRate> supported{kShadingRates.begin(), kShadingRates.end()};
  /// Where the tile grid is anchored and which tile row comes first: the
  /// top-left for Vulkan and D3D12 images, the bottom-left (the window
  /// origin) for OpenGL. A partial row, when the height is not a multiple of
  /// the tile, is the last row either way.
  bool origin_bottom_left = false;
  void validate() const;
};

/// Rates for every tile, rows in the order of the origin (row 0 at the top for
/// a top-left origin, at the bottom for a bottom-left one).
struct ShadingRateImage {
  int width_px = 0;
  int height_px = 0;
  int tile_px = 16;
  int tiles_x = 0;
  int tiles_y = 0;
  bool origin_bottom_left = false;
  std::vector<ShadingRate> rates;  ///< tiles_x * tiles_y, row-major

  [[nodiscard]] ShadingRate at(int tx, int ty) const {
    return rates[static_cast<size_t>(ty) * tiles_x + tx];
  }
  /// The tile's pixels in top-left screen coordinates: [x0, x1) x [y0, y1).
  [[nodiscard]] std::array<int, 4> tile_rect(int tx, int ty) const;
  /// The tile that holds top-left pixel (x, y).
  [[nodiscard]] std::array<int, 2> tile_of(int x, int y) const;
  /// Fraction of the screen's pixels shaded at `rate`.
  [[nodiscard]] double fraction(ShadingRate rate) const;
  /// Fragment shader invocations for one frame: per tile ceil(w / rw) * ceil(h / rh).
  [[nodiscard]] double shaded_samples() const;
  /// shaded_samples() / native pixels (1 = no saving).
  [[nodiscard]] double pixel_ratio() const;
  /// One byte per tile in the API's encoding, in the order of `rates`.
  [[nodiscard]] std::vector<std::uint8_t> encode(RateApi api) const;
};

/// The coarsest allowed supported rate for one tile (the rule above). `rect` is
/// [x0, x1) x [y0, y1) in top-left pixel coordinates.
ShadingRate tile_shading_rate(const Display& display, const AcuityModel& acuity, Vec2d gaze,
                              const std::array<int, 4>& rect, const ShadingRateOptions& options);

/// The shading-rate image of the whole display for this gaze (pixels, top-left
/// origin; a gaze off the screen is allowed). Throws foveate::Error for invalid
/// options or display.
ShadingRateImage shading_rate_image(const Display& display, const AcuityModel& acuity, Vec2d gaze,
                                    const ShadingRateOptions& options = {});

namespace detail {
/// What a tile's rate owes to the display alone: the largest angle (radians)
/// of one pixel step along x and along y over it, and through a lens the
/// coarsest spacing the panel still shows there (0 without one).
struct TileBounds {
  double ax = 0.0, ay = 0.0;
  double px = 0.0, py = 0.0;
};
}  // namespace detail

/// The same images for one display, acuity and set of options, for a gaze
/// that moves every frame: what each tile's rate owes to the display alone
/// (its pixel step angles, the panel through a lens) is worked out once, so
/// a new gaze costs one eccentricity per tile (far less than
/// shading_rate_image: docs/performance.md). The latency travel and fovea
/// scale are the gaze tracker's and are given per image. Throws
/// foveate::Error for invalid options, display or gaze.
class ShadingRatePlanner {
 public:
  ShadingRatePlanner(const Display& display, const AcuityModel& acuity,
                     const ShadingRateOptions& options = {});
  [[nodiscard]] ShadingRateImage image(Vec2d gaze, double latency_travel_deg = 0.0,
                                       double fovea_scale = 1.0) const;
  [[nodiscard]] const Display& display() const { return display_; }

 private:
  struct Tile {
    std::array<int, 4> rect;
    detail::TileBounds bounds;
  };
  Display display_;
  AcuityModel acuity_;
  ShadingRateOptions options_;
  ShadingRateImage blank_;  // sizes and grid, no rates
  std::vector<Tile> tiles_;
};

}  // namespace foveate
