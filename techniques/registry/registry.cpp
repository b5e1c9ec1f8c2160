// The one registry of techniques: the built-in ones (registry.hpp) and
// those registered at run time, each declaration checked, and techniques
// made from it.
#include "registry.hpp"

#include <cmath>
#include <mutex>

#include "foveate/core/error.hpp"
#include "foveate/core/parse.hpp"
#include "param_number.hpp"

namespace foveate {

namespace {

using detail::param_number;

void validate_declaration(const TechniqueInfo& info) {
  if (info.name.empty()) throw Error("register_technique: the technique has no name");
  if (!info.make) throw Error("technique " + info.name + ": no make function");
  for (size_t i = 0; i < info.params.size(); ++i) {
    const ParamDecl& p = info.params[i];
    const std::string where = "technique " + info.name + ", parameter '" + p.key + "'";
    if (p.key.empty() || p.key.find_first_of(".= ") != std::string::npos)
      throw Error("technique " + info.name + ": parameter key '" + p.key +
                  "' must be non-empty without '.', '=' or spaces");
    for (size_t j = 0; j < i; ++j)
      if (info.params[j].key == p.key) throw Error(where + ": declared twice");
    if (!(p.min <= p.max)) throw Error(where + ": min > max");
    if (p.type == ParamType::Boolean && (p.min != 0.0 || p.max != 1.0))
      throw Error(where + ": a boolean's range is [0, 1]");
    if (!p.derive && !(p.value >= p.min && p.value <= p.max))
      throw Error(where + ": default " + param_number(p.value) + " outside its range");
    for (double v : p.tune) {
      const bool whole = p.type == ParamType::Real || v == std::floor(v);
      if (!(v >= p.min && v <= p.max) || !whole)
        throw Error(where + ": tune value " + param_number(v) + " outside its range or type");
    }
    // A parameter with a list of values takes its default and tune's from it.
    if (!p.derive && !p.takes(p.value))
      throw Error(where + ": default " + param_number(p.value) + " not among its allowed values");
    for (double v : p.tune) {
      if (!p.takes(v))
        throw Error(where + ": tune value " + param_number(v) + " not among its allowed values");
    }
    if (p.key == kPlanMarginKey && (i != 0 || p.derive || p.min < 1.0 || p.max > 4.0))
      throw Error(where +
                  ": the planning margin is declared first, with a constant default, "
                  "within [1, 4] (plan_margin_param)");
  }
}

struct Registry {
  std::mutex mutex;
  std::vector<TechniqueInfo> all;
  Registry() {
#define FOVEATE_ADD_INFO(name) all.push_back(tech::name##_info());
    FOVEATE_BUILTIN_TECHNIQUES(FOVEATE_ADD_INFO)
#undef FOVEATE_ADD_INFO
    for (const TechniqueInfo& t : all) validate_declaration(t);
  }
};

Registry& registry() {
  static Registry r;
  return r;
}

}  // namespace

const std::vector<TechniqueInfo>& techniques() { return registry().all; }

std::vector<std::string> technique_names() {
  std::vector<std::string> names;
  for (const TechniqueInfo& t : techniques()) names.push_back(t.name);
  return names;
}

void register_technique(TechniqueInfo info) {
  validate_declaration(info);
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  for (const TechniqueInfo& t : r.all) {
    if (t.name == info.name) throw Error("technique '" + info.name + "' is already registered");
  }
  r.all.push_back(std::move(info));
}

const TechniqueInfo& technique_info(const std::string& name) {
  for (const TechniqueInfo& t : techniques()) {
    if (t.name == name) return t;
  }
  std::string names;
  for (const TechniqueInfo& t : techniques()) names += (names.empty() ? "" : ", ") + t.name;
  throw Error("unknown technique '" + name + "'" + did_you_mean(name, technique_names()) +
              " (known: " + names + ")");
}

std::unique_ptr<Technique> make_technique(const std::string& name, const TechniqueConfig& config) {
  config.display.validate();
  const TechniqueInfo& info = technique_info(name);
  const ParamValues values = resolve_parameters(info, config);
  std::unique_ptr<Technique> t = info.make(planning_config(config, values), values);
  t->name_ = info.name;
  t->values_ = values;
  t->display_ = config.display;
  return t;
}

std::vector<std::pair<std::string, double>> Technique::parameters() const {
  auto v = values_.items();
  for (auto& d : derived()) v.push_back(std::move(d));
  return v;
}

std::string scene_mismatch(const TechniqueInfo& info, const SceneInfo& scene) {
  if ((info.needs.meshes && !scene.has_meshes) || (info.needs.mesh_lods && !scene.has_mesh_lods)) {
    return "technique " + info.name + " needs a scene with " +
           (info.needs.mesh_lods ? "mesh levels of detail" : "meshes") + ", but scene '" +
           scene.name + "' has " + (scene.has_meshes ? "no levels of detail" : "no meshes") +
           " (it is shaded in screen space); use a mesh file or the guenter scene";
  }
  return {};
}

void check_scene(const TechniqueInfo& info, const SceneInfo& scene) {
  const std::string why = scene_mismatch(info, scene);
  if (!why.empty()) throw Error(why);
}

}  // namespace foveate
