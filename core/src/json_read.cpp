#include "foveate/core/json_read.hpp"

#include <cmath>
#include <cstdio>
#include <vector>

#include "foveate/core/error.hpp"
#include "foveate/core/file.hpp"
#include "foveate/core/parse.hpp"

namespace foveate {

namespace {
std::string type_of(const nlohmann::json& v) { return v.type_name(); }

std::string number_text(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

/// Finds where a document fails with a value error the parser reports without
/// a key (a number too large for a double: 1e999): a second pass that only
/// tracks the path of the value being read.
class PathTracker final : public nlohmann::json_sax<nlohmann::json> {
 public:
  std::string failed_path;
  std::size_t failed_byte = 0;
  std::string failed_token;

  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t&) override { return value(); }
  bool string(string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool start_object(std::size_t) override { return open(false); }
  bool key(string_t& k) override {
    stack_.back().key = k;
    return true;
  }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override { return open(true); }
  bool end_array() override { return close(); }
  bool parse_error(std::size_t position, const std::string& last_token,
                   const nlohmann::detail::exception&) override {
    failed_byte = position;
    failed_token = last_token;
    for (const Frame& f : stack_) {
      if (f.array) {
        failed_path += "[" + std::to_string(f.index) + "]";
      } else {
        failed_path += (failed_path.empty() ? "" : ".") + f.key;
      }
    }
    return false;
  }

 private:
  struct Frame {
    bool array = false;
    std::string key;
    std::size_t index = 0;
  };
  std::vector<Frame> stack_;

  bool value() {
    if (!stack_.empty() && stack_.back().array) ++stack_.back().index;
    return true;
  }
  bool open(bool array) {
    stack_.push_back({array, {}, 0});
    return true;
  }
  bool close() {
    stack_.pop_back();
    return value();
  }
};
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
  const std::string range =
      " is out of range [" + std::to_string(min) + ", " + std::to_string(max) + "]";
  if (v->is_number_float()) {
    // A whole number too long for a 64-bit integer (20 digits) is read as a
    // double: out of range, not a fraction; 1e3 is a whole number too.
    const double x = v->get<double>();
    if (!std::isfinite(x) || x != std::floor(x)) {
      throw Error(path(key) + ": expected an integer, got a fraction");
    }
    if (x < min || x > max) throw Error(path(key) + ": " + number_text(x) + range);
    out = static_cast<int>(x);
    return true;
  }
  if (!v->is_number_integer()) throw Error(path(key) + ": expected an integer, got " + type_of(*v));
  if (v->is_number_unsigned()) {
    const auto u = v->get<unsigned long long>();
    if (u > static_cast<unsigned long long>(max)) {
      throw Error(path(key) + ": " + std::to_string(u) + range);
    }
  }
  const long long x = v->get<long long>();
  if (x < min || x > max) throw Error(path(key) + ": " + std::to_string(x) + range);
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
    // A value the parser cannot hold (a number beyond a double: 1e999).
    PathTracker t;
    nlohmann::json::sax_parse(text, &t);
    const std::string at = t.failed_path.empty() ? "" : " (key " + t.failed_path + ")";
    if (e.id == 406) {
      throw Error(where + ": the number " + t.failed_token + " at byte " +
                  std::to_string(t.failed_byte) + at +
                  " is out of range (beyond the largest double, about 1.8e308)");
    }
    throw Error(where + ": unreadable JSON at byte " + std::to_string(t.failed_byte) + at + ": " +
                std::string(e.what()).substr(std::string(e.what()).find(']') + 2));
  }
}

nlohmann::json read_json_file(const std::string& path, const std::string& what) {
  return parse_json(read_file(path, what), path);
}

}  // namespace foveate
