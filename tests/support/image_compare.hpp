#pragma once
// Golden-image comparison with stated tolerances: the largest channel error,
// the mean channel error and the share of pixels off by more than a
// threshold. On failure the actual image and a difference image are written
// next to the test binary (FOVEATE_TEST_OUTPUT overrides the folder), and with
// FOVEATE_UPDATE_GOLDEN=1 the reference is rewritten instead.
#include <filesystem>
#include <string>

#include "foveate/core/display.hpp"  // Vec2d
#include "foveate/core/image.hpp"

namespace foveate::test {

struct Tolerance {
  int max_error = 48;           ///< largest channel difference (0..255)
  double mean_error = 0.5;      ///< mean channel difference
  int pixel_threshold = 16;     ///< a pixel "differs" when a channel is off by more
  double max_fraction = 0.005;  ///< share of differing pixels allowed
};

struct Comparison {
  bool size_matches = false;
  int max_error = 0;
  double mean_error = 0;
  double fraction = 0;
  [[nodiscard]] bool within(const Tolerance& t) const {
    return size_matches && max_error <= t.max_error && mean_error <= t.mean_error &&
           fraction <= t.max_fraction;
  }
};

Comparison compare_images(const Image& expected, const Image& actual, int pixel_threshold);
/// The same over the pixels whose centres lie within `radius` of `centre`
/// (by default with the golden tolerance's pixel threshold): a technique's
/// fovea against native.
Comparison compare_disc(const Image& a, const Image& b, Vec2d centre, double radius,
                        int pixel_threshold = Tolerance{}.pixel_threshold);
/// Absolute difference, amplified 4x, for inspection.
Image difference_image(const Image& expected, const Image& actual);

/// Where check_golden writes the actual and difference images of a failure:
/// FOVEATE_TEST_OUTPUT, else golden-failures/ in the working directory.
std::filesystem::path golden_failure_dir();

/// Compares `actual` with the PNG at `reference_path`; returns "" when within
/// tolerance, else a message naming the numbers and the files written.
std::string check_golden(const Image& actual, const std::string& reference_path,
                         const std::string& name, const Tolerance& tolerance = {});

}  // namespace foveate::test
