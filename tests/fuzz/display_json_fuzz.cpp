// Display JSON (--display FILE): a display that validates has finite geometry.
#include <cmath>

#include "foveate/core/display.hpp"
#include "foveate/core/json_read.hpp"
#include "fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  foveate::fuzz::expect_clean([&] {
    const foveate::Display d = foveate::Display::from_json(
        foveate::parse_json(foveate::fuzz::text(data, size), "fuzz"), "fuzz.json");
    const foveate::Vec2d centre{0.5 * d.width_px, 0.5 * d.height_px};
    foveate::fuzz::check(std::isfinite(d.eye_distance_px()) && d.eye_distance_px() > 0.0);
    foveate::fuzz::check(std::isfinite(d.half_fov_deg()) && std::isfinite(d.sharpness_deg()));
    foveate::fuzz::check(std::isfinite(d.eccentricity_deg({0.0, 0.0}, centre)));
    foveate::fuzz::check(std::isfinite(d.pixels_per_degree({0.0, 0.0}, centre)));
  });
  return 0;
}
