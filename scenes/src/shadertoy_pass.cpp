#include "shadertoy_pass.hpp"

#include <stb/stb_image.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <filesystem>

#include "foveate/core/error.hpp"
#include "foveate/core/file.hpp"
#include "foveate/gpu/frame.hpp"

namespace foveate::detail {

namespace {

// Definitions of the legacy names (GLSL 1.x texture functions, Shadertoy's
// old iGlobalTime), added for the names a shader uses and does not define.
// iChannelTime and iSampleRate are uniforms of the prelude.
struct Legacy {
  const char* name;
  const char* glsl;
};
const Legacy kLegacy[] = {
    {"iGlobalTime", "#define iGlobalTime iTime\n"},
    {"texture2D", "#define texture2D texture\n"},
    {"texture2DLod", "#define texture2DLod textureLod\n"},
    {"texture2DProj", "#define texture2DProj textureProj\n"},
    {"texture2DGrad", "#define texture2DGrad textureGrad\n"},
    // The channels are 2D images: a cube lookup on one reads it as an
    // equirectangular panorama; a cube sampler of the shader's own works.
    {"textureCube",
     "vec4 foveate_texture_cube(samplerCube s, vec3 d) { return texture(s, d); }\n"
     "vec4 foveate_texture_cube(samplerCube s, vec3 d, float b) { return texture(s, d, b); }\n"
     "vec4 foveate_texture_cube(sampler2D s, vec3 d) { return texture(s, foveate_equirect(d)); }\n"
     "vec4 foveate_texture_cube(sampler2D s, vec3 d, float b) {\n"
     "  return texture(s, foveate_equirect(d), b);\n}\n"
     "#define textureCube foveate_texture_cube\n"},
    {"textureCubeLod",
     "vec4 foveate_texture_cube_lod(samplerCube s, vec3 d, float l) {\n"
     "  return textureLod(s, d, l);\n}\n"
     "vec4 foveate_texture_cube_lod(sampler2D s, vec3 d, float l) {\n"
     "  return textureLod(s, foveate_equirect(d), l);\n}\n"
     "#define textureCubeLod foveate_texture_cube_lod\n"},
};
const char kEquirect[] =
    "vec2 foveate_equirect(vec3 d) {\n"
    "  d = normalize(d);\n"
    "  return vec2(atan(d.z, d.x) / 6.28318531 + 0.5, asin(clamp(d.y, -1.0, 1.0)) / 3.14159265 "
    "+ 0.5);\n}\n";

std::string mib(double bytes) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1f MiB", bytes / (1024.0 * 1024.0));
  return b;
}

}  // namespace

// Days since 1970-01-01 of a proleptic Gregorian date, and back.
static long long days_from_civil(long long y, int m, int d) {
  y -= m <= 2;
  const long long era = (y >= 0 ? y : y - 399) / 400;
  const long long yoe = y - era * 400;
  const long long doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
  const long long doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  return era * 146097 + doe - 719468;
}
static void civil_from_days(long long z, long long& y, int& m, int& d) {
  z += 719468;
  const long long era = (z >= 0 ? z : z - 146096) / 146097;
  const long long doe = z - era * 146097;
  const long long yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
  const long long doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
  const long long mp = (5 * doy + 2) / 153;
  d = static_cast<int>(doy - (153 * mp + 2) / 5 + 1);
  m = static_cast<int>(mp < 10 ? mp + 3 : mp - 9);
  y = yoe + era * 400 + (m <= 2);
}

