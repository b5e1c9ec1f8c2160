// The search of foveate tune (tune.hpp): candidates as explicit benchmark
// runs, stage by stage, per scene (the choice over every scene, stage 3's
// combinations and stage 5's contenders: tune_choice.cpp).
#include "foveate/bench/tune.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <set>

#include "foveate/bench/field_text.hpp"
#include "foveate/bench/sweep.hpp"

namespace foveate::bench {

namespace {

using Params = std::map<std::string, double>;

// A tuned parameter of a technique and the values tune tries.
struct Axis {
  std::string key;
  std::vector<double> values;
};

// The values tried for each of `technique`'s parameters, in declaration
// order (the margin first): TuneOptions::values' list where it gives one
// (TECHNIQUE.KEY before KEY; run_tune sorts them), else the declared values.
std::vector<Axis> axes_of(const std::string& technique, const TuneOptions& o) {
  std::vector<Axis> axes;
  for (const ParamDecl& d : technique_info(technique).params) {
    auto it = o.values.find(technique + "." + d.key);
    if (it == o.values.end()) it = o.values.find(d.key);
    if (it == o.values.end()) {
      if (!d.tune.empty()) axes.push_back({d.key, d.tune});
      continue;
    }
    axes.push_back({d.key, it->second});
  }
  return axes;
}

// A setting's parameters without those at their declared constant defaults
// (the margin, whose default is each technique's own, always kept), so that
// one setting has one name: layered at margin 1.5 and at margin 1.5 with
// layers=2 (its default) are one candidate, run once.
Params without_defaults(const std::string& technique, Params p) {
  for (const ParamDecl& d : technique_info(technique).params) {
    if (d.key == kPlanMarginKey || d.derive) continue;
    const auto it = p.find(d.key);
    if (it != p.end() && it->second == d.value) p.erase(it);
  }
  return p;
}

struct Candidate {
  std::string technique;
  Params params;
  bool operator<(const Candidate& o) const {
    return std::tie(technique, params) < std::tie(o.technique, o.params);
  }
};

// The techniques tuned: those asked for, or every registered one but native
// (a scene's benchmark leaves out those it cannot run).
std::vector<std::string> tuned_techniques(const TuneOptions& o) {
  std::vector<std::string> out;
  for (const std::string& t : o.techniques.value_or(technique_names())) {
    if (t != "native") out.push_back(t);
  }
  return out;
}

class Search {
 public:
  Search(const TuneOptions& o, const TuneCallbacks& c, TuneResult& r)
      : options_(o), callbacks_(c), out_(r) {}

  void scene(const std::string& name) {
    scene_ = name;
    techniques_ = tuned_techniques(options_);
    if (!options_.staged()) {
      evaluate(grid(), 1, false);
      return;
    }
    evaluate(stage1(), 1, false);
    evaluate(stage2(), 2, false);
    evaluate(stage3(), 3, false);
  }

  // Settings chosen on one scene, tried on the scenes that have not seen them.
  void cross_check(const std::vector<std::string>& scenes) {
    for (const std::string& s : scenes) {
      scene_ = s;
      techniques_ = tuned_techniques(options_);
      std::vector<Candidate> todo;
      for (const std::string& t : techniques_) {
        for (const std::string& other : scenes) {
          if (other == s) continue;
          const TunePoint* best = best_point(other, t);
          if (best && !seen(s, {t, best->params})) todo.push_back({t, best->params});
        }
      }
      evaluate(todo, 4, false);
    }
  }

  // The settings the choice falls between, timed again side by side
  // (tune_contenders). Points of one setting timed in different benchmarks
  // differ by the machine's noise (up to 15 % on a shared one), which would
  // decide between settings of equal quality; timed in one benchmark per
  // scene, beside native, they are compared on equal terms. Their new points
  // replace the earlier ones (stage 5).
  void retime(const std::vector<std::string>& scenes) {
    std::vector<Candidate> todo;
    for (const std::string& t : tuned_techniques(options_)) {
      for (Params& p : tune_contenders(out_, t)) todo.push_back({t, std::move(p)});
    }
    if (todo.empty()) return;
    for (const std::string& s : scenes) {
      scene_ = s;
      evaluate(todo, 5, true);
    }
  }

