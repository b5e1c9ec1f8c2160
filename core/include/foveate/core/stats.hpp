#pragma once
// Small statistics shared by the benchmark and the gaze analysis.
#include <vector>

namespace foveate {

/// The q-quantile (0..1) of `values`, interpolating linearly between the
/// closest ranks; 0 for no values.
double quantile(std::vector<double> values, double q);

/// The arithmetic mean of `values`; 0 for no values.
double mean(const std::vector<double>& values);

}  // namespace foveate