// `#iChannel0 "file"` lines (the VS Code Shadertoy extension names a
// pass's channels so) are not GLSL: blanked (line numbers kept), with a
// warning; channels come from --channel, NAME.json or a project.
static void blank_channel_directives(UserPass& p) {
  size_t pos = 0;
  int line = 1;
  while (pos < p.text.size()) {
    size_t eol = p.text.find('\n', pos);
    if (eol == std::string::npos) eol = p.text.size();
    size_t i = pos;
    while (i < eol && (p.text[i] == ' ' || p.text[i] == '\t')) ++i;
    if (i < eol && p.text[i] == '#') {
      ++i;
      while (i < eol && (p.text[i] == ' ' || p.text[i] == '\t')) ++i;
      if (p.text.compare(i, 8, "iChannel") == 0) {
        warn_once(p.path + ":" + std::to_string(line) +
                  ": ignoring the '#iChannel' directive (a VS Code Shadertoy extension's); bind "
                  "channels with --channel, a NAME.json beside the shader or a project");
        std::fill(p.text.begin() + static_cast<std::ptrdiff_t>(pos),
                  p.text.begin() + static_cast<std::ptrdiff_t>(eol), ' ');
      }
    }
    pos = eol + 1;
    ++line;
  }
}

UserPass read_user_pass(const std::string& path, const std::string& what, bool need_main_image) {
  require_regular_file(path, what);
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (!ec && size > kMaxShaderBytes) {
    throw Error(what + " '" + path + "': " + mib(double(size)) + ", over the limit of " +
                mib(double(kMaxShaderBytes)) + " for a shader file");
  }
  UserPass p;
  p.path = path;
  p.text = read_file(path);
  if (p.text.size() > kMaxShaderBytes) {  // grew since the size was read
    throw Error(what + " '" + path + "': over the limit of " + mib(double(kMaxShaderBytes)) +
                " for a shader file");
  }
  p.source = analyse_shadertoy_source(p.text);
  if (p.source.bom) p.text.erase(0, 3);
  blank_channel_directives(p);
  if (p.text.find_first_not_of(" \t\r\n") == std::string::npos)
    throw Error(path + ": the shader file is empty");
  if (p.text.find('\0') != std::string::npos) throw Error(path + ": not a text file");
  if (need_main_image) check_main_image(p, what);
  return p;
}

void check_main_image(const UserPass& p, const std::string& what) {
  const ShadertoySource& s = p.source;
  if (s.has_main) {
    throw Error(p.path + ":" + std::to_string(s.main_line) +
                ": defines main(); a Shadertoy shader defines only mainImage()");
  }
  if (s.has_main_image && !s.main_image_params_ok) {
    throw Error(p.path + ":" + std::to_string(s.main_image_line) + ": mainImage(" +
                s.main_image_params +
                "): expected the Shadertoy signature 'void mainImage(out vec4 fragColor, in vec2 "
                "fragCoord)'");
  }
  // A mainImage made by a macro is left to the compiler.
  if (!s.has_main_image && !s.mentions_main_image) {
    throw Error(p.path + ": no Shadertoy entry point in the " + what +
                ": expected 'void mainImage(out vec4 fragColor, in vec2 fragCoord)'");
  }
}

std::vector<gpu::StageSource::Piece> prelude_pieces(const gpu::ShaderCompiler& compiler,
                                                    const std::vector<const UserPass*>& passes) {
  // The prelude line by line (line numbers kept), without a uniform that a
  // pass declares itself with the same type.
  const std::string_view prelude = compiler.file("shadertoy_prelude.glsl");
  std::string text;
  size_t pos = 0;
  while (pos < prelude.size()) {
    size_t eol = prelude.find('\n', pos);
    if (eol == std::string_view::npos) eol = prelude.size();
    std::string_view line = prelude.substr(pos, eol - pos);
    pos = eol + 1;
    if (line.substr(0, 8) == "uniform ") {
      const size_t t0 = 8, t1 = line.find(' ', t0);
      const std::string_view type = line.substr(t0, t1 - t0);
      size_t n1 = t1 + 1;
      while (n1 < line.size() && line[n1] != ';' && line[n1] != '[') ++n1;
      const std::string_view name = line.substr(t1 + 1, n1 - t1 - 1);
      bool own = false;
      for (const UserPass* p : passes) {
        for (const ShadertoyUniform& u : p->source.uniforms)
          own = own || (u.type == type && u.name == name);
      }
      if (own) line = "";
    }
    text.append(line);
    text += '\n';
  }
  std::vector<gpu::StageSource::Piece> pieces = {{"shadertoy_prelude.glsl", text}};
  std::string legacy;
  bool equirect = false;
  for (const Legacy& l : kLegacy) {
    bool used = false, defined = false;
    for (const UserPass* p : passes) {
      used = used || p->source.uses_legacy(l.name);
      defined = defined || p->source.defines(l.name);
    }
    if (!used || defined) continue;
    const std::string_view name = l.name;
    if (name.substr(0, 11) == "textureCube" && !equirect) {
      legacy += kEquirect;
      equirect = true;
    }
    legacy += l.glsl;
  }
  if (!legacy.empty()) pieces.push_back({"shadertoy_legacy.glsl (generated)", legacy});
  return pieces;
}

