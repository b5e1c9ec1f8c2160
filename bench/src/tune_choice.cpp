// The choice of foveate tune (tune.hpp): each technique's settings ranked
// over every scene it ran on, its front per scene, the combinations of
// single changes its search tries in stage 3 and the settings it times again
// in stage 5.
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "foveate/bench/tune.hpp"
#include "foveate/core/stats.hpp"

namespace foveate::bench {

using Params = std::map<std::string, double>;

namespace {

// Stage 3: a change that raises JOD by more than this is tried with the
// others like it at every lower margin (coarser plan). Not only the nearest
// ones: what a change buys grows as the plan coarsens (vrs's `adapt` refines
// more tiles at margin 1 than at 2), so the JOD it raised at the best point
// does not tell how far down it can carry the plan.
constexpr double kJodRaise = 0.02;

// The choice: settings within the bound whose speed is within kTuneSpeedTie
// of the fastest one's tie with it (tune.hpp); among them the one that keeps
// the most JOD (its worst distance below native, within kJodTie of the
// least), then the one that shades the fewest pixels (within kPixelTie),
// then the fastest.
constexpr double kJodTie = 0.01;
constexpr double kPixelTie = 0.005;

// Stage 5: settings within this share of the fastest one's speed are timed
// again together, at most kContenders of them per technique.
constexpr double kContenderShare = 0.85;
constexpr size_t kContenders = 3;

// Whether `a` differs from `b` in `key` alone.
bool differs_only_in(const Params& a, const Params& b, const std::string& key) {
  std::set<std::string> keys;
  for (const auto& [k, v] : a) keys.insert(k);
  for (const auto& [k, v] : b) keys.insert(k);
  for (const std::string& k : keys) {
    const auto ia = a.find(k), ib = b.find(k);
    const bool same = ia != a.end() && ib != b.end() && ia->second == ib->second;
    if (!same && k != key) return false;
  }
  // (A key absent from one is at its default there.)
  return a.count(key) != b.count(key) || (a.count(key) && a.at(key) != b.at(key));
}

// `to`'s `key` as in `from` (absent there: at its default, so absent here).
void take(Params& to, const Params& from, const std::string& key) {
  const auto it = from.find(key);
  if (it == from.end()) {
    to.erase(key);
  } else {
    to[key] = it->second;
  }
}

// A setting of a technique judged on every scene it was run on: whether it
// is within the bound on each, the geometric mean of its speedups, its worst
// distance below native, the mean of its pixel ratios.
struct RankedSetting {
  Params params;
  bool within = false;
  double speed = 0.0;
  double worst = 0.0;
  double pixels = 0.0;
};

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
    RankedSetting s{params, true, 0.0, -std::numeric_limits<double>::infinity(), 0.0};
    double log_speed = 0.0;
    for (const auto& [scene, p] : by_scene) {
      s.within = s.within && p->within_bound;
      log_speed += std::log(p->speedup);
      s.worst = std::max(s.worst, p->below_native);
      s.pixels += p->pixel_ratio / static_cast<double>(by_scene.size());
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

// Among the settings within the bound that tie with the fastest in speed
// (ranked: rank_settings' order, the fastest first and within the bound):
// the most JOD, then the fewest pixels, then the fastest.
const RankedSetting& tie_break(const std::vector<RankedSetting>& ranked) {
  std::vector<const RankedSetting*> tied;
  for (const RankedSetting& s : ranked) {
    if (s.within && s.speed >= (1.0 - kTuneSpeedTie) * ranked.front().speed) tied.push_back(&s);
  }
  double least_worst = std::numeric_limits<double>::infinity();
  for (const RankedSetting* s : tied) least_worst = std::min(least_worst, s->worst);
  std::erase_if(tied, [&](const RankedSetting* s) { return s->worst > least_worst + kJodTie; });
  double fewest = std::numeric_limits<double>::infinity();
  for (const RankedSetting* s : tied) fewest = std::min(fewest, s->pixels);
  std::erase_if(tied,
                [&](const RankedSetting* s) { return s->pixels > fewest * (1.0 + kPixelTie); });
  return *tied.front();  // still in order of speed
}

}  // namespace

const TunePoint* tune_best_point(const std::vector<TunePoint>& points, const std::string& scene,
                                 const std::string& technique, int stage) {
  const TunePoint* best = nullptr;
  for (const TunePoint& p : points) {
    if (p.scene != scene || p.technique != technique || (stage > 0 && p.stage != stage)) continue;
    if (!best) {
      best = &p;
    } else if (p.within_bound != best->within_bound) {
      if (p.within_bound) best = &p;
    } else if (p.within_bound ? p.speedup > best->speedup : p.below_native < best->below_native) {
      best = &p;
    }
  }
  return best;
}

std::vector<Params> tune_combinations(
    const std::vector<TunePoint>& stage2, const TunePoint& best,
    const std::vector<std::pair<std::string, std::vector<double>>>& axes) {
  std::vector<Params> out;
  Params combined = best.params, better = best.params;
  int changes = 0, raises = 0;
  for (const auto& [key, values] : axes) {
    if (key == kPlanMarginKey) continue;
    const TunePoint *gain = nullptr, *raise = nullptr;
    for (const TunePoint& p : stage2) {
      if (!differs_only_in(p.params, best.params, key)) continue;
      if (p.within_bound && p.speedup > best.speedup && (!gain || p.speedup > gain->speedup))
        gain = &p;
      if (p.jod > best.jod + kJodRaise && (!raise || p.jod > raise->jod)) raise = &p;
    }
    if (gain) {
      take(combined, gain->params, key);
      ++changes;
    }
    if (raise) {
      take(better, raise->params, key);
      ++raises;
    }
  }
  if (changes >= 2) out.push_back(combined);
  const auto margin = best.params.find(kPlanMarginKey);
  if (raises == 0 || margin == best.params.end()) return out;
  for (const auto& [key, values] : axes) {
    if (key != kPlanMarginKey) continue;
    const auto idx = std::find(values.begin(), values.end(), margin->second) - values.begin();
    for (std::ptrdiff_t j = idx - 1; j >= 0; --j) {
      Params p = better;
      p[kPlanMarginKey] = values[static_cast<size_t>(j)];
      out.push_back(p);
    }
  }
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

std::vector<std::map<std::string, double>> tune_contenders(const TuneResult& r,
                                                           const std::string& technique) {
  const std::vector<RankedSetting> ranked = rank_settings(r, technique);
  std::vector<Params> out;
  for (const RankedSetting& s : ranked) {
    if (!s.within || s.speed < kContenderShare * ranked.front().speed || out.size() == kContenders)
      break;
    out.push_back(s.params);
  }
  // One setting alone has nothing to be compared with.
  if (out.size() < 2) out.clear();
  return out;
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
    if (best->within) best = &tie_break(ranked);
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
