#include "photometry_flags.hpp"

#include <CLI/CLI.hpp>
#include <string>

#include "foveate/core/parse.hpp"

namespace foveate::app {

void add_photometry_flags(CLI::App& command, PhotometryFlags& flags) {
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

Display with_photometry(Display display, const PhotometryFlags& flags) {
  Photometry& p = display.photometry;
  if (flags.peak_cd_m2) p.peak_cd_m2 = *flags.peak_cd_m2;
  if (flags.contrast_ratio) p.contrast_ratio = *flags.contrast_ratio;
  if (flags.ambient_lux) p.ambient_lux = *flags.ambient_lux;
  if (flags.reflectivity) p.reflectivity = *flags.reflectivity;
  p.validate([](const char* key) -> std::string {
    const std::string k = key;
    if (k == "peak_cd_m2") return "--peak-luminance";
    if (k == "contrast_ratio") return "--contrast-ratio";
    if (k == "ambient_lux") return "--ambient-lux";
    if (k == "reflectivity") return "--reflectivity";
    return k;
  });
  return display;
}

}  // namespace foveate::app
