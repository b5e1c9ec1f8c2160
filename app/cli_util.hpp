#pragma once
// Parsing helpers shared by the subcommands: every bad value becomes a
// foveate::Error that names the option.
#include <cstdint>
#include <optional>
#include <string>

#include "foveate/core/acuity.hpp"
#include "foveate/core/display.hpp"
#include "foveate/core/parse.hpp"

namespace foveate::app {

struct Size {
  int width = 0;
  int height = 0;
};

/// The size every command that renders or derives defaults uses unless told
/// otherwise (the paper's display at its own resolution).
inline constexpr const char* kDefaultSize = "1920x1080";
/// The techniques bench and demo measure unless told otherwise; those a scene
/// cannot run (lodmask without meshes) are skipped with a note.
inline constexpr const char* kDefaultTechniques =
    "native,layered,logpolar,checkerboard,lodmask,inset,vrs";

/// --quiet / --verbose, registered on every command (register_all_commands).
enum class Verbosity { Quiet, Normal, Verbose };
Verbosity& verbosity();
[[nodiscard]] inline bool quiet() { return verbosity() == Verbosity::Quiet; }
[[nodiscard]] inline bool verbose() { return verbosity() == Verbosity::Verbose; }

/// Whether foveation has anything to save at a display's pixels per degree:
/// the planner's pixel bound (3 layers, quality of `acuity`) and, when it is
/// below 1.2x, a note with the figure and a size or display to try.
struct SavingsCheck {
  double pixel_bound = 1.0;      ///< native / planned pixels (Guenter et al., 3 layers)
  double centre_ppd = 0.0;       ///< pixels per degree at the screen centre
  bool nothing_to_save = false;  ///< pixel_bound < 1.2
  std::string note;              ///< empty when there is something to save
};
/// `display` is the display at the render size (Display::resized).
SavingsCheck check_savings(const Display& display, const AcuityModel& acuity);
/// Prints check_savings' note on stderr, once per process, unless --quiet.
void note_savings(const Display& display, const AcuityModel& acuity);
/// A duration for people: "4 s", "2 min 05 s".
std::string format_duration(double seconds);

/// "WxH", each 1..16384.
Size parse_size(const std::string& text, const std::string& option);
/// --quality A|B or --slope M (at most one); defaults to quality A.
AcuityModel acuity_from_options(const std::string& quality, std::optional<double> slope);
/// --margin's value, checked: a factor from 1 to 4 (Error naming the flag).
double checked_margin(double margin);
/// A byte count: a number with an optional K, M, G or T suffix (powers of
/// 1024, "B" and "iB" allowed: 512M, 1.5GiB, 4096), more than 0.
std::uint64_t parse_byte_size(const std::string& text, const std::string& option);
/// Formats a number with `digits` decimals (no exponent).
std::string fmt(double value, int digits);

/// What a display's lens does at `gaze` (plan and rates print it): "at the
/// gaze (E deg from the lens axis) the panel shows R (radially) and T
/// (tangentially) pixels per degree, the buffer has R' and T' pixels per
/// panel pixel". The display must have a lens.
std::string lens_at_gaze(const Display& display, Vec2d gaze);

}  // namespace foveate::app
