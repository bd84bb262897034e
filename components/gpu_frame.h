#pragma once
// Resource: the frame's offscreen target, shared by the render passes.
#include <memory>

#include "engine/gpu/render_target.h"

namespace pyro {

struct GpuFrame {
  std::unique_ptr<gpu::RenderTarget> target;
};

}  // namespace pyro
