#pragma once
// What the subcommands share: the default size, --quiet / --verbose, the
// note when a display leaves nothing to save, and parsing helpers whose
// errors name the option.
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "foveate/core/acuity.hpp"
#include "foveate/core/display.hpp"
#include "foveate/core/error.hpp"
#include "foveate/core/parse.hpp"

namespace foveate::app {

/// The size every command that renders or derives defaults uses unless told
/// otherwise (the paper's display at its own resolution).
inline constexpr const char* kDefaultSize = "1920x1080";

/// --quiet / --verbose, registered on every command (register_all_commands).
enum class Verbosity { Quiet, Normal, Verbose };
Verbosity& verbosity();
[[nodiscard]] inline bool quiet() { return verbosity() == Verbosity::Quiet; }
[[nodiscard]] inline bool verbose() { return verbosity() == Verbosity::Verbose; }

/// Prints bench::check_savings' note on stderr, once per process, unless
/// --quiet: for the plan at `margin`, else at the finest planning margin the
/// techniques use by default (bench::strictest_plan_margin).
void note_savings(const Display& display, const AcuityModel& acuity,
                  std::optional<double> margin = std::nullopt);
/// A duration for people: "4 s", "2 min 05 s".
std::string format_duration(double seconds);
/// The items joined with `separator` between them.
std::string join(const std::vector<std::string>& items, const std::string& separator);

/// Runs `fn`, prefixing any foveate::Error it throws with `flag` ("--gaze: ...").
template <class Fn>
auto with_flag(const std::string& flag, Fn&& fn) -> decltype(fn()) {
  try {
    return fn();
  } catch (const Error& e) {
    throw Error(flag + ": " + e.what());
  }
}

/// KEY=V1,V2,... (bench's --sweep, tune's --values): the key and the numbers
/// in the order given. Errors name `flag`; `usage` is the form they quote
/// ("KEY=V1,V2,...").
std::pair<std::string, std::vector<double>> parse_key_values(const std::string& text,
                                                             const std::string& flag,
                                                             const std::string& usage);

/// A byte count: a number with an optional K, M, G or T suffix (powers of
/// 1024, "B" and "iB" allowed: 512M, 1.5GiB, 4096), more than 0.
std::uint64_t parse_byte_size(const std::string& text, const std::string& option);

/// What a display's lens does at `gaze` (plan and rates print it): "at the
/// gaze (E deg from the lens axis) the panel shows R (radially) and T
/// (tangentially) pixels per degree, the buffer has R' and T' pixels per
/// panel pixel". The display must have a lens.
std::string lens_at_gaze(const Display& display, Vec2d gaze);

}  // namespace foveate::app
