#include "engine/gpu/window_context.h"

#include <epoxy/gl.h>
// GLFW must not include a GL header of its own: epoxy's declares every GL entry point.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdlib>
#include <string>

#include "engine/gpu/gpu_error.h"

namespace pyro::gpu {

namespace {

std::string last_glfw_error() {
  const char* text = nullptr;
  const int code = glfwGetError(&text);
  if (code == GLFW_NO_ERROR) return "no error reported";
  return text ? std::string(text) : "GLFW error " + std::to_string(code);
}

GLFWwindow* try_create(int width, int height, const std::string& title, int creation_api,
                       const char* label, std::string& log) {
  glfwDefaultWindowHints();
  glfwWindowHint(GLFW_CONTEXT_CREATION_API, creation_api);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_DEPTH_BITS, 0);  // the scene renders into its own targets
  glfwWindowHint(GLFW_STENCIL_BITS, 0);
  GLFWwindow* w = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!w) log += std::string("  ") + label + ": " + last_glfw_error() + "\n";
  return w;
}

}  // namespace

WindowContext::WindowContext(int width, int height, const std::string& title) {
  const char* display = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  if ((!display || !*display) && (!wayland || !*wayland)) {
    throw GpuError(
        "pyro view needs a display to open its window, and DISPLAY is not set: run it in a "
        "desktop session, or headless under a virtual X server: xvfb-run -a pyro view SCENE "
        "(tools/install-deps.sh installs xvfb)");
  }
  if (!glfwInit())
    throw GpuError("cannot start GLFW on display \"" + std::string(display ? display : wayland) +
                   "\": " + last_glfw_error());
  std::string log;
  window_ = try_create(width, height, title, GLFW_NATIVE_CONTEXT_API, "native (GLX)", log);
  if (!window_) window_ = try_create(width, height, title, GLFW_EGL_CONTEXT_API, "EGL", log);
  if (!window_) {
    glfwTerminate();
    throw GpuError("cannot open a window with an OpenGL 4.5 core context; tried:\n" + log);
  }
  glfwSetWindowUserPointer(window_, this);
  glfwSetKeyCallback(window_, &WindowContext::on_key);
  glfwSetCursorPosCallback(window_, &WindowContext::on_cursor);
  glfwSetScrollCallback(window_, &WindowContext::on_scroll);
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(0);  // frames as fast as they render; the overlay shows the real rate
  const int version = epoxy_gl_version();
  if (version < 45) {
    glfwDestroyWindow(window_);
    glfwTerminate();
    throw GpuError("the window's context offers OpenGL " + std::to_string(version / 10) + "." +
                   std::to_string(version % 10) + "; Pyrocumulus needs 4.5 core");
  }
  description_ = std::string("OpenGL ") + reinterpret_cast<const char*>(glGetString(GL_VERSION)) +
                 " / " + reinterpret_cast<const char*>(glGetString(GL_RENDERER));
}

WindowContext::~WindowContext() {
  glfwDestroyWindow(window_);
  glfwTerminate();
}

void WindowContext::make_current() {
  if (glfwGetCurrentContext() != window_) glfwMakeContextCurrent(window_);
}
void WindowContext::release_current() {
  if (glfwGetCurrentContext() == window_) glfwMakeContextCurrent(nullptr);
}
void WindowContext::swap_buffers() { glfwSwapBuffers(window_); }
void WindowContext::poll_events() { glfwPollEvents(); }
void WindowContext::wait_events(double seconds) { glfwWaitEventsTimeout(seconds); }
bool WindowContext::should_close() const { return glfwWindowShouldClose(window_) != 0; }
void WindowContext::request_close() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }
void WindowContext::set_title(const std::string& title) { glfwSetWindowTitle(window_, title.c_str()); }

int WindowContext::framebuffer_width() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return w;
}
int WindowContext::framebuffer_height() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return h;
}

std::vector<KeyPress> WindowContext::take_key_presses() {
  std::vector<KeyPress> out;
  out.swap(presses_);
  return out;
}

void WindowContext::take_drag(double& dx, double& dy) {
  dx = drag_dx_;
  dy = drag_dy_;
  drag_dx_ = drag_dy_ = 0;
}

double WindowContext::take_scroll() {
  const double s = scroll_;
  scroll_ = 0;
  return s;
}

bool WindowContext::key_down(int key) const { return glfwGetKey(window_, key) == GLFW_PRESS; }

void WindowContext::on_key(GLFWwindow* w, int key, int, int action, int mods) {
  auto* self = static_cast<WindowContext*>(glfwGetWindowUserPointer(w));
  if (action == GLFW_PRESS || action == GLFW_REPEAT) self->presses_.push_back({key, mods});
}

void WindowContext::on_cursor(GLFWwindow* w, double x, double y) {
  auto* self = static_cast<WindowContext*>(glfwGetWindowUserPointer(w));
  if (self->cursor_known_ && glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS) {
    self->drag_dx_ += x - self->cursor_x_;
    self->drag_dy_ += y - self->cursor_y_;
  }
  self->cursor_x_ = x;
  self->cursor_y_ = y;
  self->cursor_known_ = true;
}

void WindowContext::on_scroll(GLFWwindow* w, double, double dy) {
  static_cast<WindowContext*>(glfwGetWindowUserPointer(w))->scroll_ += dy;
}

}  // namespace pyro::gpu
