#include "viewer/viewer_script.hpp"

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "foveate/core/error.hpp"

namespace foveate::app::viewer {

namespace {

struct Verb {
  const char* name;
  int min_args, max_args;
};
constexpr Verb kVerbs[] = {
    {"technique", 1, 1},   {"param", 1, 1},      {"reset", 0, 0},
    {"acuity", 1, 1},      {"slope", 1, 1},      {"display", 1, 1},
    {"ab", 0, 1},          {"split", 0, 1},      {"divider", 1, 1},
    {"overlay", 0, 1},     {"measure", 0, 0},    {"frames", 1, 1},
    {"wait", 1, 1},        {"screenshot", 1, 1}, {"print-state", 0, 0},
    {"quit", 0, 0},        {"mouse", 1, 2},      {"freeze", 0, 1},
    {"save-params", 1, 1}, {"quality", 1, 1}};  // quality: acuity's former name

double number(const std::string& s, const std::string& what) {
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || end != s.c_str() + s.size() || !std::isfinite(v))
    throw Error(what + ": '" + s + "' is not a number");
  return v;
}

/// on/off/toggle (no argument = toggle) against the current value.
bool on_off(const std::vector<std::string>& args, bool current, const char* on_word,
            const char* off_word) {
  if (args.empty() || args[0] == "toggle") return !current;
  if (args[0] == on_word) return true;
  if (args[0] == off_word) return false;
  throw Error(std::string("expected ") + on_word + ", " + off_word + " or toggle, got '" + args[0] +
              "'");
}

}  // namespace

const char* Script::help() {
  return "Commands (separated by ';' or new lines, '#' starts a comment):\n"
         "  technique NAME          switch technique (parameters set before are kept)\n"
         "  param [TECH.]KEY=VALUE  set a parameter (of the current technique by default)\n"
         "  reset                   the current technique's parameters back to their defaults\n"
         "  acuity A|B, slope M     the acuity model (its preset, or a slope)\n"
         "  display SPEC            display preset or JSON file\n"
         "  ab [native|foveated]    show native or the technique (no argument: flip)\n"
         "  split [on|off]          split screen: native left, foveated right\n"
         "  divider X               the split's position, 0..1 of the width\n"
         "  overlay [on|off]        the layer/region borders\n"
         "  measure                 time native on the next frame (otherwise once a second)\n"
         "  mouse X Y, mouse off    the pointer at window pixel X, Y (or out of the window) from\n"
         "                          now on, instead of the real mouse\n"
         "  freeze [on|off]         hold the gaze where it is (key F; no argument: flip)\n"
         "  save-params FILE        the parameters set, as a file --params-file reads\n"
         "  frames N, wait S        render N frames, or for S seconds, before going on\n"
         "  screenshot FILE         the window (image and panel) as PNG, at the end of the frame\n"
         "  print-state             the state as one JSON line on stdout, at the end of the frame\n"
         "  quit                    close the viewer";
}

Script::Script(const std::string& text, std::string origin) : origin_(std::move(origin)) {
  std::string norm = text;
  // Comments run to the end of their line; then ';' and new lines separate.
  std::string cleaned;
  bool comment = false;
  for (char ch : norm) {
    if (ch == '#') comment = true;
    if (ch == '\n') comment = false;
    if (!comment) cleaned += (ch == ';' ? '\n' : ch);
  }
  std::istringstream lines(cleaned);
  std::string line;
  while (std::getline(lines, line)) {
    std::istringstream words(line);
    Command c;
    std::string w;
    if (!(words >> c.verb)) continue;
    while (words >> w) c.args.push_back(w);
    c.text = line.substr(line.find_first_not_of(" \t\r"));
    while (!c.text.empty() && (c.text.back() == ' ' || c.text.back() == '\r')) c.text.pop_back();
    const Verb* verb = nullptr;
    for (const Verb& v : kVerbs) {
      if (c.verb == v.name) verb = &v;
    }
    const std::string where =
        origin_ + ": command " + std::to_string(commands_.size() + 1) + " '" + c.text + "'";
    if (!verb) {
      std::string names;
      for (const Verb& v : kVerbs) names += (names.empty() ? "" : ", ") + std::string(v.name);
      throw Error(where + ": unknown command (known: " + names + ")");
    }
    const int n = static_cast<int>(c.args.size());
    if (n < verb->min_args || n > verb->max_args) {
      throw Error(where + ": expected " + std::to_string(verb->min_args) +
                  (verb->max_args != verb->min_args ? " or " + std::to_string(verb->max_args)
                                                    : std::string()) +
                  " argument(s), got " + std::to_string(n));
    }
    try {
      if (c.verb == "frames") {
        const double f = number(c.args[0], "frames");
        if (f < 1 || f != std::floor(f) || f > 1e6) throw Error("frames: expected 1..1000000");
      } else if (c.verb == "wait") {
        const double s = number(c.args[0], "wait");
        if (s < 0 || s > 3600) throw Error("wait: expected 0..3600 seconds");
      } else if (c.verb == "slope" || c.verb == "divider") {
        number(c.args[0], c.verb);
      } else if (c.verb == "mouse") {
        if (c.args.size() == 1 && c.args[0] != "off")
          throw Error("mouse: expected X Y (window pixels) or off");
        if (c.args.size() == 2) {
          number(c.args[0], "mouse x");
          number(c.args[1], "mouse y");
        }
      } else if (c.verb == "param") {
        const auto eq = c.args[0].find('=');
        if (eq == std::string::npos || eq == 0)
          throw Error("param: expected KEY=VALUE or TECHNIQUE.KEY=VALUE");
        number(c.args[0].substr(eq + 1), "param " + c.args[0].substr(0, eq));
      }
    } catch (const Error& e) {
      throw Error(where + ": " + e.what());
    }
    commands_.push_back(std::move(c));
  }
}

