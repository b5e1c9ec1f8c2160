#pragma once
// A sweep repeats a run for every value of one key: the MAR slope (the plan
// and the metrics' yardstick), the planning margin (the plan only), a
// parameter of every technique that declares it, or one technique's.
#include <string>
#include <vector>

namespace foveate::bench {

/// The most values one sweep may have (each is a full run of the frames).
inline constexpr int kMaxSweepValues = 50;

struct Sweep {
  std::string key;        ///< "slope", "margin", "KEY" or "TECHNIQUE.KEY"; empty = no sweep
  std::string technique;  ///< empty = every technique that declares `param`
  std::string param;      ///< empty when the slope is swept
  std::vector<double> values;

  /// The values FROM, FROM + STEP, ... up to TO (counted, not accumulated, so
  /// that a step too small to change the value cannot loop); a key of one
  /// technique (TECHNIQUE.KEY) has its values checked against its
  /// declaration, a shared key's against the techniques run by
  /// check_values. Throws an OptionError of "sweep" for an unknown key, a
  /// bad range or more than kMaxSweepValues values.
  static Sweep range(const std::string& key, double from, double to, double step);
  /// The listed values, run in ascending order (a sweep's plots and tables
  /// read along the key), each checked as range() checks them. Throws an
  /// OptionError of "sweep" for an empty list, a value that is not finite or
  /// is listed twice (its runs would carry one label), or more than
  /// kMaxSweepValues values. `field` names the option in errors (tune's
  /// `values` checks its lists here too).
  static Sweep of(const std::string& key, std::vector<double> values,
                  const std::string& field = "sweep");
  [[nodiscard]] bool empty() const { return key.empty(); }
  /// Whether the run of `technique` is repeated for every value.
  [[nodiscard]] bool applies_to(const std::string& technique) const;
  /// Checks every value against each of `techniques` the key applies to
  /// (before anything runs: validate() of a benchmark or tune). Throws an OptionError of `field`
  /// naming the first refusal, or, for a technique parameter, when none of them has it
  /// (`list_field` names the list in that message): nothing would be swept.
  void check_values(const std::vector<std::string>& techniques, const std::string& field = "sweep",
                    const std::string& list_field = "techniques") const;
};

}  // namespace foveate::bench
