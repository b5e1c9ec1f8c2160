#include "foveate/bench/statistics.hpp"

#include <algorithm>
#include <random>

#include "foveate/core/stats.hpp"

namespace foveate::bench {

std::pair<double, double> speedup_interval(const std::vector<double>& native,
                                           const std::vector<double>& tech) {
  const size_t n = std::min(native.size(), tech.size());
  if (n < 2) {
    const double s = mean(native) / mean(tech);
    return {s, s};
  }
  std::mt19937 rng(12345);
  std::uniform_int_distribution<size_t> pick(0, n - 1);
  std::vector<double> ratios;
  std::vector<double> a(n), b(n);
  for (int r = 0; r < 1000; ++r) {
    for (size_t k = 0; k < n; ++k) {
      const size_t i = pick(rng);
      a[k] = native[i];
      b[k] = tech[i];
    }
    ratios.push_back(mean(a) / mean(b));
  }
  return {quantile(ratios, 0.025), quantile(ratios, 0.975)};
}

void add_pass_times(std::vector<gpu::PassTime>& sums, const std::vector<gpu::PassTime>& frame,
                    double frame_ms) {
  gpu::PassTime other{"other", 0.0};
  if (!sums.empty() && sums.back().name == "other") {
    other = sums.back();
    sums.pop_back();
  }
  double timed = 0;
  for (const gpu::PassTime& p : frame) {
    timed += p.ms;
    auto it = std::find_if(sums.begin(), sums.end(),
                           [&](const gpu::PassTime& s) { return s.name == p.name; });
    if (it == sums.end()) {
      sums.push_back(p);
    } else {
      it->ms += p.ms;
    }
  }
  other.ms += std::max(0.0, frame_ms - timed);
  sums.push_back(other);
}

}  // namespace foveate::bench
