#pragma once
// The light block on the GPU (components/light_block.h): one uniform buffer, filled from the
// LightBlock resource by the render phase's first system (light_upload_system) once a frame, and
// bound by each renderer at kLightBlockBinding before it draws (content/shaders/lights.glsl).
#include "components/light_block.h"
#include "engine/ecs/schedule.h"
#include "engine/gpu/gl_objects.h"

namespace pyro {

class LightBuffer {
 public:
  // Needs a current GL context; holds `block` from the start.
  explicit LightBuffer(const LightBlock& block = LightBlock{});
  // Copies `block` to the GPU when it differs from what the buffer holds.
  void upload(const LightBlock& block);
  // Binds the buffer at kLightBlockBinding.
  void bind() const;
  // What the buffer holds (the renderers' caches key on it).
  const LightBlock& block() const { return block_; }

 private:
  gpu::Buffer buffer_;
  LightBlock block_;
};

// The render phase's first system: the frame's LightBlock (the default lights without one) into
// the LightBuffer resource, which it creates at setup.
ecs::SystemDesc light_upload_system();

}  // namespace pyro
