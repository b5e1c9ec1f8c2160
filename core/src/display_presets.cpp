// The built-in displays: desktop monitors and head-mounted displays, with
// where each figure comes from.
#include <cmath>

#include "display_units.hpp"
#include "foveate/core/display.hpp"

namespace foveate {

using display_units::edge_deg;

namespace {

// Oculus Rift DK1, left eye, with its published lens: the Oculus SDK
// 0.2.x HMDInfo (SDK Overview 0.2.3): a 1280x800 panel 149.76 x 93.6 mm,
// EyeToScreenDistance 41 mm, LensSeparationDistance 63.5 mm,
// DistortionK {1, 0.22, 0.24, 0}, the distortion radius unit a quarter of
// the panel's width (320 px). The eye buffer is the SDK's: 1:1 with the
// panel at the lens centre (320 * 41 / 37.44 = 350.43 px per tangent) and
// scaled by its DistortionScale, the polynomial's scale at the panel's
// outer edge (fit point -1), 1.7147: 1097x1372, 61.0 deg out, 53.0 deg
// in, 62.9 deg up and down. The eyes sit on the lens axes (IPD = lens
// separation).
Display rift_dk1() {
  Lens dk1;
  dk1.panel_width_px = 640;
  dk1.panel_height_px = 800;
  dk1.radius_unit_px = 320.0;
  dk1.px_per_tan = 320.0 * 41.0 / (149.76 / 4.0);
  dk1.center_x_px = 320.0 + (149.76 / 4.0 - 63.5 / 2.0) * 1280.0 / 149.76;
  dk1.center_y_px = 400.0;
  dk1.k = {0.22, 0.24, 0.0};
  const double rho = dk1.center_x_px / dk1.radius_unit_px;  // the panel's outer edge
  const double scale = 1.0 + rho * rho * (dk1.k[0] + rho * rho * dk1.k[1]);
  const double t = scale / dk1.px_per_tan;  // view tangent per panel pixel, scaled
  Display d{"hmd-rift-dk1",
            static_cast<int>(std::lround(640.0 * scale)),
            static_cast<int>(std::lround(800.0 * scale)),
            0.0,
            0.0,
            0.0,
            FovAngles{edge_deg(-dk1.center_x_px * t), edge_deg((640.0 - dk1.center_x_px) * t),
                      edge_deg(400.0 * t), edge_deg(-400.0 * t)},
            63.5};
  d.lens = dk1;
  return d;
}

// hmd-quest2 with an EXAMPLE lens: Meta publishes no lens coefficients
// for the Quest 2. The panel and its centre density are the Oculus
// runtime's own (the same hmdq record: distorted viewport 1592x1664,
// 1029.04 pixels per tangent at the centre); k1 = 0.778 (radius unit = one
// tangent at the centre) is fitted so that the panel's left and right
// edges fall on the view's edges (tangents 1.279942 and 1), which puts the
// lens centre 856 px from the left edge; its height from the top edge
// (tangent 1.110613). A one-coefficient fit, not Meta's lens.
Display quest2_with_example_lens(const Display& quest2) {
  Display d = quest2;
  d.name = "hmd-quest2-lens";
  Lens q;
  q.panel_width_px = 1592;
  q.panel_height_px = 1664;
  q.px_per_tan = 1029.04;
  q.radius_unit_px = 1029.04;
  q.center_x_px = 856.0;
  q.center_y_px = 786.0;
  q.k = {0.778, 0.0, 0.0};
  d.lens = q;
  return d;
}

}  // namespace

const std::vector<Display>& Display::presets() {
  static const std::vector<Display> all = [] {
    std::vector<Display> v;
    // Guenter et al. section 5: LG W2363D, 1920x1080, W* = 51 cm, V* = 59 cm.
    v.push_back(Display{"desktop-1080p", 1920, 1080, 510.0, 590.0, 0.0});
    // A 27-inch 16:9 UHD monitor (597.7 mm wide) viewed from 60 cm.
    v.push_back(Display{"desktop-27-4k", 3840, 2160, 27.0 * 25.4 * 16.0 / std::hypot(16.0, 9.0),
                        600.0, 0.0});
    // Meta Quest 3, one eye: 2064x2208 panel, about 104 degrees horizontally
    // (modelled as a pinhole; real lenses distort).
    v.push_back(Display{"hmd-quest3", 2064, 2208, 0.0, 0.0, 104.0});
    // Stereo headsets, left eye (the right mirrors it). The figures are the
    // runtime's own, as recorded with hmdq in risa2000's HMD geometry
    // database (https://risa2000.github.io/hmdgdb/): the recommended per-eye
    // render target and the raw projection tangents (left, right, up, down).
    // Oculus Quest 2, Oculus runtime 1.53 (hmd_cfgs/Quest2_Native_R72.html):
    // 2352x2368, tangents -1.279942, 1.0, 1.110613, -1.191754 (52, 45, 48 and
    // 50 degrees), eye offsets +-31.75 mm.
    v.push_back(Display{
        "hmd-quest2", 2352, 2368, 0.0, 0.0, 0.0,
        FovAngles{edge_deg(-1.279942), edge_deg(1.0), edge_deg(1.110613), edge_deg(-1.191754)},
        63.5});
    // Pimax Crystal, OpenVR 1.26 (hmd_cfgs/PimaxCrystal_Native_R120.html):
    // 4312x5100, tangents -1.264092, 0.889501, 1.274264, -1.274264, reported
    // IPD 68.1 mm.
    v.push_back(Display{
        "hmd-pimax-crystal", 4312, 5100, 0.0, 0.0, 0.0,
        FovAngles{edge_deg(-1.264092), edge_deg(0.889501), edge_deg(1.274264), edge_deg(-1.274264)},
        68.1});
    v.push_back(rift_dk1());
    v.push_back(quest2_with_example_lens(v[3]));  // after hmd-quest2
    // Inside a headset no ambient light falls on the panel.
    for (Display& d : v) {
      if (d.head_mounted()) d.photometry.ambient_lux = 0.0;
    }
    return v;
  }();
  return all;
}

std::string Display::preset_names(bool stereo_only) {
  std::string out;
  for (const Display& d : presets()) {
    if (stereo_only && !d.stereo()) continue;
    if (!out.empty()) out += ", ";
    out += d.name;
  }
  return out;
}

}  // namespace foveate
