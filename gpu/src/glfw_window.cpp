// The same Context interface backed by a GLFW window.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <utility>

#include "foveate/core/error.hpp"
#include "foveate/gpu/context.hpp"

namespace foveate::gpu {

namespace {

class GlfwWindow final : public Window {
 public:
  explicit GlfwWindow(GLFWwindow* w) : window_(w) {
    glfwSetWindowUserPointer(w, this);
    glfwSetKeyCallback(w, [](GLFWwindow* win, int key, int, int action, int) {
      if (action == GLFW_PRESS)
        static_cast<GlfwWindow*>(glfwGetWindowUserPointer(win))->keys_.push_back(key);
    });
  }
  ~GlfwWindow() override {
    glfwDestroyWindow(window_);
    glfwTerminate();
  }
  void make_current() override { glfwMakeContextCurrent(window_); }
  std::string backend() const override { return "glfw"; }
  void swap_buffers() override { glfwSwapBuffers(window_); }
  Input poll() override {
    glfwPollEvents();
    Input in;
    int w = 0, h = 0, fw = 0, fh = 0;
    glfwGetWindowSize(window_, &w, &h);
    glfwGetFramebufferSize(window_, &fw, &fh);
    glfwGetCursorPos(window_, &in.mouse_x, &in.mouse_y);
    if (w > 0 && h > 0) {
      in.mouse_x *= static_cast<double>(fw) / w;
      in.mouse_y *= static_cast<double>(fh) / h;
    }
    in.mouse_inside = glfwGetWindowAttrib(window_, GLFW_HOVERED) != 0;
    in.should_close = glfwWindowShouldClose(window_) != 0;
    in.keys_pressed = std::exchange(keys_, {});
    return in;
  }
  void set_title(const std::string& t) override { glfwSetWindowTitle(window_, t.c_str()); }
  int framebuffer_width() const override {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    return w;
  }
  int framebuffer_height() const override {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    return h;
  }
  void* native_handle() const override { return window_; }
  void init(const ContextOptions& o) { install_debug_callback(o); }

 private:
  GLFWwindow* window_;
  std::vector<int> keys_;
};

}  // namespace

std::unique_ptr<Window> create_window(int width, int height, const std::string& title,
                                      const ContextOptions& options) {
  if (!glfwInit()) {
    const char* desc = nullptr;
    glfwGetError(&desc);
    // GLFW names the display it tried after its text: nothing, and a
    // trailing space, when DISPLAY is empty.
    std::string why = desc ? desc : "GLFW failed to start";
    while (!why.empty() && why.back() == ' ') why.pop_back();
    throw Error("cannot open a window: " + why +
                " (is there a display? try Xvfb, or use the headless commands)");
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, options.debug ? GLFW_TRUE : GLFW_FALSE);
  GLFWwindow* w = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!w) {
    const char* desc = nullptr;
    glfwGetError(&desc);
    glfwTerminate();
    throw Error(std::string("cannot create an OpenGL 4.5 core window: ") +
                (desc ? desc : "unknown"));
  }
  auto win = std::make_unique<GlfwWindow>(w);
  win->make_current();
  glfwSwapInterval(0);
  win->init(options);
  return win;
}

}  // namespace foveate::gpu
