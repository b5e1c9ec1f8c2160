// What the benchmark's writers share (report_common.hpp).
#include "report_common.hpp"

#include <algorithm>

#include "foveate/techniques/palette.hpp"

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

std::string run_colour(const BenchResult& b, const TechniqueResult& r) {
  int variant = 0;
  for (const TechniqueResult& o : b.results) {
    if (&o == &r) break;
    if (o.technique == r.technique) ++variant;
  }
  return technique_colour_hex(r.technique, variant);
}

std::string chart_div(const std::string& id, const std::string& svg) {
  return "<div class=\"chart\" id=\"" + id + "\">" + svg + "<a class=\"download\" href=\"" + id +
         ".svg\" download=\"" + id + ".svg\">download SVG</a></div>\n";
}

std::string cell(double v, int digits) { return format_significant(v, digits); }

}  // namespace foveate::bench
