#pragma once
// Messages of the benchmark library name the fields of its typed options
// ("frames", "gaze", "frame_timeout_s"), never a front end's spelling of
// them: the command line writes each field as its flag, Python as its
// keyword. A message that names fields is a FieldText, which each front end
// renders with its own namer; errors about one option are OptionErrors.
#include <functional>
#include <string>
#include <vector>

#include "foveate/core/error.hpp"

namespace foveate::bench {

/// How a front end writes a field's name (the command line: its flag); a
/// namer that is empty, or returns an empty string, keeps the field's name.
using FieldNamer = std::function<std::string(const std::string& field)>;

/// Text for the user in which each `{field}` of a field listed in `fields`
/// stands for that option; nothing else in the text is touched.
struct FieldText {
  std::string text;
  std::vector<std::string> fields;
  [[nodiscard]] std::string render(const FieldNamer& namer = {}) const;
};

/// Bad input in one field of the options. what() names fields as they are.
class OptionError : public Error {
 public:
  /// "FIELD: REASON".
  OptionError(const std::string& field, const std::string& reason);
  /// Any text naming `field` and others as {name} (FieldText).
  OptionError(std::string field, FieldText text);
  [[nodiscard]] const std::string& field() const { return field_; }
  [[nodiscard]] const FieldText& text() const { return text_; }
  /// The message with every field written by `namer`.
  [[nodiscard]] std::string message(const FieldNamer& namer) const { return text_.render(namer); }

 private:
  std::string field_;
  FieldText text_;
};

/// Refuses a name that `names` (the list in `field`) holds twice: a second
/// copy would run or judge the same thing again and report it twice under
/// one name. `hint` follows the reason (a FieldText may name other fields).
void reject_repeats(const std::string& field, const std::vector<std::string>& names,
                    const FieldText& hint = {});

/// Runs `fn`; a foveate::Error it throws becomes an OptionError of `field`
/// ("FIELD: what the error said"). An OptionError passes unchanged.
template <class Fn>
auto for_field(const std::string& field, Fn&& fn) -> decltype(fn()) {
  try {
    return fn();
  } catch (const OptionError&) {
    throw;
  } catch (const Error& e) {
    throw OptionError(field, e.what());
  }
}

}  // namespace foveate::bench