  /// The techniques a benchmark left out, with the scene and the reason
  /// ("lodmask on cheap (…)").
  [[nodiscard]] const std::set<std::string>& skipped() const { return skipped_; }

 private:
  std::vector<Candidate> stage1() const {
    std::vector<Candidate> c;
    for (const std::string& t : techniques_) {
      const std::vector<Axis> axes = axes_of(t, options_);
      const auto margin = std::find_if(axes.begin(), axes.end(),
                                       [](const Axis& a) { return a.key == kPlanMarginKey; });
      if (margin == axes.end()) {
        c.push_back({t, {}});
        continue;
      }
      for (double v : margin->values) c.push_back({t, {{kPlanMarginKey, v}}});
    }
    return c;
  }

  // One other parameter changed at a time from the best point, and the
  // margin one step either side.
  std::vector<Candidate> stage2() const {
    std::vector<Candidate> c;
    for (const std::string& t : techniques_) {
      const TunePoint* best = best_point(scene_, t, 1);
      if (!best) continue;
      for (const Axis& a : axes_of(t, options_)) {
        if (a.key == kPlanMarginKey) {
          const auto it = best->params.find(a.key);
          if (it == best->params.end()) continue;
          const auto pos = std::find(a.values.begin(), a.values.end(), it->second);
          const auto idx = pos - a.values.begin();
          for (auto j : {idx - 1, idx + 1}) {
            if (j < 0 || j >= static_cast<decltype(j)>(a.values.size())) continue;
            Params p = best->params;
            p[a.key] = a.values[static_cast<size_t>(j)];
            c.push_back({t, p});
          }
          continue;
        }
        for (double v : a.values) {
          Params p = best->params;
          p[a.key] = v;
          c.push_back({t, p});
        }
      }
    }
    return c;
  }

  // The combinations of stage 2's changes (tune_combinations).
  std::vector<Candidate> stage3() const {
    std::vector<Candidate> c;
    for (const std::string& t : techniques_) {
      const TunePoint* best = best_point(scene_, t, 1);
      if (!best) continue;
      std::vector<TunePoint> stage2;
      for (const TunePoint& p : out_.points) {
        if (p.scene == scene_ && p.technique == t && p.stage == 2) stage2.push_back(p);
      }
      std::vector<std::pair<std::string, std::vector<double>>> axes;
      for (const Axis& a : axes_of(t, options_)) axes.emplace_back(a.key, a.values);
      for (Params& p : tune_combinations(stage2, *best, axes)) c.push_back({t, std::move(p)});
    }
    return c;
  }

  // Shards: every margin crossed with one other parameter changed at a time.
  std::vector<Candidate> grid() const {
    std::vector<Candidate> all;
    for (const std::string& t : techniques_) {
      const std::vector<Axis> axes = axes_of(t, options_);
      std::vector<double> margins{std::nan("")};
      for (const Axis& a : axes) {
        if (a.key == kPlanMarginKey) margins = a.values;
      }
      for (double m : margins) {
        Params base;
        if (!std::isnan(m)) base[kPlanMarginKey] = m;
        all.push_back({t, base});
        for (const Axis& a : axes) {
          if (a.key == kPlanMarginKey) continue;
          for (double v : a.values) {
            Params p = base;
            p[a.key] = v;
            all.push_back({t, p});
          }
        }
      }
    }
    // One name per setting before the slicing, so that no two shards run
    // the same setting under different names.
    std::set<Candidate> named;
    std::vector<Candidate> unique;
    for (Candidate& c : all) {
      c.params = without_defaults(c.technique, c.params);
      if (named.insert(c).second) unique.push_back(c);
    }
    all = unique;
    std::vector<Candidate> mine;
    for (size_t i = 0; i < all.size(); ++i) {
      if (static_cast<int>(i % static_cast<size_t>(options_.shard.count)) == options_.shard.index)
        mine.push_back(all[i]);
    }
    return mine;
  }

  bool seen(const std::string& scene, const Candidate& c) const {
    return std::any_of(out_.points.begin(), out_.points.end(), [&](const TunePoint& p) {
      return p.scene == scene && p.technique == c.technique && p.params == c.params;
    });
  }

