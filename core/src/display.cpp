#include "foveate/core/display.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <numbers>

#include "foveate/core/error.hpp"
#include "foveate/core/json_read.hpp"
#include "foveate/core/parse.hpp"

namespace foveate {

namespace {
constexpr double kDeg = 180.0 / std::numbers::pi;
constexpr double kRad = std::numbers::pi / 180.0;
constexpr int kMaxPixels = 65536;
constexpr double kMaxEdgeDeg = 85.0;  // an edge angle's bound (tan stays finite and sane)
double tan_deg(double a) { return std::tan(a * kRad); }
// An edge angle in degrees from a raw projection value (the tangent, as
// OpenVR's GetProjectionRaw and hmdq report it).
double edge_deg(double tangent) { return std::atan(tangent) * kDeg; }
}  // namespace

double Photometry::black_cd_m2() const {
  return ambient_lux / std::numbers::pi * reflectivity + peak_cd_m2 / contrast_ratio;
}

void Photometry::validate(const std::string& where) const {
  validate([&](const char* key) { return where + "." + key; });
}

void Photometry::validate(const std::function<std::string(const char* key)>& name) const {
  const auto check = [&](const char* key, double v, double min, double max, bool open_min) {
    if (!std::isfinite(v) || v > max || (open_min ? v <= min : v < min)) {
      throw Error(name(key) + ": must be in " + (open_min ? "(" : "[") + format_number(min) + ", " +
                  format_number(max) + "], got " + format_number(v));
    }
  };
  check("peak_cd_m2", peak_cd_m2, 0.0, 1e5, true);
  check("contrast_ratio", contrast_ratio, 1.0, 1e9, true);
  check("ambient_lux", ambient_lux, 0.0, 1e6, false);
  check("reflectivity", reflectivity, 0.0, 1.0, false);
  if (black_cd_m2() >= peak_cd_m2) {
    throw Error(name("peak_cd_m2") +
                ": must exceed the black level with reflected ambient light (" +
                format_number(black_cd_m2()) + " cd/m^2), got " + format_number(peak_cd_m2));
  }
}

double Display::eye_distance_px() const {
  if (fov.set()) return width_px / (tan_deg(fov.right_deg) - tan_deg(fov.left_deg));
  if (head_mounted()) return 0.5 * width_px / std::tan(0.5 * fov_h_deg * kRad);
  return distance_mm * width_px / width_mm;
}

Vec2d Display::principal_point() const {
  if (!fov.set()) return {0.5 * width_px, 0.5 * height_px};
  const double l = tan_deg(fov.left_deg), r = tan_deg(fov.right_deg);
  const double u = tan_deg(fov.up_deg), d = tan_deg(fov.down_deg);
  // The left edge is -l focal lengths left of the axis; the top edge u above it.
  return {width_px * -l / (r - l), height_px * u / (u - d)};
}

double Display::horizontal_fov_deg() const {
  if (fov.set()) return fov.right_deg - fov.left_deg;
  return head_mounted() ? fov_h_deg : 0.0;
}

Display Display::mirrored() const {
  Display d = *this;
  d.fov = fov.mirrored();
  if (lens) d.lens = lens->mirrored();
  return d;
}

double Display::max_view_tan() const {
  const auto [cx, cy] = principal_point();
  const double dx = std::max(cx, width_px - cx), dy = std::max(cy, height_px - cy);
  return std::hypot(dx, dy) / eye_distance_px();
}

std::optional<OversamplingTable> Display::lens_oversampling_table() const {
  if (!lens) return std::nullopt;
  return OversamplingTable(*lens, eye_distance_px(), std::atan(max_view_tan()) * kDeg);
}

namespace {
// The view tangent of buffer `pixel` from the principal point.
double view_tan(const Display& d, Vec2d pixel) {
  const auto [cx, cy] = d.principal_point();
  return std::hypot(pixel.x - cx, pixel.y - cy) / d.eye_distance_px();
}
}  // namespace

PanelDensity Display::panel_pixels_per_degree(Vec2d pixel) const {
  if (!lens) throw Error("display '" + name + "': has no lens (panel_pixels_per_degree)");
  return lens->density_at_tan(view_tan(*this, pixel));
}

Oversampling Display::lens_oversampling(Vec2d pixel) const {
  if (!lens) return {};
  return lens->oversampling_at_tan(view_tan(*this, pixel), eye_distance_px());
}

double Display::displayed_pixel_angle_deg(Vec2d pixel) const {
  // The buffer's pixel angles at view tangent t: cos^2 / f radially, cos / f
  // tangentially (radians).
  const double t = view_tan(*this, pixel), f = eye_distance_px();
  const double c2 = 1.0 / (1.0 + t * t);
  double radial = c2 / f * kDeg, tangential = std::sqrt(c2) / f * kDeg;
  if (lens) {
    const PanelDensity p = lens->density_at_tan(t);
    radial = std::max(radial, 1.0 / p.radial);
    tangential = std::max(tangential, 1.0 / p.tangential);
  }
  return std::min(radial, tangential);
}

double Display::pixels_per_mm() const { return head_mounted() ? 0.0 : width_px / width_mm; }

int Display::long_axis_px() const { return std::max(width_px, height_px); }

double Display::aspect() const {
  return static_cast<double>(std::min(width_px, height_px)) / long_axis_px();
}

double Display::half_fov_deg() const {
  return std::atan(0.5 * long_axis_px() / eye_distance_px()) * kDeg;
}

double Display::sharpness_deg() const { return std::atan(2.0 / eye_distance_px()) * kDeg; }

double Display::eccentricity_deg(Vec2d pixel, Vec2d gaze) const {
  const double f = eye_distance_px();
  const auto [cx, cy] = principal_point();
  const double ax = pixel.x - cx, ay = pixel.y - cy, az = f;
  const double bx = gaze.x - cx, by = gaze.y - cy, bz = f;
  const double crx = ay * bz - az * by, cry = az * bx - ax * bz, crz = ax * by - ay * bx;
  const double cross = std::sqrt(crx * crx + cry * cry + crz * crz);
  const double dot = ax * bx + ay * by + az * bz;
  return std::atan2(cross, dot) * kDeg;
}

double Display::pixels_per_degree(Vec2d pixel, Vec2d gaze) const {
  double dx = pixel.x - gaze.x, dy = pixel.y - gaze.y;
  const double len = std::hypot(dx, dy);
  const double h = 0.5;
  if (len < h) {
    // At (or next to) the gaze point the angle grows like |t|: step away from the gaze.
    const Vec2d out{gaze.x + h, gaze.y};
    return h / eccentricity_deg(out, gaze);
  }
  dx /= len;
  dy /= len;
  const double e1 = eccentricity_deg({pixel.x + dx * h, pixel.y + dy * h}, gaze);
  const double e0 = eccentricity_deg({pixel.x - dx * h, pixel.y - dy * h}, gaze);
  return 2.0 * h / (e1 - e0);
}

double Display::radius_px_at(double eccentricity) const {
  return eye_distance_px() * std::tan(std::min(eccentricity, 89.9) * kRad);
}

Display Display::resized(int width, int height) const {
  Display d = *this;
  d.width_px = width;
  d.height_px = height;
  d.validate();
  return d;
}

void Display::validate() const {
  const std::string w = name.empty() ? "display" : "display '" + name + "'";
  validate_geometry();
  photometry.validate(w + ": photometry");
  if (!lens) return;
  if (!head_mounted()) {
    throw Error(w + ": lens needs a head-mounted display (fov_deg or fov_h_deg)");
  }
  lens->validate(w, max_view_tan());
}

void Display::validate_geometry() const {
  const std::string w = name.empty() ? "display" : "display '" + name + "'";
  if (width_px < 1 || width_px > kMaxPixels) {
    throw Error(w + ": width_px must be in [1, 65536], got " + std::to_string(width_px));
  }
  if (height_px < 1 || height_px > kMaxPixels) {
    throw Error(w + ": height_px must be in [1, 65536], got " + std::to_string(height_px));
  }
  if (!std::isfinite(ipd_mm) || ipd_mm < 0.0 || ipd_mm > 200.0) {
    throw Error(w + ": ipd_mm must be in (0, 200] (or 0 for a display without stereo), got " +
                format_number(ipd_mm));
  }
  if (fov.set()) {
    const std::pair<const char*, double> edges[] = {{"left", fov.left_deg},
                                                    {"right", fov.right_deg},
                                                    {"up", fov.up_deg},
                                                    {"down", fov.down_deg}};
    for (const auto& [key, a] : edges) {
      if (!std::isfinite(a) || std::abs(a) >= kMaxEdgeDeg) {
        throw Error(w + ": fov_deg." + key + " must be in (-85, 85) degrees, got " +
                    format_number(a));
      }
    }
    if (!(fov.right_deg > fov.left_deg)) {
      throw Error(w + ": fov_deg.right (" + format_number(fov.right_deg) +
                  ") must be greater than fov_deg.left (" + format_number(fov.left_deg) + ")");
    }
    if (!(fov.up_deg > fov.down_deg)) {
      throw Error(w + ": fov_deg.up (" + format_number(fov.up_deg) +
                  ") must be greater than fov_deg.down (" + format_number(fov.down_deg) + ")");
    }
    if (fov_h_deg != 0.0) throw Error(w + ": give either fov_h_deg or fov_deg, not both");
    return;
  }
  if (ipd_mm > 0.0) {
    throw Error(w + ": ipd_mm needs the per-eye angles fov_deg (a stereo head-mounted display)");
  }
  if (head_mounted()) {
    if (!std::isfinite(fov_h_deg) || fov_h_deg >= 179.0) {
      throw Error(w + ": fov_h_deg must be in (0, 179), got " + format_number(fov_h_deg));
    }
    return;
  }
  if (!std::isfinite(fov_h_deg) || fov_h_deg < 0.0) {
    throw Error(w + ": fov_h_deg must be in (0, 179) or 0 for a flat display, got " +
                format_number(fov_h_deg));
  }
  if (!std::isfinite(width_mm) || width_mm <= 0.0) {
    throw Error(w + ": width_mm must be > 0, got " + std::to_string(width_mm));
  }
  if (!std::isfinite(distance_mm) || distance_mm <= 0.0) {
    throw Error(w + ": distance_mm must be > 0, got " + format_number(distance_mm));
  }
}

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
    {
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
      v.push_back(d);
    }
    // hmd-quest2 with an EXAMPLE lens: Meta publishes no lens coefficients
    // for the Quest 2. The panel and its centre density are the Oculus
    // runtime's own (the same hmdq record: distorted viewport 1592x1664,
    // 1029.04 pixels per tangent at the centre); k1 = 0.778 (radius unit = one
    // tangent at the centre) is fitted so that the panel's left and right
    // edges fall on the view's edges (tangents 1.279942 and 1), which puts the
    // lens centre 856 px from the left edge; its height from the top edge
    // (tangent 1.110613). A one-coefficient fit, not Meta's lens.
    {
      Display d = v[3];  // hmd-quest2
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
      v.push_back(d);
    }
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

Display Display::from_json(const nlohmann::json& j, const std::string& where) {
  JsonReader r(j, where);
  Display d;
  d.name.clear();
  r.string("name", d.name);
  r.integer("width_px", d.width_px, 1, kMaxPixels);
  r.integer("height_px", d.height_px, 1, kMaxPixels);
  const bool has_fov = r.number("fov_h_deg", d.fov_h_deg, 1e-6, 178.999);
  const bool has_w = r.number("width_mm", d.width_mm, 1e-6, 1e7);
  const bool has_v = r.number("distance_mm", d.distance_mm, 1e-6, 1e7);
  const bool has_ipd = r.number("ipd_mm", d.ipd_mm, 1e-6, 200.0);
  const nlohmann::json* lens = r.get("lens");
  if (lens) d.lens = Lens::from_json(*lens, r.path("lens"));
  if (const nlohmann::json* photometry = r.get("photometry")) {
    if (!photometry->is_object()) throw Error(r.path("photometry") + ": expected an object");
    JsonReader p(*photometry, r.path("photometry"));
    p.number("peak_cd_m2", d.photometry.peak_cd_m2, 1e-9, 1e5);
    p.number("contrast_ratio", d.photometry.contrast_ratio, 1.0 + 1e-9, 1e9);
    p.number("ambient_lux", d.photometry.ambient_lux, 0.0, 1e6);
    p.number("reflectivity", d.photometry.reflectivity, 0.0, 1.0);
    p.finish();
  }
  const nlohmann::json* fov = r.get("fov_deg");
  if (fov) {
    if (!fov->is_object()) throw Error(r.path("fov_deg") + ": expected an object");
    JsonReader f(*fov, r.path("fov_deg"));
    const std::pair<const char*, double*> edges[] = {{"left", &d.fov.left_deg},
                                                     {"right", &d.fov.right_deg},
                                                     {"up", &d.fov.up_deg},
                                                     {"down", &d.fov.down_deg}};
    for (const auto& [key, out] : edges) {
      if (!f.number(key, *out, -kMaxEdgeDeg + 1e-9, kMaxEdgeDeg - 1e-9)) {
        throw Error(f.path(key) + ": required (degrees, OpenXR's XrFovf sign convention)");
      }
    }
    f.finish();
  }
  r.finish();
  if (!j.contains("width_px")) throw Error(r.path("width_px") + ": required");
  if (!j.contains("height_px")) throw Error(r.path("height_px") + ": required");
  if ((has_fov || fov) && (has_w || has_v)) {
    throw Error(where +
                ": give either fov_h_deg or fov_deg (head-mounted) or width_mm and distance_mm "
                "(flat), not both");
  }
  if (has_fov && fov) throw Error(where + ": give either fov_h_deg or fov_deg, not both");
  if (has_ipd && !fov) {
    throw Error(r.path("ipd_mm") +
                ": needs the per-eye angles fov_deg (a stereo head-mounted display)");
  }
  if (!has_fov && !fov) {
    if (!has_w) throw Error(r.path("width_mm") + ": required for a flat display");
    if (!has_v) throw Error(r.path("distance_mm") + ": required for a flat display");
  }
  d.validate();
  return d;
}

Display Display::load(const std::string& name_or_path) {
  for (const Display& d : presets()) {
    if (d.name == name_or_path) return d;
  }
  std::error_code ec;
  if (!std::filesystem::exists(name_or_path, ec)) {
    std::string names;
    for (const Display& d : presets()) names += (names.empty() ? "" : ", ") + d.name;
    throw Error("display '" + name_or_path + "': not a preset (" + names +
                ") nor an existing file");
  }
  Display d = from_json(read_json_file(name_or_path, "display JSON"), name_or_path);
  if (d.name.empty()) d.name = std::filesystem::path(name_or_path).stem().string();
  return d;
}

void to_json(nlohmann::json& j, const Display& d) {
  j = nlohmann::json{{"name", d.name}, {"width_px", d.width_px}, {"height_px", d.height_px}};
  if (d.fov.set()) {
    j["fov_deg"] = {{"left", d.fov.left_deg},
                    {"right", d.fov.right_deg},
                    {"up", d.fov.up_deg},
                    {"down", d.fov.down_deg}};
    if (d.ipd_mm > 0.0) j["ipd_mm"] = d.ipd_mm;
  } else if (d.head_mounted()) {
    j["fov_h_deg"] = d.fov_h_deg;
  } else {
    j["width_mm"] = d.width_mm;
    j["distance_mm"] = d.distance_mm;
  }
  if (d.lens) j["lens"] = *d.lens;
  j["photometry"] = {{"peak_cd_m2", d.photometry.peak_cd_m2},
                     {"contrast_ratio", d.photometry.contrast_ratio},
                     {"ambient_lux", d.photometry.ambient_lux},
                     {"reflectivity", d.photometry.reflectivity}};
}

}  // namespace foveate
