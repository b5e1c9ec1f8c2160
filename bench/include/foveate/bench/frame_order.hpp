#pragma once
// The order in which the runs of a benchmark render each measured frame.
#include <cstddef>
#include <vector>

namespace foveate::bench {

/// For each of `frames` measured frames, a permutation of the `runs` runs:
/// shuffled anew every frame from a fixed seed (the same sequence every
/// run), so that no technique is always first or always follows the same
/// one (on llvmpipe a pass can pay for the one before it).
std::vector<std::vector<size_t>> interleaved_orders(size_t runs, int frames);

}  // namespace foveate::bench
