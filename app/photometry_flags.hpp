#pragma once
// --peak-luminance, --contrast-ratio, --ambient-lux and --reflectivity: the
// display's photometry (FovVideoVDP's display model) set on the command line
// over what the display preset or JSON says.
#include <optional>

#include "foveate/core/display.hpp"

namespace CLI {
class App;
}

namespace foveate::app {

struct PhotometryFlags {
  std::optional<double> peak_cd_m2;
  std::optional<double> contrast_ratio;
  std::optional<double> ambient_lux;
  std::optional<double> reflectivity;
};

void add_photometry_flags(CLI::App& command, PhotometryFlags& flags);
/// The display with the flags applied; a bad value is an Error naming its flag.
Display with_photometry(Display display, const PhotometryFlags& flags);

}  // namespace foveate::app
