#pragma once
// A technique written outside foveate with its installed headers only:
// native rendering into a frame of its own, then copied to the output by a
// pass of foveate::tech::PassKit with a fragment shader of its own. Its copy
// is declared as a resolve pass, so reports count it in the resolve share.
// register_native_copy() adds it to the registry: from then on it is listed,
// benchmarked by default and reported like the built-in techniques.
#include <array>
#include <memory>
#include <span>
#include <string>

#include "foveate/gpu/embedded.hpp"
#include "foveate/techniques/pass_kit.hpp"
#include "foveate/techniques/technique.hpp"

namespace example {

inline constexpr const char* kNativeCopy = "native-copy";

// The technique's own GLSL, found by PassKit beside the library's shaders.
inline constexpr std::array<foveate::embedded::EmbeddedFile, 1> kNativeCopyShaders{{
    {"native_copy/copy.frag", R"(// Copies the native frame to the output.
in vec2 v_uv;
uniform sampler2D u_frame;
out vec4 o_color;
void main() { o_color = texture(u_frame, v_uv); }
)"},
}};

class NativeCopy final : public foveate::Technique {
 public:
  NativeCopy(const foveate::TechniqueConfig& c, const foveate::ParamValues&)
      : native_(foveate::make_technique("native", without_params(c))),
        kit_({std::span<const foveate::embedded::EmbeddedFile>(kNativeCopyShaders)}) {}

  foveate::FrameStats render(foveate::Scene& scene, const foveate::FrameInput& frame,
                             const foveate::GazeState& gaze,
                             const foveate::gpu::RenderTarget& target) override {
    frame_.ensure(target.width(), target.height());
    const foveate::FrameStats stats = native_->render(scene, frame, gaze, frame_);
    kit_.pass(kit_.fullscreen("native_copy/copy.frag"), target, {},
              [&](const foveate::gpu::Program& p, foveate::gpu::Samplers& samplers) {
                samplers.bind(p, "u_frame", frame_.color());
              });
    return stats;
  }
  [[nodiscard]] std::vector<foveate::OverlayShape> overlay(
      const foveate::GazeState& gaze) const override {
    return {foveate::tech::gaze_dot(gaze)};
  }

 private:
  static foveate::TechniqueConfig without_params(foveate::TechniqueConfig c) {
    c.params.clear();
    return c;
  }
  std::unique_ptr<foveate::Technique> native_;
  foveate::tech::PassKit kit_;
  foveate::gpu::RenderTarget frame_;
};

/// Registers the technique once per process (later calls do nothing).
inline void register_native_copy() {
  for (const foveate::TechniqueInfo& t : foveate::techniques()) {
    if (t.name == kNativeCopy) return;
  }
  foveate::TechniqueInfo t;
  t.name = kNativeCopy;
  t.summary = "native, copied to the output by a pass of its own (a technique from outside)";
  t.source = "examples/bench_consumer";
  t.resolve_passes = {"copy"};
  t.make = foveate::construct<NativeCopy>();
  foveate::register_technique(std::move(t));
}

}  // namespace example
