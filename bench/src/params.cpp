#include "foveate/bench/params.hpp"

#include <algorithm>

#include "foveate/bench/field_text.hpp"
#include "foveate/core/parse.hpp"
#include "foveate/techniques/technique.hpp"

namespace foveate::bench {

namespace {

bool declares(const TechniqueInfo& info, const std::string& key) {
  return std::any_of(info.params.begin(), info.params.end(),
                     [&](const ParamDecl& p) { return p.key == key; });
}

}  // namespace

void ParamOverrides::set(const std::string& key, double value) {
  const auto dot = key.find('.');
  if (dot == std::string::npos) {
    per_technique[""][key] = value;
    return;
  }
  const std::string technique = key.substr(0, dot);
  try {
    (void)technique_info(technique);
  } catch (const Error& e) {
    throw OptionError("params", FieldText{"{params} " + key + ": " + e.what(), {"params"}});
  }
  per_technique[technique][key.substr(dot + 1)] = value;
}

void ParamOverrides::validate(const std::vector<std::string>& techniques) const {
  std::string names;
  for (const std::string& t : techniques) names += (names.empty() ? "" : ", ") + t;
  for (const auto& [technique, values] : per_technique) {
    if (technique.empty()) continue;
    // A value for a technique that does not run would be silently ignored.
    if (std::find(techniques.begin(), techniques.end(), technique) == techniques.end()) {
      const std::string key = technique + "." + values.begin()->first;
      throw OptionError("params", FieldText{"{params} " + key + ": " + technique +
                                                " is not among the techniques run (" + names +
                                                "), so the value would be ignored",
                                            {"params"}});
    }
    const TechniqueInfo& info = technique_info(technique);
    for (const auto& [key, value] : values) {
      if (declares(info, key)) continue;
      std::vector<std::string> keys;
      for (const ParamDecl& p : info.params) keys.push_back(p.key);
      throw OptionError(
          "params",
          FieldText{"{params} " + technique + "." + key + ": " + technique + " has no parameter '" +
                        key + "'" + did_you_mean(key, keys) + " (see 'foveate techniques')",
                    {"params"}});
    }
  }
  const auto all = per_technique.find("");
  if (all == per_technique.end()) return;
  for (const auto& [key, value] : all->second) {
    bool known = false;
    std::vector<std::string> keys;
    for (const std::string& t : techniques) {
      known = known || declares(technique_info(t), key);
      for (const ParamDecl& p : technique_info(t).params) keys.push_back(p.key);
    }
    if (!known) {
      throw OptionError("params",
                        FieldText{"{params} " + key + ": no such parameter in " + names +
                                      did_you_mean(key, keys) + " (see 'foveate techniques')",
                                  {"params"}});
    }
  }
}

ParamOverrides ParamOverrides::only(const std::vector<std::string>& techniques) const {
  ParamOverrides out;
  for (const auto& [technique, values] : per_technique) {
    if (technique.empty() ||
        std::find(techniques.begin(), techniques.end(), technique) != techniques.end())
      out.per_technique[technique] = values;
  }
  return out;
}

std::map<std::string, double> ParamOverrides::for_technique(const std::string& technique) const {
  std::map<std::string, double> out;
  const TechniqueInfo& info = technique_info(technique);
  if (const auto all = per_technique.find(""); all != per_technique.end()) {
    for (const auto& [k, v] : all->second) {
      if (declares(info, k)) out[k] = v;
    }
  }
  if (const auto mine = per_technique.find(technique); mine != per_technique.end()) {
    for (const auto& [k, v] : mine->second) out[k] = v;
  }
  return out;
}

}  // namespace foveate::bench
