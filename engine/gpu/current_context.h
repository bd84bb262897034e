#pragma once
// The OpenGL context current on the calling thread. A thread has one current context at a time
// across EGL and GLX: libglvnd refuses to make an EGL context current over a window's GLX one
// (EGL_BAD_ACCESS), and a GLX one over an EGL one. A program that draws both headless
// (gl_context.h) and in a window (window_context.h) releases one before it uses the other.

namespace pyro::gpu {

// Leaves the calling thread with no current EGL context, whichever it was (none: nothing to do).
void release_current_egl_context();

}  // namespace pyro::gpu
