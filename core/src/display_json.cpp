// Displays as JSON: read from a preset's name or a file (with errors that
// name the file and the field), and written back.
#include <filesystem>
#include <nlohmann/json.hpp>

#include "display_units.hpp"
#include "foveate/core/display.hpp"
#include "foveate/core/error.hpp"
#include "foveate/core/json_read.hpp"

namespace foveate {

using display_units::kMaxEdgeDeg;
using display_units::kMaxPixels;

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
  d.source = name_or_path;
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
