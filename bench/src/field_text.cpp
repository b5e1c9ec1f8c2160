#include "foveate/bench/field_text.hpp"

namespace foveate::bench {

std::string FieldText::render(const FieldNamer& namer) const {
  std::string out = text;
  for (const std::string& field : fields) {
    const std::string mark = "{" + field + "}";
    std::string name = namer ? namer(field) : std::string();
    if (name.empty()) name = field;
    for (size_t at = out.find(mark); at != std::string::npos; at = out.find(mark, at + name.size()))
      out.replace(at, mark.size(), name);
  }
  return out;
}

OptionError::OptionError(const std::string& field, const std::string& reason)
    : OptionError(field, FieldText{"{" + field + "}: " + reason, {field}}) {}

OptionError::OptionError(std::string field, FieldText text)
    : Error(text.render()), field_(std::move(field)), text_(std::move(text)) {}

void reject_repeats(const std::string& field, const std::vector<std::string>& names,
                    const FieldText& hint) {
  for (size_t i = 0; i < names.size(); ++i) {
    for (size_t j = 0; j < i; ++j) {
      if (names[i] != names[j]) continue;
      FieldText t{"{" + field + "}: '" + names[i] + "' is listed twice", {field}};
      if (!hint.text.empty()) {
        t.text += " (" + hint.text + ")";
        t.fields.insert(t.fields.end(), hint.fields.begin(), hint.fields.end());
      }
      throw OptionError(field, t);
    }
  }
}

}  // namespace foveate::bench