  // The fastest point within the bound, else the one closest to it (of
  // `stage` only, when above 0).
  const TunePoint* best_point(const std::string& scene, const std::string& technique,
                              int stage = 0) const {
    return tune_best_point(out_.points, scene, technique, stage);
  }

  // Benchmarks the candidates on the current scene; `again`: those already
  // evaluated too, whose new points replace the old.
  void evaluate(std::vector<Candidate> candidates, int stage, bool again) {
    std::set<Candidate> unique;
    std::vector<RunSpec> runs;
    for (Candidate& c : candidates) {
      c.params = without_defaults(c.technique, c.params);
      if ((!again && seen(scene_, c)) || !unique.insert(c).second) continue;
      if (again && !seen(scene_, c)) continue;  // not run on this scene (lodmask on a shader)
      runs.push_back({c.technique, c.params, ""});
    }
    if (runs.empty()) return;
    if (callbacks_.stage) callbacks_.stage(scene_, stage, static_cast<int>(runs.size()));
    BenchOptions b = options_.bench;
    b.session.scene = scene_;
    b.techniques.reset();
    b.sweep = {};
    b.runs = runs;
    b.settle_runs = settle_probes();
    b.image_metrics = true;
    b.diagnostics = false;
    // The search judges and times in one pass (rendering every candidate's
    // frames twice took the default search from 18 to 33 minutes here);
    // stage 5 times the settings the choice falls between apart. A grid or
    // a shard has no stage 5: its candidates are timed apart.
    b.time_apart = stage == 5 || !options_.staged();
    auto& cache = caches_[scene_];
    if (!cache) cache = std::make_shared<ReferenceFrames>();
    b.reference_frames = cache;
    b.skip_unrunnable = true;
    b.shard = {};
    const BenchResult r = run_bench(b, callbacks_.bench);
    for (const std::string& s : r.skipped) {
      const auto space = s.find(' ');
      skipped_.insert(s.substr(0, space) + " on " + scene_ +
                      (space == std::string::npos ? "" : s.substr(space)));
    }
    if (out_.renderer.empty()) {
      out_.renderer = r.renderer;
      out_.environment = r.environment;
    }
    double native = b.reference > 1 ? std::nan("") : 10.0;
    for (const TechniqueResult& t : r.results) {
      if (t.run_index == 0 && t.metrics && t.metrics->fvvdp) native = t.metrics->fvvdp->jod;
    }
    // Every benchmark warms up as long as the slowest candidate to settle
    // (settle_probes), so that all of them measure the same frames; native's
    // JOD is then the same in each benchmark of a scene (same frames, same
    // reference): the first one's is kept.
    if (out_.warmup == 0) out_.warmup = r.warmup;
    if (r.warmup != out_.warmup) {
      throw Error("tune: a benchmark warmed up for " + std::to_string(r.warmup) +
                  " frames, the first for " + std::to_string(out_.warmup) +
                  ": its candidates (a combination no single tuned value needs) would be "
                  "measured on other frames than the rest");
    }
    out_.native_jod.emplace(scene_, native);
    native = out_.native_jod.at(scene_);
    if (again) {
      std::erase_if(out_.points, [&](const TunePoint& p) {
        return p.scene == scene_ && unique.count({p.technique, p.params});
      });
    }
    for (const TechniqueResult& t : r.results) {
      if (t.run_index == 0) continue;
      TunePoint p;
      p.scene = scene_;
      p.technique = t.technique;
      p.params = runs[static_cast<size_t>(t.run_index - 1)].params;
      p.stage = stage;
      p.speedup = t.speedup;
      p.speedup_lo = t.speedup_lo;
      p.speedup_hi = t.speedup_hi;
      p.jod = t.metrics && t.metrics->fvvdp ? t.metrics->fvvdp->jod : std::nan("");
      p.below_native = native - p.jod;
      p.pixel_ratio = t.pixel_ratio;
      p.within_bound = p.below_native <= options_.bound_jod;
      out_.points.push_back(p);
    }
  }

