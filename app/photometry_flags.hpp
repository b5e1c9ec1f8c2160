#pragma once
// --peak-luminance, --contrast-ratio, --ambient-lux and --reflectivity: the
// display's photometry (FovVideoVDP's display model) set on the command line
// over what the display preset or JSON says.
#include "foveate/core/display.hpp"

namespace CLI {
class App;
}

namespace foveate::app {

void add_photometry_flags(CLI::App& command, PhotometryOverrides& flags);
/// The display with the flags applied; a bad value is an Error naming its flag.
Display with_photometry(Display display, const PhotometryOverrides& flags);
/// The flag of a photometry field ("peak_cd_m2" -> "--peak-luminance").
std::string photometry_flag(const std::string& key);

}  // namespace foveate::app
