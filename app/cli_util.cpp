#include "cli_util.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "foveate/core/error.hpp"
#include "foveate/core/parse.hpp"
#include "foveate/core/planner.hpp"

namespace foveate::app {

Size parse_size(const std::string& text, const std::string& option) {
  const auto x = text.find_first_of("xX");
  double w = 0, h = 0;
  if (x == std::string::npos || !parse_number(text.substr(0, x), w) ||
      !parse_number(text.substr(x + 1), h) || w != std::floor(w) || h != std::floor(h)) {
    throw Error(option + ": expected WIDTHxHEIGHT in pixels (e.g. 640x360), got '" + text + "'");
  }
  if (w < 1 || h < 1 || w > 16384 || h > 16384) {
    throw Error(option + ": each side must be 1..16384 pixels, got '" + text + "'");
  }
  return {static_cast<int>(w), static_cast<int>(h)};
}

double checked_margin(double margin) {
  if (!(margin >= 1.0 && margin <= 4.0)) {
    char got[32];
    std::snprintf(got, sizeof got, "%g", margin);
    throw Error(std::string("--margin: expected a factor from 1 to 4 (the techniques plan for an "
                            "acuity that many times finer than the one the metrics judge by), "
                            "got ") +
                got);
  }
  return margin;
}

AcuityModel acuity_from_options(const std::string& quality, std::optional<double> slope) {
  if (!quality.empty() && slope) throw Error("--quality and --slope: give one, not both");
  if (slope) return AcuityModel::with_slope(*slope);
  if (!quality.empty()) return AcuityModel::quality(quality);
  return AcuityModel::quality("A");
}

std::uint64_t parse_byte_size(const std::string& text, const std::string& option) {
  std::string t = text;
  for (const char* suffix : {"iB", "B", "ib", "b"}) {
    const std::string sfx(suffix);
    if (t.size() > sfx.size() && t.compare(t.size() - sfx.size(), sfx.size(), sfx) == 0) {
      t.resize(t.size() - sfx.size());
      break;
    }
  }
  double scale = 1.0;
  if (!t.empty()) {
    switch (std::toupper(static_cast<unsigned char>(t.back()))) {
      case 'K':
        scale = 1024.0;
        break;
      case 'M':
        scale = 1024.0 * 1024;
        break;
      case 'G':
        scale = 1024.0 * 1024 * 1024;
        break;
      case 'T':
        scale = 1024.0 * 1024 * 1024 * 1024;
        break;
      default:
        break;
    }
    if (scale > 1.0) t.pop_back();
  }
  double v = 0.0;
  if (!parse_number(t, v) || !(v * scale >= 1.0) || !(v * scale < 1.8e19)) {
    throw Error(option + ": expected a size in bytes such as 512M or 8G, got '" + text + "'");
  }
  return static_cast<std::uint64_t>(v * scale);
}

std::string fmt(double value, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, value);
  return buf;
}

Verbosity& verbosity() {
  static Verbosity v = Verbosity::Normal;
  return v;
}

SavingsCheck check_savings(const Display& display, const AcuityModel& acuity) {
  SavingsCheck c;
  auto bound = [&](const Display& d) {
    PlannerOptions opt;
    opt.layers = 3;
    opt.grid_step_deg = 0.1;
    return plan_layers(d, acuity, opt).pixel_ratio();
  };
  c.pixel_bound = bound(display);
  const Vec2d centre =
      display.principal_point();  // the optical axis (the centre, but on asymmetric HMD eyes)
  c.centre_ppd = display.pixels_per_degree(centre, centre);
  c.nothing_to_save = c.pixel_bound < 1.2;
  if (!c.nothing_to_save) return c;
  const double eye_ppd = 1.0 / acuity.w0_deg;
  std::string note =
      "at " + std::to_string(display.width_px) + "x" + std::to_string(display.height_px) + " the " +
      display.name + " display has " + fmt(c.centre_ppd, 1) +
      " pixels per degree at the centre, coarser than the eye resolves (" + fmt(eye_ppd, 0) +
      " at the fovea) over most of the field: the planner's pixel bound is " +
      fmt(c.pixel_bound, 2) + "x, so foveation has little or nothing to save";
  // The smallest common width, same aspect and field of view, that leaves
  // something to save.
  for (int width : {1280, 1920, 2560, 3840, 7680}) {
    if (width <= display.width_px) continue;
    const int height = std::max(
        1, static_cast<int>(std::lround(double(display.height_px) * width / display.width_px)));
    const Display bigger = display.resized(width, height);
    const double b = bound(bigger);
    if (b >= 1.5) {
      note += "; try --size " + std::to_string(width) + "x" + std::to_string(height) + " (bound " +
              fmt(b, 1) + "x)";
      break;
    }
  }
  note += " or a display with more pixels per degree or a wider field of view (e.g. hmd-quest3)";
  c.note = note;
  return c;
}

void note_savings(const Display& display, const AcuityModel& acuity) {
  static bool said = false;
  if (said || quiet()) return;
  const SavingsCheck c = check_savings(display, acuity);
  if (!c.nothing_to_save) return;
  said = true;
  std::fprintf(stderr, "foveate: note: %s\n", c.note.c_str());
}

std::string format_duration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "?";
  const long s = std::lround(seconds);
  if (s < 60) return std::to_string(s) + " s";
  char buf[64];
  if (s < 3600) {
    std::snprintf(buf, sizeof buf, "%ld min %02ld s", s / 60, s % 60);
  } else {
    std::snprintf(buf, sizeof buf, "%ld h %02ld min", s / 3600, (s % 3600) / 60);
  }
  return buf;
}

std::string lens_at_gaze(const Display& display, Vec2d gaze) {
  const Oversampling o = display.lens_oversampling(gaze);
  const PanelDensity p = display.panel_pixels_per_degree(gaze);
  char s[320];
  std::snprintf(
      s, sizeof s,
      "at the gaze (%.1f deg from the lens axis) the panel shows %.1f (radially) and %.1f "
      "(tangentially) pixels per degree, the buffer has %.2f and %.2f pixels per panel "
      "pixel",
      display.eccentricity_deg(display.principal_point(), gaze), p.radial, p.tangential, o.radial,
      o.tangential);
  return s;
}

}  // namespace foveate::app
