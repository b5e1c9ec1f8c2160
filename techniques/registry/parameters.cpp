// Technique parameters: values by type, and their resolution and checks
// from the declarations (ParamDecl).
#include <algorithm>
#include <cmath>

#include "foveate/core/error.hpp"
#include "foveate/core/parse.hpp"
#include "foveate/techniques/technique.hpp"
#include "param_number.hpp"

namespace foveate {

namespace {

using detail::param_number;

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

namespace {

void check_value(const TechniqueInfo& info, const ParamDecl& p, double x) {
  const std::string what = info.name + " parameter " + p.key + "=" + param_number(x);
  if (!std::isfinite(x) || x < p.min || x > p.max) {
    throw Error(what + ": out of range [" + param_number(p.min) + ", " + param_number(p.max) + "]" +
                (p.unit.empty() ? "" : " " + p.unit));
  }
  if (p.type != ParamType::Real && x != std::floor(x))
    throw Error(what + ": must be " + type_requirement(p.type));
  if (!p.takes(x)) throw Error(what + ": must be " + allowed_text(p));
}

}  // namespace

std::string allowed_text(const ParamDecl& p) {
  std::vector<std::string> values;
  for (double v : p.allowed) values.push_back(param_number(v));
  return format_alternatives(values);
}

void check_parameter(const TechniqueInfo& info, const std::string& key, double value) {
  for (const ParamDecl& p : info.params) {
    if (p.key == key) return check_value(info, p, value);
  }
  throw Error(info.name + " has no parameter '" + key + "'");
}

ParamDecl plan_margin_param(double fidelity_default) {
  // tune tries these margins (ParamDecl::tune).
  return tuned(param(kPlanMarginKey,
                     "plan for an acuity this many times finer than the model the metrics judge "
                     "by (slope and foveal MAR divided by it): 1 = the paper's plan; the default "
                     "is the technique's shipped setting (docs/fidelity.md)",
                     "", ParamType::Real, 1.0, 4.0, fidelity_default),
               {1.0, 1.25, 1.5, 2.0, 2.5, 3.0});
}

ParamDecl edge_contrast_param(const std::string& note) {
  return tuned(param("edge_contrast",
                     "antialiasing of silhouettes, small objects and highlights: texels whose "
                     "linear luminance differs from a neighbour's by more than this share of the "
                     "brighter are reshaded with edge_samples more samples, averaged in linear "
                     "light" +
                         (note.empty() ? std::string() : "; " + note) + "; 0 = off",
                     "", ParamType::Real, 0.0, 1.0, 0.25),
               {0.0, 0.25});
}

ParamDecl edge_samples_param(double fallback) {
  return listed(tuned(param("edge_samples",
                            "new samples in each texel edge_contrast reshades, each counted as a "
                            "shaded pixel: 2 on the texel's diagonal a third of it from its "
                            "centre, averaged with the centre sample it already has (three "
                            "samples, one in each third of the texel across and down); or 4 on "
                            "a rotated grid, averaged, for twice the cost (docs/continuous.md)",
                            "", ParamType::Integer, 2.0, 4.0, fallback),
                      {2.0, 4.0}),
                {2.0, 4.0});
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

}  // namespace foveate
