#pragma once
// The options every rendering command shares (render, bench, demo, view), as
// typed on the command line: registered once, parsed into
// foveate::bench::SessionOptions. Also the --param grammar.
#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "cli_util.hpp"
#include "foveate/bench/bench.hpp"
#include "foveate/bench/params.hpp"
#include "foveate/bench/session_options.hpp"

namespace foveate::app {

/// iDate of render and bench unless --date says otherwise: runs stay
/// deterministic (a clock shader shows midnight plus the scene time).
inline constexpr const char* kFixedDate = "2026-01-01T00:00:00";

struct SessionArgs {
  std::string scene = bench::SessionOptions{}.scene;
  /// The library's default, which the Python module shares.
  std::string size = std::to_string(bench::SessionOptions{}.size.width) + "x" +
                     std::to_string(bench::SessionOptions{}.size.height);
  std::string display = bench::SessionOptions{}.display;
  PhotometryOverrides photometry;
  std::string acuity_preset;  ///< --acuity (--quality): "A", "B" or empty
  std::optional<double> slope;
  std::optional<double> margin;
  std::vector<std::string> params;
  std::string params_file;
  std::string gaze;
  std::string camera_path;
  std::vector<std::string> channels;
  std::string up;
  std::string model_memory_limit;
  double fps = bench::SessionOptions{}.fps;
  double start_time_s = bench::SessionOptions{}.start_time_s;  ///< --time
  bool strict = false;
  double frame_timeout = bench::kDefaultFrameTimeoutS;
  std::string date;  ///< --date; empty = the command's default
  bool stereo = false;
  std::string vergence;  ///< --vergence; empty = parallel
};

/// Registers --scene --size --display --acuity --slope --margin --param --gaze
/// --camera-path --channel --up --model-memory-limit --fps --time --strict --frame-timeout --date
/// on `sub`. `scene_required` makes --scene mandatory (render). `default_date` is what --date
/// means when not given ("now" in view; a fixed date elsewhere, for determinism).
/// `stereo` adds --stereo and --vergence (render, bench, view).
void add_session_options(CLI::App* sub, SessionArgs& args, bool scene_required = false,
                         const char* default_date = kFixedDate, bool stereo = false);
/// --acuity (alias --quality) and --slope, registered with one help text (the commands that
/// take an acuity model without a session).
void add_acuity_options(CLI::App* sub, std::string& preset, std::optional<double>& slope);

/// --memory-limit: what the judged runs (`what`: "run", "candidate") may
/// hold at once (BenchOptions::memory_limit_bytes).
void add_memory_limit_option(CLI::App* sub, std::string& limit, const std::string& what);
/// The typed options; an error in what the text says names the flag, and
/// the library's check of the values names the field (main() writes it as
/// its flag). An empty --date gives `default_date`.
bench::SessionOptions to_session_options(const SessionArgs& args,
                                         const char* default_date = kFixedDate);

/// --param values: "KEY=VALUE" applies to every technique that has KEY;
/// "TECHNIQUE.KEY=VALUE" to that technique only.
bench::ParamOverrides parse_params(const std::vector<std::string>& items);
/// --params-file's values for `techniques` (the techniques the command
/// runs), then --param's over them; a --param value for a technique not
/// among them, or a key none of them declares, is an OptionError of "params".
bench::ParamOverrides session_params(const SessionArgs& args,
                                     const std::vector<std::string>& techniques);

}  // namespace foveate::app
