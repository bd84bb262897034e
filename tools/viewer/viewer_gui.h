#pragma once
// The viewer's user interface: Dear ImGui on the window's GLFW input and OpenGL 3 drawing
// (Debian's libimgui.a holds both backends). It owns the ImGui context; each frame the viewer
// calls begin_frame(), draws its panels with ImGui, then render() over the scene's image. This
// file and the panels are the only ones that include ImGui.
struct GLFWwindow;

namespace pyro {

class ViewerGui {
 public:
  // Needs the window's OpenGL context current. `scale`: the font and widget scale (1: 13-pixel
  // text).
  ViewerGui(GLFWwindow* window, float scale);
  ~ViewerGui();
  ViewerGui(const ViewerGui&) = delete;
  ViewerGui& operator=(const ViewerGui&) = delete;

  void begin_frame();
  // Draws what the panels built since begin_frame() into the current framebuffer.
  void render();
  // Whether the pointer or the keyboard is over / typing into a panel: the camera and the keys
  // leave such input to the interface.
  bool wants_mouse() const;
  bool wants_keyboard() const;
};

}  // namespace pyro
