#include "tools/viewer/viewer_gui.h"

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

namespace pyro {

ViewerGui::ViewerGui(GLFWwindow* window, float scale) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // panel places are not written next to the user's files
  io.FontGlobalScale = scale;
  ImGui::StyleColorsDark();
  ImGui::GetStyle().ScaleAllSizes(scale);
  ImGui::GetStyle().Alpha = 0.92f;
  // Installs its callbacks after the window's own, which it calls in turn (GLFW chaining).
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");
}

ViewerGui::~ViewerGui() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

void ViewerGui::begin_frame() {
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
}

void ViewerGui::render() {
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

bool ViewerGui::wants_mouse() const { return ImGui::GetIO().WantCaptureMouse; }
bool ViewerGui::wants_keyboard() const { return ImGui::GetIO().WantCaptureKeyboard; }

}  // namespace pyro
