#pragma once
// A window with an OpenGL 4.5 core context through GLFW (X11: GLX, or EGL when GLX offers no
// 4.5 core context), for the interactive viewer (pyro view). It also gathers the window's input
// between frames: key presses in order, keys held down, mouse drags and the scroll wheel.
// Rendering code is shared with the headless path: libepoxy resolves GL per current context.
#include <string>
#include <vector>

struct GLFWwindow;

namespace pyro::gpu {

struct KeyPress {
  int key = 0;   // GLFW_KEY_*
  int mods = 0;  // GLFW_MOD_*
};

class WindowContext {
 public:
  // Throws GpuError (exit status 3) when there is no display (DISPLAY unset), GLFW cannot start,
  // or no OpenGL 4.5 core context can be made; the message says what was tried.
  WindowContext(int width, int height, const std::string& title);
  ~WindowContext();
  WindowContext(const WindowContext&) = delete;
  WindowContext& operator=(const WindowContext&) = delete;

  void make_current();
  // Leaves the calling thread with no current context when the window's is
  // (engine/gpu/current_context.h says why).
  void release_current();
  void swap_buffers();
  // Processes the window system's events (input, resize, close) without waiting.
  void poll_events();
  // Waits up to `seconds` for an event, then processes what came (an idle viewer sleeps here).
  void wait_events(double seconds);
  bool should_close() const;
  void request_close();
  void set_title(const std::string& title);
  // The default framebuffer's size in pixels.
  int framebuffer_width() const;
  int framebuffer_height() const;

  // Input since the last call to each take_*.
  std::vector<KeyPress> take_key_presses();
  // Cursor movement in pixels while the left mouse button was held (x right, y down).
  void take_drag(double& dx, double& dy);
  double take_scroll();  // wheel steps, positive away from the user
  bool key_down(int key) const;
  // Queues a press as if it came from the keyboard (pyro view --press-at).
  void inject_key_press(const KeyPress& press) { presses_.push_back(press); }

  // "OpenGL 4.5 (Core Profile) Mesa 22.3.6 / llvmpipe (...)", for reports.
  const std::string& description() const { return description_; }
  // For a user interface drawn on the window's input and context (the viewer's panels).
  GLFWwindow* glfw_window() const { return window_; }

 private:
  static void on_key(GLFWwindow* w, int key, int scancode, int action, int mods);
  static void on_cursor(GLFWwindow* w, double x, double y);
  static void on_scroll(GLFWwindow* w, double dx, double dy);

  GLFWwindow* window_ = nullptr;
  std::string description_;
  std::vector<KeyPress> presses_;
  double cursor_x_ = 0, cursor_y_ = 0;
  bool cursor_known_ = false;
  double drag_dx_ = 0, drag_dy_ = 0, scroll_ = 0;
};

}  // namespace pyro::gpu
