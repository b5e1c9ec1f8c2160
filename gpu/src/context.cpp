#include "foveate/gpu/context.hpp"

#include <epoxy/gl.h>

#include <cstring>
#include <utility>

#include "foveate/core/error.hpp"

namespace foveate::gpu {

std::string Context::renderer() const {
  const auto* s = glGetString(GL_RENDERER);
  return s ? reinterpret_cast<const char*>(s) : "";
}

std::string Context::version() const {
  const auto* s = glGetString(GL_VERSION);
  return s ? reinterpret_cast<const char*>(s) : "";
}

std::vector<DebugMessage> Context::take_debug_errors() { return std::exchange(errors_, {}); }

void Context::debug_callback(unsigned source, unsigned type, unsigned, unsigned severity,
                             int length, const char* message, const void* user) {
  auto* self = const_cast<Context*>(static_cast<const Context*>(user));
  if (type != GL_DEBUG_TYPE_ERROR && type != GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR) return;
  // Shader compile errors are reported (with file and line) by ShaderCompiler.
  if (source == GL_DEBUG_SOURCE_SHADER_COMPILER) return;
  std::string text(message, length < 0 ? std::strlen(message) : static_cast<size_t>(length));
  self->errors_.push_back({type, severity, text});
}

void Context::install_debug_callback(const ContextOptions& options) {
  if (!options.debug) return;
  GLint flags = 0;
  glGetIntegerv(GL_CONTEXT_FLAGS, &flags);
  if (!(flags & GL_CONTEXT_FLAG_DEBUG_BIT) && !epoxy_has_gl_extension("GL_KHR_debug")) return;
  glEnable(GL_DEBUG_OUTPUT);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDebugMessageCallback(reinterpret_cast<GLDEBUGPROC>(&Context::debug_callback), this);
}

}  // namespace foveate::gpu
