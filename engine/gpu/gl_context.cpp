#include "engine/gpu/gl_context.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <string>

#include "engine/gpu/gpu_error.h"

namespace pyro::gpu {

namespace {

std::string egl_error_name(EGLint e) {
  switch (e) {
    case EGL_SUCCESS: return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE: return "EGL_BAD_SURFACE";
    default: return "EGL error " + std::to_string(e);
  }
}

bool has_extension(const char* list, const std::string& name) {
  if (!list) return false;
  const std::string all = std::string(" ") + list + " ";
  return all.find(" " + name + " ") != std::string::npos;
}

struct Attempt {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
  EGLSurface surface = EGL_NO_SURFACE;
};

// Tries one display; returns an empty attempt and appends to `log` when it fails.
Attempt try_display(EGLDisplay display, bool surfaceless, const char* label, std::string& log) {
  Attempt a;
  if (display == EGL_NO_DISPLAY) {
    log += std::string("  ") + label + ": no display\n";
    return a;
  }
  EGLint major = 0, minor = 0;
  if (!eglInitialize(display, &major, &minor)) {
    log += std::string("  ") + label + ": eglInitialize failed (" + egl_error_name(eglGetError()) + ")\n";
    return a;
  }
  if (!eglBindAPI(EGL_OPENGL_API)) {
    log += std::string("  ") + label + ": no desktop OpenGL API\n";
    eglTerminate(display);
    return a;
  }
  const EGLint config_attribs[] = {EGL_SURFACE_TYPE, surfaceless ? 0 : EGL_PBUFFER_BIT,
                                   EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                                   EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8,
                                   EGL_NONE};
  EGLConfig config = nullptr;
  EGLint count = 0;
  const bool no_config_ok = surfaceless && has_extension(eglQueryString(display, EGL_EXTENSIONS),
                                                         "EGL_KHR_no_config_context");
  if (!eglChooseConfig(display, config_attribs, &config, 1, &count) || count == 0) {
    if (!no_config_ok) {
      log += std::string("  ") + label + ": no OpenGL-capable config\n";
      eglTerminate(display);
      return a;
    }
    config = EGL_NO_CONFIG_KHR;
  }
  const EGLint context_attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                    EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                    EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, context_attribs);
  if (context == EGL_NO_CONTEXT) {
    log += std::string("  ") + label + ": no OpenGL 4.5 core context (" +
           egl_error_name(eglGetError()) + ")\n";
    eglTerminate(display);
    return a;
  }
  EGLSurface surface = EGL_NO_SURFACE;
  if (!surfaceless) {
    const EGLint pbuffer_attribs[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
    surface = eglCreatePbufferSurface(display, config, pbuffer_attribs);
    if (surface == EGL_NO_SURFACE) {
      log += std::string("  ") + label + ": no pbuffer surface\n";
      eglDestroyContext(display, context);
      eglTerminate(display);
      return a;
    }
  }
  if (!eglMakeCurrent(display, surface, surface, context)) {
    log += std::string("  ") + label + ": eglMakeCurrent failed (" + egl_error_name(eglGetError()) + ")\n";
    if (surface != EGL_NO_SURFACE) eglDestroySurface(display, surface);
    eglDestroyContext(display, context);
    eglTerminate(display);
    return a;
  }
  a.display = display;
  a.context = context;
  a.surface = surface;
  return a;
}

}  // namespace

HeadlessContext::HeadlessContext() {
  std::string log;
  Attempt a;
  const char* client_ext = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (has_extension(client_ext, "EGL_MESA_platform_surfaceless")) {
    EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    a = try_display(d, true, "surfaceless platform", log);
  } else {
    log += "  surfaceless platform: EGL_MESA_platform_surfaceless not offered\n";
  }
  if (a.context == EGL_NO_CONTEXT && has_extension(client_ext, "EGL_EXT_platform_device")) {
    // GPU drivers without the Mesa platform (NVIDIA) offer devices directly.
    EGLDeviceEXT devices[8];
    EGLint n = 0;
    if (eglQueryDevicesEXT(8, devices, &n) && n > 0) {
      EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[0], nullptr);
      a = try_display(d, true, "device platform", log);
    }
  }
  if (a.context == EGL_NO_CONTEXT) {
    a = try_display(eglGetDisplay(EGL_DEFAULT_DISPLAY), false, "default display + pbuffer", log);
  }
  if (a.context == EGL_NO_CONTEXT) {
    throw GpuError(
        "cannot create a headless OpenGL 4.5 core context through EGL; tried:\n" + log +
        "Install Mesa's drivers (tools/install-deps.sh installs libgl1-mesa-dri and libegl-mesa0).");
  }
  display_ = a.display;
  context_ = a.context;
  surface_ = a.surface;
  const int version = epoxy_gl_version();
  if (version < 45) {
    throw GpuError("the EGL context offers OpenGL " + std::to_string(version / 10) + "." +
                   std::to_string(version % 10) + "; Pyrocumulus needs 4.5 core");
  }
  renderer_ = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  description_ = std::string("OpenGL ") + reinterpret_cast<const char*>(glGetString(GL_VERSION)) +
                 " / " + renderer_;
}

HeadlessContext::~HeadlessContext() {
  if (display_) {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (surface_) eglDestroySurface(display_, surface_);
    if (context_) eglDestroyContext(display_, context_);
    eglTerminate(display_);
  }
}

void HeadlessContext::make_current() {
  eglMakeCurrent(display_, surface_, surface_, context_);
}

}  // namespace pyro::gpu