  // Every tuned value of every technique, one at a time from its defaults:
  // made (never rendered) in each benchmark so that the warm-up lasts as
  // long as any candidate of any stage needs to settle (layered's half rate
  // needs longer), and every benchmark measures the same frames.
  std::vector<RunSpec> settle_probes() const {
    std::vector<RunSpec> probes;
    for (const std::string& t : tuned_techniques(options_)) {
      probes.push_back({t, {}, ""});
      for (const Axis& a : axes_of(t, options_)) {
        for (double v : a.values) probes.push_back({t, {{a.key, v}}, ""});
      }
    }
    return probes;
  }

  const TuneOptions& options_;
  const TuneCallbacks& callbacks_;
  TuneResult& out_;
  std::string scene_;
  // Each scene's reference frames, rendered once for every stage.
  std::map<std::string, std::shared_ptr<ReferenceFrames>> caches_;
  std::vector<std::string> techniques_;
  std::set<std::string> skipped_;
};

}  // namespace

BenchOptions TuneOptions::default_bench() {
  BenchOptions b;
  b.reference = 4;
  b.frames = 8;
  b.warmup = 2;
  b.diagnostics = false;
  return b;
}

void validate(const TuneOptions& o) {
  BenchOptions b = o.bench;
  b.runs.clear();
  b.techniques.reset();
  validate(b);
  if (!(o.bound_jod > 0.0 && o.bound_jod <= 10.0)) {
    throw OptionError("bound_jod", "expected a JOD distance in (0, 10]");
  }
  if (o.scenes.empty()) throw OptionError("scenes", "give at least one scene");
  reject_repeats("scenes", o.scenes, {"each scene is judged once", {}});
  if (o.techniques) {
    if (o.techniques->empty()) throw OptionError("techniques", "give at least one technique");
    for (const std::string& t : *o.techniques) {
      for_field("techniques", [&] { return technique_info(t); });
      if (t == "native") throw OptionError("techniques", "native is the baseline, not tuned");
    }
    reject_repeats("techniques", *o.techniques, {"each is searched once", {}});
  }
  for (const auto& [key, list] : o.values) {
    if (key == "slope") {
      throw OptionError("values",
                        "slope: the metrics' acuity, not a technique's parameter (tune plans "
                        "every technique for it; search the planning margin instead)");
    }
    // Against the techniques searched: a value another technique refuses
    // is no error here, and a key none of them has searches nothing.
    Sweep::of(key, list, "values").check_values(tuned_techniques(o), "values");
  }
  if (o.shard.count < 1 || o.shard.index < 0 || o.shard.index >= o.shard.count) {
    throw OptionError("shard", "expected job K of N with 1 <= K <= N");
  }
}

TuneResult run_tune(const TuneOptions& asked, const TuneCallbacks& callbacks) {
  validate(asked);
  // Each list ascending, as it is searched: shards given one list in two
  // orders are one run's.
  TuneOptions options = asked;
  for (auto& [key, list] : options.values) std::sort(list.begin(), list.end());
  TuneResult out;
  out.options = options;
  out.settings_key = tune_settings_key(options);
  // Every benchmark of the search sets up its scene's session again: what
  // one notes (a size too small to save anything) is said once.
  TuneCallbacks once = callbacks;
  if (callbacks.bench.session.notice) {
    auto said = std::make_shared<std::set<std::string>>();
    once.bench.session.notice = [said, notice = callbacks.bench.session.notice](const Notice& n) {
      if (said->insert(n.text.render()).second) notice(n);
    };
  }
  Search search(options, once, out);
  for (const std::string& scene : options.scenes) search.scene(scene);
  // Nothing searched can run on the scenes given (a shard may hold no run).
  if (out.points.empty() && options.shard.count == 1) {
    std::string why;
    for (const std::string& s : search.skipped()) why += (why.empty() ? "" : "; ") + s;
    throw OptionError(
        "techniques",
        FieldText{"{techniques}: none of the techniques searched can run on {scenes}" +
                      (why.empty() ? std::string() : ": " + why),
                  {"techniques", "scenes"}});
  }
  if (options.staged()) {
    if (options.scenes.size() > 1) search.cross_check(options.scenes);
    search.retime(options.scenes);
  }
  choose_parameters(out);
  return out;
}

}  // namespace foveate::bench
