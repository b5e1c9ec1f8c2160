#include "foveate/bench/frame_order.hpp"

#include <algorithm>
#include <numeric>
#include <random>

namespace foveate::bench {

std::vector<std::vector<size_t>> interleaved_orders(size_t runs, int frames) {
  std::vector<std::vector<size_t>> out;
  std::vector<size_t> order(runs);
  std::iota(order.begin(), order.end(), size_t{0});
  std::mt19937 shuffler(20261125u);
  for (int k = 0; k < frames; ++k) {
    std::shuffle(order.begin(), order.end(), shuffler);
    out.push_back(order);
  }
  return out;
}

}  // namespace foveate::bench