Image read_channel_image(const std::string& path, const std::string& what) {
  require_regular_file(path, what + " image");
  const std::string bytes = read_file(path);
  if (bytes.empty()) throw Error(what + " image '" + path + "': the file is empty");
  int w = 0, h = 0, n = 0;
  const auto byte = [&](size_t i) { return static_cast<unsigned char>(bytes[i]); };
  if (bytes.size() >= 24 && bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0 &&
      bytes.compare(12, 4, "IHDR") == 0) {
    // PNG: the size is in the header chunk (stb's own header check refuses
    // large images without saying their size).
    const auto be32 = [&](size_t i) {
      return (std::uint32_t(byte(i)) << 24) | (std::uint32_t(byte(i + 1)) << 16) |
             (std::uint32_t(byte(i + 2)) << 8) | std::uint32_t(byte(i + 3));
    };
    const std::uint32_t pw = be32(16), ph = be32(20);
    w = static_cast<int>(std::min<std::uint32_t>(pw, INT32_MAX));
    h = static_cast<int>(std::min<std::uint32_t>(ph, INT32_MAX));
  } else if (bytes.size() > static_cast<size_t>(INT32_MAX) ||
             !stbi_info_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()),
                                    static_cast<int>(bytes.size()), &w, &h, &n)) {
    throw Error(what + " image '" + path + "': not a readable image (" +
                (stbi_failure_reason() ? stbi_failure_reason() : "unknown format") + ")");
  }
  if (w > kMaxChannelSide || h > kMaxChannelSide ||
      static_cast<long long>(w) * h > kMaxChannelPixels) {
    throw Error(what + " image '" + path + "': " + std::to_string(w) + "x" + std::to_string(h) +
                " pixels, over the limit of " + std::to_string(kMaxChannelSide) +
                " pixels a side and " + std::to_string(kMaxChannelPixels >> 20) +
                " megapixels for a channel image; scale it down");
  }
  try {
    return read_image(path);
  } catch (const Error& e) {
    throw Error(what + " image: " + e.what());
  }
}

void allow_missing_shadertoy_inputs(const gpu::Program& p) {
  p.allow_missing({"iResolution", "iTime", "iGlobalTime", "iTimeDelta", "iFrameRate", "iFrame",
                   "iMouse", "iDate", "iSampleRate", "iChannel0", "iChannel1", "iChannel2",
                   "iChannel3", "iChannelTime[0]", "iChannelResolution[0]", "iChannelResolution[1]",
                   "iChannelResolution[2]", "iChannelResolution[3]"});
}

