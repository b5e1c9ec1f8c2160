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

std::string row_marks(const BenchResult& b, const TechniqueResult& r) {
  std::string marks;
  if (b.savings.nothing_to_save && r.technique != "native") marks += " †";
  if (!b.fallback_frames.empty()) marks += " ‡";
  return marks;
}

std::vector<std::string> mark_notes(const BenchResult& b) {
  std::vector<std::string> notes;
  if (b.savings.nothing_to_save) {
    notes.push_back("† Little to save: at " + std::to_string(b.options.session.size.width) + "x" +
                    std::to_string(b.options.session.size.height) +
                    " the planner's pixel bound is " + format_fixed(b.savings.pixel_bound, 2) +
                    "x (planning margin " + format_number(b.savings.margin, 2) + "), under " +
                    format_fixed(kLittleToSaveBound, 1) +
                    "x: a technique may shade as much as native or more, so these figures say "
                    "little about foveation; measure at a larger size.");
  }
  if (!b.fallback_frames.empty()) {
    std::string frames;
    for (size_t i = 0; i < b.fallback_frames.size(); ++i) {
      if (i == 8 && b.fallback_frames.size() > 9) {
        frames += ", ... (" + std::to_string(b.fallback_frames.size() - 8) + " more)";
        break;
      }
      frames += (i ? ", " : "") + std::to_string(b.fallback_frames[i]);
    }
    notes.push_back("‡ Gaze fallback: " + std::to_string(b.fallback_frames.size()) + " of " +
                    std::to_string(b.options.frames) + " measured frames (" + frames +
                    ", counted from 0) had the gaze off the image or in its fallback, where "
                    "every technique runs its fallback rather than foveation.");
  }
  return notes;
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
