#pragma once
// The viewer's scripted mode: commands separated by ';' or new lines (from
// --commands or --script FILE) that drive the same calls as the panel, on
// frame boundaries, so a test (or a demo) can change parameters, switch
// techniques, take screenshots and print the state as JSON lines.
#include <optional>
#include <string>
#include <vector>

#include "viewer/viewer.hpp"

namespace foveate::app::viewer {

/// The mouse pointer: whether it is in the window, and where (window pixels,
/// origin top-left).
struct Pointer {
  bool inside = false;
  double x = 0, y = 0;
};

/// What the loop does at the end of a frame, after the UI is drawn.
struct FrameActions {
  std::vector<std::string> screenshots;  ///< write the window's contents here (PNG)
  int print_state = 0;                   ///< print Viewer::state() this many times
  bool quit = false;                     ///< stop before rendering
  /// A script's pointer, taken instead of the real mouse from this frame on.
  std::optional<Pointer> pointer;
};

class Script {
 public:
  /// Parses and checks every command; throws foveate::Error naming `origin`
  /// ("--commands", "--script FILE"), the command and what is wrong.
  Script(const std::string& text, std::string origin);
  /// Runs the commands due at the start of frame `frame` (wall time `wall_s`)
  /// until one waits for frames or time, or asks for an end-of-frame action.
  void begin_frame(Viewer& viewer, int frame, double wall_s, FrameActions& out);
  [[nodiscard]] bool done() const { return next_ >= commands_.size(); }
  /// One line per command, for --help.
  static const char* help();

 private:
  struct Command {
    std::string verb;
    std::vector<std::string> args;
    std::string text;
  };
  void run(const Command& c, Viewer& viewer);
  std::string origin_;
  std::vector<Command> commands_;
  size_t next_ = 0;
  int resume_frame_ = 0;
  double resume_wall_ = -1.0;
};

}  // namespace foveate::app::viewer
