#pragma once
// What a Shadertoy shader's text contains, found by one linear scan (no
// regular expressions, no recursion: any input, however long or odd, is read
// in time and stack proportional to its size). Comments and quoted strings
// are skipped; preprocessor lines are read as code. Pure text analysis with
// no GL and no other foveate dependency, so that it can be fuzzed alone
// (tests/fuzz/shadertoy_source_fuzz.cpp compiles scenes/src/shadertoy_source.cpp).
#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace foveate {

/// A top-level `uniform TYPE NAME` the shader declares itself.
struct ShadertoyUniform {
  std::string type;
  std::string name;
};

struct ShadertoySource {
  /// The text starts with a UTF-8 byte order mark (EF BB BF); the analysis
  /// (and the code the compiler should see) starts after it.
  bool bom = false;
  /// `void mainImage(` ... `)` at the top level; line (1-based) where it starts.
  bool has_main_image = false;
  int main_image_line = 0;
  /// The parameter list of mainImage has the Shadertoy form
  /// `([qualifiers] vec4 NAME, [qualifiers] vec2 NAME)`; otherwise
  /// `main_image_params` holds what it has, for the message.
  bool main_image_params_ok = false;
  std::string main_image_params;
  /// `mainImage` appears as an identifier anywhere in the code (possibly
  /// through a macro).
  bool mentions_main_image = false;
  /// `void main(` at the top level: a plain GLSL fragment shader.
  bool has_main = false;
  int main_line = 0;
  /// iChannel0..3 named in the code (outside comments).
  std::array<bool, 4> channels{};
  /// Legacy names used (iGlobalTime, texture2D, textureCube, ...), in the
  /// order of kShadertoyLegacyNames, each once.
  std::vector<std::string> legacy_used;
  /// Names the shader defines itself: `#define NAME`, or NAME declared after
  /// a type (a function, a variable, a uniform).
  std::vector<std::string> user_defined;
  /// Every macro it defines (`#define NAME`), each once, in order: undefined
  /// after the user's code so that code appended after it is not rewritten.
  std::vector<std::string> macros;
  /// Its own top-level uniform declarations.
  std::vector<ShadertoyUniform> uniforms;
  /// Reads the clock, the frame number or the date (iTime, iGlobalTime,
  /// iTimeDelta, iFrame, iDate, iChannelTime).
  bool animated = false;

  [[nodiscard]] bool defines(std::string_view name) const;
  [[nodiscard]] bool uses_legacy(std::string_view name) const;
};

/// The legacy names the prelude can supply.
inline constexpr std::array<std::string_view, 9> kShadertoyLegacyNames = {
    "iGlobalTime", "texture2D",      "texture2DLod", "texture2DProj", "texture2DGrad",
    "textureCube", "textureCubeLod", "iChannelTime", "iSampleRate"};

/// Scans `text` once. Never throws on any input (it allocates only for what
/// it records, which is bounded by the text's size).
ShadertoySource analyse_shadertoy_source(std::string_view text);

}  // namespace foveate
