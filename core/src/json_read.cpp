#include "foveate/core/json_read.hpp"

#include <cmath>

#include "foveate/core/error.hpp"
#include "foveate/core/file.hpp"
#include "foveate/core/parse.hpp"

namespace foveate {

namespace {
std::string type_of(const nlohmann::json& v) { return v.type_name(); }
}  // namespace

JsonReader::JsonReader(const nlohmann::json& object, std::string where)
    : object_(object), where_(std::move(where)) {
  if (!object_.is_object()) {
    throw Error(where_ + ": expected a JSON object, got " + type_of(object_));
  }
}

std::string JsonReader::path(const char* key) const { return where_ + "." + key; }

const nlohmann::json* JsonReader::get(const char* key) {
  seen_.insert(key);
  auto it = object_.find(key);
  return it == object_.end() ? nullptr : &*it;
}

bool JsonReader::number(const char* key, double& out, double min, double max) {
  const nlohmann::json* v = get(key);
  if (!v) return false;
  if (!v->is_number()) throw Error(path(key) + ": expected a number, got " + type_of(*v));
  double x = v->get<double>();
  if (!std::isfinite(x)) throw Error(path(key) + ": must be finite");
  if (x < min || x > max) {
    throw Error(path(key) + ": " + format_number(x) + " is out of range [" + format_number(min) +
                ", " + format_number(max) + "]");
  }
  out = x;
  return true;
}

bool JsonReader::integer(const char* key, int& out, int min, int max) {
  const nlohmann::json* v = get(key);
  if (!v) return false;
  if (!v->is_number_integer()) {
    throw Error(path(key) + ": expected an integer, got " +
                (v->is_number() ? std::string("a fraction") : type_of(*v)));
  }
  long long x = v->get<long long>();
  if (x < min || x > max) {
    throw Error(path(key) + ": " + std::to_string(x) + " is out of range [" + std::to_string(min) +
                ", " + std::to_string(max) + "]");
  }
  out = static_cast<int>(x);
  return true;
}

bool JsonReader::string(const char* key, std::string& out) {
  const nlohmann::json* v = get(key);
  if (!v) return false;
  if (!v->is_string()) throw Error(path(key) + ": expected a string, got " + type_of(*v));
  out = v->get<std::string>();
  return true;
}

bool JsonReader::boolean(const char* key, bool& out) {
  const nlohmann::json* v = get(key);
  if (!v) return false;
  if (!v->is_boolean()) throw Error(path(key) + ": expected true or false, got " + type_of(*v));
  out = v->get<bool>();
  return true;
}

void JsonReader::finish() const {
  for (auto it = object_.begin(); it != object_.end(); ++it) {
    if (!seen_.count(it.key())) throw Error(where_ + ": unknown key '" + it.key() + "'");
  }
}

nlohmann::json parse_json(const std::string& text, const std::string& where) {
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw Error(where + ": invalid JSON at byte " + std::to_string(e.byte) + ": " +
                std::string(e.what()).substr(std::string(e.what()).find(':') + 2));
  } catch (const nlohmann::json::exception& e) {
    // Not a syntax error but a value the parser cannot hold, e.g. a number
    // beyond the range of a double ("1e999": out_of_range.406).
    const std::string what = e.what();
    const auto bracket = what.find("] ");
    throw Error(where + ": invalid JSON: " +
                (bracket == std::string::npos ? what : what.substr(bracket + 2)) +
                (e.id == 406 ? " (numbers must fit in a double)" : ""));
  }
}

nlohmann::json read_json_file(const std::string& path) { return parse_json(read_file(path), path); }

}  // namespace foveate
