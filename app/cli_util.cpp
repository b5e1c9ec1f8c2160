#include "cli_util.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "foveate/bench/savings.hpp"
#include "foveate/core/error.hpp"
#include "foveate/core/parse.hpp"
#include "messages.hpp"

namespace foveate::app {

std::uint64_t parse_byte_size(const std::string& text, const std::string& option) {
  std::string t = text;
  for (const char* suffix : {"iB", "B", "ib", "b"}) {
    const std::string sfx(suffix);
    if (t.size() > sfx.size() && t.compare(t.size() - sfx.size(), sfx.size(), sfx) == 0) {
      t.resize(t.size() - sfx.size());
      break;
    }
  }
  double scale = 1.0;
  if (!t.empty()) {
    switch (std::toupper(static_cast<unsigned char>(t.back()))) {
      case 'K':
        scale = 1024.0;
        break;
      case 'M':
        scale = 1024.0 * 1024;
        break;
      case 'G':
        scale = 1024.0 * 1024 * 1024;
        break;
      case 'T':
        scale = 1024.0 * 1024 * 1024 * 1024;
        break;
      default:
        break;
    }
    if (scale > 1.0) t.pop_back();
  }
  double v = 0.0;
  if (!parse_number(t, v) || !(v * scale >= 1.0) || !(v * scale < 1.8e19)) {
    throw Error(option + ": expected a size in bytes such as 512M or 8G, got '" + text + "'");
  }
  return static_cast<std::uint64_t>(v * scale);
}

Verbosity& verbosity() {
  static Verbosity v = Verbosity::Normal;
  return v;
}

void note_savings(const Display& display, const AcuityModel& acuity, std::optional<double> margin) {
  static bool said = false;
  if (said || quiet()) return;
  const bench::SavingsCheck c =
      bench::check_savings(display, acuity, bench::strictest_plan_margin(margin));
  if (!c.nothing_to_save) return;
  said = true;
  print_notice({bench::NoticeKind::Note, c.note});
}

std::string join(const std::vector<std::string>& items, const std::string& separator) {
  std::string out;
  for (const std::string& item : items) out += (out.empty() ? "" : separator) + item;
  return out;
}

std::string format_duration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "?";
  const long s = std::lround(seconds);
  if (s < 60) return std::to_string(s) + " s";
  char buf[64];
  if (s < 3600) {
    std::snprintf(buf, sizeof buf, "%ld min %02ld s", s / 60, s % 60);
  } else {
    std::snprintf(buf, sizeof buf, "%ld h %02ld min", s / 3600, (s % 3600) / 60);
  }
  return buf;
}

std::string lens_at_gaze(const Display& display, Vec2d gaze) {
  const Oversampling o = display.lens_oversampling(gaze);
  const PanelDensity p = display.panel_pixels_per_degree(gaze);
  char s[320];
  std::snprintf(
      s, sizeof s,
      "at the gaze (%.1f deg from the lens axis) the panel shows %.1f (radially) and %.1f "
      "(tangentially) pixels per degree, the buffer has %.2f and %.2f pixels per panel "
      "pixel",
      display.eccentricity_deg(display.principal_point(), gaze), p.radial, p.tangential, o.radial,
      o.tangential);
  return s;
}

std::pair<std::string, std::vector<double>> parse_key_values(const std::string& text,
                                                             const std::string& flag,
                                                             const std::string& usage) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size()) {
    throw Error(flag + ": expected " + usage + ", got '" + text + "'");
  }
  std::vector<double> values;
  std::stringstream in(text.substr(eq + 1));
  std::string item;
  const auto number = [&] {
    double v = 0;
    if (!parse_number(item, v)) throw Error(flag + ": '" + item + "' is not a number");
    values.push_back(v);
  };
  while (std::getline(in, item, ',')) number();
  // getline drops an empty last item: "1," lists an empty value.
  if (text.back() == ',') {
    item.clear();
    number();
  }
  return {text.substr(0, eq), values};
}

}  // namespace foveate::app
