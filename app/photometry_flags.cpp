#include "photometry_flags.hpp"

#include <CLI/CLI.hpp>
#include <string>

#include "foveate/core/parse.hpp"

namespace foveate::app {

void add_photometry_flags(CLI::App& command, PhotometryOverrides& flags) {
  const Photometry d;
  command.add_option("--peak-luminance", flags.peak_cd_m2,
                     "Luminance of the display's white in cd/m^2 (default: the display's; " +
                         format_number(d.peak_cd_m2) + " for the presets)");
  command.add_option("--contrast-ratio", flags.contrast_ratio,
                     "The panel's contrast, white over black without ambient light (default: the "
                     "display's; " +
                         format_number(d.contrast_ratio) + ":1 for the presets)");
  command.add_option("--ambient-lux", flags.ambient_lux,
                     "Illuminance on the screen in lux (default: the display's; " +
                         format_number(d.ambient_lux) + " for desktops, 0 in headsets)");
  command.add_option("--reflectivity", flags.reflectivity,
                     "Share of the ambient light the screen reflects (default: the display's; " +
                         format_number(d.reflectivity) + ")");
}

std::string photometry_flag(const std::string& key) {
  if (key == "peak_cd_m2") return "--peak-luminance";
  if (key == "contrast_ratio") return "--contrast-ratio";
  if (key == "ambient_lux") return "--ambient-lux";
  if (key == "reflectivity") return "--reflectivity";
  return key;
}

Display with_photometry(Display display, const PhotometryOverrides& flags) {
  flags.apply_to(display.photometry);
  display.photometry.validate([](const char* key) { return photometry_flag(key); });
  return display;
}

}  // namespace foveate::app
