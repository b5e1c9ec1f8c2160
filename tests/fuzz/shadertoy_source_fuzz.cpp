// libFuzzer target: the Shadertoy source scanner (scenes/src/shadertoy_source.cpp,
// which depends on nothing but the standard library; build it with this file).
// Any input must be scanned without a crash, and what the scan reports must
// be consistent with the text.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "foveate/scenes/shadertoy_source.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const foveate::ShadertoySource s = foveate::analyse_shadertoy_source(text);
  // Facts that hold for every input.
  if (s.has_main_image && !s.mentions_main_image) std::abort();
  if (s.has_main_image && (s.main_image_line < 1 || std::size_t(s.main_image_line) > size + 1))
    std::abort();
  if (s.has_main && (s.main_line < 1 || std::size_t(s.main_line) > size + 1)) std::abort();
  if (s.bom != (size >= 3 && text.substr(0, 3) == "\xEF\xBB\xBF")) std::abort();
  if (s.main_image_params.size() > 300) std::abort();
  for (std::size_t i = 0; i < 4; ++i) {
    const char name[] = {'i', 'C', 'h', 'a', 'n', 'n', 'e', 'l', char('0' + i), 0};
    if (s.channels[i] && text.find(name) == std::string_view::npos) std::abort();
  }
  for (const auto& name : s.legacy_used) {
    if (text.find(name) == std::string_view::npos) std::abort();
  }
  for (const auto& name : s.user_defined) {
    if (!s.uses_legacy(name)) std::abort();
  }
  for (const auto& u : s.uniforms) {
    if (u.name.empty() || u.type.empty() || text.find(u.name) == std::string_view::npos)
      std::abort();
  }
  return 0;
}
