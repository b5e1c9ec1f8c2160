#include "foveate/bench/params.hpp"

#include <algorithm>

#include "foveate/bench/field_text.hpp"
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
  const auto all = per_technique.find("");
  if (all == per_technique.end()) return;
  for (const auto& [key, value] : all->second) {
    bool known = false;
    std::string names;
    for (const std::string& t : techniques) {
      names += (names.empty() ? "" : ", ") + t;
      known = known || declares(technique_info(t), key);
    }
    if (!known) {
      throw OptionError("params", FieldText{"{params} " + key + ": no such parameter in " + names +
                                                " (see 'foveate techniques')",
                                            {"params"}});
    }
  }
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
