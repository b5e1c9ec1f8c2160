#pragma once
// One small platform interface with two backends: a headless OpenGL 4.5 core
// context through EGL (surfaceless Mesa, falling back to an EGL device with a
// pbuffer), and a GLFW window. Rendering code only sees Context.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace foveate::gpu {

struct ContextOptions {
  /// Create a KHR_debug context and collect GL errors, including uniforms a
  /// program lacks (see Context::take_debug_errors()).
  bool debug = false;
};

struct DebugMessage {
  unsigned type = 0;
  unsigned severity = 0;
  std::string text;
};

class Context {
 public:
  virtual ~Context() = default;
  Context() = default;
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  virtual void make_current() = 0;
  /// Which backend: "egl-surfaceless", "egl-device", "glfw".
  [[nodiscard]] virtual std::string backend() const = 0;
  /// GL_RENDERER, GL_VERSION.
  [[nodiscard]] std::string renderer() const;
  [[nodiscard]] std::string version() const;
  /// Errors reported through KHR_debug since the last call (debug contexts only).
  std::vector<DebugMessage> take_debug_errors();

 protected:
  void install_debug_callback(const ContextOptions& options);

 private:
  static void debug_callback(unsigned source, unsigned type, unsigned id, unsigned severity,
                             int length, const char* message, const void* user);
  std::vector<DebugMessage> errors_;
};

/// Headless context; throws foveate::Error explaining what is missing when no
/// EGL platform gives an OpenGL 4.5 core context.
std::unique_ptr<Context> create_headless_context(const ContextOptions& options = {});

/// A window with an OpenGL 4.5 core context (GLFW).
class Window : public Context {
 public:
  struct Input {
    double mouse_x = 0, mouse_y = 0;  ///< pixels, origin top-left
    bool mouse_inside = false;
    bool should_close = false;
    std::vector<int> keys_pressed;  ///< GLFW key codes pressed since the last poll
  };
  virtual void swap_buffers() = 0;
  virtual Input poll() = 0;
  virtual void set_title(const std::string& title) = 0;
  [[nodiscard]] virtual int framebuffer_width() const = 0;
  [[nodiscard]] virtual int framebuffer_height() const = 0;
  /// The backend's window handle (a GLFWwindow*), for UI toolkits that bind to it.
  [[nodiscard]] virtual void* native_handle() const = 0;
};

std::unique_ptr<Window> create_window(int width, int height, const std::string& title,
                                      const ContextOptions& options = {});

}  // namespace foveate::gpu
