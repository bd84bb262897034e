#pragma once
// A headless OpenGL 4.5 core context through EGL: the surfaceless platform first (Mesa's
// llvmpipe on machines with no GPU, or a GPU driver), then the default display with a 1x1
// pbuffer. Rendering goes to offscreen framebuffers (render_target.h).
#include <string>

namespace pyro::gpu {

class HeadlessContext {
 public:
  HeadlessContext();  // throws GpuError with what was tried when no context can be made
  ~HeadlessContext();
  HeadlessContext(const HeadlessContext&) = delete;
  HeadlessContext& operator=(const HeadlessContext&) = delete;

  void make_current();
  // "OpenGL 4.5 (Core Profile) Mesa 22.3.6 / llvmpipe (LLVM 15.0.6, 256 bits)", for reports.
  const std::string& description() const { return description_; }
  const std::string& renderer() const { return renderer_; }

 private:
  void* display_ = nullptr;
  void* context_ = nullptr;
  void* surface_ = nullptr;
  std::string description_;
  std::string renderer_;
};

}  // namespace pyro::gpu
