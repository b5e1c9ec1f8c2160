#pragma once
// Strict reading of JSON objects into plain-data structs: wrong types,
// non-finite or out-of-range numbers and unknown keys are errors that name the
// field ("display.width_mm: expected a number, got string").
#include <nlohmann/json.hpp>
#include <set>
#include <string>

namespace foveate {

class JsonReader {
 public:
  /// `where` is the path shown in messages, e.g. "display" or "scene.json: camera".
  JsonReader(const nlohmann::json& object, std::string where);

  /// Reads a number into `out` when `key` is present; returns whether it was.
  bool number(const char* key, double& out, double min = -1e300, double max = 1e300);
  bool integer(const char* key, int& out, int min = -2147483647, int max = 2147483647);
  bool string(const char* key, std::string& out);
  bool boolean(const char* key, bool& out);
  /// Marks `key` as known (for keys read by hand) and returns the value or null.
  const nlohmann::json* get(const char* key);
  [[nodiscard]] std::string path(const char* key) const;
  /// Throws foveate::Error if the object has keys nobody read.
  void finish() const;

 private:
  const nlohmann::json& object_;
  std::string where_;
  std::set<std::string> seen_;
};

/// Parses JSON text; errors say `where` and the byte position.
nlohmann::json parse_json(const std::string& text, const std::string& where);
/// Reads and parses a JSON file; errors name the file. `what` says what the
/// file is for ("display JSON"); anything but a regular file is refused.
nlohmann::json read_json_file(const std::string& path, const std::string& what = "JSON file");

}  // namespace foveate
