#include "foveate/bench/session_options.hpp"

#include <cmath>
#include <cstdio>

#include "foveate/bench/field_text.hpp"
#include "foveate/gaze/gaze.hpp"

namespace foveate::bench {

namespace {

std::string printed(double value) {
  char got[32];
  std::snprintf(got, sizeof got, "%g", value);
  return got;
}

}  // namespace

AcuityModel acuity_from(const std::string& preset, std::optional<double> slope) {
  if (!preset.empty() && slope)
    throw OptionError("slope", FieldText{"{acuity_preset} and {slope}: give one, not both",
                                         {"acuity_preset", "slope"}});
  if (slope) return AcuityModel::with_slope(*slope);
  if (!preset.empty()) {
    try {
      return AcuityModel::preset(preset);
    } catch (const Error&) {
      throw OptionError("acuity_preset",
                        "expected A or B (Guenter et al.'s acuity presets), got '" + preset + "'");
    }
  }
  return AcuityModel::preset("A");
}

void check_margin(double margin) {
  if (!(margin >= 1.0 && margin <= 4.0)) {
    throw OptionError("margin",
                      "expected a factor from 1 to 4 (the techniques plan for an acuity that "
                      "many times finer than the one the metrics judge by), got " +
                          printed(margin));
  }
}

void validate(const SessionOptions& o) {
  const std::string& up = o.scene_options.up;
  if (!up.empty() && up != "y" && up != "z")
    throw OptionError("up", "expected y or z, got '" + up + "'");
  if (const std::string why = size_problem(o.size); !why.empty()) throw OptionError("size", why);
  // The gaze is on the output (stereo: the cyclopean view, one eye's size).
  for_field("gaze", [&] { gaze::check_gaze_spec(o.gaze, o.size.width, o.size.height); });
  if (o.margin) check_margin(*o.margin);
  if (!(o.fps > 0.0 && o.fps <= 10000.0)) {
    throw OptionError("fps", "expected a rate above 0 and at most 10000 frames per second, got " +
                                 printed(o.fps));
  }
  if (!std::isfinite(o.start_time_s)) throw OptionError("start_time_s", "must be finite");
  if (o.vergence_m && !o.stereo) {
    throw OptionError("vergence_m",
                      FieldText{"{vergence_m}: only with {stereo} (it sets where the two eyes "
                                "converge)",
                                {"vergence_m", "stereo"}});
  }
  if (o.vergence_m && !(*o.vergence_m > 0.0)) {
    throw OptionError("vergence_m",
                      "expected a distance in metres > 0 (or inf), got " + printed(*o.vergence_m));
  }
  check_frame_timeout(o.frame_timeout_s);
}

}  // namespace foveate::bench
