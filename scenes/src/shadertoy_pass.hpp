#pragma once
// A Shadertoy pass, as single-pass scenes and multipass projects both read
// one: the user's pass file (checked, size-capped, BOM skipped), the prelude
// adapted to it (Shadertoy's inputs minus those it declares itself, the
// legacy names it uses), channel images checked before decoding, the inputs
// set per pass, and the warning for a channel sampled but not bound.
#include <array>
#include <string>
#include <vector>

#include "foveate/core/image.hpp"
#include "foveate/gpu/shader.hpp"
#include "foveate/scenes/scene.hpp"
#include "foveate/scenes/shadertoy_source.hpp"
#include "scene_warnings.hpp"

namespace foveate::detail {

/// Limits on what a user gives (errors name them).
inline constexpr std::size_t kMaxShaderBytes = 1u << 20;    // 1 MiB
inline constexpr int kMaxChannelSide = 16384;               // GL 4.5's guaranteed texture size
inline constexpr long long kMaxChannelPixels = 64ll << 20;  // 64 Mpx: 256 MiB decoded

/// One user shader file, read and scanned.
struct UserPass {
  std::string path;  ///< as given: names the file in errors
  std::string text;  ///< without a leading byte order mark
  ShadertoySource source;
};

/// Reads a pass file: a regular file, at most kMaxShaderBytes, text, not
/// empty. `what` names it in errors ("shader", "Buffer A"). With
/// `need_main_image`, refuses a file without mainImage or with main().
UserPass read_user_pass(const std::string& path, const std::string& what, bool need_main_image);
/// The same checks on text that is already in memory (built-in scenes).
void check_main_image(const UserPass& pass, const std::string& what);

/// GLSL pieces before the user's code: the prelude without the uniforms the
/// passes declare themselves (same name and type), then definitions of the
/// legacy names they use and do not define.
std::vector<gpu::StageSource::Piece> prelude_pieces(const gpu::ShaderCompiler& compiler,
                                                    const std::vector<const UserPass*>& passes);

/// A channel image: a regular file whose header gives a size within the
/// limits (checked before decoding); `what` is "iChannel0" or similar.
Image read_channel_image(const std::string& path, const std::string& what);

/// Shadertoy's uniforms on `program` for frame `f`; `channel_size` holds
/// iChannelResolution (0 for none).
void set_shadertoy_inputs(const gpu::Program& program, const FrameInput& f,
                          const ShadertoyDate& date, const float channel_size[4][2]);
/// The inputs a pass may leave out (Program::allow_missing).
void allow_missing_shadertoy_inputs(const gpu::Program& program);

}  // namespace foveate::detail
