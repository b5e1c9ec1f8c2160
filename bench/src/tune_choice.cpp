// The choice of foveate tune (tune.hpp): each technique's settings ranked
// over every scene it ran on, and its front per scene.
#include "tune_choice.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "foveate/core/stats.hpp"

namespace foveate::bench {

using Params = std::map<std::string, double>;

// The technique's settings judged on every scene it ran on, best first: those
// within the bound on every scene by speed, then the others by how close
// they come.
std::vector<RankedSetting> rank_settings(const TuneResult& r, const std::string& technique) {
  std::map<Params, std::map<std::string, const TunePoint*>> settings;
  std::set<std::string> scenes;
  for (const TunePoint& p : r.points) {
    if (p.technique != technique) continue;
    settings[p.params][p.scene] = &p;
    scenes.insert(p.scene);
  }
  std::vector<RankedSetting> out;
  for (const auto& [params, by_scene] : settings) {
    if (by_scene.size() != scenes.size()) continue;  // not judged on every scene
    RankedSetting s{params, true, 0.0, -std::numeric_limits<double>::infinity()};
    double log_speed = 0.0;
    for (const auto& [scene, p] : by_scene) {
      s.within = s.within && p->within_bound;
      log_speed += std::log(p->speedup);
      s.worst = std::max(s.worst, p->below_native);
    }
    s.speed = std::exp(log_speed / static_cast<double>(by_scene.size()));
    out.push_back(s);
  }
  std::stable_sort(out.begin(), out.end(), [](const RankedSetting& a, const RankedSetting& b) {
    if (a.within != b.within) return a.within;
    return a.within ? a.speed > b.speed : a.worst < b.worst;
  });
  return out;
}

std::vector<TunePoint> tune_front(const TuneResult& r, const std::string& scene,
                                  const std::string& technique) {
  std::vector<TunePoint> pts;
  for (const TunePoint& p : r.points) {
    if (p.scene == scene && p.technique == technique && std::isfinite(p.jod)) pts.push_back(p);
  }
  std::vector<TunePoint> front;
  for (const TunePoint& p : pts) {
    const bool dominated = std::any_of(pts.begin(), pts.end(), [&](const TunePoint& q) {
      return q.speedup >= p.speedup && q.jod >= p.jod && (q.speedup > p.speedup || q.jod > p.jod);
    });
    if (!dominated) front.push_back(p);
  }
  std::sort(front.begin(), front.end(),
            [](const TunePoint& a, const TunePoint& b) { return a.speedup < b.speedup; });
  return front;
}

void choose_parameters(TuneResult& r) {
  r.chosen.clear();
  r.verdict.clear();
  std::set<std::string> techniques;
  for (const TunePoint& p : r.points) techniques.insert(p.technique);
  for (const std::string& t : techniques) {
    const std::vector<RankedSetting> ranked = rank_settings(r, t);
    const RankedSetting* best = ranked.empty() ? nullptr : &ranked.front();
    if (!best) {
      r.verdict[t] = "no setting was judged on every scene";
      continue;
    }
    r.chosen[t] = best->params;
    r.verdict[t] =
        best->within
            ? "within " + format_fixed(r.options.bound_jod, 2) + " JOD of native on every scene, " +
                  format_fixed(best->speed, 2) + "x (geometric mean)"
            : "no setting within the bound; the closest: " + format_fixed(best->worst, 3) +
                  " JOD below native at worst";
  }
}

}  // namespace foveate::bench
