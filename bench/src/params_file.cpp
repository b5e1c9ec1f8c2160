#include "foveate/bench/params_file.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "foveate/core/error.hpp"
#include "foveate/core/file.hpp"
#include "foveate/core/json_read.hpp"
#include "foveate/core/parse.hpp"
#include "foveate/techniques/technique.hpp"

namespace foveate::bench {

ParamOverrides read_params_file(const std::string& path) {
  const nlohmann::json j = read_json_file(path, "parameters file");
  if (!j.is_object()) throw Error(path + ": expected a JSON object");
  JsonReader r(j, path);
  std::string schema;
  r.string("schema", schema);
  if (schema != "foveate-params/1") {
    throw Error(path + ": schema: expected \"foveate-params/1\", got \"" + schema + "\"");
  }
  std::string notes;
  r.string("notes", notes);
  const nlohmann::json* techniques = r.get("techniques");
  r.finish();
  if (!techniques || !techniques->is_object()) {
    throw Error(path + ": techniques: expected an object of technique: {key: value}");
  }
  ParamOverrides out;
  for (const auto& [technique, values] : techniques->items()) {
    const std::string where = path + ": techniques." + technique;
    const TechniqueInfo& info = [&]() -> const TechniqueInfo& {
      try {
        return technique_info(technique);
      } catch (const Error& e) {
        throw Error(where + ": " + e.what());
      }
    }();
    if (!values.is_object()) throw Error(where + ": expected an object of key: value");
    for (const auto& [key, value] : values.items()) {
      const auto decl = std::find_if(info.params.begin(), info.params.end(),
                                     [&](const ParamDecl& d) { return d.key == key; });
      if (decl == info.params.end()) {
        throw Error(where + "." + key + ": " + technique + " has no such parameter");
      }
      if (!value.is_number()) throw Error(where + "." + key + ": expected a number");
      const double v = value.get<double>();
      if (!(v >= decl->min && v <= decl->max)) {
        throw Error(where + "." + key + ": " + format_number(v) + " is outside [" +
                    format_number(decl->min) + ", " + format_number(decl->max) + "]");
      }
      out.per_technique[technique][key] = v;
    }
  }
  return out;
}

void write_params_file(const std::string& path, const TechniqueParams& params,
                       const std::string& notes) {
  nlohmann::json t = nlohmann::json::object();
  for (const auto& [technique, values] : params) t[technique] = values;
  const nlohmann::json j = {{"schema", "foveate-params/1"}, {"techniques", t}, {"notes", notes}};
  write_file_atomic(path, j.dump(2) + "\n");
}

}  // namespace foveate::bench
