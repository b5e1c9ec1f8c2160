// What the benchmark's writers share (report_common.hpp).
#include "report_common.hpp"

#include <algorithm>

namespace foveate::bench {

double resolve_ms(const TechniqueResult& r) {
  const std::vector<std::string>& resolving = technique_info(r.technique).resolve_passes;
  double ms = 0;
  for (const gpu::PassTime& p : r.passes) {
    if (std::find(resolving.begin(), resolving.end(), p.name) != resolving.end()) ms += p.ms;
  }
  return ms;
}

std::string pass_list(const TechniqueResult& r, const char* unit) {
  std::string s;
  for (size_t i = 0; i < r.passes.size(); ++i) {
    const gpu::PassTime& p = r.passes[i];
    s += (i ? ", " : "") + p.name + ' ' + format_fixed(p.ms, 1) + unit + " (" +
         format_fixed(100 * p.ms / r.mean_ms, 0) + " %)";
  }
  return s;
}

}  // namespace foveate::bench
