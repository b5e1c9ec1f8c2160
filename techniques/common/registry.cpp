// The one registry of techniques, parameter resolution from the declarations,
// and the overlay pass they share.
#include "registry.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>

#include "foveate/core/error.hpp"
#include "foveate/techniques/pass_kit.hpp"

namespace foveate {

namespace {

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

// What a value of the type must be, for errors.
const char* type_requirement(ParamType t) {
  switch (t) {
    case ParamType::Integer:
      return "a whole number";
    case ParamType::Boolean:
      return "0 or 1";
    default:
      return "a number";
  }
}

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
      throw Error(where + ": default " + number(p.value) + " outside its range");
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

void ParamValues::set(const std::string& key, double value) {
  for (auto& [k, v] : items_) {
    if (k == key) {
      v = value;
      return;
    }
  }
  items_.emplace_back(key, value);
}

bool ParamValues::has(std::string_view key) const {
  return std::any_of(items_.begin(), items_.end(), [&](const auto& kv) { return kv.first == key; });
}

double ParamValues::real(std::string_view key) const {
  for (const auto& [k, v] : items_) {
    if (k == key) return v;
  }
  throw Error("internal: parameter '" + std::string(key) + "' is not declared");
}

int ParamValues::integer(std::string_view key) const {
  return static_cast<int>(std::lround(real(key)));
}

bool ParamValues::boolean(std::string_view key) const { return real(key) != 0.0; }

const char* param_type_name(ParamType t) {
  switch (t) {
    case ParamType::Integer:
      return "integer";
    case ParamType::Boolean:
      return "boolean";
    default:
      return "real";
  }
}

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
  throw Error("unknown technique '" + name + "' (known: " + names + ")");
}

namespace {

void check_value(const TechniqueInfo& info, const ParamDecl& p, double x) {
  const std::string what = info.name + " parameter " + p.key + "=" + number(x);
  if (!std::isfinite(x) || x < p.min || x > p.max) {
    throw Error(what + ": out of range [" + number(p.min) + ", " + number(p.max) + "]" +
                (p.unit.empty() ? "" : " " + p.unit));
  }
  if (p.type != ParamType::Real && x != std::floor(x))
    throw Error(what + ": must be " + type_requirement(p.type));
}

}  // namespace

void check_parameter(const TechniqueInfo& info, const std::string& key, double value) {
  for (const ParamDecl& p : info.params) {
    if (p.key == key) return check_value(info, p, value);
  }
  throw Error(info.name + " has no parameter '" + key + "'");
}

ParamDecl plan_margin_param(double fidelity_default) {
  return tuned(
      param(kPlanMarginKey,
            "plan for an acuity this many times finer than the model the metrics judge by "
            "(slope and foveal MAR divided by it): 1 = the paper's plan; the default is the "
            "least at which this technique's error stays within native's own + 1 code against "
            "a 4x4 supersampled reference (docs/fidelity.md)",
            "", ParamType::Real, 1.0, 4.0, fidelity_default),
      {1.0, 1.25, 1.5, 2.0, 2.5, 3.0});
}

TechniqueConfig planning_config(const TechniqueConfig& config, const ParamValues& values) {
  TechniqueConfig c = config;
  if (values.has(kPlanMarginKey)) c.acuity = config.acuity.finer(values.real(kPlanMarginKey));
  return c;
}

ParamValues resolve_parameters(const TechniqueInfo& info, const TechniqueConfig& config) {
  ParamValues values;
  // Defaults derived from the acuity model see the plan's (the margin is
  // resolved first: validate_declaration keeps it first).
  TechniqueConfig planned = config;
  for (const ParamDecl& p : info.params) {
    double v = p.derive ? std::clamp(p.derive(planned, values), p.min, p.max) : p.value;
    if (p.type != ParamType::Real) v = std::round(v);
    auto it = config.params.find(p.key);
    const bool margin_given = p.key == kPlanMarginKey && config.margin.has_value();
    if (it != config.params.end() || margin_given) {
      v = it != config.params.end() ? it->second : *config.margin;
      check_value(info, p, v);
    }
    values.set(p.key, v);
    if (p.key == kPlanMarginKey) planned = planning_config(config, values);
  }
  for (const auto& [key, v] : config.params) {
    if (!values.has(key)) {
      std::string known;
      for (const ParamDecl& p : info.params) known += (known.empty() ? "" : ", ") + p.key;
      throw Error(info.name + " has no parameter '" + key +
                  "' (it has: " + (known.empty() ? "none" : known) + ")");
    }
  }
  if (info.check) info.check(values);
  return values;
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

struct OverlayRenderer::Impl {
  tech::PassKit kit;
};

OverlayRenderer::OverlayRenderer() : impl_(std::make_unique<Impl>()) {}
OverlayRenderer::~OverlayRenderer() = default;

void OverlayRenderer::draw(const std::vector<OverlayShape>& shapes,
                           const gpu::RenderTarget& target) {
  tech::PassKit& kit = impl_->kit;
  const gpu::Program& p = kit.fullscreen("common/overlay.frag");
  const int n = static_cast<int>(std::min<size_t>(shapes.size(), 32));
  const int height = target.height();
  std::vector<float> geo(static_cast<size_t>(n) * 4), style(static_cast<size_t>(n) * 4);
  for (int i = 0; i < n; ++i) {
    const OverlayShape& s = shapes[static_cast<size_t>(i)];
    const double y = s.kind == OverlayShape::Kind::Rect ? height - s.y - s.h : height - s.y;
    const float kind = s.kind == OverlayShape::Kind::Circle ? 0.f
                       : s.kind == OverlayShape::Kind::Rect ? 1.f
                                                            : 2.f;
    const size_t k = static_cast<size_t>(i) * 4;
    geo[k] = float(s.x), geo[k + 1] = float(y), geo[k + 2] = float(s.w), geo[k + 3] = float(s.h);
    style[k] = s.r, style[k + 1] = s.g, style[k + 2] = s.b, style[k + 3] = kind;
  }
  p.set("u_count", n);
  if (n > 0) {
    glProgramUniform4fv(p.id(), p.uniform("u_shape[0]"), n, geo.data());
    glProgramUniform4fv(p.id(), p.uniform("u_style[0]"), n, style.data());
  }
  gpu::PassState blend;
  blend.alpha_blend = true;
  kit.pass(p, target, blend);
}

}  // namespace foveate
