#pragma once
// Technique parameter overrides of a run: a value for every technique that
// declares the key, or for one technique only.
#include <map>
#include <string>
#include <vector>

namespace foveate::bench {

struct ParamOverrides {
  /// By technique; "" holds the values for every technique that declares the key.
  std::map<std::string, std::map<std::string, double>> per_technique;

  /// `key` is KEY (every technique that declares it) or TECHNIQUE.KEY; an
  /// unknown technique is an OptionError of "params".
  void set(const std::string& key, double value);
  /// Throws an OptionError of "params" when a value would be ignored: a KEY
  /// given for every technique that none of `techniques` declares, a
  /// TECHNIQUE.KEY for a technique not among them, or a KEY its technique
  /// does not declare.
  void validate(const std::vector<std::string>& techniques) const;
  /// The values for `techniques` (and those for every technique): a
  /// parameters file's entries for the techniques a run makes.
  [[nodiscard]] ParamOverrides only(const std::vector<std::string>& techniques) const;
  /// The overrides `technique` gets: those for every technique that it
  /// declares, then its own.
  [[nodiscard]] std::map<std::string, double> for_technique(const std::string& technique) const;
};

}  // namespace foveate::bench
