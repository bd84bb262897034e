#include "engine/gpu/current_context.h"

#include <epoxy/egl.h>

namespace pyro::gpu {

void release_current_egl_context() {
  const EGLDisplay display = eglGetCurrentDisplay();
  if (display != EGL_NO_DISPLAY)
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
}

}  // namespace pyro::gpu
