#pragma once
// The figures a benchmark derives from its measured frames.
#include <utility>
#include <vector>

#include "foveate/gpu/profiler.hpp"

namespace foveate::bench {

/// The 95 % bootstrap interval of mean(native) / mean(technique): frames
/// resampled in pairs (both rendered the same frames), fixed seed. With
/// fewer than two frames, the ratio itself at both ends.
std::pair<double, double> speedup_interval(const std::vector<double>& native_ms,
                                           const std::vector<double>& technique_ms);

/// Adds one frame's pass times to the running sums (by name, in the order
/// first seen), and the rest of the frame (time outside every timed pass)
/// as "other", kept last.
void add_pass_times(std::vector<gpu::PassTime>& sums, const std::vector<gpu::PassTime>& frame,
                    double frame_ms);

}  // namespace foveate::bench