void set_shadertoy_inputs(const gpu::Program& p, const FrameInput& f, const ShadertoyDate& date,
                          const float channel_size[4][2]) {
  p.set("iResolution", float(f.width), float(f.height), 1.0f);
  p.set("iTime", float(f.time_s));
  p.set("iGlobalTime", float(f.time_s));  // where the shader declares it itself
  p.set("iTimeDelta", float(f.delta_s));
  p.set("iFrameRate", float(f.delta_s > 0 ? 1.0 / f.delta_s : 60.0));
  p.set("iFrame", f.frame);
  // Shadertoy: xy = position while the button is down, zw = click position
  // (negative once released); pixels with the origin bottom-left.
  const float mx = float(f.mouse_px.x), my = float(f.height - f.mouse_px.y);
  p.set("iMouse", mx, my, f.mouse_down ? mx : -mx, -my);
  const std::array<float, 4> d = shadertoy_idate(date, f.time_s);
  p.set("iDate", d[0], d[1], d[2], d[3]);
  p.set("iSampleRate", 44100.0f);
  // Images and buffers play along with the scene clock.
  const float t[4] = {float(f.time_s), float(f.time_s), float(f.time_s), float(f.time_s)};
  glProgramUniform1fv(p.id(), p.uniform_if_present("iChannelTime[0]"), 4, t);
  const char* res[] = {"iChannelResolution[0]", "iChannelResolution[1]", "iChannelResolution[2]",
                       "iChannelResolution[3]"};
  for (int i = 0; i < 4; ++i) {
    glProgramUniform3f(p.id(), p.uniform_if_present(res[i]), channel_size[i][0], channel_size[i][1],
                       1.0f);
  }
}

}  // namespace foveate::detail

namespace foveate {

ShadertoyDate parse_shadertoy_date(const std::string& text) {
  ShadertoyDate d;
  if (text == "now") {
    d.real_clock = true;
    return d;
  }
  int y = 0, mo = 0, da = 0, h = 0, mi = 0, s = 0, used = 0;
  const char* c = text.c_str();
  bool ok = false;
  if (std::sscanf(c, "%4d-%2d-%2d%n", &y, &mo, &da, &used) == 3 && used == int(text.size())) {
    ok = true;
  } else if (text.size() > 10 && (text[10] == 'T' || text[10] == ' ')) {
    const std::string rest = text.substr(11);
    int used2 = 0;
    ok = std::sscanf(c, "%4d-%2d-%2d%n", &y, &mo, &da, &used) == 3 && used == 10 &&
         ((std::sscanf(rest.c_str(), "%2d:%2d:%2d%n", &h, &mi, &s, &used2) == 3 &&
           used2 == int(rest.size())) ||
          (s = 0, std::sscanf(rest.c_str(), "%2d:%2d%n", &h, &mi, &used2) == 2 &&
                      used2 == int(rest.size())));
  }
  static const int month_days[] = {31, 29, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  if (ok) {
    const bool leap = (y % 4 == 0 && y % 100 != 0) || y % 400 == 0;
    ok = y >= 1 && mo >= 1 && mo <= 12 && da >= 1 && da <= month_days[mo - 1] &&
         !(mo == 2 && da == 29 && !leap) && h >= 0 && h < 24 && mi >= 0 && mi < 60 && s >= 0 &&
         s < 60;
  }
  if (!ok) {
    throw Error("'" + text +
                "': expected now, YYYY-MM-DD or YYYY-MM-DDTHH:MM[:SS] (a valid date and time)");
  }
  d.year = y;
  d.month = mo;
  d.day = da;
  d.seconds = h * 3600.0 + mi * 60.0 + s;
  return d;
}

std::array<float, 4> shadertoy_idate(const ShadertoyDate& date, double time_s) {
  long long y = date.year;
  int m = date.month, d = date.day;
  double sec = date.seconds + time_s;
  if (date.real_clock) {
    // The local wall clock now (the scene time plays no part).
    const auto now = std::chrono::system_clock::now();
    const std::time_t t = std::chrono::system_clock::to_time_t(now);
    std::tm tm{};
    localtime_r(&t, &tm);
    const double frac =
        std::chrono::duration<double>(now.time_since_epoch()).count() - std::floor(double(t));
    return {float(tm.tm_year + 1900), float(tm.tm_mon), float(tm.tm_mday),
            float(tm.tm_hour * 3600 + tm.tm_min * 60 + tm.tm_sec + frac)};
  }
  if (!std::isfinite(sec)) sec = 0.0;
  const double whole_days = std::clamp(std::floor(sec / 86400.0), -1e8, 1e8);
  sec -= whole_days * 86400.0;
  detail::civil_from_days(detail::days_from_civil(y, m, d) + static_cast<long long>(whole_days), y,
                          m, d);
  return {float(y), float(m - 1), float(d), float(sec)};
}

}  // namespace foveate