void Script::run(const Command& c, Viewer& v) {
  const auto& a = c.args;
  if (c.verb == "technique") {
    v.set_technique(a[0]);
  } else if (c.verb == "param") {
    const auto eq = a[0].find('=');
    std::string key = a[0].substr(0, eq), tech;
    const auto dot = key.find('.');
    if (dot != std::string::npos) {
      tech = key.substr(0, dot);
      key = key.substr(dot + 1);
    }
    v.set_param(tech, key, number(a[0].substr(eq + 1), "param"));
  } else if (c.verb == "reset") {
    v.reset_params();
  } else if (c.verb == "acuity" || c.verb == "quality") {
    v.set_acuity_preset(a[0]);
  } else if (c.verb == "slope") {
    v.set_slope(number(a[0], "slope"));
  } else if (c.verb == "display") {
    v.set_display(a[0]);
  } else if (c.verb == "ab") {
    v.set_show_native(on_off(a, v.show_native(), "native", "foveated"));
  } else if (c.verb == "split") {
    v.set_split(on_off(a, v.split(), "on", "off"));
  } else if (c.verb == "divider") {
    v.set_divider(number(a[0], "divider"));
  } else if (c.verb == "overlay") {
    v.set_overlay(on_off(a, v.overlay(), "on", "off"));
  } else if (c.verb == "measure") {
    v.request_native_sample();
  } else if (c.verb == "freeze") {
    v.mouse_gaze().set_frozen(on_off(a, v.mouse_gaze().frozen(), "on", "off"));
  } else if (c.verb == "save-params") {
    v.save_params(a[0]);
  }
}

void Script::begin_frame(Viewer& viewer, int frame, double wall_s, FrameActions& out) {
  if (frame < resume_frame_ || (resume_wall_ >= 0 && wall_s < resume_wall_)) return;
  resume_wall_ = -1.0;
  while (next_ < commands_.size()) {
    const Command& c = commands_[next_];
    ++next_;
    const std::string where = origin_ + ": command " + std::to_string(next_) + " '" + c.text + "'";
    if (c.verb == "frames") {
      resume_frame_ = frame + static_cast<int>(number(c.args[0], "frames"));
      return;
    }
    if (c.verb == "wait") {
      resume_frame_ = frame + 1;
      resume_wall_ = wall_s + number(c.args[0], "wait");
      return;
    }
    if (c.verb == "screenshot") {
      out.screenshots.push_back(c.args[0]);
      resume_frame_ = frame + 1;
      return;
    }
    if (c.verb == "print-state") {
      ++out.print_state;
      resume_frame_ = frame + 1;
      return;
    }
    if (c.verb == "quit") {
      out.quit = true;
      return;
    }
    if (c.verb == "mouse") {
      out.pointer = c.args.size() == 2
                        ? Pointer{true, number(c.args[0], "mouse x"), number(c.args[1], "mouse y")}
                        : Pointer{};
      continue;
    }
    try {
      run(c, viewer);
    } catch (const Error& e) {
      throw Error(where + ": " + e.what());
    }
  }
}

}  // namespace foveate::app::viewer
