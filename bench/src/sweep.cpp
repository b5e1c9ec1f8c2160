#include "foveate/bench/sweep.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "foveate/bench/field_text.hpp"
#include "foveate/core/parse.hpp"
#include "foveate/techniques/technique.hpp"

namespace foveate::bench {

Sweep Sweep::range(const std::string& key, double from, double to, double step) {
  if (!std::isfinite(from) || !std::isfinite(to) || !std::isfinite(step))
    throw OptionError("sweep", "FROM, TO and STEP must be finite numbers");
  if (!(step > 0) || to < from) throw OptionError("sweep", "need FROM <= TO and STEP > 0");
  const double count = std::floor((to - from) / step + 1e-9) + 1;
  if (!(count <= kMaxSweepValues)) {
    throw OptionError(
        "sweep",
        FieldText{"{sweep} " + key + ": " + format_fixed(count, 0) + " values, over the limit of " +
                      std::to_string(kMaxSweepValues) + "; use a larger STEP",
                  {"sweep"}});
  }
  // A step below the values' precision leaves some of them equal: each is run once.
  std::vector<double> values;
  for (int i = 0; i < static_cast<int>(count); ++i) {
    const double x = from + i * step;
    if (values.empty() || x != values.back()) values.push_back(x);
  }
  return of(key, std::move(values));
}

Sweep Sweep::of(const std::string& key, std::vector<double> values, const std::string& field) {
  if (values.empty()) throw OptionError(field, "give at least one value");
  if (values.size() > size_t{kMaxSweepValues}) {
    throw OptionError(field,
                      FieldText{"{" + field + "} " + key + ": " + std::to_string(values.size()) +
                                    " values, over the limit of " + std::to_string(kMaxSweepValues),
                                {field}});
  }
  for (double x : values) {
    if (!std::isfinite(x)) throw OptionError(field, "values must be finite numbers");
  }
  std::sort(values.begin(), values.end());
  for (size_t i = 1; i < values.size(); ++i) {
    if (values[i] == values[i - 1]) {
      throw OptionError(field,
                        FieldText{"{" + field + "} " + key + ": " + format_number(values[i]) +
                                      " is listed twice (each value runs once)",
                                  {field}});
    }
  }
  Sweep s;
  s.key = key;
  s.values = std::move(values);
  if (s.key == "slope") return s;
  const auto dot = s.key.find('.');
  s.technique = dot == std::string::npos ? "" : s.key.substr(0, dot);
  s.param = dot == std::string::npos ? s.key : s.key.substr(dot + 1);
  bool known = false;
  for (const TechniqueInfo& t : techniques()) known = known || s.applies_to(t.name);
  if (!known) {
    throw OptionError(field,
                      "no technique has a parameter '" + s.key + "' (see 'foveate techniques')");
  }
  // One technique's values against its declaration at once; a key that
  // every declaring technique shares is checked against the techniques a
  // benchmark or tune runs (check_values), which may take values that
  // another one refuses.
  if (!s.technique.empty()) {
    const TechniqueInfo info = technique_info(s.technique);
    for (double x : s.values) for_field(field, [&] { check_parameter(info, s.param, x); });
  }
  return s;
}

void Sweep::check_values(const std::vector<std::string>& names, const std::string& field,
                         const std::string& list_field) const {
  if (empty() || param.empty()) return;
  bool any = false;
  for (const std::string& name : names) {
    if (name == "native" || !applies_to(name)) continue;
    any = true;
    const TechniqueInfo info = technique_info(name);
    for (double x : values) for_field(field, [&] { check_parameter(info, param, x); });
  }
  if (!any) {
    throw OptionError(field, FieldText{"{" + field + "} " + key + ": none of {" + list_field +
                                           "} has that parameter (see 'foveate techniques')",
                                       {field, list_field}});
  }
}

bool Sweep::applies_to(const std::string& name) const {
  if (empty()) return false;
  if (param.empty()) return true;  // the slope changes every technique
  if (!technique.empty() && technique != name) return false;
  for (const ParamDecl& p : technique_info(name).params) {
    if (p.key == param) return true;
  }
  return false;
}

}  // namespace foveate::bench
