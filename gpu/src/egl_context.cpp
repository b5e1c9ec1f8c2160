// Headless OpenGL 4.5 core through EGL: a hardware EGL device (with a
// pbuffer surface), Mesa's surfaceless platform, then a software device.
#include <epoxy/egl.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "foveate/core/error.hpp"
#include "foveate/gpu/context.hpp"

namespace foveate::gpu {

namespace {

std::string egl_error() {
  char buf[32];
  std::snprintf(buf, sizeof buf, "EGL error 0x%04X", eglGetError());
  return buf;
}

class EglContext final : public Context {
 public:
  EglContext(EGLDisplay d, EGLSurface s, EGLContext c, std::string backend)
      : display_(d), surface_(s), context_(c), backend_(std::move(backend)) {}
  ~EglContext() override {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (surface_ != EGL_NO_SURFACE) eglDestroySurface(display_, surface_);
    eglDestroyContext(display_, context_);
    eglTerminate(display_);
  }
  void make_current() override {
    if (!eglMakeCurrent(display_, surface_, surface_, context_)) {
      throw Error("eglMakeCurrent failed: " + egl_error());
    }
  }
  std::string backend() const override { return backend_; }
  void init(const ContextOptions& o) { install_debug_callback(o); }

 private:
  EGLDisplay display_;
  EGLSurface surface_;
  EGLContext context_;
  std::string backend_;
};

// Creates a 4.5 core context on `dpy`; with `pbuffer`, also a 16x16 surface.
std::unique_ptr<EglContext> try_display(EGLDisplay dpy, bool pbuffer, const std::string& backend,
                                        const ContextOptions& o, std::string& why) {
  if (dpy == EGL_NO_DISPLAY) {
    why += backend + ": no display; ";
    return nullptr;
  }
  EGLint major = 0, minor = 0;
  if (!eglInitialize(dpy, &major, &minor)) {
    why += backend + ": eglInitialize failed (" + egl_error() + "); ";
    return nullptr;
  }
  if (!eglBindAPI(EGL_OPENGL_API)) {
    why += backend + ": no desktop OpenGL API; ";
    eglTerminate(dpy);
    return nullptr;
  }
  const EGLint config_attrs[] = {EGL_SURFACE_TYPE,
                                 pbuffer ? EGL_PBUFFER_BIT : 0,
                                 EGL_RENDERABLE_TYPE,
                                 EGL_OPENGL_BIT,
                                 EGL_RED_SIZE,
                                 8,
                                 EGL_GREEN_SIZE,
                                 8,
                                 EGL_BLUE_SIZE,
                                 8,
                                 EGL_NONE};
  EGLConfig config = nullptr;
  EGLint count = 0;
  if (!eglChooseConfig(dpy, config_attrs, &config, 1, &count) || count < 1) {
    why += backend + ": no OpenGL config; ";
    eglTerminate(dpy);
    return nullptr;
  }
  const EGLint ctx_attrs[] = {EGL_CONTEXT_MAJOR_VERSION,
                              4,
                              EGL_CONTEXT_MINOR_VERSION,
                              5,
                              EGL_CONTEXT_OPENGL_PROFILE_MASK,
                              EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                              EGL_CONTEXT_OPENGL_DEBUG,
                              o.debug ? EGL_TRUE : EGL_FALSE,
                              EGL_NONE};
  EGLContext ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, ctx_attrs);
  if (ctx == EGL_NO_CONTEXT) {
    why += backend + ": no OpenGL 4.5 core context (" + egl_error() + "); ";
    eglTerminate(dpy);
    return nullptr;
  }
  EGLSurface surface = EGL_NO_SURFACE;
  if (pbuffer) {
    const EGLint pb_attrs[] = {EGL_WIDTH, 16, EGL_HEIGHT, 16, EGL_NONE};
    surface = eglCreatePbufferSurface(dpy, config, pb_attrs);
    if (surface == EGL_NO_SURFACE) {
      why += backend + ": no pbuffer surface; ";
      eglDestroyContext(dpy, ctx);
      eglTerminate(dpy);
      return nullptr;
    }
  }
  auto c = std::make_unique<EglContext>(dpy, surface, ctx, backend);
  c->make_current();
  c->init(o);
  return c;
}

}  // namespace

namespace {

struct Device {
  EGLDeviceEXT handle;
  bool software;
  std::string name;
};

std::vector<Device> egl_devices() {
  std::vector<Device> out;
  if (!epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_platform_device")) return out;
  EGLDeviceEXT devices[16];
  EGLint n = 0;
  if (!eglQueryDevicesEXT(16, devices, &n)) return out;
  const bool query = epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_device_query");
  for (EGLint i = 0; i < n; ++i) {
    const char* ext = query ? eglQueryDeviceStringEXT(devices[i], EGL_EXTENSIONS) : nullptr;
    const std::string e = ext ? ext : "";
    Device d{devices[i], e.find("EGL_MESA_device_software") != std::string::npos,
             "device " + std::to_string(i)};
    if (e.find("EGL_NV_device_cuda") != std::string::npos) d.name += " (NVIDIA)";
    if (d.software) d.name += " (software)";
    out.push_back(d);
  }
  return out;
}

std::unique_ptr<EglContext> try_device(const Device& d, const ContextOptions& options,
                                       std::string& why) {
  EGLDisplay dpy = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, d.handle, nullptr);
  return try_display(dpy, true, "egl-device", options, why);
}

std::unique_ptr<EglContext> try_surfaceless(const ContextOptions& options, std::string& why) {
  if (!epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless")) {
    why += "egl-surfaceless: EGL_MESA_platform_surfaceless missing; ";
    return nullptr;
  }
  EGLDisplay d =
      eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  return try_display(d, false, "egl-surfaceless", options, why);
}

}  // namespace

std::unique_ptr<Context> create_headless_context(const ContextOptions& options) {
  // Hardware devices first: NVIDIA's driver offers only the device platform,
  // and where Mesa is installed beside it (glvnd) Mesa's surfaceless platform
  // would give llvmpipe on a machine with a GPU. Then Mesa surfaceless, then
  // software devices. FOVEATE_EGL=device or surfaceless forces a platform.
  const char* force_env = std::getenv("FOVEATE_EGL");
  const std::string force = force_env ? force_env : "";
  if (!force.empty() && force != "device" && force != "surfaceless") {
    throw Error("FOVEATE_EGL='" + force + "': expected 'device' or 'surfaceless'");
  }
  std::string why;
  const std::vector<Device> devices =
      force == "surfaceless" ? std::vector<Device>{} : egl_devices();
  if (force != "surfaceless" && devices.empty()) why += "egl-device: no EGL device; ";
  for (const Device& d : devices) {
    if (d.software) continue;
    if (auto c = try_device(d, options, why)) return c;
  }
  if (force != "device") {
    if (auto c = try_surfaceless(options, why)) return c;
  }
  for (const Device& d : devices) {
    if (!d.software) continue;
    if (auto c = try_device(d, options, why)) return c;
  }
  throw Error("no headless OpenGL 4.5 core context: " + why +
              "install Mesa (libegl-mesa0, libgl1-mesa-dri) or a GPU driver with EGL" +
              (force.empty() ? "" : " (FOVEATE_EGL=" + force + " was set)"));
}

}  // namespace foveate::gpu
